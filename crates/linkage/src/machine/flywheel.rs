//! Flywheel sizing by the energy method, as the courses teach it: the torque a crank
//! turning at its nominal speed needs over one cycle, its mean (what a motor gives),
//! the work surplus `W(φ) = ∫ (T_mean − T) dφ` of that constant torque against the
//! load, its range ΔW_max, and the flywheel inertia `J_F = ΔW_max / (ω² δ)` that keeps
//! the coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_mean.
//!
//! A crank may turn either way: the cycle runs from the scene's start angle one turn
//! in the crank's direction, and torques are counter-clockwise positive throughout.
//!
//! The cycle is integrated panel by panel with Gauss–Legendre: one-degree panels,
//! split where a working-stroke force switches on or off (the torque has a kink or a
//! step there), so that every panel is smooth and the integral exact to round-off.

use serde::Serialize;

use super::gauss;
use super::torque::{CrankLoad, CrankTorque, full_turn};
use crate::error::{LinkageError, MachineAnalysis, Result};
use crate::error::{Param, Valid};
use crate::extremum::{Extreme, locate_max};
use crate::model::Drive;
use crate::roots_util::refine;
use crate::solve::Kinematics;

const TAU: f64 = std::f64::consts::TAU;
/// Panels over the cycle before splitting at switching angles (one degree each).
const PANELS: usize = 360;
/// Gauss–Legendre points per panel: exact for the panel's polynomial of degree 7,
/// far below round-off on a one-degree panel of a smooth torque.
const POINTS: usize = 4;

/// The flywheel the energy method asks for, and the cycle it is sized on.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FlywheelSizing {
    /// Nominal (mean) crank speed, rad/s: the scene's driver speed.
    pub speed_rad_s: f64,
    /// Coefficient of speed fluctuation asked for.
    pub delta: f64,
    /// Mean driving torque over the cycle (the motor's, at the crank), N·m.
    pub mean_torque_n_m: f64,
    /// Mean power, W.
    pub mean_power_w: f64,
    /// The torque of largest magnitude the load asks for, N·m (located, not
    /// sampled: [`crate::extremum`]).
    pub peak_torque_n_m: f64,
    /// The crank angle where it is, rad.
    pub peak_torque_at_rad: f64,
    /// Range of the work surplus ΔW_max = W_max − W_min, J.
    pub work_range_j: f64,
    /// Crank angle of the largest surplus (the fastest point), rad.
    pub angle_of_max_rad: f64,
    /// The largest surplus since the start angle, J.
    pub surplus_max_j: f64,
    /// The smallest surplus since the start angle, J.
    pub surplus_min_j: f64,
    /// Crank angle of the smallest surplus (the slowest point), rad.
    pub angle_of_min_rad: f64,
    /// The flywheel inertia on the crank, J_F = ΔW_max / (ω² δ), kg·m².
    pub flywheel_kg_m2: f64,
    /// The scene's drive's rotor and train inertia reduced to the crank (not its
    /// flywheel), kg·m²: it turns with the crank and stores the surplus as a
    /// flywheel does; 0 without a drive.
    pub drive_inertia_kg_m2: f64,
    /// The flywheel still to fit on the crank, J_F less the drive's inertia (0 where
    /// the drive alone holds δ), kg·m².
    pub flywheel_to_add_kg_m2: f64,
    /// The same flywheel on the motor shaft, ÷ n² (n the drive's ratio), kg·m²;
    /// `None` without a drive.
    pub flywheel_to_add_on_motor_kg_m2: Option<f64>,
    /// The mechanism's own inertia reduced to the crank: smallest, mean, largest.
    pub reduced_inertia_kg_m2: InertiaRange,
    /// The cycle: crank angle, torque, surplus and reduced inertia at every panel end.
    pub cycle: Vec<CyclePoint>,
}

/// Smallest, mean and largest of the reduced inertia over the cycle, kg·m².
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct InertiaRange {
    /// Smallest.
    pub min: f64,
    /// Mean over the crank angle.
    pub mean: f64,
    /// Largest.
    pub max: f64,
}

/// One crank angle of the sized cycle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CyclePoint {
    /// Crank angle, rad (from the scene's start, one turn in the crank's direction).
    pub angle_rad: f64,
    /// The torque the load asks for at the nominal speed, N·m.
    pub torque_n_m: f64,
    /// Work surplus of the mean torque since the start, J.
    pub surplus_j: f64,
    /// The mechanism's reduced inertia, kg·m².
    pub reduced_inertia_kg_m2: f64,
}

/// One smooth piece of the cycle: its ends, its loads there and its torque integral.
struct Panel {
    a: f64,
    b: f64,
    start: CrankLoad,
    /// ∫ T dφ over the panel, J.
    torque_integral: f64,
    /// ∫ J dφ over the panel, kg·m²·rad.
    inertia_integral: f64,
    /// Smallest and largest J at its nodes and start.
    inertia_span: (f64, f64),
}

