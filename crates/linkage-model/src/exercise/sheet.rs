//! A student's task sheet: the variant's drawing at its start, its data and the
//! questions, worded in the language asked for and laid out on A4 by
//! [`linkage_diagram::svg_task`]. One sheet for the app's desk and, a student
//! after another, the teacher's `linkage exercise sheets`.

use linkage::{Kinematics, Mechanism};
use linkage_diagram::pages::Sheet;
use linkage_diagram::svg_task::{CamFigure, TaskSheet, task_sheet};
use linkage_diagram::words::Lang;

use super::words::{self, unit_words};
use super::{Exercise, SubjectData, Variant};
use crate::session::words::mw;

impl Exercise {
    /// The task sheet of `variant` in `lang`.
    pub fn task_sheet(&self, variant: &Variant, lang: Lang) -> Sheet {
        let student = variant.student.as_str();
        let data = match &variant.subject {
            SubjectData::Scene(scene) => words::mechanism_data(scene, lang),
            SubjectData::Cam(cam) => words::cam_data(cam, lang),
        };
        let questions = self
            .file
            .questions
            .iter()
            .map(|q| {
                let asked = words::question(&q.ask, &self.subject, lang);
                (asked, unit_words(q.unit))
            })
            .collect();
        // The mechanism at its start, as the desk opens it.
        let posed = match &variant.subject {
            SubjectData::Scene(scene) => Mechanism::from_scene(scene)
                .and_then(Kinematics::new)
                .and_then(|mut k| k.solve(k.mechanism().driver.start_rad).map(|s| (k, s)))
                .ok(),
            SubjectData::Cam(_) => None,
        };
        // A cam over its turn, as the desk draws it.
        let cam = variant.subject.cam_turn();
        let task = TaskSheet {
            title: mw!(
                lang,
                "exercise.sheet_title",
                name = self.title(lang),
                student = student
            ),
            student: mw!(lang, "exercise.sheet_student", student = student),
            data: (words::data_heading(lang), data),
            questions: (words::questions_heading(lang), questions),
            pose: posed.as_ref().map(|(k, s)| (k.mechanism(), s)),
            cam: cam.as_ref().map(|c| CamFigure {
                points: &c.points,
                base_radius_m: c.base_radius_m,
                follower: &c.follower,
            }),
        };
        task_sheet(&task, lang)
    }
}
