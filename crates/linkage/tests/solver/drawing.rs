//! A drawing becomes the same mechanism as the scene it was drawn from: each template
//! is solved at its start, redrawn as a [`Drawing`] (points at their world places, no
//! branches, no link coordinates), and the scene the drawing makes must report the
//! same Grashof class, time ratio, swings and strokes (to 1e-9) as the template.

use linkage::analysis::{Report, report};
use linkage::drawing::{Drawing, DrawingLink, DrawingPoint, DrawingProblem, NotDrawable};
use linkage::scene::{Branch, Speed};
use linkage::{Kinematics, Mechanism, SceneFile, Vec2};

fn template(name: &str) -> SceneFile {
    let path = format!(
        "{}/../../assets/templates/{name}.ron",
        env!("CARGO_MANIFEST_DIR")
    );
    SceneFile::parse(&std::fs::read_to_string(path).expect("template")).expect("parses")
}

/// The scene as drawn at its start (`Drawing::from_pose`): world places, links by
/// their points, slider blocks as sliders on their guides; no link coordinates and
/// no branches.
fn drawn(scene: &SceneFile) -> Drawing {
    let m = Mechanism::from_scene(scene).expect("valid");
    let mut k = Kinematics::new(m.clone()).expect("solvable");
    let pose = k.solve(m.driver.start_rad).expect("assembles at start");
    Drawing::from_pose(scene, &m, &pose).expect("drawable")
}

fn report_of(scene: &SceneFile) -> Report {
    let mut k = Kinematics::new(Mechanism::from_scene(scene).expect("valid")).expect("solvable");
    report(&mut k).expect("report")
}

fn assert_close(what: &str, a: f64, b: f64) {
    assert!(
        (a - b).abs() <= 1e-9 * a.abs().max(1.0),
        "{what}: {a} vs {b}"
    );
}

/// The drawing mirrored in the x-axis: every dyad on its other branch.
fn mirrored(mut drawing: Drawing) -> Drawing {
    for p in &mut drawing.points {
        p.at.y = -p.at.y;
    }
    for s in &mut drawing.sliders {
        s.angle_rad = -s.angle_rad;
    }
    drawing
}

fn assert_same_mechanism(name: &str) {
    let original = template(name);
    assert_same_motion(name, &original, &drawn(&original));
    // Mirrored, each dyad closes on its other branch, which must be read off the
    // drawing; the motion is the mirror image: the same swings, strokes and K.
    let mirror = mirrored(drawn(&original))
        .to_scene()
        .unwrap_or_else(|e| panic!("{name} mirrored: {e}"));
    let (a, b) = (report_of(&original), report_of(&mirror));
    for (point, branch) in &original.branches {
        if let Some(side) = left_of(branch) {
            assert_eq!(
                left_of(&mirror.branches[point]),
                Some((side.0, side.1, !side.2)),
                "{name} mirrored: branch at {point}"
            );
        }
    }
    for (x, y) in a
        .swings_rad
        .values()
        .zip(b.swings_rad.values())
        .chain(a.strokes_m.values().zip(b.strokes_m.values()))
    {
        assert_close(&format!("{name} mirrored: swing or stroke"), *x, *y);
    }
    if let (Some(ka), Some(kb)) = (a.time_ratio, b.time_ratio) {
        assert_close(&format!("{name} mirrored: K"), ka, kb);
    }
}

/// An RRR branch as (first end, second end, left of first -> second) with the ends in
/// name order: `Left(a, c)` and `Right(c, a)` say the same.
fn left_of(b: &Branch) -> Option<(String, String, bool)> {
    let (a, c, left) = match b {
        Branch::Left(a, c) => (a, c, true),
        Branch::Right(a, c) => (a, c, false),
        _ => return None,
    };
    Some(if a < c {
        (a.clone(), c.clone(), left)
    } else {
        (c.clone(), a.clone(), !left)
    })
}

