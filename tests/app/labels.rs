//! The joints' names in the mechanism view keep clear of every other joint's pin
//! (by its drawn radius and a margin, [`PIN_CLEARANCE`]): every
//! shipped scene at twelve crank angles over its range, with the velocity and
//! acceleration arrows shown. Before, each name sat above and to the right of its
//! pin whatever was there, and at 60° on the die cutter "A" sat beside B's pin.

use eframe::egui;
use egui_kittest::Harness;
use linkage_lab::catalog::BUILTIN_SCENES;
use linkage_lab::session::{SceneEdit, Session};
use linkage_lab::ui::label_place::PIN_CLEARANCE;
use linkage_lab::{LinkageApp, StartOptions};

#[test]
fn no_joint_name_covers_another_joints_pin() {
    let mut h = Harness::builder()
        .with_size(egui::vec2(1500.0, 950.0))
        .build_eframe(|cc| LinkageApp::new(cc, StartOptions::default()));
    h.run_steps(2);
    let mut checked = 0;
    for scene in BUILTIN_SCENES {
        let session = Session::open_builtin(scene.key).expect("opens");
        h.state_mut().state.open_now(session);
        h.state_mut().state.view.layers.accelerations = true;
        h.run_steps(2);
        let [lo, hi] = h.state().state.session.input_range_deg();
        for k in 0..12 {
            let deg = lo + (hi - lo) * (k as f64 + 0.5) / 12.0;
            h.state_mut().state.edit(SceneEdit::Input { deg });
            h.run_steps(2);
            let st = &h.state().state;
            let camera = h.state().panels.viewport.camera;
            let view = st.controls.view.expect("the view");
            let rect = egui::Rect::from_min_max(
                egui::pos2(view[0], view[1]),
                egui::pos2(view[2], view[3]),
            );
            let pose = st.session.pose();
            let m = st.session.mechanism();
            for (name, spot) in &h.state().panels.viewport.labels {
                for &p in &st.session.topology().joint_points {
                    let other = &m.points[p].name;
                    let q = pose.points[p].position;
                    let at = camera.to_screen([q.x, q.y], rect);
                    let own = m.point_index(name).map(|i| pose.points[i].position);
                    // A pin on top of this one (two joints at one place) is its own.
                    let same_place =
                        own.is_some_and(|o| (o - q).norm() * camera.points_per_m < 2.0);
                    assert!(
                        other == name || same_place || !spot.expand(PIN_CLEARANCE).contains(at),
                        "{} at {deg:.1}°: the name {name} covers {other}'s pin",
                        scene.key
                    );
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "{checked} names checked");
}
