//! The force polygons in the polygon pane: graphical kinetostatics of the current
//! position, a figure per stage (the last Assur group first, the crank last), each
//! with its table of forces and couples, and the balancing torque. Laid out by
//! `linkage-diagram` as on the exported sheet.

use crate::i18n::tr;
use eframe::egui;
use linkage::force_polygon::ForcePolygons;
use linkage_diagram::force_figure::{
    FORCE_UNIT, ForceFigure, ForceRow, RowScale, force_rows, row_cells, row_scale, sense,
    stage_equation,
};
use linkage_model::session::Session;

use crate::ui::polygon_paint::{INK, Paper, draw};

/// The force polygons' section: the figures, or why the position has none.
pub fn section(ui: &mut egui::Ui, session: &Session, figure_height: f32) {
    ui.separator();
    ui.strong(tr!("forces.heading"));
    match session.force_polygons() {
        None => {
            ui.label(tr!("forces.kinematics_only"));
        }
        Some(Err(e)) => {
            ui.colored_label(
                ui.visuals().warn_fg_color,
                tr!(
                    "forces.none_here",
                    why = crate::ui::words::refusal(e, session.scene().length_unit)
                ),
            );
        }
        Some(Ok(fp)) => stages(ui, session, fp, figure_height),
    }
}

fn stages(ui: &mut egui::Ui, session: &Session, fp: &ForcePolygons, figure_height: f32) {
    let m = session.mechanism();
    ui.label(tr!(
        "forces.intro",
        torque = linkage_diagram::numbers::si(fp.balancing_torque, "N·m")
    ));
    for (i, stage) in fp.stages.iter().enumerate() {
        let title = crate::ui::words::stage_title(stage, m);
        ui.label(egui::RichText::new(&title).strong());
        let fig = ForceFigure::new(stage, m);
        if fig.arrows.is_empty() {
            ui.weak(tr!("forces.no_force"));
            continue;
        }
        let paper = Paper::new(ui, figure_height);
        let laid = paper.lay_out(&fig, None);
        draw(&paper.painter, FORCE_UNIT, &laid, None, INK);
        egui::CollapsingHeader::new(tr!("forces.table", stage = title))
            .id_salt(("force table", i))
            .default_open(false)
            .show(ui, |ui| {
                let ink = ui.visuals().text_color();
                ui.label(crate::ui::typeset::job(
                    &stage_equation(stage, m),
                    14.0,
                    ink,
                ));
                table(ui, &force_rows(stage, m), row_scale(m, fp), i);
            });
    }
}

fn table(ui: &mut egui::Ui, rows: &[ForceRow], scale: RowScale, salt: usize) {
    let ink = ui.visuals().text_color();
    egui::Grid::new(("forces", salt))
        .striped(true)
        .show(ui, |ui| {
            for head in [
                tr!("table.force"),
                tr!("table.magnitude"),
                tr!("table.direction"),
                tr!("table.in_stage"),
            ] {
                ui.strong(head);
            }
            ui.end_row();
            for r in rows {
                ui.label(crate::ui::typeset::job(&r.label, 14.0, ink));
                let (magnitude, direction) = row_cells(r, scale);
                ui.label(magnitude);
                match sense(r, scale) {
                    Some(s) => ui.label(crate::ui::words::sense(s)),
                    None => ui.label(direction),
                };
                ui.label(crate::ui::words::row_status(r.status));
                ui.end_row();
            }
        });
}
