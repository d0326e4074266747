//! The course sheet as SVG: the plan of positions (every position in thin lines,
//! the start in the links' colour, each numbered at its output point), the output's
//! displacement, velocity and acceleration diagrams against the crank angle with the
//! positions marked, the velocity and acceleration polygons at the chosen positions,
//! and the force polygons at the first of them, on A4 pages.

use std::fmt::Write as _;

use linkage::{Mechanism, Solution};

use crate::course::{ChosenPosition, CourseSheet, OutputSeries};
use crate::geometry::{Pt, Rect};
use crate::layout::{Sizes, layout_polygon};
use crate::pages::{Pages, Sheet, heading};
use crate::polygon_figure::PolygonFigure;
use crate::svg_draw::{
    FONT, MARGIN, PAGE_W, frame, line, measure, polygon, text_at, text_at_end, titled_pane,
};
use crate::words::{self, Lang, sw};
use linkage::polygon::Quantity;

const PLAN_H: f64 = 520.0;
const CHART_H: f64 = 150.0;
const POLYGON_H: f64 = 300.0;
const HEADING_H: f64 = 24.0;
const BLUE: &str = "#1e5aaa";

/// The sheet in `lang`, on as many A4 pages as it needs: the plan and the diagrams
/// on the first, each chosen position's polygons whole on a page.
pub fn course_sheet(c: &CourseSheet, lang: Lang) -> Sheet {
    let m = &c.mechanism;
    let title = sw!(
        lang,
        "sheet.course_title",
        name = m.name,
        count = c.positions.len(),
        omega = crate::numbers::significant(m.driver.speed_rad_s, 4)
    );
    let mut pages = Pages::new(&title);
    heading(&mut pages, &title, 16.0);
    course_body(&mut pages, c, lang, false);
    pages.finish()
}

/// The sheet's content from the plan on: the plan, the diagrams, each chosen
/// position's polygons (with their vector-equation tables where `tables`), and the
/// force polygons at the first chosen position.
pub(crate) fn course_body(pages: &mut Pages, c: &CourseSheet, lang: Lang, tables: bool) {
    let sizes = Sizes {
        font_px: FONT,
        ..Sizes::default()
    };
    let m = &c.mechanism;
    let top = pages.place(PLAN_H + 10.0);
    let pane = Rect::from_min_size([MARGIN, top], WIDTH, PLAN_H);
    let plan_title = sw!(lang, "course.plan");
    crate::svg_plan::plan(pages.out(), m, &c.positions, pane, sizes, &plan_title);
    if let Some(o) = &c.output {
        diagrams(pages, o, &c.positions, lang);
    }
    for chosen in &c.chosen {
        let s = &c.positions[chosen.number];
        chosen_polygons(pages, m, s, chosen, sizes, lang);
        if tables {
            crate::svg::equation_tables(pages, &chosen.equations, lang);
        }
    }
    if let (Some(fp), Some(first)) = (&c.forces, c.chosen.first()) {
        pages.keep(2.0 * 30.0 + 310.0);
        let text = sw!(lang, "course.position_forces", n = first.number);
        heading(pages, &text, 14.0);
        crate::svg_forces::forces(pages, m, fp, sizes, lang);
    }
}

/// The width between the margins, px.
const WIDTH: f64 = PAGE_W - 2.0 * MARGIN;

/// The output's s, v and a diagrams.
fn diagrams(pages: &mut Pages, o: &OutputSeries, positions: &[Solution], lang: Lang) {
    let marks: Vec<f64> = positions.iter().map(|s| s.input_rad.to_degrees()).collect();
    let [s, v, a] = o.units();
    let charts = [
        (
            sw!(lang, "course.displacement", name = o.name, unit = s),
            &o.s,
        ),
        (sw!(lang, "course.velocity", name = o.name, unit = v), &o.v),
        (
            sw!(lang, "course.acceleration", name = o.name, unit = a),
            &o.a,
        ),
    ];
    let note = sw!(lang, "course.against_crank");
    for (label, data) in charts {
        let top = pages.place(CHART_H + 8.0);
        let pane = Rect::from_min_size([MARGIN, top], WIDTH, CHART_H);
        chart(pages.out(), pane, [&label, &note], data, &marks);
    }
}

