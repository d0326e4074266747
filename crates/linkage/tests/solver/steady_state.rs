//! The real speed through the cycle against closed forms written here. A slider-crank
//! press (point mass on the slider, a pressing force on its working stroke only) with
//! a flywheel on the crank: driven by a constant torque its speed is known from the
//! energy equation, ½ J(φ) ω² = ½ J(φ₀) ω₀² + ∫ (T − F s'⁺) dφ with J = J_F + m s'²;
//! driven by a linear motor its mean speed over the angle follows from the motor's
//! line and the load's mean torque.

use crate::common;

use linkage::machine::steady_state;
use linkage::{Kinematics, LinkageError, Mechanism};

const TAU: f64 = std::f64::consts::TAU;
const PI: f64 = std::f64::consts::PI;
const R: f64 = 0.05;
const L: f64 = 0.2;
const MASS: f64 = 10.0;
const FORCE: f64 = 5000.0;
const OMEGA: f64 = 30.0;
const FLYWHEEL: f64 = 0.4;

fn press(motor: &str, gear: f64) -> Kinematics {
    Kinematics::new(Mechanism::from_ron(&press_text(motor, gear)).expect("scene"))
        .expect("kinematics")
}

/// The press's scene file with `motor` through a gear of `gear`.
fn press_text(motor: &str, gear: f64) -> String {
    format!(
        r#"Scene(
        name: "press",
        models: Dynamics,
        links: [
            (name: "ground", ground: true, points: {{"O": (0.0, 0.0)}}),
            (name: "crank", points: {{"O": (0.0, 0.0), "A": ({R}, 0.0)}}, mass: Some(1e-9), centroid: Some((0.0, 0.0)), inertia: Some(1e-12)),
            (name: "rod", points: {{"A": (0.0, 0.0), "C": ({L}, 0.0)}}, mass: Some(1e-9), centroid: Some((0.0, 0.0)), inertia: Some(1e-12)),
            (name: "slider", points: {{"C": (0.0, 0.0)}}, mass: Some({MASS}), centroid: Some((0.0, 0.0)), inertia: Some(1e-12)),
        ],
        sliders: [(slider: "slider", point: "C", guide: "ground", through: "O", angle: 0.0)],
        driver: (link: "crank", speed: RadPerSecond({OMEGA}), start: 0.0),
        branches: {{"C": Along}},
        forces: (point_forces: [(point: "C", force_n: (-{FORCE}, 0.0), when: WorkingStroke)]),
        drive: Some((motor: {motor}, gear_ratio: {gear}, flywheel_kg_m2: {FLYWHEEL})),
    )"#
    )
}

/// s(φ) and s'(φ) of the press's slider.
fn slide(phi: f64) -> (f64, f64) {
    let (s, s1, _) = common::slider_crank::slide(R, L, phi);
    (s, s1)
}

/// The inertia at the crank: the flywheel, the slider's m s'², and the tiny masses
/// the scene gives the crank and rod (1e-9 kg, 1e-12 kg m²: below 1e-9 of the rest).
fn inertia(phi: f64) -> f64 {
    FLYWHEEL + MASS * slide(phi).1.powi(2)
}

/// The mean load torque F·2r / 2π.
fn mean_torque() -> f64 {
    FORCE * 2.0 * R / TAU
}

/// ∫₀^φ (T_m − F s'⁺) dφ for φ in [0, 2π]: the slider moves against F for φ > π.
fn surplus(phi: f64) -> f64 {
    let load = if phi > PI {
        FORCE * (slide(phi).0 - slide(PI).0)
    } else {
        0.0
    };
    mean_torque() * phi - load
}

/// ω(φ) from ω₀ at φ = 0 by the energy equation.
fn speed(w0: f64, phi: f64) -> f64 {
    ((inertia(0.0) * w0 * w0 + 2.0 * surplus(phi)) / inertia(phi)).sqrt()
}

