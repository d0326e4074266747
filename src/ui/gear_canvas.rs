//! Where the gear lab draws, shared by its two views (the cutting in
//! `ui/gear_lab.rs`, the meshing pair in `ui/gear_pair.rs`): the canvas's painter
//! and rectangle, the shapes' list and the GPU pass.

use eframe::egui;

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
