//! UI tests of the viewer (egui_kittest, headless, rendered through wgpu on a CPU
//! adapter): every scene opens from the picker, the crank and length sliders move the
//! solver state and the polygon data shown exactly as an independent solve computes,
//! an unassemblable length is refused with its reason while the pose stays, and the
//! main view's pixels match the committed snapshot.

use eframe::egui;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage::polygon::polygons;
use linkage::{Kinematics, Mechanism};
use linkage_lab::LinkageApp;
use linkage_lab::catalog::BUILTIN_SCENES;
use linkage_lab::session::SceneSource;
use linkage_lab::session::derived::Shown;
use linkage_lab::ui::controls::CRANK_LABEL;

use crate::common;

fn harness() -> Harness<'static, LinkageApp> {
    let mut h = common::app_harness();
    h.run();
    h
}

/// Opens `key` by clicking the scene picker and the scene's name.
pub(crate) fn open_scene(h: &mut Harness<'static, LinkageApp>, key: &str) {
    let text = BUILTIN_SCENES
        .iter()
        .find(|b| b.key == key)
        .expect("shipped")
        .text;
    let name = linkage::SceneFile::parse(text).expect("parses").name;
    h.get_by_role_and_label(Role::ComboBox, "Scene").click();
    h.run();
    h.get_by_label(&name).click();
    common::settle(h);
    if h.state().state.commands.waiting.is_some() {
        h.get_by_role_and_label(Role::Button, "Drop the edits and open")
            .click();
        common::settle(h);
    }
    assert_eq!(
        h.state().state.session.source(),
        &SceneSource::Builtin(key.into())
    );
}

/// The scene as the app holds it, solved independently at `input_rad`.
fn independent(
    h: &Harness<'static, LinkageApp>,
    input_rad: f64,
) -> (Kinematics, linkage::Solution) {
    let mech = Mechanism::from_scene(h.state().state.session.scene()).expect("valid");
    let mut k = Kinematics::new(mech).expect("solvable");
    let s = k.solve(input_rad).expect("assembles");
    (k, s)
}

#[test]
fn every_scene_opens_and_its_crank_slider_moves_pose_and_polygons() {
    let mut h = harness();
    for b in BUILTIN_SCENES {
        open_scene(&mut h, b.key);
        let [lo, hi] = h.state().state.session.input_range_deg();
        let target = lo + 0.37 * (hi - lo);
        let before = h.state().state.session.polygons().to_vec();
        h.get_by_role_and_label(Role::Slider, CRANK_LABEL)
            .set_value_accesskit(target);
        h.run();
        let session = &h.state().state.session;
        assert_eq!(session.message(), None, "{}", b.key);
        let x = session.input_rad();
        assert!((x.to_degrees() - target).abs() < 1e-9, "{}: {x}", b.key);
        let (k, s) = independent(&h, x);
        let session = &h.state().state.session;
        assert_eq!(session.pose().points, s.points, "{}", b.key);
        assert_eq!(session.polygons(), polygons(&k, &s).as_slice(), "{}", b.key);
        assert_ne!(
            session.polygons(),
            before.as_slice(),
            "{}: polygons did not change",
            b.key
        );
    }
}

#[test]
fn a_length_slider_rebuilds_the_chain_and_its_polygons() {
    let mut h = harness();
    open_scene(&mut h, "slider_crank");
    let before = h.state().state.session.polygons().to_vec();
    h.get_by_role_and_label(Role::Slider, "AB")
        .set_value_accesskit(60.0);
    h.run();
    let session = &h.state().state.session;
    assert_eq!(session.message(), None);
    assert!((session.lengths()[0].value(session.scene()).expect("AB") - 60.0).abs() < 1e-12);
    let x = session.input_rad();
    let (k, s) = independent(&h, x);
    let session = &h.state().state.session;
    assert_eq!(session.pose().points, s.points);
    assert_eq!(session.polygons(), polygons(&k, &s).as_slice());
    assert_ne!(session.polygons(), before.as_slice());
    // The crank pin B sits 60 mm from A.
    let b = s.points[k.mechanism().point_index("B").expect("B")].position;
    assert!((b.norm() - 0.060).abs() < 1e-12, "{b}");
}

