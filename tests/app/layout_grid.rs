//! The layout holds at every window size after every panel action: the mechanism
//! view keeps a usable share of the window (35 % of its area on a desktop screen,
//! half of it on a phone or tablet, and never a strip), every tab row stays on
//! screen, and "Reset layout" gives back the first layout. Walked over a grid of
//! window sizes from a small phone to a 4K screen, on the scenes that hold the most
//! panes (the die cutter's machine tabs, the cam feed's cam tabs, the flipper's
//! dynamic run), each action after the ones before it, as a user piles them up.
//! Before this test the view collapsed to a strip 45 px high at 1366×768 after the
//! vector equations were opened (the plot pane grew with its contents).

use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage_lab::ui::control_map::{ControlEntry, ControlKind};
use linkage_lab::{LinkageApp, StartOptions};

/// The grid of window sizes, points: phones, tablets either way, laptops, desktops.
const SIZES: [(f32, f32); 9] = [
    (360.0, 640.0),
    (390.0, 844.0),
    (820.0, 1180.0),
    (1024.0, 768.0),
    (1280.0, 720.0),
    (1366.0, 768.0),
    (1920.0, 1080.0),
    (2560.0, 1440.0),
    (3840.0, 2160.0),
];

/// The scenes with the most panes: machine tabs, cam tabs, a dynamic run.
const SCENES: [&str; 3] = ["die_cutter", "paper_cup_cam_feed", "gravity_flipper"];

/// The app at `scene` in a window of `size`, without a GPU (the rectangles are the
/// app's own), after its first frames.
fn app(scene: &str, (w, h): (f32, f32)) -> Harness<'static, LinkageApp> {
    let scene = scene.to_owned();
    let mut h = Harness::builder()
        .with_size(egui::vec2(w, h))
        .build_eframe(move |cc| {
            let start = StartOptions {
                scene: Some(scene.clone()),
                ..StartOptions::default()
            };
            LinkageApp::new(cc, start)
        });
    frames(&mut h);
    h
}

/// A few frames: a layout change settles in two (a pane's size is remembered from
/// the frame before); the dynamic run is waited for, not counted in frames.
fn frames(h: &mut Harness<'static, LinkageApp>) {
    for _ in 0..4 {
        h.state_mut().state.session.wait_for_run();
        h.run_steps(1);
    }
}

fn rect(r: [f32; 4]) -> egui::Rect {
    egui::Rect::from_min_max(egui::pos2(r[0], r[1]), egui::pos2(r[2], r[3]))
}

fn entries(h: &Harness<'static, LinkageApp>, kind: ControlKind) -> Vec<ControlEntry> {
    h.state().state.controls.of_kind(kind).cloned().collect()
}

/// What every frame of the walk must hold, after `action`.
fn check(h: &Harness<'static, LinkageApp>, size: (f32, f32), scene: &str, action: &str) {
    let at = format!("{scene} at {}x{} after {action}", size.0, size.1);
    let window = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(size.0, size.1));
    let view = rect(
        h.state()
            .state
            .controls
            .view
            .unwrap_or_else(|| panic!("{at}: no view")),
    );
    let compact = h.state().state.layout.compact();
    let share = view.area() / window.area();
    let least = if compact { 0.5 } else { 0.35 };
    assert!(
        share >= least,
        "{at}: the view has {share:.3} of the window ({view:?})"
    );
    // Never a strip: each side at least a quarter of the window's.
    assert!(
        view.width() >= 0.25 * size.0 && view.height() >= 0.25 * size.1,
        "{at}: the view is a strip {view:?}"
    );
    assert!(
        window.expand(0.5).contains_rect(view),
        "{at}: {view:?} off screen"
    );
    // Every pane on screen, and none under the view (a pane whose contents are wider
    // than it ran off the window's edge and under the view).
    for pane in entries(h, ControlKind::Pane) {
        let r = rect(pane.rect);
        assert!(
            window.expand(0.5).contains_rect(r),
            "{at}: the {} pane runs off the window: {r:?}",
            pane.label
        );
        assert!(
            !r.shrink(1.0).intersects(view),
            "{at}: the {} pane {r:?} lies under the view {view:?}",
            pane.label
        );
    }
    for kind in [ControlKind::PlotTab, ControlKind::SheetTab] {
        for tab in entries(h, kind) {
            let r = rect(tab.rect);
            assert!(
                window.expand(0.5).contains_rect(r) && tab.visible,
                "{at}: the tab {} is off screen at {r:?}",
                tab.label
            );
        }
    }
}

