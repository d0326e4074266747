//! The viewer's model, free of any GUI type: the scene being edited, its solver, the
//! current pose (always the last valid one), the analyses and curves, the polygon
//! data at the current pose, and the dynamic run where the scene has one. Every edit
//! goes through here and either succeeds or leaves a message and the old state.

pub mod curves;
pub mod derived;
pub mod dynamic_run;
pub mod history;
pub mod limit;
pub mod notice;
pub mod params;
mod point_edit;
pub mod run_job;
pub mod topology;
pub mod url_state;

use linkage::analysis::{Report, report};
use linkage::polygon::{VectorEquation, polygons};
use linkage::scene::Models;
use linkage::sweep::{csv_header, csv_row, sweep};
use linkage::{Kinematics, Mechanism, SceneFile, Solution};

use crate::catalog::builtin;
use curves::{Curves, ModelCurves};
use derived::{Derived, Shown};
use dynamic_run::{DynamicRun, IntegratorChoice};
use history::{EditTarget, History, Snapshot};
use notice::Notice;
use params::{LengthParam, length_params};
use run_job::RunJob;
use topology::Topology;

/// The most of a frame a dynamic run computed on the UI thread (the browser) may
/// take, ms: the rest of the frame draws in well under the other 11 ms of a 60 Hz
/// frame. The app gives it less where the frame has spent more already.
pub const RUN_SLICE_MS: f64 = 5.0;

/// Where the scene came from.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneSource {
    /// A scene shipped in `assets/scenes`, by file name without `.ron`.
    Builtin(String),
    /// A file the user opened, by its name.
    File(String),
}

/// The viewer's state over one scene.
pub struct Session {
    source: SceneSource,
    original: SceneFile,
    scene: SceneFile,
    kin: Kinematics,
    pose: Solution,
    topology: Topology,
    lengths: Vec<LengthParam>,
    /// The report, made when shown, in a frame without an edit.
    report: Derived<Result<Report, String>>,
    curves: Curves,
    /// Torque or J(q), M(q) curves, made when shown, in a frame without an edit.
    model_curves: Derived<ModelCurves>,
    polygons: Vec<VectorEquation>,
    /// The finished dynamic run (dynamic scenes, once computed).
    dynamics: Option<Result<DynamicRun, String>>,
    /// The dynamic run being computed off the frame.
    job: Option<RunJob>,
    integrator: IntegratorChoice,
    message: Option<Notice>,
    /// Playback time of the dynamic run, s.
    time_s: f64,
    /// +1 or −1: the direction of play over a limited input range (it rocks).
    play_direction: f64,
    /// Counts rebuilds: views that cache per mechanism (plot bounds) key on it.
    generation: u64,
    /// Counts edits asked for, taken or refused (the app times the frames they land in).
    edits: u64,
    /// Undo and redo.
    history: History,
    /// The scene as last opened or saved: it differs from `scene` when there are
    /// unsaved edits (`None`: never saved, a drawing).
    saved: Option<SceneFile>,
    /// The scene packed for a link, made when first asked for after an edit.
    share: std::cell::OnceCell<Result<String, linkage::share::ShareError>>,
}

impl Session {
    /// Opens a shipped scene by key (`die_cutter`, ...).
    ///
    /// # Errors
    /// An unknown key, or a scene that does not solve (a bug in the shipped file).
    pub fn open_builtin(key: &str) -> Result<Self, String> {
        let b = builtin(key).ok_or_else(|| format!("no built-in scene named {key:?}"))?;
        Self::open_text(SceneSource::Builtin(key.to_string()), b.text)
    }

    /// Opens a scene from its RON text.
    ///
    /// # Errors
    /// The parse error with line and column, or why the mechanism does not assemble.
    pub fn open_text(source: SceneSource, text: &str) -> Result<Self, String> {
        let scene = SceneFile::parse(text).map_err(|e| e.to_string())?;
        Self::open_scene(source, scene)
    }

