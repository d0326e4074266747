//! A design in the synthesis window: its figure, the buttons that open it or put
//! it in place, and its table. Shared by every tab of the window.

use eframe::egui;
use linkage::SceneFile;

use crate::i18n::tr;
use crate::synthesis::Design;
use crate::ui::control_map::{ControlKind, ControlMap};

/// What to do with a design.
pub enum Chosen {
    /// Open it as a new scene.
    Open(SceneFile),
    /// Put it in place of the current scene (undo-able).
    Replace(SceneFile),
}

/// A design: its figure, the buttons that open it or put it in place, and its
/// table; returns what was asked.
pub fn design_view(
    ui: &mut egui::Ui,
    controls: &mut ControlMap,
    design: &Design,
) -> Option<Chosen> {
    crate::ui::synthesis::figure::figure(ui, &design.figure);
    let chosen = ui
        .horizontal(|ui| {
            let open = ui.button(tr!("synth.open"));
            controls.note(ui, ControlKind::FileButton, "Open as scene", &open);
            let replace = ui.button(tr!("synth.replace"));
            controls.note(ui, ControlKind::FileButton, "Replace this scene", &replace);
            if open.clicked() {
                Some(Chosen::Open(design.scene.clone()))
            } else {
                replace
                    .clicked()
                    .then(|| Chosen::Replace(design.scene.clone()))
            }
        })
        .inner;
    egui::Grid::new("design table")
        .striped(true)
        .show(ui, |ui| {
            for (what, value) in &design.table {
                ui.label(what);
                ui.label(value);
                ui.end_row();
            }
        });
    chosen
}
