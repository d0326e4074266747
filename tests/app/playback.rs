//! One state during playback: the gravity flipper played to its end stop, as a
//! user presses Play and waits, then edited. Before, at the stop the view's legend
//! said "crank 138.60 deg" (the angle of the link the run integrated past the
//! crank's dead point), the crank field 117.658 (that angle clamped to the field's
//! range), the run 35 deg, the force polygons "cannot assemble at input 138.6027
//! deg", and a spring edit was refused in the solver's words.

use eframe::egui;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use linkage_lab::ui::controls::CRANK_LABEL;
use linkage_lab::ui::number_field::format_value;
use linkage_lab::{LinkageApp, StartOptions};

fn flipper() -> Harness<'static, LinkageApp> {
    let mut h = Harness::builder()
        .with_size(egui::vec2(1500.0, 950.0))
        .build_eframe(|cc| {
            let start = StartOptions {
                scene: Some("gravity_flipper".into()),
                ..StartOptions::default()
            };
            LinkageApp::new(cc, start)
        });
    h.run_steps(2);
    h.state_mut().state.session.wait_for_run();
    h.run_steps(2);
    h
}

/// The crank field's text as the user reads it.
fn crank_field(h: &Harness<'static, LinkageApp>) -> String {
    h.get_by_role_and_label(Role::TextInput, CRANK_LABEL)
        .accesskit_node()
        .value()
        .unwrap_or_default()
}

#[test]
fn the_flipper_played_to_its_stop_shows_one_state_and_an_edit_runs_again_from_the_start() {
    let mut h = flipper();
    let end = {
        let run = h.state().state.session.dynamics();
        run.and_then(|r| r.as_ref().ok())
            .expect("the run")
            .duration_s()
    };
    h.get_by_role_and_label(Role::Button, "Play").click();
    // Frames until the run reaches its stop (kittest's frames are 1/60 s apart),
    // paused while it holds there.
    for _ in 0..200 {
        h.run_steps(1);
        if h.state().state.session.time_s() >= end {
            break;
        }
    }
    h.get_by_role_and_label(Role::Button, "Pause").click();
    h.run_steps(2);
    let st = &h.state().state;
    assert!((st.session.time_s() - end).abs() < 1e-12, "not at the stop");
    let crank = st.session.input_rad().to_degrees();
    assert!(
        (crank - 35.0).abs() < 1e-6,
        "the pose's crank at {crank} deg"
    );
    // The view drew that pose; the field shows its angle; the force polygons exist.
    let drawn = h.state().panels.viewport.drawn.expect("drawn").1;
    assert!((drawn.to_degrees() - crank).abs() < 1e-12);
    assert_eq!(crank_field(&h), format_value(crank));
    match h.state().state.session.force_polygons() {
        Some(Ok(_)) => {}
        other => panic!("no force polygons at the stop: {other:?}"),
    }
    // An edit: taken, and the run starts again from its start state.
    h.get_by_role_and_label(Role::TextInput, "k F-G (N/m)")
        .set_text_value_accesskit("1200");
    h.run_steps(2);
    let st = &h.state().state;
    assert_eq!(st.session.message(), None);
    assert_eq!(st.session.scene().forces.springs[0].k_n_per_m, 1200.0);
    assert_eq!(st.session.time_s(), 0.0);
    let start = st.session.mechanism().driver.start_rad.to_degrees();
    assert_eq!(crank_field(&h), format_value(start));
}
