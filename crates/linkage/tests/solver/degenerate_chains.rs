//! Degenerate geometry handled for what it is: a change-point four-bar assembles and
//! its branch points are reported; a chain whose joints are redundant is refused for
//! its true mobility; a point placed absurdly far away is named as the cause.

use linkage::analysis::report;
use linkage::{Kinematics, LinkageError, Mechanism, SceneProblem};

const RHOMBUS: &str = r#"Scene(name: "rhombus", models: Kinematics,
    links: [
        (name: "ground", ground: true, points: {"A": (0.0, 0.0), "D": (1.0, 0.0)}),
        (name: "crank", points: {"A": (0.0, 0.0), "B": (1.0, 0.0)}),
        (name: "coupler", points: {"B": (0.0, 0.0), "C": (1.0, 0.0)}),
        (name: "rocker", points: {"D": (0.0, 0.0), "C": (1.0, 0.0)}),
    ],
    driver: (link: "crank", speed: RadPerSecond(1.0), start: 60.0),
    branches: {"C": Left("B", "D")},
)"#;

fn kinematics(text: &str) -> linkage::Result<Kinematics> {
    Mechanism::from_ron(text).and_then(Kinematics::new)
}

#[test]
fn a_rhombus_change_point_four_bar_assembles_with_its_branch_points() {
    let mut k = kinematics(RHOMBUS).expect("the rhombus is a valid scene");
    let r = report(&mut k).expect("the rhombus assembles");
    assert!(r.full_rotation, "{:?}", r.assembly_range_rad);
    assert_eq!(
        r.grashof.map(|g| g.class),
        Some(linkage::analysis::GrashofClass::ChangePoint)
    );
    // Stretched straight at 180 deg (B, A, C... D in one line), and B on D at 0 deg.
    let near = |x: f64, want: f64| {
        let d = (x - want).rem_euclid(std::f64::consts::TAU);
        d.min(std::f64::consts::TAU - d) < 1e-6
    };
    let at_pi = r
        .branch_points
        .iter()
        .find(|b| near(b.input_rad, std::f64::consts::PI));
    let at_zero = r.branch_points.iter().find(|b| near(b.input_rad, 0.0));
    assert!(
        at_pi.is_some_and(|b| b.coincident_joints.is_empty()),
        "{:?}",
        r.branch_points
    );
    let coincident = &at_zero.expect("a branch point at 0 deg").coincident_joints;
    assert!(
        coincident
            .iter()
            .any(|p| p.contains(&"B".to_string()) && p.contains(&"D".to_string())),
        "B and D coincide there: {coincident:?}"
    );
    assert_eq!(r.branch_points.len(), 2, "{:?}", r.branch_points);
}

#[test]
fn an_over_constrained_braced_five_bar_is_refused_for_its_mobility() {
    // A five-bar (two degrees of freedom) with a brace pinned to two ground points:
    // Grübler's count gives 1 (5 moving links, 7 joints).
    let text = r#"Scene(name: "braced five-bar", models: Kinematics,
        links: [
            (name: "ground", ground: true, points: {"O1": (0.0, 0.0), "O2": (1.0, 0.0)}),
            (name: "crank", points: {"O1": (0.0, 0.0), "B": (0.3, 0.0)}),
            (name: "l2", points: {"B": (0.0, 0.0), "C": (0.8, 0.0)}),
            (name: "l3", points: {"C": (0.0, 0.0), "D": (0.8, 0.0)}),
            (name: "l4", points: {"O2": (0.0, 0.0), "D": (0.5, 0.0)}),
            (name: "brace", points: {"O1": (0.0, 0.0), "O2": (1.0, 0.0)}),
        ],
        driver: (link: "crank", speed: RadPerSecond(1.0), start: 60.0),
        guess: {
            "crank": (0.0, 0.0, 60.0),
            "l2": (0.15, 0.26, 60.0),
            "l3": (0.55, 0.95, -30.0),
            "l4": (1.0, 0.0, 100.0),
            "brace": (0.0, 0.0, 0.0),
        })"#;
    match kinematics(text) {
        Err(LinkageError::SceneInvalid(why)) => {
            assert_eq!(*why, SceneProblem::RedundantJoints { dof: 2 }, "{why}")
        }
        other => panic!("expected the mobility named, got {other:?}"),
    }
}

#[test]
fn a_point_at_1e300_is_named_not_reported_as_a_zero_length() {
    let text = RHOMBUS.replace(r#""B": (1.0, 0.0)}),"#, r#""B": (1e300, 0.0)}),"#);
    assert_ne!(text, RHOMBUS);
    let err = kinematics(&text).expect_err("refused");
    let LinkageError::SceneInvalid(why) = &err else {
        panic!("expected the far point named, got {err}");
    };
    let SceneProblem::LengthLost {
        farthest_point,
        farthest_link,
        size_m,
        ..
    } = &**why
    else {
        panic!("expected the far point named, not another problem: {why}");
    };
    assert_eq!(
        (farthest_point.as_str(), farthest_link.as_str()),
        ("B", "crank")
    );
    assert_eq!(*size_m, 1e300);
    // The wording names it as the user wrote it.
    assert!(err.to_string().contains("1.000e300"), "{err}");
}

#[test]
fn a_sweep_of_the_rhombus_steps_past_its_branch_points() {
    // From 60 deg in 30 deg steps, two samples land exactly on the branch points.
    let mut k = kinematics(RHOMBUS).expect("the rhombus is a valid scene");
    let sw = linkage::sweep::sweep(&mut k, 12).expect("the sweep goes on past 180 deg");
    let finite = sw.solutions.iter().all(|s| {
        s.points.iter().all(|p| {
            p.velocity
                .iter()
                .chain(p.acceleration.iter())
                .all(|v| v.is_finite())
        })
    });
    assert!(finite, "every row finite");
    let pi = std::f64::consts::PI;
    for at in [pi, 2.0 * pi] {
        let row = sw
            .solutions
            .iter()
            .find(|s| (s.input_rad - at).abs() < 1e-4)
            .expect("a row at the branch point");
        assert!(row.input_rad != at, "stepped a hair past {at}");
        assert!(
            sw.near_singular.contains(&row.input_rad),
            "{at} reported as near singular"
        );
    }
}
