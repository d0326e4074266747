//! The cam panel, in the controls for a scene with a cam joint: the program's
//! segments in a table (the law of each rise and return, each segment's angle), the
//! lift and the roller, the cam's figures against their limits (the pressure angle
//! and the radius of curvature, in red where passed), the joins' continuity and the
//! laws' peak coefficients, and the exports (CSV, SVG, and DXF on the desktop).
//! Every change is an undoable edit, refused with the reason where it cannot be.

use eframe::egui;
use linkage::cam::{Law, SegmentSpec, peak_coefficients};
use linkage::scene::CamJointSpec;

use crate::file_action::FileAction;
use crate::i18n::tr;
use crate::session::SceneEdit;
use crate::session::cam_curves::CamCurves;
use crate::session::cam_edit::CamEdit;
use crate::session::words::length;
use crate::state::AppState;
use crate::ui::control_map::ControlKind;
use crate::ui::number_field::{NumberSpec, boxed, cell};

/// Red, for a figure past its limit.
const PAST: egui::Color32 = egui::Color32::from_rgb(220, 70, 60);

/// The panel of every cam joint of the scene.
pub fn cam_panels(ui: &mut egui::Ui, st: &mut AppState) {
    let specs = st.session.scene().cams.clone();
    for (index, spec) in specs.iter().enumerate() {
        ui.separator();
        let title = tr!("cam.title", cam = spec.cam, follower = spec.follower);
        ui.label(egui::RichText::new(title).strong());
        segments(ui, st, index, spec);
        lift_and_roller(ui, st, index, spec);
        if let Some(c) = st.session.curves().cams.get(index).cloned() {
            figures(ui, &c, st.session.scene().length_unit);
        }
        continuity_and_peaks(ui, st, index, spec);
        exports(ui, st, index);
    }
}

/// A segment's kind in the textbook's words.
fn kind_name(s: &SegmentSpec) -> String {
    match s {
        SegmentSpec::Rise { .. } => tr!("cam.rise"),
        SegmentSpec::Dwell { .. } => tr!("cam.dwell"),
        SegmentSpec::Return { .. } => tr!("cam.return"),
    }
}

/// The table: a row per segment with its law and its angle; a refused angle's reason
/// under it.
fn segments(ui: &mut egui::Ui, st: &mut AppState, cam: usize, spec: &CamJointSpec) {
    let mut refusals = Vec::new();
    egui::Grid::new(("cam segments", cam))
        .num_columns(3)
        .striped(true)
        .show(ui, |ui| {
            let n = spec.segments.len();
            for (segment, s) in spec.segments.iter().enumerate() {
                let (kind, law, deg) = (kind_name(s), s.law(), s.angle_deg());
                let name = ui.label(format!("{} {kind}", segment + 1));
                match law {
                    Some(law) => law_menu(ui, st, (cam, segment), law, name.id),
                    None => {
                        ui.label("");
                    }
                }
                // The next segment gives or takes the difference: together they
                // hold what this one may span.
                let room = deg + spec.segments[(segment + 1) % n].angle_deg();
                let id = format!("segment {} angle (deg)", segment + 1);
                let label = tr!("cam.segment_angle", segment = segment + 1);
                let spec = NumberSpec::new(&label, "°", 0.0..=room);
                let (r, typed, refused) = cell(ui, ("cam segment", cam, segment), &spec, deg);
                refusals.extend(refused);
                let r = r.on_hover_text(tr!("cam.segment_angle_hint"));
                st.controls.note(ui, ControlKind::Cam, &id, &r);
                if let Some(deg) = typed.value() {
                    st.edit(SceneEdit::Cam {
                        cam,
                        edit: CamEdit::Span { segment, deg },
                    });
                }
                ui.end_row();
            }
        });
    for words in refusals {
        ui.colored_label(ui.visuals().warn_fg_color, words);
    }
}

/// The law of a rise or return, chosen from every law.
fn law_menu(
    ui: &mut egui::Ui,
    st: &mut AppState,
    (cam, segment): (usize, usize),
    law: Law,
    label: egui::Id,
) {
    let mut chosen = law;
    let menu = egui::ComboBox::from_id_salt(("cam law", cam, segment))
        .selected_text(law_name(law))
        .show_ui(ui, |ui| {
            for l in Law::ALL {
                ui.selectable_value(&mut chosen, l, law_name(l));
            }
        });
    let r = menu.response.labelled_by(label);
    st.controls.note(
        ui,
        ControlKind::Cam,
        &format!("segment {} law", segment + 1),
        &r,
    );
    if chosen != law {
        st.edit(SceneEdit::Cam {
            cam,
            edit: CamEdit::Law {
                segment,
                law: chosen,
            },
        });
    }
}

/// A law as the textbooks name it, in the app's language.
pub fn law_name(law: Law) -> String {
    linkage_model::exercise::words::law_name(law, crate::ui::words::lang())
}

