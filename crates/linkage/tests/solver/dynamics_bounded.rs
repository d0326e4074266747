//! Every integration ends, whatever the input: regression tests for issue 11's
//! fuzzing findings, where `simulate` ran for over 20 s (never returned) with
//! `--dt 1e-12`, `--atol 1e-300`, a spring of k = 1e12 N/m, or a spring free length
//! of 1e300 m. Each now ends with an error naming the cause and what to change.

use crate::common;

use common::scene_text;
use linkage::dynamics::{MAX_STEPS, Method, Settings, simulate};
use linkage::{Kinematics, Mechanism};

fn flipper_with(from: &str, to: &str) -> Kinematics {
    let text = scene_text("gravity_flipper.ron").replace(from, to);
    Kinematics::new(Mechanism::from_ron(&text).expect("scene")).expect("flipper")
}

fn flipper() -> Kinematics {
    flipper_with("", "")
}

#[test]
fn fixed_step_of_1e_minus_12_is_refused_before_running() {
    let mut s = Settings::new(Method::Rk4);
    s.step = 1e-12;
    s.t_end = 1.0;
    let msg = simulate(&flipper(), &s).expect_err("refused").to_string();
    assert!(
        msg.contains("step") && msg.contains(&MAX_STEPS.to_string()),
        "{msg}"
    );
    assert!(
        msg.contains("at least 1.000e-6"),
        "names the least step: {msg}"
    );
}

#[test]
fn output_dt_of_1e_minus_9_is_refused_before_running() {
    let mut s = Settings::new(Method::Dop853);
    s.output_dt = Some(1e-9);
    s.t_end = 1.0;
    let msg = simulate(&flipper(), &s).expect_err("refused").to_string();
    assert!(
        msg.contains("output dt") && msg.contains("samples"),
        "{msg}"
    );
}

#[test]
fn atol_of_1e_minus_300_ends() {
    let mut s = Settings::new(Method::Dop853);
    s.atol = 1e-300;
    s.rtol = 1e-15;
    s.t_end = 1.0;
    s.use_stops = false;
    // Either it finishes (tolerances far below round-off are met by luck) or it ends
    // with the budget's message; it never runs on.
    if let Err(e) = simulate(&flipper(), &s) {
        let msg = e.to_string();
        assert!(msg.contains("steps") || msg.contains("collapsed"), "{msg}");
    }
}

#[test]
fn spring_of_1e12_under_an_explicit_method_names_implicit_and_the_stiffness() {
    let k = flipper_with("k_n_per_m: 1500.0", "k_n_per_m: 1e12");
    let mut s = Settings::new(Method::Dp5);
    s.t_end = 1.0;
    s.use_stops = false;
    // It ends, spending its step budget or finishing at the stability limit's step;
    // either way what it says names the implicit method and the stiffness.
    let msg = match simulate(&k, &s) {
        Err(e) => e.to_string(),
        Ok(sim) => sim
            .stats
            .warnings
            .iter()
            .map(|w| w.to_string())
            .collect::<Vec<_>>()
            .join("; "),
    };
    assert!(msg.contains("implicit"), "{msg}");
    assert!(msg.contains("|λ|"), "names the stiffness: {msg}");
}

#[test]
fn spring_free_length_of_1e300_ends() {
    let k = flipper_with(
        "free_length: UnstretchedAtStart",
        "free_length: Length(1e300)",
    );
    let mut s = Settings::new(Method::Dop853);
    s.t_end = 1.0;
    match simulate(&k, &s) {
        Ok(sim) => assert!(sim.samples.iter().all(|x| x.t.is_finite())),
        Err(e) => assert!(!e.to_string().is_empty()),
    }
}
