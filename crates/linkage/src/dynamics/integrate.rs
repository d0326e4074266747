//! Time integration of the reduced equation J q̈ + ½ J' q̇² = M, with end-stop events.
//!
//! Methods: the flipper paper's own energy-increment method (steps in q, so a
//! student can see its error), semi-implicit (symplectic) Euler and classical RK4,
//! all fixed-step. Events are located inside a step on the cubic Hermite interpolant
//! of q(t) (dense output) by Brent root-finding.

use std::time::Instant;

use serde::Serialize;

use super::forces::{EnergyTerms, ForceModel, Reduced, unit_solution};
use crate::error::{LinkageError, Result};
use crate::kinematics::Kinematics;
use crate::motion::Solution;
use crate::roots_util::refine;
use crate::scene::StopAction;

/// Integration method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Method {
    /// The paper's energy increments: ½J₁w₁² = ½J₀w₀² + M₀Δφ, dt = 2Δφ/(w₀ + w₁); first order.
    EnergyIncrement,
    /// Semi-implicit (symplectic) Euler; first order, bounded energy error.
    SemiImplicitEuler,
    /// Classical fourth-order Runge–Kutta.
    Rk4,
}

/// One state of the run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Sample {
    /// Time, s.
    pub t: f64,
    /// Input coordinate, rad.
    pub q: f64,
    /// Its rate, rad/s.
    pub q_dot: f64,
    /// Its second derivative, rad/s².
    pub q_ddot: f64,
    /// Kinetic energy, J.
    pub kinetic: f64,
    /// Gravity + spring + constant-force potential, J.
    pub potential: f64,
    /// Work done so far by dampers, torques and stroke forces (non-conservative), J.
    pub work_nonconservative: f64,
}

impl Sample {
    /// Kinetic + potential − non-conservative work: constant for an exact solution.
    pub fn energy_balance(&self) -> f64 {
        self.kinetic + self.potential - self.work_nonconservative
    }
}

/// An end stop or other event, located inside its step.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SimEvent {
    /// Event name (the scene's stop name).
    pub name: String,
    /// State at the event.
    pub state: Sample,
    /// Whether the motion stopped there.
    pub stopped: bool,
}

/// Cost of a run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct RunStats {
    /// Steps taken.
    pub steps: usize,
    /// Evaluations of the reduced model (each one kinematic solve).
    pub rhs_evaluations: usize,
    /// CPU (wall) seconds of the integration.
    pub cpu_seconds: f64,
}

/// A finished run: one sample per step, the events and the cost.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Simulation {
    /// Method used.
    pub method: Method,
    /// Samples at every step (the energy method's steps are uneven in time).
    pub samples: Vec<Sample>,
    /// Events in time order.
    pub events: Vec<SimEvent>,
    /// Cost.
    pub stats: RunStats,
}

impl Simulation {
    /// Samples on a uniform time grid, by cubic Hermite interpolation between steps.
    pub fn resample(&self, dt: f64) -> Vec<Sample> {
        let (Some(first), Some(last)) = (self.samples.first(), self.samples.last()) else {
            return Vec::new();
        };
        if dt.is_nan() || dt <= 0.0 {
            return self.samples.clone();
        }
        let n = ((last.t - first.t) / dt).floor() as usize;
        let mut out = Vec::with_capacity(n + 2);
        let mut k = 0;
        for i in 0..=n {
            let t = first.t + dt * i as f64;
            while k + 2 < self.samples.len() && self.samples[k + 1].t < t {
                k += 1;
            }
            let (a, b) = (
                &self.samples[k],
                &self.samples[(k + 1).min(self.samples.len() - 1)],
            );
            out.push(interpolate(a, b, t));
        }
        if out.last().is_some_and(|s| s.t < last.t) {
            out.push(*last);
        }
        out
    }
}

