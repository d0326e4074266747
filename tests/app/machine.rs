//! The machine in the app: the flywheel tab of the plot pane shows the energy
//! method's figures for the scene, the same as the solver's, with the torque and the
//! work surplus plotted.

use eframe::egui::accesskit::Role;
use egui_kittest::kittest::Queryable as _;
use linkage::machine::size_flywheel;
use linkage::{Kinematics, Mechanism};

use crate::common;
use crate::ui::open_scene;

#[test]
fn the_flywheel_tab_shows_the_die_cutters_flywheel() {
    let mut h = common::app_harness();
    h.run();
    open_scene(&mut h, "die_cutter");
    h.get_by_role_and_label(Role::Button, "Flywheel").click();
    // The tab's figures are computed at the end of a frame without an edit.
    for _ in 0..4 {
        h.run();
    }
    let scene = h.state().state.session.scene().clone();
    let mut k = Kinematics::new(Mechanism::from_scene(&scene).expect("valid")).expect("k");
    let sized = size_flywheel(&mut k, 0.05).expect("sized");
    let shown = format!("J_F = {:.4e} kg·m²", sized.flywheel_kg_m2);
    assert!(
        h.query_by_label_contains(&shown).is_some(),
        "the tab shows {shown}"
    );
    h.snapshot("die_cutter_flywheel_tab");
}
