//! Property tests over random four-bars (Grashof and not), slider-cranks and Watt
//! six-bars, on both solver paths: loop closure to 1e-12 of the size wherever they
//! assemble, velocities and accelerations against central differences where the
//! chain is well conditioned, never a panic, and unassemblable inputs answered with
//! an error that names the reachable range.
//!
//! `LINKAGE_PROPERTY_CASES` sets the cases per generator (96 by default; CI runs
//! 34,000 of each with the test build, over 10^5 in all: scripts/check.sh).

use crate::common;

use linkage::{Kinematics, LinkageError, Mechanism};
use proptest::prelude::*;

/// Cases per generator: `LINKAGE_PROPERTY_CASES`, else 96.
fn cases() -> u32 {
    std::env::var("LINKAGE_PROPERTY_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(96)
}

fn four_bar(a: f64, b: f64, c: f64, d: f64, left: bool) -> String {
    let side = if left { "Left" } else { "Right" };
    format!(
        r#"Scene(name: "random four-bar", models: Kinematics,
        links: [
            (name: "ground", ground: true, points: {{"A": (0.0, 0.0), "D": ({d}, 0.0)}}),
            (name: "crank", points: {{"A": (0.0, 0.0), "B": ({a}, 0.0)}}),
            (name: "coupler", points: {{"B": (0.0, 0.0), "C": ({b}, 0.0)}}),
            (name: "rocker", points: {{"D": (0.0, 0.0), "C": ({c}, 0.0)}}),
        ],
        driver: (link: "crank", speed: RadPerSecond(2.0)),
        branches: {{"C": {side}("B", "D")}})"#
    )
}

/// A Watt six-bar: a four-bar whose rocker carries a second dyad (E on the rocker,
/// G held by a link to the ground pivot F).
#[allow(clippy::too_many_arguments)]
fn six_bar(
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    e: (f64, f64),
    g: f64,
    h: f64,
    f: (f64, f64),
    sides: (bool, bool),
) -> String {
    let side = |left| if left { "Left" } else { "Right" };
    let (s1, s2) = (side(sides.0), side(sides.1));
    format!(
        r#"Scene(name: "random six-bar", models: Kinematics,
        links: [
            (name: "ground", ground: true, points: {{"A": (0.0, 0.0), "D": ({d}, 0.0), "F": ({}, {})}}),
            (name: "crank", points: {{"A": (0.0, 0.0), "B": ({a}, 0.0)}}),
            (name: "coupler", points: {{"B": (0.0, 0.0), "C": ({b}, 0.0)}}),
            (name: "rocker", points: {{"D": (0.0, 0.0), "C": ({c}, 0.0), "E": ({}, {})}}),
            (name: "link5", points: {{"E": (0.0, 0.0), "G": ({g}, 0.0)}}),
            (name: "link6", points: {{"F": (0.0, 0.0), "G": ({h}, 0.0)}}),
        ],
        driver: (link: "crank", speed: RadPerSecond(2.0)),
        branches: {{"C": {s1}("B", "D"), "G": {s2}("E", "F")}})"#,
        f.0, f.1, e.0, e.1
    )
}

fn slider_crank(r: f64, l: f64, e: f64, along: bool) -> String {
    let side = if along { "Along" } else { "Against" };
    format!(
        r#"Scene(name: "random slider-crank", models: Kinematics,
        links: [
            (name: "ground", ground: true, points: {{"A": (0.0, 0.0), "Q": (0.0, {e})}}),
            (name: "crank", points: {{"A": (0.0, 0.0), "B": ({r}, 0.0)}}),
            (name: "rod", points: {{"B": (0.0, 0.0), "C": ({l}, 0.0)}}),
            (name: "slider", points: {{"C": (0.0, 0.0)}}),
        ],
        sliders: [(slider: "slider", point: "C", guide: "ground", through: "Q", angle: 0.0)],
        driver: (link: "crank", speed: RadPerSecond(-3.0)),
        branches: {{"C": {side}}})"#
    )
}

/// Largest distance between the two ends of any revolute joint (each end computed
/// from its own link's pose), relative to the mechanism size.
fn closure_residual(m: &Mechanism, s: &linkage::Solution) -> f64 {
    m.revolutes
        .iter()
        .map(|r| {
            (s.links[r.a].world(&r.a_local) - s.links[r.b].world(&r.b_local)).norm() / m.size_m
        })
        .fold(0.0, f64::max)
}

