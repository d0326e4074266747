//! Each output's largest speed and acceleration over the cycle, located ([`crate::
//! extremum`]): bracketed on a sweep and found between its rows by a golden-section
//! search on the solved rates. Where the input's range ends at dead points, the
//! output's rates grow without bound towards them: the peaks are then that, with the
//! dead points' angles, never a number read off the rows next to them.

use serde::Serialize;

use super::outputs::{Output, outputs};
use crate::error::Result;
use crate::extremum::{Extreme, locate_max};
use crate::ranges::{assembly_ranges_of, sweep_range};
use crate::solve::Kinematics;

/// Rows the peaks are bracketed on.
const ROWS: usize = 360;

/// An output's largest rate or acceleration over the cycle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Peak {
    /// Located: the signed value and its input angle.
    At(Extreme),
    /// Unbounded: the input's range ends at dead points (rad), where the output's
    /// rates have no bound.
    Unbounded {
        /// The dead points: the ends of the input's range, rad.
        dead_points_rad: [f64; 2],
    },
}

/// One output's peaks.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct OutputPeaks {
    /// The output's name (a rocker's or a slider's link).
    pub output: String,
    /// Whether it is an angle (rad/s, rad/s²) rather than a travel (m/s, m/s²).
    pub is_angle: bool,
    /// Its largest speed (signed), at the scene's input speed.
    pub speed: Peak,
    /// Its largest acceleration (signed).
    pub acceleration: Peak,
}

/// Every output's peaks at the scene's input speed.
///
/// # Errors
/// A chain that does not assemble at its start, or a solve that fails inside the
/// range.
pub fn output_peaks(k: &mut Kinematics) -> Result<Vec<OutputPeaks>> {
    let outs = outputs(k);
    let ranges = assembly_ranges_of(k);
    let (range, full) = sweep_range(k)?;
    if !full {
        // The unhaired ends: the dead points themselves.
        let ends = ranges
            .containing(k.mechanism().driver.start_rad)
            .unwrap_or(range);
        let unbounded = Peak::Unbounded {
            dead_points_rad: ends,
        };
        return Ok(outs
            .iter()
            .map(|o| OutputPeaks {
                output: o.name().to_owned(),
                is_angle: o.is_angle(),
                speed: unbounded,
                acceleration: unbounded,
            })
            .collect());
    }
    let rows = crate::sweep::sweep(k, ROWS)?;
    let mut peaks = Vec::with_capacity(outs.len());
    for o in &outs {
        let speed = locate(k, o, &rows.solutions, Output::rate)?;
        let acceleration = locate(k, o, &rows.solutions, Output::acceleration)?;
        peaks.push(OutputPeaks {
            output: o.name().to_owned(),
            is_angle: o.is_angle(),
            speed: Peak::At(speed),
            acceleration: Peak::At(acceleration),
        });
    }
    Ok(peaks)
}

/// The largest |`quantity`| of `o` over a turn, signed, and where.
fn locate(
    k: &mut Kinematics,
    o: &Output,
    rows: &[crate::motion::Solution],
    quantity: fn(&Output, &crate::motion::Solution) -> f64,
) -> Result<Extreme> {
    let samples: Vec<[f64; 2]> = rows
        .iter()
        .map(|s| [s.input_rad, quantity(o, s).abs()])
        .collect();
    let mut at = |x: f64| k.solve(x).ok().map(|s| quantity(o, &s));
    let found = locate_max(&samples, Some(std::f64::consts::TAU), |x| {
        at(x).map(f64::abs)
    })
    .unwrap_or(Extreme {
        angle_rad: 0.0,
        value: 0.0,
    });
    Ok(Extreme {
        angle_rad: found.angle_rad,
        value: at(found.angle_rad).unwrap_or(found.value),
    })
}