fn assert_same_motion(name: &str, original: &SceneFile, drawing: &Drawing) {
    let scene = drawing.to_scene().unwrap_or_else(|e| panic!("{name}: {e}"));
    // The scene it makes is a scene file like any other: it round-trips through RON.
    let text = scene.to_ron().expect("writes");
    assert_eq!(SceneFile::parse(&text).expect("reads"), scene);
    let (a, b) = (report_of(original), report_of(&scene));
    assert_eq!(
        a.grashof.as_ref().map(|g| g.class),
        b.grashof.as_ref().map(|g| g.class),
        "{name}: Grashof class"
    );
    assert_eq!(a.time_ratio.is_some(), b.time_ratio.is_some(), "{name}: K");
    if let (Some(ka), Some(kb)) = (a.time_ratio, b.time_ratio) {
        // At a toggle (the die cutter's) the output's rate vanishes to third order, so
        // its root, and K with it, is known to about (1e-16)^(1/3) rad only.
        let tolerance = if a.toggles.is_empty() { 1e-9 } else { 1e-5 };
        assert!((ka - kb).abs() <= tolerance * ka, "{name}: K {ka} vs {kb}");
    }
    assert_eq!(a.swings_rad.len(), b.swings_rad.len(), "{name}: rockers");
    for (x, y) in a.swings_rad.values().zip(b.swings_rad.values()) {
        assert_close(&format!("{name}: swing"), *x, *y);
    }
    assert_eq!(a.strokes_m.len(), b.strokes_m.len(), "{name}: sliders");
    for (x, y) in a.strokes_m.values().zip(b.strokes_m.values()) {
        assert_close(&format!("{name}: stroke"), *x, *y);
    }
    assert_eq!(a.assembly_range_rad.len(), b.assembly_range_rad.len());
    for (x, y) in a.assembly_range_rad.iter().zip(&b.assembly_range_rad) {
        assert_close(&format!("{name}: range start"), x[0], y[0]);
        assert_close(&format!("{name}: range end"), x[1], y[1]);
    }
}

#[test]
fn a_drawn_four_bar_is_the_template_four_bar() {
    assert_same_mechanism("four_bar");
}

#[test]
fn a_drawn_slider_crank_is_the_template_slider_crank() {
    assert_same_mechanism("slider_crank");
}

#[test]
fn drawn_six_bars_and_the_inverted_slider_crank_are_their_templates() {
    for name in [
        "watt_six_bar",
        "stephenson_six_bar",
        "inverted_slider_crank",
    ] {
        assert_same_mechanism(name);
    }
}

#[test]
fn an_unfinished_drawing_says_what_is_missing() {
    let mut drawing = Drawing::new("draft");
    assert_eq!(drawing.to_scene(), Err(DrawingProblem::NoLinks));
    let point = |name: &str, x: f64, y: f64, ground: bool| DrawingPoint {
        name: name.into(),
        at: Vec2::new(x, y),
        ground,
    };
    drawing.points = vec![
        point("A", 0.0, 0.0, true),
        point("B", 0.1, 0.0, false),
        point("C", 0.3, 0.2, false),
        point("D", 0.3, 0.0, true),
    ];
    let link = DrawingLink::new;
    drawing.links = vec![link("crank", vec![0, 1]), link("coupler", vec![1, 2])];
    let Err(DrawingProblem::Mobility(m)) = drawing.to_scene() else {
        panic!("open chain")
    };
    assert_eq!(m.dof(), 2);
    assert!(
        DrawingProblem::Mobility(m)
            .to_string()
            .starts_with("2 degrees of freedom")
    );
    drawing.links.push(link("rocker", vec![2, 3]));
    assert_eq!(drawing.to_scene(), Err(DrawingProblem::NoDriver));
    drawing.driver = Some(1);
    assert_eq!(
        drawing.to_scene(),
        Err(DrawingProblem::DriverNotGrounded("coupler".into()))
    );
    drawing.driver = Some(0);
    drawing.speed = Speed::Rpm(30.0);
    let scene = drawing.to_scene().expect("a four-bar");
    assert_eq!(scene.branches.len(), 1);
    // A brace across the frame locks it.
    drawing.links.push(link("brace", vec![1, 3]));
    let Err(DrawingProblem::Mobility(m)) = drawing.to_scene() else {
        panic!("locked")
    };
    assert_eq!(m.dof(), 0);
}

/// The die cutter's kinetostatics (its 120 kg die on the vertical guide, gravity, and
/// the paper's 2 MN cutting force on the working stroke) drawn: the same input torque
/// at every 15 degrees, to 1e-9.
#[test]
fn a_drawn_die_cutter_needs_the_same_input_torque() {
    use linkage::kinetostatics::Kinetostatics;
    let path = format!(
        "{}/../../assets/scenes/die_cutter.ron",
        env!("CARGO_MANIFEST_DIR")
    );
    let original =
        SceneFile::parse(&std::fs::read_to_string(path).expect("scene")).expect("parses");
    assert_eq!(original.forces.gravity, Some((0.0, -9.81)));
    assert!(
        !original.forces.point_forces.is_empty(),
        "the cutting force"
    );
    let drawn_scene = drawn(&original).to_scene().expect("a mechanism");
    let torque = |scene: &SceneFile, x: f64| {
        let mut k = Kinematics::new(Mechanism::from_scene(scene).expect("valid")).expect("solves");
        let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
        ks.at(&mut k, x).expect("solves there").torque_newton_euler
    };
    let start = original.driver.start.to_radians();
    for step in 1..24 {
        let x = f64::from(step) * 15f64.to_radians();
        let (a, b) = (torque(&original, start + x), torque(&drawn_scene, x));
        assert!(
            (a - b).abs() <= 1e-9 * a.abs().max(1.0),
            "at +{} deg: {a} vs {b} N m",
            step * 15
        );
    }
}

