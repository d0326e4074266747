//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod slider_crank;
pub mod triad;

use linkage::scene::{FreeLength, Models, SolverPath, SpringSpec};
use linkage::{Kinematics, Mechanism, Vec2};

/// Every scene shipped in `assets/scenes`.
pub const SCENES: [&str; 7] = [
    "paper_cup_feed.ron",
    "paper_cup_cam_feed.ron",
    "die_cutter.ron",
    "die_cutter_as_printed.ron",
    "gravity_flipper.ron",
    "slider_crank.ron",
    "quick_return.ron",
];

/// Every template in `assets/templates` (the editor's "New…" menu).
pub const TEMPLATES: [&str; 5] = [
    "four_bar.ron",
    "slider_crank.ron",
    "inverted_slider_crank.ron",
    "watt_six_bar.ron",
    "stephenson_six_bar.ron",
];

/// Text of a template.
pub fn template_text(file: &str) -> String {
    let path = format!(
        "{}/../../assets/templates/{file}",
        env!("CARGO_MANIFEST_DIR")
    );
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"))
}

/// Text of a shipped scene.
pub fn scene_text(file: &str) -> String {
    let path = format!("{}/../../assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"))
}

/// A shipped scene, validated.
pub fn mechanism(file: &str) -> Mechanism {
    Mechanism::from_ron(&scene_text(file)).unwrap_or_else(|e| panic!("{file}: {e}"))
}

/// Whether a cam of `m` is within `within` rad of a join of its program at the solved
/// position `s`: there the follower's higher derivatives jump (a cycloid's jerk at a
/// dwell), so finite differences across it lose their order.
pub fn near_cam_join(m: &Mechanism, s: &linkage::Solution, within: f64) -> bool {
    m.cams.iter().any(|cam| {
        let theta = s.links[cam.cam].angle_rad() - cam.phase_rad;
        cam.program
            .spans()
            .iter()
            .any(|&(start, _)| wrap(theta - start).abs() < within)
    })
}

/// A shipped scene on the given solver path.
pub fn kinematics(file: &str, path: SolverPath) -> Kinematics {
    Kinematics::with_path(mechanism(file), path).unwrap_or_else(|e| panic!("{file}: {e}"))
}

/// Inputs over the scene's sweep range (full turn or assembly interval).
pub fn cycle(k: &Kinematics, n: usize) -> Vec<f64> {
    let ([a, b], full) = linkage::sweep::sweep_range(k).expect("scene assembles somewhere");
    let div = if full { n } else { n - 1 };
    (0..n)
        .map(|i| a + (b - a) * i as f64 / div as f64)
        .collect()
}

/// Wraps an angle difference into (-π, π].
pub fn wrap(a: f64) -> f64 {
    let t = std::f64::consts::TAU;
    a - (a / t).round() * t
}

/// Velocity and acceleration scales of one position: the largest point velocity and
/// acceleration component, at least size·ω and size·ω².
pub fn motion_scales(s: &linkage::Solution, size: f64) -> (f64, f64) {
    let w = s.input_speed_rad_s.abs();
    let vmax = s
        .points
        .iter()
        .map(|p| p.velocity.amax())
        .fold(size * w, f64::max);
    let amax = s
        .points
        .iter()
        .map(|p| p.acceleration.amax())
        .fold(size * w * w, f64::max);
    (vmax, amax)
}

/// `m` with mass, centroid and inertia on every moving link, gravity, a spring from
/// the frame to the output, and a crank speed: numbers nobody tuned, derived from
/// the link's own size.
pub fn loaded(mut m: Mechanism) -> Mechanism {
    m.models = Models::Kinetostatics;
    let size = m.size_m;
    for (n, l) in m.link_ids().enumerate() {
        if l == m.ground {
            continue;
        }
        let link = &mut m.links[l];
        let k = 1.0 + 0.37 * n as f64;
        let (sum, count) = link
            .points
            .iter()
            .fold((Vec2::zeros(), 0.0_f64), |(s, c), (_, p)| (s + p, c + 1.0));
        let centre = sum / count.max(1.0) + Vec2::new(0.1, -0.07) * size * k.fract();
        link.mass_kg = Some(0.5 * k);
        link.centroid_m = Some(centre);
        link.inertia_kg_m2 = Some(0.5 * k * (0.2 * size).powi(2));
    }
    m.forces.gravity = Some((0.0, -9.81));
    let output_point = m.links[m.output].points.last().map(|(p, _)| *p);
    let ground_point = m.links[m.ground].points.first().map(|(p, _)| *p);
    if let (Some(a), Some(b)) = (output_point, ground_point) {
        m.forces.springs.push(SpringSpec {
            a: m.points[a].name.clone(),
            b: m.points[b].name.clone(),
            k_n_per_m: 50.0 / size,
            free_length: FreeLength::Length(0.5 * size),
        });
    }
    if m.driver.speed_rad_s == 0.0 {
        m.driver.speed_rad_s = 12.0;
    }
    m
}