/// Cubic Hermite interpolation of q (and its derivative for q̇) between two samples;
/// energies linearly.
fn interpolate(a: &Sample, b: &Sample, t: f64) -> Sample {
    let h = b.t - a.t;
    if h <= 0.0 {
        return *a;
    }
    let s = ((t - a.t) / h).clamp(0.0, 1.0);
    let (s2, s3) = (s * s, s * s * s);
    let q = (2.0 * s3 - 3.0 * s2 + 1.0) * a.q
        + (s3 - 2.0 * s2 + s) * h * a.q_dot
        + (-2.0 * s3 + 3.0 * s2) * b.q
        + (s3 - s2) * h * b.q_dot;
    let q_dot = ((6.0 * s2 - 6.0 * s) * a.q
        + (3.0 * s2 - 4.0 * s + 1.0) * h * a.q_dot
        + (-6.0 * s2 + 6.0 * s) * b.q
        + (3.0 * s2 - 2.0 * s) * h * b.q_dot)
        / h;
    let lerp = |x: f64, y: f64| x + (y - x) * s;
    Sample {
        t,
        q,
        q_dot,
        q_ddot: lerp(a.q_ddot, b.q_ddot),
        kinetic: lerp(a.kinetic, b.kinetic),
        potential: lerp(a.potential, b.potential),
        work_nonconservative: lerp(a.work_nonconservative, b.work_nonconservative),
    }
}

/// The reduced right-hand side with its kinematic buffer and evaluation count.
struct Rhs<'a> {
    k: &'a mut Kinematics,
    forces: &'a ForceModel,
    sol: Solution,
    evaluations: usize,
}

impl Rhs<'_> {
    /// Solves the kinematics at `q` (one RHS evaluation) and reduces there.
    fn reduce(&mut self, q: f64, q_dot: f64) -> Result<Reduced> {
        self.evaluations += 1;
        unit_solution(self.k, q, &mut self.sol)?;
        self.reduce_here(q, q_dot)
    }

    /// Reduces at the position already solved in `self.sol` (at `q`).
    fn reduce_here(&mut self, q: f64, q_dot: f64) -> Result<Reduced> {
        let r = self.forces.reduce(&self.sol, q_dot);
        if !(r.j > 0.0 && r.j.is_finite()) {
            return Err(LinkageError::Singular {
                input_deg: q.to_degrees(),
                reason: format!(
                    "equivalent inertia J = {:e}: the input coordinate is singular here",
                    r.j
                ),
            });
        }
        Ok(r)
    }

    fn accel(&mut self, q: f64, q_dot: f64) -> Result<f64> {
        Ok(self.reduce(q, q_dot)?.acceleration(q_dot))
    }

    /// A full sample at (t, q, q̇), with the non-conservative work carried in.
    fn sample(&mut self, t: f64, q: f64, q_dot: f64, work: f64) -> Result<(Sample, Reduced)> {
        self.evaluations += 1;
        unit_solution(self.k, q, &mut self.sol)?;
        self.sample_here(t, q, q_dot, work)
    }

    /// As [`Self::sample`], at the position already solved in `self.sol`.
    fn sample_here(&mut self, t: f64, q: f64, q_dot: f64, work: f64) -> Result<(Sample, Reduced)> {
        let r = self.reduce_here(q, q_dot)?;
        let e: EnergyTerms = self.forces.energy(&self.sol, r.j, q_dot);
        Ok((
            Sample {
                t,
                q,
                q_dot,
                q_ddot: r.acceleration(q_dot),
                kinetic: e.kinetic,
                potential: e.gravity + e.spring + e.forces,
                work_nonconservative: work,
            },
            r,
        ))
    }
}

/// An end stop resolved to the link it watches.
struct Stop {
    name: String,
    link: usize,
    angle: f64,
    stops: bool,
}

