//! The sheet's force section: a pane per stage of the graphical kinetostatics (the
//! last group first, the crank last), each with its scale bar in newtons, then each
//! stage's table of forces and couples and the balancing torque.

use linkage::Mechanism;
use linkage::force_polygon::ForcePolygons;

use crate::force_figure::{
    FORCE_UNIT, ForceFigure, force_rows, row_cells, row_scale, sense, stage_equation,
};
use crate::geometry::Rect;
use crate::layout::{Sizes, layout_polygon};
use crate::pages::Pages;
use crate::svg_draw::{
    FONT, MARGIN, PAGE_W, fit_text, label_at, measure, polygon, text_at, titled_pane,
};
use crate::words::{self, Lang, sw};

/// Panes per row.
const PER_ROW: usize = 2;
/// A pane's height, px.
const PANE_H: f64 = 300.0;

/// Draws the force polygons of `fp`, a row of panes kept on one page, then their
/// tables.
pub(crate) fn forces(
    pages: &mut Pages,
    m: &Mechanism,
    fp: &ForcePolygons,
    sizes: Sizes,
    lang: Lang,
) {
    pages.keep(30.0 + PANE_H + 10.0);
    crate::pages::heading(pages, &sw!(lang, "forces.heading"), 14.0);
    let width = PAGE_W - 2.0 * MARGIN;
    let w = (width - 10.0 * (PER_ROW - 1) as f64) / PER_ROW as f64;
    for row in fp.stages.chunks(PER_ROW) {
        let y = pages.place(PANE_H + 10.0);
        for (i, stage) in row.iter().enumerate() {
            let pane = Rect::from_min_size([MARGIN + i as f64 * (w + 10.0), y], w, PANE_H);
            let out = pages.out();
            let title = fit_text(&words::stage_title(lang, stage, m), w - 12.0, 12.0);
            let below_title = titled_pane(out, &pane, &title, 12.0);
            let fig = ForceFigure::new(stage, m);
            if fig.arrows.is_empty() {
                let note = sw!(lang, "forces.none_on_links");
                let at = [pane.min[0] + 6.0, below_title.centre()[1]];
                text_at(out, at, &fit_text(&note, w - 12.0, FONT), FONT, "normal");
                continue;
            }
            polygon(
                out,
                FORCE_UNIT,
                &layout_polygon(&fig, below_title, sizes, &measure),
                lang,
            );
        }
    }
    tables(pages, m, fp, lang);
}

/// Each stage's forces and couples as a table, a stage's rows kept on one page.
fn tables(pages: &mut Pages, m: &Mechanism, fp: &ForcePolygons, lang: Lang) {
    // Taller than a line: a symbol with sub- and superscripts spans 1.55 em, a line
    // of Chinese 1.45 em.
    let row = 1.75 * FONT;
    let columns = [0.0, 80.0, 200.0, 320.0];
    let scale = row_scale(m, fp);
    for stage in &fp.stages {
        let rows = force_rows(stage, m);
        let mut y = pages.place(row * (3 + rows.len()) as f64 + 0.5 * row);
        let out = pages.out();
        y += row;
        text_at(
            out,
            [MARGIN, y],
            &sw!(
                lang,
                "table.group_heading",
                group = words::stage_title(lang, stage, m)
            ),
            FONT,
            "bold",
        );
        y += row;
        let equation = stage_equation(stage, m);
        label_at(out, &equation, [MARGIN + 12.0, y - 1.05 * FONT], "#000000");
        y += row;
        let heads = [
            sw!(lang, "table.force"),
            sw!(lang, "table.magnitude"),
            sw!(lang, "table.direction"),
            sw!(lang, "table.in_stage"),
        ];
        for (x, head) in columns.iter().zip(&heads) {
            text_at(out, [MARGIN + x, y], head, FONT, "bold");
        }
        for r in rows {
            label_at(out, &r.label, [MARGIN, y + row - 1.05 * FONT], "#000000");
            y += row;
            let (magnitude, direction) = row_cells(&r, scale);
            let direction = sense(&r, scale).map_or(direction, |s| words::sense(lang, s));
            let status = words::row_status(lang, r.status);
            for (x, cell) in columns[1..].iter().zip([magnitude, direction, status]) {
                text_at(out, [MARGIN + x, y], &cell, FONT, "normal");
            }
        }
    }
    let y = pages.place(2.0 * row);
    let torque = sw!(
        lang,
        "forces.balancing_torque",
        torque = crate::numbers::si(fp.balancing_torque, "N·m")
    );
    text_at(pages.out(), [MARGIN, y + row], &torque, FONT, "bold");
}
