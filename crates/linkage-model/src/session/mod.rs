//! The viewer's model, free of any GUI type, in three parts: the *document* (the
//! scene being edited and its undo history), the *pose* (the solver and the current,
//! always valid, solution with its polygons: cheap, always current) and the
//! *analyses* (curves, report, modelled curves, dynamic run: computed with the edit,
//! when shown, or off the frame). Edits arrive as values ([`SceneEdit`]) and either
//! succeed or leave a typed [`Notice`] and the old state.

pub mod analyses;
mod built;
pub mod cam_curves;
pub mod cam_edit;
pub mod curves;
pub mod derived;
pub mod document;
pub mod dynamic_run;
mod edit;
pub mod edit_cost;
mod exports;
pub mod history;
pub mod limit;
pub mod notice;
mod notice_words;
pub mod params;
mod playback;
mod point_edit;
pub mod pose;
pub mod run_job;
pub mod topology;
pub mod url_state;
pub mod words;

#[cfg(test)]
mod tests;

use linkage::analysis::Report;
use linkage::force_polygon::ForcePolygons;
use linkage::polygon::VectorEquation;
use linkage::scene::Models;
use linkage::{Kinematics, LinkageError, Mechanism, SceneFile, Solution};

use crate::catalog::builtin;
use analyses::Analyses;
pub use analyses::RUN_SLICE_MS;
pub(crate) use built::Built;
use curves::{Curves, ModelCurves};
use derived::Shown;
use document::Document;
pub use document::SceneSource;
use dynamic_run::{DynamicRun, IntegratorChoice};
pub use edit::SceneEdit;
pub use exports::CourseChoice;
use notice::Notice;
use params::{LengthParam, length_params};
use pose::Pose;
use run_job::{RunError, RunJob};
use topology::Topology;
pub use words::unit_label_of;

/// The viewer's state over one scene.
pub struct Session {
    doc: Document,
    pose: Pose,
    analyses: Analyses,
    /// The lengths the sliders set (fixed per opened scene).
    lengths: Vec<LengthParam>,
    message: Option<Notice>,
    /// Playback time of the dynamic run, s.
    time_s: f64,
    /// Whether the crank was moved by hand since a pose of the dynamic run was
    /// shown: the pose is then the chain's at that angle, not the run's at
    /// `time_s`, and no run time goes with it.
    moved_by_hand: bool,
    /// How long playback has held the run's last state, s (it starts again after
    /// half a second).
    held_s: f64,
    /// +1 or −1: the direction of play over a limited input range (it rocks).
    play_direction: f64,
    /// Counts rebuilds: views that cache per mechanism (plot bounds) key on it.
    generation: u64,
    /// Counts edits asked for, taken or refused (the app times the frames they land in).
    edits: u64,
}

