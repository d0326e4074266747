//! How the panels are arranged for the screen at hand. On a desktop screen the
//! controls, polygons, plots and report sit around the mechanism view; on a phone or
//! a tablet, or in a small window, that would leave the view a strip, so there the
//! view takes more than half the screen (above the rest when the screen stands, left
//! of it when it lies) and the panels share the rest as tabs of one sheet, with
//! controls sized for fingers (at least 40 points).

use eframe::egui;

/// The arrangement of the panels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub enum Arrangement {
    /// Panels around the view (a desktop screen).
    #[default]
    Wide,
    /// The view above a sheet of tabs (a phone or tablet held upright).
    Tall,
    /// The view beside a sheet of tabs (a tablet lying, a small window).
    Broad,
}

/// Smallest screen, in points, that keeps the panels around the view (a laptop's
/// browser, 1366 × 660, and up): there the panels' limits (`panel_budget`) leave the
/// view its share with every pane at its least size or larger. Below, the panes would
/// be squeezed under their least sizes, and the sheet of tabs serves better.
const WIDE_FROM: egui::Vec2 = egui::vec2(1280.0, 640.0);

/// Share of the screen's area the view takes in the compact arrangements.
pub const VIEW_SHARE: f32 = 0.54;

/// Space between the view and the sheet, points.
const GAP: f32 = 8.0;

/// Least height of a touch target, points.
pub const TOUCH: f32 = 40.0;

impl Arrangement {
    /// The arrangement for a screen of `size` points.
    pub fn for_screen(size: egui::Vec2) -> Self {
        if size.x >= WIDE_FROM.x && size.y >= WIDE_FROM.y {
            Self::Wide
        } else if size.y > size.x {
            Self::Tall
        } else {
            Self::Broad
        }
    }

    /// Whether the panels share a sheet of tabs.
    pub fn compact(self) -> bool {
        self != Self::Wide
    }

    /// The view's and the sheet's rectangles in `area` (what the top bar leaves of a
    /// screen of `screen` points), the view taking `share` of the screen's area
    /// ([`VIEW_SHARE`] unless the user gave the sheet more) where the sheet keeps
    /// room for its tabs and a few rows.
    pub fn split(
        self,
        area: egui::Rect,
        screen: egui::Vec2,
        share: f32,
    ) -> (egui::Rect, egui::Rect) {
        let want = share * screen.x * screen.y;
        // The sheet keeps its tab row and two rows of touch targets.
        let least_sheet = 3.0 * TOUCH + 20.0;
        match self {
            Self::Tall | Self::Wide => {
                let h = (want / area.width())
                    .min(area.height() - least_sheet - GAP)
                    .max(0.0);
                let (view, sheet) = area.split_top_bottom_at_y(area.top() + h);
                (view, sheet.with_min_y(sheet.top() + GAP))
            }
            Self::Broad => {
                let w = (want / area.height())
                    .min(area.width() - least_sheet.max(260.0) - GAP)
                    .max(0.0);
                let (view, sheet) = area.split_left_right_at_x(area.left() + w);
                (view, sheet.with_min_x(sheet.left() + GAP))
            }
        }
    }
}

/// The tabs of the compact arrangements' sheet.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub enum SheetTab {
    /// Play, crank angle, lengths, springs, masses, branches (or, while drawing, the
    /// drawing tools).
    #[default]
    Controls,
    /// Velocity and acceleration polygons.
    Polygons,
    /// The plots.
    Plots,
    /// The report: Grashof class, K, strokes, swings, transmission angle.
    Report,
    /// Solver path, conditioning, cost; the integrator of dynamic scenes.
    Accuracy,
}

impl SheetTab {
    /// Every tab, in the order shown.
    pub const ALL: [Self; 5] = [
        Self::Controls,
        Self::Polygons,
        Self::Plots,
        Self::Report,
        Self::Accuracy,
    ];

    /// The tab's name in the control map (English, the tests' handle).
    pub fn label(self) -> &'static str {
        match self {
            Self::Controls => "Controls",
            Self::Polygons => "Polygons",
            Self::Plots => "Plots",
            Self::Report => "Report",
            Self::Accuracy => "Accuracy",
        }
    }

    /// The tab's name as shown, in the app's language.
    pub fn shown(self) -> String {
        match self {
            Self::Controls => crate::i18n::tr!("tab.controls"),
            Self::Polygons => crate::i18n::tr!("tab.polygons"),
            Self::Plots => crate::i18n::tr!("tab.plots"),
            Self::Report => crate::i18n::tr!("tab.report"),
            Self::Accuracy => crate::i18n::tr!("tab.accuracy"),
        }
    }
}

