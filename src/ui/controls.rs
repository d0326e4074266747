//! The control panel: play, speed, crank angle (or run time), one slider per link
//! length, spring constants and masses where the scene has them, branch toggles.

use eframe::egui;
use linkage::scene::Models;

use crate::i18n::tr;
use crate::session::params::{mass_range, spring_range};
use crate::session::{SceneEdit, unit_label};
use crate::state::AppState;
use crate::ui::control_map::ControlKind;
use crate::ui::number_field::{NumberInput, NumberSpec, slider_row};

/// The crank-angle slider's name in the control map, and its English label (UI
/// tests find it by this).
pub const CRANK_LABEL: &str = "crank angle (°)";

/// The control panel.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    ui.heading(tr!("controls.heading"));
    play_and_speed(ui, st);
    crank_and_run_time(ui, st);
    lengths(ui, st);
    springs(ui, st);
    masses(ui, st);
    branches(ui, st);
    crate::ui::cam_panel::cam_panels(ui, st);
}

/// Play or pause, and the animation's speed.
pub(crate) fn play_and_speed(ui: &mut egui::Ui, st: &mut AppState) {
    let (id, text) = if st.play.playing {
        ("Pause", tr!("controls.pause"))
    } else {
        ("Play", tr!("controls.play"))
    };
    let play = ui.button(text);
    st.controls.note(ui, ControlKind::Play, id, &play);
    if play.clicked() {
        st.play.playing = !st.play.playing;
    }
    let label = tr!("controls.speed");
    let spec = NumberSpec::new(&label, "", 0.01..=4.0).logarithmic();
    let (_, input) = slider_row(ui, "speed", &spec, st.play.speed);
    if let Some(v) = input.value() {
        st.play.speed = v;
    }
}

/// The crank angle, the dynamic run's time, and a refused edit's message.
pub(crate) fn crank_and_run_time(ui: &mut egui::Ui, st: &mut AppState) {
    let [lo, hi] = st.session.input_range_deg();
    let mut input = st.session.input_rad().to_degrees();
    if st.session.curves().full_rotation {
        input = input.rem_euclid(360.0);
    }
    let label = tr!("controls.crank_angle");
    let spec = NumberSpec::new(&label, "°", lo..=hi);
    let spec = if st.session.curves().full_rotation {
        spec.wrapping()
    } else {
        spec
    };
    let (crank, typed) = slider_row(ui, "crank", &spec, input);
    st.controls
        .note(ui, ControlKind::Crank, CRANK_LABEL, &crank);
    if let Some(deg) = typed.value() {
        st.play.playing = false;
        st.edit(SceneEdit::Input { deg });
    }

    if let Some(Ok(run)) = st.session.dynamics() {
        let label = tr!("controls.run_time");
        let spec = NumberSpec::new(&label, "s", 0.0..=run.duration_s());
        let (r, typed) = slider_row(ui, "run time", &spec, st.session.time_s());
        st.controls
            .note(ui, ControlKind::RunTime, "run time (s)", &r);
        if let Some(s) = typed.value() {
            st.play.playing = false;
            st.edit(SceneEdit::RunTime { s });
        }
    }

    if let Some(msg) = st.session.message_in(crate::ui::words::lang()) {
        ui.colored_label(ui.visuals().warn_fg_color, msg);
    }
}

/// Notes a row in the control map and asks for its edit.
fn row_edit(
    ui: &egui::Ui,
    st: &mut AppState,
    kind: ControlKind,
    label: &str,
    (r, input): (egui::Response, NumberInput),
    edit: impl FnOnce(f64) -> SceneEdit,
) {
    st.controls.note(ui, kind, label, &r);
    if let Some(v) = input.value() {
        st.edit(edit(v));
    }
}

