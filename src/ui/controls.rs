//! The control panel: play, speed, crank angle (or run time), one slider per link
//! length, spring constants and masses where the scene has them, branch toggles.

use eframe::egui;
use linkage::scene::Models;

use crate::session::params::{mass_range, spring_range};
use crate::session::{SceneEdit, unit_label};
use crate::state::AppState;
use crate::ui::control_map::ControlKind;

/// Label of the crank-angle slider (UI tests find it by this).
pub const CRANK_LABEL: &str = "crank angle (deg)";

/// Room a slider's number box takes beside it, points.
const NUMBER_BOX: f32 = 80.0;

/// Whether `ui` is too narrow for a slider, its number box and a label `label_width`
/// wide in one row (a phone's sheet, with sliders long enough for a finger).
fn too_narrow(ui: &egui::Ui, label_width: f32) -> bool {
    ui.available_width() < ui.spacing().slider_width + NUMBER_BOX + label_width
}

/// A slider with its label: beside it on a desktop screen (the panels are laid out
/// for that); on a phone or tablet beside it where the sheet holds both, else above
/// it, the slider then filling the width its number box leaves, so that no label is
/// cut off and the slider is long enough for a finger.
pub(crate) fn labelled(
    ui: &mut egui::Ui,
    slider: egui::Slider<'_>,
    label: &str,
    touch: bool,
) -> egui::Response {
    let text = egui::WidgetText::from(label).into_galley(
        ui,
        Some(egui::TextWrapMode::Extend),
        f32::INFINITY,
        egui::TextStyle::Body,
    );
    if !touch || !too_narrow(ui, text.size().x) {
        return ui.add(slider.text(label));
    }
    let name = ui.label(label);
    let width = (ui.available_width() - NUMBER_BOX).max(60.0);
    ui.scope(|ui| {
        ui.spacing_mut().slider_width = width;
        ui.add(slider).labelled_by(name.id)
    })
    .inner
}

/// The control panel.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    ui.heading("Controls");
    let touch = st.layout.compact();
    play_and_speed(ui, st, touch);
    crank_and_run_time(ui, st, touch);
    lengths(ui, st, touch);
    springs(ui, st, touch);
    masses(ui, st, touch);
    branches(ui, st);
    crate::ui::cam_panel::cam_panels(ui, st);
}

/// Play or pause, and the animation's speed (on a narrow phone, under the button).
fn play_and_speed(ui: &mut egui::Ui, st: &mut AppState, touch: bool) {
    let speed = |ui: &mut egui::Ui, st: &mut AppState| {
        labelled(
            ui,
            egui::Slider::new(&mut st.play.speed, 0.01..=4.0).logarithmic(true),
            "speed ×",
            touch,
        );
    };
    // The longest row: Play, the speed slider, its number and label.
    let narrow = touch && too_narrow(ui, 140.0);
    ui.horizontal(|ui| {
        let label = if st.play.playing { "Pause" } else { "Play" };
        let play = ui.button(label);
        st.controls.note(ui, ControlKind::Play, label, &play);
        if play.clicked() {
            st.play.playing = !st.play.playing;
        }
        if !narrow {
            speed(ui, st);
        }
    });
    if narrow {
        speed(ui, st);
    }
}

/// The crank angle, the dynamic run's time, and a refused edit's message.
fn crank_and_run_time(ui: &mut egui::Ui, st: &mut AppState, touch: bool) {
    let [lo, hi] = st.session.input_range_deg();
    let mut input = st.session.input_rad().to_degrees();
    if st.session.curves().full_rotation {
        input = input.rem_euclid(360.0);
    }
    let slider = egui::Slider::new(&mut input, lo..=hi);
    // A full turn wraps, so dragging past 360 continues from 0.
    let crank = labelled(ui, slider, CRANK_LABEL, touch);
    st.controls
        .note(ui, ControlKind::Crank, CRANK_LABEL, &crank);
    if crank.changed() {
        st.play.playing = false;
        st.edit(SceneEdit::Input { deg: input });
    }

    if let Some(Ok(run)) = st.session.dynamics() {
        let end = run.duration_s();
        let mut t = st.session.time_s();
        let r = labelled(
            ui,
            egui::Slider::new(&mut t, 0.0..=end),
            "run time (s)",
            touch,
        );
        st.controls
            .note(ui, ControlKind::RunTime, "run time (s)", &r);
        if r.changed() {
            st.play.playing = false;
            st.edit(SceneEdit::RunTime { s: t });
        }
    }

    if let Some(msg) = st.session.message() {
        ui.colored_label(ui.visuals().warn_fg_color, msg);
    }
}

/// One slider per link length.
fn lengths(ui: &mut egui::Ui, st: &mut AppState, touch: bool) {
    ui.separator();
    ui.label(format!("Link lengths ({})", unit_label(st.session.scene())));
    let lengths: Vec<_> = st.session.lengths().to_vec();
    for (i, p) in lengths.iter().enumerate() {
        let Some(mut v) = p.value(st.session.scene()) else {
            continue;
        };
        let r = labelled(ui, egui::Slider::new(&mut v, p.range()), &p.label, touch);
        st.controls.note(ui, ControlKind::Length, &p.label, &r);
        if r.changed() {
            st.edit(SceneEdit::Length { index: i, value: v });
        }
    }
}

/// One slider per spring's stiffness, where the scene models forces.
fn springs(ui: &mut egui::Ui, st: &mut AppState, touch: bool) {
    let springs: Vec<(usize, String, f64, f64)> = st
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
                s.k_n_per_m,
                o.k_n_per_m,
            )
        })
        .collect();
    if st.session.models() != Models::Kinematics && !springs.is_empty() {
        ui.separator();
        for (i, label, mut k, orig) in springs {
            let r = labelled(
                ui,
                egui::Slider::new(&mut k, spring_range(orig)),
                &label,
                touch,
            );
            st.controls.note(ui, ControlKind::Spring, &label, &r);
            if r.changed() {
                st.edit(SceneEdit::SpringK {
                    index: i,
                    n_per_m: k,
                });
            }
        }
    }
}

/// One slider per link mass of a dynamic scene.
fn masses(ui: &mut egui::Ui, st: &mut AppState, touch: bool) {
    if st.session.models() == Models::Dynamics {
        let masses: Vec<(usize, String, f64, f64)> = st
            .session
            .scene()
            .links
            .iter()
            .zip(&st.session.original().links)
            .enumerate()
            .filter_map(|(i, (l, o))| Some((i, format!("mass {} (kg)", l.name), l.mass?, o.mass?)))
            .collect();
        if !masses.is_empty() {
            ui.separator();
            for (i, label, mut m, orig) in masses {
                let r = labelled(
                    ui,
                    egui::Slider::new(&mut m, mass_range(orig)),
                    &label,
                    touch,
                );
                st.controls.note(ui, ControlKind::Mass, &label, &r);
                if r.changed() {
                    st.edit(SceneEdit::Mass { index: i, kg: m });
                }
            }
        }
    }
}

/// A checkbox per dyad to flip its assembly branch.
fn branches(ui: &mut egui::Ui, st: &mut AppState) {
    let branches = st.session.branches();
    if !branches.is_empty() {
        ui.separator();
        ui.label("Assembly branch");
        for (point, words, flipped) in branches {
            let mut on = flipped;
            let label = format!("flip at {point} (now {words})");
            let r = ui.checkbox(&mut on, &label);
            st.controls.note(ui, ControlKind::Branch, &label, &r);
            if r.changed() {
                st.edit(SceneEdit::FlipBranch { point });
            }
        }
    }
}