/// Integrates from the scene's start (input angle, at rest unless `q_dot0` is given)
/// to `t_end` seconds or the first end stop. `step` is Δt (s) for the time-stepping
/// methods and Δφ (rad) for the energy-increment method.
pub fn simulate(
    k: &mut Kinematics,
    method: Method,
    step: f64,
    t_end: f64,
    q_dot0: f64,
    use_stops: bool,
) -> Result<Simulation> {
    let invalid = |name: &str, value: f64, valid: &str| LinkageError::InvalidParameter {
        name: name.into(),
        value,
        valid: valid.into(),
    };
    if !(step > 0.0 && step.is_finite()) {
        return Err(invalid(
            "step",
            step,
            "must be finite and > 0 (s, or rad for the energy method)",
        ));
    }
    if !(t_end > 0.0 && t_end.is_finite()) {
        return Err(invalid("t_end", t_end, "must be finite and > 0 s"));
    }
    if !q_dot0.is_finite() {
        return Err(invalid("initial speed", q_dot0, "must be finite"));
    }
    let m = k.mechanism().clone();
    let q0 = m.driver.start_rad;
    let mut start = k.empty_solution();
    unit_solution(k, q0, &mut start)?;
    let forces = ForceModel::new(&m, &start)?;
    if forces.is_massless() {
        return Err(LinkageError::SceneInvalid(
            "no link has a mass: there is nothing to integrate".into(),
        ));
    }
    let stops: Vec<Stop> = if use_stops {
        m.forces
            .stops
            .iter()
            .filter_map(|s| {
                m.link_index(&s.link).map(|link| Stop {
                    name: s.name.clone(),
                    link,
                    angle: s.angle,
                    stops: s.action == StopAction::Stop,
                })
            })
            .collect()
    } else {
        Vec::new()
    };
    let clock = Instant::now();
    let mut rhs = Rhs {
        sol: k.empty_solution(),
        k,
        forces: &forces,
        evaluations: 0,
    };
    let (first, first_reduced) = rhs.sample(0.0, q0, q_dot0, 0.0)?;
    let mut samples = vec![first];
    let mut events = Vec::new();
    let mut steps = 0usize;
    // Signed distance of a stop's link from its stop angle at input q.
    let gap = |rhs: &mut Rhs<'_>, q: f64, stop: &Stop| -> f64 {
        if unit_solution(rhs.k, q, &mut rhs.sol).is_err() {
            return f64::NAN;
        }
        let a = rhs.sol.links[stop.link].angle_rad() - stop.angle;
        a - (a / std::f64::consts::TAU).round() * std::f64::consts::TAU
    };
    // The state at the start of each step, with its reduction and stop gaps, carried
    // over from the end of the previous step rather than solved again.
    let (mut a, mut ra) = (first, first_reduced);
    let mut gaps: Vec<f64> = stops.iter().map(|stop| gap(&mut rhs, a.q, stop)).collect();
    'run: while a.t < t_end {
        let (next, r_next) = match method {
            Method::Rk4 => rk4_step(&mut rhs, &a, &ra, step.min(t_end - a.t))?,
            Method::SemiImplicitEuler => euler_step(&mut rhs, &a, &ra, step.min(t_end - a.t))?,
            Method::EnergyIncrement => match energy_step(&mut rhs, &a, &ra, step)? {
                Some(b) => b,
                None => {
                    events.push(SimEvent {
                        name: "turning point".into(),
                        state: a,
                        stopped: true,
                    });
                    break 'run;
                }
            },
        };
        steps += 1;
        for (stop, ga) in stops.iter().zip(gaps.iter_mut()) {
            let gb = gap(&mut rhs, next.q, stop);
            if ga.is_finite()
                && gb.is_finite()
                && *ga != 0.0
                && ga.signum() != gb.signum()
                && (*ga - gb).abs() < 1.0
            {
                let t_hit = refine(a.t, next.t, |t| {
                    gap(&mut rhs, interpolate(&a, &next, t).q, stop)
                })
                .unwrap_or(next.t);
                let at = interpolate(&a, &next, t_hit);
                let (state, _) = rhs.sample(at.t, at.q, at.q_dot, at.work_nonconservative)?;
                events.push(SimEvent {
                    name: stop.name.clone(),
                    state,
                    stopped: stop.stops,
                });
                if stop.stops {
                    samples.push(state);
                    break 'run;
                }
            }
            *ga = gb;
        }
        samples.push(next);
        (a, ra) = (next, r_next);
    }
    let stats = RunStats {
        steps,
        rhs_evaluations: rhs.evaluations,
        cpu_seconds: clock.elapsed().as_secs_f64(),
    };
    Ok(Simulation {
        method,
        samples,
        events,
        stats,
    })
}

