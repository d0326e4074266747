//! The sheet's force section: a pane per stage of the graphical kinetostatics (the
//! last group first, the crank last), each with its scale bar in newtons, then each
//! stage's table of forces and couples and the balancing torque.

use linkage::Mechanism;
use linkage::force_polygon::ForcePolygons;

use crate::force_figure::{
    FORCE_UNIT, ForceFigure, force_rows, row_cells, stage_equation, stage_title,
};
use crate::geometry::Rect;
use crate::layout::{Sizes, layout_polygon};
use crate::svg_draw::{FONT, MARGIN, PAGE_W, label_at, measure, polygon, text_at, titled_pane};

/// Panes per row.
const PER_ROW: usize = 2;
/// A pane's height, px.
const PANE_H: f64 = 300.0;

/// Draws the force polygons of `fp` from `y` on; returns the y below.
pub(crate) fn forces(
    out: &mut String,
    m: &Mechanism,
    fp: &ForcePolygons,
    y: f64,
    sizes: Sizes,
) -> f64 {
    let mut y = y;
    text_at(out, [MARGIN, y + 14.0], "Force polygons", 14.0, "bold");
    y += 24.0;
    let width = PAGE_W - 2.0 * MARGIN;
    let w = (width - 10.0 * (PER_ROW - 1) as f64) / PER_ROW as f64;
    for row in fp.stages.chunks(PER_ROW) {
        for (i, stage) in row.iter().enumerate() {
            let pane = Rect::from_min_size([MARGIN + i as f64 * (w + 10.0), y], w, PANE_H);
            let below_title = titled_pane(out, &pane, &stage_title(stage, m), 12.0);
            let fig = ForceFigure::new(stage, m);
            if fig.arrows.is_empty() {
                let note = "no force on these links here: the polygon is a point";
                text_at(out, below_title.centre(), note, FONT, "normal");
                continue;
            }
            polygon(
                out,
                FORCE_UNIT,
                &layout_polygon(&fig, below_title, sizes, &measure),
            );
        }
        y += PANE_H + 10.0;
    }
    tables(out, m, fp, y)
}

/// Each stage's forces and couples as a table; returns the y below.
fn tables(out: &mut String, m: &Mechanism, fp: &ForcePolygons, mut y: f64) -> f64 {
    let row = 1.5 * FONT;
    let columns = [0.0, 80.0, 200.0, 300.0];
    for stage in &fp.stages {
        y += row;
        text_at(
            out,
            [MARGIN, y],
            &format!("{}:", stage_title(stage, m)),
            FONT,
            "bold",
        );
        y += row;
        let equation = stage_equation(stage, m);
        label_at(out, &equation, [MARGIN + 12.0, y - 1.05 * FONT], "#000000");
        y += row;
        for (x, head) in columns
            .iter()
            .zip(["force", "magnitude", "direction", "in this stage"])
        {
            text_at(out, [MARGIN + x, y], head, FONT, "bold");
        }
        for r in force_rows(stage, m) {
            label_at(out, &r.label, [MARGIN, y + 0.45 * FONT], "#000000");
            y += row;
            let (magnitude, direction) = row_cells(&r);
            for (x, cell) in columns[1..]
                .iter()
                .zip([magnitude, direction, r.status.to_string()])
            {
                text_at(out, [MARGIN + x, y], &cell, FONT, "normal");
            }
        }
    }
    y += row;
    let torque = format!(
        "Balancing torque on the crank M_b = {}",
        crate::numbers::si(fp.balancing_torque, "N·m")
    );
    text_at(out, [MARGIN, y], &torque, FONT, "bold");
    y
}
