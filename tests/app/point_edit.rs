//! Moving points, as the editor's drag does: the point lands where it is put at the
//! current crank angle and every other joint stays; a place the chain reaches only on
//! its other branch is refused with the reason and nothing changes; undo takes it back; and a
//! drag with the pointer in the view (move points on) moves the joint under it while
//! a drag elsewhere pans.

use eframe::egui;
use linkage_lab::session::notice::{Notice, PointRefusal};
use linkage_lab::session::{SceneEdit, Session};

use crate::common;
use common::pointer;

fn joints(s: &Session) -> Vec<(String, [f64; 2])> {
    let m = s.mechanism();
    s.topology()
        .joint_points
        .iter()
        .map(|&p| {
            let q = s.pose().points[p].position;
            (m.points[p].name.clone(), [q.x, q.y])
        })
        .collect()
}

#[test]
fn a_moved_point_lands_where_put_and_the_other_joints_stay() {
    for (scene, point) in [
        ("slider_crank", "B"),
        ("die_cutter", "C"),
        ("gravity_flipper", "B"),
        ("paper_cup_feed", "B"),
    ] {
        let mut s = Session::open_builtin(scene).expect("opens");
        let before = joints(&s);
        let (_, at) = before.iter().find(|(n, _)| n == point).expect("joint");
        let size = s.mechanism().size_m;
        let to = [at[0] + 0.01 * size, at[1] - 0.02 * size];
        s.apply(SceneEdit::MovePoint {
            name: String::from(point),
            to_m: to,
        });
        assert_eq!(s.message(), None, "{scene}");
        for ((name, was), (_, now)) in before.iter().zip(joints(&s)) {
            let want = if name == point { to } else { *was };
            let off = (now[0] - want[0]).hypot(now[1] - want[1]);
            assert!(off <= 1e-9 * size, "{scene}: {name} is {off:e} m off");
        }
        s.apply(SceneEdit::Undo);
        assert_eq!(joints(&s), before, "{scene}: undo");
    }
}

#[test]
fn a_place_on_the_other_branch_is_refused() {
    let mut s = Session::open_builtin("gravity_flipper").expect("opens");
    let scene = s.scene().clone();
    // C mirrored across the line B–D: every link carrying C follows it, so the chain
    // still closes at this angle, but on the other assembly branch than the scene's
    // ("left of B->D"), where the solver does not put it.
    let at = |name: &str| {
        let p = s.mechanism().point_index(name).expect("point");
        let q = s.pose().points[p].position;
        [q.x, q.y]
    };
    let (b, c, d) = (at("B"), at("C"), at("D"));
    let u = [d[0] - b[0], d[1] - b[1]];
    let t = ((c[0] - b[0]) * u[0] + (c[1] - b[1]) * u[1]) / (u[0] * u[0] + u[1] * u[1]);
    let foot = [b[0] + t * u[0], b[1] + t * u[1]];
    let mirror = [2.0 * foot[0] - c[0], 2.0 * foot[1] - c[1]];
    s.apply(SceneEdit::MovePoint {
        name: String::from("C"),
        to_m: mirror,
    });
    assert!(
        matches!(
            s.notice(),
            Some(Notice::PointRefused {
                why: PointRefusal::OtherBranch,
                ..
            })
        ),
        "{:?}",
        s.notice()
    );
    let msg = s.message().expect("refused");
    assert!(msg.starts_with("C cannot go to ("), "{msg}");
    assert!(msg.contains("other branch"), "{msg}");
    assert_eq!(s.scene(), &scene);
    assert!(!s.can_undo());
    // The die cutter's die slides on a vertical guide: its pin moves only along it.
    let mut cutter = Session::open_builtin("die_cutter").expect("opens");
    let e = cutter.mechanism().point_index("E").expect("E");
    let q = cutter.pose().points[e].position;
    cutter.apply(SceneEdit::MovePoint {
        name: String::from("E"),
        to_m: [q.x + 0.01, q.y],
    });
    assert!(
        cutter
            .message()
            .expect("refused")
            .contains("only along the guide's line"),
        "{:?}",
        cutter.message()
    );
    cutter.apply(SceneEdit::MovePoint {
        name: String::from("E"),
        to_m: [q.x, q.y + 0.01],
    });
    assert_eq!(cutter.message(), None, "along the guide it moves");
    s.apply(SceneEdit::MovePoint {
        name: String::from("Q"),
        to_m: [0.0, 0.0],
    });
    assert_eq!(s.message().as_deref(), Some("there is no point named Q"));
    s.apply(SceneEdit::MovePoint {
        name: String::from("B"),
        to_m: [f64::NAN, 0.0],
    });
    assert!(s.message().expect("refused").contains("not finite"));
}

