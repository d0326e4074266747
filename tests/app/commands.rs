//! One edit path (issue 32, item 3): every change of the session goes through the
//! app's one command queue, applied between panels, and each kind does what a change
//! of its kind must wherever it was asked for. Opening a scene (a file, a built-in, a
//! template, a link, a design) and a drawing's edit replace the session: play stops,
//! the scene edits still queued for the old session are dropped, and the new history
//! starts empty (a drawing's edits are undone in the drawing). A scene edit is undoable
//! and leaves play running. Over unsaved edits, opening asks first.

use egui_kittest::Harness;
use linkage_lab::LinkageApp;
use linkage_lab::command::Command;
use linkage_lab::drawing::edit::{Body, DrawingEdit};
use linkage_lab::session::{SceneEdit, SceneSource, Session};

use crate::common;

/// The app on the slider-crank, playing, after `change` and then an edit of the old
/// scene were asked for in the same frame.
fn playing_then(change: Command) -> Harness<'static, LinkageApp> {
    let mut h = common::stateful_harness();
    let slider_crank = Session::open_builtin("slider_crank").expect("opens");
    common::open_dropping_edits(&mut h.state_mut().state, slider_crank);
    h.run();
    let st = &mut h.state_mut().state;
    st.play.playing = true;
    st.push(change);
    // Asked by a panel laid out after the change: meant for the scene it saw.
    st.edit(SceneEdit::Input { deg: 33.0 });
    // Two frames: a playing app never settles.
    h.run_steps(2);
    h
}

/// The ways a user opens a scene, each as the panel that opens it builds it.
fn scenes_to_open() -> Vec<(&'static str, Session)> {
    let template = &linkage_lab::catalog::TEMPLATES[0];
    let text = linkage_lab::catalog::builtin("quick_return").expect("shipped");
    let design = Session::open_builtin("paper_cup_feed")
        .expect("opens")
        .scene()
        .clone();
    let open = |source, text| Session::open_text(source, text).expect("opens");
    vec![
        (
            "built-in",
            Session::open_builtin("die_cutter").expect("opens"),
        ),
        (
            "template",
            open(SceneSource::File("t.ron".into()), template.text),
        ),
        ("file", open(SceneSource::File("q.ron".into()), text.text)),
        (
            "design",
            Session::open_scene(SceneSource::File("synthesized.ron".into()), design)
                .expect("opens"),
        ),
    ]
}

#[test]
fn opening_a_scene_stops_play_drops_the_old_scenes_edits_and_starts_a_fresh_history() {
    for (how, session) in scenes_to_open() {
        let name = session.scene().name.clone();
        let h = playing_then(Command::Open(Box::new(session)));
        let st = &h.state().state;
        assert_eq!(st.session.scene().name, name, "{how}: opened");
        assert!(!st.play.playing, "{how}: play stops");
        assert_eq!(
            st.session.edit_count(),
            0,
            "{how}: the old scene's edit lands"
        );
        assert!(!st.session.is_dirty(), "{how}: opens edited");
        assert!(
            !st.session.can_undo(),
            "{how}: undo reaches into the old scene"
        );
        assert!(st.commands.queue.is_empty() && st.commands.waiting.is_none());
    }
}

#[test]
fn a_drawing_edit_stops_play_drops_the_old_scenes_edits_and_is_undone_in_the_drawing() {
    let mut h = common::stateful_harness();
    let slider_crank = Session::open_builtin("slider_crank").expect("opens");
    common::open_dropping_edits(&mut h.state_mut().state, slider_crank);
    h.state_mut().state.push(Command::DrawCurrent);
    h.run();
    let before = h.state().state.session.scene().clone();
    assert!(
        h.state().state.drawing.is_some(),
        "the scene became a drawing"
    );

    let st = &mut h.state_mut().state;
    st.play.playing = true;
    st.push(Command::Drawing(DrawingEdit::SetMass(
        Body::Link(1),
        Some(2.5),
    )));
    st.edit(SceneEdit::Input { deg: 33.0 });
    h.run_steps(2);
    let st = &h.state().state;
    assert_ne!(
        st.session.scene(),
        &before,
        "the drawing's edit reaches the scene"
    );
    assert!(!st.play.playing, "play stops");
    assert_eq!(st.session.edit_count(), 0, "the old scene's edit lands");

    h.state_mut().state.push(Command::Undo);
    h.run();
    let st = &h.state().state;
    assert_eq!(
        st.session.scene(),
        &before,
        "undo takes the drawing's edit back"
    );
    assert!(st.drawing.as_ref().is_some_and(|d| d.can_redo()));
    h.state_mut().state.push(Command::Redo);
    h.run();
    assert_ne!(
        h.state().state.session.scene(),
        &before,
        "redo makes it again"
    );
}

#[test]
fn a_scene_edit_keeps_play_running_and_is_undoable() {
    let mut h = common::stateful_harness();
    let slider_crank = Session::open_builtin("slider_crank").expect("opens");
    common::open_dropping_edits(&mut h.state_mut().state, slider_crank);
    h.run();
    let opened = h.state().state.session.scene().clone();
    let st = &mut h.state_mut().state;
    st.play.playing = true;
    st.edit(SceneEdit::Length {
        index: 1,
        value: 61.0,
    });
    h.run_steps(2);
    let st = &h.state().state;
    assert!(st.play.playing, "a length edit stops play");
    assert_ne!(st.session.scene(), &opened);
    h.state_mut().state.push(Command::Undo);
    h.run_steps(2);
    assert_eq!(h.state().state.session.scene(), &opened, "undo");
}

#[test]
fn over_unsaved_edits_opening_or_drawing_asks_and_the_answer_decides() {
    let mut h = common::stateful_harness();
    let longer = h.state().state.session.lengths()[0].original * 1.01;
    h.state_mut().state.edit(SceneEdit::Length {
        index: 0,
        value: longer,
    });
    h.run();
    assert!(h.state().state.session.is_dirty());
    let edited = h.state().state.session.scene().clone();
    for change in [
        Command::Open(Box::new(
            Session::open_builtin("paper_cup_feed").expect("opens"),
        )),
        Command::StartDrawing,
    ] {
        h.state_mut().state.push(change);
        h.run();
        let st = &h.state().state;
        assert!(st.commands.waiting.is_some(), "asks first");
        assert_eq!(
            st.session.scene(),
            &edited,
            "nothing replaced before the answer"
        );
        h.state_mut().state.push(Command::Answer(false));
        h.run();
        let st = &h.state().state;
        assert!(st.commands.waiting.is_none() && st.drawing.is_none());
        assert_eq!(st.session.scene(), &edited, "kept");
    }
    h.state_mut().state.push(Command::StartDrawing);
    h.state_mut().state.push(Command::Answer(true));
    h.run();
    assert!(h.state().state.drawing.is_some(), "the drawing starts");
}
