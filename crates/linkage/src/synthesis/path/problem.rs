//! The path-generation problem in normalised coordinates (targets centred on their
//! centroid and scaled by their size, so bounds and tolerances are the same for a
//! watch part and a press), and the two costs the search uses: a coarse one of a
//! sampled coupler curve for the global search, and exact residuals for the
//! least-squares refinement.

use std::f64::consts::TAU;

use super::geometry::{CouplerFourBar, PARAMS, to_segment};
use crate::motion::Vec2;

/// Crank angles the coarse cost samples the coupler curve at.
const SAMPLES: usize = 60;
/// The cost of a position that does not close, in units of the targets' size.
const OPEN: f64 = 10.0;

/// The distance from `target` to the coupler curve near crank angle `theta`, and
/// where: two rounds of fitting a parabola to the squared distance, a sample step
/// apart and then an eighth of one. The chord between samples would cut inside the
/// curve by up to a thousandth of its size at 6° and the search would chase that;
/// this is the curve itself to about 1e-8.
fn nearest_on_curve(m: &CouplerFourBar, target: Vec2, theta: f64, step: f64) -> (f64, f64) {
    let dist2 = |t: f64| {
        m.point_at(t)
            .map_or(f64::INFINITY, |p| (p - target).norm_squared())
    };
    let mut best = (dist2(theta), theta);
    for h in [0.5 * step, step / 16.0] {
        let centre = best.1;
        let (lo, mid, hi) = (dist2(centre - h), best.0, dist2(centre + h));
        let curvature = lo - 2.0 * mid + hi;
        if curvature.is_nan() || curvature <= 0.0 || !lo.is_finite() || !hi.is_finite() {
            continue;
        }
        let shift = (0.5 * h * (lo - hi) / curvature).clamp(-h, h);
        let at = centre + shift;
        let d = dist2(at);
        if d < best.0 {
            best = (d, at);
        }
    }
    (best.0.sqrt(), best.1)
}

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

/// Targets, timing and limits, normalised.
#[derive(Clone, Debug)]
pub struct Problem {
    /// The targets.
    pub targets: Vec<Vec2>,
    /// Crank angles of the targets relative to the first, rad, when timed.
    pub timing: Option<Vec<f64>>,
    /// The constraints.
    pub limits: Limits,
    /// World point of the normalised origin.
    pub centre: Vec2,
    /// World length of the normalised unit.
    pub scale: f64,
}

impl Problem {
    /// Lower and upper bounds of the global search's unknowns: the four-bar's nine
    /// parameters, a branch selector (its sign) and, when timed, the crank angle of
    /// the first target. A curve of unit size comes from links of about its size.
    pub fn bounds(&self) -> Vec<(f64, f64)> {
        let [lo, hi] = self.limits.region;
        let mut b = vec![
            (lo.x, hi.x),
            (lo.y, hi.y),
            (lo.x, hi.x),
            (lo.y, hi.y),
            (0.02, 1.0),
            (0.05, 2.5),
            (0.05, 2.5),
            (-1.5, 1.5),
            (-1.5, 1.5),
            (-1.0, 1.0),
        ];
        if self.timing.is_some() {
            b.push((0.0, TAU));
        }
        b
    }

    /// The four-bar a search vector describes.
    pub fn linkage(&self, v: &[f64]) -> CouplerFourBar {
        CouplerFourBar::from_params(&v[..PARAMS], v[PARAMS] >= 0.0)
    }

    /// The crank angle of target `i` when timed, from the first's.
    fn timed_angle(&self, first: f64, i: usize) -> f64 {
        self.timing.as_ref().map_or(first, |t| first + t[i])
    }

    /// The coarse cost of a search vector: root-mean-square distance of the targets
    /// from the coupler curve (sampled every 6°, untimed) or from the coupler point
    /// at their crank angles (timed), plus penalties for broken constraints. Also
    /// gives each target's crank angle, for the refinement to start from.
    pub fn coarse(&self, v: &[f64], angles: &mut [f64]) -> f64 {
        let m = self.linkage(v);
        let mut penalty = 0.0;
        if self.limits.crank_turns {
            penalty += 10.0 * m.turning_shortfall();
        }
        let sum = match self.timing {
            Some(_) => self.timed_sum(&m, v[PARAMS + 1], angles),
            None => self.untimed_sum(&m, angles),
        };
        let Some(sum) = sum else {
            return OPEN + penalty;
        };
        penalty += self.travel_penalty(&m, angles);
        (sum / self.targets.len() as f64).sqrt() + penalty
    }

