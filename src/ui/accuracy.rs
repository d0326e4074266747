//! The accuracy panel: which solver path and tolerance, what a frame costs, and for
//! dynamic scenes the integrator, its tolerance, its cost and its error estimate —
//! the speed/accuracy trade, live.

use eframe::egui;
use linkage::PathKind;
use linkage::dynamics::Method;
use linkage::scene::Models;

use crate::i18n::tr;
use crate::session::dynamic_run::{IntegratorChoice, METHODS};
use crate::state::AppState;
use crate::ui::control_map::ControlKind;
use crate::ui::number_field::{NumberSpec, slider_row};

/// "degrees of freedom: 3(n − 1) − 2j = …" for the mechanism's links and joints,
/// with "− h" for its cam contacts (higher pairs, one constraint each) where it has
/// any.
pub fn mobility_line(m: &linkage::Mechanism) -> String {
    let n = m.links.len();
    let j = m.revolutes.len() + m.sliders.len();
    let h = m.cams.len();
    let dof = 3 * (n as i64 - 1) - 2 * j as i64 - h as i64;
    let moving = n - 1;
    if h == 0 {
        return tr!(
            "accuracy.mobility",
            moving = moving,
            j = j,
            dof = dof,
            n = n
        );
    }
    tr!(
        "accuracy.mobility_cams",
        moving = moving,
        j = j,
        h = h,
        dof = dof,
        n = n
    )
}

/// The accuracy panel.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    ui.heading(tr!("accuracy.heading"));
    let k = st.session.kinematics();
    let solver = &k.mechanism().solver;
    match k.path() {
        PathKind::ClosedForm => ui.label(tr!("accuracy.closed_form")),
        path => ui.label(tr!(
            "accuracy.newton",
            path = path.label(),
            tolerance = format!("{:.0e}", solver.tolerance),
            iterations = solver.max_iterations
        )),
    };
    let conditioning = format!("{:.3e}", st.session.pose().conditioning);
    ui.label(tr!("accuracy.conditioning", value = conditioning))
        .on_hover_text(tr!("accuracy.conditioning_hint"));
    ui.label(mobility_line(k.mechanism()))
        .on_hover_text(tr!("accuracy.mobility_hint"));
    if st.timing.show {
        let frame = format!("{:.0}", st.timing.cost.frame_us);
        let solver = format!("{:.0}", st.timing.cost.solver_us);
        ui.label(tr!("accuracy.cpu", frame = frame, solver = solver));
    }

    match st.session.models() {
        Models::Kinematics => {
            ui.label(tr!("accuracy.kinematics_only"));
            return;
        }
        Models::Kinetostatics => {
            ui.label(tr!("accuracy.kinetostatics_only"));
            return;
        }
        Models::Dynamics => {}
    }
    ui.separator();
    ui.label(tr!("accuracy.dynamics"));
    let mut choice = st.session.integrator();
    integrator_menu(ui, st, &mut choice);
    let changed = tolerance_slider(ui, st, &mut choice);
    run_stats(ui, st);
    if changed || choice.method != st.session.integrator().method {
        st.edit(crate::session::SceneEdit::Integrator(choice));
    }
}

/// The integrator's menu, each item noted for the tests.
fn integrator_menu(ui: &mut egui::Ui, st: &mut AppState, choice: &mut IntegratorChoice) {
    let mut items = Vec::new();
    let menu = egui::ComboBox::from_label(tr!("accuracy.integrator"))
        .selected_text(choice.method.label())
        .show_ui(ui, |ui| {
            for m in METHODS {
                let r = ui.selectable_value(&mut choice.method, m, m.label());
                items.push((m.label(), r.rect, ui.clip_rect().contains_rect(r.rect)));
            }
        });
    st.controls
        .note(ui, ControlKind::Integrator, "integrator", &menu.response);
    for (label, rect, visible) in items {
        st.controls
            .note_rect(ControlKind::IntegratorItem, label, rect, visible);
    }
}

/// The adaptive methods' rtol, or the fixed step (Δφ or Δt); returns whether it
/// changed.
fn tolerance_slider(ui: &mut egui::Ui, st: &mut AppState, choice: &mut IntegratorChoice) -> bool {
    let (value, spec) = if choice.method.is_adaptive() {
        (
            &mut choice.rtol,
            NumberSpec::new("rtol", "", 1e-12..=1e-3).logarithmic(),
        )
    } else {
        let (range, label, unit) = if choice.method == Method::EnergyIncrement {
            (1e-4..=1e-1, "Δφ (rad)", "rad")
        } else {
            (1e-6..=1e-2, "Δt (s)", "s")
        };
        choice.step = choice.step.clamp(*range.start(), *range.end());
        (
            &mut choice.step,
            NumberSpec::new(label, unit, range).logarithmic(),
        )
    };
    let (tolerance, input) = slider_row(ui, "tolerance", &spec, *value);
    st.controls
        .note(ui, ControlKind::Tolerance, "tolerance", &tolerance);
    match input.value() {
        Some(v) => {
            *value = v;
            true
        }
        None => false,
    }
}

/// The run's progress, its cost and accuracy, its warnings and end stops, or why it
/// failed.
fn run_stats(ui: &mut egui::Ui, st: &AppState) {
    match st.session.dynamics() {
        None => {
            let [t, end] = st.session.run_progress().unwrap_or([0.0, 0.0]);
            let (t, end) = (format!("{t:.3}"), format!("{end:.1}"));
            ui.label(tr!("accuracy.computing", t = t, end = end));
        }
        Some(Ok(run)) => {
            let s = run.stats();
            let cpu = if st.timing.show {
                tr!(
                    "accuracy.run_cpu",
                    ms = format!("{:.2}", s.cpu_seconds * 1e3)
                )
            } else {
                String::new()
            };
            ui.label(tr!(
                "accuracy.run_steps",
                steps = s.steps,
                rejected = s.rejected_steps,
                rhs = s.rhs_evaluations,
                cpu = cpu
            ));
            ui.label(tr!(
                "accuracy.run_error",
                estimate = format!("{:.2e}", s.max_error_estimate),
                drift = format!("{:.2e}", run.energy_drift_j)
            ));
            for w in &s.warnings {
                let words = crate::session::words::run_warning(w, crate::ui::words::lang());
                ui.colored_label(ui.visuals().warn_fg_color, words);
            }
            for e in run.sim.events.iter().filter(|e| e.stopped) {
                ui.label(format!(
                    "{}: t = {:.4} s, φ = {:.3}°, ω = {:.4} rad/s",
                    e.name,
                    e.state.t,
                    e.state.q.to_degrees(),
                    e.state.q_dot
                ));
            }
        }
        Some(Err(e)) => {
            let why = e.words(st.session.scene().length_unit, crate::ui::words::lang());
            ui.colored_label(ui.visuals().error_fg_color, why);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shipped_scene_and_template_counts_one_degree_of_freedom() {
        let all = crate::catalog::BUILTIN_SCENES
            .iter()
            .chain(crate::catalog::TEMPLATES);
        for b in all {
            let m = linkage::Mechanism::from_ron(b.text).expect("valid");
            let line = mobility_line(&m);
            assert!(line.contains(" = 1 ("), "{}: {line}", b.key);
        }
        let m = linkage::Mechanism::from_ron(
            crate::catalog::builtin("slider_crank")
                .expect("shipped")
                .text,
        )
        .expect("valid");
        assert_eq!(
            mobility_line(&m),
            "degrees of freedom: 3(n − 1) − 2j = 3·3 − 2·4 = 1 (4 links, 4 joints)"
        );
    }
}
