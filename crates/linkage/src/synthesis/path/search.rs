//! The path search as a resumable job: differential evolution finds basins, and
//! every few generations Levenberg–Marquardt polishes the best member to the exact
//! targets. A polished design within tolerance is kept and the evolution restarts
//! from a fresh population to look for another; so does one that has stalled.
//! [`PathSearch::step`] runs a slice of evaluations at a time, for a caller that
//! must keep drawing frames (the browser) or that wants progress.

use super::design::PathDesign;
use super::evolution::{Population, SplitMix};
use super::least_squares::{Settings, minimise};
use super::problem::Problem;
use super::{PARAMS, SearchOptions};

/// Generations between polishes of the best member.
const POLISH_EVERY: u32 = 10;
/// Generations without a 1 % gain after which the evolution restarts.
const STALL: u32 = 60;

/// Where a search stands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Progress {
    /// Evaluations of a candidate linkage so far.
    pub evaluations: u64,
    /// The budget of evaluations.
    pub max_evaluations: u64,
    /// The best design's largest miss over the targets' size (the evolution's
    /// coarse figure until a design has been polished).
    pub best_relative_error: f64,
    /// Designs found within the tolerance.
    pub solutions: usize,
    /// Whether the search has finished (enough solutions, or its budget spent).
    pub done: bool,
    /// Wall-clock time spent searching so far, s.
    pub seconds: f64,
}

impl Progress {
    /// The share of the budget spent, 0 to 1.
    pub fn fraction(&self) -> f64 {
        if self.done {
            return 1.0;
        }
        (self.evaluations as f64 / self.max_evaluations.max(1) as f64).min(1.0)
    }
}

/// A path search under way.
#[derive(Clone, Debug)]
pub struct PathSearch {
    problem: Problem,
    options: SearchOptions,
    rng: SplitMix,
    population: Option<Population>,
    generations: u32,
    since_gain: u32,
    run_best: f64,
    /// The best coarse cost when last polished: polishing again pays only after a gain.
    polished_at: f64,
    evaluations: u64,
    max_evaluations: u64,
    seconds: f64,
    found: Vec<PathDesign>,
    /// The normalised parameters and branch of each found design, to tell them apart.
    found_params: Vec<([f64; PARAMS], bool)>,
}

impl PathSearch {
    pub(super) fn start(problem: Problem, options: SearchOptions) -> Self {
        Self {
            rng: SplitMix::new(options.seed),
            max_evaluations: options.max_evaluations,
            problem,
            options,
            population: None,
            generations: 0,
            since_gain: 0,
            run_best: f64::INFINITY,
            polished_at: f64::INFINITY,
            evaluations: 0,
            seconds: 0.0,
            found: vec![],
            found_params: vec![],
        }
    }

    /// Runs at least `evaluations` more evaluations (whole generations), or to the end.
    pub fn step(&mut self, evaluations: u64) -> Progress {
        let started = web_time::Instant::now();
        let until = self.evaluations.saturating_add(evaluations);
        while self.evaluations < until && !self.is_done() {
            self.generation();
        }
        self.seconds += started.elapsed().as_secs_f64();
        self.progress()
    }

    /// Runs to the end.
    pub fn run(&mut self) -> Progress {
        self.step(u64::MAX)
    }

    /// Raises the budget by `evaluations`, to go on after the search has ended.
    pub fn extend(&mut self, evaluations: u64) {
        self.max_evaluations = self
            .max_evaluations
            .max(self.evaluations)
            .saturating_add(evaluations);
    }

    /// Whether enough solutions are found or the budget is spent.
    pub fn is_done(&self) -> bool {
        self.solutions() >= self.options.solutions || self.evaluations >= self.max_evaluations
    }

    fn solutions(&self) -> usize {
        self.found
            .iter()
            .filter(|d| d.relative_error <= self.options.tolerance)
            .count()
    }

    /// Where the search stands.
    pub fn progress(&self) -> Progress {
        let coarse = self
            .population
            .as_ref()
            .map_or(f64::INFINITY, |p| p.costs[p.best()]);
        let polished = self
            .found
            .first()
            .map_or(f64::INFINITY, |d| d.relative_error);
        Progress {
            evaluations: self.evaluations,
            max_evaluations: self.max_evaluations,
            best_relative_error: polished.min(coarse),
            solutions: self.solutions(),
            done: self.is_done(),
            seconds: self.seconds,
        }
    }

