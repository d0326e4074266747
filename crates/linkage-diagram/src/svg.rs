//! An A4 sheet of one position as plain SVG 1.1: title, the pose (with instant
//! centres if asked), the velocity and acceleration polygons side by side, each with
//! its scale bar, and the vector-equation tables. Text is text (searchable, editable
//! in Inkscape); symbols are set with `tspan` sub- and superscripts. Coordinates are
//! CSS pixels (96 per inch) and the sheet is sized in millimetres.

use linkage::force_polygon::ForcePolygons;
use linkage::instant_centres::{Centre, InstantCentres};
use linkage::polygon::{Quantity, VectorEquation};
use linkage::{Mechanism, Solution};

use crate::geometry::Rect;
use crate::label::{Label, Script};
use crate::layout::{Sizes, layout_polygon};
use crate::numbers::{degrees, si, si_beside, significant};
use crate::pages::{Pages, Sheet, heading};
use crate::polygon_figure::{self, PolygonFigure, unit};
use crate::pose_figure::PoseFigure;
use crate::pose_layout::{LaidPose, layout_pose};
use crate::svg_draw::{
    FONT, MARGIN, PAGE_W, circle, fit_text, frame, label_at, leaders_and_label, line, measure,
    polygon, polygon_shape, scale_bar, text_at, titled_pane,
};
use crate::words::{self, Lang, sw};

/// Which parts the sheet holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Parts {
    /// The mechanism's pose.
    pub pose: bool,
    /// The velocity polygon.
    pub velocity: bool,
    /// The acceleration polygon.
    pub acceleration: bool,
    /// Instant centres on the pose.
    pub centres: bool,
    /// The vector-equation tables.
    pub table: bool,
    /// The force polygons and their tables (when the position has them).
    pub forces: bool,
}

impl Default for Parts {
    fn default() -> Self {
        Self {
            pose: true,
            velocity: true,
            acceleration: true,
            centres: false,
            table: true,
            forces: false,
        }
    }
}

/// One position of a mechanism: what the sheet draws.
#[derive(Clone, Copy, Debug)]
pub struct Position<'a> {
    /// The mechanism.
    pub mechanism: &'a Mechanism,
    /// Its solution at the position.
    pub solution: &'a Solution,
    /// The polygon equations there.
    pub equations: &'a [VectorEquation],
    /// Its instant centres, if they are to be drawn.
    pub centres: Option<&'a InstantCentres>,
    /// Its force polygons, if they are to be drawn.
    pub forces: Option<&'a ForcePolygons>,
}

/// The sheet of `pos` with `parts` in `lang`, on as many A4 pages as it needs.
pub fn sheet(pos: &Position<'_>, parts: Parts, lang: Lang) -> Sheet {
    let sizes = Sizes {
        font_px: FONT,
        ..Sizes::default()
    };
    let m = pos.mechanism;
    let s = pos.solution;
    let title = sw!(
        lang,
        "sheet.position_title",
        name = m.name,
        input = degrees(s.input_rad.to_degrees()),
        omega = significant(s.input_speed_rad_s, 4)
    );
    let mut pages = Pages::new(&title);
    heading(&mut pages, &title, 16.0);
    if parts.pose {
        let centres = if parts.centres { pos.centres } else { None };
        let fig = PoseFigure::new(m, s, centres);
        let top = pages.place(POSE_H + 10.0);
        let pane = Rect::from_min_size([MARGIN, top], WIDTH, POSE_H);
        pose(&mut pages, &layout_pose(&fig, pane, sizes, &measure), lang);
    }
    polygons(&mut pages, pos, parts, sizes, lang);
    if parts.table {
        equation_tables(&mut pages, pos.equations, lang);
    }
    if parts.forces
        && let Some(fp) = pos.forces
    {
        crate::svg_forces::forces(&mut pages, m, fp, sizes, lang);
    }
    pages.finish()
}

/// The pose pane's height, px.
const POSE_H: f64 = 360.0;
/// A polygon pane's height, px.
const POLYGON_H: f64 = 320.0;
/// The width between the margins, px.
const WIDTH: f64 = PAGE_W - 2.0 * MARGIN;

/// The velocity and acceleration polygons asked for, side by side.
fn polygons(pages: &mut Pages, pos: &Position<'_>, parts: Parts, sizes: Sizes, lang: Lang) {
    let quantities: Vec<Quantity> = [
        (parts.velocity, Quantity::Velocity),
        (parts.acceleration, Quantity::Acceleration),
    ]
    .into_iter()
    .filter_map(|(on, q)| on.then_some(q))
    .collect();
    if quantities.is_empty() {
        return;
    }
    let top = pages.place(POLYGON_H + 10.0);
    let w = (WIDTH - 10.0 * (quantities.len() - 1) as f64) / quantities.len() as f64;
    for (i, &q) in quantities.iter().enumerate() {
        let fig = PolygonFigure::of_position(q, pos.mechanism, pos.solution, pos.equations);
        let pane = Rect::from_min_size([MARGIN + i as f64 * (w + 10.0), top], w, POLYGON_H);
        // The figure keeps clear of the pane's title.
        let title = words::polygon_title(lang, q);
        let below_title = titled_pane(pages.out(), &pane, &title, 13.0);
        polygon(
            pages.out(),
            fig.unit(),
            &layout_polygon(&fig, below_title, sizes, &measure),
            lang,
        );
    }
}

