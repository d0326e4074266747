//! The course sheet as SVG: the plan of positions (every position in thin lines,
//! the start in the links' colour, each numbered at its output point), the output's
//! displacement, velocity and acceleration diagrams against the crank angle with the
//! positions marked, the velocity and acceleration polygons at the chosen positions,
//! and the force polygons at the first of them — one sheet, A4 wide, as long as it
//! needs.

use std::fmt::Write as _;

use linkage::{Mechanism, Solution};

use crate::course::{ChosenPosition, CourseSheet, OutputSeries};
use crate::geometry::{Pt, Rect};
use crate::layout::{Fit, Sizes, layout_polygon, round_scale};
use crate::polygon_figure::{PolygonFigure, title};
use crate::svg_draw::{
    FONT, MARGIN, PAGE_W, TITLE_H, document, frame, line, measure, polygon, text_at, titled_pane,
};
use linkage::polygon::Quantity;

const PLAN_H: f64 = 380.0;
const CHART_H: f64 = 150.0;
const POLYGON_H: f64 = 300.0;
const BLUE: &str = "#1e5aaa";
const GREY: &str = "#9a9a9a";

/// The sheet as SVG text.
pub fn course_sheet(c: &CourseSheet) -> String {
    let sizes = Sizes {
        font_px: FONT,
        ..Sizes::default()
    };
    let width = PAGE_W - 2.0 * MARGIN;
    let m = &c.mechanism;
    let mut body = String::new();
    let title = format!(
        "{}: {} positions, ω = {} rad/s",
        m.name,
        c.positions.len(),
        crate::numbers::significant(m.driver.speed_rad_s, 4)
    );
    text_at(&mut body, [MARGIN, MARGIN + 14.0], &title, 16.0, "bold");
    let mut y = MARGIN + 30.0;
    plan(
        &mut body,
        m,
        &c.positions,
        Rect::from_min_size([MARGIN, y], width, PLAN_H),
        sizes,
    );
    y += PLAN_H + 10.0;
    if let Some(o) = &c.output {
        y = diagrams(&mut body, o, &c.positions, y);
    }
    for chosen in &c.chosen {
        y = chosen_polygons(&mut body, m, &c.positions[chosen.number], chosen, y, sizes);
    }
    if let (Some(fp), Some(first)) = (&c.forces, c.chosen.first()) {
        let heading = format!(
            "Position {}: forces at the scene's crank speed",
            first.number
        );
        text_at(&mut body, [MARGIN, y + 14.0], &heading, 14.0, "bold");
        y = crate::svg_forces::forces(&mut body, m, fp, y + 22.0, sizes);
    }
    document(&title, &body, y + MARGIN)
}

/// The output's s, v and a diagrams from `y` on; returns the y below.
fn diagrams(body: &mut String, o: &OutputSeries, positions: &[Solution], mut y: f64) -> f64 {
    let width = PAGE_W - 2.0 * MARGIN;
    let marks: Vec<f64> = positions.iter().map(|s| s.input_rad.to_degrees()).collect();
    let units = o.units();
    for (i, (what, data)) in [
        ("displacement", &o.s),
        ("velocity", &o.v),
        ("acceleration", &o.a),
    ]
    .into_iter()
    .enumerate()
    {
        let pane = Rect::from_min_size([MARGIN, y], width, CHART_H);
        let label = format!("{} {what} ({})", o.name, units[i]);
        chart(body, pane, &label, data, &marks);
        y += CHART_H + 8.0;
    }
    y
}

/// A chosen position's velocity and acceleration polygons from `y` on; returns the
/// y below.
fn chosen_polygons(
    body: &mut String,
    m: &Mechanism,
    s: &Solution,
    chosen: &ChosenPosition,
    mut y: f64,
    sizes: Sizes,
) -> f64 {
    let width = PAGE_W - 2.0 * MARGIN;
    let heading = format!(
        "Position {} (crank at {}): polygons",
        chosen.number,
        crate::numbers::degrees(s.input_rad.to_degrees())
    );
    text_at(body, [MARGIN, y + 14.0], &heading, 14.0, "bold");
    y += 22.0;
    let w = (width - 10.0) / 2.0;
    for (i, q) in [Quantity::Velocity, Quantity::Acceleration]
        .into_iter()
        .enumerate()
    {
        let pane = Rect::from_min_size([MARGIN + i as f64 * (w + 10.0), y], w, POLYGON_H);
        let below = titled_pane(body, &pane, title(q), 12.0);
        let fig = PolygonFigure::of_position(q, m, s, &chosen.equations);
        polygon(
            body,
            fig.unit(),
            &layout_polygon(&fig, below, sizes, &measure),
        );
    }
    y += POLYGON_H + 10.0;
    y
}

