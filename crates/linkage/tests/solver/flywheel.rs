//! Flywheel sizing by the energy method against closed forms written here: an in-line
//! slider-crank with a point mass on the slider and a pressing force on its working
//! stroke only (half the cycle), whose torque, surplus and reduced inertia are known
//! exactly; and the die cutter's torque against the Newton–Euler kinetostatics.

use crate::common;

use common::kinematics;
use linkage::kinetostatics::Kinetostatics;
use linkage::machine::size_flywheel;
use linkage::scene::SolverPath;
use linkage::{Kinematics, LinkageError, Mechanism};

const TAU: f64 = std::f64::consts::TAU;
/// Crank, rod (m), slider mass (kg), pressing force (N), crank speed (rad/s).
const R: f64 = 0.05;
const L: f64 = 0.2;
const MASS: f64 = 10.0;
const FORCE: f64 = 5000.0;
const OMEGA: f64 = 30.0;
/// The scene's start angle, deg: off the one-degree grid, so that the working
/// stroke's switch at φ = π falls inside a panel.
const START_DEG: f64 = 17.37;

fn press() -> Kinematics {
    press_turning(OMEGA)
}

/// The press with its crank turning at `omega` (rad/s, negative clockwise).
fn press_turning(omega: f64) -> Kinematics {
    let text = format!(
        r#"Scene(
        name: "press",
        models: Kinetostatics,
        links: [
            (name: "ground", ground: true, points: {{"O": (0.0, 0.0)}}),
            (name: "crank", points: {{"O": (0.0, 0.0), "A": ({R}, 0.0)}}),
            (name: "rod", points: {{"A": (0.0, 0.0), "C": ({L}, 0.0)}}),
            (name: "slider", points: {{"C": (0.0, 0.0)}}, mass: Some({MASS}), centroid: Some((0.0, 0.0))),
        ],
        sliders: [(slider: "slider", point: "C", guide: "ground", through: "O", angle: 0.0)],
        driver: (link: "crank", speed: RadPerSecond({omega}), start: {START_DEG}),
        branches: {{"C": Along}},
        forces: (point_forces: [(point: "C", force_n: (-{FORCE}, 0.0), when: WorkingStroke)]),
    )"#
    );
    Kinematics::new(Mechanism::from_ron(&text).expect("scene")).expect("kinematics")
}

/// The press's slider: s(φ), s'(φ), s''(φ).
fn slide(phi: f64) -> (f64, f64, f64) {
    common::slider_crank::slide(R, L, phi)
}

/// The torque at constant ω: the slider's inertia force m s'' ω² times s', and the
/// force F times s' while the slider moves against it (s' > 0).
fn torque(phi: f64) -> f64 {
    let (_, s1, s2) = slide(phi);
    MASS * OMEGA * OMEGA * s1 * s2 + if s1 > 0.0 { FORCE * s1 } else { 0.0 }
}

/// The mean torque: the force's work F·2r over a turn of 2π (inertia gives none).
fn mean_torque() -> f64 {
    FORCE * 2.0 * R / TAU
}

/// W(φ) = T_m φ − ½ m ω² s'(φ)² − F (s(φ) − s(π)) on the working stroke φ > π, for
/// φ in [0, 2π] from φ = 0 (where s' = 0).
fn surplus_from_zero(phi: f64) -> f64 {
    let (s, s1, _) = slide(phi);
    let load = if phi > std::f64::consts::PI {
        FORCE * (s - slide(std::f64::consts::PI).0)
    } else {
        0.0
    };
    mean_torque() * phi - 0.5 * MASS * OMEGA * OMEGA * s1 * s1 - load
}

/// The extreme of `f` (largest when `sign` is 1, smallest when −1): on a fine grid,
/// then golden-section search around the best grid point.
fn extreme(f: impl Fn(f64) -> f64, sign: f64) -> (f64, f64) {
    let n = 20_000;
    let h = TAU / n as f64;
    let best = (0..=n)
        .map(|i| i as f64 * h)
        .max_by(|a, b| (sign * f(*a)).total_cmp(&(sign * f(*b))))
        .expect("grid");
    let (mut a, mut b) = ((best - h).max(0.0), (best + h).min(TAU));
    let g = (5f64.sqrt() - 1.0) / 2.0;
    while b - a > 1e-12 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if sign * f(c) > sign * f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let x = 0.5 * (a + b);
    (x, f(x))
}

/// The surplus since the scene's start angle, at any crank angle of the turn that
/// follows it (the surplus over a whole turn is zero).
fn surplus(phi: f64) -> f64 {
    surplus_from_zero(phi.rem_euclid(TAU)) - surplus_from_zero(START_DEG.to_radians())
}

/// Angles `a` and `b` equal to `tol` modulo a turn.
fn same_angle(a: f64, b: f64, tol: f64) -> bool {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d) < tol
}

fn close(got: f64, want: f64, scale: f64, what: &str) {
    assert!(
        (got - want).abs() <= 1e-9 * scale,
        "{what}: {got} vs {want} (off by {:e} of {scale})",
        (got - want).abs() / scale
    );
}

