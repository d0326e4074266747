//! Long work off the frame, one way for every kind: natively on a worker thread; in
//! the browser, which has no threads here, a slice of a few milliseconds per frame.
//! The dynamic run and the path search are both [`Work`]; a [`Job`] runs either,
//! shows what it has reached each frame, stops, continues, and hands the work back.
//! Slicing does not change the work: it takes the same steps either way.

/// Work done in steps, each about a millisecond.
pub trait Work: Send + 'static {
    /// What the frame shows of the work while it runs.
    type Snapshot: Clone + Send + 'static;

    /// Steps a worker thread takes between two snapshots.
    const THREAD_STEPS: u32 = 1;

    /// Takes `steps` steps; returns whether the work is done (finished or failed).
    fn advance(&mut self, steps: u32) -> bool;

    /// What the frame shows now.
    fn snapshot(&self) -> Self::Snapshot;
}

/// How the slices of a sliced job went (the browser test judges by these that frames
/// kept coming).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Slices {
    /// Slices run (one per frame).
    pub count: u64,
    /// The longest slice, ms.
    pub longest_ms: f64,
    /// The longest single step of a slice (its granularity: a slice ends at the
    /// first step past its budget), ms.
    pub longest_step_ms: f64,
}

/// Work under way, stopped or done.
pub struct Job<W: Work> {
    state: State<W>,
    snapshot: W::Snapshot,
    slices: Slices,
}

enum State<W: Work> {
    /// Natively: the work goes on in a thread until done or told to stop.
    #[cfg(not(target_arch = "wasm32"))]
    Thread(worker::Worker<W>),
    /// Advanced a slice per [`Job::poll`].
    Sliced(Box<W>),
    /// Not running: stopped, or done.
    Stopped(Box<W>),
    /// Between states, or the work was taken (or its thread panicked).
    Gone,
}

impl<W: Work> Job<W> {
    /// Starts `work` off the frame: on a thread natively, in slices in the browser.
    pub fn start(work: W) -> Self {
        let snapshot = work.snapshot();
        Self {
            state: State::running(Box::new(work)),
            snapshot,
            slices: Slices::default(),
        }
    }

    /// Starts `work` to be advanced only by [`Job::poll`] on the caller's thread (the
    /// browser's way; natively too, to test it).
    pub fn start_sliced(work: W) -> Self {
        let snapshot = work.snapshot();
        Self {
            state: State::Sliced(Box::new(work)),
            snapshot,
            slices: Slices::default(),
        }
    }

    /// Advances a sliced job by about `budget_ms` of this thread's time (none for a
    /// budget of 0 or NaN: a frame with none left), or takes a thread's latest
    /// snapshot; returns what to show. A job whose work is done stops.
    pub fn poll(&mut self, budget_ms: f64) -> &W::Snapshot {
        match &mut self.state {
            #[cfg(not(target_arch = "wasm32"))]
            State::Thread(w) => {
                self.snapshot = w.snapshot();
                if w.finished() {
                    self.stop();
                }
            }
            State::Sliced(work) => {
                let done = run_slice(work.as_mut(), budget_ms, &mut self.slices);
                self.snapshot = work.snapshot();
                if done {
                    self.stop();
                }
            }
            State::Stopped(_) | State::Gone => {}
        }
        &self.snapshot
    }

    /// What to show now.
    pub fn snapshot(&self) -> &W::Snapshot {
        &self.snapshot
    }

    /// How the slices went so far (none for work on a thread).
    pub fn slices(&self) -> Slices {
        self.slices
    }

    /// Whether the work is running.
    pub fn is_running(&self) -> bool {
        !matches!(self.state, State::Stopped(_) | State::Gone)
    }

    /// Stops the work where it is (waiting for a thread's current steps); it can
    /// continue.
    pub fn stop(&mut self) {
        self.state = match std::mem::replace(&mut self.state, State::Gone) {
            #[cfg(not(target_arch = "wasm32"))]
            State::Thread(w) => match w.stop() {
                Some(work) => {
                    self.snapshot = work.snapshot();
                    State::Stopped(work)
                }
                None => State::Gone,
            },
            State::Sliced(work) | State::Stopped(work) => State::Stopped(work),
            State::Gone => State::Gone,
        };
    }

    /// Continues stopped work, first changed by `prepare` (more budget, say): on a
    /// thread natively unless `sliced`.
    pub fn resume(&mut self, sliced: bool, prepare: impl FnOnce(&mut W)) {
        if let State::Stopped(mut work) = std::mem::replace(&mut self.state, State::Gone) {
            prepare(&mut work);
            self.state = if sliced {
                State::Sliced(work)
            } else {
                State::running(work)
            };
        } else {
            debug_assert!(false, "resume of a job that is not stopped");
        }
    }

    /// The work, once stopped or done; `None` while it runs, or once taken.
    pub fn take(&mut self) -> Option<Box<W>> {
        match std::mem::replace(&mut self.state, State::Gone) {
            State::Stopped(work) => Some(work),
            running => {
                self.state = running;
                None
            }
        }
    }

    /// Runs the work to its end here, or waits for its thread; then hands it back
    /// (`None` if its thread panicked).
    pub fn finish(mut self) -> Option<Box<W>> {
        #[cfg(not(target_arch = "wasm32"))]
        if matches!(self.state, State::Thread(_))
            && let State::Thread(w) = std::mem::replace(&mut self.state, State::Gone)
        {
            return w.join();
        }
        while self.is_running() {
            self.poll(f64::INFINITY);
        }
        self.take()
    }
}

