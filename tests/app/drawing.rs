//! Building a mechanism from nothing, as a user does: New… > Empty, then clicks on
//! the canvas with the drawing tools. The drawn four-bar and slider-crank must report
//! what the same mechanisms written by hand as scene files report (Grashof class, K,
//! swings and strokes to 1e-9); undo goes back to the empty drawing and redo to the
//! end, exactly.

use eframe::egui;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage::analysis::{Report, report};
use linkage::{Kinematics, Mechanism, SceneFile};
use linkage_lab::LinkageApp;
use linkage_lab::session::SceneEdit;
use linkage_lab::ui::control_map::ControlKind;

use crate::common;
use common::click;
use common::click_control;

fn harness() -> Harness<'static, LinkageApp> {
    common::stateful_harness()
}

/// Clicks the canvas at world place `(x, y)` (mm).
fn click_mm(h: &mut Harness<'static, LinkageApp>, x: f64, y: f64) {
    let st = &h.state().state;
    let [x0, y0, x1, y1] = st.controls.view.expect("the canvas is drawn");
    let rect = egui::Rect::from_min_max(egui::pos2(x0, y0), egui::pos2(x1, y1));
    let at = h
        .state()
        .panels
        .viewport
        .camera
        .to_screen([x * 1e-3, y * 1e-3], rect);
    click(h, at);
}

fn start_drawing(h: &mut Harness<'static, LinkageApp>) {
    click_control(h, ControlKind::FileButton, "New…");
    h.run();
    click_control(h, ControlKind::TemplateItem, "Empty: draw your own");
    assert!(
        h.state().state.drawing.is_some(),
        "the drawing tools are out"
    );
}

fn tool(h: &mut Harness<'static, LinkageApp>, label: &str) {
    click_control(h, ControlKind::DrawTool, label);
}

fn report_of(scene: &SceneFile) -> Report {
    let mut k = Kinematics::new(Mechanism::from_scene(scene).expect("valid")).expect("solves");
    report(&mut k).expect("report")
}

fn assert_close(what: &str, a: f64, b: f64) {
    assert!(
        (a - b).abs() <= 1e-9 * a.abs().max(1.0),
        "{what}: {a} vs {b}"
    );
}

/// The app's scene (the drawing) reports what `by_hand` does.
fn assert_reports_as(h: &Harness<'static, LinkageApp>, by_hand: &str) {
    let st = &h.state().state;
    let b = st.drawing.as_ref().expect("drawing");
    assert_eq!(b.problem, None, "the drawing is a mechanism");
    let hand = SceneFile::parse(by_hand).expect("the hand-written scene parses");
    let (drawn, hand) = (report_of(st.session.scene()), report_of(&hand));
    assert_eq!(
        drawn.grashof.as_ref().map(|g| g.class),
        hand.grashof.as_ref().map(|g| g.class)
    );
    let (kd, kh) = (drawn.time_ratio.expect("K"), hand.time_ratio.expect("K"));
    assert_close("K", kd, kh);
    assert_eq!(drawn.swings_rad.len(), hand.swings_rad.len());
    for (a, b) in drawn.swings_rad.values().zip(hand.swings_rad.values()) {
        assert_close("swing", *a, *b);
    }
    assert_eq!(drawn.strokes_m.len(), hand.strokes_m.len());
    for (a, b) in drawn.strokes_m.values().zip(hand.strokes_m.values()) {
        assert_close("stroke", *a, *b);
    }
}

/// Undo to the empty drawing, then redo to the end: the same drawing and scene.
fn assert_undo_redo_exact(h: &mut Harness<'static, LinkageApp>) {
    let st = &h.state().state;
    let (drawing, scene) = (
        st.drawing.as_ref().expect("drawing").drawing().clone(),
        st.session.scene().clone(),
    );
    let mut steps = 0;
    while h
        .state()
        .state
        .drawing
        .as_ref()
        .is_some_and(|b| b.can_undo())
    {
        click_control(h, ControlKind::History, "Undo");
        steps += 1;
        assert!(steps < 100, "undo ends");
    }
    let b = h.state().state.drawing.as_ref().expect("drawing");
    assert!(b.drawing().points.is_empty() && b.drawing().links.is_empty());
    for _ in 0..steps {
        click_control(h, ControlKind::History, "Redo");
    }
    let st = &h.state().state;
    assert_eq!(st.drawing.as_ref().expect("drawing").drawing(), &drawing);
    assert_eq!(st.session.scene(), &scene);
}

