//! Dynamics at the extremes, each against an independent reference: two different
//! coordinates of the paper's reduction, an independent fixed-step method and the
//! energy balance; the run through link 1's dead point; a stiff spring; 10⁴ periods
//! of an undamped oscillation per method; and links from 1e-4 m to 1e3 m.

use crate::common;

use common::{mechanism, scene_text};
use linkage::dynamics::{Method, Settings, Simulation, simulate, tradeoff};
use linkage::error::{RunRefusal, RunWarning};
use linkage::scene::FreeLength;
use linkage::{Kinematics, LinkId, LinkageError, Mechanism};

fn flipper() -> Kinematics {
    Kinematics::new(mechanism("gravity_flipper.ron")).expect("flipper")
}

fn flipper_with_spring(k_n_per_m: f64) -> Kinematics {
    let text = scene_text("gravity_flipper.ron")
        .replace("k_n_per_m: 1500.0", &format!("k_n_per_m: {k_n_per_m:e}"));
    Kinematics::new(Mechanism::from_ron(&text).expect("scene")).expect("flipper")
}

fn adaptive(method: Method, rtol: f64, atol: f64) -> Settings {
    let mut s = Settings::new(method);
    s.rtol = rtol;
    s.atol = atol;
    s.t_end = 2.0;
    s
}

fn fixed(method: Method, step: f64, t_end: f64) -> Settings {
    let mut s = Settings::new(method);
    s.step = step;
    s.t_end = t_end;
    s
}

fn stop_time(sim: &Simulation) -> f64 {
    let stop = sim.events.last().expect("an event");
    assert!(stop.stopped, "{}", stop.name);
    stop.state.t
}

/// The paper's reduction in link 1's angle (no switch: J grows toward its dead point
/// but stays finite up to the stop) against the same reduction in link 3's angle (up
/// to 0.12 s: link 3 has a dead point of its own at 0.13 s), against a run that starts
/// in link 3's angle and switches, against RK4 at a small fixed step, and the energy
/// balance: all within 1e-9.
#[test]
fn two_coordinates_a_tight_run_and_the_energy_balance_agree() {
    let k = flipper();
    let grid = 1e-3;
    let link3 = k.mechanism().link_index("link3");
    let mut in_link1 = adaptive(Method::Dop853, 1e-12, 1e-14);
    in_link1.switch_coordinates = false;
    in_link1.output_dt = Some(grid);
    let a = simulate(&k, &in_link1).expect("link 1 coordinate");
    assert!(a.samples.iter().all(|s| s.coordinate_link == LinkId(1)));
    let mut in_link3 = in_link1.clone();
    in_link3.coordinate = link3;
    in_link3.t_end = 0.12;
    let b = simulate(&k, &in_link3).expect("link 3 coordinate");
    assert!(b.samples.iter().all(|s| s.coordinate_link == LinkId(3)));
    let overlap = b
        .samples
        .iter()
        .zip(&a.samples)
        .map(|(x, y)| (x.q - y.q).abs())
        .fold(0.0, f64::max);
    assert_eq!(b.samples.len(), 121);
    assert!(overlap <= 1e-9, "coordinates disagree by {overlap:e} rad");
    // Past 0.13 s link 3's own coordinate cannot go on: named, not stalled.
    in_link3.t_end = 2.0;
    let err = simulate(&k, &in_link3).expect_err("link 3's dead point");
    assert!(
        matches!(
            &err,
            linkage::LinkageError::Singular {
                reason: linkage::error::Singularity::CoordinateDeadPoint { coordinate, .. },
                ..
            } if coordinate == "link3"
        ),
        "{err}"
    );
    let mut switching = in_link3.clone();
    switching.switch_coordinates = true;
    let d = simulate(&k, &switching).expect("from link 3, switching");
    let mut rk4 = fixed(Method::Rk4, 2e-5, 2.0);
    rk4.output_dt = Some(grid);
    let c = simulate(&k, &rk4).expect("rk4");
    for (name, other) in [("switching from link 3", &d), ("RK4", &c)] {
        let diff = tradeoff::max_q_difference(&a, other);
        assert!(diff <= 1e-9, "{name} disagrees by {diff:e} rad");
        assert!((stop_time(&a) - stop_time(other)).abs() <= 1e-9);
    }
    for sim in [&a, &b, &c, &d] {
        assert!(
            sim.energy_drift() <= 1e-9,
            "energy drift {:e} J",
            sim.energy_drift()
        );
    }
    // The paper's numbers, from the tight run.
    let peak = a
        .samples
        .iter()
        .max_by(|x, y| x.q_dot.abs().total_cmp(&y.q_dot.abs()))
        .expect("samples");
    assert!((peak.q - 0.88).abs() < 0.01 && (peak.t - 0.16).abs() < 0.01);
}

