//! The path search off the frame: natively on a worker thread (whose generations
//! use every core through the solver's `parallel` feature); in the browser, which
//! has no threads here, a slice of a few milliseconds per frame. Either way the
//! window shows a [`Snapshot`] each frame: the progress, the best design so far
//! (its curve drawn live) and the designs found. Slicing does not change the
//! search: the same seed gives the same designs.

use linkage::synthesis::path::{PathDesign, PathSearch, Progress};

/// Evaluations between two looks at the clock or the stop flag (about a millisecond).
const CHUNK: u64 = 160;
/// More evaluations granted when a finished search is continued.
const MORE: u64 = 1_000_000;

/// What the window shows of a search.
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// Where it stands.
    pub progress: Progress,
    /// The best design so far, polished or not.
    pub leader: Option<PathDesign>,
    /// The designs found, best first.
    pub designs: Vec<PathDesign>,
}

impl Snapshot {
    fn of(search: &PathSearch) -> Self {
        Self {
            progress: search.progress(),
            leader: search.leader(),
            designs: search.designs().to_vec(),
        }
    }
}

/// How the slices of a sliced search went (the browser test judges by these that
/// frames kept coming).
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

/// A search under way or stopped.
pub struct PathJob {
    state: State,
    snapshot: Snapshot,
    slices: Slices,
}

enum State {
    /// Natively: the search runs on a thread until done or told to stop.
    #[cfg(not(target_arch = "wasm32"))]
    Thread(worker::Worker),
    /// Advanced a slice per [`PathJob::poll`].
    Sliced(Box<PathSearch>),
    /// Not running: stopped, or done.
    Stopped(Box<PathSearch>),
    /// Only while changing state.
    Moving,
}

impl PathJob {
    /// Starts `search` off the frame: on a thread natively, in slices in the browser.
    pub fn start(search: PathSearch) -> Self {
        let snapshot = Snapshot::of(&search);
        Self {
            state: State::running(Box::new(search)),
            snapshot,
            slices: Slices::default(),
        }
    }

    /// Starts `search` to be advanced only by [`PathJob::poll`] (the browser's way;
    /// natively too, to test it).
    pub fn start_sliced(search: PathSearch) -> Self {
        let snapshot = Snapshot::of(&search);
        Self {
            state: State::Sliced(Box::new(search)),
            snapshot,
            slices: Slices::default(),
        }
    }

    /// Advances a sliced search by about `budget_ms`, or takes a thread's latest
    /// snapshot; returns what to show.
    pub fn poll(&mut self, budget_ms: f64) -> &Snapshot {
        match &mut self.state {
            #[cfg(not(target_arch = "wasm32"))]
            State::Thread(w) => {
                self.snapshot = w.snapshot();
                if w.finished() {
                    self.stop();
                }
            }
            State::Sliced(search) => {
                run_slice(search, budget_ms, &mut self.slices);
                self.snapshot = Snapshot::of(search);
                if search.is_done() {
                    self.stop();
                }
            }
            State::Stopped(_) | State::Moving => {}
        }
        &self.snapshot
    }

    /// What to show now.
    pub fn snapshot(&self) -> &Snapshot {
        &self.snapshot
    }

    /// How the slices went so far (none for a search on a thread).
    pub fn slices(&self) -> Slices {
        self.slices
    }

    /// Whether the search is running.
    pub fn is_running(&self) -> bool {
        !matches!(self.state, State::Stopped(_) | State::Moving)
    }

    /// Stops the search where it is (it can continue).
    pub fn stop(&mut self) {
        self.state = match std::mem::replace(&mut self.state, State::Moving) {
            #[cfg(not(target_arch = "wasm32"))]
            State::Thread(w) => match w.stop() {
                Some(search) => {
                    self.snapshot = Snapshot::of(&search);
                    State::Stopped(search)
                }
                None => State::Moving,
            },
            State::Sliced(search) | State::Stopped(search) => State::Stopped(search),
            State::Moving => State::Moving,
        };
    }

    /// Continues a stopped search (with more evaluations if it had spent its budget).
    pub fn resume(&mut self, sliced: bool) {
        if let State::Stopped(mut search) = std::mem::replace(&mut self.state, State::Moving) {
            if search.is_done() {
                search.extend(MORE);
            }
            self.state = if sliced {
                State::Sliced(search)
            } else {
                State::running(search)
            };
        }
    }
}

/// Steps `search` until `budget_ms` is spent or it is done, noting the slice.
fn run_slice(search: &mut PathSearch, budget_ms: f64, slices: &mut Slices) {
    let started = web_time::Instant::now();
    let elapsed_ms = || started.elapsed().as_secs_f64() * 1e3;
    while !search.is_done() && elapsed_ms() < budget_ms {
        let before = elapsed_ms();
        search.step(CHUNK);
        slices.longest_step_ms = slices.longest_step_ms.max(elapsed_ms() - before);
    }
    slices.count += 1;
    slices.longest_ms = slices.longest_ms.max(elapsed_ms());
}

impl State {
    #[cfg(not(target_arch = "wasm32"))]
    fn running(search: Box<PathSearch>) -> Self {
        State::Thread(worker::Worker::spawn(search))
    }

    #[cfg(target_arch = "wasm32")]
    fn running(search: Box<PathSearch>) -> Self {
        State::Sliced(search)
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod worker {
    //! The search on its own thread, publishing a snapshot after every chunk.

    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::{Arc, Mutex, PoisonError};
    use std::thread::JoinHandle;

    use linkage::synthesis::path::PathSearch;

    use super::{CHUNK, Snapshot};

    /// A running search.
    pub struct Worker {
        stop: Arc<AtomicBool>,
        latest: Arc<Mutex<Snapshot>>,
        handle: JoinHandle<Box<PathSearch>>,
    }

    impl Worker {
        pub fn spawn(mut search: Box<PathSearch>) -> Self {
            let stop = Arc::new(AtomicBool::new(false));
            let latest = Arc::new(Mutex::new(Snapshot::of(&search)));
            let (flag, out) = (stop.clone(), latest.clone());
            let handle = std::thread::spawn(move || {
                while !search.is_done() && !flag.load(Ordering::Relaxed) {
                    // Whole generations of the population (80) at a time: CHUNK × 4
                    // keeps the stop flag answered within a few milliseconds.
                    search.step(4 * CHUNK);
                    *out.lock().unwrap_or_else(PoisonError::into_inner) = Snapshot::of(&search);
                }
                search
            });
            Self {
                stop,
                latest,
                handle,
            }
        }

        pub fn snapshot(&self) -> Snapshot {
            self.latest
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .clone()
        }

        pub fn finished(&self) -> bool {
            self.handle.is_finished()
        }

        /// Stops the thread and takes the search back (`None` if the thread panicked).
        pub fn stop(self) -> Option<Box<PathSearch>> {
            self.stop.store(true, Ordering::Relaxed);
            self.handle.join().ok()
        }
    }
}
