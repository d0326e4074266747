//! The global search: differential evolution (current-to-pbest/1 with binomial
//! crossover, as in JADE) over the problem's search vectors, in generations that
//! a caller can run a slice at a time. Its random numbers come from SplitMix64
//! ([`crate::rng`]): the same designs for the same seed on every platform.

use super::problem::Problem;

pub use crate::rng::SplitMix;

/// One population of search vectors with their coarse costs and crank angles.
#[derive(Clone, Debug)]
pub struct Population {
    /// The members.
    pub members: Vec<Vec<f64>>,
    /// Their coarse costs.
    pub costs: Vec<f64>,
    /// Each member's targets' crank angles.
    pub angles: Vec<Vec<f64>>,
}

/// A coarse evaluation: cost and the targets' crank angles.
type Scored = (f64, Vec<f64>);

/// How far (as a share of each bound's width, in Euclidean distance) a place where
/// an earlier run of the evolution ended without a design raises the cost.
const NICHE_RADIUS: f64 = 0.05;
/// How much it raises it there, in units of the targets' size: above the costs of
/// the wrong basins that restarts fall into again and again (about 3e-3 measured).
const NICHE_HEIGHT: f64 = 1e-2;

/// What the evolution minimises: the problem's coarse cost, raised near the places
/// where earlier runs of the evolution ended without a design (sequential niching,
/// Beasley, Bull and Martin 1993), so that a restart explores elsewhere instead of
/// falling into the same wrong basin again.
pub struct Landscape<'a> {
    /// The problem.
    pub problem: &'a Problem,
    /// Where earlier runs ended without a design.
    pub visited: &'a [Vec<f64>],
}

impl Landscape<'_> {
    fn raised(&self, v: &[f64], bounds: &[(f64, f64)]) -> f64 {
        self.visited
            .iter()
            .map(|t| {
                let d = v
                    .iter()
                    .zip(t)
                    .zip(bounds)
                    .map(|((a, b), (lo, hi))| ((a - b) / (hi - lo)).powi(2))
                    .sum::<f64>()
                    .sqrt();
                NICHE_HEIGHT * (1.0 - d / NICHE_RADIUS).max(0.0)
            })
            .sum()
    }
}

fn score_all(landscape: &Landscape, vectors: &[Vec<f64>]) -> Vec<Scored> {
    let problem = landscape.problem;
    let bounds = problem.bounds();
    let score = |v: &Vec<f64>| {
        let mut angles = vec![0.0; problem.targets.len()];
        let cost = problem.coarse(v, &mut angles) + landscape.raised(v, &bounds);
        (
            if cost.is_finite() {
                cost
            } else {
                f64::INFINITY
            },
            angles,
        )
    };
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        vectors.par_iter().map(score).collect()
    }
    #[cfg(not(feature = "parallel"))]
    vectors.iter().map(score).collect()
}

impl Population {
    /// `size` members drawn uniformly within the bounds, scored.
    pub fn random(landscape: &Landscape, size: usize, rng: &mut SplitMix) -> Self {
        let bounds = landscape.problem.bounds();
        let members: Vec<Vec<f64>> = (0..size)
            .map(|_| {
                bounds
                    .iter()
                    .map(|&(lo, hi)| lo + (hi - lo) * rng.unit())
                    .collect()
            })
            .collect();
        let (costs, angles) = score_all(landscape, &members).into_iter().unzip();
        Self {
            members,
            costs,
            angles,
        }
    }

    /// The index of the least cost.
    pub fn best(&self) -> usize {
        (0..self.costs.len())
            .min_by(|&i, &j| self.costs[i].total_cmp(&self.costs[j]))
            .unwrap_or(0)
    }

    /// One generation; returns the evaluations it took.
    pub fn evolve(&mut self, landscape: &Landscape, rng: &mut SplitMix) -> u64 {
        let trials = self.trials(landscape.problem, rng);
        let scored = score_all(landscape, &trials);
        for (i, (trial, (cost, angles))) in trials.into_iter().zip(scored).enumerate() {
            if cost <= self.costs[i] {
                self.members[i] = trial;
                self.costs[i] = cost;
                self.angles[i] = angles;
            }
        }
        self.members.len() as u64
    }

    /// Mutants crossed with their parents: v = x + F (x_pbest − x) + F (x_r1 − x_r2),
    /// x_pbest one of the best tenth, F drawn per member from [0.4, 0.9).
    fn trials(&self, problem: &Problem, rng: &mut SplitMix) -> Vec<Vec<f64>> {
        let n = self.members.len();
        let mut ranked: Vec<usize> = (0..n).collect();
        ranked.sort_by(|&i, &j| self.costs[i].total_cmp(&self.costs[j]));
        let top = (n / 10).max(2);
        let bounds = problem.bounds();
        let dims = bounds.len();
        (0..n)
            .map(|i| {
                let pbest = &self.members[ranked[rng.below(top)]];
                let r1 = pick_other(rng, n, &[i]);
                let r2 = pick_other(rng, n, &[i, r1]);
                let f = 0.4 + 0.5 * rng.unit();
                let forced = rng.below(dims);
                let x = &self.members[i];
                (0..dims)
                    .map(|d| {
                        if d != forced && rng.unit() >= 0.9 {
                            return x[d];
                        }
                        let v = x[d]
                            + f * (pbest[d] - x[d])
                            + f * (self.members[r1][d] - self.members[r2][d]);
                        into_bounds(v, x[d], bounds[d])
                    })
                    .collect()
            })
            .collect()
    }
}

/// A member index other than those in `not`.
fn pick_other(rng: &mut SplitMix, n: usize, not: &[usize]) -> usize {
    loop {
        let k = rng.below(n);
        if !not.contains(&k) {
            return k;
        }
    }
}

/// A mutant coordinate outside its bounds goes halfway back to its parent's (the
/// JADE rule), which keeps the search near a bound without piling up on it.
fn into_bounds(v: f64, parent: f64, (lo, hi): (f64, f64)) -> f64 {
    if v < lo {
        0.5 * (lo + parent)
    } else if v > hi {
        0.5 * (hi + parent)
    } else {
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix_is_uniform_enough_and_repeatable() {
        let (mut a, mut b) = (SplitMix::new(7), SplitMix::new(7));
        let draws: Vec<f64> = (0..10_000).map(|_| a.unit()).collect();
        assert!(draws.iter().all(|&u| (0.0..1.0).contains(&u)));
        let mean = draws.iter().sum::<f64>() / draws.len() as f64;
        assert!((mean - 0.5).abs() < 0.01, "mean {mean}");
        assert!(draws.iter().all(|&u| u == b.unit()));
    }
}
