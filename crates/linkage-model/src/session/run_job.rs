//! The dynamic run computed off the frame as a [`Job`], so that an edit shows at once
//! and the run follows: natively on a worker thread; in the browser, which has no
//! threads here, in slices of a few milliseconds per frame. Either way the result is
//! exactly the one `simulate` gives: slicing a run does not change its steps.

use linkage::dynamics::Run;
use linkage::{Kinematics, LinkageError};
use linkage_diagram::words::Lang;

use super::dynamic_run::{DynamicRun, IntegratorChoice, settings_for};
use super::words::mw;
use crate::job::{Job, Work};

/// Integrator steps in one step of the job (a step costs microseconds).
const STEPS_PER_CHUNK: usize = 16;

/// Why a dynamic run has no result.
#[derive(Clone, Debug, PartialEq)]
pub enum RunError {
    /// The solver stopped it (it cannot start, or a step failed).
    Solver(LinkageError),
    /// The worker thread ended without a result.
    ThreadEnded,
    /// Its result was already taken.
    Finished,
}

impl RunError {
    /// Why the run has no result, in `lang`, lengths in `unit`: a refusal for the
    /// run's settings names the app's controls.
    pub fn words(&self, unit: linkage::scene::LengthUnit, lang: Lang) -> String {
        match self {
            Self::Solver(e) => super::words::error(e, unit, lang),
            Self::ThreadEnded => mw!(lang, "notice.thread_ended"),
            Self::Finished => mw!(lang, "notice.result_taken"),
        }
    }
}

impl std::fmt::Display for RunError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.words(linkage::scene::LengthUnit::Metre, Lang::English))
    }
}

/// The run as work in steps. It starts at its first step, so that a run on a thread
/// starts there, not in the frame that made the edit.
enum RunWork {
    /// Not started: the chain and the integrator.
    Pending(Box<Kinematics>, IntegratorChoice),
    /// Under way or finished.
    Running(Box<Run>),
    /// Stopped by the solver.
    Failed(RunError),
}

impl Work for RunWork {
    /// Simulated time reached, s.
    type Snapshot = f64;

    fn advance(&mut self, steps: u32) -> bool {
        if let Self::Pending(k, choice) = self {
            *self = match Run::start(k, &settings_for(*choice)) {
                Ok(run) => Self::Running(Box::new(run)),
                Err(e) => Self::Failed(RunError::Solver(e)),
            };
        }
        let Self::Running(run) = self else {
            return true;
        };
        match run.advance(STEPS_PER_CHUNK * steps as usize) {
            Ok(done) => done,
            Err(e) => {
                *self = Self::Failed(RunError::Solver(e));
                true
            }
        }
    }

    fn snapshot(&self) -> f64 {
        match self {
            Self::Running(run) => run.time_s(),
            Self::Pending(..) | Self::Failed(_) => 0.0,
        }
    }
}

/// A dynamic run being computed; dropping it stops its thread.
pub struct RunJob {
    choice: IntegratorChoice,
    job: Job<RunWork>,
    /// Whether the result was handed out.
    taken: bool,
}

impl RunJob {
    /// Starts the run of `k` with `choice` off the frame: on a worker thread
    /// natively, sliced over frames in the browser.
    pub fn start(k: &Kinematics, choice: IntegratorChoice) -> Self {
        Self::with(
            Job::start(RunWork::Pending(Box::new(k.clone()), choice)),
            choice,
        )
    }

    /// Starts the run to be advanced only by [`RunJob::poll`] on the caller's thread,
    /// as the browser does (natively too, to test it).
    pub fn start_sliced(k: &Kinematics, choice: IntegratorChoice) -> Self {
        Self::with(
            Job::start_sliced(RunWork::Pending(Box::new(k.clone()), choice)),
            choice,
        )
    }

    fn with(job: Job<RunWork>, choice: IntegratorChoice) -> Self {
        Self {
            choice,
            job,
            taken: false,
        }
    }

    /// Simulated time reached as of the last poll, s.
    pub fn progress_s(&self) -> f64 {
        *self.job.snapshot()
    }

    /// The run's end time, s.
    pub fn end_s(&self) -> f64 {
        settings_for(self.choice).t_end
    }

    /// Advances the run: a sliced run by steps for at most `budget_ms` of this thread's
    /// time, a threaded one not at all. The result once the run has finished.
    pub fn poll(&mut self, budget_ms: f64) -> Option<Result<DynamicRun, RunError>> {
        self.job.poll(budget_ms);
        if self.job.is_running() {
            return None;
        }
        let work = self.job.take();
        let gone = self.gone();
        self.taken = true;
        Some(outcome(self.choice, work, gone))
    }

    /// Waits for the result (blocks; a sliced run is run to its end here).
    pub fn wait(self) -> Result<DynamicRun, RunError> {
        let gone = self.gone();
        outcome(self.choice, self.job.finish(), gone)
    }

    /// Why there is no work to take a result from: it was taken, or its thread ended
    /// without one.
    fn gone(&self) -> RunError {
        if self.taken {
            RunError::Finished
        } else {
            RunError::ThreadEnded
        }
    }
}

/// The run's result from its finished work; `gone` where there is no work.
fn outcome(
    choice: IntegratorChoice,
    work: Option<Box<RunWork>>,
    gone: RunError,
) -> Result<DynamicRun, RunError> {
    match work.map(|w| *w) {
        Some(RunWork::Running(run)) => Ok(DynamicRun::from_simulation(choice, run.finish())),
        Some(RunWork::Failed(e)) => Err(e),
        Some(RunWork::Pending(..)) | None => Err(gone),
    }
}
