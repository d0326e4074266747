//! The document: the scene being edited, where it came from, the scene as opened and
//! as last saved, and the undo/redo history of its edits. It knows nothing of the
//! solver: the session builds what a scene means ([`super::pose`], [`super::analyses`]).

use std::cell::OnceCell;

use linkage::SceneFile;
use linkage::share::ShareError;

use super::history::{EditTarget, History, Snapshot};

/// Where the scene came from.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneSource {
    /// A scene shipped in `assets/scenes`, by file name without `.ron`.
    Builtin(String),
    /// A file the user opened, by its name.
    File(String),
}

/// The scene being edited and its history.
pub struct Document {
    source: SceneSource,
    original: SceneFile,
    scene: SceneFile,
    /// The scene as last opened or saved: it differs from `scene` when there are
    /// unsaved edits (`None`: never saved, a drawing).
    saved: Option<SceneFile>,
    history: History,
    /// The scene packed for a link, made when first asked for after an edit.
    share: OnceCell<Result<String, ShareError>>,
}

impl Document {
    /// A document over `scene` as opened from `source`, saved, with no history.
    pub fn new(source: SceneSource, scene: SceneFile) -> Self {
        Self {
            source,
            original: scene.clone(),
            saved: Some(scene.clone()),
            scene,
            history: History::default(),
            share: OnceCell::new(),
        }
    }

    /// Where the scene came from.
    pub fn source(&self) -> &SceneSource {
        &self.source
    }

    /// The scene as edited (what Save writes).
    pub fn scene(&self) -> &SceneFile {
        &self.scene
    }

    /// The scene as opened (slider ranges and URL state are relative to it).
    pub fn original(&self) -> &SceneFile {
        &self.original
    }

    /// Makes `scene` current after an edit of `target`; the scene before it, with
    /// the crank angle `input_rad` it stood at, is kept for undo.
    pub fn commit(&mut self, target: EditTarget, scene: SceneFile, input_rad: f64) {
        let before = self.snapshot(input_rad);
        self.history.record(target, before);
        self.set_scene(scene);
    }

    /// The scene an undo (`back`) or a redo would put back.
    pub fn travel_target(&self, back: bool) -> Option<&Snapshot> {
        if back {
            self.history.to_undo()
        } else {
            self.history.to_redo()
        }
    }

    /// Makes the scene of [`Document::travel_target`] current; the scene it replaces,
    /// at `input_rad`, goes to the other stack.
    pub fn travel(&mut self, back: bool, input_rad: f64) {
        let Some(to) = self.travel_target(back).map(|s| s.scene.clone()) else {
            return;
        };
        let now = self.snapshot(input_rad);
        if back {
            self.history.undone(now);
        } else {
            self.history.redone(now);
        }
        self.set_scene(to);
    }

    fn snapshot(&self, input_rad: f64) -> Snapshot {
        Snapshot {
            scene: self.scene.clone(),
            input_rad,
        }
    }

    fn set_scene(&mut self, scene: SceneFile) {
        self.scene = scene;
        self.share = OnceCell::new();
    }

    /// Whether there is an edit to undo.
    pub fn can_undo(&self) -> bool {
        self.history.can_undo()
    }

    /// Whether there is an undone edit to redo.
    pub fn can_redo(&self) -> bool {
        self.history.can_redo()
    }

    /// Ends the edit gesture in progress (a slider let go): the next edit is a new
    /// undo step.
    pub fn end_gesture(&mut self) {
        self.history.end_gesture();
    }

    /// Whether the scene has edits not saved to a file (or, for a shipped scene, not
    /// in it).
    pub fn is_dirty(&self) -> bool {
        self.saved.as_ref() != Some(&self.scene)
    }

    /// Notes that the scene as it is now has been saved.
    pub fn mark_saved(&mut self) {
        self.saved = Some(self.scene.clone());
    }

    /// Notes that the scene was never saved (a drawing): it counts as unsaved work.
    pub fn mark_unsaved(&mut self) {
        self.saved = None;
    }

    /// The scene packed for a link (`linkage::share`), or why it does not fit.
    pub fn share_payload(&self) -> Result<&str, &ShareError> {
        self.share
            .get_or_init(|| {
                // Writing a scene that was read cannot fail; were it to, the empty
                // link would be refused where it is opened, naming the cause.
                linkage::share::encode(&self.to_ron().unwrap_or_default())
            })
            .as_ref()
            .map(String::as_str)
    }

    /// The scene as RON text.
    ///
    /// # Errors
    /// Serialisation failure.
    pub fn to_ron(&self) -> Result<String, linkage::LinkageError> {
        self.scene.to_ron()
    }
}
