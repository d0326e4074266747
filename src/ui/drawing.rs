//! The app's side of building a mechanism: starting a drawing, making its edits,
//! undo and redo, and opening the drawing as the session each time it is a complete
//! mechanism (so the analyses follow it), unsaved until the user saves it.

use linkage::drawing::Drawing;

use crate::drawing::DrawingEditor;
use crate::drawing::edit::DrawingEdit;
use crate::session::{SceneEdit, SceneSource, Session};
use crate::state::AppState;

/// The file name a drawing is saved and shared under until the user names one.
const DRAWING_FILE: &str = "my_mechanism.ron";

/// Starts an empty drawing. The current scene stays open until the drawing is a
/// mechanism, then the drawing replaces it: over unsaved edits the user is asked
/// first (`ui::scene_picker`'s question).
pub fn start(st: &mut AppState) {
    if st.session.is_dirty() {
        st.commands.drawing = true;
        return;
    }
    start_now(st);
}

/// Starts an empty drawing whatever the current scene holds.
pub fn start_now(st: &mut AppState) {
    resume(st, Drawing::new("My mechanism"));
}

/// The open scene, in its current pose, as a drawing to edit (add and delete links,
/// sliders, points), or the reason it cannot be one in the status line.
pub fn draw_current(st: &mut AppState) {
    let s = &st.session;
    match Drawing::from_pose(s.scene(), s.mechanism(), s.pose()) {
        Ok(drawing) => resume(st, drawing),
        Err(why) => st.status = Some(format!("this scene cannot become a drawing: {why}")),
    }
}

/// Goes on with `drawing` (a drawing kept over a reload), opening it as the scene
/// when it is a mechanism.
pub fn resume(st: &mut AppState, drawing: Drawing) {
    st.commands.drawing = false;
    st.drawing = Some(DrawingEditor::new(drawing));
    sync(st);
    st.play.playing = false;
    st.view.edit_points = false;
}

/// Makes `edit` on the drawing.
pub fn edit(st: &mut AppState, edit: DrawingEdit) {
    // Timed with the frame's other edits: a drag on the canvas is an edit per frame.
    let started = web_time::Instant::now();
    if st.drawing.as_mut().is_some_and(|b| b.apply(edit)) {
        sync(st);
    }
    st.timing.edit_ms += started.elapsed().as_secs_f64() * 1e3;
}

/// Takes back the drawing's last edit.
pub fn undo(st: &mut AppState) {
    if st.drawing.as_mut().is_some_and(DrawingEditor::undo) {
        sync(st);
    }
}

/// Makes the drawing's last undone edit again.
pub fn redo(st: &mut AppState) {
    if st.drawing.as_mut().is_some_and(DrawingEditor::redo) {
        sync(st);
    }
}

/// Undo: of the drawing while drawing, else of the scene's edits.
pub fn undo_any(st: &mut AppState) {
    if st.drawing.is_some() {
        undo(st);
    } else {
        st.edit(SceneEdit::Undo);
    }
}

/// Redo: of the drawing while drawing, else of the scene's edits.
pub fn redo_any(st: &mut AppState) {
    if st.drawing.is_some() {
        redo(st);
    } else {
        st.edit(SceneEdit::Redo);
    }
}

/// Leaves the drawing tools; the last complete drawing stays open as the scene.
pub fn finish(st: &mut AppState) {
    st.drawing = None;
    st.commands.fit = true;
}

/// Opens the drawing as the session when it is a mechanism.
fn sync(st: &mut AppState) {
    let Some(scene) = st.drawing.as_mut().and_then(DrawingEditor::refresh) else {
        return;
    };
    match Session::open_scene(SceneSource::File(DRAWING_FILE.into()), scene) {
        Ok(mut session) => {
            session.mark_unsaved();
            st.session = session;
            st.timing.opened += 1;
        }
        Err(why) => st.status = Some(format!("the drawing does not solve: {why}")),
    }
}