/// The point each position is numbered at: the crank pin (the driver's point
/// farthest from its pivot), which the textbook numbers 0, 1, … round its circle.
fn tip(m: &Mechanism, s: &Solution) -> Option<Pt> {
    let crank = &m.links[m.driver.link];
    let rv = &m.revolutes[m.driver.pivot];
    let pivot = if rv.a == m.driver.link {
        rv.a_local
    } else {
        rv.b_local
    };
    let local = crank
        .points
        .iter()
        .map(|(_, p)| *p)
        .max_by(|a, b| (a - pivot).norm().total_cmp(&(b - pivot).norm()))?;
    let at = s.links[m.driver.link].point(&local).position;
    Some([at.x, at.y])
}

/// Every position's links, the start drawn strong, each numbered.
fn plan(out: &mut String, m: &Mechanism, positions: &[Solution], pane: Rect, sizes: Sizes) {
    frame(out, &pane);
    text_at(
        out,
        [pane.min[0] + 6.0, pane.min[1] + 15.0],
        "Plan of positions",
        12.0,
        "bold",
    );
    let outline = |s: &Solution| -> Vec<Vec<Pt>> {
        m.moving_links()
            .map(|l| {
                m.links[l]
                    .points
                    .iter()
                    .map(|(_, local)| {
                        let p = s.links[l].point(local).position;
                        [p.x, p.y]
                    })
                    .collect()
            })
            .collect()
    };
    let all: Vec<Vec<Vec<Pt>>> = positions.iter().map(outline).collect();
    let Some(units) = Rect::around(all.iter().flatten().flatten().copied()) else {
        return;
    };
    let inner = Rect {
        min: [pane.min[0], pane.min[1] + TITLE_H],
        max: pane.max,
    };
    let fit = Fit::new(units, inner, sizes);
    for (i, links) in all.iter().enumerate().rev() {
        let (colour, width) = if i == 0 { (BLUE, 2.5) } else { (GREY, 0.8) };
        for l in links {
            let px: Vec<Pt> = l.iter().map(|&p| fit.px(p)).collect();
            for pair in px.windows(2) {
                line(out, pair[0], pair[1], colour, width, false);
            }
            if px.len() > 2 {
                line(out, px[px.len() - 1], px[0], colour, width, false);
            }
        }
        if let Some(t) = tip(m, &positions[i]) {
            let at = fit.px(t);
            text_at(
                out,
                [at[0] + 4.0, at[1] - 4.0],
                &i.to_string(),
                11.0,
                "normal",
            );
        }
    }
    for (_, local) in &m.links[m.ground].points {
        let p = fit.px([local.x, local.y]);
        let _ = writeln!(
            out,
            "<polygon points=\"{:.1},{:.1} {:.1},{:.1} {:.1},{:.1}\" fill=\"#cccccc\" stroke=\"#333333\"/>",
            p[0],
            p[1],
            p[0] - 6.0,
            p[1] + 10.0,
            p[0] + 6.0,
            p[1] + 10.0
        );
    }
    let bar = fit.scale_bar(units.width().max(units.height()), inner, sizes);
    line(out, bar.from, bar.to, "#000000", 2.0, false);
    text_at(
        out,
        [bar.to[0] + 6.0, bar.to[1] + 4.0],
        &crate::numbers::si(bar.value, "m"),
        FONT,
        "normal",
    );
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
fn chart(out: &mut String, pane: Rect, label: &str, data: &[[f64; 2]], marks: &[f64]) {
    frame(out, &pane);
    text_at(
        out,
        [pane.min[0] + 6.0, pane.min[1] + 14.0],
        label,
        12.0,
        "bold",
    );
    let note = "against the crank angle; positions numbered";
    text_at(
        out,
        [pane.max[0] - 200.0, pane.min[1] + 14.0],
        note,
        10.0,
        "normal",
    );
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
    let step = round_scale(y1 - y0);
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

/// A line and the number at each position's crank angle.
fn position_marks(out: &mut String, axes: &Axes, marks: &[f64]) {
    let [x0, x1] = axes.x;
    for (i, &x) in marks.iter().enumerate() {
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