/// Sizes the flywheel of `k`'s mechanism for speed fluctuation `delta` at its scene's
/// crank speed.
///
/// # Errors
/// `delta` outside (0, 1), a crank at rest, an input that does not turn fully, or a
/// position that does not solve.
pub fn size_flywheel(k: &mut Kinematics, delta: f64) -> Result<FlywheelSizing> {
    check_inputs(k, delta)?;
    let start = k.mechanism().driver.start_rad;
    let mut crank = CrankTorque::new(k)?;
    let w = crank.speed_rad_s();
    let rule = gauss::rule(POINTS);
    // One turn in the direction the crank turns.
    let turn = TAU.copysign(w);
    let ends = panel_ends(&mut crank, start, turn)?;
    let panels = ends
        .windows(2)
        .map(|e| panel(&mut crank, &rule, e[0], e[1]))
        .collect::<Result<Vec<_>>>()?;
    let total: f64 = panels.iter().map(|p| p.torque_integral).sum();
    let mean_torque = total / turn;
    let (cycle, surplus_at_ends) = cycle_points(&panels, start + turn, mean_torque);
    let (max, min) = extremes(&mut crank, &rule, &panels, &surplus_at_ends, mean_torque)?;
    let work_range_j = max.1 - min.1;
    let peak = peak_torque(&mut crank, &cycle, turn);
    let inertia = InertiaRange {
        min: panels
            .iter()
            .map(|p| p.inertia_span.0)
            .fold(f64::INFINITY, f64::min),
        mean: panels.iter().map(|p| p.inertia_integral).sum::<f64>() / turn,
        max: panels.iter().map(|p| p.inertia_span.1).fold(0.0, f64::max),
    };
    let flywheel_kg_m2 = work_range_j / (w * w * delta);
    let drive = k.mechanism().drive.as_ref();
    let drive_inertia = drive.map_or(0.0, Drive::inertia_beside_flywheel_kg_m2);
    let to_add = (flywheel_kg_m2 - drive_inertia).max(0.0);
    Ok(FlywheelSizing {
        speed_rad_s: w,
        delta,
        mean_torque_n_m: mean_torque,
        mean_power_w: mean_torque * w,
        peak_torque_n_m: peak.value,
        peak_torque_at_rad: peak.angle_rad,
        work_range_j,
        angle_of_max_rad: max.0,
        surplus_max_j: max.1,
        surplus_min_j: min.1,
        angle_of_min_rad: min.0,
        flywheel_kg_m2,
        drive_inertia_kg_m2: drive_inertia,
        flywheel_to_add_kg_m2: to_add,
        flywheel_to_add_on_motor_kg_m2: drive.map(|d| to_add / (d.gear_ratio * d.gear_ratio)),
        reduced_inertia_kg_m2: inertia,
        cycle,
    })
}

/// δ in (0, 1), a crank turning (either way) over a full cycle.
fn check_inputs(k: &Kinematics, delta: f64) -> Result<()> {
    if !(delta.is_finite() && delta > 0.0 && delta < 1.0) {
        return Err(LinkageError::invalid(
            Param::Delta,
            delta,
            Valid::SpeedFluctuation,
        ));
    }
    let speed = k.mechanism().driver.speed_rad_s;
    if !(speed.is_finite() && speed != 0.0) {
        return Err(LinkageError::invalid(
            Param::DriverSpeed,
            speed,
            Valid::NominalSpeed,
        ));
    }
    full_turn(k, MachineAnalysis::Flywheel)
}

/// One-degree panel ends over the `turn` (±2π) from `start`, with the angles where a
/// working-stroke force switches added (found by root-finding on its power ratio).
fn panel_ends(crank: &mut CrankTorque<'_>, start: f64, turn: f64) -> Result<Vec<f64>> {
    let grid: Vec<f64> = (0..=PANELS)
        .map(|i| start + turn * i as f64 / PANELS as f64)
        .collect();
    let ratios = grid
        .iter()
        .map(|&x| crank.switching(x))
        .collect::<Result<Vec<_>>>()?;
    let mut ends = grid.clone();
    for force in 0..ratios.first().map_or(0, Vec::len) {
        for (i, pair) in ratios.windows(2).enumerate() {
            let (ra, rb) = (pair[0][force], pair[1][force]);
            if ra * rb < 0.0 {
                let (a, b) = (grid[i].min(grid[i + 1]), grid[i].max(grid[i + 1]));
                let root = refine(a, b, |x| crank.switching(x).map_or(f64::NAN, |r| r[force]));
                ends.extend(root);
            }
        }
    }
    // In the direction of turning.
    ends.sort_by(|a, b| (a * turn).total_cmp(&(b * turn)));
    // A switch that falls on a grid angle would leave a zero-width panel.
    ends.dedup_by(|b, a| (*b - *a).abs() <= 1e-12);
    Ok(ends)
}

