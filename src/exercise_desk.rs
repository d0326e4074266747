//! The student's side of an exercise: the exercise open, the student's number typed,
//! the variant drawn from it and opened as the scene, the answers as typed, and from
//! them the marks (homework) and the answer code. While a desk is open the app shows
//! only what the exercise gives (its data, the mechanism moving, the questions): the
//! analyses that would show the answers stay closed.

use linkage_model::exercise::code::{AnswerSheet, TypedAnswerError, typed_answer};
use linkage_model::exercise::subject::CamTurn;
use linkage_model::exercise::{Exercise, Mode, StudentId, SubjectData, Variant};

use crate::session::{SceneSource, Session};

/// An exercise open on the student's side.
#[derive(Clone, Debug)]
pub struct ExerciseDesk {
    /// The exercise.
    pub exercise: Exercise,
    /// The student's number as being typed.
    pub student_text: String,
    /// The student's variant, once the number was taken.
    pub variant: Option<Variant>,
    /// Each question's answer as typed (with or without its unit).
    pub answers: Vec<String>,
    /// Why the number typed gave no variant.
    pub refusal: Option<DeskRefusal>,
    /// A cam variant sampled over its turn, made once when the variant is drawn
    /// (the view draws it every frame).
    pub cam: Option<CamTurn>,
}

/// Why a student's number gave no variant.
#[derive(Clone, Debug, PartialEq)]
pub enum DeskRefusal {
    /// Not a student number.
    BadNumber,
    /// No variant for it (the exercise's requirements), or the variant's scene did
    /// not open: worded by the model.
    NoVariant(String),
}

/// One answer as typed, read.
#[derive(Clone, Debug, PartialEq)]
pub enum Answer {
    /// Nothing typed.
    Empty,
    /// A number in the question's unit.
    Value(f64),
    /// Not a number, or in a unit of another kind.
    Refused(TypedAnswerError),
}

impl ExerciseDesk {
    /// A desk over `exercise`, no student yet.
    pub fn new(exercise: Exercise) -> Self {
        let answers = vec![String::new(); exercise.file.questions.len()];
        Self {
            exercise,
            student_text: String::new(),
            variant: None,
            answers,
            refusal: None,
            cam: None,
        }
    }

    /// Takes the number typed: draws its variant and returns the scene to open (a
    /// mechanism's; a cam exercise opens none).
    pub fn start(&mut self) -> Option<Session> {
        self.variant = None;
        self.cam = None;
        self.answers.iter_mut().for_each(String::clear);
        let Ok(student) = StudentId::parse(&self.student_text) else {
            self.refusal = Some(DeskRefusal::BadNumber);
            return None;
        };
        let variant = match self.exercise.variant(&student) {
            Ok(v) => v,
            Err(e) => {
                self.refusal = Some(DeskRefusal::NoVariant(e.to_string()));
                return None;
            }
        };
        self.refusal = None;
        let session = match &variant.subject {
            SubjectData::Scene(scene) => {
                let name = format!("{}_{}.ron", self.exercise.file.id, student);
                match Session::open_scene(SceneSource::File(name), scene.as_ref().clone()) {
                    Ok(s) => Some(s),
                    Err(e) => {
                        self.refusal = Some(DeskRefusal::NoVariant(e.to_string()));
                        return None;
                    }
                }
            }
            SubjectData::Cam(_) => None,
        };
        self.cam = variant.subject.cam_turn();
        self.variant = Some(variant);
        session
    }

    /// Answer `i` as typed, read in its question's unit.
    pub fn answer(&self, i: usize) -> Answer {
        let (Some(text), Some(q)) = (self.answers.get(i), self.exercise.file.questions.get(i))
        else {
            return Answer::Empty;
        };
        match text.trim() {
            "" => Answer::Empty,
            t => typed_answer(t, q.unit).map_or_else(Answer::Refused, Answer::Value),
        }
    }

    /// In homework, whether answer `i` is right (`None`: a test, no variant, or no
    /// number typed).
    pub fn mark(&self, i: usize) -> Option<bool> {
        let variant = self.variant.as_ref()?;
        if self.exercise.file.mode != Mode::Homework {
            return None;
        }
        let Answer::Value(v) = self.answer(i) else {
            return None;
        };
        Some(
            self.exercise.file.questions[i]
                .tolerance
                .accepts(v, variant.truths[i]),
        )
    }