    /// Opens a scene (a drawing's, or one parsed from a file).
    ///
    /// # Errors
    /// Why the mechanism does not assemble.
    pub fn open_scene(source: SceneSource, scene: SceneFile) -> Result<Self, String> {
        let saved = Some(scene.clone());
        let built = Built::new(&scene, None)?;
        let lengths = length_params(&scene);
        let mut session = Self {
            source,
            original: scene.clone(),
            scene,
            kin: built.kin,
            pose: built.pose,
            topology: built.topology,
            lengths,
            report: Derived::default(),
            curves: built.curves,
            model_curves: Derived::default(),
            polygons: Vec::new(),
            dynamics: None,
            job: None,
            integrator: IntegratorChoice::default(),
            message: None,
            time_s: 0.0,
            play_direction: 1.0,
            generation: 0,
            edits: 0,
            history: History::default(),
            saved,
            share: std::cell::OnceCell::new(),
        };
        session.refresh_polygons();
        session.start_run();
        Ok(session)
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

    /// The mechanism.
    pub fn mechanism(&self) -> &Mechanism {
        self.kin.mechanism()
    }

    /// The solver (for its path and tolerances).
    pub fn kinematics(&self) -> &Kinematics {
        &self.kin
    }

    /// Joints and links by index (fixed per mechanism).
    pub fn topology(&self) -> &Topology {
        &self.topology
    }

    /// The current pose: always a valid, solved one.
    pub fn pose(&self) -> &Solution {
        &self.pose
    }

    /// Current input angle, rad.
    pub fn input_rad(&self) -> f64 {
        self.pose.input_rad
    }

    /// The report (Grashof, K, strokes, limits, transmission angle) or why it failed;
    /// computed now if it is not yet.
    pub fn report(&self) -> &Result<Report, String> {
        self.report.get_or_init(|| self.compute_report())
    }

    /// The report as a panel shows it: the current one, or the one from before the
    /// last edit until [`Session::catch_up`] has made the current one.
    pub fn report_shown(&self) -> Shown<'_, Result<Report, String>> {
        self.report.shown()
    }

    /// The curves of what the scene models beyond kinematics (input torque; J(q) and
    /// M(q)); computed now if they are not yet.
    pub fn model_curves(&self) -> &ModelCurves {
        self.model_curves
            .get_or_init(|| self.compute_model_curves())
    }

