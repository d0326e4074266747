//! Path generation: a four-bar whose coupler point passes through 3 to 20 target
//! points, with or without prescribed crank angles (timing). A global search
//! (differential evolution, `evolution`) over the coupler curve's shape, placed on
//! the targets by the similarity that fits best (`shape.rs`, `coarse.rs`), finds
//! basins; Levenberg–Marquardt (`least_squares`) then meets the targets exactly
//! where the four-bar can. The user's constraints (a crank that turns, a least
//! transmission angle, a region for the ground pivots, targets on one branch, in
//! their order) are penalties in the search and are checked exactly on every design
//! kept. Designs are kept by family (a four-bar and its two Roberts–Chebyshev
//! cognates, `cognates.rs`), ranked by their largest miss.
//!
//! With timing, the crank angles given are relative: the search chooses where the
//! first target is met and the others follow at the given differences. Without,
//! the targets are met in the order given, once round the curve, either way (or in
//! any order, when asked).

mod coarse;
mod cognates;
mod design;
mod dyads;
mod evolution;
mod family;
mod geometry;
mod least_squares;
mod polish;
mod problem;
mod projected;
mod search;
mod shape;
mod slide;

pub use cognates::TurnsWith;
pub use design::{PathCognate, PathDesign, PathLinkage};
pub use geometry::{CouplerFourBar, PARAMS, Pins};
pub use search::{PathSearch, Progress};

use serde::Serialize;

use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::motion::Vec2;
use problem::{Encoding, Limits, Problem};

/// How far from the targets' centroid, each way, the ground pivots may lie unless
/// the user gives a region, in units of the targets' size: ordinary four-bars have
/// their pivots up to about three sizes away.
pub const DEFAULT_REGION: f64 = 4.0;

/// Fewest targets a search takes.
pub const MIN_TARGETS: usize = 3;
/// Most targets a search takes.
pub const MAX_TARGETS: usize = 20;

/// The points the coupler point must pass through.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct PathTargets {
    /// The targets in order, m.
    pub points_m: Vec<[f64; 2]>,
    /// The crank angle at each target, deg (only differences matter), when timed.
    pub crank_deg: Option<Vec<f64>>,
}

/// How untimed targets are met along the coupler curve.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TargetOrder {
    /// In the order given, once round the curve, in either direction: as a designer
    /// lists the points the coupler must pass.
    #[default]
    AsGiven,
    /// In any order, each target on the curve wherever it is nearest.
    Any,
}

/// What the user asks of the linkage besides meeting the targets.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PathConstraints {
    /// The crank must turn through a whole revolution (off by default: targets from
    /// a rocking linkage have no turning-crank design, and a design whose crank rocks
    /// often has a cognate whose crank turns).
    pub crank_turns: bool,
    /// Least transmission angle over the crank's travel through the targets, deg
    /// (0 for none).
    pub min_transmission_deg: f64,
    /// Where both ground pivots must lie, as lower and upper corners, m; `None`
    /// for within [`DEFAULT_REGION`] times the targets' size of their centroid, each
    /// way.
    pub ground_region_m: Option<[[f64; 2]; 2]>,
    /// The targets must lie on one assembly branch, reached without a dead point.
    pub one_branch: bool,
    /// How untimed targets are met (timed ones follow their crank angles).
    pub order: TargetOrder,
}

impl Default for PathConstraints {
    fn default() -> Self {
        Self {
            crank_turns: false,
            min_transmission_deg: 0.0,
            ground_region_m: None,
            one_branch: true,
            order: TargetOrder::AsGiven,
        }
    }
}

/// How long and how hard to search.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SearchOptions {
    /// Seed of the search's random numbers: the same seed gives the same designs.
    pub seed: u64,
    /// Stop once this many families (a design and its cognates) are within tolerance.
    pub solutions: usize,
    /// A design is within tolerance when its largest miss is at most this share of
    /// the targets' size.
    pub tolerance: f64,
    /// Most evaluations of a candidate linkage.
    pub max_evaluations: u64,
    /// Members of the evolving population.
    pub population: usize,
}

impl Default for SearchOptions {
    fn default() -> Self {
        Self {
            seed: 1,
            solutions: 1,
            tolerance: 1e-6,
            max_evaluations: 3_000_000,
            population: 80,
        }
    }
}

fn invalid(param: Param, value: f64, valid: Valid) -> LinkageError {
    LinkageError::invalid(param, value, valid)
}

