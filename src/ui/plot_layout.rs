//! How the plot pane lays out several plots: side by side where it is wide enough,
//! else one under another (a phone's sheet). Shared by every tab.

use eframe::egui;

/// Narrowest a plot is drawn beside another, points: below, plots stand one under
/// another (a phone's sheet), each [`STACKED_HEIGHT`] high.
const LEAST_WIDTH: f32 = 200.0;
/// Height of a plot in a stack, points.
const STACKED_HEIGHT: f32 = 200.0;

/// Lays out `n` plots side by side where the pane is wide enough, else one under
/// another; `draw(ui, i, height)` draws the `i`-th, `height` high.
pub fn side_by_side(ui: &mut egui::Ui, n: usize, mut draw: impl FnMut(&mut egui::Ui, usize, f32)) {
    if ui.available_width() >= LEAST_WIDTH * n as f32 {
        let height = ui.available_height().max(80.0);
        ui.columns(n, |cols| {
            for (i, col) in cols.iter_mut().enumerate() {
                draw(col, i, height);
            }
        });
    } else {
        for i in 0..n {
            draw(ui, i, STACKED_HEIGHT);
        }
    }
}