    /// The designs found, best first (those outside the tolerance included).
    pub fn designs(&self) -> &[PathDesign] {
        &self.found
    }

    /// The best design now: the best found, or the evolution's best member while
    /// none is found (for showing the search's progress live).
    pub fn leader(&self) -> Option<PathDesign> {
        let Some(population) = self.population.as_ref() else {
            // Between a restart and the next generation.
            return self.found.first().cloned();
        };
        let i = population.best();
        let live = PathDesign::new(
            &self.problem,
            &population.members[i],
            population.members[i][PARAMS] >= 0.0,
            &population.angles[i],
        );
        match self.found.first() {
            Some(d) if d.relative_error <= live.relative_error => Some(d.clone()),
            _ => Some(live),
        }
    }

    fn generation(&mut self) {
        let size = self.options.population.max(8);
        let Some(population) = self.population.as_mut() else {
            self.population = Some(Population::random(&self.problem, size, &mut self.rng));
            self.evaluations += size as u64;
            return;
        };
        self.evaluations += population.evolve(&self.problem, &mut self.rng);
        self.generations += 1;
        let best = population.costs[population.best()];
        if best < 0.99 * self.run_best {
            self.run_best = best;
            self.since_gain = 0;
        } else {
            self.since_gain += 1;
        }
        let stalled = self.since_gain >= STALL;
        let gained = best < 0.5 * self.polished_at;
        if (self.generations.is_multiple_of(POLISH_EVERY) && gained) || stalled {
            self.polished_at = best;
            let met = self.polish_best();
            if met || stalled {
                self.restart();
            }
        }
    }

    fn restart(&mut self) {
        self.population = None;
        self.generations = 0;
        self.since_gain = 0;
        self.run_best = f64::INFINITY;
        self.polished_at = f64::INFINITY;
    }

    /// Polishes the best member; keeps the result if it meets the constraints and
    /// returns whether it is within tolerance.
    fn polish_best(&mut self) -> bool {
        let Some(population) = self.population.as_ref() else {
            return false;
        };
        let i = population.best();
        let left = population.members[i][PARAMS] >= 0.0;
        let u0 = self
            .problem
            .unknowns(&population.members[i], &population.angles[i]);
        let problem = &self.problem;
        let tolerance = self.options.tolerance;
        let settings = Settings {
            iterations: 100,
            cost_floor: (1e-3 * tolerance).powi(2),
            step: 1e-7,
        };
        let fit = minimise(&u0, problem.residual_count(), settings, |u, r| {
            problem.residuals(u, left, r)
        });
        let Some(fit) = fit else {
            return false;
        };
        self.evaluations += fit.evaluations;
        let angles = problem.angles_of(&fit.x);
        let design = PathDesign::new(problem, &fit.x, left, &angles);
        if !self.feasible(&design, &fit.x, left) {
            return false;
        }
        let met = design.relative_error <= tolerance;
        self.keep(design, &fit.x, left);
        met
    }

    /// Whether the polished design meets the user's constraints exactly.
    fn feasible(&self, design: &PathDesign, u: &[f64], left: bool) -> bool {
        let limits = &self.problem.limits;
        let m = super::geometry::CouplerFourBar::from_params(&u[..PARAMS], left);
        let slack = 1e-9;
        design.relative_error.is_finite()
            && (!limits.crank_turns || m.turning_shortfall() <= slack)
            && self.problem.outside_region(&m) <= slack
            && (!limits.one_branch || design.min_transmission_deg.is_some())
            && design
                .min_transmission_deg
                .is_none_or(|mu| mu.to_radians() >= limits.min_transmission - slack)
    }

    /// Keeps `design` if it is new, or in place of a worse twin; best first.
    fn keep(&mut self, design: PathDesign, u: &[f64], left: bool) {
        let params: [f64; PARAMS] = std::array::from_fn(|k| u[k]);
        let twin = self.found_params.iter().position(|(p, l)| {
            *l == left
                && p.iter()
                    .zip(&params)
                    .map(|(a, b)| (a - b).abs())
                    .fold(0.0, f64::max)
                    < 1e-3
        });
        match twin {
            Some(k) if self.found[k].relative_error <= design.relative_error => return,
            Some(k) => {
                self.found.remove(k);
                self.found_params.remove(k);
            }
            None => {}
        }
        let at = self
            .found
            .partition_point(|d| d.relative_error <= design.relative_error);
        self.found.insert(at, design);
        self.found_params.insert(at, (params, left));
    }
}
