//! What a run returns: samples, events, cost, and the kinematics of every coordinate
//! segment so that each sample's full pose can be recovered.

use serde::Serialize;

use super::settings::Method;
use crate::error::{Result, RunWarning};
use crate::ids::LinkId;
use crate::motion::Solution;
use crate::solve::Kinematics;

/// One state of the run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Sample {
    /// Time, s.
    pub t: f64,
    /// The scene's input coordinate (its driver link's angle), rad, unwrapped.
    pub q: f64,
    /// Its rate, rad/s.
    pub q_dot: f64,
    /// Its second derivative, rad/s².
    pub q_ddot: f64,
    /// Index of the link whose angle was the integration coordinate here.
    pub coordinate_link: LinkId,
    /// That coordinate, rad.
    pub x: f64,
    /// Its rate, rad/s.
    pub x_dot: f64,
    /// Kinetic energy, J.
    pub kinetic: f64,
    /// Gravity + spring + constant-force potential, J.
    pub potential: f64,
    /// Work done so far by dampers, torques and stroke forces (non-conservative), J.
    pub work_nonconservative: f64,
    /// Index of the coordinate segment (see [`Simulation::pose`]).
    pub segment: usize,
}

impl Sample {
    /// Kinetic + potential − non-conservative work: constant for an exact solution.
    pub fn energy_balance(&self) -> f64 {
        self.kinetic + self.potential - self.work_nonconservative
    }
}

/// An end stop, a reported crossing, a turning point or a coordinate switch, located
/// inside its step.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SimEvent {
    /// Event name (the scene's stop name, or what happened).
    pub name: String,
    /// State at the event.
    pub state: Sample,
    /// Whether the motion stopped there.
    pub stopped: bool,
}

/// Cost and quality of a run.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct RunStats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (adaptive methods).
    pub rejected_steps: usize,
    /// Evaluations of the reduced right-hand side (each one kinematic solve).
    pub rhs_evaluations: usize,
    /// Every kinematic solve, also those for events, output and Jacobians.
    pub kinematic_solves: usize,
    /// CPU (wall) seconds of the integration, output included.
    pub cpu_seconds: f64,
    /// Largest scaled local error estimate of an accepted step (adaptive methods:
    /// ≤ 1 means within rtol/atol); 0 for methods without an estimate.
    pub max_error_estimate: f64,
    /// Magnitude of the stiffest eigenvalue of the linearised motion at the start,
    /// 1/s: explicit steps must stay below about 2.8/this.
    pub stiffness_per_s: f64,
    /// Warnings about the run's accuracy or cost.
    pub warnings: Vec<RunWarning>,
}

/// A finished run.
#[derive(Clone, Debug)]
pub struct Simulation {
    /// Method used.
    pub method: Method,
    /// Samples: on the output grid when one was asked for, else at every step.
    pub samples: Vec<Sample>,
    /// Events in time order.
    pub events: Vec<SimEvent>,
    /// Cost.
    pub stats: RunStats,
    /// Kinematics of each coordinate segment, driven by its coordinate.
    pub(crate) segments: Vec<Kinematics>,
}

impl Simulation {
    /// The full pose (every link and point, velocities at the sample's speed) at a
    /// sample of this run.
    ///
    /// # Errors
    /// Only if the sample does not come from this run.
    pub fn pose(&mut self, s: &Sample) -> Result<Solution> {
        let k = self.segments.get_mut(s.segment).ok_or_else(|| {
            crate::error::LinkageError::invalid(
                crate::error::Param::SampleSegment,
                s.segment as f64,
                crate::error::Valid::SampleOfRun,
            )
        })?;
        let mut sol = k.empty_solution();
        k.solve_into(s.x, s.x_dot, &mut sol)?;
        Ok(sol)
    }

    /// Largest |energy balance − its start value| over the samples and events, J.
    pub fn energy_drift(&self) -> f64 {
        let Some(e0) = self.samples.first().map(Sample::energy_balance) else {
            return 0.0;
        };
        self.samples
            .iter()
            .chain(self.events.iter().map(|e| &e.state))
            .map(|s| (s.energy_balance() - e0).abs())
            .fold(0.0, f64::max)
    }
}
