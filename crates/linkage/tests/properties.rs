//! Property tests over random four-bars (Grashof and not) and slider-cranks:
//! loop closure to 1e-12 wherever they assemble, never a panic, and unassemblable
//! inputs answered with an error that names the reachable range.

use linkage::{Kinematics, LinkageError, Mechanism};
use proptest::prelude::*;

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

fn check(text: &str) -> Result<(), TestCaseError> {
    let m = Mechanism::from_ron(text).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let mut reference = Kinematics::with_path(m.clone(), linkage::scene::SolverPath::ClosedForm)
        .map_err(|e| TestCaseError::fail(e.to_string()))?;
    for path in [
        linkage::scene::SolverPath::ClosedForm,
        linkage::scene::SolverPath::Newton,
    ] {
        let mut k = match Kinematics::with_path(m.clone(), path) {
            Ok(k) => k,
            // The Newton path starts from the scene's start pose; it may not assemble.
            Err(LinkageError::CannotAssemble { reachable, .. }) => {
                prop_assert!(
                    reachable.contains("reachable") || reachable.contains("no input"),
                    "{reachable}"
                );
                continue;
            }
            Err(e) => return Err(TestCaseError::fail(format!("{path:?}: {e}"))),
        };
        for i in 0..72 {
            let x = std::f64::consts::TAU * i as f64 / 72.0;
            let margin = reference.assembly_margin(x).unwrap_or(f64::NAN);
            match k.solve(x) {
                Ok(s) => {
                    prop_assert!(closure_residual(&m, &s) < 1e-12, "{path:?} residual at {x}");
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
                    prop_assert!(
                        reachable.contains("reachable input range")
                            || reachable.contains("no input"),
                        "{reachable}"
                    );
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
    #![proptest_config(ProptestConfig { cases: 96, .. ProptestConfig::default() })]

    #[test]
    fn random_four_bars(a in 0.01f64..2.0, b in 0.01f64..2.0, c in 0.01f64..2.0, d in 0.01f64..2.0, left: bool) {
        check(&four_bar(a, b, c, d, left))?;
    }

    #[test]
    fn random_slider_cranks(r in 0.01f64..1.0, l in 0.01f64..2.0, e in -1.0f64..1.0, along: bool) {
        check(&slider_crank(r, l, e, along))?;
    }
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
                prop_assert_eq!(r.grashof.map(|g| g.class), Some("crank-rocker".to_string()));
                Ok(())
            },
        )
        .map_err(|e| e.to_string())
        .unwrap_or_else(|e| panic!("{e}"));
}
