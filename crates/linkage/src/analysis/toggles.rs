//! Toggles: positions where an output/input velocity ratio is zero or infinite, and
//! near-singular positions met in a sweep.

use serde::Serialize;

use super::TAU;
use super::limits::LimitPosition;
use super::transmission::{CollinearJoint, collinear_joints};
use crate::assembly::AssemblyRanges;
use crate::solve::Kinematics;

/// A position where an output/input velocity ratio is zero or infinite.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Toggle {
    /// Input angle, rad.
    pub input_rad: f64,
    /// Which ratio: zero (a limit of `output`) or infinite (a dead point of the input).
    pub ratio: ToggleRatio,
    /// The output, or the group that locks.
    pub output: String,
    /// Revolute joints whose two links are collinear there (within 0.1 deg).
    pub collinear_joints: Vec<CollinearJoint>,
}

/// The output/input velocity ratio at a toggle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ToggleRatio {
    /// The output at rest: a limit position of it.
    Zero,
    /// The input at a dead point.
    Infinite,
}

impl std::fmt::Display for ToggleRatio {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Zero => "zero",
            Self::Infinite => "infinite",
        })
    }
}

/// A near-singular position met during a sweep.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Tangency {
    /// Input angle, rad.
    pub input_rad: f64,
    /// Conditioning there.
    pub conditioning: f64,
}

/// The toggles: every limit position of an output (its rate zero), and the ends of
/// a range that does not turn fully (the input's rate infinite there).
pub(super) fn toggles(
    k: &mut Kinematics,
    limits: &[LimitPosition],
    working: &AssemblyRanges,
) -> Vec<Toggle> {
    let mut toggles = Vec::new();
    let mut sol = k.empty_solution();
    for lp in limits {
        if k.solve_into(lp.input_rad, 1.0, &mut sol).is_ok() {
            toggles.push(Toggle {
                input_rad: lp.input_rad,
                ratio: ToggleRatio::Zero,
                output: lp.output.clone(),
                collinear_joints: collinear_joints(k, &sol, 0.1_f64.to_radians()),
            });
        }
    }
    if working.full_rotation {
        return toggles;
    }
    for [a, b] in &working.intervals {
        // A hair inside the range: exactly at the dead point velocities are undefined.
        let hair = 1e-9 * (b - a);
        for x in [*a + hair, *b - hair] {
            let group = k
                .group_conditioning(x)
                .into_iter()
                .min_by(|p, q| p.1.total_cmp(&q.1))
                .map_or_else(|| "chain".to_string(), |(n, _)| n);
            let collinear = if k.solve_into(x, 1.0, &mut sol).is_ok() {
                collinear_joints(k, &sol, 0.1_f64.to_radians())
            } else {
                Vec::new()
            };
            toggles.push(Toggle {
                input_rad: x.rem_euclid(TAU),
                ratio: ToggleRatio::Infinite,
                output: group,
                collinear_joints: collinear,
            });
        }
    }
    toggles
}
