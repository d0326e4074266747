//! Shaking force and moment against the closed form of an in-line slider-crank with
//! point masses (m_A at the crank pin, m_s on the slider), no gravity and no load:
//! the frame carries F = −Σ m a = m_A r ω² (cos φ, sin φ) − m_s s''(φ) ω² e_x, and
//! about a point P the moment −Σ (r − P) × m a = −P × F (both masses' r × a vanish
//! about the pivot, on the guide line through it). The
//! least-squares crank counterweight is the textbook one: m_A r + ½ m_s r opposite
//! the crank (the rotating mass and half the reciprocating one), since s'' has −r cos φ
//! as its only odd harmonic.

use crate::common;

use linkage::machine::{BalanceAim, counterweights, shaking, with_counterweights};
use linkage::{Kinematics, LinkageError, Mechanism};

const R: f64 = 0.05;
const L: f64 = 0.2;
const M_PIN: f64 = 2.0;
const M_SLIDER: f64 = 10.0;
const OMEGA: f64 = 30.0;

fn engine() -> Kinematics {
    let text = format!(
        r#"Scene(
        name: "engine",
        models: Kinetostatics,
        links: [
            (name: "ground", ground: true, points: {{"O": (0.0, 0.0)}}),
            (name: "crank", points: {{"O": (0.0, 0.0), "A": ({R}, 0.0)}}, mass: Some({M_PIN}), centroid: Some(({R}, 0.0))),
            (name: "rod", points: {{"A": (0.0, 0.0), "C": ({L}, 0.0)}}),
            (name: "slider", points: {{"C": (0.0, 0.0)}}, mass: Some({M_SLIDER}), centroid: Some((0.0, 0.0))),
        ],
        sliders: [(slider: "slider", point: "C", guide: "ground", through: "O", angle: 0.0)],
        driver: (link: "crank", speed: RadPerSecond({OMEGA}), start: 0.0),
        branches: {{"C": Along}},
    )"#
    );
    Kinematics::new(Mechanism::from_ron(&text).expect("scene")).expect("kinematics")
}

/// s''(φ) of the engine's slider.
fn s2(phi: f64) -> f64 {
    common::slider_crank::slide(R, L, phi).2
}

/// The shaking force, with a counterweight of mass-radius `c` on the crank at angle
/// `at` from it.
fn force(phi: f64, c: f64, at: f64) -> [f64; 2] {
    let w2 = OMEGA * OMEGA;
    let (sn, cs) = phi.sin_cos();
    let (csn, ccs) = (phi + at).sin_cos();
    [
        M_PIN * R * w2 * cs - M_SLIDER * s2(phi) * w2 + c * w2 * ccs,
        M_PIN * R * w2 * sn + c * w2 * csn,
    ]
}

#[test]
fn the_shaking_force_and_moment_of_an_engine_match_their_closed_forms() {
    let about = [0.3, -0.1];
    let s = shaking(&mut engine(), about).expect("shaking");
    let scale = M_SLIDER * R * OMEGA * OMEGA * 2.0;
    for p in &s.cycle {
        let f = force(p.angle_rad, 0.0, 0.0);
        for axis in 0..2 {
            assert!(
                (p.force_n[axis] - f[axis]).abs() <= 1e-9 * scale,
                "at {}: {:?} vs {f:?}",
                p.angle_rad,
                p.force_n
            );
        }
        // (−P) × F.
        let moment = -about[0] * f[1] + about[1] * f[0];
        assert!(
            (p.moment_n_m - moment).abs() <= 1e-9 * scale * 0.3,
            "at {}: {} vs {moment}",
            p.angle_rad,
            p.moment_n_m
        );
    }
}

#[test]
fn the_least_squares_counterweight_balances_the_rotating_and_half_the_reciprocating_mass() {
    let mut k = engine();
    let before = shaking(&mut k, [0.0, 0.0]).expect("shaking");
    let crank = [k.mechanism().driver.link];
    let c = counterweights(&mut k, &before, &crank, BalanceAim::Rms).expect("weights")[0];
    let want = M_PIN * R + 0.5 * M_SLIDER * R;
    assert!(
        (c.mass_radius_kg_m - want).abs() <= 1e-9 * want,
        "{} vs {want}",
        c.mass_radius_kg_m
    );
    let off = (c.angle_rad.abs() - std::f64::consts::PI).abs();
    assert!(off <= 1e-9, "opposite the crank: {}", c.angle_rad);
    assert!(
        (c.mass_kg * R - want).abs() <= 1e-9 * want,
        "at the crank's length"
    );
    let mut balanced = Kinematics::new(with_counterweights(k.mechanism(), &[c])).expect("k");
    let after = shaking(&mut balanced, [0.0, 0.0]).expect("shaking");
    let scale = M_SLIDER * R * OMEGA * OMEGA;
    for p in &after.cycle {
        let f = force(p.angle_rad, want, std::f64::consts::PI);
        assert!(
            (p.force_n[0] - f[0]).abs() <= 1e-9 * scale
                && (p.force_n[1] - f[1]).abs() <= 1e-9 * scale
        );
    }
    assert!(
        after.rms_force_n < before.rms_force_n,
        "{} vs {}",
        after.rms_force_n,
        before.rms_force_n
    );
}

