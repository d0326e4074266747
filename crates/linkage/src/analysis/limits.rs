//! Limit positions of every output, found by Brent root-finding on its velocity ratio
//! (bracketed on a grid), and the range each output sweeps.

use serde::Serialize;

use super::outputs::Output;
use super::{RESTING_RATE, TAU};
use crate::assembly::AssemblyRanges;
use crate::motion::Solution;
use crate::roots_util::{refine, sign_changes};
use crate::solve::Kinematics;

/// Which extreme of an output a limit position is (`"max"` or `"min"` in JSON).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Extreme {
    /// The output's largest value.
    Max,
    /// The output's smallest value.
    Min,
}

impl std::fmt::Display for Extreme {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Extreme::Max => "max",
            Extreme::Min => "min",
        })
    }
}

/// An extreme of one output.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LimitPosition {
    /// Input angle, rad.
    pub input_rad: f64,
    /// Output name.
    pub output: String,
    /// Whether the output is largest or smallest there.
    pub kind: Extreme,
    /// Output value there (rad or m).
    pub value: f64,
}

/// Evaluates solutions at unit input speed (rates are velocity ratios).
struct Probe<'a> {
    k: &'a mut Kinematics,
    sol: Solution,
}

impl Probe<'_> {
    fn at(&mut self, x: f64) -> Option<&Solution> {
        self.k
            .solve_into(x, 1.0, &mut self.sol)
            .ok()
            .map(|_| &self.sol)
    }
}

/// Limit positions of `out` over the assembly ranges, by root-finding on its rate.
pub fn limit_positions(
    k: &mut Kinematics,
    out: &Output,
    ranges: &AssemblyRanges,
) -> Vec<LimitPosition> {
    found_limits(k, out, ranges)
        .into_iter()
        .map(|f| f.limit)
        .collect()
}

/// A limit position and whether its rate vanishes to a higher order there (see
/// [`flat`]).
pub(super) struct FoundLimit {
    pub(super) limit: LimitPosition,
    flat: bool,
}

pub(super) fn found_limits(
    k: &mut Kinematics,
    out: &Output,
    ranges: &AssemblyRanges,
) -> Vec<FoundLimit> {
    let start = k.mechanism().driver.start_rad;
    let size = k.mechanism().size_m;
    let mut probe = Probe {
        sol: k.empty_solution(),
        k,
    };
    let ratio =
        |probe: &mut Probe, x: f64| probe.at(x).map_or(f64::NAN, |s| out.relative_rate(s, size));
    let mut found = Vec::new();
    for xs in ranges.grids(start) {
        let rates: Vec<f64> = xs.iter().map(|&x| ratio(&mut probe, x)).collect();
        for i in sign_changes(&rates) {
            // An output at rest (a change-point chain's folded mode holds its rocker
            // still) changes the sign of round-off only: no limit there.
            if rates[i].abs().max(rates[i + 1].abs()) < RESTING_RATE {
                continue;
            }
            let Some(root) = refine(xs[i], xs[i + 1], |x| ratio(&mut probe, x)) else {
                continue;
            };
            let flat = flat(&mut |x| ratio(&mut probe, x), root);
            let Some(s) = probe.at(root) else { continue };
            found.push(FoundLimit {
                limit: LimitPosition {
                    input_rad: root.rem_euclid(TAU),
                    output: out.name().to_string(),
                    kind: if rates[i] > 0.0 {
                        Extreme::Max
                    } else {
                        Extreme::Min
                    },
                    value: out.value(s),
                },
                flat,
            });
        }
    }
    found
}

/// Whether `rate` vanishes at `root` to a higher (third or odd higher) order: then
/// round-off hides the root within about (1e-16)^(1/3) ≈ 5e-6 rad of where it is, and
/// a root found there is only that good. A simple root's rate grows tenfold from 1e-3
/// to 1e-2 rad away, a triple root's a thousandfold.
fn flat(rate: &mut dyn FnMut(f64) -> f64, root: f64) -> bool {
    let growth = |h: f64, rate: &mut dyn FnMut(f64) -> f64| {
        (rate(root + 10.0 * h) * rate(root - 10.0 * h) / (rate(root + h) * rate(root - h)))
            .abs()
            .sqrt()
    };
    let g = growth(1e-3, rate);
    // Between 10 (order 1) and 1000 (order 3).
    g.is_finite() && g > 100.0
}

/// How far from a flat root (see [`flat`]) a simple root of another output may lie
/// and still be taken for the same, rad: several times the round-off band of a triple
/// root, far below the grid step that separates distinct roots.
const SAME_ROOT: f64 = 1e-4;

