//! The path search off the frame as a [`crate::job::Job`]: natively on a worker thread (whose generations
//! use every core through the solver's `parallel` feature); in the browser, which
//! has no threads here, a slice of a few milliseconds per frame. Either way the
//! window shows a [`Snapshot`] each frame: the progress, the best design so far
//! (its curve drawn live) and the designs found. Slicing does not change the
//! search: the same seed gives the same designs.

use linkage::synthesis::path::{PathDesign, PathSearch, Progress};

use crate::job::{Job, Work};

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

pub use crate::job::Slices;

impl Work for PathSearch {
    type Snapshot = Snapshot;
    // Whole generations of the population (80) at a time on a thread: 4 × CHUNK keeps
    // the stop flag answered within a few milliseconds.
    const THREAD_STEPS: u32 = 4;

    fn advance(&mut self, steps: u32) -> bool {
        self.step(u64::from(steps) * CHUNK);
        self.is_done()
    }

    fn snapshot(&self) -> Snapshot {
        Snapshot::of(self)
    }
}

/// A search under way or stopped.
pub struct PathJob(Job<PathSearch>);

impl PathJob {
    /// Starts `search` off the frame: on a thread natively, in slices in the browser.
    pub fn start(search: PathSearch) -> Self {
        Self(Job::start(search))
    }

    /// Starts `search` to be advanced only by [`PathJob::poll`] (the browser's way;
    /// natively too, to test it).
    pub fn start_sliced(search: PathSearch) -> Self {
        Self(Job::start_sliced(search))
    }

    /// Advances a sliced search by about `budget_ms`, or takes a thread's latest
    /// snapshot; returns what to show.
    pub fn poll(&mut self, budget_ms: f64) -> &Snapshot {
        self.0.poll(budget_ms)
    }

    /// What to show now.
    pub fn snapshot(&self) -> &Snapshot {
        self.0.snapshot()
    }

    /// How the slices went so far (none for a search on a thread).
    pub fn slices(&self) -> Slices {
        self.0.slices()
    }

    /// Whether the search is running.
    pub fn is_running(&self) -> bool {
        self.0.is_running()
    }

    /// Stops the search where it is (it can continue).
    pub fn stop(&mut self) {
        self.0.stop();
    }

    /// Continues a stopped search (with more evaluations if it had spent its budget).
    pub fn resume(&mut self, sliced: bool) {
        self.0.resume(sliced, |search| {
            if search.is_done() {
                search.extend(MORE);
            }
        });
    }
}
