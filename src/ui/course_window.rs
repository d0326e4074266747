//! The course sheet's window: how many positions over the crank's range (12, as the
//! course asks), at which the polygons are drawn, and the sheet exported as SVG, PNG
//! or PDF in the app's language — what `linkage course-sheet` writes.

use eframe::egui;

use crate::file_action::FileAction;
use crate::i18n::tr;
use crate::state::AppState;
use crate::ui::control_map::ControlKind;
use crate::ui::files::Files;

/// The button that opens the window.
pub fn button(ui: &mut egui::Ui, st: &mut AppState) {
    let r = ui.button(tr!("file.course"));
    st.controls
        .note(ui, ControlKind::FileButton, "Course sheet…", &r);
    if r.clicked() {
        st.course.open = !st.course.open;
    }
}

/// The window, while open; its export buttons start the files' actions.
pub fn window(ctx: &egui::Context, st: &mut AppState, files: &mut Files, frame: &eframe::Frame) {
    if !st.course.open {
        return;
    }
    let mut open = true;
    let mut chosen = None;
    egui::Window::new(tr!("course.title"))
        .open(&mut open)
        .collapsible(false)
        .resizable(false)
        .show(ctx, |ui| {
            ui.horizontal(|ui| {
                let label = ui.label(tr!("course.positions"));
                let range = 2..=72;
                ui.add(egui::DragValue::new(&mut st.course.positions).range(range))
                    .labelled_by(label.id);
            });
            ui.horizontal(|ui| {
                ui.checkbox(&mut st.course.from_start, tr!("course.from_start"));
                if !st.course.from_start {
                    let drag = egui::DragValue::new(&mut st.course.first_deg)
                        .range(-360.0..=360.0)
                        .suffix("°");
                    ui.add(drag).on_hover_text(tr!("course.first_hint"));
                }
            });
            ui.horizontal(|ui| {
                let label = ui.label(tr!("course.chosen"));
                ui.text_edit_singleline(&mut st.course.chosen)
                    .labelled_by(label.id)
                    .on_hover_text(tr!("course.chosen_hint"));
            });
            let check = st.course.chosen_numbers();
            if let Err(why) = &check {
                ui.colored_label(ui.visuals().warn_fg_color, why);
            }
            ui.horizontal(|ui| {
                let r = ui.add_enabled(check.is_ok(), egui::Button::new(tr!("course.report")));
                let r = r.on_hover_text(tr!("course.report_hint"));
                st.controls
                    .note(ui, ControlKind::FileButton, "Course report…", &r);
                if r.clicked() {
                    chosen = Some(FileAction::ReportPdf);
                }
            });
            ui.horizontal(|ui| {
                for (id, action) in [
                    ("Course SVG…", FileAction::CourseSvg),
                    ("Course PNG…", FileAction::CoursePng),
                    ("Course PDF…", FileAction::CoursePdf),
                ] {
                    let text = format!("{}…", action.file_type().1.to_uppercase());
                    let r = ui.add_enabled(check.is_ok(), egui::Button::new(text));
                    st.controls.note(ui, ControlKind::FileButton, id, &r);
                    if r.clicked() {
                        chosen = Some(action);
                    }
                }
            });
        });
    st.course.open = open;
    if let Some(action) = chosen {
        files.start(ctx, st, action, frame);
    }
}
