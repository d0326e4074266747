//! How the plot pane lays out several plots: side by side where it is wide enough,
//! else one under another (a phone's sheet); and the value range a plot shows.
//! Shared by every tab.

use eframe::egui;

/// Narrowest a plot is drawn beside another, points: below, plots stand one under
/// another (a phone's sheet). A cam's s, v, a and j stand side by side in a laptop's
/// plot pane (771 points at 1366×768) with their ticks 0…360 read.
const LEAST_WIDTH: f32 = 180.0;
/// The lowest a plot is drawn, points: its axis titles, four labelled ticks and its
/// curve read. Down to this the plots fit the pane (a plot a few points taller than
/// the pane hid its axis title below the pane's edge, the flywheel tab at 1366×768);
/// a pane lower still scrolls instead of squashing its plots.
pub const LEAST_HEIGHT: f32 = 120.0;
/// The highest a plot in a stack is drawn, points (a phone's sheet shows the next
/// one's top below it).
const STACKED_HEIGHT: f32 = 260.0;
/// Room right of a plot, points, for half its last tick's label ("360").
const TICK_ROOM: f32 = 12.0;
/// How far beyond the middle 90 % of a curve's values, in that range's spreads, its
/// extremes may lie and still be shown: further, they are a dead point's spike.
const SPIKE: f64 = 1.0;

/// Lays out `n` plots side by side where the pane is wide enough, else one under
/// another; `draw(ui, i, height)` draws the `i`-th, `height` high: the room left in
/// the pane's view (inside its scroll area, `ui`'s available height), never less than
/// [`LEAST_HEIGHT`].
pub fn side_by_side(ui: &mut egui::Ui, n: usize, mut draw: impl FnMut(&mut egui::Ui, usize, f32)) {
    // The last tick's label is centred on the plot's right edge: room for its half.
    let mut draw = |ui: &mut egui::Ui, i: usize, height: f32| {
        let drawn = ui.scope(|ui| {
            ui.set_max_width(ui.available_width() - TICK_ROOM);
            draw(ui, i, height);
        });
        note_drawn(ui, drawn.response.rect);
    };
    let room = ui.available_height() - ui.spacing().item_spacing.y;
    if ui.available_width() >= LEAST_WIDTH * n as f32 {
        let height = room.max(LEAST_HEIGHT);
        ui.columns(n, |cols| {
            for (i, col) in cols.iter_mut().enumerate() {
                draw(col, i, height);
            }
        });
    } else {
        let height = room.clamp(LEAST_HEIGHT, STACKED_HEIGHT);
        for i in 0..n {
            draw(ui, i, height);
        }
    }
}

/// A plot drawn this frame: its rectangle (axes and titles included) and the part of
/// the pane it is seen through.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrawnPlot {
    /// The plot with its axes.
    pub rect: egui::Rect,
    /// What the pane shows of the plot's scroll area.
    pub seen: egui::Rect,
}

/// The plots of one frame, with that frame's number.
#[derive(Clone, Debug, Default)]
struct DrawnPlots {
    frame: u64,
    plots: Vec<DrawnPlot>,
}

fn drawn_id() -> egui::Id {
    egui::Id::unique("plot_layout::drawn")
}

/// Notes a plot drawn at `rect` in `ui`'s frame.
fn note_drawn(ui: &egui::Ui, rect: egui::Rect) {
    let frame = ui.ctx().cumulative_frame_nr();
    let seen = ui.clip_rect();
    ui.ctx().data_mut(|d| {
        let drawn = d.get_temp_mut_or_default::<DrawnPlots>(drawn_id());
        if drawn.frame != frame {
            *drawn = DrawnPlots {
                frame,
                plots: Vec::new(),
            };
        }
        drawn.plots.push(DrawnPlot { rect, seen });
    });
}

/// The plots drawn in the last frame that drew any (tests check that none is cut by
/// the pane's edge).
pub fn drawn_plots(ctx: &egui::Context) -> Vec<DrawnPlot> {
    ctx.data(|d| d.get_temp::<DrawnPlots>(drawn_id()))
        .map(|d| d.plots)
        .unwrap_or_default()
}

/// The y range a plot shows, padded by a tenth: every value where the extremes lie
/// within [`SPIKE`] times the middle 90 %'s spread of it (a quick-return's peak
/// acceleration is shown, not cut), else the middle 90 % alone: near a dead point
/// velocities and accelerations grow without bound, and fitting the plot to those
/// spikes would flatten the rest of the cycle into a line (the flipper's
/// acceleration rises over its last 3 % of samples to 7000 deg/s², beside 100 for
/// the rest).
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
    let (mut lo, mut hi) = (at(0.05), at(0.95));
    let (least, most) = (ys[0], ys[ys.len() - 1]);
    let spread = hi - lo;
    if least >= lo - SPIKE * spread && most <= hi + SPIKE * spread {
        (lo, hi) = (least, most);
    }
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
        // A peak beyond the middle 90 % but not a spike (a quick-return's
        // acceleration) is shown whole.
        let mut data: Vec<[f64; 2]> = (0..100)
            .map(|i| [f64::from(i), f64::from(i % 10)])
            .collect();
        data.push([100.0, -8.0]);
        let [lo, hi] = robust_range(&data);
        assert!(lo < -8.0 && hi > 9.0, "{lo} {hi}");
    }
}
