//! The machine in the app: the flywheel tab of the plot pane shows the energy
//! method's figures for the scene, the same as the solver's, with the torque and the
//! work surplus plotted.

use eframe::egui::accesskit::Role;
use egui_kittest::kittest::Queryable as _;
use linkage::machine::size_flywheel;
use linkage::{Kinematics, Mechanism};
use linkage_diagram::numbers::{si, significant};

use crate::common;
use crate::ui::open_scene;

#[test]
fn the_flywheel_tab_shows_the_die_cutters_flywheel() {
    let mut h = common::app_harness();
    h.run();
    open_scene(&mut h, "die_cutter");
    let mut k = open_tab(&mut h, "Flywheel");
    let sized = size_flywheel(&mut k, 0.05).expect("sized");
    let shown = format!("J_F = {} kg·m²", significant(sized.flywheel_kg_m2, 4));
    assert_shown(&h, &shown);
    h.snapshot("die_cutter_flywheel_tab");
}

/// Opens the plot tab `tab` and lets its figures be computed (at the end of a frame
/// without an edit); the scene's kinematics, to compute them again here.
fn open_tab(
    h: &mut egui_kittest::Harness<'static, linkage_lab::LinkageApp>,
    tab: &str,
) -> Kinematics {
    h.get_by_role_and_label(Role::Button, tab).click();
    for _ in 0..4 {
        h.run();
    }
    let scene = h.state().state.session.scene().clone();
    Kinematics::new(Mechanism::from_scene(&scene).expect("valid")).expect("k")
}

/// The tab shows the text `shown`.
fn assert_shown(h: &egui_kittest::Harness<'static, linkage_lab::LinkageApp>, shown: &str) {
    assert!(
        h.query_by_label_contains(shown).is_some(),
        "the tab shows {shown}"
    );
}

/// The app opened on a scene file of `docs/examples`.
fn harness_on_example(file: &str) -> egui_kittest::Harness<'static, linkage_lab::LinkageApp> {
    let path = format!("{}/docs/examples/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("an example");
    let session = linkage_lab::session::Session::open_text(
        linkage_lab::session::SceneSource::File(file.into()),
        &text,
    )
    .expect("opens");
    let mut h = common::app_harness();
    h.run();
    h.state_mut().state.session = session;
    h.run();
    // The view fits a scene the app opens itself; this one was put in its place.
    h.get_by_role_and_label(Role::Button, "Fit view").click();
    h.run();
    h
}

#[test]
fn the_steady_speed_tab_shows_the_die_cutter_with_its_motor() {
    let mut h = harness_on_example("die_cutter_linear_motor.ron");
    let k = open_tab(&mut h, "Speed");
    let st = linkage::machine::steady_state(&k).expect("steady");
    let shown = format!("δ = {:.4}", st.delta);
    assert_shown(&h, &shown);
    h.snapshot("die_cutter_steady_speed_tab");
}

#[test]
fn the_shaking_tab_shows_the_engine_before_and_after_its_counterweight() {
    let mut h = harness_on_example("slider_crank_engine.ron");
    let mut k = open_tab(&mut h, "Shaking");
    let sc = linkage_lab::session::curves::ShakingCurves::compute(&mut k).expect("shaking");
    let shown = format!(
        "peak {} without, {} with",
        si(sc.before.peak_force_n, "N"),
        si(sc.after.peak_force_n, "N")
    );
    assert_shown(&h, &shown);
    h.snapshot("engine_shaking_tab");
}

/// The die cutter driven through its gear train: the flywheel tab says what the
/// train's rotor and shafts already hold at the crank and the flywheel still to fit,
/// on the crank and on the motor shaft, as the solver sizes them.
#[test]
fn the_flywheel_tab_counts_the_drive_trains_inertia() {
    let mut h = harness_on_example("die_cutter_with_train.ron");
    let mut k = open_tab(&mut h, "Flywheel");
    let sized = size_flywheel(&mut k, 0.05).expect("sized");
    let on_motor = sized.flywheel_to_add_on_motor_kg_m2.expect("a drive");
    let shown = format!(
        "{} kg·m² on the crank, {} kg·m² on the motor shaft",
        significant(sized.flywheel_to_add_kg_m2, 4),
        significant(on_motor, 4)
    );
    assert_shown(&h, &shown);
    h.snapshot("die_cutter_with_train_flywheel_tab");
}
