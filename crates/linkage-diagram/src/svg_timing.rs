//! The timing diagram as an SVG sheet: one lane per output, stacked against the main
//! shaft's angle, each curve its share of the output's stroke (lowest at the lane's
//! foot, highest at its head), its dwells shaded, the shaft's angle gridded every
//! 30 degrees, and each lane's stroke written beside it.

use std::fmt::Write as _;

use linkage::analysis::{TimingDiagram, TimingLane};

use crate::geometry::Rect;
use crate::pages::{BOTTOM, Pages, Sheet};
use crate::svg_draw::{MARGIN, PAGE_W, fit_text, line, text_at, text_at_end, titled_pane};
use crate::words::{Lang, sw};

/// A lane's height, px.
const LANE_H: f64 = 70.0;
/// The room left of the lanes for their names, px.
const NAMES_W: f64 = 120.0;
const CURVE: &str = "#2f5f9e";
const DWELL: &str = "#f1e3bf";

/// The timing diagram of `title`'s scene, on one A4 page (the lanes narrowed to fit
/// where there are many).
pub fn timing_sheet(title: &str, d: &TimingDiagram, lang: Lang) -> Sheet {
    let mut pages = Pages::new(title);
    let lanes = d.lanes.len().max(1) as f64;
    let lane_h = LANE_H.min((BOTTOM - MARGIN - 80.0) / lanes);
    let lanes_h = lane_h * lanes;
    let top = pages.place(40.0 + lanes_h + 40.0);
    let body = pages.out();
    let pane = Rect {
        min: [MARGIN, top],
        max: [PAGE_W - MARGIN, top + 40.0 + lanes_h + 40.0],
    };
    let heading = fit_text(
        &sw!(lang, "timing.title", title = title),
        pane.width() - 12.0,
        14.0,
    );
    let inner = titled_pane(body, &pane, &heading, 14.0);
    let plot = Rect {
        min: [inner.min[0] + NAMES_W, inner.min[1] + 10.0],
        max: [inner.max[0] - 12.0, inner.min[1] + 10.0 + lanes_h],
    };
    let (Some(&x0), Some(&x1)) = (d.shaft_rad.first(), d.shaft_rad.last()) else {
        return pages.finish();
    };
    let span = (x1 - x0).max(1e-300);
    let x_px = |x: f64| plot.min[0] + (x - x0) / span * plot.width();
    shaft_grid(body, &plot, [x0, x1], &x_px, lang);
    for (i, lane) in d.lanes.iter().enumerate() {
        let top = plot.min[1] + lane_h * i as f64;
        let band = Rect {
            min: [plot.min[0], top + 8.0],
            max: [plot.max[0], top + lane_h - 8.0],
        };
        draw_lane(body, lane, &band, &d.shaft_rad, &x_px);
        let at = [inner.min[0] + 6.0, band.min[1] + 14.0];
        text_at(
            body,
            at,
            &fit_text(&lane.name, NAMES_W - 10.0, 12.0),
            12.0,
            "bold",
        );
        let stroke = stroke_text(lane, lang);
        text_at(body, [at[0], at[1] + 16.0], &stroke, 10.0, "normal");
    }
    pages.finish()
}

/// The lane's stroke as a reader writes it: degrees or millimetres.
fn stroke_text(lane: &TimingLane, lang: Lang) -> String {
    let [lo, hi] = lane.range;
    if lane.is_angle {
        let angle = crate::numbers::degrees((hi - lo).to_degrees());
        sw!(lang, "timing.swing", angle = angle)
    } else {
        sw!(
            lang,
            "timing.stroke",
            length = crate::numbers::si(hi - lo, "m")
        )
    }
}

/// Vertical lines every 30 degrees of the shaft, labelled under the plot.
fn shaft_grid(
    out: &mut String,
    plot: &Rect,
    [x0, x1]: [f64; 2],
    x_px: &dyn Fn(f64) -> f64,
    lang: Lang,
) {
    let step = 30f64.to_radians();
    let mut x = (x0 / step).ceil() * step;
    while x <= x1 + 1e-9 {
        let px = x_px(x);
        line(
            out,
            [px, plot.min[1]],
            [px, plot.max[1]],
            "#e4e4e4",
            0.7,
            false,
        );
        let label = format!("{:.0}", x.to_degrees());
        text_at(out, [px - 8.0, plot.max[1] + 14.0], &label, 10.0, "normal");
        x += step;
    }
    let note = sw!(lang, "timing.axis");
    text_at_end(out, [plot.max[0], plot.max[1] + 28.0], &note, 10.0);
}

/// One lane: its dwells shaded, its foot and head ruled, its curve.
fn draw_lane(
    out: &mut String,
    lane: &TimingLane,
    band: &Rect,
    shaft: &[f64],
    x_px: &dyn Fn(f64) -> f64,
) {
    for [a, b] in &lane.dwells {
        let (xa, xb) = (x_px(*a), x_px(*b));
        let _ = writeln!(
            out,
            "<rect x=\"{xa:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"{DWELL}\"/>",
            band.min[1],
            (xb - xa).max(0.5),
            band.height()
        );
    }
    for y in [band.min[1], band.max[1]] {
        line(
            out,
            [band.min[0], y],
            [band.max[0], y],
            "#bbbbbb",
            0.6,
            true,
        );
    }
    let points: Vec<String> = shaft
        .iter()
        .zip(&lane.share)
        .filter(|(_, s)| s.is_finite())
        .map(|(&x, &s)| format!("{:.1},{:.1}", x_px(x), band.max[1] - s * band.height()))
        .collect();
    let _ = writeln!(
        out,
        "<polyline points=\"{}\" fill=\"none\" stroke=\"{CURVE}\" stroke-width=\"1.6\"/>",
        points.join(" ")
    );
}
