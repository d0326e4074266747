//! Undo and redo, as a user meets them: a slider drag is one undo step; undo goes back
//! to the scene as opened and redo forward to the last edit, exactly; the Undo button
//! and Ctrl+Z / Ctrl+Shift+Z / Ctrl+Y do it; the top bar marks unsaved edits, and
//! opening another scene over them asks first.

use eframe::egui;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage_lab::session::{SceneEdit, Session};
use linkage_lab::{LinkageApp, StartOptions};

fn harness() -> Harness<'static, LinkageApp> {
    let mut h = Harness::builder()
        .with_size(egui::vec2(1500.0, 950.0))
        .build_eframe(|cc| LinkageApp::new(cc, StartOptions::default()));
    h.state_mut().state.timing.show = false;
    h.run();
    h
}

#[test]
fn a_drag_is_one_step_and_undo_redo_walk_the_whole_history_exactly() {
    let mut s = Session::open_builtin("slider_crank").expect("opens");
    let opened = s.scene().clone();
    // A drag: three edits of one length without the gesture ending.
    for v in [60.0, 61.0, 62.0] {
        s.apply(SceneEdit::Length { index: 1, value: v });
    }
    let dragged = s.scene().clone();
    s.end_gesture();
    s.apply(SceneEdit::FlipBranch {
        point: String::from("C"),
    });
    s.end_gesture();
    let flipped = s.scene().clone();
    assert_ne!(flipped, dragged);
    assert!(s.is_dirty());

    s.apply(SceneEdit::Undo);
    assert_eq!(s.scene(), &dragged);
    s.apply(SceneEdit::Undo);
    assert_eq!(s.scene(), &opened, "one undo takes the whole drag back");
    assert!(!s.can_undo() && !s.is_dirty());
    s.apply(SceneEdit::Redo);
    s.apply(SceneEdit::Redo);
    assert_eq!(s.scene(), &flipped);
    assert!(!s.can_redo());
    // A new edit after an undo drops what was undone.
    s.apply(SceneEdit::Undo);
    s.end_gesture();
    s.apply(SceneEdit::Length {
        index: 1,
        value: 70.0,
    });
    assert!(!s.can_redo());
}

#[test]
fn a_refused_edit_is_not_an_undo_step() {
    let mut s = Session::open_builtin("slider_crank").expect("opens");
    s.apply(SceneEdit::Input { deg: 90.0 });
    // A rod of 10 mm cannot reach the guide from a crank of 50 mm standing upright.
    s.apply(SceneEdit::Length {
        index: 1,
        value: 10.0,
    });
    assert!(s.message().is_some(), "an unassemblable length is refused");
    assert!(!s.can_undo());
}

#[test]
fn buttons_and_shortcuts_undo_and_redo() {
    let mut h = harness();
    let opened = h.state().state.session.scene().clone();
    h.state_mut().state.session.apply(SceneEdit::Length {
        index: 0,
        value: 500.0,
    });
    h.run();
    let edited = h.state().state.session.scene().clone();
    assert_ne!(edited, opened);
    assert!(h.query_by_label("(edited)").is_some());

    h.get_by_role_and_label(Role::Button, "Undo").click();
    h.run();
    assert_eq!(h.state().state.session.scene(), &opened);
    assert!(h.query_by_label("(edited)").is_none());
    h.get_by_role_and_label(Role::Button, "Redo").click();
    h.run();
    assert_eq!(h.state().state.session.scene(), &edited);

    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(h.state().state.session.scene(), &opened, "Ctrl+Z");
    h.key_press_modifiers(
        egui::Modifiers::COMMAND | egui::Modifiers::SHIFT,
        egui::Key::Z,
    );
    h.run();
    assert_eq!(h.state().state.session.scene(), &edited, "Ctrl+Shift+Z");
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Y);
    h.run();
    assert_eq!(h.state().state.session.scene(), &edited, "Ctrl+Y");
}

#[test]
fn opening_another_scene_over_unsaved_edits_asks_first() {
    let mut h = harness();
    h.state_mut().state.session.apply(SceneEdit::Length {
        index: 0,
        value: 500.0,
    });
    h.run();
    let edited = h.state().state.session.scene().clone();
    let other = Session::open_builtin("slider_crank").expect("opens");
    h.state_mut().state.open(other);
    h.run();
    assert!(
        h.query_by_label_contains("has edits that are not saved")
            .is_some()
    );
    h.get_by_role_and_label(Role::Button, "Keep editing")
        .click();
    h.run();
    assert_eq!(h.state().state.session.scene(), &edited, "kept");
    assert!(h.state().state.commands.waiting.is_none());

    h.state_mut()
        .state
        .open(Session::open_builtin("slider_crank").expect("opens"));
    h.run();
    h.get_by_role_and_label(Role::Button, "Drop the edits and open")
        .click();
    h.run();
    assert_eq!(
        h.state().state.session.scene().name,
        "Slider-crank (in-line)"
    );
}
