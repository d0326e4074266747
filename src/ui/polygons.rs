//! The polygon pane: the velocity and acceleration polygons of the current position as
//! the textbooks draw them, laid out by `linkage-diagram` (the same layout the
//! exported sheet uses): fitted to the pane with a round scale bar, arrow heads in
//! pixels, typeset labels placed clear of each other, coincident points under one
//! label. Hovering an arrow names it with its magnitude and direction and marks its
//! row in the vector-equation table; hovering a row marks the arrow.

use eframe::egui::{self, Pos2};
use linkage::polygon::{Quantity, Symbol, VectorEquation};
use linkage_diagram::PolygonFigure;
use linkage_diagram::label::Label;
use linkage_diagram::layout::LaidPolygon;
use linkage_diagram::numbers;
use linkage_diagram::polygon_figure::title;

use crate::i18n::tr;
use crate::state::AppState;
use crate::ui::construction::ConstructionView;
use crate::ui::control_map::ControlKind;
use crate::ui::polygon_paint::{INK, Paper, draw, pos};

/// A section header of the pane or a figure, where it was drawn.
struct Section {
    kind: ControlKind,
    name: String,
    rect: egui::Rect,
    visible: bool,
}

impl Section {
    fn of(ui: &egui::Ui, name: String, header: &egui::Response) -> Self {
        Self {
            kind: ControlKind::Section,
            name,
            rect: header.rect,
            visible: ui.clip_rect().contains_rect(header.rect),
        }
    }

    /// A figure, in view where at least half of it shows.
    fn figure(ui: &egui::Ui, name: String, rect: egui::Rect) -> Self {
        let shown = ui.clip_rect().intersect(rect);
        Self {
            kind: ControlKind::Figure,
            name,
            rect,
            visible: shown.is_positive() && shown.area() >= 0.5 * rect.area(),
        }
    }
}

/// An arrow this close to the pointer (points) is the hovered one.
const HOVER_PX: f32 = 6.0;

/// On a phone or tablet, the figures stand side by side where the pane is this many
/// times wider than a figure may be high.
const SIDE_BY_SIDE: f32 = 1.4;

/// The polygon pane's own state.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonPane {
    /// The polygon term under the pointer last frame (in a figure or its table row).
    pub hover: Option<Symbol>,
    /// The equation being constructed step by step, and the step.
    pub construction: ConstructionView,
}

impl PolygonPane {
    /// The polygon pane: its heading and enlarge button, then the figures and
    /// tables, scrolled inside the pane. Each figure fits the pane's height (on a
    /// phone, one figure at a time in view) unless enlarged on a phone or tablet,
    /// where it takes the sheet's full width.
    pub fn ui(&mut self, ui: &mut egui::Ui, st: &mut AppState) {
        ui.horizontal(|ui| {
            ui.heading(tr!("polygons.heading"));
            // (the control map's English name, the text shown, the hint)
            let (id, text, tip) = match (st.layout.polygons_wide, st.layout.compact()) {
                (true, false) => (
                    "narrower",
                    tr!("polygons.narrower"),
                    tr!("polygons.narrower_hint"),
                ),
                (true, true) => ("fit", tr!("polygons.fit"), tr!("polygons.fit_hint")),
                (false, false) => (
                    "enlarge",
                    tr!("polygons.enlarge"),
                    tr!("polygons.enlarge_hint"),
                ),
                (false, true) => (
                    "enlarge",
                    tr!("polygons.enlarge"),
                    tr!("polygons.enlarge_sheet_hint"),
                ),
            };
            let button = ui.button(text).on_hover_text(tip);
            st.controls
                .note(ui, ControlKind::PolygonLayout, id, &button);
            if button.clicked() {
                st.layout.polygons_wide = !st.layout.polygons_wide;
            }
        });
        // A figure's title and the row of its table's header stay in view with it.
        let figure_height = if st.layout.compact() && st.layout.polygons_wide {
            f32::INFINITY
        } else {
            ui.available_height() - 2.0 * ui.spacing().interact_size.y - 8.0
        };
        // Both ways: what is wider than the pane (a long section title at its least
        // width) scrolls inside it rather than widening it off the window.
        let sections = egui::ScrollArea::both()
            .auto_shrink([false, true])
            .show(ui, |ui| self.figures(ui, st, figure_height))
            .inner;
        for s in sections {
            st.controls.note_rect(s.kind, &s.name, s.rect, s.visible);
        }
    }