/// Draws the pose; the centres not drawn are listed below it, a line each.
pub(crate) fn pose(pages: &mut Pages, laid: &LaidPose, lang: Lang) {
    let out = pages.out();
    frame(out, &laid.pane);
    for l in &laid.links {
        if l.len() > 2 {
            polygon_shape(out, l, "#dde6f3", "#1e5aaa");
        } else if let [a, b] = l[..] {
            line(out, a, b, "#1e5aaa", 3.0, false);
        }
    }
    for &p in &laid.ground_pivots {
        let tri = [p, [p[0] - 7.0, p[1] + 11.0], [p[0] + 7.0, p[1] + 11.0]];
        polygon_shape(out, &tri, "#cccccc", "#333333");
        line(
            out,
            [p[0] - 10.0, p[1] + 11.0],
            [p[0] + 10.0, p[1] + 11.0],
            "#333333",
            1.5,
            false,
        );
    }
    for sl in &laid.sliders {
        polygon_shape(out, sl, "#f3e2c8", "#7a4a10");
    }
    for &j in &laid.joints {
        circle(out, j, 3.0, "white", "#000000");
    }
    for &c in &laid.centres {
        circle(out, c, 2.5, "#b0306a", "none");
    }
    for l in &laid.labels {
        leaders_and_label(out, &l.label, &l.placed.rect, l.placed.leader, "#000000");
    }
    for l in &laid.link_numbers {
        leaders_and_label(out, &l.label, &l.placed.rect, l.placed.leader, "#1e5aaa");
    }
    if let Some(bar) = &laid.scale_bar {
        scale_bar(out, bar, "m");
    }
    for (label, centre) in &laid.centres_off {
        let note = match centre {
            Centre::AtInfinity(d) => sw!(
                lang,
                "sheet.centre_at_infinity",
                deg = degrees(d[1].atan2(d[0]).to_degrees())
            ),
            Centre::At(p) => sw!(
                lang,
                "sheet.centre_off",
                x = si(p[0], "m"),
                y = si(p[1], "m")
            ),
        };
        let mut text = label.clone();
        text.runs.push(crate::label::Run {
            text: note,
            script: Script::Base,
        });
        let top = pages.place(20.0);
        label_at(pages.out(), &text, [MARGIN, top], "#000000");
    }
}

/// The velocity and then the acceleration equations' tables.
pub(crate) fn equation_tables(pages: &mut Pages, equations: &[VectorEquation], lang: Lang) {
    for q in [Quantity::Velocity, Quantity::Acceleration] {
        table(pages, equations, q, lang);
    }
}

/// The table of `quantity`'s equations, an equation's rows kept on one page.
fn table(pages: &mut Pages, equations: &[VectorEquation], quantity: Quantity, lang: Lang) {
    // Taller than a line: a symbol with sub- and superscripts spans 1.55 em, a line
    // of Chinese 1.45 em.
    let row = 1.75 * FONT;
    let columns = [0.0, 80.0, 190.0, 270.0, 470.0];
    let scale = polygon_figure::largest_of_kind(equations, quantity);
    for eq in equations.iter().filter(|e| e.kind == quantity) {
        let terms = eq.lhs.len() + eq.rhs.len();
        let mut y = pages.place(row * (3 + terms) as f64 + 0.5 * row);
        let out = pages.out();
        y += row;
        let group = sw!(
            lang,
            "table.group_heading",
            group = words::group(lang, &eq.group)
        );
        text_at(out, [MARGIN, y], &group, FONT, "bold");
        y += row;
        label_at(
            out,
            &Label::of_equation(eq),
            [MARGIN + 12.0, y - 1.05 * FONT],
            "#000000",
        );
        y += row;
        let heads = [
            sw!(lang, "table.term"),
            sw!(lang, "table.magnitude"),
            sw!(lang, "table.direction"),
            sw!(lang, "table.along"),
            sw!(lang, "table.known"),
        ];
        for (x, head) in columns.iter().zip(&heads) {
            text_at(out, [MARGIN + x, y], head, FONT, "bold");
        }
        for t in eq.lhs.iter().chain(&eq.rhs) {
            let cells = [
                si_beside(t.magnitude, scale, unit(quantity)),
                degrees(t.direction_rad.to_degrees()),
                words::direction(lang, &t.direction),
                sw!(
                    lang,
                    "table.known_cell",
                    magnitude = words::known(lang, t.magnitude_known),
                    direction = words::known(lang, t.direction_known)
                ),
            ];
            label_at(
                out,
                &Label::of_symbol(&t.symbol),
                [MARGIN, y + row - 1.05 * FONT],
                "#000000",
            );
            y += row;
            // Each cell cut to its column, the last to the page's margin.
            let ends = columns[2..].iter().copied().chain([WIDTH]);
            for ((x, end), cell) in columns[1..].iter().zip(ends).zip(&cells) {
                let fitted = fit_text(cell, end - x - 8.0, FONT);
                text_at(out, [MARGIN + x, y], &fitted, FONT, "normal");
            }
        }
    }
}
