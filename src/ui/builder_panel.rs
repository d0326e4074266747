//! The side panel while drawing: the tools, what the drawing still lacks (with its
//! Grübler count), every point's coordinates to type, and Done.

use eframe::egui;
use linkage::Vec2;

use crate::app::AppState;
use crate::builder::Tool;
use crate::builder::edit::SketchEdit;
use crate::ui::control_map::ControlKind;
use crate::ui::drawing;

/// Draws the panel; its edits go to the drawing.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.builder.as_ref() else {
        return;
    };
    ui.heading("Draw a mechanism");
    let mut chosen = None;
    ui.horizontal_wrapped(|ui| {
        for tool in Tool::ALL {
            let r = ui.selectable_label(b.tool == tool, tool.label());
            st.controls
                .note(ui, ControlKind::DrawTool, tool.label(), &r);
            if r.clicked() {
                chosen = Some(tool);
            }
        }
    });
    ui.label(egui::RichText::new(b.tool.hint()).weak());
    ui.separator();
    status(ui, st);
    ui.separator();
    let action = actions(ui, st);
    ui.separator();
    points(ui, st);
    if let (Some(tool), Some(b)) = (chosen, st.builder.as_mut()) {
        b.tool = tool;
        b.pending = None;
    }
    if action {
        drawing::finish(st);
    }
}

/// The mobility and what is missing, or that the drawing is a mechanism.
fn status(ui: &mut egui::Ui, st: &AppState) {
    let Some(b) = st.builder.as_ref() else {
        return;
    };
    let m = b.sketch().mobility();
    ui.label(format!(
        "degrees of freedom: 3·{} − 2·{} = {}",
        m.moving,
        m.revolutes + m.prismatics,
        m.dof()
    ));
    match &b.problem {
        Some(why) => ui.colored_label(egui::Color32::from_rgb(150, 90, 0), why.to_string()),
        None => ui.colored_label(
            egui::Color32::from_rgb(20, 110, 40),
            "a mechanism: its report, plots and polygons follow the drawing",
        ),
    };
    if let Some(why) = &b.refusal {
        ui.colored_label(egui::Color32::DARK_RED, why.to_string());
    }
}

/// "Done" (once the drawing is a mechanism): back to the viewer over it. Returns
/// whether it was clicked.
fn actions(ui: &mut egui::Ui, st: &mut AppState) -> bool {
    let Some(b) = st.builder.as_ref() else {
        return false;
    };
    let done = ui.add_enabled(b.problem.is_none(), egui::Button::new("Done"));
    st.controls.note(ui, ControlKind::DrawTool, "Done", &done);
    done.clicked()
}

/// Every point with its coordinates (mm) to type, and whether it is a ground pivot.
fn points(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.builder.as_ref() else {
        return;
    };
    let unit = b.sketch().length_unit.to_metres();
    let mut edits = Vec::new();
    egui::Grid::new("drawing points")
        .num_columns(4)
        .show(ui, |ui| {
            for (p, point) in b.sketch().points.iter().enumerate() {
                ui.label(&point.name);
                let mut xy = [point.at.x / unit, point.at.y / unit];
                let mut changed = false;
                for v in &mut xy {
                    changed |= ui
                        .add(egui::DragValue::new(v).speed(1.0).suffix(" mm"))
                        .changed();
                }
                let mut ground = point.ground;
                if ui.checkbox(&mut ground, "ground").changed() {
                    edits.push(SketchEdit::SetGround { point: p, ground });
                }
                if changed {
                    let to = Vec2::new(xy[0] * unit, xy[1] * unit);
                    edits.push(SketchEdit::MovePoint { point: p, to });
                }
                ui.end_row();
            }
        });
    for e in edits {
        drawing::edit(st, e);
    }
}
