//! The global search's cost of a vector: how far the four-bar it describes passes
//! from the targets, plus penalties for broken constraints, and where on its curve
//! each target is met (the refinement starts there).
//!
//! Timed and in-order vectors hold a shape (see `shape.rs`); the curve is placed on
//! the targets by the similarity that fits best, so each cost is a fit. In order, the
//! targets are first spread along the curve's arc as they are spread along their own
//! polyline, then moved twice to their nearest points (in order) with a fit after
//! each move, as iterative closest points does. Any order keeps the search's earlier
//! vectors: the four-bar in the targets' frame, each target on its nearest point.

use std::f64::consts::{PI, TAU};

use nalgebra::Complex;

use super::geometry::{CouplerFourBar, PARAMS, to_segment};
use super::problem::{Encoding, Problem};
use super::shape::{SHAPE, Similarity, complex, fit, unit_linkage};
use super::slide::Places;
use crate::motion::Vec2;

/// Crank angles the curve is sampled at (once round untimed in any order; over the
/// travel in order).
const SAMPLES: usize = 60;
/// The cost of a position that does not close, in units of the targets' size.
const OPEN: f64 = 10.0;
/// Weight of a constraint's shortfall against a miss of the same size.
const PENALTY: f64 = 10.0;
/// Gauss–Newton steps of the targets sliding along the curve (`slide.rs`).
const SLIDES: usize = 3;

/// A search vector's four-bar, placed in the targets' frame.
pub struct Placed {
    /// The coarse cost.
    pub cost: f64,
    /// The four-bar, when one could be placed.
    pub linkage: Option<CouplerFourBar>,
}

impl Problem {
    /// The coarse cost of `v`, writing each target's crank angle into `angles`.
    pub fn coarse(&self, v: &[f64], angles: &mut [f64]) -> f64 {
        self.place(v, angles).cost
    }

    /// The four-bar of `v` in the targets' frame with its cost, writing each target's
    /// crank angle into `angles`.
    pub fn place(&self, v: &[f64], angles: &mut [f64]) -> Placed {
        let placed = match self.encoding {
            Encoding::Timed => self.place_timed(v, angles),
            Encoding::InOrder => self.place_in_order(v, angles),
            Encoding::AnyOrder => self.place_any_order(v, angles),
        };
        match placed {
            Some((cost, m)) if cost.is_finite() => Placed {
                cost,
                linkage: Some(m),
            },
            _ => Placed {
                cost: OPEN + 1.0,
                linkage: None,
            },
        }
    }

    /// The penalties of a placed four-bar: a crank that must turn and does not, pivots
    /// outside the region, and a travel that leaves the branch or falls below the
    /// least transmission angle.
    fn penalties(&self, m: &CouplerFourBar, angles: &[f64]) -> f64 {
        let limits = &self.limits;
        let mut p = PENALTY * self.outside_region(m);
        if limits.crank_turns {
            p += PENALTY * m.turning_shortfall();
        }
        if limits.one_branch || limits.min_transmission > 0.0 {
            p += match self.travel(m, angles) {
                None if limits.one_branch => 1.0,
                None => 0.0,
                Some(arc) => self.transmission_short_over(m, arc),
            };
        }
        p
    }

    /// The targets as complex numbers.
    fn targets_complex(&self) -> Vec<Complex<f64>> {
        self.targets.iter().map(|t| complex(*t)).collect()
    }

    fn place_timed(&self, v: &[f64], angles: &mut [f64]) -> Option<(f64, CouplerFourBar)> {
        let unit = unit_linkage(v, v[SHAPE] >= 0.0);
        let timing = self.timing.as_deref().unwrap_or(&[]);
        let lowest = timing.iter().copied().fold(0.0, f64::min);
        let highest = timing.iter().copied().fold(0.0, f64::max);
        let first = arc_place(&unit.closing_arcs(), v[SHAPE + 1], highest - lowest)? - lowest;
        let mut points = Vec::with_capacity(self.targets.len());
        let mut gaps = 0.0;
        for (i, angle) in angles.iter_mut().enumerate() {
            *angle = self.timed_angle(first, i);
            let (p, gap) = unit.point_and_gap_at(*angle)?;
            points.push(complex(p));
            gaps += gap;
        }
        let (sim, left) = fit(&points, &self.targets_complex())?;
        Some(self.settle(&unit, &sim, left, gaps, angles))
    }

