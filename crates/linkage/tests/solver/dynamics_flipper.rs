//! Dynamics of the gravity flipper (paper 3) against independent references: the
//! reduction's dJ/dq against finite differences of J, ½Jq̇² against the kinetic
//! energy summed link by link on the Newton path, the paper's reported peak, a
//! refined run, and the energy balance.

use crate::common;

use common::{kinematics, mechanism, scene_text};
use linkage::dynamics::{ForceModel, Method, Settings, simulate};
use linkage::scene::SolverPath;
use linkage::{Kinematics, LinkageError, Mechanism, SceneProblem};

fn reduced_at(k: &mut Kinematics, forces: &ForceModel, q: f64) -> linkage::dynamics::Reduced {
    let mut s = k.empty_solution();
    k.solve_into(q, 1.0, &mut s).expect("assembles");
    forces.reduce(&s, 0.0)
}

/// Fixed-step settings: `step` (s, or rad for the energy method) to `t_end`.
fn fixed(method: Method, step: f64, t_end: f64) -> Settings {
    let mut s = Settings::new(method);
    s.step = step;
    s.t_end = t_end;
    s
}

fn model(k: &mut Kinematics) -> ForceModel {
    let start = k.solve(k.mechanism().driver.start_rad).expect("start");
    ForceModel::new(&k.mechanism().clone(), &start).expect("forces")
}

/// Central differences, h = 1e-5 rad: truncation h²/6·|J'''| ≈ 1e-11 of J, round-off
/// eps·J/h ≈ 2e-11 of J; 1e-7 of J leaves margin while a wrong term is of order 1.
#[test]
fn dj_dq_matches_finite_differences_of_j() {
    let mut k = kinematics("gravity_flipper.ron", SolverPath::ClosedForm);
    let forces = model(&mut k);
    let h = 1e-5;
    for deg in [40.0_f64, 50.0, 60.0, 69.5, 90.0, 110.0] {
        let q = deg.to_radians();
        let r = reduced_at(&mut k, &forces, q);
        let fd = (reduced_at(&mut k, &forces, q + h).j - reduced_at(&mut k, &forces, q - h).j)
            / (2.0 * h);
        assert!(
            (fd - r.dj_dq).abs() < 1e-7 * r.j.max(1e-3),
            "{deg} deg: {fd} vs {}",
            r.dj_dq
        );
        assert!(r.j > 0.0);
    }
}

/// ½ J q̇² against Σ ½ m v_s² + ½ I ω², summed from a Newton-path solution at speed w.
#[test]
fn equivalent_inertia_gives_the_kinetic_energy() {
    let m = mechanism("gravity_flipper.ron");
    let mut cf = Kinematics::with_path(m.clone(), SolverPath::ClosedForm).expect("cf");
    let mut nw = Kinematics::with_path(m.clone(), SolverPath::Newton).expect("newton");
    let forces = model(&mut cf);
    let w = -2.7;
    for deg in [45.0_f64, 69.5, 100.0] {
        let q = deg.to_radians();
        let j = reduced_at(&mut cf, &forces, q).j;
        let mut s = nw.empty_solution();
        nw.solve_into(q, w, &mut s).expect("newton");
        let ke: f64 = m
            .moving_links()
            .map(|l| {
                let link = &m.links[l];
                let c = s.links[l].point(&link.centroid_m.expect("centroid"));
                0.5 * link.mass_kg.expect("mass") * c.velocity.norm_squared()
                    + 0.5 * link.inertia_kg_m2.expect("inertia") * s.links[l].omega_rad_s.powi(2)
            })
            .sum();
        assert!(
            (0.5 * j * w * w - ke).abs() < 1e-12 * ke,
            "{deg} deg: {} vs {ke}",
            0.5 * j * w * w
        );
    }
}

#[test]
fn flipper_run_matches_the_paper_and_stops_at_35_deg() {
    let k = kinematics("gravity_flipper.ron", SolverPath::Auto);
    let sim = simulate(&k, &fixed(Method::Rk4, 1e-4, 2.0)).expect("run");
    let peak = sim
        .samples
        .iter()
        .max_by(|a, b| a.q_dot.abs().total_cmp(&b.q_dot.abs()))
        .expect("samples");
    // The paper: |ω1| grows until about 0.16 s and peaks near φ1 = 0.88 rad.
    assert!((peak.q - 0.88).abs() < 0.01, "peak at φ1 = {} rad", peak.q);
    assert!((peak.t - 0.16).abs() < 0.01, "peak at t = {} s", peak.t);
    assert!(peak.q_dot < 0.0, "link 1 turns clockwise");
    let stop = sim
        .events
        .iter()
        .find(|e| e.name == "table end stop")
        .expect("end stop reached");
    assert!(stop.stopped);
    assert!(
        (stop.state.q - 35f64.to_radians()).abs() < 1e-9,
        "stops at {} deg",
        stop.state.q.to_degrees()
    );
    // "falls so that the table meets its end stop gently": slower than a third of the peak.
    assert!(stop.state.q_dot.abs() < peak.q_dot.abs() / 3.0);
    // Energy balance of RK4 at this step: exact solution conserves it; RK4's local error
    // h⁵ over ~2500 steps stays far below 1e-8 J of a 23 J budget.
    let e0 = sim.samples[0].energy_balance();
    let drift = sim
        .samples
        .iter()
        .map(|s| (s.energy_balance() - e0).abs())
        .fold(0.0, f64::max);
    assert!(drift < 1e-8, "RK4 energy drift {drift:e} J");
}