/// One row per link length, on a logarithmic scale (a drag changes a length by
/// the same ratio anywhere along it).
fn lengths(ui: &mut egui::Ui, st: &mut AppState) {
    ui.separator();
    let unit = unit_label(st.session.scene());
    ui.label(tr!("controls.link_lengths", unit = unit));
    let lengths: Vec<_> = st.session.lengths().to_vec();
    for (i, p) in lengths.iter().enumerate() {
        let Some(v) = p.value(st.session.scene()) else {
            continue;
        };
        let spec = NumberSpec::new(&p.label, unit, p.range()).logarithmic();
        let row = slider_row(ui, ("length", i), &spec, v);
        row_edit(ui, st, ControlKind::Length, &p.label, row, |value| {
            SceneEdit::Length { index: i, value }
        });
    }
}

/// One row per spring's stiffness, where the scene models forces.
fn springs(ui: &mut egui::Ui, st: &mut AppState) {
    if st.session.models() == Models::Kinematics {
        return;
    }
    // (index, the control map's English name, the label shown, k, k as opened)
    let springs: Vec<(usize, String, String, f64, f64)> = st
        .session
        .scene()
        .forces
        .springs
        .iter()
        .zip(&st.session.original().forces.springs)
        .enumerate()
        .map(|(i, (s, o))| {
            (
                i,
                format!("k {}-{} (N/m)", s.a, s.b),
                tr!("controls.spring", a = s.a, b = s.b),
                s.k_n_per_m,
                o.k_n_per_m,
            )
        })
        .collect();
    if springs.is_empty() {
        return;
    }
    ui.separator();
    for (i, id, label, k, orig) in springs {
        let spec = NumberSpec::new(&label, "N/m", spring_range(orig)).logarithmic();
        let row = slider_row(ui, ("spring", i), &spec, k);
        row_edit(ui, st, ControlKind::Spring, &id, row, |n_per_m| {
            SceneEdit::SpringK { index: i, n_per_m }
        });
    }
}

/// One row per link mass of a dynamic scene.
fn masses(ui: &mut egui::Ui, st: &mut AppState) {
    if st.session.models() != Models::Dynamics {
        return;
    }
    // (index, the control map's English name, the label shown, kg, kg as opened)
    let masses: Vec<(usize, String, String, f64, f64)> = st
        .session
        .scene()
        .links
        .iter()
        .zip(&st.session.original().links)
        .enumerate()
        .filter_map(|(i, (l, o))| {
            let id = format!("mass {} (kg)", l.name);
            let label = tr!("controls.mass", link = l.name);
            Some((i, id, label, l.mass?, o.mass?))
        })
        .collect();
    if masses.is_empty() {
        return;
    }
    ui.separator();
    for (i, id, label, m, orig) in masses {
        let spec = NumberSpec::new(&label, "kg", mass_range(orig)).logarithmic();
        let row = slider_row(ui, ("mass", i), &spec, m);
        row_edit(ui, st, ControlKind::Mass, &id, row, |kg| SceneEdit::Mass {
            index: i,
            kg,
        });
    }
}

/// A checkbox per dyad to flip its assembly branch.
fn branches(ui: &mut egui::Ui, st: &mut AppState) {
    let branches = st.session.branches();
    if !branches.is_empty() {
        ui.separator();
        ui.label(tr!("controls.branch"));
        for (point, branch, flipped) in branches {
            let mut on = flipped;
            let label = tr!("controls.flip", point = point, now = branch_shown(&branch));
            let r = ui
                .push_id(("branch", &point), |ui| ui.checkbox(&mut on, &label))
                .inner;
            let english = crate::session::branch_words(&branch);
            let id = format!("flip at {point} (now {english})");
            st.controls.note(ui, ControlKind::Branch, &id, &r);
            if r.changed() {
                st.edit(SceneEdit::FlipBranch { point });
            }
        }
    }
}

/// A dyad's assembly branch in the app's language.
fn branch_shown(b: &linkage::scene::Branch) -> String {
    use linkage::scene::Branch;
    match b {
        Branch::Left(a, c) => tr!("branch.left", a = a, c = c),
        Branch::Right(a, c) => tr!("branch.right", a = a, c = c),
        Branch::Along => tr!("branch.along"),
        Branch::Against => tr!("branch.against"),
    }
}
