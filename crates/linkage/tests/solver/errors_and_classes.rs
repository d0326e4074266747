//! Bad input gets a message naming its cause; Grashof classes against hand-made
//! four-bars; the crank-rocker synthesis checked by the solver itself.

use linkage::scene::SolverPath;
use linkage::synthesis::crank_rocker;
use linkage::{Kinematics, LinkageError, Mechanism};

fn four_bar(a: f64, b: f64, c: f64, d: f64) -> String {
    format!(
        r#"Scene(name: "four-bar", models: Kinematics,
        links: [
            (name: "ground", ground: true, points: {{"A": (0.0, 0.0), "D": ({d}, 0.0)}}),
            (name: "crank", points: {{"A": (0.0, 0.0), "B": ({a}, 0.0)}}),
            (name: "coupler", points: {{"B": (0.0, 0.0), "C": ({b}, 0.0)}}),
            (name: "rocker", points: {{"D": (0.0, 0.0), "C": ({c}, 0.0)}}),
        ],
        driver: (link: "crank", speed: RadPerSecond(1.0), start: 60.0),
        branches: {{"C": Left("B", "D")}})"#
    )
}

#[test]
fn malformed_scene_reports_line_and_column() {
    let text = "Scene(\n  name: \"x\",\n  models: Kinematics,\n  links: [ (name: 3) ],\n)";
    match Mechanism::from_ron(text) {
        Err(LinkageError::SceneSyntax {
            line,
            column,
            message,
        }) => {
            assert_eq!(line, 4, "{message}");
            assert!(column > 1, "{column}");
        }
        other => panic!("expected a syntax error, got {other:?}"),
    }
}

#[test]
fn invalid_scenes_name_the_cause() {
    let base = four_bar(0.1, 0.3, 0.3, 0.3);
    let cases = [
        (
            base.replace(r#"branches: {"C": Left("B", "D")}"#, ""),
            "needs an assembly branch",
        ),
        (
            base.replace(r#"Left("B", "D")"#, r#"Left("A", "D")"#),
            "must name its end joints",
        ),
        (
            base.replace(r#""B": (0.1, 0.0)}"#, r#""B": (0.0, 0.0)}"#),
            "zero length",
        ),
        (
            base.replace(r#"link: "crank""#, r#"link: "coupler""#),
            "shares no point with ground",
        ),
        (
            base.replace(
                r#"(name: "rocker", points: {"D": (0.0, 0.0), "C": (0.3, 0.0)}),"#,
                "",
            ),
            "mobility",
        ),
        (
            base.replace(
                "0.3, 0.0)}),\n            (name: \"rocker\"",
                "NaN, 0.0)}),\n            (name: \"rocker\"",
            ),
            "finite",
        ),
    ];
    for (text, needle) in cases {
        let err = Mechanism::from_ron(&text)
            .and_then(Kinematics::new)
            .expect_err(needle);
        assert!(
            err.to_string().contains(needle),
            "expected `{needle}` in `{err}`"
        );
    }
}

#[test]
fn non_finite_input_is_refused_with_a_message() {
    let mut k = Kinematics::new(Mechanism::from_ron(&four_bar(0.1, 0.3, 0.3, 0.3)).expect("valid"))
        .expect("k");
    let err = k.solve(f64::NAN).expect_err("NaN input");
    assert!(
        matches!(&err, LinkageError::InvalidParameter { value, .. } if value.is_nan()),
        "{err}"
    );
}

#[test]
fn grashof_classes() {
    let class = |a, b, c, d| {
        let k =
            Kinematics::new(Mechanism::from_ron(&four_bar(a, b, c, d)).expect("valid")).expect("k");
        linkage::analysis::grashof(&k).expect("four-bar").class
    };
    use linkage::analysis::GrashofClass::*;
    assert_eq!(class(0.1, 0.3, 0.3, 0.3), CrankRocker);
    assert_eq!(class(0.3, 0.35, 0.4, 0.1), DoubleCrank);
    assert_eq!(class(0.3, 0.1, 0.3, 0.3), DoubleRocker);
    assert_eq!(class(0.3, 0.3, 0.1, 0.3), RockerCrank);
    assert_eq!(class(0.2, 0.3, 0.3, 0.2), ChangePoint);
    assert_eq!(class(0.3, 0.3, 0.35, 0.45), TripleRocker);
    // The JSON `report` prints keeps the words.
    assert_eq!(
        serde_json::to_string(&CrankRocker).expect("json"),
        "\"crank-rocker\""
    );
    assert_eq!(DoubleCrank.to_string(), "double-crank (drag link)");
}

#[test]
fn change_point_four_bar_reports_its_tangency_instead_of_flipping() {
    // Parallelogram: at input 0 all four links are collinear (a change point).
    let text = four_bar(0.2, 0.3, 0.2, 0.3);
    let mut k = Kinematics::new(Mechanism::from_ron(&text).expect("valid")).expect("k");
    let sw = linkage::sweep::sweep(&mut k, 720);
    match sw {
        Ok(sw) => assert!(
            !sw.near_singular.is_empty(),
            "the change point must be reported"
        ),
        Err(e) => assert!(matches!(e, LinkageError::Singular { .. }), "{e}"),
    }
}

/// The synthesis checked by the solver: the four-bar it designs swings its rocker by
/// the asked swing and has the asked K (both found by the analysis, independently).
#[test]
fn crank_rocker_synthesis_meets_swing_and_k() {
    for (swing_deg, kk) in [(40.0_f64, 1.2), (16.6, 1.3), (70.0, 1.5)] {
        let d = crank_rocker(0.5, swing_deg.to_radians(), kk, 0.3, None).expect("design");
        let text = linkage::synthesis::four_bar_scene(&d, kk)
            .to_ron()
            .expect("ron");
        let mut k = Kinematics::with_path(
            Mechanism::from_ron(&text).expect("scene"),
            SolverPath::ClosedForm,
        )
        .expect("k");
        let r = linkage::analysis::report(&mut k).expect("report");
        assert!(
            (r.swings_rad["rocker"] - swing_deg.to_radians()).abs() < 1e-9,
            "swing {}",
            r.swings_rad["rocker"]
        );
        assert!(
            (r.time_ratio.expect("K") - kk).abs() < 1e-6,
            "K {:?}",
            r.time_ratio
        );
        assert!((r.transmission_angle_rad.expect("mu").min - d.min_transmission_rad).abs() < 1e-6);
    }
    let err = crank_rocker(0.5, 0.5, 1.0, 0.0, None).expect_err("K = 1");
    assert!(
        matches!(&err, LinkageError::InvalidParameter { param: linkage::error::Param::TimeRatio, value, .. }
            if *value == 1.0),
        "{err}"
    );
}