/// Draws the four-bar of the tests: pivots A and B, the crank A-C, the coupler C-D
/// and the rocker D-B.
fn draw_four_bar(h: &mut Harness<'static, LinkageApp>) {
    let h = &mut *h;
    start_drawing(h);
    tool(h, "Pivot");
    click_mm(h, 0.0, 0.0);
    click_mm(h, 300.0, 0.0);
    tool(h, "Link");
    click_mm(h, 0.0, 0.0);
    click_mm(h, 0.0, 50.0);
    click_mm(h, 0.0, 50.0);
    click_mm(h, 200.0, 200.0);
    click_mm(h, 200.0, 200.0);
    click_mm(h, 300.0, 0.0);
    let problem = h
        .state()
        .state
        .drawing
        .as_ref()
        .and_then(|b| b.problem.clone());
    assert_eq!(
        problem.map(|p| p.to_string()).as_deref(),
        Some("1 degree of freedom: pick the input link (Driver)")
    );
    tool(h, "Driver");
    click_mm(h, 0.0, 25.0);
}

#[test]
fn a_four_bar_drawn_by_pointer_reports_as_its_scene_file() {
    let mut h = harness();
    draw_four_bar(&mut h);
    // The same four-bar by hand: link coordinates, lengths worked out, the crank
    // upright at the start, the branch named.
    let rocker = (100.0f64 * 100.0 + 200.0 * 200.0).sqrt();
    let coupler = (200.0f64 * 200.0 + 150.0 * 150.0).sqrt();
    let by_hand = format!(
        r#"Scene(
            name: "four-bar by hand", models: Kinematics, length_unit: Millimetre,
            links: [
                (name: "ground", ground: true, points: {{"A": (0.0, 0.0), "D": (300.0, 0.0)}}),
                (name: "crank", points: {{"A": (0.0, 0.0), "B": (50.0, 0.0)}}),
                (name: "coupler", points: {{"B": (0.0, 0.0), "C": ({coupler}, 0.0)}}),
                (name: "rocker", points: {{"D": (0.0, 0.0), "C": ({rocker}, 0.0)}}),
            ],
            driver: (link: "crank", speed: Rpm(60.0), start: 90.0),
            branches: {{"C": Left("B", "D")}},
            output: Some("rocker"),
        )"#
    );
    assert_reports_as(&h, &by_hand);
    assert_undo_redo_exact(&mut h);
    // Done: back to the viewer over the drawn mechanism, unsaved.
    tool(&mut h, "Done");
    let st = &h.state().state;
    assert!(st.drawing.is_none());
    assert!(st.session.is_dirty(), "a drawing is unsaved work");
}

