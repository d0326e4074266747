//! The polygon pane: the velocity and acceleration polygons of the current position as
//! the textbooks draw them, laid out by `linkage-diagram` (the same layout the
//! exported sheet uses): fitted to the pane with a round scale bar, arrow heads in
//! pixels, typeset labels placed clear of each other, coincident points under one
//! label. Hovering an arrow names it with its magnitude and direction and marks its
//! row in the vector-equation table; hovering a row marks the arrow.

use eframe::egui::{self, Color32, Pos2, Sense, Stroke, Vec2};
use linkage::polygon::{Quantity, Symbol, VectorEquation};
use linkage_diagram::label::Label;
use linkage_diagram::layout::{LaidPolygon, Sizes, layout_polygon_fitting};
use linkage_diagram::{PolygonFigure, Rect};

use crate::app::AppState;
use crate::ui::control_map::ControlKind;
use crate::ui::typeset::galley;

/// Label size in the figures, points.
const FONT: f32 = 13.0;
/// The figure's background: paper, in either theme.
pub const PAPER: Color32 = Color32::from_rgb(252, 252, 248);
/// The figure's black.
pub const INK: Color32 = Color32::from_gray(25);
/// An arrow this close to the pointer (points) is the hovered one.
const HOVER_PX: f32 = 6.0;

/// The polygon pane.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    ui.horizontal(|ui| {
        ui.heading("Polygons");
        let (text, tip) = match (st.polygons_wide, st.layout.compact()) {
            (true, _) => ("narrower", "Give the mechanism its room back"),
            (false, false) => ("enlarge", "Polygons and mechanism share the window equally"),
            (false, true) => ("enlarge", "Give the sheet the larger part of the screen"),
        };
        let button = ui.button(text).on_hover_text(tip);
        st.controls
            .note(ui, ControlKind::PolygonLayout, text, &button);
        if button.clicked() {
            st.polygons_wide = !st.polygons_wide;
        }
    });
    let before = st.polygon_hover.take();
    let mut hovered = None;
    let s = &st.session;
    for q in [Quantity::Velocity, Quantity::Acceleration] {
        ui.strong(title(q));
        let fig = PolygonFigure::of_position(q, s.mechanism(), s.pose(), s.polygons());
        let over_figure = figure(ui, &fig, before.as_ref());
        let over_table = egui::CollapsingHeader::new(format!("{}: vector equations", title(q)))
            .default_open(false)
            .show(ui, |ui| table(ui, s.polygons(), q, before.as_ref()))
            .body_returned
            .flatten();
        hovered = hovered.or(over_figure).or(over_table);
    }
    st.polygon_hover = hovered;
    egui::CollapsingHeader::new("Construct an equation step by step")
        .default_open(false)
        .show(ui, |ui| crate::ui::construction::section(ui, st));
}

fn title(q: Quantity) -> &'static str {
    match q {
        Quantity::Velocity => "Velocity polygon",
        Quantity::Acceleration => "Acceleration polygon",
    }
}

fn rgb(c: [u8; 3]) -> Color32 {
    Color32::from_rgb(c[0], c[1], c[2])
}

/// A figure point (pixels) as an egui position.
pub fn pos(p: [f64; 2]) -> Pos2 {
    Pos2::new(p[0] as f32, p[1] as f32)
}

/// A figure's pane: the width available, about 3:4, drawn on paper in either theme
/// so that the figure looks as it will on the sheet.
pub struct Paper {
    /// Its rectangle.
    pub rect: egui::Rect,
    /// Pointer interaction over it (hover).
    pub response: egui::Response,
    /// A painter clipped to it.
    pub painter: egui::Painter,
}