    /// The answer code of the answers typed (`None` before a variant, or while an
    /// answer is refused).
    pub fn code(&self) -> Option<String> {
        let variant = self.variant.as_ref()?;
        let answers = (0..self.answers.len())
            .map(|i| match self.answer(i) {
                Answer::Empty => Some(None),
                Answer::Value(v) => Some(Some(v)),
                Answer::Refused(_) => None,
            })
            .collect::<Option<Vec<_>>>()?;
        Some(self.exercise.answer_code(&AnswerSheet {
            student: variant.student.clone(),
            answers,
        }))
    }
}

/// The shipped exercise and student a link names (`#exercise=KEY&student=N`).
pub fn exercise_link(fragment: &str) -> Option<(String, Option<String>)> {
    let pairs: Vec<(&str, &str)> = fragment
        .trim_start_matches('#')
        .split('&')
        .filter_map(|p| p.split_once('='))
        .collect();
    let value = |key: &str| {
        pairs
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, v)| v.to_string())
    };
    Some((value("exercise")?, value("student")))
}

fn shipped(key: &str) -> Result<Exercise, String> {
    let e = crate::catalog::EXERCISES
        .iter()
        .find(|e| e.key == key)
        .ok_or_else(|| format!("no exercise {key}"))?;
    Exercise::parse(e.text).map_err(|e| e.to_string())
}

/// The varied dimensions of `student`'s variant of the shipped exercise `key`, as
/// JSON (`{"values": [...], "draws": n}`, or `{"error": "..."}`): the browser test
/// compares them with the command line's, to the last bit. No truth: the page
/// could show it.
pub fn variant_json(key: &str, student: &str) -> String {
    let variant = shipped(key).and_then(|ex| {
        let student = StudentId::parse(student).map_err(|e| e.to_string())?;
        ex.variant(&student).map_err(|e| e.to_string())
    });
    let json = match variant {
        Ok(v) => serde_json::json!({"values": v.values, "draws": v.draws}),
        Err(e) => serde_json::json!({"error": e}),
    };
    json.to_string()
}

/// The answer code of `student`'s answers `answers` (each typed with or without its
/// unit, separated by `|`) to the shipped exercise `key`, made as the desk makes it
/// (or why not, after `error: `).
pub fn code_for(key: &str, student: &str, answers: &str) -> String {
    let made = shipped(key).and_then(|exercise| {
        let mut desk = ExerciseDesk::new(exercise);
        desk.student_text = student.to_string();
        desk.start();
        desk.answers = answers.split('|').map(str::to_string).collect();
        desk.code()
            .ok_or_else(|| "no code: a student number or an answer refused".to_string())
    });
    made.unwrap_or_else(|e| format!("error: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_names_the_exercise_and_the_student() {
        let link = exercise_link("#exercise=die_cutter_slider&student=2026001");
        assert_eq!(
            link,
            Some(("die_cutter_slider".into(), Some("2026001".into())))
        );
        assert_eq!(
            exercise_link("#exercise=cam_pressure_angle").map(|l| l.1),
            Some(None)
        );
        assert_eq!(exercise_link("#scene=die_cutter"), None);
    }

    /// The page's hooks give what the desk gives: the same dimensions as the
    /// variant, a code the teacher reads back with the answers converted.
    #[test]
    fn the_pages_hooks_give_the_desks_variant_and_code() {
        let json = variant_json("die_cutter_slider", "2026001");
        assert_eq!(json, r#"{"draws":3,"values":[80.5,188.0,40.0]}"#);
        assert!(variant_json("die_cutter_slider", "no number!").contains("error"));
        let code = code_for("die_cutter_slider", "2026001", "105 mm/s|||||1.3");
        assert!(
            code.starts_with("LX1:die-slider:") && code.contains(":2026001:0.105/////1.3:"),
            "{code}"
        );
        assert!(code_for("die_cutter_slider", "2026001", "1 rad/s|||||").starts_with("error: "));
        assert!(code_for("no_such", "1", "").starts_with("error: "));
    }
}