/// Steps `work` until `budget_ms` is spent or it is done, noting the slice; returns
/// whether it is done.
fn run_slice<W: Work>(work: &mut W, budget_ms: f64, slices: &mut Slices) -> bool {
    let started = web_time::Instant::now();
    let elapsed_ms = || started.elapsed().as_secs_f64() * 1e3;
    let mut done = false;
    while !done && elapsed_ms() < budget_ms {
        let before = elapsed_ms();
        done = work.advance(1);
        slices.longest_step_ms = slices.longest_step_ms.max(elapsed_ms() - before);
    }
    slices.count += 1;
    slices.longest_ms = slices.longest_ms.max(elapsed_ms());
    done
}

impl<W: Work> State<W> {
    #[cfg(not(target_arch = "wasm32"))]
    fn running(work: Box<W>) -> Self {
        State::Thread(worker::Worker::spawn(work))
    }

    #[cfg(target_arch = "wasm32")]
    fn running(work: Box<W>) -> Self {
        State::Sliced(work)
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod worker {
    //! The work on its own thread, publishing a snapshot after every few steps and
    //! stopped when asked or when its job is dropped.

    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::{Arc, Mutex, PoisonError};
    use std::thread::JoinHandle;

    use super::Work;

    /// Work running on a thread.
    pub struct Worker<W: Work> {
        stop: Arc<AtomicBool>,
        latest: Arc<Mutex<W::Snapshot>>,
        handle: Option<JoinHandle<Box<W>>>,
    }

    impl<W: Work> Worker<W> {
        pub fn spawn(mut work: Box<W>) -> Self {
            let stop = Arc::new(AtomicBool::new(false));
            let latest = Arc::new(Mutex::new(work.snapshot()));
            let (flag, out) = (stop.clone(), latest.clone());
            let handle = std::thread::spawn(move || {
                while !flag.load(Ordering::Relaxed) {
                    let done = work.advance(W::THREAD_STEPS);
                    *out.lock().unwrap_or_else(PoisonError::into_inner) = work.snapshot();
                    if done {
                        break;
                    }
                }
                work
            });
            Self {
                stop,
                latest,
                handle: Some(handle),
            }
        }

        pub fn snapshot(&self) -> W::Snapshot {
            self.latest
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .clone()
        }

        pub fn finished(&self) -> bool {
            self.handle.as_ref().is_none_or(JoinHandle::is_finished)
        }

        /// Stops the thread and takes the work back (`None` if the thread panicked).
        pub fn stop(mut self) -> Option<Box<W>> {
            self.stop.store(true, Ordering::Relaxed);
            self.handle.take()?.join().ok()
        }

        /// Waits for the work's end and takes it back.
        pub fn join(mut self) -> Option<Box<W>> {
            self.handle.take()?.join().ok()
        }
    }

    impl<W: Work> Drop for Worker<W> {
        /// A dropped job's thread stops at its next snapshot: nobody waits for it.
        fn drop(&mut self) {
            self.stop.store(true, Ordering::Relaxed);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Counts to `end`, `steps` at a time.
    struct Count {
        n: u64,
        end: u64,
    }

    impl Work for Count {
        type Snapshot = u64;
        const THREAD_STEPS: u32 = 3;

        fn advance(&mut self, steps: u32) -> bool {
            self.n = (self.n + u64::from(steps)).min(self.end);
            self.n == self.end
        }

        fn snapshot(&self) -> u64 {
            self.n
        }
    }

    #[test]
    fn a_job_on_a_thread_and_in_slices_ends_at_the_same_work() {
        let threaded = Job::start(Count { n: 0, end: 1000 }).finish();
        assert_eq!(threaded.map(|c| c.n), Some(1000));
        let mut sliced = Job::start_sliced(Count { n: 0, end: 1000 });
        assert_eq!(sliced.poll(0.0), &0, "no time left, no step");
        while sliced.is_running() {
            sliced.poll(f64::INFINITY);
        }
        assert_eq!(sliced.snapshot(), &1000);
        assert_eq!(sliced.take().map(|c| c.n), Some(1000));
        assert!(sliced.take().is_none(), "the work is handed out once");
    }

    /// A job polled to its end, then finished, hands its work back (the dynamic run
    /// waited for after the frames saw it end).
    #[test]
    fn a_job_seen_done_still_hands_its_work_back() {
        let mut job = Job::start(Count { n: 0, end: 50 });
        while job.is_running() {
            job.poll(f64::INFINITY);
        }
        assert_eq!(job.finish().map(|c| c.n), Some(50));
    }

    #[test]
    fn a_stopped_job_continues_where_it_stopped() {
        // A thread told to stop stops, whatever work is left.
        let mut endless = Job::start(Count {
            n: 0,
            end: u64::MAX,
        });
        endless.stop();
        assert!(!endless.is_running());
        let reached = *endless.snapshot();
        endless.resume(true, |c| c.end = reached + 7);
        while endless.is_running() {
            endless.poll(f64::INFINITY);
        }
        assert_eq!(endless.snapshot(), &(reached + 7));
    }
}