#[test]
fn a_slider_crank_drawn_by_pointer_reports_as_its_scene_file() {
    let mut h = harness();
    start_drawing(&mut h);
    tool(&mut h, "Pivot");
    click_mm(&mut h, 0.0, 0.0);
    tool(&mut h, "Link");
    click_mm(&mut h, 0.0, 0.0);
    click_mm(&mut h, 0.0, 50.0);
    click_mm(&mut h, 0.0, 50.0);
    click_mm(&mut h, 200.0, -30.0);
    tool(&mut h, "Slider");
    click_mm(&mut h, 200.0, -30.0);
    tool(&mut h, "Driver");
    click_mm(&mut h, 0.0, 25.0);
    let rod = (200.0f64 * 200.0 + 80.0 * 80.0).sqrt();
    let by_hand = format!(
        r#"Scene(
            name: "slider-crank by hand", models: Kinematics, length_unit: Millimetre,
            links: [
                (name: "ground", ground: true, points: {{"A": (0.0, 0.0), "G": (0.0, -30.0)}}),
                (name: "crank", points: {{"A": (0.0, 0.0), "B": (50.0, 0.0)}}),
                (name: "rod", points: {{"B": (0.0, 0.0), "C": ({rod}, 0.0)}}),
                (name: "slider", points: {{"C": (0.0, 0.0)}}),
            ],
            sliders: [(slider: "slider", point: "C", guide: "ground", through: "G", angle: 0.0)],
            driver: (link: "crank", speed: Rpm(60.0), start: 90.0),
            branches: {{"C": Along}},
            output: Some("slider"),
        )"#
    );
    // The hand-written scene is the drawing: C starts at (200, -30) mm.
    let hand = SceneFile::parse(&by_hand).expect("parses");
    let mut k = Kinematics::new(Mechanism::from_scene(&hand).expect("valid")).expect("solves");
    let c = k.mechanism().point_index("C").expect("C");
    let at = k.solve(90f64.to_radians()).expect("assembles").points[c].position;
    assert!(
        (at.x - 0.2).abs() < 1e-12 && (at.y + 0.03).abs() < 1e-12,
        "{at:?}"
    );
    assert_reports_as(&h, &by_hand);
    assert_undo_redo_exact(&mut h);
}

/// A link renamed in the side panel (click its name, type, Enter) and picked as the
/// output: the scene and its report use the new name; a taken name is refused.
#[test]
fn a_drawn_link_is_renamed_and_made_the_output() {
    let mut h = harness();
    draw_four_bar(&mut h);
    let rename = |h: &mut Harness<'static, LinkageApp>, from: &str, to: &str| {
        h.get_by_role_and_label(Role::Button, from).click();
        h.run();
        h.run();
        h.event(egui::Event::Key {
            key: egui::Key::A,
            physical_key: None,
            pressed: true,
            repeat: false,
            modifiers: egui::Modifiers::COMMAND,
        });
        h.event(egui::Event::Text(to.into()));
        h.event(egui::Event::Key {
            key: egui::Key::Enter,
            physical_key: None,
            pressed: true,
            repeat: false,
            modifiers: egui::Modifiers::default(),
        });
        h.run();
        h.run();
    };
    rename(&mut h, "link 3", "rocker");
    let scene = h.state().state.session.scene().clone();
    assert!(
        scene.links.iter().any(|l| l.name == "rocker"),
        "{:?}",
        scene.links
    );
    rename(&mut h, "link 1", "rocker");
    let b = h.state().state.drawing.as_ref().expect("drawing");
    assert_eq!(
        b.refusal.as_ref().map(|r| r.to_string()).as_deref(),
        Some("the name rocker is taken")
    );
    assert_eq!(b.drawing().links[0].name, "link 1");
    // The rocker's row is the third.
    h.get_all_by_label("output")
        .nth(2)
        .expect("three links")
        .click();
    h.run();
    h.run();
    assert_eq!(
        h.state().state.session.scene().output.as_deref(),
        Some("rocker")
    );
    let report = report_of(h.state().state.session.scene());
    assert!(
        report.swings_rad.contains_key("rocker"),
        "{:?}",
        report.swings_rad
    );
}

/// A new drawing over a scene with unsaved edits asks first; keeping them keeps the
/// scene, dropping them starts the drawing.
#[test]
fn a_drawing_over_unsaved_edits_asks_first() {
    let mut h = harness();
    let length = h.state().state.session.lengths()[0].original;
    h.state_mut().state.session.apply(SceneEdit::Length {
        index: 0,
        value: 1.01 * length,
    });
    assert!(h.state().state.session.is_dirty());
    click_control(&mut h, ControlKind::FileButton, "New…");
    h.run();
    click_control(&mut h, ControlKind::TemplateItem, "Empty: draw your own");
    assert!(h.state().state.drawing.is_none(), "not before the answer");
    click_control(&mut h, ControlKind::FileButton, "Keep editing");
    assert!(h.state().state.drawing.is_none() && h.state().state.session.is_dirty());
    click_control(&mut h, ControlKind::FileButton, "New…");
    h.run();
    click_control(&mut h, ControlKind::TemplateItem, "Empty: draw your own");
    click_control(&mut h, ControlKind::FileButton, "Drop the edits and open");
    assert!(h.state().state.drawing.is_some(), "the drawing started");
}

