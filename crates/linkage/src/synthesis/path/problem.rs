//! The path-generation problem in normalised coordinates (targets centred on their
//! centroid and scaled by their size, so bounds and tolerances are the same for a
//! watch part and a press): its constraints, the global search's vectors
//! ([`Encoding`]) and the exact residuals the least-squares refinement uses. The
//! search's coarse costs are in `coarse.rs`.

use std::f64::consts::PI;

use super::geometry::{CouplerFourBar, PARAMS};
use super::shape::{POINT_RATIO, RATIO, SHAPE};
use crate::motion::Vec2;

/// Constraints in normalised units.
#[derive(Clone, Debug)]
pub struct Limits {
    /// The crank must turn through a whole revolution.
    pub crank_turns: bool,
    /// Least transmission angle over the travel through the targets, rad.
    pub min_transmission: f64,
    /// Where both ground pivots must lie: lower and upper corners.
    pub region: [Vec2; 2],
    /// The targets must lie on one branch, reached without a dead point.
    pub one_branch: bool,
}

/// What a vector of the global search holds, by how the targets are given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    /// Crank angles given: the shape ([`SHAPE`] numbers), the branch, and where in
    /// the crank's closing arcs the travel through the targets lies.
    Timed,
    /// Untimed, met in the order given once round the curve: the shape, the branch,
    /// where in the closing arcs the travel lies, and its share of them, signed by
    /// its sense.
    InOrder,
    /// Untimed, in any order: the four-bar's nine numbers in the targets' frame and
    /// the branch (the search before targets kept their order).
    AnyOrder,
}

/// Targets, timing, limits and encoding, normalised.
#[derive(Clone, Debug)]
pub struct Problem {
    /// The targets.
    pub targets: Vec<Vec2>,
    /// Crank angles of the targets relative to the first, rad, when timed.
    pub timing: Option<Vec<f64>>,
    /// The constraints.
    pub limits: Limits,
    /// What the search's vectors hold.
    pub encoding: Encoding,
    /// Each target's share of the length of the polyline through the targets in
    /// order (0 at the first, 1 at the last): where along the curve to place it first.
    pub along: Vec<f64>,
    /// World point of the normalised origin.
    pub centre: Vec2,
    /// World length of the normalised unit.
    pub scale: f64,
}

/// Each point's share of the length of the polyline through `points` in order.
pub fn shares_along(points: &[Vec2]) -> Vec<f64> {
    let mut run = vec![0.0];
    for w in points.windows(2) {
        let last = run.last().copied().unwrap_or(0.0);
        run.push(last + (w[1] - w[0]).norm());
    }
    let total = run.last().copied().unwrap_or(0.0);
    run.iter()
        .map(|l| if total > 0.0 { l / total } else { 0.0 })
        .collect()
}

impl Problem {
    /// Lower and upper bounds of the global search's unknowns (see [`Encoding`]);
    /// a branch selector's sign picks the branch.
    pub fn bounds(&self) -> Vec<(f64, f64)> {
        match self.encoding {
            Encoding::AnyOrder => self.world_bounds(),
            Encoding::Timed | Encoding::InOrder => {
                let (ratio, point) = (RATIO.ln(), POINT_RATIO.ln());
                let mut b = vec![(-ratio, ratio); SHAPE - 2];
                b.push((-point, point));
                b.push((-PI, PI));
                b.push((-1.0, 1.0));
                // Where the travel lies in the closing arcs, and (in order) its share
                // of them with its sense: see `coarse.rs`.
                b.push((0.0, 2.0));
                if self.encoding == Encoding::InOrder {
                    b.push((-1.0, 1.0));
                }
                b
            }
        }
    }

    /// The four-bar's nine numbers and the branch, in the targets' frame: pivots in
    /// the region, links long enough to reach the targets from anywhere in it.
    fn world_bounds(&self) -> Vec<(f64, f64)> {
        let [lo, hi] = self.limits.region;
        let reach = lo.abs().max().max(hi.abs().max()) + 1.0;
        vec![
            (lo.x, hi.x),
            (lo.y, hi.y),
            (lo.x, hi.x),
            (lo.y, hi.y),
            (0.02, 1.0),
            (0.05, 2.0 * reach),
            (0.05, 2.0 * reach),
            (-reach, reach),
            (-reach, reach),
            (-1.0, 1.0),
        ]
    }

