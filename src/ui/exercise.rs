//! The exercise desk's pane: the student's number, then the variant's data, the
//! mechanism's play and crank angle, the questions with an answer field each (marked
//! in homework), and the answer code to send. The words are `exercise_words`'.

use eframe::egui;

use crate::exercise_desk::{Answer, DeskRefusal, ExerciseDesk};
use crate::i18n::tr;
use crate::state::AppState;
use crate::ui::control_map::ControlKind;
use crate::ui::exercise_words as words;
use linkage_model::exercise::{Mode, SubjectData};

/// The student-number field's and the answers' names in the control map (the tests'
/// handles in any language).
pub const STUDENT_FIELD: &str = "student number";
/// The start button's name in the control map.
pub const START_BUTTON: &str = "get my exercise";

/// The pane.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(desk) = st.exercise.as_mut() else {
        return;
    };
    ui.heading(desk.exercise.title(crate::ui::words::lang()).to_string());
    ui.label(match desk.exercise.file.mode {
        Mode::Homework => tr!("exercise.homework"),
        Mode::Test => tr!("exercise.test"),
    });
    if student_row(ui, desk, &mut st.controls) {
        st.start_exercise();
    }
    let Some(desk) = st.exercise.as_ref() else {
        return;
    };
    if let Some(why) = &desk.refusal {
        let words = match why {
            DeskRefusal::BadNumber => tr!("exercise.bad_number"),
            DeskRefusal::NoVariant(why) => tr!("exercise.no_variant", why = why),
        };
        ui.colored_label(ui.visuals().error_fg_color, words);
    }
    if desk.variant.is_none() {
        return;
    }
    ui.separator();
    data(ui, st);
    if matches!(
        st.exercise
            .as_ref()
            .and_then(|d| d.variant.as_ref())
            .map(|v| &v.subject),
        Some(SubjectData::Scene(_))
    ) {
        crate::ui::controls::play_and_speed(ui, st);
        crate::ui::controls::crank_and_run_time(ui, st);
    }
    ui.separator();
    if let Some(desk) = st.exercise.as_mut() {
        questions(ui, desk, &mut st.controls);
        ui.separator();
        code(ui, desk);
    }
    let sheet = ui.button(tr!("exercise.task_sheet"));
    st.controls
        .note(ui, ControlKind::Exercise, "task sheet", &sheet);
    if sheet.clicked() {
        st.commands.file = Some(crate::file_action::FileAction::TaskSheetPdf);
    }
    ui.separator();
    ui.small(tr!("exercise.hidden_note"));
}

/// The student-number field and its button; whether the number was taken.
fn student_row(
    ui: &mut egui::Ui,
    desk: &mut ExerciseDesk,
    controls: &mut crate::ui::control_map::ControlMap,
) -> bool {
    ui.horizontal_wrapped(|ui| {
        let label = ui.label(tr!("exercise.student_number"));
        let field = ui
            .add(
                egui::TextEdit::singleline(&mut desk.student_text)
                    .id_salt("exercise student")
                    .desired_width(140.0),
            )
            .labelled_by(label.id);
        controls.note(ui, ControlKind::Exercise, STUDENT_FIELD, &field);
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        let button = ui.button(tr!("exercise.start"));
        controls.note(ui, ControlKind::Exercise, START_BUTTON, &button);
        button.clicked() || entered
    })
    .inner
}

/// The variant's data.
fn data(ui: &mut egui::Ui, st: &AppState) {
    let Some(variant) = st.exercise.as_ref().and_then(|d| d.variant.as_ref()) else {
        return;
    };
    ui.strong(linkage_model::exercise::words::data_heading(
        crate::ui::words::lang(),
    ));
    let rows = match &variant.subject {
        SubjectData::Scene(_) => words::mechanism_data(&st.session),
        SubjectData::Cam(cam) => words::cam_data(cam),
    };
    egui::Grid::new("exercise data")
        .num_columns(2)
        .show(ui, |ui| {
            for (name, value) in rows {
                ui.label(marked(ui, &name));
                ui.add(egui::Label::new(value).wrap());
                ui.end_row();
            }
        });
}

/// Each question with its answer field, unit and (homework) mark.
fn questions(
    ui: &mut egui::Ui,
    desk: &mut ExerciseDesk,
    controls: &mut crate::ui::control_map::ControlMap,
) {
    ui.strong(linkage_model::exercise::words::questions_heading(
        crate::ui::words::lang(),
    ));
    for i in 0..desk.answers.len() {
        let q = &desk.exercise.file.questions[i];
        let (unit, tolerance) = (q.unit, q.tolerance);
        let label = ui.label(marked(
            ui,
            &format!(
                "{}. {}",
                i + 1,
                words::question(&q.ask, &desk.exercise.subject)
            ),
        ));
        ui.horizontal_wrapped(|ui| {
            let field = ui
                .add(
                    egui::TextEdit::singleline(&mut desk.answers[i])
                        .id_salt(("exercise answer", i))
                        .desired_width(120.0),
                )
                .labelled_by(label.id);
            controls.note(
                ui,
                ControlKind::Exercise,
                &format!("answer {}", i + 1),
                &field,
            );
            ui.label(words::unit_words(unit));
            match (desk.answer(i), desk.mark(i)) {
                (Answer::Refused(e), _) => {
                    ui.colored_label(ui.visuals().error_fg_color, words::refusal(&e));
                }
                (_, Some(right)) => {
                    let tol = words::tolerance(tolerance, unit);
                    let (text, colour) = if right {
                        (
                            tr!("exercise.right", tol = tol),
                            egui::Color32::from_rgb(40, 140, 60),
                        )
                    } else {
                        (
                            tr!("exercise.wrong", tol = tol),
                            ui.visuals().error_fg_color,
                        )
                    };
                    ui.colored_label(colour, text);
                }
                _ => {}
            }
        });
    }
}

/// The answer code and its copy button.
fn code(ui: &mut egui::Ui, desk: &ExerciseDesk) {
    let Some(code) = desk.code() else {
        ui.label(tr!("exercise.code_waiting"));
        return;
    };
    ui.label(tr!("exercise.code"));
    ui.horizontal_wrapped(|ui| {
        let mut shown = code.as_str();
        ui.add(
            egui::TextEdit::singleline(&mut shown)
                .id_salt("exercise code")
                .desired_width(f32::INFINITY),
        );
    });
    if ui.button(tr!("exercise.copy")).clicked() {
        ui.ctx().copy_text(code);
    }
}

/// `text` with its `_{…}` subscripts set as the textbooks set them (v_E, α_max),
/// wrapped to the pane.
fn marked(ui: &egui::Ui, text: &str) -> egui::text::LayoutJob {
    let size = egui::TextStyle::Body.resolve(ui.style()).size;
    let label = linkage_diagram::label::Label::marked(text);
    let mut job = crate::ui::typeset::job(&label, size, ui.visuals().text_color());
    job.wrap.max_width = ui.available_width();
    job
}