/// What the user sees with the four-bar drawn: the tools, the count, the drawing on
/// its grid, and the analyses of the drawn mechanism.
#[test]
fn drawing_snapshot() {
    let mut h = common::app_harness();
    h.run();
    h.run();
    draw_four_bar(&mut h);
    h.run();
    h.snapshot("drawn_four_bar");
}

/// A six-bar from a template, edited by dragging a joint with "move points" on: the
/// joint lands under the pointer (to the 1 mm grid), the output's swing changes, and
/// one undo restores the template exactly.
#[test]
fn a_six_bar_template_edited_by_dragging_a_joint() {
    let mut h = harness();
    click_control(&mut h, ControlKind::FileButton, "New…");
    h.run();
    click_control(&mut h, ControlKind::TemplateItem, "Watt six-bar (template)");
    assert_eq!(
        h.state().state.session.scene().name,
        "Watt six-bar (template)"
    );
    // By its accessible name: kittest's pointer does not toggle a checkbox that
    // carries a hover text.
    h.get_by_label("move points").click();
    h.run();
    h.run();
    assert!(h.state().state.view.edit_points);
    let template = h.state().state.session.scene().clone();
    let swing = |h: &Harness<'static, LinkageApp>| {
        report_of(h.state().state.session.scene()).swings_rad["output"]
    };
    let before = swing(&h);
    let st = &h.state().state;
    let [x0, y0, x1, y1] = st.controls.view.expect("the view is drawn");
    let rect = egui::Rect::from_min_max(egui::pos2(x0, y0), egui::pos2(x1, y1));
    let e = st.session.mechanism().point_index("E").expect("E");
    let q = st.session.pose().points[e].position;
    let from = h.state().panels.viewport.camera.to_screen([q.x, q.y], rect);
    let to = from + egui::vec2(12.0, -10.0);
    h.event(egui::Event::PointerMoved(from));
    h.event(egui::Event::PointerButton {
        pos: from,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::default(),
    });
    h.run();
    for k in 1..=4 {
        h.event(egui::Event::PointerMoved(
            from + (to - from) * (k as f32 / 4.0),
        ));
        h.run();
    }
    h.event(egui::Event::PointerButton {
        pos: to,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::default(),
    });
    h.run();
    h.run();
    let st = &h.state().state;
    assert_eq!(st.session.message(), None);
    let q = st.session.pose().points[e].position;
    let landed = h.state().panels.viewport.camera.to_screen([q.x, q.y], rect);
    assert!(
        landed.distance(to) < 3.0,
        "E at {landed:?}, the pointer at {to:?}"
    );
    let after = swing(&h);
    assert!(
        (after - before).abs() > 1e-4,
        "the output's swing {before} -> {after}"
    );
    h.get_by_label("Undo").click();
    h.run();
    h.run();
    assert_eq!(h.state().state.session.scene(), &template);
}

