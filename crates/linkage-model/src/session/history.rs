//! Undo and redo of the edits to a scene. Each entry keeps the whole scene as it was
//! before an edit (a scene is a few kB, so snapshots are exact and simple, where
//! inverse edits would have to be written and tested per kind), with the crank angle
//! then, so that an undone edit can be rebuilt where it assembled.
//!
//! A slider drag makes an edit per frame; those with the same target in one gesture
//! (until the app says the gesture ended: a frame without an edit) make one entry,
//! so one undo takes the whole drag back.

use linkage::SceneFile;

/// What an edit changed: consecutive edits of one target in one gesture merge.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EditTarget {
    /// A length, by parameter index.
    Length(usize),
    /// A spring constant, by spring index.
    Spring(usize),
    /// A link's mass, by link index.
    Mass(usize),
    /// The assembly branch at a point.
    Branch(String),
    /// A point moved (dragged in the editor).
    Point(String),
    /// A cam joint's program or roller, by its index.
    Cam(usize),
    /// Everything put back as opened.
    Reset,
    /// A whole scene put in place (a synthesized design).
    Replaced,
}

/// A scene as it was, and where the crank stood.
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// The scene.
    pub scene: SceneFile,
    /// The input angle then, rad.
    pub input_rad: f64,
}

/// The undo and redo stacks.
#[derive(Clone, Debug, Default)]
pub struct History {
    undo: Vec<(EditTarget, Snapshot)>,
    redo: Vec<(EditTarget, Snapshot)>,
    /// The target of the gesture in progress, whose later edits merge into its entry.
    open: Option<EditTarget>,
}

/// Most entries kept: older ones are dropped (about 5 MB of the largest shipped scene).
pub const MAX_ENTRIES: usize = 1000;

impl History {
    /// Notes that an edit of `target` is about to replace `before`.
    pub fn record(&mut self, target: EditTarget, before: Snapshot) {
        if self.open.as_ref() == Some(&target) {
            return;
        }
        self.undo.push((target.clone(), before));
        if self.undo.len() > MAX_ENTRIES {
            self.undo.remove(0);
        }
        self.redo.clear();
        self.open = Some(target);
    }

    /// Ends the gesture in progress: the next edit starts a new entry.
    pub fn end_gesture(&mut self) {
        self.open = None;
    }

    /// The scene an undo would put back.
    pub fn to_undo(&self) -> Option<&Snapshot> {
        self.undo.last().map(|(_, s)| s)
    }

    /// The scene a redo would put back.
    pub fn to_redo(&self) -> Option<&Snapshot> {
        self.redo.last().map(|(_, s)| s)
    }

    /// Moves the last entry to the redo stack, `now` being what it replaced.
    pub fn undone(&mut self, now: Snapshot) {
        if let Some((target, _)) = self.undo.pop() {
            self.redo.push((target, now));
        }
        self.open = None;
    }

    /// Moves the last undone entry back, `now` being what it replaced.
    pub fn redone(&mut self, now: Snapshot) {
        if let Some((target, _)) = self.redo.pop() {
            self.undo.push((target, now));
        }
        self.open = None;
    }

    /// Whether there is an edit to undo.
    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    /// Whether there is an undone edit to redo.
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }
}