    /// The model curves as a plot shows them (see [`Session::report_shown`]).
    pub fn model_curves_shown(&self) -> Shown<'_, ModelCurves> {
        self.model_curves.shown()
    }

    /// Computes what a panel showed out of date since the last edit (the app calls it
    /// at the end of a frame that carried no edit). Returns whether it computed
    /// anything (the panels show it next frame).
    pub fn catch_up(&self) -> bool {
        let report = self.report.catch_up(|| self.compute_report());
        let curves = self.model_curves.catch_up(|| self.compute_model_curves());
        report || curves
    }

    fn compute_report(&self) -> Result<Report, String> {
        report(&mut self.kin.clone()).map_err(|e| e.to_string())
    }

    fn compute_model_curves(&self) -> ModelCurves {
        ModelCurves::compute(&self.kin, &self.curves.input_deg)
    }

    /// The curves over the cycle.
    pub fn curves(&self) -> &Curves {
        &self.curves
    }

    /// The velocity and acceleration polygon equations at the current pose.
    pub fn polygons(&self) -> &[VectorEquation] {
        &self.polygons
    }

    /// The editable lengths.
    pub fn lengths(&self) -> &[LengthParam] {
        &self.lengths
    }

    /// The dynamic run: `None` for scenes that model no dynamics, and while the run is
    /// being computed ([`Session::run_progress`]).
    pub fn dynamics(&self) -> Option<&Result<DynamicRun, String>> {
        self.dynamics.as_ref()
    }

    /// While the dynamic run is being computed: the simulated time reached and the
    /// run's end time, s.
    pub fn run_progress(&self) -> Option<[f64; 2]> {
        self.job.as_ref().map(|j| [j.progress_s(), j.end_s()])
    }

    /// Advances the dynamic run being computed (where it runs on this thread, for
    /// `slice_ms`, at most [`RUN_SLICE_MS`]) and takes its result when it is done.
    /// Returns whether a run is still being computed (the caller asks for another
    /// frame).
    pub fn poll_run(&mut self, slice_ms: f64) -> bool {
        let Some(job) = &mut self.job else {
            return false;
        };
        if let Some(result) = job.poll(slice_ms.min(RUN_SLICE_MS)) {
            self.finish_run(result);
        }
        self.job.is_some()
    }

    /// Waits until the dynamic run being computed is done (tests, exports).
    pub fn wait_for_run(&mut self) {
        if let Some(job) = self.job.take() {
            self.finish_run(job.wait());
        }
    }

    /// Computes the dynamic run on this thread, sliced as in the browser, instead of
    /// on a worker thread.
    pub fn run_sliced(&mut self) {
        self.start_job(RunJob::start_sliced);
    }

    /// The integrator settings of the dynamic run.
    pub fn integrator(&self) -> IntegratorChoice {
        self.integrator
    }

    /// Playback time of the dynamic run, s.
    pub fn time_s(&self) -> f64 {
        self.time_s
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

    /// What the last edit could not do, and why, in words (made here, when shown).
    pub fn message(&self) -> Option<String> {
        self.message.as_ref().map(Notice::to_string)
    }

    /// What the last edit could not do, as data.
    pub fn notice(&self) -> Option<&Notice> {
        self.message.as_ref()
    }

    /// What the scene models.
    pub fn models(&self) -> Models {
        self.scene.models
    }

    /// The input slider's range, deg: a full turn (wrapping) or the assembly interval.
    pub fn input_range_deg(&self) -> [f64; 2] {
        if self.curves.full_rotation {
            [0.0, 360.0]
        } else {
            let [a, b] = self.curves.range_rad;
            [a.to_degrees(), b.to_degrees()]
        }
    }

    /// Moves the crank to `input_deg` (wrapped for a full turn).
    ///
    /// On failure the pose stays and the message says why, with the reachable range.
    pub fn set_input_deg(&mut self, input_deg: f64) {
        self.edits += 1;
        self.move_to_deg(input_deg);
    }

    /// Moves the crank as playback does (not an edit).
    fn move_to_deg(&mut self, input_deg: f64) {
        if !input_deg.is_finite() {
            self.message = Some(Notice::Text(format!(
                "input angle {input_deg} is not a number; the pose is unchanged"
            )));
            return;
        }
        let x = if self.curves.full_rotation {
            input_deg.rem_euclid(360.0)
        } else {
            input_deg
        }
        .to_radians();
        match self.kin.solve(x) {
            Ok(s) => {
                self.pose = s;
                self.message = None;
                self.refresh_polygons();
            }
            Err(e) => self.message = Some(Notice::Text(e.to_string())),
        }
    }

    /// Advances the animation by `dt_s` of real time at `speed` times real speed: the
    /// dynamic run plays in its own time; kinematic scenes turn at the crank speed.
    pub fn advance(&mut self, dt_s: f64, speed: f64) {
        let dt = dt_s * speed;
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        if let Some(Ok(run)) = &mut self.dynamics {
            let end = run.duration_s();
            self.time_s = if self.time_s + dt > end + 0.5 {
                0.0 // loop after half a second at the end
            } else {
                self.time_s + dt
            };
            if let Some((_, pose)) = run.pose_at(self.time_s) {
                self.pose = pose;
                self.refresh_polygons();
            }
            return;
        }
        let speed_rad_s = self.mechanism().driver.speed_rad_s;
        // A scene without a crank speed still turns, at one turn per 4 s, for viewing.
        let w = if speed_rad_s != 0.0 {
            speed_rad_s
        } else {
            std::f64::consts::FRAC_PI_2
        };
        let mut next = self.input_rad().to_degrees() + (w * dt * self.play_direction).to_degrees();
        if !self.curves.full_rotation {
            let [a, b] = self.input_range_deg();
            if next > b || next < a {
                self.play_direction = -self.play_direction;
                next = next.clamp(a, b);
            }
        }
        self.move_to_deg(next);
    }

    /// Sets the playback time of the dynamic run and shows its pose.
    pub fn set_time_s(&mut self, t: f64) {
        if let Some(Ok(run)) = &mut self.dynamics {
            let t = t.clamp(0.0, run.duration_s());
            if let Some((_, pose)) = run.pose_at(t) {
                self.time_s = t;
                self.pose = pose;
                self.refresh_polygons();
            }
        }
    }

    /// Sets length `index` to `value` (scene units).
    ///
    /// If the chain cannot assemble at the current input with it, nothing changes and
    /// the notice names the cause and the limit, found on the closure margin.
    pub fn set_length(&mut self, index: usize, value: f64) {
        self.edits += 1;
        let Some(param) = self.lengths.get(index).cloned() else {
            return;
        };
        let mut scene = self.scene.clone();
        if let Err(e) = param.apply(&mut scene, value) {
            self.message = Some(Notice::Text(e));
            return;
        }
        let input = self.input_rad();
        let why = match limit::try_assemble(&scene, input) {
            Ok(built) => return self.commit(EditTarget::Length(index), scene, built),
            Err(why) => why,
        };
        let good = param.value(&self.scene);
        let limit =
            good.and_then(|good| limit::length_limit(&self.scene, &param, good, value, input));
        self.message = Some(Notice::LengthRefused {
            label: param.label.clone(),
            value,
            unit: unit_label(&self.scene),
            input_deg: input.to_degrees(),
            why,
            limit,
        });
    }

    /// Sets the constant of spring `index`, N/m.
    pub fn set_spring_k(&mut self, index: usize, k_n_per_m: f64) {
        self.edits += 1;
        if !(k_n_per_m.is_finite() && k_n_per_m >= 0.0) {
            self.message = Some(Notice::Text(format!(
                "spring constant {k_n_per_m} N/m is invalid: it must be finite and >= 0"
            )));
            return;
        }
        let mut scene = self.scene.clone();
        let Some(spring) = scene.forces.springs.get_mut(index) else {
            return;
        };
        spring.k_n_per_m = k_n_per_m;
        if let Err(why) = self.rebuild(EditTarget::Spring(index), scene) {
            self.message = Some(Notice::Text(why));
        }
    }

    /// Sets the mass of link `index`, kg.
    pub fn set_mass(&mut self, index: usize, mass_kg: f64) {
        self.edits += 1;
        if !(mass_kg.is_finite() && mass_kg > 0.0) {
            self.message = Some(Notice::Text(format!(
                "mass {mass_kg} kg is invalid: it must be finite and > 0"
            )));
            return;
        }
        let mut scene = self.scene.clone();
        let Some(link) = scene.links.get_mut(index) else {
            return;
        };
        // Scale the inertia with the mass: same shape, denser material.
        if let (Some(old), Some(i)) = (link.mass, link.inertia.as_mut())
            && old > 0.0
        {
            *i *= mass_kg / old;
        }
        link.mass = Some(mass_kg);
        if let Err(why) = self.rebuild(EditTarget::Mass(index), scene) {
            self.message = Some(Notice::Text(why));
        }
    }

    /// The assembly branches of the chain, by the point of each dyad: (point, branch
    /// in words, whether it differs from the scene as opened).
    pub fn branches(&self) -> Vec<(String, String, bool)> {
        let m = self.mechanism();
        m.branches
            .iter()
            .map(|(p, b)| {
                let name = m.points[*p].name.clone();
                let flipped = self
                    .original
                    .branches
                    .get(&name)
                    .is_some_and(|orig| orig != b);
                (name, branch_words(b), flipped)
            })
            .collect()
    }

    /// Flips the assembly branch of the dyad at `point`.
    pub fn flip_branch(&mut self, point: &str) {
        self.edits += 1;
        let m = self.mechanism();
        let Some(b) = m
            .branches
            .iter()
            .find(|(p, _)| m.points[*p].name == point)
            .map(|(_, b)| b.flipped())
        else {
            return;
        };
        let mut scene = self.scene.clone();
        scene.branches.insert(point.to_string(), b);
        if let Err(why) = self.rebuild(EditTarget::Branch(point.to_string()), scene) {
            self.message = Some(Notice::Text(format!(
                "flipping the branch at {point}: {why}"
            )));
        }
    }

    /// Changes the integrator of the dynamic run and runs it again.
    pub fn set_integrator(&mut self, choice: IntegratorChoice) {
        self.edits += 1;
        self.integrator = choice;
        self.start_run();
        self.time_s = 0.0;
    }

    /// Puts back the scene as opened.
    pub fn reset(&mut self) {
        self.edits += 1;
        let scene = self.original.clone();
        if scene == self.scene {
            return;
        }
        if let Err(why) = self.rebuild(EditTarget::Reset, scene) {
            self.message = Some(Notice::Text(why));
        }
    }

    /// Takes the last edit back (a whole slider drag is one edit).
    pub fn undo(&mut self) {
        self.travel(true);
    }

    /// Makes the last undone edit again.
    pub fn redo(&mut self) {
        self.travel(false);
    }

    /// Puts back the scene the history holds next, backwards (undo) or forwards
    /// (redo), and moves the entry to the other stack; a scene that no longer builds
    /// stays in the history, with the reason shown.
    fn travel(&mut self, back: bool) {
        self.edits += 1;
        let next = if back {
            self.history.to_undo()
        } else {
            self.history.to_redo()
        };
        let Some(to) = next.cloned() else {
            return;
        };
        match self.rebuild_snapshot(&to) {
            Ok(built) => {
                let now = self.snapshot();
                if back {
                    self.history.undone(now);
                } else {
                    self.history.redone(now);
                }
                self.accept(to.scene, built);
            }
            Err(why) => {
                let what = if back { "undo" } else { "redo" };
                self.message = Some(Notice::Text(format!("cannot {what}: {why}")));
            }
        }
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

    /// The edited scene packed for a link (`linkage::share`), or why it does not fit.
    pub fn share_payload(&self) -> Result<&str, &linkage::share::ShareError> {
        self.share
            .get_or_init(|| {
                // Writing a scene that was read cannot fail; were it to, the empty
                // link would be refused where it is opened, naming the cause.
                linkage::share::encode(&self.to_ron().unwrap_or_default())
            })
            .as_ref()
            .map(String::as_str)
    }

    /// The edited scene as RON text.
    ///
    /// # Errors
    /// Serialisation failure, as text.
    pub fn to_ron(&self) -> Result<String, String> {
        self.scene.to_ron().map_err(|e| e.to_string())
    }

    /// The current mechanism's sweep as CSV, in the `linkage sweep` format (same
    /// header, SI units, velocities at the scene's crank speed).
    ///
    /// # Errors
    /// The sweep's error, as text.
    pub fn sweep_csv(&self) -> Result<String, String> {
        let mut k = self.kin.clone();
        let sw = sweep(&mut k, curves::CURVE_STEPS).map_err(|e| e.to_string())?;
        let m = k.mechanism();
        let mut out = csv_header(m).join(",");
        out.push('\n');
        for (s, angles) in sw.solutions.iter().zip(&sw.angles) {
            let row: Vec<String> = csv_row(m, s, angles).iter().map(f64::to_string).collect();
            out.push_str(&row.join(","));
            out.push('\n');
        }
        Ok(out)
    }

    /// The sheet of the current position (pose, polygons, tables; instant centres if
    /// `centres`) as SVG: what `linkage diagram` writes for the same scene and input.
    pub fn sheet_svg(&self, centres: bool) -> String {
        let m = self.mechanism();
        let pose = self.pose();
        let found = linkage::instant_centres::instant_centres(m, pose);
        let position = linkage_diagram::svg::Position {
            mechanism: m,
            solution: pose,
            equations: self.polygons(),
            centres: Some(&found),
        };
        let parts = linkage_diagram::svg::Parts {
            centres,
            ..Default::default()
        };
        linkage_diagram::svg::sheet(&position, parts)
    }

    /// Starts computing the dynamic run of a dynamic scene off the frame; the
    /// previous run, finished or not, is dropped.
    fn start_run(&mut self) {
        self.start_job(RunJob::start);
    }

    fn start_job(&mut self, start: fn(&Kinematics, IntegratorChoice) -> RunJob) {
        self.dynamics = None;
        self.job =
            (self.scene.models == Models::Dynamics).then(|| start(&self.kin, self.integrator));
    }

    fn finish_run(&mut self, result: Result<DynamicRun, String>) {
        self.job = None;
        self.dynamics = Some(result);
        self.generation += 1;
        self.time_s = 0.0;
    }

    /// Rebuilds everything from `scene` at the current input; on failure nothing
    /// changes.
    fn rebuild(&mut self, target: EditTarget, scene: SceneFile) -> Result<(), String> {
        let built = Built::new(&scene, Some(self.input_rad()))?;
        self.commit(target, scene, built);
        Ok(())
    }

    /// Makes an edit of `target` current, the scene before it kept for undo.
    fn commit(&mut self, target: EditTarget, scene: SceneFile, built: Built) {
        let before = self.snapshot();
        self.history.record(target, before);
        self.accept(scene, built);
    }

    fn snapshot(&self) -> Snapshot {
        Snapshot {
            scene: self.scene.clone(),
            input_rad: self.input_rad(),
        }
    }

    /// Builds `to` at the current input, or where it stood if it does not assemble
    /// here.
    fn rebuild_snapshot(&self, to: &Snapshot) -> Result<Built, String> {
        Built::new(&to.scene, Some(self.input_rad()))
            .or_else(|_| Built::new(&to.scene, Some(to.input_rad)))
    }

    /// Makes `scene`, built as `built`, the current one: what is on screen now, the
    /// rest when shown, the dynamic run off the frame.
    fn accept(&mut self, scene: SceneFile, built: Built) {
        self.scene = scene;
        self.share = std::cell::OnceCell::new();
        self.kin = built.kin;
        self.pose = built.pose;
        self.topology = built.topology;
        self.report.invalidate();
        self.curves = built.curves;
        self.model_curves.invalidate();
        self.time_s = 0.0;
        self.message = None;
        self.generation += 1;
        self.refresh_polygons();
        self.start_run();
    }

    fn refresh_polygons(&mut self) {
        self.polygons = polygons(&self.kin, &self.pose);
    }
}

/// A mechanism built from a scene with what an edit shows at once: the pose and the
/// curves (the report, the modelled curves and the dynamic run follow when shown).
pub(crate) struct Built {
    kin: Kinematics,
    pose: Solution,
    topology: Topology,
    curves: Curves,
}

impl Built {
    /// Builds at `input` (or the scene's start angle).
    pub(crate) fn new(scene: &SceneFile, input: Option<f64>) -> Result<Self, String> {
        let mech = Mechanism::from_scene(scene).map_err(|e| e.to_string())?;
        let kin = Kinematics::new(mech).map_err(|e| e.to_string())?;
        let start = kin.mechanism().driver.start_rad;
        Self::at(kin, input.unwrap_or(start)).map_err(|e| e.to_string())
    }

    /// Where point `name` is in the built pose, m.
    pub(crate) fn point_position(&self, name: &str) -> Option<linkage::Vec2> {
        let p = self.kin.mechanism().point_index(name)?;
        Some(self.pose.points[p].position)
    }

    /// Solves `kin` at `input` and sweeps it.
    pub(crate) fn at(mut kin: Kinematics, input: f64) -> linkage::Result<Self> {
        let pose = kin.solve(input)?;
        let curves = Curves::compute(&mut kin)?;
        Ok(Self {
            topology: Topology::of(kin.mechanism()),
            kin,
            pose,
            curves,
        })
    }
}

fn branch_words(b: &linkage::scene::Branch) -> String {
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
    use linkage::scene::LengthUnit;
    match scene.length_unit {
        LengthUnit::Metre => "m",
        LengthUnit::Millimetre => "mm",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_scene_computes_only_what_it_models() {
        let kin = Session::open_builtin("slider_crank").expect("opens");
        assert!(kin.dynamics().is_none());
        let none = kin.model_curves();
        assert!(none.torque_n_m.is_empty() && none.inertia_kg_m2.is_empty());

        let ks = Session::open_builtin("die_cutter").expect("opens");
        assert!(ks.dynamics().is_none() && ks.run_progress().is_none());
        assert!(
            ks.model_curves().torque_n_m.len() > 300,
            "torque over the cycle"
        );
        assert!(ks.model_curves().inertia_kg_m2.is_empty());

        let mut dy = Session::open_builtin("gravity_flipper").expect("opens");
        dy.wait_for_run();
        let run = dy.dynamics().expect("a run").as_ref().expect("runs");
        // The CLI's DOP853 run reaches the end stop at t = 0.244660 s; rtol 1e-8 here.
        assert!(
            (run.duration_s() - 0.244660).abs() < 1e-5,
            "{}",
            run.duration_s()
        );
        let reduced = dy.model_curves();
        assert!(!reduced.inertia_kg_m2.is_empty() && !reduced.moment_n_m.is_empty());
    }

    #[test]
    fn non_finite_edits_leave_a_message_and_the_pose() {
        let mut s = Session::open_builtin("quick_return").expect("opens");
        let pose = s.pose().clone();
        s.set_input_deg(f64::NAN);
        assert!(s.message().expect("message").contains("not a number"));
        s.set_length(0, f64::INFINITY);
        assert!(s.message().expect("message").contains("positive length"));
        s.set_spring_k(0, -1.0); // no spring: nothing to change, no panic
        assert_eq!(s.pose(), &pose);
    }

    #[test]
    fn an_edit_shows_at_once_and_the_run_follows_off_the_frame() {
        let mut s = Session::open_builtin("gravity_flipper").expect("opens");
        s.wait_for_run();
        let first = s
            .dynamics()
            .expect("a run")
            .as_ref()
            .expect("runs")
            .duration_s();
        s.set_mass(1, 2.0 * s.scene().links[1].mass.expect("a mass"));
        assert!(s.message().is_none(), "{:?}", s.message());
        // The pose and curves are new at once; the run is being computed.
        assert!(s.dynamics().is_none() && s.run_progress().is_some());
        s.wait_for_run();
        let second = s
            .dynamics()
            .expect("a run")
            .as_ref()
            .expect("runs")
            .duration_s();
        assert!(s.run_progress().is_none());
        assert!((first - second).abs() > 1e-6, "{first} vs {second}");
    }

    #[test]
    fn a_run_sliced_over_frames_is_the_run_computed_at_once() {
        let mut whole = Session::open_builtin("gravity_flipper").expect("opens");
        whole.wait_for_run();
        let mut sliced = Session::open_builtin("gravity_flipper").expect("opens");
        sliced.run_sliced();
        let mut frames = 0;
        while sliced.poll_run(RUN_SLICE_MS) {
            frames += 1;
            assert!(frames < 100_000, "the run ends");
        }
        let a = &whole.dynamics().expect("run").as_ref().expect("ok").sim;
        let b = &sliced.dynamics().expect("run").as_ref().expect("ok").sim;
        assert_eq!(a.samples, b.samples, "the same steps and samples");
        assert_eq!(a.stats.steps, b.stats.steps);
    }

    #[test]
    fn a_refused_length_names_its_limit_found_on_the_margin() {
        let mut checked = 0;
        for b in crate::catalog::BUILTIN_SCENES {
            let mut s = Session::open_builtin(b.key).expect("opens");
            for i in 0..s.lengths().len() {
                let v = s.lengths()[i].value(s.scene()).expect("a length");
                for factor in [0.01, 100.0] {
                    let pose = s.pose().clone();
                    s.set_length(i, factor * v);
                    let Some(Notice::LengthRefused {
                        limit: Some(limit), ..
                    }) = s.notice().cloned()
                    else {
                        s.set_length(i, v);
                        continue;
                    };
                    let what = format!("{} length {i} x{factor}", b.key);
                    assert_eq!(s.pose(), &pose, "{what}: the last valid pose stays");
                    assert!(
                        limit > v.min(factor * v) && limit < v.max(factor * v),
                        "{what}"
                    );
                    // The limit assembles and a hair beyond it does not.
                    let beyond = limit + (factor * v - limit) * 1e-6;
                    s.set_length(i, beyond);
                    assert!(
                        s.message().is_some(),
                        "{what}: just past {limit} is refused"
                    );
                    s.set_length(i, limit);
                    assert!(s.message().is_none(), "{what}: {:?}", s.message());
                    s.set_length(i, v);
                    checked += 1;
                }
            }
        }
        assert!(checked >= 3, "{checked} refusals checked");
    }

    #[test]
    fn playback_follows_the_run_and_loops() {
        let mut s = Session::open_builtin("gravity_flipper").expect("opens");
        s.wait_for_run();
        let start = s.input_rad();
        s.advance(0.1, 1.0);
        assert!((s.time_s() - 0.1).abs() < 1e-12);
        assert!(
            s.input_rad() < start,
            "the table falls: link 1 turns clockwise"
        );
        s.advance(10.0, 1.0);
        assert_eq!(s.time_s(), 0.0, "loops after the end");
    }
}