#[test]
fn an_unassemblable_length_is_refused_with_its_reason_and_the_pose_stays() {
    let mut h = harness();
    open_scene(&mut h, "slider_crank");
    h.get_by_role_and_label(Role::Slider, CRANK_LABEL)
        .set_value_accesskit(90.0);
    h.run();
    let pose = h.state().state.session.pose().clone();
    let scene = h.state().state.session.scene().clone();
    // At 90 deg the crank pin is 50 mm off the guide: a 20 mm rod cannot reach it.
    h.get_by_role_and_label(Role::Slider, "BC")
        .set_value_accesskit(20.0);
    h.run();
    let session = &h.state().state.session;
    let msg = session.message().expect("a message").to_string();
    // In the user's words: the rod by its pins, the distance it cannot span.
    assert!(
        msg.contains("BC = 20 mm does not fit at crank 90°"),
        "{msg}"
    );
    assert!(msg.contains("BC (20 mm) cannot reach the guide"), "{msg}");
    // The limit found by bisection is the crank radius, 50 mm.
    assert!(msg.contains("can go to 50 mm"), "{msg}");
    assert_eq!(session.pose(), &pose);
    assert_eq!(session.scene(), &scene);
    // And the message is on screen.
    assert!(h.query_by_label_contains("does not fit").is_some());
}

#[test]
fn main_view_snapshot() {
    let mut h = harness();
    open_scene(&mut h, "gravity_flipper");
    h.get_by_role_and_label(Role::Slider, CRANK_LABEL)
        .set_value_accesskit(50.0);
    h.run();
    h.snapshot("gravity_flipper_50deg");
}

/// The cam on the feed's main shaft: its disc turns with the crank and the roller
/// rides it, at a crank angle inside the cam's rise.
#[test]
fn cam_and_four_bar_on_one_shaft_snapshot() {
    let mut h = harness();
    open_scene(&mut h, "paper_cup_cam_feed");
    h.get_by_role_and_label(Role::Slider, CRANK_LABEL)
        .set_value_accesskit(60.0);
    h.run();
    h.snapshot("paper_cup_cam_feed_60deg");
    // The timing tab: the bell crank's dwells shaded, and the slider.
    h.get_by_role_and_label(Role::Button, "Timing").click();
    h.run();
    let timing = &h.state().state.session.curves().timing;
    let names: Vec<&str> = timing.lanes.iter().map(|l| l.name.as_str()).collect();
    assert_eq!(names, ["bell_crank", "slider"]);
    assert_eq!(timing.lanes[0].dwells.len(), 2);
    h.snapshot("paper_cup_cam_feed_timing");
}