/// ∫ f over [0, 2π], Simpson on each half (the load switches at π).
fn over_turn(f: impl Fn(f64) -> f64) -> f64 {
    let n = 20_000;
    let half = |a: f64| {
        let h = PI / n as f64;
        (0..=n)
            .map(|i| {
                let c = if i == 0 || i == n {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                c * f(a + i as f64 * h)
            })
            .sum::<f64>()
            * h
            / 3.0
    };
    half(0.0) + half(PI)
}

#[test]
fn a_constant_torque_press_runs_at_the_speed_of_its_energy_equation() {
    let state = steady_state(&press("Constant(torque_n_m: 80.0)", 1.0)).expect("steady");
    // The ω₀ whose period is one turn at the nominal mean speed, by the secant method
    // on the period ∫ dφ / ω.
    let period = |w0: f64| over_turn(|phi| 1.0 / speed(w0, phi));
    let (mut a, mut b) = (OMEGA * 0.9, OMEGA * 1.1);
    for _ in 0..60 {
        let (fa, fb) = (period(a) - TAU / OMEGA, period(b) - TAU / OMEGA);
        if fb == fa {
            break;
        }
        (a, b) = (b, b - fb * (b - a) / (fb - fa));
    }
    let w0 = b;
    let torque = state.constant_torque_n_m.expect("constant torque used");
    assert!(
        (torque - mean_torque()).abs() <= 1e-9 * mean_torque(),
        "{torque}"
    );
    assert!(
        (state.start_speed_rad_s - w0).abs() <= 1e-9 * w0,
        "{} vs {w0}",
        state.start_speed_rad_s
    );
    assert!(
        (state.mean_rad_s - OMEGA).abs() <= 1e-9 * OMEGA,
        "{}",
        state.mean_rad_s
    );
    for p in &state.cycle {
        let want = speed(w0, p.angle_rad.rem_euclid(TAU).min(TAU));
        assert!(
            (p.speed_rad_s - want).abs() <= 1e-9 * OMEGA,
            "at {} rad: {} vs {want}",
            p.angle_rad,
            p.speed_rad_s
        );
    }
    // Periodic: the motor's work over the turn is the load's, the balance closes.
    let cycle_work = FORCE * 2.0 * R;
    assert!(
        (state.drive_work_j - cycle_work).abs() <= 1e-4 * cycle_work,
        "{}",
        state.drive_work_j
    );
    assert!(
        state.work_over_turn_j.abs() <= 1e-9 * cycle_work,
        "{}",
        state.work_over_turn_j
    );
}

#[test]
fn a_linear_motor_press_turns_at_the_mean_speed_its_line_gives() {
    // Rated 40 N·m at 1450 rpm on the motor, no load at 1500 rpm, through a gear of 5.
    let gear = 5.0;
    let (no_load, rated) = (1500.0 * TAU / 60.0, 1450.0 * TAU / 60.0);
    let rated_torque = 40.0;
    let motor =
        format!("Linear(no_load_rpm: 1500.0, rated_torque_n_m: {rated_torque}, rated_rpm: 1450.0)");
    let state = steady_state(&press(&motor, gear)).expect("steady");
    // Over a turn the drive's mean torque at the crank equals the load's:
    // n T_r (ω_nl − n ω̄) / (ω_nl − ω_r) = T_m, with ω̄ the angle-mean crank speed.
    let angle_mean = (no_load - mean_torque() * (no_load - rated) / (gear * rated_torque)) / gear;
    let got = state
        .cycle
        .windows(2)
        .map(|p| 0.5 * (p[0].speed_rad_s + p[1].speed_rad_s) * (p[1].angle_rad - p[0].angle_rad))
        .sum::<f64>()
        / TAU;
    assert!(
        (got - angle_mean).abs() <= 1e-5 * angle_mean,
        "{got} vs {angle_mean}"
    );
    let first = state.cycle.first().expect("cycle").speed_rad_s;
    let last = state.cycle.last().expect("cycle").speed_rad_s;
    assert!(
        (first - last).abs() <= 1e-9 * angle_mean,
        "periodic: {first} vs {last}"
    );
    assert!(state.delta > 0.0 && state.delta < 0.5, "{}", state.delta);
    let cycle_work = FORCE * 2.0 * R;
    assert!(
        state.work_over_turn_j.abs() <= 1e-9 * cycle_work,
        "{}",
        state.work_over_turn_j
    );
}

#[test]
fn a_scene_without_a_drive_is_refused_with_the_reason() {
    let k = common::kinematics("die_cutter.ron", linkage::scene::SolverPath::Auto);
    let err = steady_state(&k).expect_err("no drive");
    assert!(matches!(err, LinkageError::NeedsMotor), "{err}");
    assert!(err.to_string().contains("needs a motor"), "{err}");
}

/// A similar machine s times larger (masses s³, inertias and the flywheel s⁵, torques
/// s⁴, times √s) fluctuates alike: the same δ, speeds times 1/√s.
#[test]
fn the_steady_state_of_a_similar_machine_is_the_same_at_every_scale() {
    let motor = "Linear(no_load_rpm: 1500.0, rated_torque_n_m: 40.0, rated_rpm: 1450.0)";
    let text = press_text(motor, 5.0);
    let at_one = steady_state(&press(motor, 5.0)).expect("steady");
    for s in [1e-4, 1e3] {
        let scaled = linkage::SceneFile::parse(&text).expect("scene").scaled(s);
        let k = Kinematics::new(Mechanism::from_scene(&scaled).expect("scaled")).expect("k");
        let st = steady_state(&k).expect("steady");
        assert!(
            (st.delta - at_one.delta).abs() <= 1e-7 * at_one.delta,
            "s {s}: {} vs {}",
            st.delta,
            at_one.delta
        );
        let want = at_one.mean_rad_s / s.sqrt();
        assert!(
            (st.mean_rad_s - want).abs() <= 1e-9 * want,
            "s {s}: {} vs {want}",
            st.mean_rad_s
        );
    }
}
