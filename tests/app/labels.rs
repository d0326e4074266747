//! The joints' names in the mechanism view keep clear of every other joint's pin (by
//! its drawn radius, which grows as the view zooms in, and a margin) and of every
//! arrow's tip: every shipped scene at twelve crank angles over its range, with the
//! velocity and acceleration arrows shown, on a desktop, a phone and a tablet zoomed
//! in; as fitted, every arrow ends inside the view. Before, each name sat above and
//! to the right of its pin whatever was there,
//! and at 60° on the die cutter "A" sat beside B's pin; on the phone "A" sat at the
//! tip of C's velocity arrow, zoomed in, names hid under the pins, and the
//! paper-cup feed's slider G moved its arrow off the view at crank 0.

use eframe::egui;
use egui_kittest::Harness;
use linkage_lab::LinkageApp;
use linkage_lab::catalog::BUILTIN_SCENES;
use linkage_lab::render::build::PIN_SHARE;
use linkage_lab::session::{SceneEdit, Session};
use linkage_lab::ui::label_place::{PIN_CLEARANCE, TIP_CLEARANCE};

use crate::common;

/// The screen points of what the names must keep off: every joint's pin (with its
/// name) and every arrow's tip, as the view drew them in the last frame.
struct Drawn {
    pins: Vec<(String, egui::Pos2)>,
    tips: Vec<(String, egui::Pos2)>,
    pin_clearance: f32,
    /// The view's rectangle.
    rect: egui::Rect,
}

fn drawn(h: &Harness<'static, LinkageApp>) -> Drawn {
    let st = &h.state().state;
    let viewport = &h.state().panels.viewport;
    let (camera, scales) = (viewport.camera, viewport.scales);
    let view = st.controls.view.expect("the view");
    let rect = egui::Rect::from_min_max(egui::pos2(view[0], view[1]), egui::pos2(view[2], view[3]));
    let (pose, m) = (st.session.pose(), st.session.mechanism());
    let at = |q: linkage::Vec2| camera.to_screen([q.x, q.y], rect);
    let mut d = Drawn {
        pins: vec![],
        tips: vec![],
        pin_clearance: ((PIN_SHARE * m.size_m * camera.points_per_m) as f32 + 3.0)
            .max(PIN_CLEARANCE),
        rect,
    };
    for &p in &st.session.topology().joint_points {
        let (name, pm) = (m.points[p].name.clone(), &pose.points[p]);
        d.pins.push((name.clone(), at(pm.position)));
        for (v, scale) in [
            (pm.velocity, scales.velocity),
            (pm.acceleration, scales.acceleration),
        ] {
            let tip = at(pm.position + v * scale);
            if scale > 0.0 && tip.distance(at(pm.position)) > 2.0 {
                d.tips.push((name.clone(), tip));
            }
        }
    }
    d
}

/// Checks every name of every shipped scene at twelve crank angles in a window of
/// `size`, zoomed `zoom` times from the fitted view; returns the names checked.
fn check_names(size: egui::Vec2, zoom: f64) -> usize {
    let mut h = common::stateful_sized_harness(size);
    let mut checked = 0;
    for scene in BUILTIN_SCENES {
        let session = Session::open_builtin(scene.key).expect("opens");
        common::open_dropping_edits(&mut h.state_mut().state, session);
        h.state_mut().state.view.layers.accelerations = true;
        h.run_steps(2);
        if zoom != 1.0 {
            let camera = &mut h.state_mut().panels.viewport.camera;
            camera.points_per_m *= zoom;
            camera.by_hand = true;
        }
        let [lo, hi] = h.state().state.session.input_range_deg();
        for k in 0..12 {
            let deg = lo + (hi - lo) * (k as f64 + 0.5) / 12.0;
            h.state_mut().state.edit(SceneEdit::Input { deg });
            h.run_steps(2);
            let d = drawn(&h);
            let place = format!("{} at {deg:.1}° in {size:?} zoomed {zoom}", scene.key);
            for (name, spot) in &h.state().panels.viewport.labels {
                let own = d.pins.iter().find(|(n, _)| n == name).map(|(_, p)| *p);
                for (other, at) in &d.pins {
                    // A pin on top of this one (two joints at one place) is its own.
                    let same_place = own.is_some_and(|o| o.distance(*at) < 2.0);
                    assert!(
                        other == name || same_place || !spot.expand(d.pin_clearance).contains(*at),
                        "{place}: the name {name} covers {other}'s pin"
                    );
                }
                for (whose, tip) in &d.tips {
                    assert!(
                        !spot.expand(TIP_CLEARANCE).contains(*tip),
                        "{place}: the name {name} sits at the tip of {whose}'s arrow"
                    );
                }
                checked += 1;
            }
            // As fitted, every arrow ends in the view (its head too).
            for (whose, tip) in d.tips.iter().filter(|_| zoom == 1.0) {
                assert!(
                    d.rect.shrink(8.0).contains(*tip),
                    "{place}: {whose}'s arrow runs past the view's edge to {tip:?} ({:?})",
                    d.rect
                );
            }
        }
    }
    checked
}