/// Without the end stop link 1 reaches its dead point (34.2969 deg, B-C-D collinear)
/// and turns back while link 3 goes on: the run switches to link 3's angle there and
/// back, without NaN, error or step-size collapse, and keeps the energy balance.
#[test]
fn a_run_without_stops_goes_through_the_dead_point() {
    let k = flipper();
    let mut s = adaptive(Method::Dop853, 1e-10, 1e-12);
    s.use_stops = false;
    s.t_end = 3.0;
    s.output_dt = Some(1e-4);
    let sim = simulate(&k, &s).expect("through the dead point");
    assert!(
        sim.samples
            .iter()
            .all(|x| x.q.is_finite() && x.q_dot.is_finite())
    );
    let lowest = sim
        .samples
        .iter()
        .map(|x| x.q)
        .fold(f64::INFINITY, f64::min);
    let dead_point = 34.2969_f64.to_radians();
    assert!(
        (lowest - dead_point).abs() < 2e-6,
        "lowest φ1 {} deg",
        lowest.to_degrees()
    );
    let switches = sim
        .events
        .iter()
        .filter(|e| e.name.starts_with("coordinate switch"))
        .count();
    assert!(switches >= 8, "{switches} switches in 3 s");
    // Back up to the release angle each period: nothing is lost at the dead points.
    let highest_late = sim
        .samples
        .iter()
        .filter(|x| x.t > 2.0)
        .map(|x| x.q)
        .fold(f64::NEG_INFINITY, f64::max);
    assert!((highest_late - 69.5_f64.to_radians()).abs() < 1e-6);
    assert!(
        sim.energy_drift() < 1e-8,
        "energy drift {:e} J",
        sim.energy_drift()
    );
    assert!(
        sim.stats.steps < 1000,
        "{} steps: the step size collapsed",
        sim.stats.steps
    );
}

/// k = 1e7 N/m: the stiffest mode is about 609 rad/s. A fixed explicit step beyond
/// its stability limit is refused with the limit named; the implicit midpoint rule
/// runs at the same step and keeps the energy bounded; an adaptive method run at a
/// loose tolerance warns that stability, not accuracy, sets its step.
#[test]
fn a_stiff_spring_is_refused_by_explicit_steps_and_run_by_the_implicit_one() {
    let k = flipper_with_spring(1e7);
    for method in [Method::Rk4, Method::SemiImplicitEuler] {
        let err = simulate(&k, &fixed(method, 5e-3, 0.5)).expect_err("beyond the limit");
        // As data: the method, the limit and the stiffness, for each edge to word.
        let LinkageError::Run(refusal) = &err else {
            panic!("not a run's refusal: {err}")
        };
        let RunRefusal::StepBeyondStability { limit, .. } = **refusal else {
            panic!("not the stability limit: {refusal}")
        };
        assert_eq!(limit.method, method);
        assert!(
            limit.h_limit_s < 5e-3 && limit.stiffness_per_s > 500.0,
            "{limit:?}"
        );
        // The solver's own words name the limit and the implicit method, and no
        // command-line option (the CLI and the app name their own).
        let text = err.to_string();
        assert!(
            text.contains("stability limit") && text.contains("implicit") && !text.contains("--"),
            "{text}"
        );
    }
    let sim = simulate(&k, &fixed(Method::ImplicitMidpoint, 5e-3, 0.5)).expect("implicit");
    assert!(sim.stats.stiffness_per_s > 500.0 && sim.stats.stiffness_per_s < 700.0);
    let potential_swing = sim.samples.iter().map(|x| x.kinetic).fold(0.0, f64::max);
    assert!(potential_swing > 0.0);
    assert!(
        sim.energy_drift() < 1e-2 * potential_swing,
        "implicit midpoint energy error {:e} J of {potential_swing:e} J",
        sim.energy_drift()
    );
    let loose = simulate(&k, &adaptive(Method::Dop853, 1e-3, 1e-3)).expect("adaptive");
    assert!(
        loose.stats.warnings.iter().any(
            |w| matches!(w, RunWarning::Stiff { limit, .. } if limit.method == Method::Dop853)
        ),
        "{:?}",
        loose.stats.warnings
    );
}

