//! What the panels ask of the model, as data: every change of the session (a scene
//! edit, a drawing edit, opening a scene, starting or leaving a drawing, undo and
//! redo) is a [`Command`] queued while the panels are laid out and applied between
//! them (`AppState::apply_commands`), as egui's and rerun's apps queue theirs, so that
//! no panel sees the session change under it and every kind of change does what a
//! change of its kind must (stop play, drop edits meant for the old scene, refit).

use linkage::drawing::Drawing;

use crate::drawing::edit::DrawingEdit;
use crate::i18n::tr;
use crate::session::{SceneEdit, Session};

/// One change of the model a panel asks for.
pub enum Command {
    /// An edit of the open scene (sliders, fields, branches, points, cams, a
    /// synthesised design replacing the scene): undoable in the scene's history.
    Edit(SceneEdit),
    /// Open another scene (a file, a built-in, a template, a link, a design): over
    /// unsaved edits the user is asked first.
    Open(Box<Session>),
    /// Start an empty drawing; over unsaved edits the user is asked first.
    StartDrawing,
    /// The open scene, in its current pose, as a drawing to edit.
    DrawCurrent,
    /// Go on with a drawing kept over a reload.
    ResumeDrawing(Box<Drawing>),
    /// An edit of the drawing, which opens as the scene when it is a mechanism.
    Drawing(DrawingEdit),
    /// Leave the drawing tools; the last complete drawing stays open as the scene.
    FinishDrawing,
    /// Take back the last edit: the drawing's while drawing, else the scene's.
    Undo,
    /// Make the last undone edit again, likewise.
    Redo,
    /// The user's answer to the question over unsaved edits: `true` drops them and
    /// does what waits ([`Waiting`]), `false` keeps them.
    Answer(bool),
}

/// A change that would drop unsaved edits, waiting for the user's answer.
pub enum Waiting {
    /// A scene to open.
    Open(Box<Session>),
    /// A new, empty drawing.
    Drawing,
}

impl Waiting {
    /// What the change does, for the question ("Open \"Die cutter\"").
    pub fn describe(&self) -> String {
        match self {
            Self::Open(s) => tr!("unsaved.open_scene", name = s.scene().name),
            Self::Drawing => tr!("unsaved.new_drawing"),
        }
    }
}