/// The cam panel: a segment's angle moves the join (the next segment makes up the
/// difference), the lift scales the program, a span that leaves the next segment
/// nothing is refused with its range, and undo takes the edits back.
#[test]
fn the_cam_panel_edits_the_program_and_undo_takes_it_back() {
    use linkage::cam::SegmentSpec;
    let mut h = harness();
    open_scene(&mut h, "paper_cup_cam_feed");
    let spans = |h: &Harness<'static, LinkageApp>| -> Vec<f64> {
        h.state().state.session.scene().cams[0]
            .segments
            .iter()
            .map(SegmentSpec::angle_deg)
            .collect()
    };
    assert_eq!(spans(&h), [110.0, 70.0, 110.0, 70.0]);
    h.get_by_role_and_label(Role::TextInput, "segment 1 angle (°)")
        .set_text_value_accesskit("100");
    h.run();
    assert_eq!(spans(&h), [100.0, 80.0, 110.0, 70.0]);
    let swing = |h: &Harness<'static, LinkageApp>| {
        let lane = &h.state().state.session.curves().timing.lanes[0];
        (lane.range[1] - lane.range[0]).to_degrees()
    };
    assert!((swing(&h) - 8.0).abs() < 1e-9);
    h.get_by_role_and_label(Role::TextInput, "lift (°)")
        .set_text_value_accesskit("10");
    h.run();
    assert!((swing(&h) - 10.0).abs() < 1e-9, "{}", swing(&h));
    h.get_by_role_and_label(Role::TextInput, "segment 2 angle (°)")
        .set_text_value_accesskit("200");
    h.run();
    // Past what it and the next segment hold together: refused with that range.
    assert!(
        h.query_by_label_contains("segment 2 angle (°): 200° is outside the range 0 … 190°")
            .is_some(),
        "no refusal with its range"
    );
    assert_eq!(spans(&h), [100.0, 80.0, 110.0, 70.0]);
    h.get_by_role_and_label(Role::Button, "Cam limits").click();
    h.run();
    h.snapshot("paper_cup_cam_feed_cam_limits");
    h.get_by_role_and_label(Role::Button, "Cam s v a j").click();
    h.run();
    h.snapshot("paper_cup_cam_feed_cam_motion");
    for _ in 0..2 {
        h.state_mut()
            .state
            .edit(linkage_lab::session::SceneEdit::Undo);
        h.run();
    }
    assert_eq!(spans(&h), [110.0, 70.0, 110.0, 70.0]);
    assert!((swing(&h) - 8.0).abs() < 1e-9);
}

#[test]
fn an_edit_shows_in_the_view_in_the_frame_that_makes_it() {
    let mut h = harness();
    for key in ["slider_crank", "die_cutter"] {
        open_scene(&mut h, key);
        let before = h.state().state.session.generation();
        h.get_by_role_and_label(Role::Slider, CRANK_LABEL)
            .set_value_accesskit(77.0);
        h.step();
        let st = &h.state().state;
        let now = (st.session.generation(), st.session.input_rad());
        assert!((now.1.to_degrees() - 77.0).abs() < 1e-9, "{key}: {now:?}");
        assert_eq!(
            h.state().panels.viewport.drawn,
            Some(now),
            "{key}: the crank, in the same frame"
        );
        let label = st.session.lengths()[0].label.clone();
        let v = st.session.lengths()[0]
            .value(st.session.scene())
            .expect("a length");
        h.get_by_role_and_label(Role::Slider, &label)
            .set_value_accesskit(1.01 * v);
        h.step();
        let st = &h.state().state;
        assert!(st.session.generation() > before, "{key}: rebuilt");
        let now = (st.session.generation(), st.session.input_rad());
        assert_eq!(
            h.state().panels.viewport.drawn,
            Some(now),
            "{key}: a length, in the same frame"
        );
        assert!(
            st.commands.queue.is_empty(),
            "{key}: every edit asked for is applied"
        );
    }
}

#[test]
fn a_dragged_slider_moves_the_pose_each_frame_and_the_report_follows_when_it_stops() {
    let mut h = harness();
    open_scene(&mut h, "slider_crank");
    assert!(h.query_by_label("stroke slider = 100 mm").is_some());
    // Two frames that each carry an edit, as a drag gives: the pose and curves move
    // with each, the report waits.
    for ab in [60.0, 61.0] {
        h.get_by_role_and_label(Role::Slider, "AB")
            .set_value_accesskit(ab);
        h.step();
        let session = &h.state().state.session;
        let value = session.lengths()[0].value(session.scene()).expect("AB");
        assert!((value - ab).abs() < 1e-12, "{value}");
        assert!(
            matches!(session.report_shown(), Shown::Outdated(_)),
            "no report computed in a frame that carries an edit"
        );
    }
    assert!(h.query_by_label("updating…").is_some());
    assert!(h.query_by_label("stroke slider = 100 mm").is_some());
    // The first frame without an edit makes it; the next shows it.
    h.step();
    assert!(matches!(
        h.state().state.session.report_shown(),
        Shown::Current(_)
    ));
    h.run();
    assert!(h.query_by_label("updating…").is_none());
    assert!(h.query_by_label("stroke slider = 122 mm").is_some());
}