/// The largest lift (every lift scales with it) and the roller's radius.
fn lift_and_roller(ui: &mut egui::Ui, st: &mut AppState, cam: usize, spec: &CamJointSpec) {
    let largest = spec
        .segments
        .iter()
        .filter_map(SegmentSpec::lift)
        .fold(0.0, f64::max);
    let arm = st.session.curves().cams.get(cam).is_some_and(|c| c.is_arm);
    let length = crate::session::unit_label(st.session.scene());
    // A lift up to ten times the one the cam has (an arm's swing below a right
    // angle), a roller up to ten times its own: past these the cam's figures are
    // meaningless; within them, the scene's own checks refuse what does not build.
    let (unit, lift_range) = if arm {
        ("°", 0.0..=(10.0 * largest).min(90.0))
    } else {
        (length, 0.0..=10.0 * largest)
    };
    let lift = tr!("cam.lift", unit = unit);
    let spec_lift = NumberSpec::new(&lift, unit, lift_range);
    let (r, typed) = boxed(ui, ("cam lift", cam), &spec_lift, largest);
    let r = r.on_hover_text(tr!("cam.lift_hint"));
    st.controls.note(ui, ControlKind::Cam, "lift", &r);
    if let Some(to) = typed.value() {
        st.edit(SceneEdit::Cam {
            cam,
            edit: CamEdit::Lift(to),
        });
    }
    let roller = tr!("cam.roller", unit = length);
    let top = 10.0 * spec.roller_radius.max(f64::MIN_POSITIVE);
    let spec_roller = NumberSpec::new(&roller, length, 0.0..=top);
    let (r, typed) = boxed(ui, ("cam roller", cam), &spec_roller, spec.roller_radius);
    st.controls.note(ui, ControlKind::Cam, "roller", &r);
    if let Some(radius) = typed.value() {
        st.edit(SceneEdit::Cam {
            cam,
            edit: CamEdit::Roller(radius),
        });
    }
}

/// The base circle, the largest pressure angle and the least radius of the
/// profile, each located on the cam (not read off its samples), red past their
/// limits.
fn figures(ui: &mut egui::Ui, c: &CamCurves, unit: linkage::scene::LengthUnit) {
    ui.label(tr!(
        "cam.base_circle",
        radius = length(c.base_radius_m, unit)
    ));
    let p = c.largest_pressure;
    let text = tr!(
        "cam.largest_pressure",
        angle = format!("{:.2}", p.value.abs().to_degrees()),
        at = format!("{:.1}", p.angle_rad.to_degrees()),
        limit = format!("{:.0}", c.pressure_limit_rad.to_degrees())
    );
    let past = p.value.abs() > c.pressure_limit_rad;
    ui.label(if past {
        egui::RichText::new(text).color(PAST)
    } else {
        text.into()
    });
    let undercut = c
        .points
        .iter()
        .any(|q| q.pitch_radius_m > 0.0 && q.profile_radius_m <= 0.0);
    let r = c.least_profile_radius;
    let text = tr!(
        "cam.least_radius",
        radius = length(r.value, unit),
        at = format!("{:.1}", r.angle_rad.to_degrees()),
        undercut = if undercut {
            tr!("cam.undercut")
        } else {
            String::new()
        }
    );
    ui.label(if undercut {
        egui::RichText::new(text).color(PAST)
    } else {
        text.into()
    });
}

/// The continuity at each join and the laws' peak coefficients, folded away.
fn continuity_and_peaks(ui: &mut egui::Ui, st: &AppState, cam: usize, spec: &CamJointSpec) {
    let Some(joint) = st.session.mechanism().cams.get(cam) else {
        return;
    };
    egui::CollapsingHeader::new(tr!("cam.joins"))
        .id_salt(("cam joins", cam))
        .show(ui, |ui| {
            for j in joint.program.joins() {
                ui.label(tr!(
                    "cam.join",
                    at = format!("{:.1}", j.angle_rad.to_degrees()),
                    before = j.before + 1,
                    after = j.after + 1,
                    continuity = format!("{:?}", j.continuity)
                ));
            }
            let mut laws: Vec<Law> = spec.segments.iter().filter_map(SegmentSpec::law).collect();
            laws.dedup();
            for law in laws {
                let k = peak_coefficients(law);
                ui.label(format!(
                    "{}: C_v {:.4}, C_a {:.4}, C_j {:.4}",
                    law_name(law),
                    k.velocity,
                    k.acceleration,
                    k.jerk
                ));
            }
        });
}

/// The exports: the table as CSV, the profile as SVG, and on the desktop as DXF.
fn exports(ui: &mut egui::Ui, st: &mut AppState, cam: usize) {
    let mut actions = vec![
        ("Cam CSV…", FileAction::CamCsv(cam)),
        ("Cam SVG…", FileAction::CamSvg(cam)),
    ];
    if cfg!(not(target_arch = "wasm32")) {
        actions.push(("Cam DXF…", FileAction::CamDxf(cam)));
    }
    ui.horizontal_wrapped(|ui| {
        for (id, action) in actions {
            let shown = match action {
                FileAction::CamCsv(_) => tr!("cam.csv"),
                FileAction::CamSvg(_) => tr!("cam.svg"),
                _ => tr!("cam.dxf"),
            };
            let r = ui.button(shown).on_hover_text(action.title());
            st.controls.note(ui, ControlKind::Cam, id, &r);
            if r.clicked() {
                st.commands.file = Some(action);
            }
        }
    });
}