/// Moves each flat limit onto a simple limit of another output found within
/// [`SAME_ROOT`], where there is one, and takes the output's value there. A flat
/// limit is where an output's rate is the product of two rates that vanish together
/// (the die cutter's die at its toggle: the die's rate through the rocker's, the
/// rocker at its own limit): the simple root of the other output is the same place,
/// known to round-off instead of to 5e-6 rad.
pub(super) fn align_flat_limits(
    k: &mut Kinematics,
    outs: &[Output],
    found: &mut [Vec<FoundLimit>],
) {
    let simple: Vec<(usize, f64)> = found
        .iter()
        .enumerate()
        .flat_map(|(o, limits)| {
            limits
                .iter()
                .filter(|f| !f.flat)
                .map(move |f| (o, f.limit.input_rad))
        })
        .collect();
    let mut sol = k.empty_solution();
    for (o, limits) in found.iter_mut().enumerate() {
        for f in limits.iter_mut().filter(|f| f.flat) {
            let near = simple
                .iter()
                .filter(|&&(other, _)| other != o)
                .map(|&(_, x)| (x, angle_between(x, f.limit.input_rad)))
                .filter(|&(_, d)| d <= SAME_ROOT)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            if let Some((x, _)) = near
                && k.solve_into(x, 1.0, &mut sol).is_ok()
            {
                f.limit.input_rad = x;
                f.limit.value = outs[o].value(&sol);
            }
        }
    }
}

/// The angle between two angles, rad, in [0, π].
fn angle_between(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

/// Range swept by an output: the span between its extremes, including the ends of
/// limited input ranges; a rocker that turns fully sweeps 2π.
pub(super) fn span(
    k: &mut Kinematics,
    out: &Output,
    limits: &[LimitPosition],
    ranges: &AssemblyRanges,
) -> f64 {
    let mut values: Vec<f64> = limits.iter().map(|l| l.value).collect();
    if !ranges.full_rotation {
        for [a, b] in &ranges.intervals {
            values.extend(dead_point_value(k, out, *a, 1.0, b - a));
            values.extend(dead_point_value(k, out, *b, -1.0, b - a));
        }
    }
    if values.is_empty() {
        return if out.is_angle() { TAU } else { 0.0 };
    }
    if out.is_angle() {
        // Angles: the smallest arc that holds every extreme.
        let base = values[0];
        let rel: Vec<f64> = values
            .iter()
            .map(|v| (v - base + std::f64::consts::PI).rem_euclid(TAU))
            .collect();
        let hi = rel.iter().cloned().fold(f64::MIN, f64::max);
        let lo = rel.iter().cloned().fold(f64::MAX, f64::min);
        hi - lo
    } else {
        let hi = values.iter().cloned().fold(f64::MIN, f64::max);
        let lo = values.iter().cloned().fold(f64::MAX, f64::min);
        hi - lo
    }
}

/// The value of `out` at the dead point `end` of an input range of length `width`
/// (`inward` is +1 at the start of the range, -1 at its end).
///
/// Exactly at the dead point the solve is singular, and a hair inside it the output
/// is still off by c·√hair (the branch turns back there: v − v* ∝ √|x − x*|), which
/// is 1e-5 for a hair of 1e-9. So the dead point is found from two probes as the root
/// of 1/rate², which is linear in x there, and the value is extrapolated to it along
/// the square root. Where the rate does not follow that law (an output whose rate
/// stays finite at the dead point), the nearer probe's value is taken.
fn dead_point_value(
    k: &mut Kinematics,
    out: &Output,
    end: f64,
    inward: f64,
    width: f64,
) -> Option<f64> {
    let (d1, d2) = (1e-9 * width, 4e-9 * width);
    let mut sol = k.empty_solution();
    k.solve_into(end + inward * d1, 1.0, &mut sol).ok()?;
    let (v1, r1) = (out.value(&sol), out.rate(&sol));
    let Ok(()) = k.solve_into(end + inward * d2, 1.0, &mut sol) else {
        return Some(v1);
    };
    let (g1, g2) = (r1.powi(-2), out.rate(&sol).powi(-2));
    // Distance from the nearer probe back to the root of the line through (d, 1/rate²).
    let dist = g1 * (d2 - d1) / (g2 - g1);
    if !(dist.is_finite() && dist > 0.0 && dist < 2.0 * d1) {
        return Some(v1);
    }
    Some(v1 - 2.0 * dist * r1 * inward)
}
