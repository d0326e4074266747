//! How a polygon figure is painted in the app: paper and ink, the fit of a laid-out
//! figure to a pane, and the arrows, points, labels and scale bar. Used by the
//! polygon pane and by the step-by-step construction.

use eframe::egui::{self, Color32, Pos2, Sense, Stroke, Vec2};
use linkage_diagram::Rect;
use linkage_diagram::label::Label;
use linkage_diagram::layout::{Figure, LaidPolygon, Sizes, layout_polygon_fitting};

use crate::ui::typeset::galley;

/// The lowest a figure is drawn, points: below, its labels would cover it.
const LEAST_HEIGHT: f32 = 120.0;

/// Label size in the figures, points.
pub(crate) const FONT: f32 = 13.0;
/// The figure's background: paper, in either theme.
pub const PAPER: Color32 = Color32::from_rgb(252, 252, 248);
/// The figure's black.
pub const INK: Color32 = Color32::from_gray(25);
fn rgb(c: [u8; 3]) -> Color32 {
    Color32::from_rgb(c[0], c[1], c[2])
}

/// A figure point (pixels) as an egui position.
pub fn pos(p: [f64; 2]) -> Pos2 {
    Pos2::new(p[0] as f32, p[1] as f32)
}

/// A figure's pane: the width available, about 3:4 (lower where the pane that holds
/// it is lower), drawn on paper in either theme so that the figure looks as it will
/// on the sheet.
pub struct Paper {
    /// Its rectangle.
    pub rect: egui::Rect,
    /// Pointer interaction over it (hover).
    pub response: egui::Response,
    /// A painter clipped to it.
    pub painter: egui::Painter,
}

impl Paper {
    /// Allocates the pane in `ui`, at most `max_height` high (so that a figure fits
    /// the pane it is shown in), and paints the paper.
    pub fn new(ui: &mut egui::Ui, max_height: f32) -> Self {
        let w = ui.available_width().max(160.0);
        let h = (w * 0.72)
            .clamp(160.0, 560.0)
            .min(max_height.max(LEAST_HEIGHT));
        let (rect, response) = ui.allocate_exact_size(Vec2::new(w, h), Sense::hover());
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 4.0, PAPER);
        Self {
            rect,
            response,
            painter,
        }
    }

    /// `fig` laid out on it, labels measured as egui sets them; scaled by `fit`
    /// (figure units) if given, else by the figure's own extent.
    pub fn lay_out(&self, fig: &dyn Figure, fit: Option<Rect>) -> LaidPolygon {
        let measure = |l: &Label| {
            let g = galley(&self.painter, l, FONT, INK);
            [f64::from(g.size().x), f64::from(g.size().y)]
        };
        let pane = Rect {
            min: [f64::from(self.rect.min.x), f64::from(self.rect.min.y)],
            max: [f64::from(self.rect.max.x), f64::from(self.rect.max.y)],
        };
        let sizes = Sizes {
            font_px: f64::from(FONT),
            head_px: 9.0,
        };
        layout_polygon_fitting(fig, fit, pane, sizes, &measure)
    }
}

/// Draws a laid-out figure: arrows, points, labels, and the scale bar in `unit`;
/// `lit` drawn thicker.
pub fn draw(
    painter: &egui::Painter,
    unit: &str,
    laid: &LaidPolygon,
    lit: Option<usize>,
    ink: Color32,
) {
    for a in &laid.arrows {
        let c = rgb(a.style.rgb());
        let width = match (Some(a.index) == lit, a.style.dashed()) {
            (true, _) => 3.2,
            (false, true) => 1.3,
            (false, false) => 1.8,
        };
        let (s, e) = (pos(a.from), pos(a.to));
        if a.style.dashed() {
            painter.extend(egui::Shape::dashed_line(
                &[s, e],
                Stroke::new(width, c),
                5.0,
                3.0,
            ));
        } else {
            painter.line_segment([s, e], Stroke::new(width, c));
        }
        if let Some(h) = a.head {
            painter.add(egui::Shape::convex_polygon(
                h.iter().map(|&p| pos(p)).collect(),
                c,
                Stroke::NONE,
            ));
        }
    }
    for &v in &laid.vertices {
        painter.circle_filled(pos(v), 2.5, ink);
    }
    for l in &laid.labels {
        let colour = match l.owner {
            linkage_diagram::layout::LabelOwner::Arrow(i) => laid
                .arrows
                .iter()
                .find(|a| a.index == i)
                .map_or(ink, |a| rgb(a.style.rgb())),
            linkage_diagram::layout::LabelOwner::Vertices(_) => ink,
        };
        if let Some([a, b]) = l.leader {
            painter.line_segment([pos(a), pos(b)], Stroke::new(0.7, Color32::from_gray(150)));
        }
        painter.galley(
            pos(l.rect.min),
            galley(painter, &l.label, FONT, colour),
            colour,
        );
    }
    if let Some(bar) = &laid.scale_bar {
        let (a, b) = (pos(bar.from), pos(bar.to));
        painter.line_segment([a, b], Stroke::new(2.0, ink));
        for end in [a, b] {
            painter.line_segment(
                [end - Vec2::Y * 3.0, end + Vec2::Y * 3.0],
                Stroke::new(1.0, ink),
            );
        }
        painter.text(
            b + Vec2::new(6.0, 0.0),
            egui::Align2::LEFT_CENTER,
            linkage_diagram::numbers::si(bar.value, unit),
            egui::FontId::proportional(12.0),
            ink,
        );
    }
}