/// Why a shipped scene, or the scene an address names, did not open.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum OpenError {
    /// No shipped scene has the key.
    #[error("no built-in scene named {0:?}")]
    NoSuchScene(String),
    /// The scene does not parse or solve.
    #[error(transparent)]
    Scene(#[from] LinkageError),
    /// A share link that carries no scene.
    #[error(transparent)]
    Share(#[from] linkage::share::ShareError),
    /// An address that names no scene.
    #[error("the URL names no scene")]
    NoScene,
}

impl OpenError {
    /// Why the scene did not open, in `lang`.
    pub fn words(&self, lang: linkage_diagram::words::Lang) -> String {
        use linkage_diagram::refusal;
        match self {
            Self::NoSuchScene(key) => words::mw!(lang, "notice.no_such_scene", key = key),
            Self::Scene(e) => refusal::error(lang, e, linkage::scene::LengthUnit::Metre),
            Self::Share(e) => refusal::share(lang, e),
            Self::NoScene => words::mw!(lang, "notice.no_scene"),
        }
    }
}

impl Session {
    /// Opens a shipped scene by key (`die_cutter`, ...).
    ///
    /// # Errors
    /// An unknown key, or a scene that does not solve (a bug in the shipped file).
    pub fn open_builtin(key: &str) -> Result<Self, OpenError> {
        let b = builtin(key).ok_or_else(|| OpenError::NoSuchScene(key.to_string()))?;
        Ok(Self::open_text(
            SceneSource::Builtin(key.to_string()),
            b.text,
        )?)
    }

    /// Opens a scene from its RON text.
    ///
    /// # Errors
    /// The parse error with line and column, or why the mechanism does not assemble.
    pub fn open_text(source: SceneSource, text: &str) -> Result<Self, LinkageError> {
        let scene = SceneFile::parse(text)?;
        Self::open_scene(source, scene)
    }

    /// Opens a scene (a drawing's, or one parsed from a file).
    ///
    /// # Errors
    /// Why the mechanism does not assemble.
    pub fn open_scene(source: SceneSource, scene: SceneFile) -> Result<Self, LinkageError> {
        let built = Built::new(&scene, None, &[])?;
        let mut session = Self {
            lengths: length_params(&scene),
            doc: Document::new(source, scene),
            pose: Pose::new(built.kin, built.pose, built.topology),
            analyses: Analyses::new(built.curves),
            message: None,
            time_s: 0.0,
            moved_by_hand: false,
            held_s: 0.0,
            play_direction: 1.0,
            generation: 0,
            edits: 0,
        };
        session.start_run();
        Ok(session)
    }

    /// The document: the scene, where it came from, and its history.
    pub fn document(&self) -> &Document {
        &self.doc
    }

    /// Where the scene came from.
    pub fn source(&self) -> &SceneSource {
        self.doc.source()
    }

    /// The scene as edited (what Save writes).
    pub fn scene(&self) -> &SceneFile {
        self.doc.scene()
    }

    /// The scene as opened (slider ranges and URL state are relative to it).
    pub fn original(&self) -> &SceneFile {
        self.doc.original()
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &Mechanism {
        self.pose.mechanism()
    }

    /// The solver (for its path and tolerances).
    pub fn kinematics(&self) -> &Kinematics {
        self.pose.kinematics()
    }

    /// Joints and links by index (fixed per mechanism).
    pub fn topology(&self) -> &Topology {
        self.pose.topology()
    }

    /// The current pose: always a valid, solved one.
    pub fn pose(&self) -> &Solution {
        self.pose.solution()
    }

    /// Current input angle, rad.
    pub fn input_rad(&self) -> f64 {
        self.pose().input_rad
    }

    /// The velocity and acceleration polygon equations at the current pose.
    pub fn polygons(&self) -> &[VectorEquation] {
        self.pose.polygons()
    }

    /// The force polygons at the current pose, or why there are none there; `None`
    /// for a kinematics-only scene.
    pub fn force_polygons(&self) -> Option<&Result<ForcePolygons, LinkageError>> {
        self.pose.forces()
    }

    /// The report (Grashof, K, strokes, limits, transmission angle) or why it failed;
    /// computed now if it is not yet.
    pub fn report(&self) -> &Result<Report, LinkageError> {
        self.analyses.report(self.kinematics())
    }

    /// The report as a panel shows it: the current one, or the one from before the
    /// last edit until [`Session::catch_up`] has made the current one.
    pub fn report_shown(&self) -> Shown<'_, Result<Report, LinkageError>> {
        self.analyses.report_shown()
    }

    /// The curves of what the scene models beyond kinematics (input torque; J(q) and
    /// M(q)); computed now if they are not yet.
    pub fn model_curves(&self) -> &ModelCurves {
        self.analyses.model_curves(self.kinematics())
    }

    /// The model curves as a plot shows them (see [`Session::report_shown`]).
    pub fn model_curves_shown(&self) -> Shown<'_, ModelCurves> {
        self.analyses.model_curves_shown()
    }

    /// Computes what a panel showed out of date since the last edit (the app calls it
    /// at the end of a frame that carried no edit). Returns whether it computed
    /// anything (the panels show it next frame).
    pub fn catch_up(&self) -> bool {
        self.analyses.catch_up(self.kinematics())
    }

    /// The curves over the cycle.
    pub fn curves(&self) -> &Curves {
        self.analyses.curves()
    }

    /// The editable lengths.
    pub fn lengths(&self) -> &[LengthParam] {
        &self.lengths
    }

    /// The dynamic run: `None` for scenes that model no dynamics, and while the run is
    /// being computed ([`Session::run_progress`]).
    pub fn dynamics(&self) -> Option<&Result<DynamicRun, RunError>> {
        self.analyses.dynamics()
    }

    /// While the dynamic run is being computed: the simulated time reached and the
    /// run's end time, s.
    pub fn run_progress(&self) -> Option<[f64; 2]> {
        self.analyses.run_progress()
    }

    /// Advances the dynamic run being computed (where it runs on this thread, for
    /// `slice_ms`, at most [`RUN_SLICE_MS`]) and takes its result when it is done.
    /// Returns whether a run is still being computed (the caller asks for another
    /// frame).
    pub fn poll_run(&mut self, slice_ms: f64) -> bool {
        if self.analyses.poll_run(slice_ms) {
            self.run_finished();
        }
        self.analyses.running()
    }

    /// Waits until the dynamic run being computed is done (tests, exports).
    pub fn wait_for_run(&mut self) {
        if self.analyses.wait_for_run() {
            self.run_finished();
        }
    }

    /// Computes the dynamic run on this thread, sliced as in the browser, instead of
    /// on a worker thread.
    pub fn run_sliced(&mut self) {
        let models = self.models();
        self.analyses
            .start_run(self.pose.kinematics(), models, RunJob::start_sliced);
    }

    /// The integrator settings of the dynamic run.
    pub fn integrator(&self) -> IntegratorChoice {
        self.analyses.integrator()
    }

    /// Playback time of the dynamic run, s.
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// The dynamic run's time whose pose is shown, s; `None` in a scene without a
    /// run, or with the crank moved by hand since (the pose is then no state of the
    /// run: the flipper's legend said "t = 0.000 s" at any angle the slider set).
    pub fn run_time_shown(&self) -> Option<f64> {
        let run = matches!(self.analyses.dynamics(), Some(Ok(_)));
        (run && !self.moved_by_hand).then_some(self.time_s)
    }

    /// How many times the mechanism was rebuilt by edits (0 as opened).
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// How many edits were asked for (crank angle, lengths, springs, masses, branches,
    /// integrator, reset), taken or refused.
    pub fn edit_count(&self) -> u64 {
        self.edits
    }

    /// What the last edit could not do, and why, in English (made here, when shown).
    pub fn message(&self) -> Option<String> {
        self.message_in(linkage_diagram::words::Lang::English)
    }

    /// What the last edit could not do, and why, in `lang`.
    pub fn message_in(&self, lang: linkage_diagram::words::Lang) -> Option<String> {
        let unit = self.scene().length_unit;
        self.message.as_ref().map(|n| n.words(unit, lang))
    }

    /// What the last edit could not do, as data.
    pub fn notice(&self) -> Option<&Notice> {
        self.message.as_ref()
    }

    /// What the scene models.
    pub fn models(&self) -> Models {
        self.scene().models
    }

    /// The assembly branches of the chain, by the point of each dyad: (point, its
    /// branch, whether it differs from the scene as opened). The app words the
    /// branch in the user's language ([`branch_words`] in English).
    pub fn branches(&self) -> Vec<(String, linkage::scene::Branch, bool)> {
        let m = self.mechanism();
        m.branches
            .iter()
            .map(|(p, b)| {
                let name = m.points[*p].name.clone();
                let flipped = self
                    .original()
                    .branches
                    .get(&name)
                    .is_some_and(|orig| orig != b);
                (name, b.clone(), flipped)
            })
            .collect()
    }

    /// Whether there is an edit to undo.
    pub fn can_undo(&self) -> bool {
        self.doc.can_undo()
    }

    /// Whether there is an undone edit to redo.
    pub fn can_redo(&self) -> bool {
        self.doc.can_redo()
    }

    /// Ends the edit gesture in progress (a slider let go): the next edit is a new
    /// undo step.
    pub fn end_gesture(&mut self) {
        self.doc.end_gesture();
    }

    /// Whether the scene has edits not saved to a file (or, for a shipped scene, not
    /// in it).
    pub fn is_dirty(&self) -> bool {
        self.doc.is_dirty()
    }

    /// Notes that the scene as it is now has been saved.
    pub fn mark_saved(&mut self) {
        self.doc.mark_saved();
    }

    /// Notes that the scene was never saved (a drawing): it counts as unsaved work.
    pub fn mark_unsaved(&mut self) {
        self.doc.mark_unsaved();
    }

    /// The edited scene packed for a link (`linkage::share`), or why it does not fit.
    pub fn share_payload(&self) -> Result<&str, &linkage::share::ShareError> {
        self.doc.share_payload()
    }

    /// The edited scene as RON text.
    ///
    /// # Errors
    /// Serialisation failure.
    pub fn to_ron(&self) -> Result<String, LinkageError> {
        self.doc.to_ron()
    }

    /// Starts computing the dynamic run of a dynamic scene off the frame; the
    /// previous run, finished or not, is dropped.
    fn start_run(&mut self) {
        let models = self.models();
        self.analyses
            .start_run(self.pose.kinematics(), models, RunJob::start);
    }

    fn run_finished(&mut self) {
        self.generation += 1;
        self.time_s = 0.0;
    }

    /// Makes the mechanism `built` (of the document's scene, just changed) current:
    /// the pose and curves now, the rest when shown, the dynamic run off the frame.
    fn accept(&mut self, built: Built) {
        // A dynamic scene's edit shows the run's start (undo, where it stood).
        let start = built.kin.mechanism().driver.start_rad;
        self.moved_by_hand = (built.pose.input_rad - start).abs() > 1e-12;
        self.pose = Pose::new(built.kin, built.pose, built.topology);
        self.analyses.invalidate(built.curves);
        self.time_s = 0.0;
        self.message = None;
        self.generation += 1;
        self.start_run();
    }
}

/// A branch in English words ("right of B->D", "ahead along the guide").
pub fn branch_words(b: &linkage::scene::Branch) -> String {
    use linkage::scene::Branch;
    match b {
        Branch::Left(a, c) => format!("left of {a}->{c}"),
        Branch::Right(a, c) => format!("right of {a}->{c}"),
        Branch::Along => "ahead along the guide".into(),
        Branch::Against => "behind along the guide".into(),
    }
}

/// The scene's length unit as shown on sliders.
pub fn unit_label(scene: &SceneFile) -> &'static str {
    unit_label_of(scene.length_unit)
}