#[test]
fn dragging_a_joint_moves_it_and_dragging_elsewhere_pans() {
    let mut h = common::stateful_harness();
    h.state_mut().state.view.edit_points = true;
    h.run();
    let [x0, y0, x1, y1] = h.state().state.controls.view.expect("the view is drawn");
    let rect = egui::Rect::from_min_max(egui::pos2(x0, y0), egui::pos2(x1, y1));
    let st = &h.state().state;
    let c = st.session.mechanism().point_index("C").expect("C");
    let q = st.session.pose().points[c].position;
    let from = h.state().panels.viewport.camera.to_screen([q.x, q.y], rect);
    let to = from + egui::vec2(-40.0, 25.0);
    let scene = st.session.scene().clone();
    pointer(&mut h, from, Some(true));
    for k in 1..=5 {
        pointer(&mut h, from + (to - from) * (k as f32 / 5.0), None);
    }
    pointer(&mut h, to, Some(false));
    let st = &h.state().state;
    assert_eq!(st.session.message(), None);
    assert_ne!(st.session.scene(), &scene, "the drag moved C");
    let q = st.session.pose().points[c].position;
    let landed = h.state().panels.viewport.camera.to_screen([q.x, q.y], rect);
    // The grid (1 mm) and alignment may move it a little from the pointer.
    assert!(
        landed.distance(to) < 8.0,
        "C at {landed:?}, pointer at {to:?}"
    );
    // One undo takes the whole drag back.
    h.state_mut().state.session.apply(SceneEdit::Undo);
    assert_eq!(h.state().state.session.scene(), &scene);

    // A slow frame: the press and 20 points of motion arrive together. The joint is
    // grabbed where the button went down, not where the pointer is by then.
    h.event(egui::Event::PointerMoved(from));
    h.event(egui::Event::PointerButton {
        pos: from,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::default(),
    });
    h.event(egui::Event::PointerMoved(from + egui::vec2(20.0, 0.0)));
    h.run();
    pointer(&mut h, from + egui::vec2(20.0, 0.0), Some(false));
    assert_ne!(
        h.state().state.session.scene(),
        &scene,
        "a quick drag moves C too"
    );
    h.state_mut().state.session.apply(SceneEdit::Undo);

    // A drag on empty space pans.
    let camera = h.state().panels.viewport.camera;
    let empty = rect.left_bottom() + egui::vec2(30.0, -60.0);
    pointer(&mut h, empty, Some(true));
    pointer(&mut h, empty + egui::vec2(50.0, 0.0), None);
    pointer(&mut h, empty + egui::vec2(50.0, 0.0), Some(false));
    assert_ne!(h.state().panels.viewport.camera, camera, "panned");
    assert_eq!(h.state().state.session.scene(), &scene);
}

#[test]
fn dragging_the_crank_pin_turns_the_crank() {
    let mut h = common::stateful_harness();
    let [x0, y0, x1, y1] = h.state().state.controls.view.expect("the view is drawn");
    let rect = egui::Rect::from_min_max(egui::pos2(x0, y0), egui::pos2(x1, y1));
    let st = &h.state().state;
    let m = st.session.mechanism();
    let pivot = st.session.pose().points[m.revolutes[m.driver.pivot].point].position;
    let pin = m.links[m.driver.link]
        .points
        .iter()
        .map(|&(p, _)| p)
        .find(|&p| p != m.revolutes[m.driver.pivot].point)
        .expect("a crank pin");
    let q = st.session.pose().points[pin].position;
    let before = st.session.input_rad();
    let scene = st.session.scene().clone();
    // The pin carried 30° round the pivot, in five steps.
    let turned = |deg: f64| {
        let (s, c) = deg.to_radians().sin_cos();
        let r = q - pivot;
        h.state().panels.viewport.camera.to_screen(
            [pivot.x + c * r.x - s * r.y, pivot.y + s * r.x + c * r.y],
            rect,
        )
    };
    let path: Vec<egui::Pos2> = (0..=5).map(|k| turned(6.0 * f64::from(k))).collect();
    pointer(&mut h, path[0], Some(true));
    for &p in &path[1..] {
        pointer(&mut h, p, None);
    }
    pointer(&mut h, path[5], Some(false));
    let st = &h.state().state;
    let turned_deg = (st.session.input_rad() - before).to_degrees();
    assert!((turned_deg - 30.0).abs() < 0.5, "turned {turned_deg}°");
    assert_eq!(
        st.session.scene(),
        &scene,
        "turning is not an edit of the scene"
    );
}
