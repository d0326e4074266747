//! Counterweights on the links pivoted to the frame, against two references:
//! - Berkof and Lowen (1969): any four-bar can be fully force-balanced by
//!   counterweights on its crank and its rocker (the total centre of mass then stands
//!   still). So the best counterweights on those two links, by either aim, leave no
//!   shaking force: checked on a four-bar with masses nobody tuned, to 1e-9 of its
//!   unbalanced peak, through the shaking force of the mechanism with the
//!   counterweights added.
//!
//! The slider-crank's counterweights (least squares against the textbook's, the
//! peak-minimising one a minimum of the real peak) are tested in `shaking.rs`.

use linkage::machine::{BalanceAim, Shaking, counterweights, shaking, with_counterweights};
use linkage::{Kinematics, LinkageError, Mechanism, SceneProblem};

fn four_bar() -> Kinematics {
    let text = r#"Scene(
        name: "four-bar with masses",
        models: Kinetostatics,
        links: [
            (name: "ground", ground: true, points: {"A": (0.0, 0.0), "D": (0.3, 0.02)}),
            (name: "crank", points: {"A": (0.0, 0.0), "B": (0.08, 0.0)}, mass: Some(0.7), centroid: Some((0.03, 0.01)), inertia: Some(0.0004)),
            (name: "coupler", points: {"B": (0.0, 0.0), "C": (0.27, 0.0), "E": (0.12, 0.09)}, mass: Some(1.9), centroid: Some((0.13, 0.04)), inertia: Some(0.012)),
            (name: "rocker", points: {"D": (0.0, 0.0), "C": (0.2, 0.0)}, mass: Some(1.1), centroid: Some((0.09, -0.015)), inertia: Some(0.004)),
        ],
        driver: (link: "crank", speed: RadPerSecond(25.0), start: 0.3),
        branches: {"C": Left("B", "D")},
        output: Some("rocker"),
    )"#;
    Kinematics::new(Mechanism::from_ron(text).expect("scene")).expect("kinematics")
}

fn shaken(m: Mechanism) -> Shaking {
    let mut k = Kinematics::new(m).expect("kinematics");
    shaking(&mut k, [0.0, 0.0]).expect("shaking")
}

#[test]
fn a_four_bar_is_fully_force_balanced_by_its_crank_and_rocker_counterweights() {
    let mut k = four_bar();
    let before = shaking(&mut k, [0.0, 0.0]).expect("shaking");
    let m = k.mechanism().clone();
    let links = [
        m.link_index("crank").expect("crank"),
        m.link_index("rocker").expect("rocker"),
    ];
    for aim in [BalanceAim::Rms, BalanceAim::Peak] {
        let weights = counterweights(&mut k, &before, &links, aim).expect("weights");
        let after = shaken(with_counterweights(&m, &weights));
        assert!(
            after.peak_force_n <= 1e-9 * before.peak_force_n,
            "{aim:?}: {} N left of {} N",
            after.peak_force_n,
            before.peak_force_n
        );
    }
}

#[test]
fn a_counterweight_on_a_link_without_a_ground_pivot_is_refused_by_name() {
    let mut k = four_bar();
    let before = shaking(&mut k, [0.0, 0.0]).expect("shaking");
    let coupler = k.mechanism().link_index("coupler").expect("coupler");
    let e = counterweights(&mut k, &before, &[coupler], BalanceAim::Rms).expect_err("no pivot");
    match e {
        LinkageError::SceneInvalid(p) => {
            assert!(matches!(*p, SceneProblem::NotPivoted { ref link } if link == "coupler"))
        }
        other => panic!("{other}"),
    }
}