/// Central differences of every point's position and velocity at x ± h, times the
/// input speed: estimates of its velocity and acceleration.
fn differences(
    k: &mut Kinematics,
    x: f64,
    h: f64,
    w: f64,
) -> Option<Vec<(linkage::Vec2, linkage::Vec2)>> {
    let (lo, hi) = (k.solve(x - h).ok()?, k.solve(x + h).ok()?);
    let f = w / (2.0 * h);
    Some(
        lo.points
            .iter()
            .zip(&hi.points)
            .map(|(l, u)| ((u.position - l.position) * f, (u.velocity - l.velocity) * f))
            .collect(),
    )
}

/// Velocities and accelerations of every point against central differences of the
/// positions and velocities, Richardson-extrapolated from steps h and h/2 (error of
/// order h⁴, so a sharply curved motion does not pass for a wrong derivative).
/// Leaves `k` solved at x.
fn derivatives_match(
    k: &mut Kinematics,
    m: &Mechanism,
    s: &linkage::Solution,
) -> Result<(), String> {
    let (x, h, w) = (s.input_rad, 1e-4, s.input_speed_rad_s);
    let (Some(coarse), Some(fine)) = (differences(k, x, h, w), differences(k, x, 0.5 * h, w))
    else {
        return k.solve(x).map(|_| ()).map_err(|e| e.to_string());
    };
    let (vs, acs) = common::motion_scales(s, m.size_m);
    for (p, point) in s.points.iter().enumerate() {
        let v = (fine[p].0 * 4.0 - coarse[p].0) / 3.0;
        let a = (fine[p].1 * 4.0 - coarse[p].1) / 3.0;
        let (dv, da) = ((v - point.velocity).amax(), (a - point.acceleration).amax());
        if dv > 1e-6 * vs || da > 1e-6 * acs {
            return Err(format!(
                "point {p}: velocity off by {dv:e} (scale {vs:e}), acceleration by {da:e} (scale {acs:e})"
            ));
        }
    }
    k.solve(x).map(|_| ()).map_err(|e| e.to_string())
}

/// Distance (rad, around the circle) from `x` to the nearest of `ends`.
fn distance_to(ends: &[f64], x: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    ends.iter()
        .map(|e| {
            let d = (x - e).rem_euclid(tau);
            d.min(tau - d)
        })
        .fold(f64::INFINITY, f64::min)
}

fn check(text: &str) -> Result<(), TestCaseError> {
    let m = Mechanism::from_ron(text).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let mut reference = Kinematics::with_path(m.clone(), linkage::scene::SolverPath::ClosedForm)
        .map_err(|e| TestCaseError::fail(e.to_string()))?;
    let ends: Vec<f64> = linkage::analysis::assembly_ranges_of(&reference)
        .intervals
        .iter()
        .flat_map(|[a, b]| [*a, *b])
        .collect();
    for path in [
        linkage::scene::SolverPath::ClosedForm,
        linkage::scene::SolverPath::Newton,
    ] {
        let mut k = match Kinematics::with_path(m.clone(), path) {
            Ok(k) => k,
            // The Newton path starts from the scene's start pose; it may not assemble.
            Err(LinkageError::CannotAssemble { reachable, .. }) => {
                prop_assert!(!reachable.full_rotation, "{reachable}");
                continue;
            }
            Err(e) => return Err(TestCaseError::fail(format!("{path:?}: {e}"))),
        };
        // 24 inputs (15 deg apart) per mechanism: coverage comes from the number of
        // mechanisms, 34,000 of each in CI.
        for i in 0..24 {
            let x = std::f64::consts::TAU * i as f64 / 24.0;
            let margin = reference.assembly_margin(x).unwrap_or(f64::NAN);
            match k.solve(x) {
                Ok(s) => {
                    prop_assert!(closure_residual(&m, &s) < 1e-12, "{path:?} residual at {x}");
                    // Differences need the motion smooth over x ± h: away from dead
                    // points (where it goes as √ of the distance) and tangencies.
                    if s.conditioning > 0.1 && distance_to(&ends, x) > 0.05 {
                        derivatives_match(&mut k, &m, &s)
                            .map_err(|e| TestCaseError::fail(format!("{path:?} at {x}: {e}")))?;
                    }
                    let finite = s.points.iter().all(|p| {
                        p.position
                            .iter()
                            .chain(p.velocity.iter())
                            .chain(p.acceleration.iter())
                            .all(|v| v.is_finite())
                    });
                    prop_assert!(finite, "{path:?}: non-finite value at {x}");
                }
                Err(LinkageError::CannotAssemble { reachable, .. }) => {
                    prop_assert!(
                        margin < 1e-9,
                        "refused an assemblable input {x} (margin {margin})"
                    );
                    prop_assert!(!reachable.full_rotation, "{reachable}");
                }
                // Exactly at a dead point, or Newton refusing to cross one: named, not a panic.
                Err(
                    LinkageError::Singular { .. }
                    | LinkageError::BranchJump { .. }
                    | LinkageError::NewtonDiverged { .. },
                ) => {
                    prop_assert!(
                        path == linkage::scene::SolverPath::Newton || margin.abs() < 1e-6,
                        "{path:?} singular at {x} with margin {margin}"
                    );
                }
                Err(e) => return Err(TestCaseError::fail(format!("{path:?} at {x}: {e}"))),
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), .. ProptestConfig::default() })]

    #[test]
    fn random_four_bars(a in 0.01f64..2.0, b in 0.01f64..2.0, c in 0.01f64..2.0, d in 0.01f64..2.0, left: bool) {
        check(&four_bar(a, b, c, d, left))?;
    }

    #[test]
    fn random_slider_cranks(r in 0.01f64..1.0, l in 0.01f64..2.0, e in -1.0f64..1.0, along: bool) {
        check(&slider_crank(r, l, e, along))?;
    }
}

