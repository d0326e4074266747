//! What the gear lab's two views share (the cutting in `ui/gear_lab.rs`, the meshing
//! pair in `ui/gear_pair.rs`): where they draw (the canvas's painter and rectangle,
//! the shapes' list and the GPU pass) and the Play button.

use eframe::egui;

use crate::gear_lab::GearLab;
use crate::i18n::tr;
use crate::render::Renderer;
use crate::render::shape::SharedShapes;

/// Where the lab draws: the canvas's painter and rectangle, the shapes' list and
/// the GPU pass.
pub struct Canvas<'a> {
    /// The canvas's painter (egui's texts over the GPU's shapes).
    pub painter: &'a egui::Painter,
    /// The canvas.
    pub rect: egui::Rect,
    /// The shapes the GPU pass draws.
    pub shapes: &'a SharedShapes,
    /// The GPU pass, where there is one.
    pub renderer: Option<&'a Renderer>,
    /// Physical pixels per point.
    pub pixels_per_point: f32,
}

impl Canvas<'_> {
    /// Paints the shapes through `camera`.
    pub fn paint(&self, camera: &crate::render::view::Camera) {
        let view = camera.uniform(self.rect, self.pixels_per_point);
        crate::ui::viewport::paint_shapes(
            self.painter,
            self.rect,
            view,
            self.shapes,
            self.renderer,
        );
    }
}

/// Play or Pause, for the roll or the pair's turn.
pub fn play_button(ui: &mut egui::Ui, lab: &mut GearLab) {
    let label = if lab.playing {
        tr!("gear.pause")
    } else {
        tr!("gear.play")
    };
    if ui.button(label).clicked() {
        lab.toggle_play();
    }
}