    /// The cost of the unit four-bar `unit` placed by `sim` with `left` squared misses
    /// and `gaps` (unit lengths) of positions that do not close; turns `angles` from
    /// the unit linkage's crank angles into the placed one's.
    fn settle(
        &self,
        unit: &CouplerFourBar,
        sim: &Similarity,
        left: f64,
        gaps: f64,
        angles: &mut [f64],
    ) -> (f64, CouplerFourBar) {
        let m = sim.linkage(unit);
        let turn = sim.turn();
        angles.iter_mut().for_each(|a| *a += turn);
        let n = self.targets.len() as f64;
        let open = PENALTY * gaps * sim.alpha.norm() / n;
        let cost = (left / n).sqrt() + open + self.penalties(&m, angles);
        (cost, m)
    }

    fn place_in_order(&self, v: &[f64], angles: &mut [f64]) -> Option<(f64, CouplerFourBar)> {
        let unit = unit_linkage(v, v[SHAPE] >= 0.0);
        let arcs = unit.closing_arcs();
        let share = v[SHAPE + 2];
        let room = if arcs.len() == 1 {
            arcs[0].1
        } else {
            arcs.first()?.1
        };
        let length = share.abs() * room;
        let lower = arc_place(&arcs, v[SHAPE + 1], length)?;
        let (start, travel) = if share >= 0.0 {
            (lower, length)
        } else {
            (lower + length, -length)
        };
        let step = travel / SAMPLES as f64;
        let mut curve = [Vec2::zeros(); SAMPLES + 1];
        let mut gaps = 0.0;
        // The crank turned a step at a time by one fixed rotation: no sine or cosine
        // per sample (their round-off, 60 steps of an ulp, is far below any cost).
        let (sin, cos) = step.sin_cos();
        let mut along = Vec2::new(start.cos(), start.sin());
        for p in curve.iter_mut() {
            let (at, gap) = unit.point_and_gap_along(along)?;
            *p = at;
            gaps += gap / SAMPLES as f64;
            along = Vec2::new(cos * along.x - sin * along.y, sin * along.x + cos * along.y);
        }
        let mut index = self.spread_along(&curve);
        let mut points: Vec<Complex<f64>> = index
            .iter()
            .map(|&x| complex(along_polyline(&curve, x)))
            .collect();
        let targets = self.targets_complex();
        let (sim, _) = fit(&points, &targets)?;
        // Closest points once, from the spread along the curve; then sliding.
        self.nearest_in_order(&unit, (&curve, start, step), &sim, &mut index);
        for (z, x) in points.iter_mut().zip(&index) {
            *z = complex(
                unit.point_at(start + step * x)
                    .unwrap_or_else(|| along_polyline(&curve, *x)),
            );
        }
        let (sim, _) = fit(&points, &targets)?;
        let places = Places {
            unit: &unit,
            start,
            step,
            last: SAMPLES as f64,
        };
        let (sim, left) = places.slide(&targets, &mut index, sim, SLIDES)?;
        for (a, x) in angles.iter_mut().zip(&index) {
            *a = start + step * x;
        }
        Some(self.settle(&unit, &sim, left, gaps, angles))
    }

    /// Each target's first place on the sampled curve, as a fractional sample index:
    /// at its share of the curve's length, as it lies along the targets' polyline.
    fn spread_along(&self, curve: &[Vec2]) -> Vec<f64> {
        let mut run = Vec::with_capacity(curve.len());
        let mut total = 0.0;
        run.push(0.0);
        for w in curve.windows(2) {
            total += (w[1] - w[0]).norm();
            run.push(total);
        }
        let mut k = 0;
        self.along
            .iter()
            .map(|share| {
                let want = share * total;
                while k + 1 < run.len() - 1 && run[k + 1] < want {
                    k += 1;
                }
                let piece = run[k + 1] - run[k];
                let t = if piece > 0.0 {
                    ((want - run[k]) / piece).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                k as f64 + t
            })
            .collect()
    }

    /// Moves each target (mapped back by `sim` onto the unit curve) to its nearest
    /// point on the curve between its neighbours' places, so that the order holds:
    /// the nearest sample segment, refined on the curve itself. `index` holds
    /// fractional sample indices of `curve`, sampled at `start + step·index`.
    fn nearest_in_order(
        &self,
        unit: &CouplerFourBar,
        (curve, start, step): (&[Vec2], f64, f64),
        sim: &Similarity,
        index: &mut [f64],
    ) {
        let n = index.len();
        let last = curve.len() - 1;
        for i in 0..n {
            let q = sim.invert(self.targets[i]);
            let lo = if i == 0 { 0.0 } else { index[i - 1] };
            let hi = if i + 1 == n {
                last as f64
            } else {
                index[i + 1]
            };
            let (lo_k, hi_k) = (lo.floor() as usize, (hi.ceil() as usize).clamp(1, last));
            let mut best = (f64::INFINITY, index[i]);
            for k in lo_k.min(last - 1)..hi_k {
                let (d, t) = to_segment(q, curve[k], curve[k + 1]);
                if d < best.0 {
                    best = (d, (k as f64 + t).clamp(lo, hi));
                }
            }
            let dist2 = |x: f64| {
                unit.point_at(start + step * x)
                    .map_or(f64::INFINITY, |p| (p - q).norm_squared())
            };
            index[i] = parabola_min(dist2, best.1, 1.0, (lo, hi)).1;
        }
    }

    fn place_any_order(&self, v: &[f64], angles: &mut [f64]) -> Option<(f64, CouplerFourBar)> {
        let m = CouplerFourBar::from_params(&v[..PARAMS], v[PARAMS] >= 0.0);
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
            let (dist, theta) = nearest_on_curve(&m, *target, best.1, step);
            angles[i] = theta;
            sum += dist * dist;
        }
        let cost = (sum / self.targets.len() as f64).sqrt() + self.penalties(&m, angles);
        Some((cost, m))
    }
}

