//! How large the desktop arrangement's panels may grow. The controls, the polygons
//! and the plots sit around the mechanism view; each may be dragged wider or taller,
//! and their contents (an opened table, a plot tab with four plots) ask for more
//! room, but together they never take the view below [`VIEW_LEAST_SHARE`] of the
//! window. egui lays the panels out one after another (controls, polygons, plots),
//! so each panel's limit is worked out from what the ones before it left: the view
//! keeps its share whatever the user does with the panels, at any window size.

use eframe::egui::{Rangef, Rect, Vec2};

/// The least share of the window's area the mechanism view keeps on a desktop screen
/// (the layout test asserts 35 %; the budget keeps a little more).
pub const VIEW_LEAST_SHARE: f32 = 0.36;

/// The controls pane: its default width, the least it keeps, and the largest share
/// of the window's width it may take.
const CONTROLS: (f32, f32, f32) = (260.0, 190.0, 0.3);
/// The polygon pane: default and least width.
const POLYGONS: (f32, f32) = (300.0, 220.0);
/// The plot pane: default and least height (its tab row and a plot whose axes read).
const PLOTS: (f32, f32) = (240.0, 180.0);

/// A panel's limits: its size at first, and the range the user and its contents may
/// move it in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PanelLimits {
    /// The size before the user drags it.
    pub default: f32,
    /// Least and largest size.
    pub range: Rangef,
}

impl PanelLimits {
    /// `default` within `least..=most`, where `most` (what the view leaves) wins over
    /// `least` in a window too small for both.
    fn new(default: f32, least: f32, most: f32) -> Self {
        let most = most.max(0.0);
        let least = least.min(most);
        Self {
            default: default.clamp(least, most),
            range: Rangef::new(least, most),
        }
    }

    /// The limits as the size itself (an enlarged pane takes all it may).
    pub fn largest(self) -> f32 {
        self.range.max
    }
}

/// The margin the view's panel keeps around it, both sides together, points.
const VIEW_MARGIN: f32 = 16.0;

/// The area the view must keep in a window of `window` points.
fn least_view_area(window: Vec2) -> f32 {
    VIEW_LEAST_SHARE * window.x * window.y
}

/// The width the view's panel needs to keep the view its share, `height` high.
fn view_panel_width(window: Vec2, height: f32) -> f32 {
    least_view_area(window) / (height - VIEW_MARGIN).max(1.0) + VIEW_MARGIN
}

/// The height the view's panel needs, `width` wide.
fn view_panel_height(window: Vec2, width: f32) -> f32 {
    least_view_area(window) / (width - VIEW_MARGIN).max(1.0) + VIEW_MARGIN
}

/// The controls pane on the left of `area` (what the top bar and the report strip
/// leave): it leaves room for the least polygon pane and a view of its share above
/// the least plot pane.
pub fn controls(area: Rect, window: Vec2) -> PanelLimits {
    let (default, least, share) = CONTROLS;
    let view_width = view_panel_width(window, area.height() - PLOTS.1);
    let most = (share * window.x).min(area.width() - POLYGONS.1 - view_width);
    PanelLimits::new(default, least, most)
}

/// The polygon pane on the right of `rest` (what the controls left): the view beside
/// it keeps its share above the least plot pane.
pub fn polygons(rest: Rect, window: Vec2) -> PanelLimits {
    let (default, least) = POLYGONS;
    let view_width = view_panel_width(window, rest.height() - PLOTS.1);
    PanelLimits::new(default, least, rest.width() - view_width)
}

/// The plot pane at the bottom of `rest` (what the side panes left): the view above
/// it keeps its share.
pub fn plots(rest: Rect, window: Vec2) -> PanelLimits {
    let (default, least) = PLOTS;
    let view_height = view_panel_height(window, rest.width());
    PanelLimits::new(default, least, rest.height() - view_height)
}

#[cfg(test)]
mod tests {
    use super::*;
    use eframe::egui::{pos2, vec2};

    /// Every panel at its largest, at the layout test's desktop sizes (and a laptop's
    /// browser, 1366 × 660) with a top bar of two rows: the view keeps its
    /// share and every pane its least size.
    #[test]
    fn the_view_keeps_its_share_with_every_panel_at_its_largest() {
        for (w, h) in [
            (1280.0, 640.0),
            (1280.0, 720.0),
            (1366.0, 660.0),
            (1366.0, 768.0),
            (1920.0, 1080.0),
            (2560.0, 1440.0),
            (3840.0, 2160.0),
        ] {
            let window = vec2(w, h);
            for bars in [50.0, 60.0] {
                let area = Rect::from_min_max(pos2(0.0, bars), pos2(w, h - 28.0));
                let left = controls(area, window).largest();
                let rest = area.with_min_x(area.min.x + left);
                let right = polygons(rest, window).largest();
                let rest = rest.with_max_x(rest.max.x - right);
                let bottom = plots(rest, window).largest();
                let view = rest
                    .with_max_y(rest.max.y - bottom)
                    .shrink(VIEW_MARGIN / 2.0);
                let share = view.area() / (w * h);
                assert!(
                    share >= VIEW_LEAST_SHARE - 1e-4,
                    "{w}x{h}, bars {bars}: {share}"
                );
                let least = |v: f32, l: f32| v >= l - 1e-3;
                assert!(
                    least(left, CONTROLS.1) && least(right, POLYGONS.1),
                    "{w}x{h}: {left} {right}"
                );
                assert!(bottom >= PLOTS.1 - 1e-3, "{w}x{h}: plots {bottom}");
            }
        }
    }

    /// A window too small for the least panels: the view's share wins.
    #[test]
    fn in_a_small_window_the_view_wins_over_the_least_panels() {
        let window = vec2(700.0, 500.0);
        let area = Rect::from_min_max(pos2(0.0, 60.0), window.to_pos2());
        let c = controls(area, window);
        assert!(
            c.range.max < CONTROLS.1 && c.range.min <= c.range.max,
            "{c:?}"
        );
        assert!(c.default <= c.range.max);
    }
}