/// A chosen position's velocity and acceleration polygons under their heading, on
/// one page.
fn chosen_polygons(
    pages: &mut Pages,
    m: &Mechanism,
    s: &Solution,
    chosen: &ChosenPosition,
    sizes: Sizes,
    lang: Lang,
) {
    let text = sw!(
        lang,
        "course.position_polygons",
        n = chosen.number,
        deg = crate::numbers::degrees(s.input_rad.to_degrees())
    );
    // The heading stays with its polygons.
    let top = pages.place(HEADING_H + POLYGON_H + 10.0);
    text_at(pages.out(), [MARGIN, top + 16.0], &text, 14.0, "bold");
    let y = top + HEADING_H;
    let w = (WIDTH - 10.0) / 2.0;
    for (i, q) in [Quantity::Velocity, Quantity::Acceleration]
        .into_iter()
        .enumerate()
    {
        let pane = Rect::from_min_size([MARGIN + i as f64 * (w + 10.0), y], w, POLYGON_H);
        let out = pages.out();
        let below = titled_pane(out, &pane, &words::polygon_title(lang, q), 12.0);
        let fig = PolygonFigure::of_position(q, m, s, &chosen.equations);
        let laid = layout_polygon(&fig, below, sizes, &measure);
        polygon(out, fig.unit(), &laid, lang);
    }
}

/// A chart's mapping from (crank angle, value) to pixels.
struct Axes {
    plot: Rect,
    x: [f64; 2],
    y: [f64; 2],
}

impl Axes {
    fn px(&self, p: Pt) -> Pt {
        let (plot, [x0, x1], [y0, y1]) = (&self.plot, self.x, self.y);
        [
            plot.min[0] + (p[0] - x0) / (x1 - x0).max(1e-300) * plot.width(),
            plot.max[1] - (p[1] - y0) / (y1 - y0) * plot.height(),
        ]
    }
}

/// A line chart of `data` (crank angle on x) with the positions at `marks` numbered.
fn chart(out: &mut String, pane: Rect, [label, note]: [&str; 2], data: &[[f64; 2]], marks: &[f64]) {
    frame(out, &pane);
    text_at(
        out,
        [pane.min[0] + 6.0, pane.min[1] + 14.0],
        label,
        12.0,
        "bold",
    );
    text_at_end(out, [pane.max[0] - 6.0, pane.min[1] + 14.0], note, 10.0);
    let Some(extent) = Rect::around(data.iter().copied()) else {
        return;
    };
    let (y0, y1) = value_range(data);
    let axes = Axes {
        plot: Rect {
            min: [pane.min[0] + 60.0, pane.min[1] + 22.0],
            max: [pane.max[0] - 10.0, pane.max[1] - 22.0],
        },
        x: [extent.min[0], extent.max[0]],
        y: [y0, y1],
    };
    value_ticks(out, &axes, pane);
    position_marks(out, &axes, marks);
    curve(out, &axes, data, pane);
}

/// Grid lines at a round step of the value, labelled.
fn value_ticks(out: &mut String, axes: &Axes, pane: Rect) {
    let [y0, y1] = axes.y;
    let step = tick_step(y1 - y0);
    if step <= 0.0 {
        return;
    }
    let mut v = (y0 / step).ceil() * step;
    while v <= y1 + 1e-9 * step {
        let p = axes.px([axes.x[0], v]);
        line(
            out,
            [axes.plot.min[0], p[1]],
            [axes.plot.max[0], p[1]],
            "#e4e4e4",
            0.7,
            false,
        );
        // A tick at zero reads 0, not the float noise of the steps that reach it.
        let tick = if v.abs() < 1e-9 * step {
            "0".to_string()
        } else {
            // Plain digits, never an exponent (150000, not 1.5e5): a round step's
            // value has few significant digits.
            crate::numbers::significant(v, 4)
        };
        text_at(out, [pane.min[0] + 4.0, p[1] + 4.0], &tick, 10.0, "normal");
        v += step;
    }
}