#[test]
fn shaking_needs_masses_and_a_turning_crank() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../assets/scenes/slider_crank.ron"
    ))
    .expect("scene");
    let mut k = Kinematics::new(Mechanism::from_ron(&text).expect("scene")).expect("k");
    let err = shaking(&mut k, [0.0, 0.0]).expect_err("kinematics only");
    assert!(matches!(err, LinkageError::SceneInvalid(_)), "{err}");
}

fn shaken(m: Mechanism) -> linkage::machine::Shaking {
    let mut k = Kinematics::new(m).expect("kinematics");
    shaking(&mut k, [0.0, 0.0]).expect("shaking")
}

#[test]
fn the_peak_minimising_counterweight_is_a_minimum_of_the_real_peak() {
    let mut k = engine();
    let before = shaking(&mut k, [0.0, 0.0]).expect("shaking");
    let m = k.mechanism().clone();
    let crank = [m.driver.link];
    let rms = counterweights(&mut k, &before, &crank, BalanceAim::Rms).expect("rms")[0];
    let peak = counterweights(&mut k, &before, &crank, BalanceAim::Peak).expect("peak")[0];
    let peak_after = shaken(with_counterweights(&m, &[peak])).peak_force_n;
    let rms_after = shaken(with_counterweights(&m, &[rms])).peak_force_n;
    assert!(peak_after <= rms_after, "{peak_after} > {rms_after}");
    // No small change of the counterweight lowers the real peak.
    let step = 1e-3 * peak.mass_radius_kg_m;
    for i in 0..12 {
        let turn = std::f64::consts::TAU * i as f64 / 12.0;
        let mut moved = peak;
        let c = [
            peak.mass_radius_kg_m * peak.angle_rad.cos() + step * turn.cos(),
            peak.mass_radius_kg_m * peak.angle_rad.sin() + step * turn.sin(),
        ];
        let radius = peak.mass_radius_kg_m / peak.mass_kg;
        moved.angle_rad = c[1].atan2(c[0]);
        moved.mass_radius_kg_m = c[0].hypot(c[1]);
        moved.at_m = [
            radius * moved.angle_rad.cos(),
            radius * moved.angle_rad.sin(),
        ];
        moved.mass_kg = moved.mass_radius_kg_m / radius;
        let p = shaken(with_counterweights(&m, &[moved])).peak_force_n;
        assert!(
            p >= peak_after * (1.0 - 1e-9),
            "a step at {turn} lowers the peak: {p} < {peak_after}"
        );
    }
}

/// The peak shaking force is located between the cycle's samples: against the
/// closed form's largest |F| (a fine grid, then golden-section search on the closed
/// form, written here) to the rounding of the force, and at its angle.
#[test]
fn the_peak_shaking_force_is_located_on_the_closed_form() {
    let s = shaking(&mut engine(), [0.0, 0.0]).expect("shaking");
    let size = |phi: f64| {
        let [x, y] = force(phi, 0.0, 0.0);
        x.hypot(y)
    };
    let n = 20_000;
    let h = std::f64::consts::TAU / n as f64;
    let best = (0..n)
        .map(|i| i as f64 * h)
        .max_by(|a, b| size(*a).total_cmp(&size(*b)))
        .expect("grid");
    let (mut a, mut b) = (best - h, best + h);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    while b - a > 1e-13 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if size(c) > size(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let at = 0.5 * (a + b);
    let want = size(at);
    assert!(
        (s.peak_force_n - want).abs() <= 1e-12 * want,
        "{} vs {want}",
        s.peak_force_n
    );
    let d = (s.peak_force_at_rad - at).rem_euclid(std::f64::consts::TAU);
    assert!(
        d.min(std::f64::consts::TAU - d) < 1e-6,
        "at {} vs {at}",
        s.peak_force_at_rad
    );
}
