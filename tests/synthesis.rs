//! The synthesis window as a user works it: open it, pick a kind, Design, Open as
//! scene; the scene that opens meets the requirements (K and the swing, the stroke,
//! the precision points, the positions), checked by the solver's own analyses.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage::analysis::report;
use linkage::{Kinematics, Mechanism};
use linkage_lab::LinkageApp;

mod common;

fn click(h: &mut Harness<'static, LinkageApp>, label: &str) {
    h.get_by_label(label).click();
    h.run();
}

/// Designs the kind on tab `tab` with its default inputs and opens it.
fn design_and_open(h: &mut Harness<'static, LinkageApp>, tab: &str) -> Kinematics {
    click(h, tab);
    click(h, "Design");
    click(h, "Open as scene");
    if h.state().state.pending_open.is_some() {
        click(h, "Drop the edits and open");
    }
    let session = &h.state().state.session;
    assert!(session.is_dirty(), "a design is unsaved work");
    Kinematics::new(Mechanism::from_scene(session.scene()).expect("valid")).expect("solves")
}

#[test]
fn each_design_opens_as_a_scene_that_meets_its_requirements() {
    // Rendered through wgpu: the test keeps a picture of the window with a design.
    let mut h = common::app_harness();
    h.run();
    h.run();
    click(&mut h, "Synthesis…");
    assert!(h.state().state.synthesis.is_some(), "the window is open");
    click(&mut h, "Design");
    h.snapshot("synthesis_crank_rocker");

    // Crank-rocker: rocker 600 mm, swing 16.6°, K 1.3.
    let mut k = design_and_open(&mut h, "crank-rocker");
    assert_eq!(
        h.state().state.session.scene().name,
        "Synthesized crank-rocker"
    );
    let r = report(&mut k).expect("report");
    assert!(
        (r.time_ratio.expect("K") - 1.3).abs() < 1e-6,
        "{:?}",
        r.time_ratio
    );
    let swing = r.swings_rad["rocker"].to_degrees();
    assert!((swing - 16.6).abs() < 1e-6, "{swing}");

    // Die cutter: stroke 50 mm, K 1.3.
    let mut k = design_and_open(&mut h, "die cutter");
    let r = report(&mut k).expect("report");
    assert!(
        (r.time_ratio.expect("K") - 1.3).abs() < 1e-6,
        "{:?}",
        r.time_ratio
    );
    let stroke = r.strokes_m.values().next().expect("a slider");
    assert!((stroke - 0.05).abs() < 1e-9, "{stroke}");

    // Function: the rocker's line CD at each precision point's crank angle.
    let mut k = design_and_open(&mut h, "function");
    let inputs = h
        .state()
        .state
        .synthesis
        .as_ref()
        .expect("open")
        .inputs
        .clone();
    let (c, d) = {
        let m = k.mechanism();
        (
            m.point_index("C").expect("C"),
            m.point_index("D").expect("D"),
        )
    };
    let crank_flip = k.mechanism().driver.start_rad - 34.0192f64.to_radians();
    for line in inputs.function_points.lines() {
        let v: Vec<f64> = line
            .split(',')
            .map(|x| x.trim().parse().expect("number"))
            .collect();
        let s = k.solve(v[0].to_radians() + crank_flip).expect("assembles");
        let cd = s.points[c].position - s.points[d].position;
        // The rocker's angle, up to the half turn of a rocker that points back.
        let off = (cd.y.atan2(cd.x) - v[1].to_radians()).rem_euclid(std::f64::consts::PI);
        let off = off.min(std::f64::consts::PI - off);
        assert!(off < 1e-9, "at {} deg: {off} rad", v[0]);
    }

    // Three positions: the coupler point P is at the first position as it opens.
    let mut k = design_and_open(&mut h, "three positions");
    let p = k.mechanism().point_index("P").expect("P");
    let at = k.solve(0.0).expect("assembles").points[p].position;
    assert!(at.norm() < 1e-12, "{at:?}");
    assert!(
        h.query_by_label("pole P12").is_some(),
        "the poles are listed"
    );

    // A stroke beyond 2L is refused with its reason, and nothing opens.
    click(&mut h, "die cutter");
    h.state_mut()
        .state
        .synthesis
        .as_mut()
        .expect("open")
        .inputs
        .die[0] = 2000.0;
    h.run();
    click(&mut h, "Design");
    assert!(
        h.query_all_by_label_contains("stroke H").count() > 1,
        "the refusal names the stroke"
    );
    assert!(h.query_by_label("Open as scene").is_none());
}