/// A drawn link's mass sits at the mean of its points with a uniform body's inertia:
/// a bar m L²/12, an equilateral plate m a²/12 (the textbook values).
#[test]
fn drawn_masses_are_uniform_bodies() {
    let point = |name: &str, x: f64, y: f64, ground: bool| DrawingPoint {
        name: name.into(),
        at: Vec2::new(x, y),
        ground,
    };
    let h = 0.1 * 3f64.sqrt() / 2.0;
    let mut drawing = Drawing::new("masses");
    drawing.points = vec![
        point("A", 0.0, 0.0, true),
        point("B", 0.0, 0.1, false),
        point("C", 0.1, 0.1, false),
        point("E", 0.05, 0.1 + h, false),
        point("D", 0.3, 0.0, true),
    ];
    let link = |name: &str, points: Vec<usize>, mass_kg| DrawingLink {
        mass_kg,
        ..DrawingLink::new(name, points)
    };
    drawing.links = vec![
        link("crank", vec![0, 1], Some(2.0)),
        link("plate", vec![1, 2, 3], Some(3.0)),
        link("rocker", vec![2, 4], None),
    ];
    drawing.driver = Some(0);
    drawing.models = linkage::scene::Models::Kinetostatics;
    let scene = drawing.to_scene().expect("a four-bar with a coupler plate");
    let crank = &scene.links[1];
    assert_eq!(crank.mass, Some(2.0));
    assert_close(
        "crank inertia",
        crank.inertia.expect("inertia"),
        2.0 * 0.01 / 12.0,
    );
    let (cx, cy) = crank.centroid.expect("centroid");
    assert_close("crank centroid x", cx, 0.0);
    assert_close("crank centroid y", cy, 50.0);
    let plate = &scene.links[2];
    assert_close(
        "plate inertia",
        plate.inertia.expect("inertia"),
        3.0 * 0.01 / 12.0,
    );
    assert_eq!(scene.links[3].mass, None);
    // A link's own centroid (world, m) and inertia go through as they are (the
    // scene writes millimetres, and link coordinates are the world's at input 0).
    drawing.links[0].centroid = Some(Vec2::new(0.01, 0.03));
    drawing.links[0].inertia_kg_m2 = Some(0.5);
    let scene = drawing.to_scene().expect("still a four-bar");
    let (cx, cy) = scene.links[1].centroid.expect("centroid");
    assert_close("own centroid x", cx, 10.0);
    assert_close("own centroid y", cy, 30.0);
    assert_eq!(scene.links[1].inertia, Some(0.5));
}

/// A chain with no dyad decomposition (a triad six-bar: a floating plate held by
/// three binary links, one to the crank and two to ground) drawn: the scene starts
/// Newton from the drawing itself, assembles as drawn, and moves.
#[test]
fn a_drawn_triad_six_bar_solves_by_newton_from_the_drawing() {
    let point = |name: &str, x: f64, y: f64, ground: bool| DrawingPoint {
        name: name.into(),
        at: Vec2::new(x, y),
        ground,
    };
    let link = DrawingLink::new;
    let mut drawing = Drawing::new("triad");
    drawing.points = vec![
        point("A", 0.0, 0.0, true),
        point("B", 0.05, 0.0, false),
        point("P", 0.15, 0.2, false),
        point("Q", 0.35, 0.2, false),
        point("R", 0.25, 0.05, false),
        point("D", 0.45, 0.0, true),
        point("G", 0.3, -0.15, true),
    ];
    drawing.links = vec![
        link("crank", vec![0, 1]),
        link("plate", vec![2, 3, 4]),
        link("to crank", vec![1, 2]),
        link("to D", vec![3, 5]),
        link("to G", vec![4, 6]),
    ];
    drawing.driver = Some(0);
    assert_eq!(drawing.mobility().dof(), 1);
    let scene = drawing.to_scene().expect("a triad six-bar");
    assert!(
        scene.branches.is_empty() && scene.guess.len() == 5,
        "{:?}",
        scene.guess
    );
    let mut k = Kinematics::new(Mechanism::from_scene(&scene).expect("valid")).expect("solves");
    assert_eq!(k.path(), linkage::PathKind::Newton);
    let q = k.mechanism().point_index("Q").expect("Q");
    let moved = k
        .solve(5f64.to_radians())
        .expect("assembles 5 deg on")
        .points[q]
        .position;
    assert!(
        (moved - Vec2::new(0.35, 0.2)).norm() > 1e-4,
        "the plate moves"
    );
}

