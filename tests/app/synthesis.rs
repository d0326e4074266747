//! The synthesis window as a user works it: open it, pick a kind, Design, Open as
//! scene; the scene that opens meets the requirements (K and the swing, the stroke,
//! the precision points, the positions), checked by the solver's own analyses.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage::analysis::report;
use linkage::{Kinematics, Mechanism};
use linkage_lab::LinkageApp;

use crate::common;

use common::click_label as click;

/// Designs the kind on tab `tab` with its default inputs and opens it.
fn design_and_open(h: &mut Harness<'static, LinkageApp>, tab: &str) -> Kinematics {
    click(h, tab);
    click(h, "Design");
    click(h, "Open as scene");
    if h.state().state.commands.waiting.is_some() {
        click(h, "Drop the edits and open");
    }
    let session = &h.state().state.session;
    // Opened as it came out of the synthesis: not "(edited)", nothing to ask.
    assert!(!session.is_dirty(), "a fresh design is marked edited");
    Kinematics::new(Mechanism::from_scene(session.scene()).expect("valid")).expect("solves")
}

#[test]
fn each_design_opens_as_a_scene_that_meets_its_requirements() {
    // Rendered through wgpu: the test keeps a picture of the window with a design.
    let mut h = common::app_harness();
    h.run();
    h.run();
    click(&mut h, "Synthesis…");
    assert!(h.state().panels.synthesis.is_open(), "the window is open");
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
    // The paper's loads come from its scene file; the words are the app's, naming
    // the inputs typed and no command line.
    let scene = h.state().state.session.scene().clone();
    assert_eq!(scene.name, "Die cutter (H = 50 mm, K = 1.3, L = 600 mm)");
    let die = scene
        .links
        .iter()
        .find(|l| l.name == "die")
        .expect("the die");
    assert_eq!(die.mass, Some(120.0));
    assert_eq!(scene.forces.point_forces.len(), 1);
    for words in std::iter::once(&scene.description).chain(&scene.notes) {
        assert!(
            !words.contains("linkage ") && !words.contains("--"),
            "{words}"
        );
    }

    // Function: the rocker's line CD at each precision point's crank angle.
    let mut k = design_and_open(&mut h, "function");
    let inputs = h
        .state()
        .panels
        .synthesis
        .view()
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
    let mut k = design_and_open(&mut h, "positions");
    let p = k.mechanism().point_index("P").expect("P");
    let at = k.solve(0.0).expect("assembles").points[p].position;
    assert!(at.norm() < 1e-12, "{at:?}");
    assert!(
        h.query_by_label("pole P12").is_some(),
        "the poles are listed"
    );

    // A stroke beyond 2L is refused with its reason, and nothing opens.
    click(&mut h, "die cutter");
    common::synthesis_inputs(&mut h).die[0] = 2000.0;
    h.run();
    click(&mut h, "Design");
    assert!(
        h.query_all_by_label_contains("stroke H").count() > 1,
        "the refusal names the stroke"
    );
    assert!(h.query_by_label("Open as scene").is_none());
}

/// Five positions of a crank-rocker's coupler (A0 at the origin, B0 at (400, 50)
/// mm): the Burmester points hold the known fixed pivots, and the pair of them
/// chosen moves the body through all five (the design's own check, 1e-9 mm); the
/// construction is drawn. A function generator from y = log10 x shows its
/// structural error over the range.
#[test]
fn five_positions_and_a_function_show_their_constructions() {
    let mut h = common::app_harness();
    h.run();
    h.run();
    common::synthesis_tab(&mut h, "positions");
    let five = "112.763114, 41.042417, 55.592249\n41.042417, 112.763114, 39.007115\n\
                -60.000000, 103.923048, 33.671856\n-118.176930, 20.837781, 37.449441\n\
                -77.134513, -91.925333, 53.256293\n";
    let inputs = common::synthesis_inputs(&mut h);
    inputs.poses = five.into();
    // The poses are rounded to 1e-6 mm: the known pivots are found to about that.
    let design = linkage_lab::synthesis::design(inputs).expect("designs");
    let linkage_lab::synthesis::Figure::Construction(c) = &design.figure else {
        panic!("no construction");
    };
    let index = |x: f64, y: f64| {
        c.burmester
            .iter()
            .position(|b| (b[0] - x).hypot(b[1] - y) < 1e-3)
            .unwrap_or_else(|| panic!("({x}, {y}) not among {:?}", c.burmester))
    };
    let pair = [index(0.0, 0.0) + 1, index(400.0, 50.0) + 1];
    common::synthesis_inputs(&mut h).motion.pair = pair;
    // A frame to lay the window out for five positions before clicking in it.
    h.run();
    click(&mut h, "Design");
    let view = h.state().panels.synthesis.view().expect("open");
    let Some(Ok(design)) = &view.result else {
        panic!("{:?}", view.result);
    };
    let miss = &design.table.last().expect("rows").1;
    let mm: f64 = miss
        .split(' ')
        .next()
        .expect("number")
        .parse()
        .expect("a number");
    assert!(mm < 1e-6, "{miss}");
    h.snapshot("synthesis_five_positions");

    click(&mut h, "function");
    click(&mut h, "a function");
    click(&mut h, "Design");
    let view = h.state().panels.synthesis.view().expect("open");
    let Some(Ok(design)) = &view.result else {
        panic!("{:?}", view.result);
    };
    assert!(matches!(
        design.figure,
        linkage_lab::synthesis::Figure::ErrorCurve(_)
    ));
    h.snapshot("synthesis_function_error");
}