/// Two fingers on the drawing: moved together they pan the view, spread apart they
/// zoom it about their centre (egui alone zooms about the first finger: the picture
/// slid away under the pinch), and neither edits the drawing.
#[test]
fn two_fingers_pan_and_zoom_the_drawing() {
    let mut h = harness();
    draw_four_bar(&mut h);
    let st = &h.state().state;
    let [x0, y0, x1, y1] = st.controls.view.expect("the canvas is drawn");
    let centre = egui::pos2(0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let (camera, drawing) = (
        h.state().panels.viewport.camera,
        st.drawing.as_ref().expect("drawing").drawing().clone(),
    );
    let touch = |h: &mut Harness<'static, LinkageApp>, id: u64, phase, pos| {
        h.event(egui::Event::Touch {
            device_id: egui::TouchDeviceId(1),
            id: egui::TouchId(id),
            phase,
            pos,
            force: None,
        });
    };
    use egui::TouchPhase::{End, Move, Start};
    let fingers = |offset: egui::Vec2, spread: f32| {
        [
            centre + offset - egui::vec2(spread, 0.0),
            centre + offset + egui::vec2(spread, 0.0),
        ]
    };
    let [a, b] = fingers(egui::Vec2::ZERO, 40.0);
    touch(&mut h, 1, Start, a);
    touch(&mut h, 2, Start, b);
    h.run();
    for k in 1..=5 {
        let [a, b] = fingers(egui::vec2(10.0 * k as f32, 0.0), 40.0);
        touch(&mut h, 1, Move, a);
        touch(&mut h, 2, Move, b);
        h.run();
    }
    let panned = h.state().panels.viewport.camera;
    assert!(
        panned.center_m[0] < camera.center_m[0],
        "the view follows the fingers right"
    );
    // Fingers moved together keep their spread: no zoom beyond rounding.
    assert!((panned.points_per_m / camera.points_per_m - 1.0).abs() < 1e-3);
    let rect = egui::Rect::from_min_max(egui::pos2(x0, y0), egui::pos2(x1, y1));
    let pinch_centre = centre + egui::vec2(50.0, 0.0);
    let under = panned.to_world(pinch_centre, rect);
    for k in 1..=5 {
        let [a, b] = fingers(egui::vec2(50.0, 0.0), 40.0 + 8.0 * k as f32);
        touch(&mut h, 1, Move, a);
        touch(&mut h, 2, Move, b);
        h.run();
    }
    let [a, b] = fingers(egui::vec2(50.0, 0.0), 80.0);
    touch(&mut h, 1, End, a);
    touch(&mut h, 2, End, b);
    h.run();
    let st = &h.state().state;
    assert!(
        h.state().panels.viewport.camera.points_per_m > 1.5 * camera.points_per_m,
        "spread fingers zoom in"
    );
    // About the fingers' centre: what was under it stays under it (to a point).
    let stays = h.state().panels.viewport.camera.to_screen(under, rect);
    assert!(
        stays.distance(pinch_centre) < 1.0,
        "{stays:?} vs {pinch_centre:?}"
    );
    assert_eq!(st.drawing.as_ref().expect("drawing").drawing(), &drawing);
}

/// The open scene as a drawing (New… > This scene as a drawing): a template becomes
/// a drawing of the same mechanism, which then takes structural edits (a link
/// deleted leaves 2 degrees of freedom); a scene with springs is refused with why.
#[test]
fn a_template_becomes_a_drawing_and_takes_structural_edits() {
    let mut h = harness();
    click_control(&mut h, ControlKind::FileButton, "New…");
    h.run();
    click_control(&mut h, ControlKind::TemplateItem, "Four-bar (template)");
    let template = h.state().state.session.scene().clone();
    click_control(&mut h, ControlKind::FileButton, "New…");
    h.run();
    click_control(&mut h, ControlKind::TemplateItem, "This scene as a drawing");
    let st = &h.state().state;
    let b = st.drawing.as_ref().expect("drawing");
    assert_eq!(b.problem, None, "the template is a complete drawing");
    let (a, d) = (report_of(&template), report_of(st.session.scene()));
    assert_close("K", a.time_ratio.expect("K"), d.time_ratio.expect("K"));
    assert_close("swing", a.swings_rad["rocker"], d.swings_rad["rocker"]);
    // The rocker deleted: an open chain of 2 degrees of freedom.
    tool(&mut h, "Delete");
    let st = &h.state().state;
    let drawing = st.drawing.as_ref().expect("drawing").drawing();
    let at = |name: &str| {
        drawing
            .points
            .iter()
            .find(|p| p.name == name)
            .expect("point")
            .at
    };
    let (c, dp) = (at("C"), at("D"));
    click_mm(&mut h, 500.0 * (c.x + dp.x), 500.0 * (c.y + dp.y));
    let b = h.state().state.drawing.as_ref().expect("drawing");
    assert_eq!(b.drawing().links.len(), 2);
    assert_eq!(b.drawing().mobility().dof(), 2);
    // The flipper has a spring: it stays a scene.
    click_control(&mut h, ControlKind::ScenePicker, "Scene");
    h.run();
    let flipper = h
        .state()
        .state
        .controls
        .of_kind(ControlKind::SceneItem)
        .find(|e| e.label.contains("flipper") || e.label.contains("Flipper"))
        .map(|e| e.label.clone());
    if let Some(label) = flipper {
        click_control(&mut h, ControlKind::SceneItem, &label);
        if h.state().state.commands.waiting.is_some() {
            click_control(&mut h, ControlKind::FileButton, "Drop the edits and open");
        }
        click_control(&mut h, ControlKind::FileButton, "New…");
        h.run();
        click_control(&mut h, ControlKind::TemplateItem, "This scene as a drawing");
        let st = &h.state().state;
        assert!(st.drawing.is_none());
        let status = st.status.clone().unwrap_or_default();
        assert!(
            status.starts_with("this scene cannot become a drawing"),
            "{status}"
        );
    } else {
        panic!("no flipper in the scene picker");
    }
}

