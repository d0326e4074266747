//! Branch points of a closed-form chain: inputs inside the assembly range where a
//! dyad's two assembly modes meet, so that the chain may leave there in either (the
//! change points of a Grashof change-point four-bar: its links stretched straight, or
//! two of its joints coinciding). There the dyad's conditioning (|sin| of the angle
//! between its links) falls to zero without the chain coming apart, unlike at a
//! dead point, which ends the range.

use serde::Serialize;

use crate::assembly::AssemblyRanges;
use crate::dyad::GroupLabel;
use crate::solve::Kinematics;

/// Conditioning below which a grid minimum is refined.
const CANDIDATE: f64 = 0.05;
/// Refined conditioning below which the minimum is a branch point.
const BRANCH: f64 = 1e-6;

/// An input where two assembly modes of one group meet.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BranchPoint {
    /// Input angle, rad (in [0, 2π)).
    pub input_rad: f64,
    /// The group whose modes meet, as [`Kinematics::group_name`] names it.
    pub group: GroupLabel,
    /// Pairs of joints that coincide there (empty when the links are stretched or
    /// folded straight instead).
    pub coincident_joints: Vec<[String; 2]>,
}

/// Branch points inside `ranges` (closed-form chains; none otherwise): local minima
/// of each group's conditioning on a coarse grid, refined by golden-section
/// search, kept where the conditioning reaches zero.
pub fn branch_points(k: &mut Kinematics, ranges: &AssemblyRanges) -> Vec<BranchPoint> {
    let groups = k.group_count();
    let start = k.mechanism().driver.start_rad;
    let mut found = Vec::new();
    for grid in ranges.grids(start) {
        // Every 4th point of the analyses' grid (2 deg on a full turn): the
        // conditioning is V-shaped at a branch point, so a minimum still shows, and the
        // report, drawn on the frame of an edit, pays a quarter of a sweep for it.
        let xs: Vec<f64> = grid.into_iter().step_by(4).collect();
        let values: Vec<Vec<f64>> = xs.iter().map(|&x| k.group_conditioning_values(x)).collect();
        for g in 0..groups {
            let series: Vec<f64> = values.iter().map(|v| v[g]).collect();
            for (i, w) in series.windows(3).enumerate() {
                let [before, here, after] = [w[0], w[1], w[2]];
                if here < CANDIDATE && here <= before && here < after {
                    let x = golden_minimum(xs[i], xs[i + 2], |x| k.group_conditioning_values(x)[g]);
                    if k.group_conditioning_values(x)[g] < BRANCH {
                        found.push(BranchPoint {
                            input_rad: x.rem_euclid(std::f64::consts::TAU),
                            group: k.group_name(g),
                            coincident_joints: coincident(k, x),
                        });
                    }
                }
            }
        }
    }
    found
}

/// Minimum of a unimodal `f` on [a, b] to round-off (golden-section search: the
/// conditioning is V-shaped at a branch point, so no derivative to find roots of).
fn golden_minimum(a: f64, b: f64, mut f: impl FnMut(f64) -> f64) -> f64 {
    crate::extremum::golden_max(|x| Some(-f(x)), a, b).map_or(0.5 * (a + b), |e| e.angle_rad)
}

/// Named joints that coincide (within 1e-6 of the mechanism's size) just beside `x`
/// (exactly there the solve is singular).
fn coincident(k: &mut Kinematics, x: f64) -> Vec<[String; 2]> {
    let size = k.mechanism().size_m;
    let Ok(s) = k.solve(x + 1e-9) else {
        return Vec::new();
    };
    let m = k.mechanism();
    let mut pairs = Vec::new();
    for (i, p) in s.points.iter().enumerate() {
        for (j, q) in s.points.iter().enumerate().skip(i + 1) {
            if (p.position - q.position).norm() < 1e-6 * size {
                pairs.push([m.points[i].name.clone(), m.points[j].name.clone()]);
            }
        }
    }
    pairs
}
