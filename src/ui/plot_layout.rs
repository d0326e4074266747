//! How the plot pane lays out several plots: side by side where it is wide enough,
//! else one under another (a phone's sheet); and the value range a plot shows.
//! Shared by every tab.

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

/// The y range that holds the middle 96 % of the values, padded by a tenth: near a
/// dead point velocities and accelerations grow without bound, and fitting the plot
/// to those spikes would flatten the rest of the cycle into a line.
pub fn robust_range(data: &[[f64; 2]]) -> [f64; 2] {
    let mut ys: Vec<f64> = data
        .iter()
        .map(|p| p[1])
        .filter(|y| y.is_finite())
        .collect();
    if ys.is_empty() {
        return [-1.0, 1.0];
    }
    ys.sort_by(f64::total_cmp);
    let at = |q: f64| ys[((ys.len() - 1) as f64 * q).round() as usize];
    let (lo, hi) = (at(0.02), at(0.98));
    let pad = 0.1
        * (hi - lo)
            .max(1e-9 * hi.abs().max(lo.abs()))
            .max(f64::MIN_POSITIVE);
    [lo - pad, hi + pad]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn robust_range_ignores_dead_point_spikes() {
        let mut data: Vec<[f64; 2]> = (0..100)
            .map(|i| [f64::from(i), f64::from(i % 10)])
            .collect();
        data.push([100.0, 1e12]);
        data.push([101.0, f64::NAN]);
        let [lo, hi] = robust_range(&data);
        assert!(lo < 0.0 && hi > 9.0 && hi < 11.0, "{lo} {hi}");
        assert_eq!(robust_range(&[]), [-1.0, 1.0]);
        let [lo, hi] = robust_range(&[[0.0, 5.0]]);
        assert!(lo < 5.0 && hi > 5.0);
    }
}