/// A four-bar drawn by pointer, computing dynamics, with masses, a spring and a force
/// placed with the Spring and Force tools: its scene carries them by name, and its
/// dynamic run is that of the same machine written by hand as a scene file (the drawn
/// input 0 is the hand-written start, 90 degrees).
#[test]
fn a_drawn_four_bar_with_a_spring_and_a_force_runs_as_its_scene_file() {
    use linkage_lab::drawing::edit::{Body, DrawingEdit as Draw};
    // Rendered through wgpu: the test ends with a picture of the loads.
    let mut h = common::app_harness();
    h.run();
    h.run();
    draw_four_bar(&mut h);
    h.get_by_label("dynamics").click();
    h.run();
    for (link, kg) in [(0, 0.5), (1, 1.5), (2, 2.0)] {
        h.state_mut()
            .state
            .push(linkage_lab::command::Command::Drawing(Draw::SetMass(
                Body::Link(link),
                Some(kg),
            )));
    }
    h.run();
    tool(&mut h, "Spring");
    click_mm(&mut h, 0.0, 50.0);
    click_mm(&mut h, 300.0, 0.0);
    tool(&mut h, "Force");
    click_mm(&mut h, 200.0, 200.0);
    let st = &h.state().state;
    assert_eq!(st.drawing.as_ref().and_then(|b| b.problem.clone()), None);
    let forces = &st.session.scene().forces;
    assert_eq!(forces.springs.len(), 1, "{forces:?}");
    assert_eq!(
        (forces.springs[0].a.as_str(), forces.springs[0].b.as_str()),
        ("C", "B")
    );
    assert_eq!(forces.point_forces.len(), 1);
    assert_eq!(forces.point_forces[0].point, "D");
    assert!(
        h.query_by_label("spring C–B").is_some(),
        "the panel lists it"
    );
    h.snapshot("drawn_four_bar_loads");

    let rocker = (100.0f64 * 100.0 + 200.0 * 200.0).sqrt();
    let coupler = (200.0f64 * 200.0 + 150.0 * 150.0).sqrt();
    let inertia = |kg: f64, mm: f64| kg * (mm * 1e-3).powi(2) / 12.0;
    let by_hand = format!(
        r#"Scene(
            name: "four-bar by hand", models: Dynamics, length_unit: Millimetre,
            links: [
                (name: "ground", ground: true, points: {{"A": (0.0, 0.0), "D": (300.0, 0.0)}}),
                (name: "crank", points: {{"A": (0.0, 0.0), "B": (50.0, 0.0)}},
                    mass: Some(0.5), centroid: Some((25.0, 0.0)), inertia: Some({})),
                (name: "coupler", points: {{"B": (0.0, 0.0), "C": ({coupler}, 0.0)}},
                    mass: Some(1.5), centroid: Some(({}, 0.0)), inertia: Some({})),
                (name: "rocker", points: {{"D": (0.0, 0.0), "C": ({rocker}, 0.0)}},
                    mass: Some(2.0), centroid: Some(({}, 0.0)), inertia: Some({})),
            ],
            driver: (link: "crank", speed: Rpm(60.0), start: 90.0),
            branches: {{"C": Left("B", "D")}},
            output: Some("rocker"),
            forces: (
                springs: [(a: "B", b: "D", k_n_per_m: 1000.0, free_length: UnstretchedAtStart)],
                point_forces: [(point: "C", force_n: (0.0, -100.0))],
            ),
        )"#,
        inertia(0.5, 50.0),
        coupler / 2.0,
        inertia(1.5, coupler),
        rocker / 2.0,
        inertia(2.0, rocker),
    );
    let mut hand = linkage_lab::session::Session::open_text(
        linkage_lab::session::SceneSource::File("by hand".into()),
        &by_hand,
    )
    .expect("the hand-written scene opens");
    hand.wait_for_run();
    h.state_mut().state.session.wait_for_run();
    let drawn_run = h
        .state()
        .state
        .session
        .dynamics()
        .expect("a run")
        .as_ref()
        .expect("runs");
    let hand_run = hand.dynamics().expect("a run").as_ref().expect("runs");
    let (a, b) = (&drawn_run.sim.samples, &hand_run.sim.samples);
    assert!(
        a.len() > 10 && a.len() == b.len(),
        "{} vs {} samples",
        a.len(),
        b.len()
    );
    let turned = a.iter().map(|s| (s.q - a[0].q).abs()).fold(0.0, f64::max);
    assert!(turned > 0.1, "it moves: {turned} rad");
    // The same run to the integrator's tolerance (rtol 1e-8, over a run whose speed
    // swings to tens of rad/s): the two scenes differ only in how their links'
    // coordinates are written.
    let peak = b.iter().map(|s| s.q_dot.abs()).fold(0.0, f64::max);
    for (x, y) in a.iter().zip(b) {
        assert!((x.t - y.t).abs() < 1e-12);
        assert!(
            (x.q + std::f64::consts::FRAC_PI_2 - y.q).abs() < 1e-6,
            "t = {}: q {} vs {}",
            x.t,
            x.q + std::f64::consts::FRAC_PI_2,
            y.q
        );
        assert!(
            (x.q_dot - y.q_dot).abs() < 1e-6 * peak,
            "t = {}: {} vs {} rad/s",
            x.t,
            x.q_dot,
            y.q_dot
        );
    }
}

