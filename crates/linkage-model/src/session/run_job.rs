//! The dynamic run computed off the frame, so that an edit shows at once and the run
//! follows: natively on a worker thread; in the browser, which has no threads here,
//! in slices of a few milliseconds per frame. Either way the result is exactly the
//! one `simulate` gives: slicing a run does not change its steps.

use linkage::dynamics::Run;
use linkage::{Kinematics, LinkageError};

use super::dynamic_run::{DynamicRun, IntegratorChoice, settings_for};

/// Steps taken between two looks at the clock (a step costs microseconds).
const STEPS_PER_CHUNK: usize = 16;

/// Why a dynamic run has no result.
#[derive(Clone, Debug, PartialEq)]
pub enum RunError {
    /// The solver stopped it (it cannot start, or a step failed).
    Solver(LinkageError),
    /// The worker thread ended without a result.
    ThreadEnded,
    /// A newer edit dropped it.
    Cancelled,
    /// A sliced run asked for its result before its end.
    Unfinished,
    /// Its result was already taken.
    Finished,
}

impl std::fmt::Display for RunError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Solver(e) => write!(f, "{e}"),
            Self::ThreadEnded => f.write_str("the run's thread ended"),
            Self::Cancelled => f.write_str("cancelled"),
            Self::Unfinished => f.write_str("the run did not finish"),
            Self::Finished => f.write_str("the run's result was already taken"),
        }
    }
}

/// A dynamic run being computed.
pub struct RunJob {
    choice: IntegratorChoice,
    inner: Inner,
}

enum Inner {
    /// Native: the run goes on in a thread; dropping the job stops it.
    #[cfg(not(target_arch = "wasm32"))]
    Thread(worker::Worker),
    /// The run advanced a slice per call of [`RunJob::poll`] (the browser).
    Sliced(Box<Result<Run, RunError>>),
}

impl RunJob {
    /// Starts the run of `k` with `choice` on a worker thread.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn start(k: &Kinematics, choice: IntegratorChoice) -> Self {
        Self {
            choice,
            inner: Inner::Thread(worker::Worker::spawn(k.clone(), choice)),
        }
    }

    /// Starts the run of `k` with `choice`, sliced over frames (no threads here).
    #[cfg(target_arch = "wasm32")]
    pub fn start(k: &Kinematics, choice: IntegratorChoice) -> Self {
        Self::start_sliced(k, choice)
    }

    /// Starts the run to be advanced only by [`RunJob::poll`] on the caller's thread,
    /// as the browser does (natively too, to test it).
    pub fn start_sliced(k: &Kinematics, choice: IntegratorChoice) -> Self {
        Self {
            choice,
            inner: Inner::Sliced(Box::new(start_run(k, choice))),
        }
    }

    /// Simulated time reached so far, s.
    pub fn progress_s(&self) -> f64 {
        match &self.inner {
            #[cfg(not(target_arch = "wasm32"))]
            Inner::Thread(w) => w.progress_s(),
            Inner::Sliced(run) => run.as_ref().as_ref().map_or(0.0, Run::time_s),
        }
    }

    /// The run's end time, s.
    pub fn end_s(&self) -> f64 {
        settings_for(self.choice).t_end
    }

    /// Advances the run: a sliced run by steps for at most `budget_ms` of this thread's
    /// time, a threaded one not at all. The result once the run has finished.
    pub fn poll(&mut self, budget_ms: f64) -> Option<Result<DynamicRun, RunError>> {
        let choice = self.choice;
        match &mut self.inner {
            #[cfg(not(target_arch = "wasm32"))]
            Inner::Thread(w) => w.try_result(),
            Inner::Sliced(run) => {
                let finished = match run.as_mut() {
                    Ok(r) => advance_for(r, budget_ms),
                    Err(e) => Err(e.clone()),
                };
                match finished {
                    Ok(false) => None,
                    Err(e) => Some(Err(e)),
                    Ok(true) => {
                        let done = std::mem::replace(run.as_mut(), Err(RunError::Finished));
                        Some(done.map(|r| DynamicRun::from_simulation(choice, r.finish())))
                    }
                }
            }
        }
    }

    /// Waits for the result (blocks; a sliced run is run to its end here).
    pub fn wait(mut self) -> Result<DynamicRun, RunError> {
        #[cfg(not(target_arch = "wasm32"))]
        if let Inner::Thread(w) = &mut self.inner {
            return w.join();
        }
        // Without a time budget a sliced run goes on to its end or its error.
        self.poll(f64::INFINITY)
            .unwrap_or(Err(RunError::Unfinished))
    }
}

