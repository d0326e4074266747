//! The path tab of the synthesis window as a user works it: targets placed by
//! clicking its canvas, a search run off the frame to a design, the design put in
//! place of the scene (undo-able) and opened as a scene of its own; the scene's
//! coupler point passes through the targets when the solver moves it there.

use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage::synthesis::path::PathDesign;
use linkage::{Kinematics, Mechanism, Vec2};
use linkage_lab::LinkageApp;
use linkage_lab::ui::control_map::ControlKind;

use crate::common;

use common::click_label as click;

/// Where the path tab's targets are, mm.
fn targets_mm(h: &Harness<'static, LinkageApp>) -> Vec<[f64; 2]> {
    tab(h).inputs.path.targets.iter().map(|t| t.at_mm).collect()
}

/// The search's progress now.
fn progress(h: &Harness<'static, LinkageApp>) -> linkage::synthesis::path::Progress {
    tab(h)
        .path
        .job
        .as_ref()
        .expect("a search")
        .snapshot()
        .progress
}

fn tab<'h>(h: &'h Harness<'static, LinkageApp>) -> &'h linkage_lab::ui::synthesis::SynthesisView {
    h.state()
        .panels
        .synthesis
        .view()
        .expect("the window is open")
}

/// Frames until the search is done (it runs on its own thread), at most 60 s.
fn until_done(h: &mut Harness<'static, LinkageApp>) -> Vec<PathDesign> {
    for _ in 0..3000 {
        h.step();
        let job = tab(h).path.job.as_ref().expect("a search");
        if !job.is_running() {
            return job.snapshot().designs.clone();
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    panic!("the search did not finish in 60 s");
}

/// The targets' size and the largest miss of the scene's P, solved at each crank
/// angle of `design`, over them.
fn scene_miss(
    scene: &linkage::SceneFile,
    design: &PathDesign,
    targets_mm: &[[f64; 2]],
) -> (f64, f64) {
    let mut k = Kinematics::new(Mechanism::from_scene(scene).expect("valid")).expect("solves");
    let p = k.mechanism().point_index("P").expect("P on the coupler");
    let mut miss: f64 = 0.0;
    for (t, deg) in targets_mm.iter().zip(&design.linkage.crank_deg) {
        let at = k.solve(deg.to_radians()).expect("closes").points[p].position;
        miss = miss.max((at - Vec2::new(t[0], t[1]) * 1e-3).norm());
    }
    let (xs, ys): (Vec<f64>, Vec<f64>) = targets_mm.iter().map(|t| (t[0], t[1])).unzip();
    let span = |v: &[f64]| {
        v.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
            - v.iter().cloned().fold(f64::INFINITY, f64::min)
    };
    (span(&xs).hypot(span(&ys)) * 1e-3, miss)
}

#[test]
fn targets_clicked_on_the_canvas_are_searched_to_a_design_that_opens() {
    let mut h = common::stateful_harness();
    common::synthesis_tab(&mut h, "path");
    click(&mut h, "Clear targets");
    assert!(tab(&h).inputs.path.targets.is_empty());
    // The canvas lies between the "timed" checkbox and the targets' label.
    let above = h.get_by_label_contains("timed: a crank angle").rect();
    // (The label and the text field under it carry the same name.)
    let below = h
        .query_all_by_label_contains("targets: x mm, y mm (click")
        .map(|n| n.rect())
        .min_by(|a, b| a.top().total_cmp(&b.top()))
        .expect("the targets' label");
    let (top, bottom) = (above.bottom() + 20.0, below.top() - 20.0);
    let (left, width) = (above.left() + 60.0, 300.0);
    for (fx, fy) in [
        (0.1, 0.8),
        (0.3, 0.2),
        (0.55, 0.1),
        (0.8, 0.35),
        (0.9, 0.75),
    ] {
        let at = egui::pos2(left + fx * width, top + fy * (bottom - top));
        common::click(&mut h, at);
    }
    let targets: Vec<[f64; 2]> = targets_mm(&h);
    assert_eq!(targets.len(), 5, "{targets:?}");
    for (i, a) in targets.iter().enumerate() {
        for b in &targets[..i] {
            assert!(
                (a[0] - b[0]).hypot(a[1] - b[1]) > 1e-9,
                "distinct targets: {targets:?}"
            );
        }
    }

    // A drag moves the second target; the others stay.
    let second = h
        .state()
        .state
        .controls
        .entries
        .iter()
        .find(|e| e.kind == ControlKind::SynthesisTarget && e.label == "target 2")
        .map(|e| egui::pos2(0.5 * (e.rect[0] + e.rect[2]), 0.5 * (e.rect[1] + e.rect[3])))
        .expect("target 2 on the canvas");
    common::pointer(&mut h, second, Some(true));
    for k in 1..=6 {
        common::pointer(
            &mut h,
            second + egui::vec2(4.0 * k as f32, 3.0 * k as f32),
            None,
        );
    }
    common::pointer(&mut h, second + egui::vec2(24.0, 18.0), Some(false));
    let moved: Vec<[f64; 2]> = targets_mm(&h);
    assert_eq!(moved.len(), 5, "a drag adds no target: {moved:?}");
    assert_ne!(moved[1], targets[1], "target 2 moved");
    for k in [0, 2, 3, 4] {
        assert_eq!(moved[k], targets[k], "target {} stayed", k + 1);
    }
    let targets = moved;

    h.get_by_label("Search").click();
    let designs = until_done(&mut h);
    let best = designs.first().expect("a design").clone();
    let tolerance = tab(&h).inputs.path.tolerance;
    assert!(best.relative_error <= tolerance, "{best:?}");

    // Put in place of the scene: undo-able.
    let before = h.state().state.session.scene().clone();
    h.get_by_label("Replace this scene").scroll_to_me();
    h.run();
    click(&mut h, "Replace this scene");
    let placed = h.state().state.session.scene().clone();
    assert_eq!(
        placed.name,
        "Path generator",
        "{:?}",
        h.state().state.session.message()
    );
    let (size, miss) = scene_miss(&placed, &best, &targets);
    assert!(miss <= tolerance * size, "misses by {miss} m of {size} m");
    click(&mut h, "Undo");
    assert_eq!(
        h.state().state.session.scene(),
        &before,
        "undo puts the scene back"
    );

    // Opened as a scene of its own.
    h.get_by_label("Open as scene").scroll_to_me();
    h.run();
    click(&mut h, "Open as scene");
    if h.state().state.commands.waiting.is_some() {
        click(&mut h, "Drop the edits and open");
    }
    assert_eq!(h.state().state.session.scene().name, "Path generator");
    assert!(
        !h.state().state.session.is_dirty(),
        "a fresh design is marked edited"
    );
}

#[test]
fn a_search_stops_and_continues_where_it_was() {
    let mut h = common::stateful_harness();
    common::synthesis_tab(&mut h, "path");
    // The default targets, timed: eight points rounded to 0.1 mm at prescribed crank
    // angles, which no four-bar meets to the tolerance asked here (sixteen equations
    // in ten unknowns), so the search is still running when stopped.
    let inputs = common::synthesis_inputs(&mut h);
    inputs.path.tolerance = 1e-9;
    inputs.path.timed = true;
    h.get_by_label("Search").click();
    for _ in 0..5 {
        h.step();
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    h.get_by_label("Stop").click();
    h.step();
    let stopped = progress(&h);
    assert!(!tab(&h).path.job.as_ref().expect("a search").is_running());
    assert!(stopped.evaluations > 0 && !stopped.done, "{stopped:?}");
    h.step();
    let still = progress(&h);
    assert_eq!(
        still.evaluations, stopped.evaluations,
        "nothing runs while stopped"
    );
    h.get_by_label("Continue").click();
    for _ in 0..10 {
        h.step();
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let later = progress(&h);
    assert!(later.evaluations > stopped.evaluations, "{later:?}");
    h.get_by_label("Stop").click();
    h.step();
}

/// A picture of the tab after a search of its default targets: the coupler curve
/// through the numbered targets, the linkage at the first, the designs listed.
#[test]
fn the_path_tab_after_a_search_looks_right() {
    let mut h = common::app_harness();
    h.run();
    h.run();
    common::synthesis_tab(&mut h, "path");
    h.get_by_label("Search").click();
    let designs = until_done(&mut h);
    assert!(!designs.is_empty());
    h.run();
    h.snapshot("synthesis_path_search");
}
