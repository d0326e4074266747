//! The report strip: Grashof class, time ratio, strokes and swings, limit positions,
//! transmission angle; each entry shows where on the cycle it occurs when hovered.

use eframe::egui;

use linkage::analysis::Report;

use crate::app::AppState;
use crate::session::derived::Shown;

/// The strip along the bottom. While edits come (a slider dragged) it shows the
/// report from before them, greyed, until a frame without an edit makes the new one.
pub fn strip(ui: &mut egui::Ui, st: &AppState) {
    egui::Panel::bottom("report").show(ui, |ui| {
        ui.horizontal_wrapped(|ui| match st.session.report_shown() {
            Shown::Current(r) => entries(ui, r),
            Shown::Outdated(r) => {
                ui.weak("updating…");
                ui.separator();
                ui.add_enabled_ui(false, |ui| entries(ui, r));
            }
            Shown::Pending => {
                ui.weak("report: computing…");
            }
        });
    });
}

/// The report's entries in a row, or why there is none.
fn entries(ui: &mut egui::Ui, report: &Result<Report, linkage::LinkageError>) {
    let r = match report {
        Ok(r) => r,
        Err(e) => {
            ui.colored_label(ui.visuals().warn_fg_color, format!("no report: {e}"));
            return;
        }
    };
    match &r.grashof {
        Some(g) => ui
            .label(format!("Grashof: {}", g.class))
            .on_hover_text(format!(
                "s + l = {:.4} m, p + q = {:.4} m ({}){}",
                g.s_plus_l_m,
                g.p_plus_q_m,
                g.links.join(", "),
                if g.change_point {
                    "; change point: the links can fold flat"
                } else {
                    ""
                }
            )),
        None => ui.label("Grashof: not a four-bar"),
    };
    ui.separator();
    match r.time_ratio {
        Some(k) => ui
            .label(format!("K = {k:.4}"))
            .on_hover_text(r.time_ratio_note.clone().unwrap_or_default()),
        None => ui
            .label("K: none")
            .on_hover_text(r.time_ratio_note.clone().unwrap_or_default()),
    };
    for (name, stroke) in &r.strokes_m {
        ui.separator();
        ui.label(format!("stroke {name} = {:.2} mm", stroke * 1e3))
            .on_hover_text(limits_of(r, name));
    }
    for (name, swing) in &r.swings_rad {
        ui.separator();
        ui.label(format!("swing {name} = {:.2}°", swing.to_degrees()))
            .on_hover_text(limits_of(r, name));
    }
    if let Some(t) = &r.transmission_angle_rad {
        ui.separator();
        ui.label(format!("μ min = {:.2}°", t.min.to_degrees()))
            .on_hover_text(format!(
                "at crank {:.2}° (group {}); max {:.2}° at crank {:.2}°",
                t.at.to_degrees(),
                t.group,
                t.max.to_degrees(),
                t.at_max.to_degrees()
            ));
    }
    if !r.toggles.is_empty() {
        ui.separator();
        let text: Vec<String> = r
            .toggles
            .iter()
            .map(|t| {
                format!(
                    "crank {:.2}°: {} ({})",
                    t.input_rad.to_degrees(),
                    t.ratio,
                    t.collinear_joints.join(", ")
                )
            })
            .collect();
        ui.label(format!("{} toggle/dead positions", r.toggles.len()))
            .on_hover_text(text.join("\n"));
    }
    if !r.branch_points.is_empty() {
        ui.separator();
        let text: Vec<String> = r.branch_points.iter().map(branch_point_line).collect();
        ui.label(format!("{} branch points", r.branch_points.len()))
            .on_hover_text(text.join("\n"));
    }
}

/// "crank 180.00°: RRR dyad (coupler, rocker) at C, B on D".
fn branch_point_line(b: &linkage::branch_points::BranchPoint) -> String {
    let pairs: Vec<String> = b
        .coincident_joints
        .iter()
        .map(|[p, q]| format!(", {p} on {q}"))
        .collect();
    format!(
        "crank {:.2}°: {}{} (the chain may go on in either mode)",
        b.input_rad.to_degrees(),
        b.group,
        pairs.concat()
    )
}

fn limits_of(r: &linkage::analysis::Report, output: &str) -> String {
    let lines: Vec<String> = r
        .limit_positions
        .iter()
        .filter(|l| l.output == output)
        .map(|l| format!("{} at crank {:.3}°", l.kind, l.input_rad.to_degrees()))
        .collect();
    if lines.is_empty() {
        "no limit positions".into()
    } else {
        lines.join("\n")
    }
}