/// 10⁴ periods of the flipper held by a stiff spring (k = 1e5 N/m, period 0.107 s,
/// amplitude 0.6 deg, no stops): the largest energy error over 1070 s, as a fraction
/// of the oscillation's kinetic energy, stays within each method's stated bound. The
/// time-reversible implicit midpoint rule's error does not grow (last tenth within
/// 1.1 of the first); semi-implicit Euler's does (it is not symplectic in (q, q̇) when
/// J depends on q), RK4 and the adaptive pairs lose energy slowly.
#[test]
fn ten_thousand_periods_keep_the_energy_within_stated_bounds() {
    let k = flipper_with_spring(1e5);
    let t_end = 1070.0;
    let cases: [(Method, f64, f64); 5] = [
        // (method, step or rtol, bound on drift / kinetic amplitude)
        (Method::SemiImplicitEuler, 1e-3, 2e-1),
        (Method::ImplicitMidpoint, 2e-3, 3e-4),
        (Method::Rk4, 1e-3, 1e-3),
        (Method::Dp5, 1e-9, 1e-4),
        (Method::Dop853, 1e-10, 3e-6),
    ];
    for (method, setting, bound) in cases {
        let mut s = if method.is_adaptive() {
            adaptive(method, setting, setting * 1e-3)
        } else {
            fixed(method, setting, t_end)
        };
        s.t_end = t_end;
        s.use_stops = false;
        s.output_dt = Some(1.0);
        // A deliberate long run: Euler at 1e-3 s takes 1.07e6 steps, past the default.
        s.max_steps = 2_000_000;
        let sim = simulate(&k, &s).unwrap_or_else(|e| panic!("{method:?}: {e}"));
        assert!(
            (sim.samples.last().expect("samples").t - t_end).abs() < 1e-6,
            "{method:?} ended early"
        );
        let (amplitude, drift) = energy_drift(&sim, 0.0, t_end);
        eprintln!(
            "{method:?}: energy error {:.3e} of the kinetic amplitude {amplitude:.3e} J, {} RHS",
            drift / amplitude,
            sim.stats.rhs_evaluations
        );
        assert!(
            drift / amplitude <= bound,
            "{method:?}: {:e} > {bound:e}",
            drift / amplitude
        );
        if method == Method::ImplicitMidpoint {
            let (early, late) = (
                energy_drift(&sim, 0.0, 0.1 * t_end).1,
                energy_drift(&sim, 0.9 * t_end, t_end).1,
            );
            assert!(
                late <= 1.1 * early,
                "drift grows from {early:e} to {late:e} J"
            );
        }
    }
}