/// The drive panel: a drawn four-bar that computes kinetostatics gets a motor from
/// the chooser, a flywheel typed in, and its scene carries them; a gear ratio of 0 is
/// refused by name and the drive kept.
#[test]
fn a_drawn_mechanism_gets_its_drive_from_the_panel() {
    use linkage::scene::{MotorSpec, Shaft};
    let mut h = common::app_harness();
    h.run();
    h.run();
    draw_four_bar(&mut h);
    h.get_by_label("kinetostatics").click();
    h.run();
    h.get_by_label("motor").click();
    h.run();
    h.get_by_label("linear (induction motor)").click();
    h.run();
    h.get_by_label("motor shaft").click();
    h.run();
    let drive = h
        .state()
        .state
        .session
        .scene()
        .drive
        .clone()
        .expect("a drive");
    assert!(matches!(drive.motor, MotorSpec::Linear { .. }), "{drive:?}");
    assert_eq!(drive.flywheel_on, Shaft::Motor);
    let mut bad = drive.clone();
    bad.gear_ratio = 0.0;
    h.state_mut()
        .state
        .push(linkage_lab::command::Command::Drawing(
            linkage_lab::drawing::edit::DrawingEdit::SetDrive(Some(bad)),
        ));
    h.run();
    let st = &h.state().state;
    assert_eq!(st.session.scene().drive.as_ref(), Some(&drive), "kept");
    let said = st
        .drawing
        .as_ref()
        .and_then(|b| b.refusal.clone())
        .map(|r| r.to_string())
        .unwrap_or_default();
    assert!(said.contains("drive.gear_ratio"), "{said}");
    h.snapshot("drawn_four_bar_drive");
}