impl Paper {
    /// Allocates the pane in `ui` and paints the paper.
    pub fn new(ui: &mut egui::Ui) -> Self {
        let w = ui.available_width().max(160.0);
        let h = (w * 0.72).clamp(160.0, 560.0);
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
    pub fn lay_out(&self, fig: &PolygonFigure, fit: Option<Rect>) -> LaidPolygon {
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

/// Draws one polygon filling the pane's width; returns the symbol of the arrow under
/// the pointer. `marked` is the term hovered last frame (here or in the table).
fn figure(ui: &mut egui::Ui, fig: &PolygonFigure, marked: Option<&Symbol>) -> Option<Symbol> {
    let paper = Paper::new(ui);
    let laid = paper.lay_out(fig, None);
    let Paper {
        rect,
        response,
        painter,
    } = paper;
    let ink = INK;
    if laid.px_per_unit <= 0.0 {
        painter.text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            "at rest: the polygon is a point",
            egui::FontId::proportional(12.0),
            ink,
        );
        return None;
    }
    let near = response.hover_pos().and_then(|p| nearest_arrow(&laid, p));
    let lit = near.or_else(|| marked.and_then(|m| fig.arrows.iter().position(|a| &a.symbol == m)));
    draw(&painter, fig, &laid, lit, ink);
    let arrow = &fig.arrows[near?];
    let symbol = arrow.symbol.clone();
    let v = [arrow.to[0] - arrow.from[0], arrow.to[1] - arrow.from[1]];
    response.on_hover_ui_at_pointer(|ui| {
        let ink = ui.visuals().text_color();
        ui.label(crate::ui::typeset::job(
            &Label::of_symbol(&symbol),
            15.0,
            ink,
        ));
        ui.label(format!(
            "{:.4} {} at {:.2}°",
            v[0].hypot(v[1]),
            fig.unit(),
            v[1].atan2(v[0]).to_degrees()
        ));
    });
    Some(symbol)
}

/// The arrow within [`HOVER_PX`] of `p`, the nearest.
fn nearest_arrow(laid: &LaidPolygon, p: Pos2) -> Option<usize> {
    laid.arrows
        .iter()
        .map(|a| {
            let (s, e) = (pos(a.from), pos(a.to));
            let d = e - s;
            let t = ((p - s).dot(d) / d.length_sq().max(1e-6)).clamp(0.0, 1.0);
            ((s + d * t).distance(p), a.index)
        })
        .filter(|(d, _)| *d <= HOVER_PX)
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, i)| i)
}

/// Draws a laid-out figure: arrows, points, labels, scale bar; `lit` drawn thicker.
pub fn draw(
    painter: &egui::Painter,
    fig: &PolygonFigure,
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
            linkage_diagram::layout::LabelOwner::Arrow(i) => rgb(fig.arrows[i].style.rgb()),
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
            format!(
                "{} {}",
                linkage_diagram::svg::round_text(bar.value),
                fig.unit()
            ),
            egui::FontId::proportional(12.0),
            ink,
        );
    }
}

/// The vector-equation table of `q`, typeset; the `marked` term's row highlighted.
/// Returns the symbol of the row under the pointer.
fn table(
    ui: &mut egui::Ui,
    equations: &[VectorEquation],
    q: Quantity,
    marked: Option<&Symbol>,
) -> Option<Symbol> {
    let ink = ui.visuals().text_color();
    let highlight = ui.visuals().selection.bg_fill;
    let mut hovered = None;
    for (i, eq) in equations.iter().filter(|e| e.kind == q).enumerate() {
        ui.label(format!("{}:", eq.group));
        ui.label(crate::ui::typeset::job(&Label::of_equation(eq), 14.0, ink));
        egui::Grid::new((q, i)).striped(true).show(ui, |ui| {
            for head in ["term", "magnitude", "direction", "known"] {
                ui.strong(head);
            }
            ui.end_row();
            for t in eq.lhs.iter().chain(&eq.rhs) {
                let on = marked == Some(&t.symbol);
                let mut job = crate::ui::typeset::job(&Label::of_symbol(&t.symbol), 14.0, ink);
                if on {
                    job.sections
                        .iter_mut()
                        .for_each(|s| s.format.background = highlight);
                }
                let cell = |text: String| {
                    let r = egui::RichText::new(text);
                    if on { r.background_color(highlight) } else { r }
                };
                let known = |k: bool| if k { "known" } else { "solved" };
                let row = [
                    ui.label(job),
                    ui.label(cell(format!(
                        "{:.4} {}",
                        t.magnitude,
                        linkage_diagram::polygon_figure::unit(q)
                    ))),
                    ui.label(cell(format!(
                        "{:.2}° ({})",
                        t.direction_rad.to_degrees(),
                        t.direction
                    ))),
                    ui.label(cell(format!(
                        "magnitude {}, direction {}",
                        known(t.magnitude_known),
                        known(t.direction_known)
                    ))),
                ];
                if row.iter().any(egui::Response::hovered) {
                    hovered = Some(t.symbol.clone());
                }
                ui.end_row();
            }
        });
    }
    hovered
}