#[test]
fn a_press_flywheel_matches_its_closed_form() {
    let delta = 0.05;
    let sized = size_flywheel(&mut press(), delta).expect("sized");
    let (at_max, w_max) = extreme(surplus_from_zero, 1.0);
    let (at_min, w_min) = extreme(surplus_from_zero, -1.0);
    let range = w_max - w_min;
    close(
        sized.mean_torque_n_m,
        mean_torque(),
        mean_torque(),
        "mean torque",
    );
    close(
        sized.mean_power_w,
        mean_torque() * OMEGA,
        mean_torque() * OMEGA,
        "mean power",
    );
    close(sized.work_range_j, range, range, "ΔW_max");
    close(
        sized.flywheel_kg_m2,
        range / (OMEGA * OMEGA * delta),
        range / (OMEGA * OMEGA * delta),
        "J_F",
    );
    assert!(
        same_angle(sized.angle_of_max_rad, at_max, 1e-5),
        "{} vs {at_max}",
        sized.angle_of_max_rad
    );
    assert!(
        same_angle(sized.angle_of_min_rad, at_min, 1e-5),
        "{} vs {at_min}",
        sized.angle_of_min_rad
    );
    let peak = sized
        .cycle
        .iter()
        .map(|c| c.torque_n_m.abs())
        .fold(0.0, f64::max);
    let peak_inertia = sized.reduced_inertia_kg_m2.max;
    for c in &sized.cycle {
        close(c.torque_n_m, torque(c.angle_rad), peak, "torque");
        close(c.surplus_j, surplus(c.angle_rad), range, "surplus");
        let s1 = slide(c.angle_rad).1;
        close(
            c.reduced_inertia_kg_m2,
            MASS * s1 * s1,
            peak_inertia,
            "reduced inertia",
        );
    }
    // The mean torque does the load's work over one turn: the surplus closes.
    close(
        sized.cycle.last().expect("cycle").surplus_j,
        0.0,
        range,
        "surplus after a turn",
    );
}

#[test]
fn the_die_cutters_cycle_torque_is_the_newton_euler_torque() {
    let mut k = kinematics("die_cutter.ron", SolverPath::Auto);
    let sized = size_flywheel(&mut k, 0.05).expect("sized");
    let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
    let peak = sized.peak_torque_n_m.abs().max(sized.mean_torque_n_m.abs());
    for c in sized.cycle.iter().step_by(7) {
        let Ok(state) = ks.at(&mut k, c.angle_rad) else {
            continue; // a dead point of the input: the reactions are indeterminate there
        };
        close(
            c.torque_n_m,
            state.torque_newton_euler,
            peak,
            "die cutter torque",
        );
    }
}

#[test]
fn a_delta_outside_its_range_and_a_rocking_input_are_refused_with_the_reason() {
    for delta in [0.0, -0.1, 1.0, f64::NAN] {
        let err = size_flywheel(&mut press(), delta).expect_err("refused");
        assert!(
            matches!(
                &err,
                LinkageError::InvalidParameter {
                    param: linkage::error::Param::Delta,
                    ..
                }
            ),
            "{err}"
        );
    }
    let mut rocker = kinematics("gravity_flipper.ron", SolverPath::Auto);
    let err = size_flywheel(&mut rocker, 0.05).expect_err("not a crank");
    assert!(
        matches!(
            err,
            LinkageError::NotACrank {
                needs: linkage::error::MachineAnalysis::Flywheel,
                ..
            }
        ),
        "{err}"
    );
    assert!(
        err.to_string().contains("flywheel sizing needs a crank"),
        "{err}"
    );
}

/// Turning clockwise is the same machine seen from behind (the in-line slider's
/// position is even in the crank angle): the same surplus range, flywheel and mean
/// power, counter-clockwise torques of the opposite sign.
#[test]
fn a_crank_turning_clockwise_needs_the_same_flywheel() {
    let ccw = size_flywheel(&mut press_turning(OMEGA), 0.05).expect("sized");
    let cw = size_flywheel(&mut press_turning(-OMEGA), 0.05).expect("sized");
    close(
        cw.work_range_j,
        ccw.work_range_j,
        ccw.work_range_j,
        "ΔW_max",
    );
    close(
        cw.flywheel_kg_m2,
        ccw.flywheel_kg_m2,
        ccw.flywheel_kg_m2,
        "J_F",
    );
    close(
        cw.mean_power_w,
        ccw.mean_power_w,
        ccw.mean_power_w,
        "mean power",
    );
    close(
        cw.mean_torque_n_m,
        -ccw.mean_torque_n_m,
        ccw.mean_torque_n_m,
        "mean torque",
    );
    // The slowest point mirrored about φ = 0 (s is even in φ).
    let mirrored = -ccw.angle_of_min_rad;
    assert!(
        same_angle(cw.angle_of_min_rad, mirrored, 1e-6),
        "{} vs {mirrored}",
        cw.angle_of_min_rad
    );
}

/// The peak torque is located, not read off the sizing's panels: against the closed
/// form's own extreme (a fine grid and a golden-section search on it, written here)
/// to the rounding of the torque, with its angle. The press's largest |T| is on its
/// working stroke.
#[test]
fn the_peak_torque_is_located_on_the_closed_form() {
    let sized = size_flywheel(&mut press(), 0.05).expect("sized");
    let (at_max, max) = extreme(torque, 1.0);
    let (at_min, min) = extreme(torque, -1.0);
    let (at, want) = if max.abs() >= min.abs() {
        (at_max, max)
    } else {
        (at_min, min)
    };
    close(sized.peak_torque_n_m, want, want.abs(), "peak torque");
    assert!(
        same_angle(sized.peak_torque_at_rad, at, 1e-6),
        "at {} rad, the closed form's at {at}",
        sized.peak_torque_at_rad
    );
    // A sampled peak would have been lower than the located one.
    let sampled = sized
        .cycle
        .iter()
        .map(|c| c.torque_n_m.abs())
        .fold(0.0, f64::max);
    assert!(sampled <= sized.peak_torque_n_m.abs() * (1.0 + 1e-15));
}