impl PathSearch {
    /// A search for `targets` under `constraints`; nothing runs until
    /// [`PathSearch::step`] or [`PathSearch::run`].
    ///
    /// # Errors
    /// Fewer than 3 or more than 20 targets, a value that is not finite, targets
    /// that all coincide, timing not given for every target, a ground region that
    /// is empty, a transmission angle outside 0 to 90°, or options that cannot run.
    pub fn new(
        targets: &PathTargets,
        constraints: &PathConstraints,
        options: SearchOptions,
    ) -> Result<Self> {
        check_options(&options)?;
        let problem = normalise(targets, constraints)?;
        Ok(Self::start(problem, options))
    }
}

fn check_options(o: &SearchOptions) -> Result<()> {
    if !(o.tolerance > 0.0 && o.tolerance < 1.0) {
        return Err(invalid(
            Param::SearchTolerance,
            o.tolerance,
            Valid::OpenUnit,
        ));
    }
    if o.solutions == 0 {
        return Err(invalid(Param::Solutions, 0.0, Valid::AtLeast(1)));
    }
    if o.population < 8 {
        return Err(invalid(
            Param::Population,
            o.population as f64,
            Valid::AtLeast(8),
        ));
    }
    Ok(())
}

/// The targets' centroid and size (the diagonal of their bounding box).
fn frame(points: &[[f64; 2]]) -> Result<(Vec2, f64)> {
    let n = points.len();
    if !(MIN_TARGETS..=MAX_TARGETS).contains(&n) {
        return Err(invalid(
            Param::Targets,
            n as f64,
            Valid::Count {
                lo: MIN_TARGETS,
                hi: MAX_TARGETS,
            },
        ));
    }
    if let Some(bad) = points.iter().flatten().find(|v| !v.is_finite()) {
        return Err(invalid(Param::TargetCoordinate, *bad, Valid::AFiniteNumber));
    }
    let (mut lo, mut hi) = (Vec2::repeat(f64::INFINITY), Vec2::repeat(f64::NEG_INFINITY));
    let mut centre = Vec2::zeros();
    for p in points {
        let p = Vec2::from(*p);
        lo = lo.inf(&p);
        hi = hi.sup(&p);
        centre += p / n as f64;
    }
    let size = (hi - lo).norm();
    if size <= 1e-12 * hi.abs().max().max(lo.abs().max()) || size == 0.0 {
        return Err(invalid(Param::TargetSpread, size, Valid::TargetsApart));
    }
    Ok((centre, size))
}

fn normalise(targets: &PathTargets, constraints: &PathConstraints) -> Result<Problem> {
    let (centre, scale) = frame(&targets.points_m)?;
    let timing = match &targets.crank_deg {
        None => None,
        Some(deg) if deg.len() != targets.points_m.len() => {
            return Err(invalid(
                Param::CrankAngles,
                deg.len() as f64,
                Valid::OnePerTarget,
            ));
        }
        Some(deg) => {
            if let Some(bad) = deg.iter().find(|v| !v.is_finite()) {
                return Err(invalid(Param::CrankAngle, *bad, Valid::FiniteDegrees));
            }
            Some(deg.iter().map(|d| (d - deg[0]).to_radians()).collect())
        }
    };
    let mu = constraints.min_transmission_deg;
    if !(0.0..90.0).contains(&mu) {
        return Err(invalid(Param::LeastTransmission, mu, Valid::Below90));
    }
    let region = match constraints.ground_region_m {
        None => [Vec2::repeat(-DEFAULT_REGION), Vec2::repeat(DEFAULT_REGION)],
        Some([lo, hi]) => {
            if let Some(bad) = lo.iter().chain(&hi).find(|v| !v.is_finite()) {
                return Err(invalid(
                    Param::GroundRegionCorner,
                    *bad,
                    Valid::AFiniteNumber,
                ));
            }
            if lo[0] >= hi[0] || lo[1] >= hi[1] {
                return Err(invalid(
                    Param::GroundRegionWidth,
                    (hi[0] - lo[0]).min(hi[1] - lo[1]),
                    Valid::MoreThanZero,
                ));
            }
            [
                (Vec2::from(lo) - centre) / scale,
                (Vec2::from(hi) - centre) / scale,
            ]
        }
    };
    let points: Vec<Vec2> = targets
        .points_m
        .iter()
        .map(|p| (Vec2::from(*p) - centre) / scale)
        .collect();
    let encoding = match (&timing, constraints.order) {
        (Some(_), _) => Encoding::Timed,
        (None, TargetOrder::AsGiven) => Encoding::InOrder,
        (None, TargetOrder::Any) => Encoding::AnyOrder,
    };
    Ok(Problem {
        along: problem::shares_along(&points),
        targets: points,
        encoding,
        timing,
        limits: Limits {
            crank_turns: constraints.crank_turns,
            min_transmission: mu.to_radians(),
            region,
            one_branch: constraints.one_branch,
        },
        centre,
        scale,
    })
}