// The six-bars cost most (two loops solved at every position): in two tests, half the
// cases each, by the first dyad's branch, so that the test threads share them (CI's
// run at scale waited 60 s on one thread for them).
proptest! {
    #![proptest_config(ProptestConfig { cases: cases().div_ceil(2), .. ProptestConfig::default() })]

    #[test]
    fn random_six_bars_first_dyad_left(dims in six_bar_dimensions(), left2: bool) {
        check(&six_bar_of(dims, (true, left2)))?;
    }

    #[test]
    fn random_six_bars_first_dyad_right(dims in six_bar_dimensions(), left2: bool) {
        check(&six_bar_of(dims, (false, left2)))?;
    }
}

/// A random Watt six-bar's lengths and points: crank a, coupler b, rocker c, frame d,
/// E on the rocker, the second dyad's g and h, the ground pivot F.
type SixBarDimensions = [f64; 10];

prop_compose! {
    fn six_bar_dimensions()(
        a in 0.05f64..0.5, b in 0.3f64..1.5, c in 0.3f64..1.5, d in 0.5f64..1.5,
        ex in -0.5f64..0.5, ey in -0.5f64..0.5, g in 0.3f64..1.5, h in 0.3f64..1.5,
        fx in -1.0f64..2.0, fy in -1.0f64..1.5,
    ) -> SixBarDimensions {
        [a, b, c, d, ex, ey, g, h, fx, fy]
    }
}

/// The six-bar of `dims` on the branches `left`.
fn six_bar_of(dims: SixBarDimensions, left: (bool, bool)) -> String {
    let [a, b, c, d, ex, ey, g, h, fx, fy] = dims;
    six_bar(a, b, c, d, (ex, ey), g, h, (fx, fy), left)
}

/// The closed form answers every input of a random Grashof crank-rocker (it turns fully).
#[test]
fn grashof_crank_rockers_turn_fully() {
    let mut runner = proptest::test_runner::TestRunner::default();
    runner
        .run(
            &(0.05f64..0.2, 0.6f64..1.0, 0.6f64..1.0, 0.6f64..1.0),
            |(a, b, c, d)| {
                let longest = b.max(c).max(d);
                prop_assume!(a + longest < b + c + d - longest);
                let mut k = Kinematics::new(
                    Mechanism::from_ron(&four_bar(a, b, c, d, true))
                        .map_err(|e| TestCaseError::fail(e.to_string()))?,
                )
                .map_err(|e| TestCaseError::fail(e.to_string()))?;
                let r = linkage::analysis::report(&mut k)
                    .map_err(|e| TestCaseError::fail(e.to_string()))?;
                prop_assert!(r.full_rotation);
                prop_assert_eq!(
                    r.grashof.map(|g| g.class),
                    Some(linkage::analysis::GrashofClass::CrankRocker)
                );
                Ok(())
            },
        )
        .map_err(|e| e.to_string())
        .unwrap_or_else(|e| panic!("{e}"));
}
