//! The top bar: scene picker, file actions, view toggles.

use std::sync::OnceLock;

use eframe::egui;

use crate::app::AppState;
use crate::catalog::BUILTIN_SCENES;
use crate::session::{SceneSource, Session};
use crate::ui::control_map::ControlKind;
use crate::ui::files;

/// Display names of the shipped scenes (their `name` field), read once.
fn names() -> &'static [String] {
    static NAMES: OnceLock<Vec<String>> = OnceLock::new();
    NAMES.get_or_init(|| {
        BUILTIN_SCENES
            .iter()
            .map(|b| {
                linkage::SceneFile::parse(b.text).map_or_else(|_| b.key.to_string(), |s| s.name)
            })
            .collect()
    })
}

/// The top bar.
pub fn top_bar(ui: &mut egui::Ui, st: &mut AppState, frame: &eframe::Frame) {
    egui::Panel::top("scene_bar").show(ui, |ui| {
        ui.horizontal_wrapped(|ui| {
            ui.strong("Linkage Lab");
            // The file buttons come before the scene's name, whose width varies, so
            // that they stay in place whichever scene is open.
            files::buttons(ui, st, frame);
            let current = match st.session.source() {
                SceneSource::Builtin(key) => BUILTIN_SCENES
                    .iter()
                    .position(|b| b.key == key)
                    .map_or_else(|| key.clone(), |i| names()[i].clone()),
                SceneSource::File(name) => name.clone(),
            };
            let mut chosen = None;
            let mut items = Vec::new();
            let picker = egui::ComboBox::from_label("Scene")
                .selected_text(current)
                .width(300.0)
                .show_ui(ui, |ui| {
                    // A popup's first frame is a sizing pass, laid out away from where
                    // it will be drawn: its rects are not where a click lands.
                    let placed = !ui.is_sizing_pass();
                    for (b, name) in BUILTIN_SCENES.iter().zip(names()) {
                        let r = ui.selectable_label(false, name);
                        let visible = placed && ui.clip_rect().contains_rect(r.rect);
                        items.push((name, r.rect, visible));
                        if r.clicked() {
                            chosen = Some(b.key);
                        }
                    }
                });
            st.controls
                .note(ui, ControlKind::ScenePicker, "Scene", &picker.response);
            for (name, rect, visible) in items {
                st.controls
                    .note_rect(ControlKind::SceneItem, name, rect, visible);
            }
            if let Some(key) = chosen {
                match Session::open_builtin(key) {
                    Ok(s) => st.open(s),
                    Err(e) => st.status = Some(e),
                }
            }
            if ui.button("Reset edits").clicked() {
                st.session.reset();
            }
            if ui.button("Fit view").clicked() {
                st.fit_pending = true;
            }
            for (on, label) in [
                (&mut st.layers.velocities, "v vectors"),
                (&mut st.layers.accelerations, "a vectors"),
                (&mut st.layers.traces, "traces"),
                (&mut st.layers.centres, "instant centres"),
            ] {
                let r = ui.checkbox(on, label);
                st.controls.note(ui, ControlKind::Layer, label, &r);
            }
            if let Some(status) = &st.status {
                ui.label(status);
            }
        });
    });
    files::prompt_window(ui.ctx(), st);
}