fn start_run(k: &Kinematics, choice: IntegratorChoice) -> Result<Run, RunError> {
    Run::start(k, &settings_for(choice)).map_err(RunError::Solver)
}

/// Steps `run` until it finishes or `budget_ms` of wall time is spent (no step at all
/// for a budget of 0: a frame that has none left).
fn advance_for(run: &mut Run, budget_ms: f64) -> Result<bool, RunError> {
    if budget_ms.is_nan() || budget_ms <= 0.0 {
        return Ok(false);
    }
    let clock = web_time::Instant::now();
    loop {
        if run.advance(STEPS_PER_CHUNK).map_err(RunError::Solver)? {
            return Ok(true);
        }
        if clock.elapsed().as_secs_f64() * 1e3 >= budget_ms {
            return Ok(false);
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod worker {
    //! The native worker thread, stopped when its job is dropped.

    use std::sync::Arc;
    use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
    use std::sync::mpsc::{Receiver, TryRecvError, channel};

    use linkage::Kinematics;

    use super::{DynamicRun, IntegratorChoice, RunError, STEPS_PER_CHUNK, start_run};

    /// A run on its own thread.
    pub struct Worker {
        result: Receiver<Result<DynamicRun, RunError>>,
        cancel: Arc<AtomicBool>,
        /// Simulated time reached, as f64 bits.
        progress: Arc<AtomicU64>,
    }

    impl Worker {
        pub fn spawn(k: Kinematics, choice: IntegratorChoice) -> Self {
            let (tx, result) = channel();
            let cancel = Arc::new(AtomicBool::new(false));
            let progress = Arc::new(AtomicU64::new(0f64.to_bits()));
            let (stop, seen) = (cancel.clone(), progress.clone());
            std::thread::spawn(move || {
                let outcome = run_to_end(&k, choice, &stop, &seen);
                // The job may be gone (a newer edit): nobody is waiting then.
                let _ = tx.send(outcome);
            });
            Self {
                result,
                cancel,
                progress,
            }
        }

        pub fn progress_s(&self) -> f64 {
            f64::from_bits(self.progress.load(Ordering::Relaxed))
        }

        pub fn try_result(&mut self) -> Option<Result<DynamicRun, RunError>> {
            match self.result.try_recv() {
                Ok(r) => Some(r),
                Err(TryRecvError::Empty) => None,
                Err(TryRecvError::Disconnected) => Some(Err(RunError::ThreadEnded)),
            }
        }

        pub fn join(&mut self) -> Result<DynamicRun, RunError> {
            self.result.recv().unwrap_or(Err(RunError::ThreadEnded))
        }
    }

    impl Drop for Worker {
        fn drop(&mut self) {
            self.cancel.store(true, Ordering::Relaxed);
        }
    }

    fn run_to_end(
        k: &Kinematics,
        choice: IntegratorChoice,
        cancel: &AtomicBool,
        progress: &AtomicU64,
    ) -> Result<DynamicRun, RunError> {
        let mut run = start_run(k, choice)?;
        while !run.advance(STEPS_PER_CHUNK).map_err(RunError::Solver)? {
            if cancel.load(Ordering::Relaxed) {
                return Err(RunError::Cancelled);
            }
            progress.store(run.time_s().to_bits(), Ordering::Relaxed);
        }
        Ok(DynamicRun::from_simulation(choice, run.finish()))
    }
}