/// Every shipped scene either becomes a drawing that makes the same mechanism (the
/// same report), or is refused with what the drawing would lose.
#[test]
fn every_shipped_scene_is_drawn_as_itself_or_refused_with_the_reason() {
    let dir = format!("{}/../../assets/scenes", env!("CARGO_MANIFEST_DIR"));
    let mut drawn_ok = Vec::new();
    for entry in std::fs::read_dir(dir).expect("scenes") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|e| e != "ron") {
            continue;
        }
        let name = path
            .file_stem()
            .expect("name")
            .to_string_lossy()
            .to_string();
        let scene =
            SceneFile::parse(&std::fs::read_to_string(&path).expect("scene")).expect("parses");
        let m = Mechanism::from_scene(&scene).expect("valid");
        let pose = Kinematics::new(m.clone())
            .expect("solves")
            .solve(m.driver.start_rad)
            .expect("assembles");
        match Drawing::from_pose(&scene, &m, &pose) {
            Ok(drawing) => {
                assert_same_motion(&name, &scene, &drawing);
                drawn_ok.push(name);
            }
            Err(NotDrawable::CamJoint(joint)) => {
                assert!(m.cams.iter().any(|c| c.name == joint), "{name}: {joint}");
            }
            Err(why) => {
                let f = &scene.forces;
                let lost = !(f.torques.is_empty() && f.stops.is_empty());
                assert!(why == NotDrawable::Forces && lost, "{name}: {why}");
            }
        }
    }
    drawn_ok.sort();
    assert_eq!(
        drawn_ok,
        [
            "die_cutter",
            "die_cutter_as_printed",
            "paper_cup_feed",
            "quick_return",
            "slider_crank"
        ]
    );
}

/// The gravity flipper without its end stop (a drawing carries no stops) drawn in a
/// pose other than its start: the same reduced model, J(q) and M(q), at every 5
/// degrees of its range, to 1e-9. That holds only if the drawing carries the spring
/// (with the free length it had at the start), the workpiece's point force, gravity,
/// and each link's own centroid and inertia.
#[test]
fn a_drawn_flipper_has_the_same_reduced_model() {
    use linkage::dynamics::ForceModel;
    let path = format!(
        "{}/../../assets/scenes/gravity_flipper.ron",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut original =
        SceneFile::parse(&std::fs::read_to_string(path).expect("scene")).expect("parses");
    let m = Mechanism::from_scene(&original).expect("valid");
    assert_eq!(
        Drawing::from_pose(
            &original,
            &m,
            &Kinematics::new(m.clone())
                .expect("k")
                .solve(m.driver.start_rad)
                .expect("pose")
        ),
        Err(NotDrawable::Forces),
        "its stop is refused"
    );
    original.forces.stops.clear();
    let m = Mechanism::from_scene(&original).expect("valid");
    let mut k = Kinematics::new(m.clone()).expect("solvable");
    let elsewhere = m.driver.start_rad - 10f64.to_radians();
    let pose = k.solve(elsewhere).expect("assembles");
    let drawing = Drawing::from_pose(&original, &m, &pose).expect("drawable");
    assert!(
        drawing.springs[0].free_length_m.is_some(),
        "the start's free length"
    );
    let drawn_scene = drawing.to_scene().expect("a mechanism");
    let reduced = |scene: &SceneFile, at: &[f64]| -> Vec<[f64; 2]> {
        let mut k = Kinematics::new(Mechanism::from_scene(scene).expect("valid")).expect("k");
        let s0 = k.solve(k.mechanism().driver.start_rad).expect("start");
        let model = ForceModel::new(k.mechanism(), &s0).expect("model");
        at.iter()
            .map(|&x| {
                let mut unit = k.empty_solution();
                k.solve_into(x, 1.0, &mut unit).expect("solves");
                let r = model.reduce(&unit, 0.0);
                [r.j, r.moment()]
            })
            .collect()
    };
    // Every 5 degrees of the original's range; the drawing's input 0 is `elsewhere`.
    let inputs: Vec<f64> = (8..=22).map(|i| f64::from(i * 5).to_radians()).collect();
    let a = reduced(&original, &inputs);
    let shifted: Vec<f64> = inputs.iter().map(|x| x - elsewhere).collect();
    let b = reduced(&drawn_scene, &shifted);
    for (i, (a, b)) in a.iter().zip(&b).enumerate() {
        assert_close(&format!("J at step {i}"), a[0], b[0]);
        assert_close(&format!("M at step {i}"), a[1], b[1]);
    }
}
