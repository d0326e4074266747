//! The analyses of the current mechanism: the curves over the cycle (made with each
//! edit: they are always on screen), the report and the modelled curves (made when
//! shown, in a frame without an edit: [`Derived`]) and the dynamic run (made off the
//! frame: [`RunJob`]).

use linkage::analysis::{Report, report};
use linkage::scene::Models;
use linkage::{Kinematics, LinkageError};

use super::curves::{Curves, ModelCurves};
use super::derived::{Derived, Shown};
use super::dynamic_run::{DynamicRun, IntegratorChoice};
use super::run_job::{RunError, RunJob};

/// The most of a frame a dynamic run computed on the UI thread (the browser) may
/// take, ms: the rest of the frame draws in well under the other 11 ms of a 60 Hz
/// frame. The app gives it less where the frame has spent more already.
pub const RUN_SLICE_MS: f64 = 5.0;

/// What is derived from one mechanism.
pub struct Analyses {
    curves: Curves,
    /// The report, made when shown, in a frame without an edit.
    report: Derived<Result<Report, LinkageError>>,
    /// Torque or J(q), M(q) curves, made when shown, in a frame without an edit.
    model_curves: Derived<ModelCurves>,
    /// The finished dynamic run (dynamic scenes, once computed).
    dynamics: Option<Result<DynamicRun, RunError>>,
    /// The dynamic run being computed off the frame.
    job: Option<RunJob>,
    integrator: IntegratorChoice,
}

impl Analyses {
    /// The analyses of a mechanism whose curves are `curves`; nothing else computed.
    pub fn new(curves: Curves) -> Self {
        Self {
            curves,
            report: Derived::default(),
            model_curves: Derived::default(),
            dynamics: None,
            job: None,
            integrator: IntegratorChoice::default(),
        }
    }

    /// The curves over the cycle.
    pub fn curves(&self) -> &Curves {
        &self.curves
    }

    /// The mechanism changed to one with `curves`: the report and the modelled curves
    /// are out of date (panels show the old ones, marked, until caught up).
    pub fn invalidate(&mut self, curves: Curves) {
        self.curves = curves;
        self.report.invalidate();
        self.model_curves.invalidate();
    }

    /// The report of `kin`, computed now if it is not yet.
    pub fn report(&self, kin: &Kinematics) -> &Result<Report, LinkageError> {
        self.report.get_or_init(|| report(&mut kin.clone()))
    }

    /// The report as a panel shows it.
    pub fn report_shown(&self) -> Shown<'_, Result<Report, LinkageError>> {
        self.report.shown()
    }

    /// The curves of what `kin` models beyond kinematics, computed now if not yet.
    pub fn model_curves(&self, kin: &Kinematics) -> &ModelCurves {
        self.model_curves
            .get_or_init(|| ModelCurves::compute(kin, &self.curves.input_deg))
    }

    /// The model curves as a plot shows them.
    pub fn model_curves_shown(&self) -> Shown<'_, ModelCurves> {
        self.model_curves.shown()
    }

    /// Computes what a panel showed out of date; returns whether it computed anything.
    pub fn catch_up(&self, kin: &Kinematics) -> bool {
        let report = self.report.catch_up(|| report(&mut kin.clone()));
        let curves = self
            .model_curves
            .catch_up(|| ModelCurves::compute(kin, &self.curves.input_deg));
        report || curves
    }

    /// The finished dynamic run, if there is one.
    pub fn dynamics(&self) -> Option<&Result<DynamicRun, RunError>> {
        self.dynamics.as_ref()
    }

    /// The finished dynamic run, to be played.
    pub fn dynamics_mut(&mut self) -> Option<&mut Result<DynamicRun, RunError>> {
        self.dynamics.as_mut()
    }

    /// The simulated time reached and the end time of the run being computed, s.
    pub fn run_progress(&self) -> Option<[f64; 2]> {
        self.job.as_ref().map(|j| [j.progress_s(), j.end_s()])
    }

    /// The integrator settings of the dynamic run.
    pub fn integrator(&self) -> IntegratorChoice {
        self.integrator
    }

    /// Sets the integrator (the caller starts the run again).
    pub fn set_integrator(&mut self, choice: IntegratorChoice) {
        self.integrator = choice;
    }

    /// Starts the dynamic run of `kin` where the scene `models` dynamics (the previous
    /// run, finished or not, is dropped), with `start` (a thread, or slices).
    pub fn start_run(
        &mut self,
        kin: &Kinematics,
        models: Models,
        start: fn(&Kinematics, IntegratorChoice) -> RunJob,
    ) {
        self.dynamics = None;
        self.job = (models == Models::Dynamics).then(|| start(kin, self.integrator));
    }

    /// Advances the run being computed for at most `slice_ms`; returns whether it
    /// finished in this call.
    pub fn poll_run(&mut self, slice_ms: f64) -> bool {
        let Some(job) = &mut self.job else {
            return false;
        };
        let Some(result) = job.poll(slice_ms.min(RUN_SLICE_MS)) else {
            return false;
        };
        self.job = None;
        self.dynamics = Some(result);
        true
    }

    /// Waits for the run being computed; returns whether there was one.
    pub fn wait_for_run(&mut self) -> bool {
        let Some(job) = self.job.take() else {
            return false;
        };
        self.dynamics = Some(job.wait());
        true
    }

    /// Whether a run is being computed.
    pub fn running(&self) -> bool {
        self.job.is_some()
    }
}