#[test]
fn no_joint_name_covers_another_joints_pin_on_a_desktop() {
    let checked = check_names(egui::vec2(1500.0, 950.0), 1.0);
    assert!(checked > 100, "{checked} names checked");
}

#[test]
fn no_joint_name_covers_a_pin_or_an_arrows_tip_on_a_phone() {
    let checked = check_names(egui::vec2(390.0, 844.0), 1.0);
    assert!(checked > 100, "{checked} names checked");
}

#[test]
fn names_clear_the_pins_drawn_larger_when_zoomed_in() {
    let checked = check_names(egui::vec2(820.0, 1180.0), 3.0);
    assert!(checked > 100, "{checked} names checked");
}

/// The arrows keep one scale through the cycle (a drawing's μv): at most angles the
/// velocity and acceleration scales are the cycle's, a third of the mechanism for
/// its typical largest vector; only an arrow that would leave the view, or pass
/// half the mechanism, draws another. Before, each frame scaled its own largest
/// arrow to a third, and lengths said nothing from one angle to the next.
#[test]
fn the_arrows_keep_one_scale_through_the_cycle() {
    let mut h = common::stateful_harness();
    for scene in BUILTIN_SCENES {
        let session = Session::open_builtin(scene.key).expect("opens");
        common::open_dropping_edits(&mut h.state_mut().state, session);
        h.state_mut().state.view.layers.accelerations = true;
        h.run_steps(2);
        let (size, typical) = {
            let s = &h.state().state.session;
            (s.mechanism().size_m, s.curves().typical_largest)
        };
        let [lo, hi] = h.state().state.session.input_range_deg();
        let mut at_cycle_scale = [0; 2];
        for k in 0..12 {
            let deg = lo + (hi - lo) * (k as f64 + 0.5) / 12.0;
            h.state_mut().state.edit(SceneEdit::Input { deg });
            h.run_steps(2);
            let scales = h.state().panels.viewport.scales;
            for (n, (scale, typical)) in [scales.velocity, scales.acceleration]
                .into_iter()
                .zip(typical)
                .enumerate()
            {
                let cycle = 0.33 * size / typical;
                at_cycle_scale[n] += usize::from((scale - cycle).abs() <= 1e-9 * cycle);
            }
        }
        assert!(
            at_cycle_scale.iter().all(|&n| n >= 8),
            "{}: of 12 angles, {at_cycle_scale:?} at the cycle's scales",
            scene.key
        );
    }
}

/// The points a user reads of in the controls are named on the drawing: a spring's
/// ends ("k F-G"), a length slider's ends ("AH": H, the guide's point) and the marks
/// on moving links (coupler points with their traces). Before, only the joints
/// were: the flipper's F and G, S2 and W, the paper-cup feed's H were nowhere.
#[test]
fn the_springs_ends_and_the_marks_are_named_in_the_view() {
    let mut h = common::stateful_harness();
    let mut named = 0;
    for scene in BUILTIN_SCENES {
        let session = Session::open_builtin(scene.key).expect("opens");
        common::open_dropping_edits(&mut h.state_mut().state, session);
        h.run_steps(2);
        let st = &h.state().state;
        let (m, topology) = (st.session.mechanism(), st.session.topology());
        let springs = st.session.scene().forces.springs.iter();
        let wanted: Vec<String> = springs
            .flat_map(|sp| [sp.a.clone(), sp.b.clone()])
            .chain(topology.marks.iter().map(|&p| m.points[p].name.clone()))
            .chain(
                st.session
                    .lengths()
                    .iter()
                    .flat_map(|l| [l.from.clone(), l.to.clone()]),
            )
            .collect();
        let labels = &h.state().panels.viewport.labels;
        for name in &wanted {
            assert!(
                labels.iter().any(|(n, _)| n == name),
                "{}: {name} is not named in the view",
                scene.key
            );
            named += 1;
        }
    }
    assert!(named >= 4, "{named} points checked");
}