/// The integrals of one smooth panel.
fn panel(crank: &mut CrankTorque<'_>, rule: &[(f64, f64)], a: f64, b: f64) -> Result<Panel> {
    let start = crank.at(a)?;
    let mut p = Panel {
        a,
        b,
        start,
        torque_integral: 0.0,
        inertia_integral: 0.0,
        inertia_span: (start.reduced_inertia_kg_m2, start.reduced_inertia_kg_m2),
    };
    for (x, wt) in gauss::on(rule, a, b) {
        let load = crank.at(x)?;
        p.torque_integral += wt * load.torque_n_m;
        p.inertia_integral += wt * load.reduced_inertia_kg_m2;
        let j = load.reduced_inertia_kg_m2;
        p.inertia_span = (p.inertia_span.0.min(j), p.inertia_span.1.max(j));
    }
    Ok(p)
}

/// The cycle at every panel start (and at `end`, the end of the turn), and the
/// surplus there.
fn cycle_points(panels: &[Panel], end: f64, mean_torque: f64) -> (Vec<CyclePoint>, Vec<f64>) {
    let mut surplus = 0.0;
    let mut points = Vec::with_capacity(panels.len() + 1);
    let mut at_ends = Vec::with_capacity(panels.len() + 1);
    for p in panels {
        points.push(CyclePoint {
            angle_rad: p.a,
            torque_n_m: p.start.torque_n_m,
            surplus_j: surplus,
            reduced_inertia_kg_m2: p.start.reduced_inertia_kg_m2,
        });
        at_ends.push(surplus);
        surplus += mean_torque * (p.b - p.a) - p.torque_integral;
    }
    // The surplus closes the cycle at zero (to round-off): the mean torque does the
    // load's work over one turn.
    if let Some(first) = points.first().copied() {
        points.push(CyclePoint {
            angle_rad: end,
            surplus_j: surplus,
            ..first
        });
        at_ends.push(surplus);
    }
    (points, at_ends)
}

/// The torque of largest magnitude over the turn, signed, and where: the panels'
/// starts bracket it, a golden-section search on the torque locates it.
fn peak_torque(crank: &mut CrankTorque<'_>, cycle: &[CyclePoint], turn: f64) -> Extreme {
    // Ascending angle whichever way the crank turns.
    let mut samples: Vec<[f64; 2]> = cycle
        .iter()
        .take(cycle.len().saturating_sub(1))
        .map(|c| [c.angle_rad, c.torque_n_m.abs()])
        .collect();
    samples.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let located = locate_max(&samples, Some(turn.abs()), |x| {
        crank.at(x).ok().map(|l| l.torque_n_m.abs())
    });
    let Some(at) = located else {
        return Extreme {
            angle_rad: 0.0,
            value: 0.0,
        };
    };
    // Its sign: the torque's own there.
    let signed = crank.at(at.angle_rad).map_or(at.value, |l| l.torque_n_m);
    Extreme {
        angle_rad: at.angle_rad,
        value: signed,
    }
}

/// The largest and smallest surplus (angle, J): at a root of T − T_mean inside a panel,
/// or at a panel end (where a switching load may step).
fn extremes(
    crank: &mut CrankTorque<'_>,
    rule: &[(f64, f64)],
    panels: &[Panel],
    surplus_at_ends: &[f64],
    mean_torque: f64,
) -> Result<((f64, f64), (f64, f64))> {
    let mut candidates: Vec<(f64, f64)> = panels
        .iter()
        .zip(surplus_at_ends)
        .map(|(p, &s)| (p.a, s))
        .collect();
    for (i, (p, &s0)) in panels.iter().zip(surplus_at_ends).enumerate() {
        // A panel ends where the next one starts, solved already; the last ends a
        // turn after the first begins.
        let at_b = match panels.get(i + 1) {
            Some(next) => next.start,
            None => crank.at(p.b)?,
        };
        let excess_a = p.start.torque_n_m - mean_torque;
        let excess_b = at_b.torque_n_m - mean_torque;
        if excess_a * excess_b >= 0.0 {
            continue;
        }
        let Some(root) = refine(p.a.min(p.b), p.a.max(p.b), |x| {
            crank.at(x).map_or(f64::NAN, |l| l.torque_n_m - mean_torque)
        }) else {
            continue;
        };
        let mut partial = 0.0;
        for (x, wt) in gauss::on(rule, p.a, root) {
            partial += wt * crank.at(x)?.torque_n_m;
        }
        candidates.push((root, s0 + mean_torque * (root - p.a) - partial));
    }
    let by_surplus = |a: &&(f64, f64), b: &&(f64, f64)| a.1.total_cmp(&b.1);
    let max = *candidates.iter().max_by(by_surplus).unwrap_or(&(0.0, 0.0));
    let min = *candidates.iter().min_by(by_surplus).unwrap_or(&(0.0, 0.0));
    Ok((max, min))
}
