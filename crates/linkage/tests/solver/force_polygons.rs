//! Force polygons (graphical kinetostatics, group by group from the output back to
//! the crank) against two references:
//! - a massless slider-crank pressed by a force P on its slider, whose rod is a
//!   two-force member (P acts at a point S of the slider on the guide line, so that
//!   it is the slider's): the rod force P / cos β along the rod, the guide's normal
//!   force, the crank pivot's reaction and the balancing torque in closed form,
//!   written here;
//! - the whole-chain Newton–Euler solution, on every shipped scene and template given
//!   masses, inertias, gravity and a spring it did not choose, at 72 positions: every
//!   polygon closes to 1e-9 of its largest force and every reaction and the balancing
//!   torque agree to 1e-9.

use crate::common;

use linkage::force_polygon::{ForcePolygons, ForceSymbol, JointId, Stage, force_polygons};
use linkage::kinetostatics::Kinetostatics;
use linkage::{Kinematics, LinkageError, Mechanism, Vec2};

const R: f64 = 0.04;
const L: f64 = 0.15;
const P: f64 = 800.0;

fn press() -> Kinematics {
    let text = format!(
        r#"Scene(
        name: "press",
        models: Kinetostatics,
        links: [
            (name: "ground", ground: true, points: {{"O": (0.0, 0.0)}}),
            (name: "crank", points: {{"O": (0.0, 0.0), "A": ({R}, 0.0)}}),
            (name: "rod", points: {{"A": (0.0, 0.0), "C": ({L}, 0.0)}}),
            (name: "slider", points: {{"C": (0.0, 0.0), "S": (0.02, 0.0)}}),
        ],
        sliders: [(slider: "slider", point: "C", guide: "ground", through: "O", angle: 0.0)],
        driver: (link: "crank", speed: RadPerSecond(10.0), start: 0.0),
        branches: {{"C": Along}},
        forces: (point_forces: [(point: "S", force_n: (-{P}, 0.0))]),
    )"#
    );
    Kinematics::new(Mechanism::from_ron(&text).expect("scene")).expect("kinematics")
}

/// The press's closed form at φ: the rod's unit vector from A to C, the rod force
/// (compression positive), the guide's normal force on the slider, the balancing
/// torque.
fn press_closed_form(phi: f64) -> (Vec2, f64, f64, f64) {
    let a = Vec2::new(R * phi.cos(), R * phi.sin());
    let c = Vec2::new(a.x + (L * L - a.y * a.y).sqrt(), 0.0);
    let u = (c - a) / L;
    // The slider: P pushes back along −x, the rod pushes along u, the guide along y.
    let rod = P / u.x;
    let normal = -rod * u.y;
    // The crank: the rod pushes it at A with −rod·u; M_b balances that moment.
    let torque = rod * (a.x * u.y - a.y * u.x);
    (u, rod, normal, torque)
}

#[test]
fn a_pressed_slider_crank_gives_the_textbook_rod_force_and_balancing_torque() {
    let mut k = press();
    let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
    for i in 0..36 {
        let phi = 0.05 + i as f64 * std::f64::consts::TAU / 36.0;
        let fp = force_polygons(&mut k, &mut ks, phi).expect("polygons");
        let (u, rod, normal, torque) = press_closed_form(phi);
        let tol = 1e-9 * P / u.x.abs();
        // The rod is the group's first link; its inner reaction is the rod's push on
        // the slider at C: rod·u.
        let group = &fp.stages[0];
        let inner = group.inner.expect("an inner reaction");
        assert!(
            (inner.force - u * rod).norm() <= tol,
            "at {phi}: {:?}",
            inner.force
        );
        let guide = fp
            .joints
            .iter()
            .find(|j| matches!(j.joint, JointId::Prismatic(_)))
            .expect("the guide");
        assert!(
            (guide.force - Vec2::new(0.0, normal)).norm() <= tol,
            "at {phi}: {:?} vs {normal}",
            guide.force
        );
        assert!(
            guide.couple.abs() <= tol * L,
            "no couple on a slider through C"
        );
        assert!((fp.balancing_torque - torque).abs() <= tol * R, "at {phi}");
        // The crank pivot holds the crank against the rod's push −rod·u.
        let crank = fp.stages.last().expect("the crank");
        let pivot = crank.polygon.last().expect("the pivot's reaction");
        assert!((pivot.force - u * rod).norm() <= tol);
        for stage in &fp.stages {
            assert!(stage.closure_gap() <= 1e-9 * stage.largest());
        }
    }
}