/// Phones held upright, a tablet either way, a small desktop window: the screens the
/// issue names (390×844, 430×932, 768×1024, 1024×768) and 800×600.
/// Both polygon figures show at least half of their box on the sheet's Polygons
/// tab (before, on a phone the acceleration polygon was below the fold).
fn both_polygons_in_view(h: &Harness<'static, LinkageApp>, device: &str) {
    use linkage_lab::ui::control_map::ControlKind;
    let figures: Vec<_> = h
        .state()
        .state
        .controls
        .of_kind(ControlKind::Figure)
        .map(|e| (e.label.clone(), e.visible))
        .collect();
    assert_eq!(figures.len(), 2, "{device}: {figures:?}");
    assert!(
        figures.iter().all(|(_, shown)| *shown),
        "{device}: a polygon is out of view: {figures:?}"
    );
}

const DEVICES: [(&str, f32, f32); 5] = [
    ("phone_390x844", 390.0, 844.0),
    ("phone_430x932", 430.0, 932.0),
    ("tablet_768x1024", 768.0, 1024.0),
    ("tablet_1024x768", 1024.0, 768.0),
    ("window_800x600", 800.0, 600.0),
];

/// Regression (issue 22, finding 5): at 390×844 the desktop panels sat side by side
/// and the mechanism view was a strip about 100 px wide. On every device size the
/// view takes at least half the screen; every tab of the sheet (controls, polygons,
/// plots, report, accuracy) is there and shows; every control a finger touches is at
/// least 40 points high; and each device's controls are kept as a picture.
#[test]
fn phones_and_tablets_give_the_view_half_the_screen_and_reach_every_panel() {
    use linkage_lab::ui::control_map::ControlKind;
    use linkage_lab::ui::layout::SheetTab;
    // One set of snapshot results over the harnesses, as kittest asks.
    let mut snapshots = egui_kittest::SnapshotResults::new();
    for (name, w, hgt) in DEVICES {
        let mut h = common::sized_harness(w, hgt);
        h.run();
        h.run();
        let st = &h.state().state;
        let [x0, y0, x1, y1] = st.controls.view.expect("the view is drawn");
        let share = (x1 - x0) * (y1 - y0) / (w * hgt);
        assert!(
            share >= 0.5,
            "{name}: the view has {share:.2} of the screen"
        );
        for e in st.controls.entries.iter().filter(|e| e.visible) {
            let touched = matches!(
                e.kind,
                ControlKind::Play
                    | ControlKind::Crank
                    | ControlKind::Length
                    | ControlKind::Branch
                    | ControlKind::SheetTab
                    | ControlKind::Menu
                    | ControlKind::History
                    | ControlKind::ScenePicker
            );
            if touched {
                let height = e.rect[3] - e.rect[1];
                assert!(
                    height >= 40.0 - 0.5,
                    "{name}: {:?} {} is {height} high",
                    e.kind,
                    e.label
                );
            }
        }
        h.snapshot(format!("{name}_controls"));
        for tab in SheetTab::ALL {
            let entry = h
                .state()
                .state
                .controls
                .entries
                .iter()
                .find(|e| e.kind == ControlKind::SheetTab && e.label == tab.label())
                .cloned()
                .unwrap_or_else(|| panic!("{name}: no {} tab", tab.label()));
            let [a, b, c, d] = entry.rect;
            common::click(&mut h, egui::pos2(0.5 * (a + c), 0.5 * (b + d)));
            h.run();
            assert_eq!(h.state().state.layout.tab, tab, "{name}");
            if tab == SheetTab::Polygons {
                both_polygons_in_view(&h, name);
            }
            if name == "phone_390x844" && tab != SheetTab::Controls {
                h.snapshot(format!("{name}_{}", tab.label().to_lowercase()));
            }
        }
        scene_list_fits(&mut h, name, w);
        if name == "phone_390x844" {
            phone_menu_and_synthesis(&mut h);
        }
        snapshots.extend_harness(&mut h);
    }
}