/// The arrangement in use and the sheet's tab.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LayoutState {
    /// The arrangement of the last frame.
    pub arrangement: Arrangement,
    /// The sheet's tab shown.
    pub tab: SheetTab,
    /// Whether the polygons are enlarged: on a desktop screen their pane as wide as
    /// the view's share allows, on a phone or tablet each figure the sheet's full
    /// width (the sheet scrolls) instead of fitted to the sheet's height.
    pub polygons_wide: bool,
    /// Counts "reset layout": the panels' ids carry it, so that a reset starts them
    /// afresh at their default sizes (egui remembers a panel's size by its id).
    pub generation: u32,
    /// Whether the style was set for the arrangement (the first frame sets it).
    styled: bool,
}

impl LayoutState {
    /// Chooses the arrangement for the screen and, when it changes, the style that
    /// goes with it; returns whether it changed (the view is then fitted anew).
    pub fn update(&mut self, ctx: &egui::Context) -> bool {
        let now = Arrangement::for_screen(ctx.content_rect().size());
        if self.styled && now == self.arrangement {
            return false;
        }
        self.arrangement = now;
        self.styled = true;
        ctx.all_styles_mut(|s| style_for(s, now));
        true
    }

    /// Whether the panels share a sheet of tabs.
    pub fn compact(&self) -> bool {
        self.arrangement.compact()
    }

    /// Back to the panels' default sizes, the polygons not enlarged.
    pub fn reset(&mut self) {
        self.generation = self.generation.wrapping_add(1);
        self.polygons_wide = false;
    }

    /// A panel's id: its name, the layout's generation, and whether the polygons
    /// are enlarged (the enlarged layout keeps its own sizes, so that "narrower"
    /// gives back the sizes the user had).
    pub fn panel_id(&self, name: &'static str) -> (&'static str, u32, bool) {
        (name, self.generation, self.polygons_wide)
    }
}

/// Spacing and text for an arrangement: egui's defaults on a desktop screen; on a
/// touch screen, targets at least [`TOUCH`] points high, sliders wide enough to
/// drag with a finger, and text a little larger.
fn style_for(s: &mut egui::Style, arrangement: Arrangement) {
    s.spacing = egui::style::Spacing::default();
    s.text_styles = egui::style::default_text_styles();
    if !arrangement.compact() {
        return;
    }
    let sp = &mut s.spacing;
    sp.interact_size = egui::vec2(TOUCH, TOUCH);
    sp.button_padding = egui::vec2(12.0, 8.0);
    sp.item_spacing = egui::vec2(10.0, 8.0);
    sp.icon_width = 24.0;
    sp.icon_width_inner = 14.0;
    sp.slider_width = 180.0;
    sp.slider_rail_height = 10.0;
    sp.combo_width = 200.0;
    for (style, font) in s.text_styles.iter_mut() {
        if matches!(
            style,
            egui::TextStyle::Body | egui::TextStyle::Button | egui::TextStyle::Monospace
        ) {
            font.size = 15.0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against the devices: phones and tablets either way, a small window,
    /// get the sheet; a desktop screen keeps the panels around the view.
    #[test]
    fn phones_tablets_and_small_windows_get_the_sheet() {
        let at = |w: f32, h: f32| Arrangement::for_screen(egui::vec2(w, h));
        assert_eq!(at(390.0, 844.0), Arrangement::Tall);
        assert_eq!(at(430.0, 932.0), Arrangement::Tall);
        assert_eq!(at(768.0, 1024.0), Arrangement::Tall);
        assert_eq!(at(1024.0, 768.0), Arrangement::Broad);
        assert_eq!(at(800.0, 600.0), Arrangement::Broad);
        assert_eq!(at(1100.0, 700.0), Arrangement::Broad);
        assert_eq!(at(1280.0, 720.0), Arrangement::Wide);
        assert_eq!(at(1366.0, 660.0), Arrangement::Wide);
        assert_eq!(at(1366.0, 768.0), Arrangement::Wide);
        assert_eq!(at(1500.0, 950.0), Arrangement::Wide);
    }

    /// The view gets at least half the screen in both compact arrangements, whatever
    /// the top bar takes of it (up to three rows of touch targets).
    #[test]
    fn the_view_gets_more_than_half_the_screen() {
        for (w, h) in [
            (390.0, 844.0),
            (430.0, 932.0),
            (768.0, 1024.0),
            (1024.0, 768.0),
            (800.0, 600.0),
        ] {
            let screen = egui::vec2(w, h);
            let arrangement = Arrangement::for_screen(screen);
            for bar in [TOUCH + 12.0, 2.0 * TOUCH + 20.0, 3.0 * TOUCH + 28.0] {
                let area = egui::Rect::from_min_max(egui::pos2(0.0, bar), egui::pos2(w, h));
                let (view, sheet) = arrangement.split(area, screen, VIEW_SHARE);
                let share = view.area() / (w * h);
                assert!(share >= 0.5, "{w}×{h} with a bar of {bar}: {share}");
                assert!(
                    sheet.height() >= 3.0 * TOUCH && sheet.width() >= 260.0,
                    "{sheet:?}"
                );
            }
        }
    }
}