/// Convergence against a tight run: RK4's stop time changes by < 1e-9 s when the step
/// is halved (fourth order), the energy method's error halves with its step (first
/// order, as a student should see).
#[test]
fn methods_converge_to_the_reference_run() {
    let stop_time = |method: Method, step: f64| {
        let k = kinematics("gravity_flipper.ron", SolverPath::Auto);
        let sim = simulate(&k, &fixed(method, step, 2.0)).expect("run");
        sim.events.iter().find(|e| e.stopped).expect("stop").state.t
    };
    let reference = stop_time(Method::Rk4, 2.5e-5);
    assert!((stop_time(Method::Rk4, 5e-5) - reference).abs() < 1e-9);
    let e1 = (stop_time(Method::EnergyIncrement, 2e-3) - reference).abs();
    let e2 = (stop_time(Method::EnergyIncrement, 1e-3) - reference).abs();
    let ratio = e1 / e2;
    assert!(
        (1.6..2.5).contains(&ratio),
        "energy method errors {e1:e}, {e2:e}: ratio {ratio}"
    );
    let s1 = (stop_time(Method::SemiImplicitEuler, 1e-4) - reference).abs();
    let s2 = (stop_time(Method::SemiImplicitEuler, 5e-5) - reference).abs();
    assert!(
        (1.6..2.5).contains(&(s1 / s2)),
        "semi-implicit Euler errors {s1:e}, {s2:e}"
    );
}

#[test]
fn missing_or_invalid_mass_data_is_named() {
    let text = scene_text("gravity_flipper.ron").replace(", inertia: Some(0.012)", "");
    let k = Kinematics::new(Mechanism::from_ron(&text).expect("valid kinematics")).expect("k");
    let err = simulate(&k, &fixed(Method::Rk4, 1e-3, 0.1)).expect_err("missing inertia");
    let LinkageError::SceneInvalid(problem) = &err else {
        panic!("expected the missing inertia named, got {err}");
    };
    assert_eq!(
        **problem,
        SceneProblem::MissingInertia {
            link: "table".into(),
            field: "inertia"
        }
    );
    let text = scene_text("gravity_flipper.ron").replace("mass: Some(1.0)", "mass: Some(-1.0)");
    let err = Mechanism::from_ron(&text).expect_err("negative mass");
    assert!(
        err.to_string()
            .contains("link1.mass = -1 is invalid: must be finite and > 0"),
        "{err}"
    );
    let text = scene_text("gravity_flipper.ron").replace("k_n_per_m: 1500.0", "k_n_per_m: 0.0");
    let err = Mechanism::from_ron(&text).expect_err("zero k");
    assert!(
        matches!(&err, LinkageError::InvalidParameter { value, .. } if *value == 0.0),
        "{err}"
    );
    let k = kinematics("gravity_flipper.ron", SolverPath::Auto);
    let err = simulate(&k, &fixed(Method::Rk4, f64::NAN, 0.1)).expect_err("NaN step");
    assert!(
        matches!(&err, LinkageError::InvalidParameter { param: linkage::error::Param::Step, value, .. }
            if value.is_nan()),
        "{err}"
    );
}

/// The benchmark's settings (benches/dynamics.rs: DOP853, rtol 1e-8, atol 3e-10) reach
/// the end stop with a phi error of at most 1e-9 rad against the rtol-1e-13 reference,
/// on a 1 ms grid and at the stop, in at most 250 right-hand-side evaluations
/// (scipy's DOP853 needs about 416 for 2e-10 rad on the same problem).
#[test]
fn flipper_budget() {
    let k = kinematics("gravity_flipper.ron", SolverPath::Auto);
    let mut s = Settings::new(Method::Dop853);
    s.rtol = 1e-8;
    s.atol = 3e-10;
    s.t_end = 2.0;
    let reference = linkage::dynamics::tradeoff::reference_run(&k, &s, 1e-3).expect("reference");
    let row = linkage::dynamics::tradeoff::measure(&k, &s, 1e-3, &reference).expect("run");
    assert!(
        row.max_q_error <= 1e-9,
        "phi error {:e} rad",
        row.max_q_error
    );
    assert!(
        row.rhs_evaluations <= 250,
        "{} evaluations",
        row.rhs_evaluations
    );
    assert!(
        row.event_time_error <= 1e-9,
        "stop time error {:e} s",
        row.event_time_error
    );
}