/// The paper's energy-increment method takes M at the start of each increment, so it
/// gains energy on every swing (toward and away from equilibrium alike): over 100
/// periods the oscillation grows, here by more than 1 % at Δφ = 5e-4 rad. A student
/// should see it; nobody should run it for 10⁴ periods.
#[test]
fn the_energy_increment_method_gains_energy_every_swing() {
    let k = flipper_with_spring(1e5);
    let mut s = fixed(Method::EnergyIncrement, 5e-4, 10.7);
    s.use_stops = false;
    s.output_dt = Some(0.1);
    let sim = simulate(&k, &s).expect("energy method");
    let e0 = sim.samples[0].energy_balance();
    let gains: Vec<f64> = sim
        .samples
        .iter()
        .map(|x| x.energy_balance() - e0)
        .collect();
    let (amplitude, _) = energy_drift(&sim, 0.0, 10.7);
    let tenth = gains.len() / 10;
    let early = gains[..tenth]
        .iter()
        .fold(f64::NEG_INFINITY, |a, &b| a.max(b));
    let late = gains[gains.len() - tenth..]
        .iter()
        .fold(f64::NEG_INFINITY, |a, &b| a.max(b));
    assert!(
        early > 0.0 && late > 5.0 * early,
        "gains {early:e} then {late:e} J"
    );
    assert!(late > 1e-2 * amplitude, "{late:e} of {amplitude:e} J");
}

/// (Largest kinetic energy, largest |energy balance − start|) over samples in [from, to].
fn energy_drift(sim: &Simulation, from: f64, to: f64) -> (f64, f64) {
    let e0 = sim.samples[0].energy_balance();
    sim.samples
        .iter()
        .filter(|x| x.t >= from && x.t <= to)
        .fold((0.0, 0.0), |(k, d), x| {
            (k.max(x.kinetic), d.max((x.energy_balance() - e0).abs()))
        })
}

/// The flipper scaled by s: lengths × s, masses × s³, inertias × s⁵, spring rate × s²,
/// forces × s³, gravity unchanged. Its motion is the same in angle with time × √s, so
/// the stop comes at √s times the original time at the same angles.
fn scaled_flipper(s: f64) -> Kinematics {
    let mut m = mechanism("gravity_flipper.ron");
    for link in &mut m.links {
        for (_, p) in &mut link.points {
            *p *= s;
        }
        link.centroid_m = link.centroid_m.map(|c| c * s);
        link.mass_kg = link.mass_kg.map(|x| x * s.powi(3));
        link.inertia_kg_m2 = link.inertia_kg_m2.map(|x| x * s.powi(5));
    }
    for p in &mut m.points {
        p.local *= s;
    }
    for r in &mut m.revolutes {
        r.a_local *= s;
        r.b_local *= s;
    }
    for spring in &mut m.forces.springs {
        spring.k_n_per_m *= s * s;
        if let FreeLength::Length(l) = &mut spring.free_length {
            *l *= s;
        }
    }
    for f in &mut m.forces.point_forces {
        f.force_n = (f.force_n.0 * s.powi(3), f.force_n.1 * s.powi(3));
    }
    m.size_m *= s;
    Kinematics::new(m).expect("scaled flipper")
}

#[test]
fn links_from_a_tenth_of_a_millimetre_to_a_kilometre_scale_consistently() {
    let run = |s: f64| {
        let mut settings = adaptive(Method::Dop853, 1e-11, 1e-13);
        settings.t_end = 2.0 * s.sqrt();
        settings.output_dt = Some(1e-3 * s.sqrt());
        simulate(&scaled_flipper(s), &settings).expect("scaled run")
    };
    let unit = run(1.0);
    let t_unit = stop_time(&unit);
    let peak = |sim: &Simulation| {
        sim.samples
            .iter()
            .map(|x| x.q_dot.abs())
            .fold(0.0, f64::max)
    };
    for s in [1e-4, 1e-2, 1e2, 1e3] {
        let sim = run(s);
        let t = stop_time(&sim) / s.sqrt();
        assert!(
            (t - t_unit).abs() < 1e-9 * t_unit,
            "scale {s}: stop at {t} vs {t_unit}"
        );
        let stop = &sim.events.last().expect("stop").state;
        assert!((stop.q - 35f64.to_radians()).abs() < 1e-12);
        // Speeds scale as 1/√s; the energy balance as s⁴.
        let ratio = peak(&sim) * s.sqrt() / peak(&unit);
        assert!(
            (ratio - 1.0).abs() < 1e-8,
            "scale {s}: peak speed ratio {ratio}"
        );
        assert!(sim.energy_drift() <= 1e-9 * s.powi(4) * 25.0, "scale {s}");
    }
}
