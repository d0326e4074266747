//! Solving several inputs in SIMD lanes (`Kinematics::solve_lanes`) gives what solving
//! them one by one gives, on every dyad type, and fails exactly as one by one does.

use crate::common;

use common::{SCENES, cycle, kinematics, motion_scales};
use linkage::scene::SolverPath;
use linkage::{Kinematics, Mechanism, Solution};
use linkage::{LANES, LaneSolution};

/// Two blocks pinned together at P: one slides on a turning arm, one on a ground
/// guide, so P is where the arm's line meets the guide (a PRP dyad; no shipped scene
/// has one).
const CROSSED_SLIDERS: &str = r#"Scene(
    name: "crossed sliders", models: Kinematics, length_unit: Millimetre, angle_unit: Degree,
    links: [
        (name: "ground", ground: true, points: {"O": (0.0, 0.0), "Q": (0.0, 100.0)}),
        (name: "arm", points: {"O": (0.0, 0.0)}),
        (name: "on_arm", points: {"P": (0.0, 0.0)}),
        (name: "on_guide", points: {"P": (0.0, 0.0)}),
    ],
    sliders: [
        (slider: "on_arm", point: "P", guide: "arm", through: "O", angle: 0.0),
        (slider: "on_guide", point: "P", guide: "ground", through: "Q", angle: 0.0),
    ],
    driver: (link: "arm", speed: Rpm(30.0), start: 60.0),
)"#;

/// Largest difference between lane `k` and the one-position solution, relative to
/// the position's scales (size, size·ω, size·ω² or the largest value present).
fn lane_difference(lanes: &LaneSolution, k: usize, one: &Solution, size: f64) -> f64 {
    let mut lane = Solution::default();
    lanes.lane_into(k, &mut lane);
    let (vmax, amax) = motion_scales(one, size);
    let mut worst: f64 = (lane.input_rad - one.input_rad).abs();
    for (p, q) in lane.points.iter().zip(&one.points) {
        worst = worst
            .max((p.position - q.position).amax() / size)
            .max((p.velocity - q.velocity).amax() / vmax)
            .max((p.acceleration - q.acceleration).amax() / amax);
    }
    for (p, q) in lane.links.iter().zip(&one.links) {
        worst = worst
            .max((p.rotation.re - q.rotation.re).abs())
            .max((p.rotation.im - q.rotation.im).abs())
            .max((p.omega_rad_s - q.omega_rad_s).abs() / vmax * size)
            .max((p.alpha_rad_s2 - q.alpha_rad_s2).abs() / amax * size);
    }
    for (p, q) in lane.slides.iter().zip(&one.slides) {
        worst = worst
            .max((p.displacement_m - q.displacement_m).abs() / size)
            .max((p.velocity_m_s - q.velocity_m_s).abs() / vmax)
            .max((p.acceleration_m_s2 - q.acceleration_m_s2).abs() / amax);
    }
    worst
}

/// Solves `inputs` in lanes with `k` and one by one with a copy of it made before
/// (the Newton path carries its pose from one solve to the next, so both follow
/// the same sequence); the worst difference scaled by the squared conditioning
/// (round-off grows as 1/conditioning per derivative near a dead point).
fn compare(k: &mut Kinematics, inputs: &[f64]) -> f64 {
    let mut alone = k.clone();
    let size = k.mechanism().size_m;
    let speed = k.mechanism().driver.speed_rad_s;
    let mut lanes = k.empty_lane_solution();
    let mut one = k.empty_solution();
    let mut worst: f64 = 0.0;
    for chunk in inputs.chunks_exact(LANES) {
        let x: [f64; LANES] = chunk.try_into().expect("a chunk of LANES");
        k.solve_lanes(x, speed, &mut lanes)
            .unwrap_or_else(|e| panic!("lanes at {x:?}: {e}"));
        for (lane, &input) in x.iter().enumerate() {
            alone
                .solve_into(input, speed, &mut one)
                .unwrap_or_else(|e| panic!("one at {input}: {e}"));
            let scale = one.conditioning.min(1.0).powi(2);
            worst = worst.max(lane_difference(&lanes, lane, &one, size) * scale);
        }
    }
    worst
}

/// The closed form in lanes differs from one-by-one only by the lanes' sine and
/// cosine of the input (within an ulp or two of the standard library's), so 1e-13
/// of the scales is already loose. The Newton path solves lane by lane, in order,
/// so it must agree exactly.
#[test]
fn lanes_match_one_by_one_on_every_scene_and_dyad() {
    for file in SCENES {
        for path in [SolverPath::ClosedForm, SolverPath::Newton] {
            let mut k = kinematics(file, path);
            let inputs = cycle(&k, 256);
            let worst = compare(&mut k, &inputs);
            let bound = if path == SolverPath::Newton {
                0.0
            } else {
                1e-13
            };
            assert!(worst <= bound, "{file} {path:?}: lanes differ by {worst:e}");
        }
    }
    let mech = Mechanism::from_ron(CROSSED_SLIDERS).expect("crossed sliders scene");
    let mut k = Kinematics::with_path(mech, SolverPath::ClosedForm).expect("PRP closed form");
    let inputs: Vec<f64> = (0..64)
        .map(|i| (20.0 + 140.0 * i as f64 / 63.0).to_radians())
        .collect();
    let worst = compare(&mut k, &inputs);
    assert!(worst <= 1e-13, "PRP: lanes differ by {worst:e}");
}

/// One lane that cannot assemble, or is not a number, fails the call with the error
/// that solving that input alone gives; the lanes before it do not hide it.
#[test]
fn a_failing_lane_reports_its_own_input() {
    let mut k = kinematics("gravity_flipper.ron", SolverPath::ClosedForm);
    let speed = k.mechanism().driver.speed_rad_s;
    let inputs = cycle(&k, 8);
    let outside = inputs[0] - 1.0;
    let mut lanes = k.empty_lane_solution();
    for bad in [outside, f64::NAN] {
        let x = [inputs[2], inputs[3], bad, inputs[4]];
        let batch = k
            .solve_lanes(x, speed, &mut lanes)
            .expect_err("a lane outside the assembly range");
        let alone = k
            .solve(bad)
            .expect_err("that input alone fails too")
            .to_string();
        assert_eq!(batch.to_string(), alone);
        if bad.is_finite() {
            assert!(alone.contains("reachable"), "{alone}"); // the refusal names the range
        }
    }
    // The buffer is usable again after a failure.
    let x = [inputs[1], inputs[2], inputs[3], inputs[4]];
    k.solve_lanes(x, speed, &mut lanes)
        .expect("all lanes assemble");
    let mut one = k.empty_solution();
    k.solve_into(inputs[3], speed, &mut one).expect("assembles");
    let size = k.mechanism().size_m;
    assert!(lane_difference(&lanes, 2, &one, size) <= 1e-13);
}
