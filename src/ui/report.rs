//! The report strip: Grashof class, time ratio, strokes and swings, limit positions,
//! transmission angle; each entry shows where on the cycle it occurs when hovered.

use eframe::egui;

use linkage::analysis::Report;
use linkage::scene::LengthUnit;
use linkage_model::session::words::length;

use crate::i18n::tr;
use crate::session::derived::Shown;
use crate::state::AppState;

/// The strip along the bottom. While edits come (a slider dragged) it shows the
/// report from before them, greyed, until a frame without an edit makes the new one.
pub fn strip(ui: &mut egui::Ui, st: &AppState) {
    egui::Panel::bottom("report").show(ui, |ui| {
        ui.horizontal_wrapped(|ui| {
            // The last file action's line first, where it does not move the top bar.
            if let Some(status) = &st.status {
                ui.strong(status);
                ui.separator();
            }
            shown(ui, st, Form::Strip);
        });
    });
}

/// The report as a page of the compact arrangements' sheet: each entry with where on
/// the cycle it occurs written under it (a finger cannot hover).
pub fn page(ui: &mut egui::Ui, st: &AppState) {
    shown(ui, st, Form::Page);
}

/// How the entries are laid out.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Form {
    /// In a row, the details on hover.
    Strip,
    /// One under another, the details written out.
    Page,
}

fn shown(ui: &mut egui::Ui, st: &AppState, form: Form) {
    let unit = st.session.scene().length_unit;
    match st.session.report_shown() {
        Shown::Current(r) => entries(ui, r, unit, form),
        Shown::Outdated(r) => {
            ui.weak(tr!("report.updating"));
            if form == Form::Strip {
                ui.separator();
            }
            ui.add_enabled_ui(false, |ui| entries(ui, r, unit, form));
        }
        Shown::Pending => {
            ui.weak(tr!("report.computing"));
        }
    }
}

/// The report's entries, or why there is none.
fn entries(
    ui: &mut egui::Ui,
    report: &Result<Report, linkage::LinkageError>,
    unit: LengthUnit,
    form: Form,
) {
    let r = match report {
        Ok(r) => r,
        Err(e) => {
            let why = crate::ui::words::refusal(e, unit);
            ui.colored_label(ui.visuals().warn_fg_color, tr!("report.none", why = why));
            return;
        }
    };
    for (k, (headline, details)) in items(r, unit).into_iter().enumerate() {
        match form {
            Form::Strip => {
                if k > 0 {
                    ui.separator();
                }
                let shown = ui.label(headline);
                if !details.is_empty() {
                    shown.on_hover_text(details);
                }
            }
            Form::Page => {
                ui.strong(headline);
                if !details.is_empty() {
                    ui.weak(details);
                }
                ui.add_space(4.0);
            }
        }
    }
}

/// The Grashof entry: the class, and the sums it is judged by.
fn grashof_item(r: &Report, unit: LengthUnit) -> (String, String) {
    match &r.grashof {
        Some(g) => (
            tr!("report.grashof", class = grashof_class(g.class)),
            format!(
                "s + l = {}, p + q = {} ({}){}",
                length(g.s_plus_l_m, unit),
                length(g.p_plus_q_m, unit),
                g.links.join(", "),
                if g.change_point {
                    tr!("report.change_point")
                } else {
                    String::new()
                }
            ),
        ),
        None => (tr!("report.grashof_none"), String::new()),
    }
}

/// Each entry of the report: its headline and where on the cycle it occurs.
fn items(r: &Report, unit: LengthUnit) -> Vec<(String, String)> {
    let mut out = vec![grashof_item(r, unit)];
    let note = r
        .time_ratio_note
        .as_ref()
        .map(ToString::to_string)
        .unwrap_or_default();
    out.push(match r.time_ratio {
        Some(k) => (format!("K = {k:.3}"), note),
        None => (tr!("report.k_none"), note),
    });
    for (name, stroke) in &r.strokes_m {
        out.push((
            tr!("report.stroke", name = name, length = length(*stroke, unit)),
            limits_of(r, name),
        ));
    }
    for (name, swing) in &r.swings_rad {
        out.push((
            tr!(
                "report.swing",
                name = name,
                deg = format!("{:.2}", swing.to_degrees())
            ),
            limits_of(r, name),
        ));
    }
    if let Some(t) = &r.transmission_angle_rad {
        out.push((
            tr!("report.mu_min", deg = format!("{:.2}", t.min.to_degrees())),
            tr!(
                "report.mu_where",
                at = format!("{:.2}", t.at.to_degrees()),
                group = crate::ui::words::group(&t.group),
                max = format!("{:.2}", t.max.to_degrees()),
                at_max = format!("{:.2}", t.at_max.to_degrees())
            ),
        ));
    }
    if !r.toggles.is_empty() {
        let text: Vec<String> = r
            .toggles
            .iter()
            .map(|t| {
                tr!(
                    "report.toggle_line",
                    deg = format!("{:.2}", t.input_rad.to_degrees()),
                    ratio = ratio_words(t.ratio),
                    joints = joined(&t.collinear_joints)
                )
            })
            .collect();
        out.push((
            tr!("report.toggles", count = r.toggles.len()),
            text.join("\n"),
        ));
    }
    if !r.branch_points.is_empty() {
        let text: Vec<String> = r.branch_points.iter().map(branch_point_line).collect();
        out.push((
            tr!("report.branch_points", count = r.branch_points.len()),
            text.join("\n"),
        ));
    }
    out
}

/// The Grashof class in the textbook's words.
fn grashof_class(class: linkage::analysis::GrashofClass) -> String {
    use linkage::analysis::GrashofClass as G;
    match class {
        G::CrankRocker => tr!("grashof.crank_rocker"),
        G::DoubleCrank => tr!("grashof.double_crank"),
        G::DoubleRocker => tr!("grashof.double_rocker"),
        G::RockerCrank => tr!("grashof.rocker_crank"),
        G::ChangePoint => tr!("grashof.change_point"),
        G::TripleRocker => tr!("grashof.triple_rocker"),
    }
}

/// "crank 180.00°: coupler and rocker, joined at C, B on D".
fn branch_point_line(b: &linkage::branch_points::BranchPoint) -> String {
    let pairs: Vec<String> = b
        .coincident_joints
        .iter()
        .map(|[p, q]| tr!("report.coincident", p = p, q = q))
        .collect();
    tr!(
        "report.branch_line",
        deg = format!("{:.2}", b.input_rad.to_degrees()),
        group = crate::ui::words::group(&b.group),
        pairs = pairs.concat()
    )
}

/// What a toggle's velocity ratio means, in the user's words.
fn ratio_words(ratio: linkage::analysis::ToggleRatio) -> String {
    match ratio {
        linkage::analysis::ToggleRatio::Zero => tr!("report.ratio_zero"),
        linkage::analysis::ToggleRatio::Infinite => tr!("report.ratio_infinite"),
    }
}

fn limits_of(r: &linkage::analysis::Report, output: &str) -> String {
    let lines: Vec<String> = r
        .limit_positions
        .iter()
        .filter(|l| l.output == output)
        .map(|l| {
            let deg = format!("{:.3}", l.input_rad.to_degrees());
            match l.kind {
                linkage::analysis::Extreme::Max => tr!("report.limit_max", deg = deg),
                linkage::analysis::Extreme::Min => tr!("report.limit_min", deg = deg),
            }
        })
        .collect();
    if lines.is_empty() {
        tr!("report.no_limits")
    } else {
        lines.join("\n")
    }
}

/// Items in their report words, separated by commas.
fn joined(items: &[impl std::fmt::Display]) -> String {
    items
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}
