//! Assembly ranges, and the input interval a sweep covers.

use crate::assembly::AssemblyRanges;
use crate::error::{AssemblyFailure, LinkageError, Result};
use crate::solve::Kinematics;

/// Assembly ranges: of a closed-form chain by root-finding on the groups' margins; of
/// a chain solved by Newton alone, the range its branch was traced over (between
/// folds) when it was built.
pub fn assembly_ranges_of(k: &Kinematics) -> AssemblyRanges {
    k.assembly_ranges()
}

/// The input interval a sweep covers: a full turn from the start angle, or the
/// assembly interval that holds the start angle (ends pulled in by a hair, since
/// the ends are dead points).
pub fn sweep_range(k: &Kinematics) -> Result<([f64; 2], bool)> {
    let start = k.mechanism().driver.start_rad;
    let ranges = assembly_ranges_of(k);
    if ranges.full_rotation {
        return Ok(([start, start + std::f64::consts::TAU], true));
    }
    let [a, b] = ranges
        .containing(start)
        .ok_or_else(|| LinkageError::CannotAssemble {
            input_deg: start.to_degrees(),
            reason: AssemblyFailure::Nowhere,
            reachable: ranges.clone(),
        })?;
    // Velocities grow as 1/√(distance to the dead point) and accelerations as its
    // -3/2 power: a hair of 1e-6 of the range keeps the round-off in the range's ends
    // (an ulp of the input) below 1e-9 of the end rows' values.
    let hair = 1e-6 * (b - a);
    Ok(([a + hair, b - hair], false))
}