/// Clicks the widget labelled `label` if it is there (an action not every scene
/// or arrangement has), then lets the layout settle.
fn click_if_there(h: &mut Harness<'static, LinkageApp>, label: &str) -> bool {
    let there = h.query_by_label(label).is_some();
    if there {
        h.get_by_label(label).click();
        frames(h);
    }
    there
}

/// A drag with the primary button from `from` to `to`, in steps.
fn drag(h: &mut Harness<'static, LinkageApp>, from: egui::Pos2, to: egui::Pos2) {
    let button = |pos, pressed| egui::Event::PointerButton {
        pos,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::default(),
    };
    h.event(egui::Event::PointerMoved(from));
    h.run_steps(1);
    h.event(button(from, true));
    h.run_steps(1);
    for k in 1..=4 {
        h.event(egui::Event::PointerMoved(from.lerp(to, k as f32 / 4.0)));
        h.run_steps(1);
    }
    h.event(button(to, false));
    frames(h);
}

/// Every plot tab the scene has, each clicked in turn, checked after each.
fn every_plot_tab(h: &mut Harness<'static, LinkageApp>, size: (f32, f32), scene: &str) {
    let tabs = entries(h, ControlKind::PlotTab);
    for tab in tabs {
        let centre = rect(tab.rect).center();
        h.event(egui::Event::PointerMoved(centre));
        h.run_steps(1);
        common_click(h, centre);
        check(h, size, scene, &format!("the plot tab {}", tab.label));
    }
}

fn common_click(h: &mut Harness<'static, LinkageApp>, at: egui::Pos2) {
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos: at,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::default(),
        });
        h.run_steps(1);
    }
    frames(h);
}

/// Every collapsible section of the polygon pane opened.
const SECTIONS: [&str; 3] = [
    "Velocity polygon: vector equations",
    "Acceleration polygon: vector equations",
    "Construct an equation step by step",
];

/// The desktop arrangement's walk.
fn desktop_walk(h: &mut Harness<'static, LinkageApp>, size: (f32, f32), scene: &str) {
    let first = h.state().state.controls.view;
    for section in SECTIONS {
        if click_if_there(h, section) {
            check(h, size, scene, section);
        }
    }
    every_plot_tab(h, size, scene);
    assert!(click_if_there(h, "enlarge"), "no enlarge");
    check(h, size, scene, "enlarge");
    every_plot_tab(h, size, scene);
    assert!(click_if_there(h, "narrower"), "no narrower");
    check(h, size, scene, "narrower");
    // Each pane's edge dragged as far as it goes, into the view.
    let pane = |h: &Harness<'static, LinkageApp>, name: &str| {
        entries(h, ControlKind::Pane)
            .into_iter()
            .find(|e| e.label == name)
            .map(|e| rect(e.rect))
            .unwrap_or_else(|| panic!("no {name} pane"))
    };
    let controls = pane(h, "controls");
    let y = controls.center().y;
    drag(
        h,
        egui::pos2(controls.max.x, y),
        egui::pos2(size.0 - 2.0, y),
    );
    check(h, size, scene, "the controls' edge dragged right");
    let polygons = pane(h, "polygons");
    drag(h, egui::pos2(polygons.min.x, y), egui::pos2(2.0, y));
    check(h, size, scene, "the polygons' edge dragged left");
    let plots = pane(h, "plots");
    let x = plots.center().x;
    drag(h, egui::pos2(x, plots.min.y), egui::pos2(x, 2.0));
    check(h, size, scene, "the plots' edge dragged up");
    assert!(click_if_there(h, "Synthesis…"), "no synthesis button");
    check(h, size, scene, "the synthesis window");
    click_if_there(h, "Synthesis…");
    assert!(click_if_there(h, "Reset layout"), "no reset layout");
    check(h, size, scene, "reset layout");
    assert_eq!(
        h.state().state.controls.view,
        first,
        "{scene} at {size:?}: reset layout did not give back the first layout"
    );
}