#[test]
fn the_group_polygon_lists_the_load_first_known_and_the_outer_reactions_unknown() {
    let mut k = press();
    let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
    let fp = force_polygons(&mut k, &mut ks, 1.0).expect("polygons");
    assert!(matches!(fp.stages[0].stage, Stage::Group { index: 0, .. }));
    assert!(matches!(fp.stages[1].stage, Stage::Crank { .. }));
    let group = &fp.stages[0].polygon;
    // R on the rod from the crank (unknown), P (known), R on the slider from the
    // guide (direction known: normal to the guide).
    assert_eq!(group.len(), 3, "{group:?}");
    assert!(!group[0].magnitude_known && !group[0].direction_known);
    assert!(matches!(group[1].symbol, ForceSymbol::Load { .. }));
    assert!(group[1].magnitude_known && group[1].direction_known);
    assert!(!group[2].magnitude_known && group[2].direction_known);
    let m = k.mechanism();
    let names: Vec<String> = group.iter().map(|f| f.symbol.parts(m).text()).collect();
    assert_eq!(names, ["R_23", "P_S", "R_14"]);
}

/// Checks one position; false where the chain does not assemble or is at a dead
/// point of its input.
fn agrees_with_newton_euler(
    k: &mut Kinematics,
    ks: &mut Kinetostatics,
    phi: f64,
    who: &str,
) -> bool {
    let Ok(ne) = ks.at(k, phi) else { return false };
    let fp: ForcePolygons = match force_polygons(k, ks, phi) {
        Ok(fp) => fp,
        Err(LinkageError::Singular { .. }) => return false,
        Err(e) => panic!("{who} at {phi}: {e}"),
    };
    let scale = ne
        .joints
        .iter()
        .map(|j| Vec2::new(j.force.0, j.force.1).norm())
        .fold(0.0, f64::max);
    let size = k.mechanism().size_m;
    for stage in &fp.stages {
        assert!(
            stage.closure_gap() <= 1e-9 * stage.largest(),
            "{who} at {phi}: {:?} does not close: {} of {}",
            stage.stage,
            stage.closure_gap(),
            stage.largest()
        );
    }
    assert_eq!(fp.joints.len(), ne.joints.len());
    for (g, n) in fp.joints.iter().zip(&ne.joints) {
        let gap = (g.force - Vec2::new(n.force.0, n.force.1)).norm();
        assert!(
            gap <= 1e-9 * scale,
            "{who} at {phi}, {}: {gap} of {scale}",
            n.name
        );
        assert!(
            (g.couple - n.couple).abs() <= 1e-9 * scale * size,
            "{who}: {}",
            n.name
        );
    }
    let torque_gap = (fp.balancing_torque - ne.torque_newton_euler).abs();
    assert!(
        torque_gap <= 1e-9 * scale * size,
        "{who} at {phi}: torque {torque_gap}"
    );
    true
}

#[test]
fn every_scene_and_template_given_masses_closes_its_polygons_and_matches_newton_euler() {
    let scenes = common::SCENES
        .iter()
        .map(|f| (f.to_string(), common::scene_text(f)))
        .chain(
            common::TEMPLATES
                .iter()
                .map(|f| (f.to_string(), common::template_text(f))),
        );
    let mut checked = 0;
    for (file, text) in scenes {
        let m = common::loaded(Mechanism::from_ron(&text).expect("scene"));
        let mut k = Kinematics::new(m).expect("kinematics");
        if !k.has_closed_form() {
            continue;
        }
        let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
        let positions = common::cycle(&k, 72);
        let agreed = positions
            .iter()
            .filter(|&&phi| agrees_with_newton_euler(&mut k, &mut ks, phi, &file))
            .count();
        assert!(agreed >= 60, "{file}: only {agreed} of 72 positions");
        checked += 1;
    }
    assert!(checked >= 10, "only {checked} scenes have a closed form");
}

#[test]
fn a_chain_solved_by_newton_alone_is_told_it_has_no_force_polygons() {
    let text = common::triad::Triad::locking().scene(0.0);
    let m = common::loaded(Mechanism::from_ron(&text).expect("triad"));
    let mut k = Kinematics::new(m).expect("kinematics");
    assert!(!k.has_closed_form());
    let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
    let phi = k.mechanism().driver.start_rad + 0.2;
    let e = force_polygons(&mut k, &mut ks, phi).expect_err("no dyads");
    assert!(matches!(e, LinkageError::NotDecomposable(_)), "{e}");
}
