//! A uniform rod pendulum released from the horizontal, with a `Report` end stop at
//! the bottom, against the exact solution in Jacobi elliptic functions. Regression
//! test for issue 11: the output samples in the rest of the step that held a reported
//! event were frozen at one later state (errors up to 0.08 rad), because the output
//! was cut at the event and the skipped samples were read off the next step's
//! clamped interpolant. Every sample must now come from its own step's dense output.

use linkage::dynamics::{Method, Settings, simulate};
use linkage::{Kinematics, Mechanism};

const LENGTH_M: f64 = 0.8;
const G: f64 = 9.81;

fn pendulum() -> Kinematics {
    let l = LENGTH_M;
    let text = format!(
        r#"Scene(
    name: "Uniform rod pendulum",
    models: Dynamics,
    links: [
        (name: "ground", ground: true, points: {{"O": (0.0, 0.0)}}),
        (name: "rod", points: {{"O": (0.0, 0.0), "T": ({l}, 0.0)}},
            mass: Some(2.0), centroid: Some(({h}, 0.0)), inertia: Some({i})),
    ],
    driver: (link: "rod", speed: RadPerSecond(1.0), start: 0.0),
    forces: (
        gravity: Some((0.0, -{G})),
        stops: [(name: "bottom", link: "rod", angle: -90.0, action: Report)],
    ),
)"#,
        h = l / 2.0,
        i = 2.0 * l * l / 12.0,
    );
    Kinematics::new(Mechanism::from_ron(&text).expect("scene")).expect("kinematics")
}

/// Jacobi sn(u | k) and the complete elliptic integral K(k) by the arithmetic-
/// geometric mean (Abramowitz & Stegun 16.4 and 17.6), to round-off.
fn sn_and_k(u: f64, k: f64) -> (f64, f64) {
    let (mut a, mut b, mut c) = (vec![1.0_f64], (1.0 - k * k).sqrt(), vec![k]);
    while c.last().is_some_and(|c| c.abs() > 1e-17) && a.len() < 40 {
        let (an, bn) = (*a.last().expect("a"), b);
        c.push(0.5 * (an - bn));
        a.push(0.5 * (an + bn));
        b = (an * bn).sqrt();
    }
    let n = a.len() - 1;
    let k_complete = std::f64::consts::FRAC_PI_2 / a[n];
    let mut phi = 2f64.powi(n as i32) * a[n] * u;
    for i in (1..=n).rev() {
        phi = 0.5 * (phi + (c[i] / a[i] * phi.sin()).asin());
    }
    (phi.sin(), k_complete)
}

/// Exact rod angle from +x at time t (released from rest at 0 rad, i.e. 90 deg from
/// the downward vertical): sin(θ/2) = k sn(K − ω₀t | k), θ = φ + π/2, k = sin(π/4).
fn exact_angle(t: f64) -> f64 {
    let omega0 = (1.5 * G / LENGTH_M).sqrt();
    let k = std::f64::consts::FRAC_PI_4.sin();
    let (_, kk) = sn_and_k(0.0, k);
    let (sn, _) = sn_and_k(kk - omega0 * t, k);
    2.0 * (k * sn).asin() - std::f64::consts::FRAC_PI_2
}

fn period_s() -> f64 {
    let (_, kk) = sn_and_k(0.0, std::f64::consts::FRAC_PI_4.sin());
    4.0 * kk / (1.5 * G / LENGTH_M).sqrt()
}

#[test]
fn elliptic_reference_is_self_consistent() {
    // Small-amplitude limit and the known value K(sin 45°) = 1.8540746773013719.
    let (_, kk) = sn_and_k(0.0, std::f64::consts::FRAC_PI_4.sin());
    assert!((kk - 1.854_074_677_301_371_9).abs() < 1e-14, "{kk}");
    assert!(exact_angle(0.0).abs() < 1e-14);
    assert!((exact_angle(period_s() / 4.0) + std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    assert!((exact_angle(period_s() / 2.0) + std::f64::consts::PI).abs() < 1e-7);
}

#[test]
fn report_stop_leaves_every_sample_on_the_exact_solution() {
    let k = pendulum();
    let period = period_s();
    let mut settings = Settings::new(Method::Dop853);
    settings.rtol = 1e-12;
    settings.atol = 1e-14;
    settings.t_end = period;
    // Fine enough that the steps holding the events span several samples.
    settings.output_dt = Some(period / 2003.0);
    let sim = simulate(&k, &settings).expect("runs");
    assert!(sim.samples.len() >= 2003, "{} samples", sim.samples.len());
    let mut worst = 0.0_f64;
    for s in &sim.samples {
        worst = worst.max((s.q - exact_angle(s.t)).abs());
    }
    assert!(worst < 1e-8, "largest sample error {worst:.3e} rad");
    let hits: Vec<f64> = sim
        .events
        .iter()
        .filter(|e| e.name == "bottom")
        .map(|e| e.state.t)
        .collect();
    assert_eq!(hits.len(), 2, "bottom passed twice in one period: {hits:?}");
    assert!(sim.events.iter().all(|e| !e.stopped));
    assert!(
        (hits[0] - period / 4.0).abs() < 1e-8,
        "{} vs T/4 {}",
        hits[0],
        period / 4.0
    );
    assert!(
        (hits[1] - 0.75 * period).abs() < 1e-8,
        "{} vs 3T/4 {}",
        hits[1],
        0.75 * period
    );
}