/// The sheet's walk on a phone or tablet: every tab, the polygons enlarged and
/// fitted with their sections open, every plot tab, the menu's synthesis window.
fn sheet_walk(h: &mut Harness<'static, LinkageApp>, size: (f32, f32), scene: &str) {
    let tabs = entries(h, ControlKind::SheetTab);
    assert!(!tabs.is_empty(), "{scene} at {size:?}: no sheet tabs");
    for tab in tabs {
        common_click(h, rect(tab.rect).center());
        check(h, size, scene, &format!("the sheet tab {}", tab.label));
        match tab.label.as_str() {
            "Polygons" => {
                for section in SECTIONS {
                    if click_if_there(h, section) {
                        check(h, size, scene, section);
                    }
                }
                assert!(click_if_there(h, "enlarge"), "no enlarge");
                check(h, size, scene, "enlarge");
                assert!(click_if_there(h, "fit"), "no fit");
                check(h, size, scene, "fit");
            }
            "Plots" => every_plot_tab(h, size, scene),
            _ => {}
        }
    }
}

#[test]
fn the_view_and_the_tab_rows_hold_at_every_size_after_every_panel_action() {
    for size in SIZES {
        for scene in SCENES {
            let mut h = app(scene, size);
            check(&h, size, scene, "opening");
            if h.state().state.layout.compact() {
                sheet_walk(&mut h, size, scene);
            } else {
                desktop_walk(&mut h, size, scene);
            }
        }
    }
}

/// The key of every scene file in `assets/scenes`.
fn shipped_scene_keys() -> Vec<String> {
    crate::common::shipped_scene_files()
        .iter()
        .map(|p| p.file_stem().expect("stem").to_string_lossy().into_owned())
        .collect()
}

/// The first row of plots of every plot tab of every shipped scene is seen whole in
/// the plot pane as it first opens on a laptop and on a desktop screen: no axis title
/// hidden below the pane's edge (the flywheel tab's, at 1366×768, was: its plots kept
/// 150 points where the pane had 145 left). Plots stacked below the first row are
/// scrolled to, as on a phone's sheet.
#[test]
fn every_plot_is_seen_whole_in_the_first_layout() {
    use linkage_lab::ui::plot_layout::drawn_plots;
    for size in [(1366.0, 768.0), (1920.0, 1080.0)] {
        for scene in shipped_scene_keys() {
            let mut h = app(&scene, size);
            for tab in entries(&h, ControlKind::PlotTab) {
                common_click(&mut h, rect(tab.rect).center());
                let at = format!("{scene} at {}x{}, plot tab {}", size.0, size.1, tab.label);
                let plots = drawn_plots(&h.ctx);
                assert!(!plots.is_empty(), "{at}: no plot drawn");
                let first_row = plots[0].rect.min.y;
                for p in plots
                    .iter()
                    .filter(|p| (p.rect.min.y - first_row).abs() < 0.5)
                {
                    assert!(
                        p.seen.expand(0.5).contains_rect(p.rect),
                        "{at}: the plot {:?} is cut by the pane's edge {:?}",
                        p.rect,
                        p.seen
                    );
                }
            }
        }
    }
}