/// The step of a chart's value ticks: the least of 1, 2 or 5 × 10^k that makes at
/// most five steps over `extent`, so that the ticks' numbers keep a line apart.
fn tick_step(extent: f64) -> f64 {
    if !(extent.is_finite() && extent > 0.0) {
        return 0.0;
    }
    let least = extent / 5.0;
    let decade = 10f64.powf(least.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&v| v >= least)
        .unwrap_or(10.0 * decade)
}

/// A line and the number at each position's crank angle.
fn position_marks(out: &mut String, axes: &Axes, marks: &[f64]) {
    let [x0, x1] = axes.x;
    // On a turn the diagrams run from the range's start; positions counted from
    // another angle are marked where they fall in that turn.
    let turn = (x1 - x0 - 360.0).abs() < 2.0;
    for (i, &x) in marks.iter().enumerate() {
        let x = if turn {
            x0 + (x - x0).rem_euclid(360.0)
        } else {
            x
        };
        if x < x0 - 1e-9 || x > x1 + 1e-9 {
            continue;
        }
        let p = axes.px([x, axes.y[0]]);
        line(
            out,
            [p[0], axes.plot.min[1]],
            [p[0], axes.plot.max[1]],
            "#c9d6ea",
            0.8,
            false,
        );
        let at = [p[0] - 3.0, axes.plot.max[1] + 13.0];
        text_at(out, at, &i.to_string(), 10.0, "normal");
    }
}

/// The curve, clipped to the plot: near a dead point of a rocking input the rates
/// run off to infinity, past the range the axis shows.
fn curve(out: &mut String, axes: &Axes, data: &[[f64; 2]], pane: Rect) {
    let points: Vec<String> = data
        .iter()
        .map(|&p| {
            let q = axes.px(p);
            format!("{:.1},{:.1}", q[0], q[1])
        })
        .collect();
    let plot = &axes.plot;
    let clip = format!("clip{:.0}", pane.min[1]);
    let _ = writeln!(
        out,
        "<clipPath id=\"{clip}\"><rect x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\"/></clipPath>\n\
         <polyline points=\"{}\" fill=\"none\" stroke=\"{BLUE}\" stroke-width=\"1.6\" clip-path=\"url(#{clip})\"/>",
        plot.min[0],
        plot.min[1],
        plot.width(),
        plot.height(),
        points.join(" ")
    );
}

/// The values the axis shows: from the 1st to the 99th percentile, widened by a
/// tenth each way, so that the runaway rates by a rocking input's dead points do not
/// flatten the rest of the curve; a constant gets a unit either side.
fn value_range(data: &[[f64; 2]]) -> (f64, f64) {
    let mut v: Vec<f64> = data.iter().map(|p| p[1]).collect();
    v.sort_by(f64::total_cmp);
    let at = |q: f64| v[((v.len() - 1) as f64 * q).round() as usize];
    let (lo, hi) = (at(0.01), at(0.99));
    let (lo, hi) = (
        lo.min(v[0].max(lo - (hi - lo))),
        hi.max(v[v.len() - 1].min(hi + (hi - lo))),
    );
    let pad = 0.1 * (hi - lo);
    if pad > 0.0 {
        (lo - pad, hi + pad)
    } else {
        (lo - 1.0, hi + 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A chart of large values (a die's acceleration in mm/s², a press's force)
    /// labels its ticks in plain digits: 150000, never 1.5e5.
    #[test]
    fn large_values_tick_in_plain_digits() {
        let pane = Rect::from_min_size([0.0, 0.0], 400.0, 150.0);
        let axes = Axes {
            plot: Rect::from_min_size([60.0, 20.0], 330.0, 110.0),
            x: [0.0, 360.0],
            y: [-150_000.0, 250_000.0],
        };
        let mut out = String::new();
        value_ticks(&mut out, &axes, pane);
        assert!(
            out.contains(">200000<") && out.contains(">-100000<"),
            "{out}"
        );
        assert!(!out.contains("e5"), "{out}");
    }
}