    /// Penalties for leaving the branch between targets, or for a transmission
    /// angle below the least allowed over the travel.
    fn travel_penalty(&self, m: &CouplerFourBar, angles: &[f64]) -> f64 {
        let limits = &self.limits;
        if !limits.one_branch && limits.min_transmission <= 0.0 {
            return 0.0;
        }
        match m.travel(angles) {
            None if limits.one_branch => 1.0,
            None => 0.0,
            Some(arc) => self.transmission_short_over(m, arc),
        }
    }

    /// How far the least transmission angle over the crank arc `(start, len)`
    /// falls below the least allowed, rad (0 when it does not).
    fn transmission_short_over(&self, m: &CouplerFourBar, (start, len): (f64, f64)) -> f64 {
        (self.limits.min_transmission - m.least_transmission_over(start, len)).max(0.0)
    }

    fn timed_sum(&self, m: &CouplerFourBar, first: f64, angles: &mut [f64]) -> Option<f64> {
        let mut sum = 0.0;
        for (i, target) in self.targets.iter().enumerate() {
            angles[i] = self.timed_angle(first, i);
            sum += m
                .point_at(angles[i])
                .map_or(OPEN * OPEN, |p| (p - target).norm_squared());
        }
        Some(sum)
    }

    fn untimed_sum(&self, m: &CouplerFourBar, angles: &mut [f64]) -> Option<f64> {
        let step = TAU / SAMPLES as f64;
        let curve: [Option<Vec2>; SAMPLES] = std::array::from_fn(|k| m.point_at(k as f64 * step));
        if curve.iter().filter(|p| p.is_some()).count() < 2 {
            return None;
        }
        let mut sum = 0.0;
        for (i, target) in self.targets.iter().enumerate() {
            let mut best = (f64::INFINITY, 0.0);
            for k in 0..SAMPLES {
                if let (Some(p0), Some(p1)) = (curve[k], curve[(k + 1) % SAMPLES]) {
                    let (dist, t) = to_segment(*target, p0, p1);
                    if dist < best.0 {
                        best = (dist, (k as f64 + t) * step);
                    }
                }
            }
            if best.0.is_infinite() {
                return None;
            }
            let (dist, theta) = nearest_on_curve(m, *target, best.1, step);
            angles[i] = theta;
            sum += dist * dist;
        }
        Some(sum)
    }

    /// Number of exact residuals: three per target and three constraint terms.
    pub fn residual_count(&self) -> usize {
        3 * self.targets.len() + 3
    }

    /// The refinement's unknowns from a search vector and the targets' crank angles:
    /// the four-bar's parameters, then the first target's crank angle (timed) or
    /// every target's (untimed).
    pub fn unknowns(&self, v: &[f64], angles: &[f64]) -> Vec<f64> {
        let mut u = v[..PARAMS].to_vec();
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
        for (i, target) in self.targets.iter().enumerate() {
            let theta = match self.timing {
                Some(_) => self.timed_angle(u[PARAMS], i),
                None => u[PARAMS + i],
            };
            let Some((p, gap)) = m.point_and_gap_at(theta) else {
                return false;
            };
            out[3 * i] = p.x - target.x;
            out[3 * i + 1] = p.y - target.y;
            out[3 * i + 2] = gap;
        }
        let n = 3 * self.targets.len();
        out[n] = if self.limits.crank_turns {
            m.turning_shortfall()
        } else {
            0.0
        };
        out[n + 1] = self.outside_region(&m);
        out[n + 2] = self.transmission_deficit(&m, u);
        true
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

    fn transmission_deficit(&self, m: &CouplerFourBar, u: &[f64]) -> f64 {
        if self.limits.min_transmission <= 0.0 {
            return 0.0;
        }
        let angles = self.angles_of(u);
        m.travel(&angles)
            .map_or(0.0, |arc| self.transmission_short_over(m, arc))
    }
}
