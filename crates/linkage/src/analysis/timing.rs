//! The timing diagram of a machine: every output (each link pinned to ground, each
//! slider) against the main shaft's angle, as a share of its own stroke, with the
//! intervals where it rests. It is how a packaging machine's cams and linkages on one
//! shaft are laid out against each other: which motion starts when another ends.

use serde::Serialize;

use super::outputs::{Output, outputs};
use crate::error::Result;
use crate::solve::Kinematics;
use crate::sweep::{Sweep, sweep};

/// Share of an output's largest rate below which it counts as resting: a cam's dwell
/// rests exactly, a linkage's limit position only for an instant.
const REST_SHARE: f64 = 1e-6;

/// One output's lane.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TimingLane {
    /// The output's link.
    pub name: String,
    /// Whether its value is an angle (rad) rather than a travel (m).
    pub is_angle: bool,
    /// Its lowest and highest value over the cycle (rad or m).
    pub range: [f64; 2],
    /// At each shaft angle of the diagram, the value as a share of the stroke: 0 at
    /// the lowest, 1 at the highest (0 throughout for an output that does not move).
    pub share: Vec<f64>,
    /// Shaft-angle intervals where it rests (dwells), rad; each at least two samples.
    pub dwells: Vec<[f64; 2]>,
}

/// The timing diagram: the main shaft's angles and a lane per output.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct TimingDiagram {
    /// The main shaft's (the input's) angles, rad, over its turn or its range.
    pub shaft_rad: Vec<f64>,
    /// A lane per output, rockers then sliders.
    pub lanes: Vec<TimingLane>,
}

/// An output's lane from its values and rates at the shaft angles `shaft_rad`.
pub fn timing_lane(
    name: &str,
    is_angle: bool,
    shaft_rad: &[f64],
    values: &[f64],
    rates: &[f64],
) -> TimingLane {
    let finite = |v: &&f64| v.is_finite();
    let lo = values
        .iter()
        .filter(finite)
        .copied()
        .fold(f64::INFINITY, f64::min);
    let hi = values
        .iter()
        .filter(finite)
        .copied()
        .fold(f64::NEG_INFINITY, f64::max);
    let stroke = hi - lo;
    let share = values
        .iter()
        .map(|v| if stroke > 0.0 { (v - lo) / stroke } else { 0.0 })
        .collect();
    let peak = rates
        .iter()
        .filter(finite)
        .map(|r| r.abs())
        .fold(0.0, f64::max);
    let resting: Vec<bool> = rates.iter().map(|r| r.abs() <= REST_SHARE * peak).collect();
    TimingLane {
        name: name.to_string(),
        is_angle,
        range: if lo <= hi { [lo, hi] } else { [0.0, 0.0] },
        share,
        dwells: if peak > 0.0 {
            runs(&resting, shaft_rad)
        } else {
            Vec::new()
        },
    }
}

/// The intervals of at least two consecutive resting samples.
fn runs(resting: &[bool], shaft_rad: &[f64]) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, &rest) in resting.iter().chain([&false]).enumerate() {
        match (rest, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                if i - s >= 2 {
                    out.push([shaft_rad[s], shaft_rad[i - 1]]);
                }
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// The timing diagram of the scene of `k` at `samples` shaft angles over its sweep.
///
/// # Errors
/// The sweep's (a start that does not assemble, too few or too many samples).
pub fn timing(k: &mut Kinematics, samples: usize) -> Result<TimingDiagram> {
    let sw = sweep(k, samples)?;
    Ok(timing_of_sweep(k, &sw))
}

/// The timing diagram of a sweep `sw` of the scene of `k` (made once for the app's
/// curves and its timing tab alike).
pub fn timing_of_sweep(k: &Kinematics, sw: &Sweep) -> TimingDiagram {
    let shaft_rad: Vec<f64> = sw.solutions.iter().map(|s| s.input_rad).collect();
    let lanes = outputs(k)
        .iter()
        .map(|o| {
            // Rocker angles unwrapped along the sweep, so that a full turn is no jump.
            let values: Vec<f64> = match o {
                Output::Rocker { link, .. } => sw.angles.iter().map(|a| a[link.index()]).collect(),
                Output::Slide { .. } => sw.solutions.iter().map(|s| o.value(s)).collect(),
            };
            let rates: Vec<f64> = sw.solutions.iter().map(|s| o.rate(s)).collect();
            timing_lane(o.name(), o.is_angle(), &shaft_rad, &values, &rates)
        })
        .collect();
    TimingDiagram { shaft_rad, lanes }
}
