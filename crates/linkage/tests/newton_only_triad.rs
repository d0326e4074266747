//! A chain with no dyad decomposition (a crank driving a class-III Assur triad: a
//! ternary link held by three binary links) is solved by the Newton path alone, from
//! the scene's rough `guess` poses: closure to 1e-12 and velocities matching finite
//! differences, while the closed-form path refuses with the reason.

use linkage::scene::SolverPath;
use linkage::{Kinematics, LinkageError, Mechanism, Vec2};

/// Scene with pins placed at the start pose; guesses are off by `err` (m and rad).
fn triad_scene(err: f64) -> String {
    let v = Vec2::new;
    let (o, p1) = (v(0.0, 0.0), v(0.1, 0.0));
    let (q1, q2, q3) = (v(0.3, 0.2), v(0.5, 0.25), v(0.4, 0.4));
    let (g2, g3) = (v(0.6, 0.0), v(0.2, 0.6));
    let bar = |a: Vec2, b: Vec2| ((b - a).norm(), (b - a).y.atan2((b - a).x).to_degrees());
    let (l1, a1) = bar(p1, q1);
    let (l2, a2) = bar(g2, q2);
    let (l3, a3) = bar(g3, q3);
    let (t2, t3) = (q2 - q1, q3 - q1);
    let e = err;
    let ed = err.to_degrees();
    format!(
        r#"Scene(name: "triad", models: Kinematics,
        links: [
            (name: "ground", ground: true, points: {{"O": ({ox}, {oy}), "G2": ({g2x}, {g2y}), "G3": ({g3x}, {g3y})}}),
            (name: "crank", points: {{"O": (0.0, 0.0), "P1": (0.1, 0.0)}}),
            (name: "l1", points: {{"P1": (0.0, 0.0), "Q1": ({l1}, 0.0)}}),
            (name: "tri", points: {{"Q1": (0.0, 0.0), "Q2": ({t2x}, {t2y}), "Q3": ({t3x}, {t3y})}}),
            (name: "l2", points: {{"G2": (0.0, 0.0), "Q2": ({l2}, 0.0)}}),
            (name: "l3", points: {{"G3": (0.0, 0.0), "Q3": ({l3}, 0.0)}}),
        ],
        driver: (link: "crank", speed: RadPerSecond(1.5), start: 0.0),
        guess: {{
            "crank": (0.0, 0.0, 0.0),
            "l1": ({p1x}, {p1y}, {a1}),
            "tri": ({q1x}, {q1y}, {ed}),
            "l2": ({g2x}, {g2y}, {a2e}),
            "l3": ({g3x}, {g3y}, {a3e}),
        }})"#,
        ox = o.x,
        oy = o.y,
        g2x = g2.x,
        g2y = g2.y,
        g3x = g3.x,
        g3y = g3.y,
        t2x = t2.x,
        t2y = t2.y,
        t3x = t3.x,
        t3y = t3.y,
        p1x = p1.x + e,
        p1y = p1.y - e,
        q1x = q1.x - e,
        q1y = q1.y + e,
        a2e = a2 + ed,
        a3e = a3 - ed,
    )
}

#[test]
fn triad_is_solved_by_newton_alone() {
    let m = Mechanism::from_ron(&triad_scene(0.01)).expect("valid scene");
    match Kinematics::with_path(m.clone(), SolverPath::ClosedForm) {
        Err(LinkageError::NotDecomposable(why)) => {
            assert!(why.contains("no RRR, RRP, RPR or PRP dyad"), "{why}")
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
