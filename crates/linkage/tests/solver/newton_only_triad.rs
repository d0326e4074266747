//! A chain with no dyad decomposition (a crank driving a class-III Assur triad: a
//! ternary link held by three binary links) is solved by the Newton path alone, from
//! the scene's rough `guess` poses: closure to 1e-12 and velocities matching finite
//! differences, while the closed-form path refuses with the reason.

use linkage::error::Undecomposable;
use linkage::scene::SolverPath;
use linkage::{Kinematics, LinkageError, Mechanism};

use crate::common;
use common::triad::Triad;

/// The locking layout's scene; guesses are off by `err` (m and rad).
fn triad_scene(err: f64) -> String {
    Triad::locking().scene(err)
}

#[test]
fn triad_is_solved_by_newton_alone() {
    let m = Mechanism::from_ron(&triad_scene(0.01)).expect("valid scene");
    match Kinematics::with_path(m.clone(), SolverPath::ClosedForm) {
        Err(LinkageError::NotDecomposable(why)) => {
            assert!(matches!(why, Undecomposable::NoDyad { .. }), "{why}")
        }
        other => panic!("closed form should refuse: {other:?}"),
    }
    let mut k = Kinematics::new(m.clone()).expect("auto path falls back to Newton");
    assert_eq!(k.path(), linkage::PathKind::Newton);
    let h = 1e-5;
    // This layout has a dead point of the triad near +1 deg (conditioning 0.016 at 0).
    for deg in (-40..=-5).step_by(5) {
        let x = f64::from(deg).to_radians();
        let s = k.solve(x).unwrap_or_else(|e| panic!("{deg} deg: {e}"));
        let closure = m
            .revolutes
            .iter()
            .map(|r| (s.links[r.a].world(&r.a_local) - s.links[r.b].world(&r.b_local)).norm())
            .fold(0.0, f64::max);
        assert!(closure < 1e-12, "{deg} deg: closure {closure:e}");
        // Velocity against a central difference (truncation h²·|x'''| ≈ 1e-10).
        let (lo, hi) = (k.solve(x - h).expect("lo"), k.solve(x + h).expect("hi"));
        for p in 0..s.points.len() {
            let fd = (hi.points[p].position - lo.points[p].position) * (1.5 / (2.0 * h));
            assert!(
                (fd - s.points[p].velocity).amax() < 1e-7,
                "{deg} deg point {p}"
            );
        }
        k.solve(x).expect("back");
    }
    // Past the dead point Newton refuses (an error naming the input), never flips.
    let err = k
        .solve(10f64.to_radians())
        .expect_err("the triad locks near +1 deg");
    assert!(err.to_string().contains("deg"), "{err}");
}

#[test]
fn missing_guess_is_named() {
    let text = triad_scene(0.0).replace(r#""l3": ("#, r#""unused": ("#);
    let err = Mechanism::from_ron(&text)
        .and_then(Kinematics::new)
        .expect_err("no guess for l3");
    assert!(err.to_string().contains("guess"), "{err}");
}