/// Work of the non-conservative moment over a step, by the trapezoid rule in q.
fn work(a: &Sample, b: &Sample, ra: &Reduced, rb: &Reduced) -> f64 {
    0.5 * (ra.m_damping + ra.m_other + rb.m_damping + rb.m_other) * (b.q - a.q)
}

/// One RK4 step from `a`, whose reduction `ra` is known: three new stages and the
/// end state, four kinematic solves.
fn rk4_step(rhs: &mut Rhs<'_>, a: &Sample, ra: &Reduced, h: f64) -> Result<(Sample, Reduced)> {
    let k1 = (a.q_dot, ra.acceleration(a.q_dot));
    let k2 = (
        a.q_dot + 0.5 * h * k1.1,
        rhs.accel(a.q + 0.5 * h * k1.0, a.q_dot + 0.5 * h * k1.1)?,
    );
    let k3 = (
        a.q_dot + 0.5 * h * k2.1,
        rhs.accel(a.q + 0.5 * h * k2.0, a.q_dot + 0.5 * h * k2.1)?,
    );
    let k4 = (
        a.q_dot + h * k3.1,
        rhs.accel(a.q + h * k3.0, a.q_dot + h * k3.1)?,
    );
    let q = a.q + h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
    let q_dot = a.q_dot + h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
    let (mut b, rb) = rhs.sample(a.t + h, q, q_dot, a.work_nonconservative)?;
    b.work_nonconservative += work(a, &b, ra, &rb);
    Ok((b, rb))
}

/// One semi-implicit Euler step from `a` (reduction `ra` known): one kinematic solve.
fn euler_step(rhs: &mut Rhs<'_>, a: &Sample, ra: &Reduced, h: f64) -> Result<(Sample, Reduced)> {
    let q_dot = a.q_dot + h * ra.acceleration(a.q_dot);
    let q = a.q + h * q_dot;
    let (mut b, rb) = rhs.sample(a.t + h, q, q_dot, a.work_nonconservative)?;
    b.work_nonconservative += work(a, &b, ra, &rb);
    Ok((b, rb))
}

/// One energy increment of size `dphi` in the direction of motion (from rest: the
/// direction the moment pushes). `None` at a turning point (kinetic energy would go
/// negative). One kinematic solve, at the new q.
fn energy_step(
    rhs: &mut Rhs<'_>,
    a: &Sample,
    ra: &Reduced,
    dphi: f64,
) -> Result<Option<(Sample, Reduced)>> {
    let direction = if a.q_dot != 0.0 {
        a.q_dot.signum()
    } else {
        ra.moment().signum()
    };
    if direction == 0.0 {
        return Ok(None);
    }
    let dq = direction * dphi;
    let q = a.q + dq;
    let rb = rhs.reduce(q, a.q_dot)?;
    let w2 = (ra.j * a.q_dot * a.q_dot + 2.0 * ra.moment() * dq) / rb.j;
    if w2 < 0.0 {
        return Ok(None);
    }
    let q_dot = direction * w2.sqrt();
    let t = a.t + 2.0 * dq / (a.q_dot + q_dot);
    // J at q does not depend on q̇; only the damping moment does, so the solve just
    // done at q serves the sample too.
    let (mut b, rb) = rhs.sample_here(t, q, q_dot, a.work_nonconservative)?;
    b.work_nonconservative += work(a, &b, ra, &rb);
    Ok(Some((b, rb)))
}
