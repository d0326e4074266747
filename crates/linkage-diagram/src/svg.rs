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
use crate::polygon_figure::{self, PolygonFigure, unit};
use crate::pose_figure::PoseFigure;
use crate::pose_layout::{LaidPose, layout_pose};
use crate::svg_draw::{
    FONT, MARGIN, PAGE_H, PAGE_W, circle, document, frame, label_at, leaders_and_label, line,
    measure, polygon, polygon_shape, scale_bar, text_at, titled_pane,
};

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

/// The sheet of `pos` with `parts`, as SVG text.
pub fn sheet(pos: &Position<'_>, parts: Parts) -> String {
    let sizes = Sizes {
        font_px: FONT,
        ..Sizes::default()
    };
    let width = PAGE_W - 2.0 * MARGIN;
    let mut body = String::new();
    let mut y = MARGIN;
    let m = pos.mechanism;
    let s = pos.solution;
    let title = format!(
        "{} at input {}, ω = {} rad/s",
        m.name,
        degrees(s.input_rad.to_degrees()),
        significant(s.input_speed_rad_s, 4)
    );
    text_at(&mut body, [MARGIN, y + 14.0], &title, 16.0, "bold");
    y += 30.0;
    if parts.pose {
        let centres = if parts.centres { pos.centres } else { None };
        let fig = PoseFigure::new(m, s, centres);
        let pane = Rect::from_min_size([MARGIN, y], width, 360.0);
        y = pose(&mut body, &layout_pose(&fig, pane, sizes, &measure)) + 10.0;
    }
    let quantities: Vec<Quantity> = [
        (parts.velocity, Quantity::Velocity),
        (parts.acceleration, Quantity::Acceleration),
    ]
    .into_iter()
    .filter_map(|(on, q)| on.then_some(q))
    .collect();
    if !quantities.is_empty() {
        let w = (width - 10.0 * (quantities.len() - 1) as f64) / quantities.len() as f64;
        for (i, &q) in quantities.iter().enumerate() {
            let fig = PolygonFigure::of_position(q, m, s, pos.equations);
            let pane = Rect::from_min_size([MARGIN + i as f64 * (w + 10.0), y], w, 320.0);
            // The figure keeps clear of the pane's title.
            let below_title = titled_pane(&mut body, &pane, polygon_figure::title(q), 13.0);
            polygon(
                &mut body,
                fig.unit(),
                &layout_polygon(&fig, below_title, sizes, &measure),
            );
        }
        y += 330.0;
    }
    if parts.table {
        for q in [Quantity::Velocity, Quantity::Acceleration] {
            y = table(&mut body, pos.equations, q, y);
        }
    }
    if parts.forces
        && let Some(fp) = pos.forces
    {
        y = crate::svg_forces::forces(&mut body, m, fp, y + 10.0, sizes);
    }
    document(&title, &body, PAGE_H.max(y + MARGIN))
}

/// Draws the pose; the centres not drawn are listed below it. Returns the y below.
fn pose(out: &mut String, laid: &LaidPose) -> f64 {
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
    if let Some(bar) = &laid.scale_bar {
        scale_bar(out, bar, "m");
    }
    let mut y = laid.pane.max[1];
    for (label, centre) in &laid.centres_off {
        let note = match centre {
            Centre::AtInfinity(d) => format!(
                ": at infinity, direction {}",
                degrees(d[1].atan2(d[0]).to_degrees())
            ),
            Centre::At(p) => format!(
                ": at ({}, {}), off the figure",
                si(p[0], "m"),
                si(p[1], "m")
            ),
        };
        let mut text = label.clone();
        text.runs.push(crate::label::Run {
            text: note,
            script: Script::Base,
        });
        y += 16.0;
        label_at(out, &text, [laid.pane.min[0], y - 1.05 * FONT], "#000000");
    }
    y
}

/// The table of `quantity`'s equations from `y` on; returns the y below it.
fn table(out: &mut String, equations: &[VectorEquation], quantity: Quantity, mut y: f64) -> f64 {
    let row = 1.5 * FONT;
    let columns = [0.0, 80.0, 190.0, 270.0, 470.0];
    for eq in equations.iter().filter(|e| e.kind == quantity) {
        y += row;
        text_at(out, [MARGIN, y], &format!("{}:", eq.group), FONT, "bold");
        y += row;
        label_at(
            out,
            &Label::of_equation(eq),
            [MARGIN + 12.0, y - 1.05 * FONT],
            "#000000",
        );
        y += row;
        for (x, head) in columns
            .iter()
            .zip(["term", "magnitude", "direction", "along", "known"])
        {
            text_at(out, [MARGIN + x, y], head, FONT, "bold");
        }
        let scale = polygon_figure::largest_term(eq);
        for t in eq.lhs.iter().chain(&eq.rhs) {
            let cells = [
                si_beside(t.magnitude, scale, unit(quantity)),
                degrees(t.direction_rad.to_degrees()),
                t.direction.clone(),
                format!(
                    "magnitude {}, direction {}",
                    known(t.magnitude_known),
                    known(t.direction_known)
                ),
            ];
            label_at(
                out,
                &Label::of_symbol(&t.symbol),
                [MARGIN, y + 0.45 * FONT],
                "#000000",
            );
            y += row;
            for (x, cell) in columns[1..].iter().zip(&cells) {
                text_at(out, [MARGIN + x, y], cell, FONT, "normal");
            }
        }
    }
    y
}

fn known(k: bool) -> &'static str {
    if k { "known" } else { "solved" }
}
