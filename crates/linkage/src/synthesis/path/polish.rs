//! The refinement of the evolution's best member to the exact targets, advanced an
//! iteration at a time so that a search in the browser keeps its frames: untimed,
//! first with the crank angles projected out (`projected.rs`), then with every
//! unknown together; timed, with every unknown at once.

use super::geometry::PARAMS;
use super::least_squares::{Minimiser, Settings};
use super::problem::Problem;

/// The least-squares settings of a refinement to `tolerance`: many iterations, but a
/// start that stops gaining is left at once (starts in the true solution's valley
/// crawl along it for hundreds of steps; starts at a local minimum gain nothing).
fn settings(tolerance: f64) -> Settings {
    Settings {
        iterations: 2000,
        cost_floor: (1e-3 * tolerance).powi(2),
        step: 6e-6,
        stall: 0.9,
    }
}

/// The settings of a last, patient refinement of a design that ended within
/// [`NEAR_MISS`] times the tolerance but not within it: where the targets barely
/// determine the linkage (smallest singular values of 1e-6 measured) the last
/// digits come slowly, and the stall rule above would leave them.
fn patient_settings(tolerance: f64) -> Settings {
    Settings {
        iterations: 5000,
        stall: 0.999,
        ..settings(tolerance)
    }
}

/// How far beyond the tolerance a refined design may miss and still be given the
/// patient refinement.
const NEAR_MISS: f64 = 30.0;

/// A four-bar to refine: its nine numbers, its branch (C left of B→D) and each
/// target's crank angle, rad.
pub type Start = ([f64; PARAMS], bool, Vec<f64>);

/// Which unknowns are being refined.
#[derive(Clone, Debug)]
enum Stage {
    /// The nine numbers, each target's angle its foot point from `start`;
    /// `patient` for the last refinement of a near miss.
    Projected {
        lm: Minimiser,
        start: Vec<f64>,
        feet: Vec<f64>,
        patient: bool,
    },
    /// The nine numbers and the angles (every target's, or the first's when timed);
    /// `patient` for the last refinement of a near miss.
    Joint { lm: Minimiser, patient: bool },
}

/// What a finished refinement gave.
pub enum Outcome {
    /// Refined numbers, branch and each target's crank angle.
    Refined {
        /// The four-bar's nine numbers.
        params: [f64; PARAMS],
        /// Each target's crank angle, rad.
        angles: Vec<f64>,
    },
    /// The residuals stopped existing (no linkage closes there).
    Failed,
}

/// A refinement under way.
#[derive(Clone, Debug)]
pub struct Polish {
    left: bool,
    tolerance: f64,
    stage: Stage,
    /// Whether the evolution had stalled when it began (it restarts afterwards).
    pub after_stall: bool,
    /// Whether it refines a start found from the dyads (`dyads.rs`), not a member of
    /// the evolution.
    pub from_dyads: bool,
}

impl Polish {
    /// A refinement of the four-bar `params` on branch `left` meeting the targets at
    /// `angles`; `None` where its residuals do not exist.
    pub fn start(
        problem: &Problem,
        (params, left, angles): Start,
        tolerance: f64,
        after_stall: bool,
    ) -> Option<Self> {
        let stage = first_stage(problem, &params, left, angles, settings(tolerance), false)?;
        Some(Self {
            left,
            tolerance,
            stage,
            after_stall,
            from_dyads: false,
        })
    }

    /// The branch refined.
    pub fn left(&self) -> bool {
        self.left
    }

    /// One iteration; returns the evaluations it used and, when finished, what it
    /// gave.
    pub fn advance(&mut self, problem: &Problem) -> (u64, Option<Outcome>) {
        let left = self.left;
        match &mut self.stage {
            Stage::Projected {
                lm,
                start,
                feet,
                patient,
            } => {
                let mut residuals =
                    |p: &[f64], r: &mut [f64]| problem.projected_residuals(p, left, start, feet, r);
                let used = lm.iterate(&mut residuals);
                if !lm.is_done() {
                    return (used, None);
                }
                let fitted = lm.fitted();
                let mut r = vec![0.0; problem.residual_count()];
                if !residuals(&fitted.x, &mut r) {
                    return (used, Some(Outcome::Failed));
                }
                let params: [f64; PARAMS] = std::array::from_fn(|k| fitted.x[k]);
                let angles = feet.clone();
                let patient = *patient;
                match joint(
                    problem,
                    &params,
                    left,
                    &angles,
                    settings(self.tolerance),
                    patient,
                ) {
                    Some(stage) => {
                        self.stage = stage;
                        (used, None)
                    }
                    None => (used, Some(Outcome::Failed)),
                }
            }
            Stage::Joint { lm, patient } => {
                let used = lm.iterate(&mut |u, r| problem.residuals(u, left, r));
                if !lm.is_done() {
                    return (used, None);
                }
                let x = lm.fitted().x;
                let miss = largest_miss(lm.residuals(), problem.targets.len());
                if !*patient && miss > self.tolerance && miss <= NEAR_MISS * self.tolerance {
                    // Untimed, the patient refinement projects the angles out again:
                    // jointly, an ill-determined linkage's last digits crawl.
                    let params: [f64; PARAMS] = std::array::from_fn(|k| x[k]);
                    let settings = patient_settings(self.tolerance);
                    let angles = problem.angles_of(&x);
                    if let Some(stage) = first_stage(problem, &params, left, angles, settings, true)
                    {
                        self.stage = stage;
                        return (used, None);
                    }
                }
                let outcome = Outcome::Refined {
                    params: std::array::from_fn(|k| x[k]),
                    angles: problem.angles_of(&x),
                };
                (used, Some(outcome))
            }
        }
    }
}

/// The first stage of a refinement of `params` on branch `left` meeting the targets
/// at `angles`: untimed, with the angles projected out; timed, every unknown at once.
fn first_stage(
    problem: &Problem,
    params: &[f64; PARAMS],
    left: bool,
    angles: Vec<f64>,
    settings: Settings,
    patient: bool,
) -> Option<Stage> {
    if problem.timing.is_none() {
        projected(problem, params, left, angles, settings, patient)
    } else {
        joint(problem, params, left, &angles, settings, patient)
    }
}

/// The projected refinement of `params`, each target's angle its foot point from
/// `angles`.
fn projected(
    problem: &Problem,
    params: &[f64; PARAMS],
    left: bool,
    angles: Vec<f64>,
    settings: Settings,
    patient: bool,
) -> Option<Stage> {
    let mut feet = angles.clone();
    let lm = Minimiser::new(params, problem.residual_count(), settings, &mut |p, r| {
        problem.projected_residuals(p, left, &angles, &mut feet, r)
    })?;
    Some(Stage::Projected {
        lm,
        start: angles,
        feet,
        patient,
    })
}

/// The joint refinement of `params` and `angles`.
fn joint(
    problem: &Problem,
    params: &[f64; PARAMS],
    left: bool,
    angles: &[f64],
    settings: Settings,
    patient: bool,
) -> Option<Stage> {
    let u0 = problem.unknowns(params, angles);
    let lm = Minimiser::new(&u0, problem.residual_count(), settings, &mut |u, r| {
        problem.residuals(u, left, r)
    })?;
    Some(Stage::Joint { lm, patient })
}

/// The largest distance of the coupler point from a target, in the targets'
/// normalised units (their size is 1), from residuals ordered as
/// [`Problem::residuals`] orders them.
fn largest_miss(r: &[f64], targets: usize) -> f64 {
    (0..targets)
        .map(|i| r[3 * i].hypot(r[3 * i + 1]))
        .fold(0.0, f64::max)
}