    /// The figures, their tables, the construction and the force polygons; returns
    /// where each section's header and figure is (for the control map). On a phone
    /// or tablet both figures are in view: side by side where the pane is wider than
    /// a figure is high, else stacked at half the height each (before, each took the
    /// pane's height: on a phone the figure was a third of its box's width and the
    /// acceleration polygon below the fold).
    fn figures(&mut self, ui: &mut egui::Ui, st: &AppState, figure_height: f32) -> Vec<Section> {
        let mut sections = Vec::new();
        let before = self.hover.take();
        let mut hovered = None;
        let s = &st.session;
        let quantities = [Quantity::Velocity, Quantity::Acceleration];
        // On a phone or tablet both figures are in view: side by side where the pane
        // is wide, else one above the other at half the height each.
        let both = st.layout.compact() && !st.layout.polygons_wide;
        let side_by_side = both && ui.available_width() > SIDE_BY_SIDE * figure_height;
        let figure_height = if both && !side_by_side {
            0.5 * (figure_height - ui.spacing().interact_size.y)
        } else {
            figure_height
        };
        let show_figure = |ui: &mut egui::Ui, q: Quantity, sections: &mut Vec<Section>| {
            ui.strong(polygon_title(q));
            let fig = PolygonFigure::of_position(q, s.mechanism(), s.pose(), s.polygons());
            let (over, rect) = figure(ui, &fig, before.as_ref(), figure_height);
            sections.push(Section::figure(ui, title(q).to_owned(), rect));
            over
        };
        if side_by_side {
            hovered = ui.columns(2, |columns| {
                let mut over = None;
                for (column, q) in columns.iter_mut().zip(quantities) {
                    over = over.or(show_figure(column, q, &mut sections));
                }
                over
            });
        }
        for q in quantities {
            if !side_by_side {
                hovered = hovered.or(show_figure(ui, q, &mut sections));
            }
            // A table wider than the pane scrolls sideways instead of widening it.
            let name = format!("{}: vector equations", title(q));
            let shown =
                egui::CollapsingHeader::new(tr!("polygons.equations", polygon = polygon_title(q)))
                    .id_salt(("equations header", q))
                    .default_open(false)
                    .show(ui, |ui| {
                        egui::ScrollArea::horizontal()
                            .id_salt(("equations", q))
                            .show(ui, |ui| table(ui, s.polygons(), q, before.as_ref()))
                            .inner
                    });
            sections.push(Section::of(ui, name, &shown.header_response));
            hovered = hovered.or(shown.body_returned.flatten());
        }
        self.hover = hovered;
        let name = "Construct an equation step by step";
        let shown = egui::CollapsingHeader::new(tr!("polygons.construct"))
            .id_salt("construction header")
            .default_open(false)
            .show(ui, |ui| self.construction.ui(ui, st, figure_height));
        sections.push(Section::of(ui, name.to_owned(), &shown.header_response));
        crate::ui::force_polygons::section(ui, &st.session, figure_height);
        sections
    }
}

/// The polygon's name as the textbook has it, in the app's language.
fn polygon_title(q: Quantity) -> String {
    match q {
        Quantity::Velocity => tr!("polygons.velocity"),
        Quantity::Acceleration => tr!("polygons.acceleration"),
    }
}

/// Draws `fig` at most `height` high; returns the arrow under the pointer and the
/// figure's box.
fn figure(
    ui: &mut egui::Ui,
    fig: &PolygonFigure,
    marked: Option<&Symbol>,
    height: f32,
) -> (Option<Symbol>, egui::Rect) {
    let paper = Paper::new(ui, height);
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
            tr!("polygons.at_rest"),
            egui::FontId::proportional(12.0),
            ink,
        );
        return (None, rect);
    }
    let near = response.hover_pos().and_then(|p| nearest_arrow(&laid, p));
    let lit = near.or_else(|| marked.and_then(|m| fig.arrows.iter().position(|a| &a.symbol == m)));
    draw(&painter, fig.unit(), &laid, lit, ink);
    let Some(near) = near else {
        return (None, rect);
    };
    let arrow = &fig.arrows[near];
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
            "{} at {}",
            numbers::si(v[0].hypot(v[1]), fig.unit()),
            numbers::degrees(v[1].atan2(v[0]).to_degrees())
        ));
    });
    (Some(symbol), rect)
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
    let scale = linkage_diagram::polygon_figure::largest_of_kind(equations, q);
    for (i, eq) in equations.iter().filter(|e| e.kind == q).enumerate() {
        ui.label(format!("{}:", crate::ui::words::group(&eq.group)));
        ui.label(crate::ui::typeset::job(&Label::of_equation(eq), 14.0, ink));
        egui::Grid::new((q, i)).striped(true).show(ui, |ui| {
            for head in [
                tr!("table.term"),
                tr!("table.magnitude"),
                tr!("table.direction"),
                tr!("table.known"),
            ] {
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
                let known = |k: bool| {
                    if k {
                        tr!("table.is_known")
                    } else {
                        tr!("table.solved")
                    }
                };
                let row = [
                    ui.label(job),
                    ui.label(cell(numbers::si_beside(
                        t.magnitude,
                        scale,
                        linkage_diagram::polygon_figure::unit(q),
                    ))),
                    ui.label(cell(format!(
                        "{} ({})",
                        numbers::degrees(t.direction_rad.to_degrees()),
                        crate::ui::words::direction(&t.direction)
                    ))),
                    ui.label(cell(tr!(
                        "table.known_cell",
                        magnitude = known(t.magnitude_known),
                        direction = known(t.direction_known)
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