/// Where a search vector's number `pick` (0 to 2) puts a travel of `length` rad
/// inside the crank's closing arcs: its lower end. A turning crank's travel starts
/// anywhere (`pick` π); a rocking crank's lies inside its arc (of two, `pick`'s whole
/// part chooses), `pick`'s fraction sliding it from one end of the room to the other,
/// so that every vector's targets close where the arc is long enough (else the travel
/// is centred and its ends do not close). `None` where the loop closes nowhere.
fn arc_place(arcs: &[(f64, f64)], pick: f64, length: f64) -> Option<f64> {
    let &(start, len) = match arcs {
        [] => return None,
        [whole] if whole.1 >= TAU => return Some(pick * PI),
        [one] => one,
        [first, second, ..] => {
            if pick >= 1.0 {
                second
            } else {
                first
            }
        }
    };
    let frac = if arcs.len() == 1 {
        0.5 * pick
    } else {
        pick.fract()
    };
    let room = len - length;
    Some(if room >= 0.0 {
        start + frac.clamp(0.0, 1.0) * room
    } else {
        start + 0.5 * room
    })
}

/// The point a fractional sample index `x` names on the sampled curve.
fn along_polyline(curve: &[Vec2], x: f64) -> Vec2 {
    let k = (x.floor().max(0.0) as usize).min(curve.len() - 2);
    let t = (x - k as f64).clamp(0.0, 1.0);
    curve[k] + (curve[k + 1] - curve[k]) * t
}

/// The distance from `target` to the coupler curve near crank angle `theta`, and
/// where ([`parabola_min`] with a step of `step`). The chord between samples would
/// cut inside the curve by up to a thousandth of its size at 6° and the search would
/// chase that; this is the curve itself to about 1e-8.
pub fn nearest_on_curve(m: &CouplerFourBar, target: Vec2, theta: f64, step: f64) -> (f64, f64) {
    let dist2 = |t: f64| {
        m.point_at(t)
            .map_or(f64::INFINITY, |p| (p - target).norm_squared())
    };
    let (d2, at) = parabola_min(dist2, theta, step, (f64::NEG_INFINITY, f64::INFINITY));
    (d2.sqrt(), at)
}

/// Where near `x`, within `bounds`, `dist2` is least, and its value there: two rounds
/// of fitting a parabola through three values, half a `step` apart and then a
/// sixteenth of one.
fn parabola_min(dist2: impl Fn(f64) -> f64, x: f64, step: f64, bounds: (f64, f64)) -> (f64, f64) {
    let mut best = (dist2(x), x);
    for h in [0.5 * step, step / 16.0] {
        let centre = best.1;
        let (lo, mid, hi) = (dist2(centre - h), best.0, dist2(centre + h));
        let curvature = lo - 2.0 * mid + hi;
        if curvature.is_nan() || curvature <= 0.0 || !lo.is_finite() || !hi.is_finite() {
            continue;
        }
        let shift = (0.5 * h * (lo - hi) / curvature).clamp(-h, h);
        let at = (centre + shift).clamp(bounds.0, bounds.1);
        let d = dist2(at);
        if d < best.0 {
            best = (d, at);
        }
    }
    best
}
