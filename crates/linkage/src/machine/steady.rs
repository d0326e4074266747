//! The real speed through the cycle: the periodic steady state of
//! `J(φ) φ'' + ½ J'(φ) φ'² = M_drive(φ') + M(φ, φ')` with the scene's drive, found by
//! shooting: a Newton iteration on the crank speed at the start angle, each try one
//! turn of the dynamics' own integrator (DOP853 at rtol 1e-12) ended by an event at
//! the start angle, where the speed must come back to what it started at.
//!
//! A motor whose torque falls with speed has one such state. A constant torque has a
//! periodic state only when it equals the load's mean torque, and then one for every
//! speed level: the steady state is taken at that torque (the energy method's mean at
//! the nominal speed) with its mean speed the scene's nominal speed.

use serde::Serialize;

use super::flywheel::size_flywheel;
use super::torque::full_turn;
use crate::dynamics::{Method, Sample, Settings, Simulation, simulate};
use crate::error::{LinkageError, MachineAnalysis, Result};
use crate::error::{Param, Valid};
use crate::model::{Mechanism, Motor};
use crate::scene::{StopAction, StopSpec};
use crate::solve::Kinematics;

const TAU: f64 = std::f64::consts::TAU;
/// Relative tolerance of one turn's integration.
const RTOL: f64 = 1e-12;
/// Shooting ends when the speed after a turn is back to this share of the speed.
const CLOSURE: f64 = 1e-11;
/// Most shooting iterations.
const MOST_ITERATIONS: usize = 30;
/// Samples over the periodic cycle.
const CYCLE_SAMPLES: usize = 720;

/// The periodic motion of the crank with its drive.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SteadyState {
    /// Crank speed at the scene's start angle, rad/s.
    pub start_speed_rad_s: f64,
    /// Largest crank speed over the cycle, rad/s.
    pub max_rad_s: f64,
    /// Smallest, rad/s.
    pub min_rad_s: f64,
    /// Mean speed, one turn over the period, rad/s.
    pub mean_rad_s: f64,
    /// The coefficient of speed fluctuation achieved, (max − min) / mean.
    pub delta: f64,
    /// One turn's time, s.
    pub period_s: f64,
    /// The constant torque used at the crank, when the motor gives one (the load's
    /// mean torque), N·m.
    pub constant_torque_n_m: Option<f64>,
    /// Work of the non-conservative forces (motor and loads) over the turn, J: zero
    /// when the state is periodic, the kinetic and potential energy coming back.
    pub work_over_turn_j: f64,
    /// The drive's work over the turn, J (what the load takes).
    pub drive_work_j: f64,
    /// Shooting iterations.
    pub iterations: usize,
    /// The cycle: time, crank angle and speed.
    pub cycle: Vec<SpeedPoint>,
}

/// One instant of the periodic cycle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SpeedPoint {
    /// Time since the start angle, s.
    pub t_s: f64,
    /// Crank angle, rad.
    pub angle_rad: f64,
    /// Crank speed, rad/s.
    pub speed_rad_s: f64,
}

/// What shooting adjusts: the speed after a turn equal to the speed before, or, for a
/// constant torque, the mean speed equal to the nominal speed.
#[derive(Clone, Copy)]
enum Aim {
    Periodic,
    MeanSpeed(f64),
}

/// The periodic steady state of `k`'s mechanism driven by its scene's drive.
///
/// # Errors
/// No drive in the scene, an input that does not turn fully, a run that does not
/// complete a turn (the motor stalls), or shooting that does not close.
pub fn steady_state(k: &Kinematics) -> Result<SteadyState> {
    let (m, aim, constant) = prepared(k)?;
    let kin = Kinematics::new(m)?;
    let nominal = k.mechanism().driver.speed_rad_s;
    let mut w0 = nominal;
    let mut iterations = 0;
    let end = loop {
        iterations += 1;
        let (miss, end) = shot(&kin, w0, aim)?;
        if miss.abs() <= CLOSURE * nominal.abs() || iterations >= MOST_ITERATIONS {
            if miss.abs() > 1e-6 * nominal.abs() {
                return Err(no_closure(miss, nominal));
            }
            break end;
        }
        let h = 1e-6 * w0;
        let (miss_h, _) = shot(&kin, w0 + h, aim)?;
        let slope = (miss_h - miss) / h;
        if !(slope.is_finite() && slope != 0.0) {
            return Err(no_closure(miss, nominal));
        }
        w0 -= miss / slope;
    };
    finish(&kin, w0, &end, constant, iterations)
}