/// The scene picker's list lies within the screen, every scene in it whole (a
/// phone's screen is narrower than the longest name: the list wraps them).
fn scene_list_fits(h: &mut Harness<'static, LinkageApp>, name: &str, width: f32) {
    use linkage_lab::ui::control_map::ControlKind;
    let picker = h
        .state()
        .state
        .controls
        .of_kind(ControlKind::ScenePicker)
        .next()
        .cloned()
        .expect("a scene picker");
    let [a, b, c, d] = picker.rect;
    common::click(h, egui::pos2(0.5 * (a + c), 0.5 * (b + d)));
    h.run();
    let items: Vec<_> = h
        .state()
        .state
        .controls
        .of_kind(ControlKind::SceneItem)
        .cloned()
        .collect();
    assert!(!items.is_empty(), "{name}: the scene list did not open");
    for e in items {
        let [x0, _, x1, _] = e.rect;
        assert!(
            e.visible && x0 >= 0.0 && x1 <= width,
            "{name}: \"{}\" lies at {x0}..{x1} of {width} points (visible: {})",
            e.label,
            e.visible
        );
    }
    if name == "phone_390x844" {
        h.snapshot(format!("{name}_scenes"));
    }
    h.key_press(egui::Key::Escape);
    h.run();
}

/// The phone's menu holds the top bar's other actions; the synthesis window it opens
/// fits the screen's width.
fn phone_menu_and_synthesis(h: &mut Harness<'static, LinkageApp>) {
    use linkage_lab::ui::control_map::ControlKind;
    let at = |h: &Harness<'static, LinkageApp>, kind: ControlKind, label: &str| {
        let e = h
            .state()
            .state
            .controls
            .entries
            .iter()
            .find(|e| e.kind == kind && e.label == label && e.visible)
            .cloned()
            .unwrap_or_else(|| panic!("no {kind:?} {label}"));
        let [a, b, c, d] = e.rect;
        assert!(d - b >= 40.0 - 0.5, "{label} is {} high", d - b);
        egui::pos2(0.5 * (a + c), 0.5 * (b + d))
    };
    let menu = at(h, ControlKind::Menu, "Menu");
    common::click(h, menu);
    h.run();
    for label in [
        "Open scene…",
        "Save scene…",
        "Export CSV…",
        "New…",
        "Synthesis…",
    ] {
        at(h, ControlKind::FileButton, label);
    }
    h.snapshot("phone_390x844_menu");
    let synthesis = at(h, ControlKind::FileButton, "Synthesis…");
    common::click(h, synthesis);
    h.run();
    h.run();
    assert!(h.state().panels.synthesis.is_open());
    h.snapshot("phone_390x844_synthesis");
}

/// The equation tables name each group as the user knows it, by its links and
/// joint ("link_ce and die, joined at E"), not by the solver's dyad kind ("RRP dyad
/// (link_ce, die) at E", as they did before issue 32).
#[test]
fn the_equation_tables_name_groups_by_their_links_not_dyad_kinds() {
    let mut h = common::stateful_harness();
    h.get_by_label("Velocity polygon: vector equations").click();
    common::settle(&mut h);
    assert!(
        h.query_all_by_label_contains("joined at").next().is_some(),
        "no group named by its joint"
    );
    let dyads: Vec<String> = h
        .query_all_by_label_contains(" dyad (")
        .map(|n| format!("{n:?}"))
        .collect();
    assert!(dyads.is_empty(), "a dyad kind in the tables: {dyads:?}");
}