    /// The crank angle of target `i` when timed, from the first's.
    pub fn timed_angle(&self, first: f64, i: usize) -> f64 {
        self.timing.as_ref().map_or(first, |t| first + t[i])
    }

    /// Number of exact residuals: three per target and three constraint terms.
    pub fn residual_count(&self) -> usize {
        3 * self.targets.len() + 3
    }

    /// The refinement's unknowns from a four-bar's nine numbers and the targets' crank
    /// angles: the numbers, then the first target's crank angle (timed) or every
    /// target's (untimed).
    pub fn unknowns(&self, params: &[f64; PARAMS], angles: &[f64]) -> Vec<f64> {
        let mut u = params.to_vec();
        match self.timing {
            Some(_) => u.push(angles[0]),
            None => u.extend_from_slice(angles),
        }
        u
    }

    /// The targets' crank angles from the refinement's unknowns.
    pub fn angles_of(&self, u: &[f64]) -> Vec<f64> {
        match self.timing {
            Some(_) => (0..self.targets.len())
                .map(|i| self.timed_angle(u[PARAMS], i))
                .collect(),
            None => u[PARAMS..].to_vec(),
        }
    }

    /// The exact residuals of the refinement's unknowns `u` on branch `left`: each
    /// target's miss and how far its position is from closing, then the turning
    /// shortfall, the pivots' distance outside the region and the transmission
    /// angle's deficit (each 0 when met). False only where a length is not positive.
    pub fn residuals(&self, u: &[f64], left: bool, out: &mut [f64]) -> bool {
        let m = CouplerFourBar::from_params(&u[..PARAMS], left);
        let angles = self.angles_of(u);
        for (i, (target, &theta)) in self.targets.iter().zip(&angles).enumerate() {
            let Some((p, gap)) = m.point_and_gap_at(theta) else {
                return false;
            };
            out[3 * i] = p.x - target.x;
            out[3 * i + 1] = p.y - target.y;
            out[3 * i + 2] = gap;
        }
        self.constraint_residuals(&m, &angles, out);
        true
    }

    /// Writes the residuals after the targets' three each: the turning shortfall
    /// (when the crank must turn), the pivots' distance outside the region and the
    /// transmission angle's deficit over `angles`.
    pub fn constraint_residuals(&self, m: &CouplerFourBar, angles: &[f64], out: &mut [f64]) {
        let n = 3 * self.targets.len();
        out[n] = if self.limits.crank_turns {
            m.turning_shortfall()
        } else {
            0.0
        };
        out[n + 1] = self.outside_region(m);
        out[n + 2] = self.transmission_deficit(m, angles);
    }

    /// How far the ground pivots lie outside the region (0 inside).
    pub fn outside_region(&self, m: &CouplerFourBar) -> f64 {
        let [lo, hi] = self.limits.region;
        let out = |p: Vec2| {
            (lo.x - p.x).max(0.0)
                + (p.x - hi.x).max(0.0)
                + (lo.y - p.y).max(0.0)
                + (p.y - hi.y).max(0.0)
        };
        out(m.a) + out(m.d)
    }

    /// The crank's travel through the targets at `angles` (rad), as the encoding
    /// asks: in their order (the arc from the first to the last, in the sense the
    /// second lies), or the shortest arc holding them all (timed, any order). `None`
    /// where that arc leaves the branch.
    pub fn travel(&self, m: &CouplerFourBar, angles: &[f64]) -> Option<(f64, f64)> {
        match self.encoding {
            Encoding::InOrder => m.ordered_travel(angles),
            Encoding::Timed | Encoding::AnyOrder => m.travel(angles),
        }
    }

    /// How far the least transmission angle over the travel falls below the least
    /// allowed, rad (0 when it does not, or where no travel stays on the branch).
    pub fn transmission_deficit(&self, m: &CouplerFourBar, angles: &[f64]) -> f64 {
        if self.limits.min_transmission <= 0.0 {
            return 0.0;
        }
        self.travel(m, angles)
            .map_or(0.0, |arc| self.transmission_short_over(m, arc))
    }

    /// How far the least transmission angle over the crank arc `(start, len)` falls
    /// below the least allowed, rad (0 when it does not).
    pub fn transmission_short_over(&self, m: &CouplerFourBar, (start, len): (f64, f64)) -> f64 {
        (self.limits.min_transmission - m.least_transmission_over(start, len)).max(0.0)
    }
}