/// The mechanism with one stop at the start angle (the end of a turn) and none of
/// its own, and what to aim at.
fn prepared(k: &Kinematics) -> Result<(Mechanism, Aim, Option<f64>)> {
    let mut m = k.mechanism().clone();
    let Some(drive) = m.drive.as_mut() else {
        return Err(LinkageError::NeedsMotor);
    };
    full_turn(k, MachineAnalysis::SteadyState)?;
    let (aim, constant) = match drive.motor {
        Motor::Constant(_) => {
            let mean = size_flywheel(&mut k.clone(), 0.5)?.mean_torque_n_m;
            drive.motor = Motor::Constant(mean / drive.gear_ratio);
            (Aim::MeanSpeed(m.driver.speed_rad_s), Some(mean))
        }
        _ => (Aim::Periodic, None),
    };
    m.forces.stops = vec![StopSpec {
        name: "one turn".into(),
        link: m.links[m.driver.link].name.clone(),
        angle: m.driver.start_rad,
        action: StopAction::Stop,
    }];
    Ok((m, aim, constant))
}

/// One turn from speed `w0`: how far it misses the aim, and where the turn ended.
fn shot(k: &Kinematics, w0: f64, aim: Aim) -> Result<(f64, Sample)> {
    let end = turn_end(&one_turn(k, w0, None)?, w0)?;
    let miss = match aim {
        Aim::Periodic => end.q_dot - w0,
        Aim::MeanSpeed(w) => TAU.copysign(w) / end.t - w,
    };
    Ok((miss, end))
}

/// The dynamics over one turn from the start angle at speed `w0`.
fn one_turn(k: &Kinematics, w0: f64, output_dt: Option<f64>) -> Result<Simulation> {
    let mut s = Settings::new(Method::Dop853);
    s.rtol = RTOL;
    // The state is (angle rad, speed rad/s): an absolute tolerance of RTOL rad on the
    // angle, less when the crank is slow so that the speed keeps RTOL relative too.
    s.atol = RTOL * w0.abs().min(1.0);
    s.q_dot0 = w0;
    s.t_end = 4.0 * TAU / w0.abs();
    s.switch_coordinates = false;
    s.output_dt = output_dt;
    simulate(k, &s)
}

/// The state where the turn ended, or why it did not.
fn turn_end(run: &Simulation, w0: f64) -> Result<Sample> {
    match run.events.iter().find(|e| e.stopped) {
        Some(e) => Ok(e.state),
        None => Err(LinkageError::invalid(
            Param::CrankSpeedAtStart,
            w0,
            Valid::MotorDrives,
        )),
    }
}

fn no_closure(miss: f64, nominal: f64) -> LinkageError {
    LinkageError::invalid(
        Param::SteadyMiss,
        miss,
        Valid::ShootingCloses {
            closure: CLOSURE,
            nominal_rad_s: nominal,
        },
    )
}

/// The converged state from `w0`, whose turn ended at `end`: that turn once more,
/// sampled on a fine grid.
fn finish(
    k: &Kinematics,
    w0: f64,
    end: &Sample,
    constant: Option<f64>,
    iterations: usize,
) -> Result<SteadyState> {
    let run = one_turn(k, w0, Some(end.t / CYCLE_SAMPLES as f64))?;
    let mut cycle: Vec<SpeedPoint> = run
        .samples
        .iter()
        .filter(|s| s.t < end.t)
        .map(|s| SpeedPoint {
            t_s: s.t,
            angle_rad: s.q,
            speed_rad_s: s.q_dot,
        })
        .collect();
    cycle.push(SpeedPoint {
        t_s: end.t,
        angle_rad: end.q,
        speed_rad_s: end.q_dot,
    });
    let speeds = cycle.iter().map(|c| c.speed_rad_s);
    let max = speeds.clone().fold(f64::NEG_INFINITY, f64::max);
    let min = speeds.fold(f64::INFINITY, f64::min);
    let mean = TAU.copysign(w0) / end.t;
    let drive_work_j = drive_work(k, &run, end)?;
    Ok(SteadyState {
        start_speed_rad_s: w0,
        max_rad_s: max,
        min_rad_s: min,
        mean_rad_s: mean,
        delta: (max - min) / mean.abs(),
        period_s: end.t,
        constant_torque_n_m: constant,
        work_over_turn_j: end.work_nonconservative - run.samples[0].work_nonconservative,
        drive_work_j,
        iterations,
        cycle,
    })
}

/// The drive's work over the turn, ∫ M_drive(ω) dφ, by the trapezoid rule on the
/// sampled cycle (a figure for the reader; the balance above is exact).
fn drive_work(k: &Kinematics, run: &Simulation, end: &Sample) -> Result<f64> {
    let Some(drive) = &k.mechanism().drive else {
        return Ok(0.0);
    };
    let points: Vec<(f64, f64)> = run
        .samples
        .iter()
        .filter(|s| s.t < end.t)
        .chain(std::iter::once(end))
        .map(|s| (s.q, drive.torque_at_crank(s.q_dot)))
        .collect();
    Ok(points
        .windows(2)
        .map(|p| 0.5 * (p[0].1 + p[1].1) * (p[1].0 - p[0].0))
        .sum())
}
