//! The integrator choice and the run's settings, validated before anything runs.

use crate::error::{Param, Valid};
use crate::ids::LinkId;

use crate::error::{LinkageError, Result};

pub use crate::integrator::Method;

/// Most steps one run may take. Every run ends: a tolerance far below round-off, a
/// step far below the motion's time scale or a stiff spring under an explicit method
/// would otherwise run for hours. A million DOP853 steps is about a second here.
pub const MAX_STEPS: usize = 1_000_000;

/// Most output samples one run may hold (`t_end / output_dt`), about 100 MB.
pub const MAX_OUTPUT_SAMPLES: f64 = 1e6;

/// How to run a simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Integration method.
    pub method: Method,
    /// Fixed step: Δt in s, or Δφ in rad for the energy method. Adaptive methods use
    /// it as the largest step allowed (0: no limit).
    pub step: f64,
    /// Relative tolerance of the adaptive methods.
    pub rtol: f64,
    /// Absolute tolerance of the adaptive methods (rad and rad/s).
    pub atol: f64,
    /// End time, s (the run also ends at an end stop).
    pub t_end: f64,
    /// Initial rate of the scene's input coordinate, rad/s (0: released from rest).
    pub q_dot0: f64,
    /// Whether end stops act (else they are ignored).
    pub use_stops: bool,
    /// Samples on this uniform time grid by dense output; `None`: one per step.
    pub output_dt: Option<f64>,
    /// Link whose angle is the coordinate at the start (`None`: the scene's driver).
    pub coordinate: Option<LinkId>,
    /// Whether to switch to a regular coordinate near a dead point of the current one.
    pub switch_coordinates: bool,
    /// Most steps the run may take ([`MAX_STEPS`] by default): every run ends.
    pub max_steps: usize,
}

impl Settings {
    /// Sensible defaults for `method`: Δt = 1e-4 s (Δφ = 1e-3 rad for the energy
    /// method), rtol 1e-9, atol 1e-12, 10 s, from rest, stops on, coordinate switching on.
    pub fn new(method: Method) -> Self {
        Self {
            method,
            step: if method == Method::EnergyIncrement {
                1e-3
            } else if method.is_adaptive() {
                0.0
            } else {
                1e-4
            },
            rtol: 1e-9,
            atol: 1e-12,
            t_end: 10.0,
            q_dot0: 0.0,
            use_stops: true,
            output_dt: None,
            coordinate: None,
            switch_coordinates: true,
            max_steps: MAX_STEPS,
        }
    }

    /// Refuses non-finite or out-of-range values, naming the valid range.
    pub fn validate(&self) -> Result<()> {
        let invalid = |param: Param, value: f64, valid: Valid| {
            Err(LinkageError::invalid(param, value, valid))
        };
        if self.method.is_adaptive() {
            if !(self.rtol.is_finite() && self.rtol >= 1e-15 && self.rtol < 1.0) {
                return invalid(Param::Rtol, self.rtol, Valid::Rtol);
            }
            if !(self.atol.is_finite() && self.atol > 0.0) {
                return invalid(Param::Atol, self.atol, Valid::Positive);
            }
            if !(self.step.is_finite() && self.step >= 0.0) {
                return invalid(Param::MaxStep, self.step, Valid::MaxStep);
            }
        } else if !(self.step > 0.0 && self.step.is_finite()) {
            return invalid(Param::Step, self.step, Valid::Step);
        }
        if !(self.t_end > 0.0 && self.t_end.is_finite()) {
            return invalid(Param::TEnd, self.t_end, Valid::PositiveSeconds);
        }
        if !self.q_dot0.is_finite() {
            return invalid(Param::InitialSpeed, self.q_dot0, Valid::FiniteShort);
        }
        if let Some(dt) = self.output_dt {
            if !(dt > 0.0 && dt.is_finite()) {
                return invalid(Param::OutputDt, dt, Valid::PositiveSeconds);
            }
            if self.t_end / dt > MAX_OUTPUT_SAMPLES {
                let least = self.t_end / MAX_OUTPUT_SAMPLES;
                return invalid(
                    Param::OutputDt,
                    dt,
                    Valid::OutputSamples {
                        samples: self.t_end / dt,
                        t_end_s: self.t_end,
                        max: MAX_OUTPUT_SAMPLES,
                        least_s: least,
                    },
                );
            }
        }
        let fixed_time_step = !self.method.is_adaptive() && self.method != Method::EnergyIncrement;
        if fixed_time_step && self.t_end / self.step > self.max_steps as f64 {
            let least = self.t_end / self.max_steps as f64;
            return invalid(
                Param::Step,
                self.step,
                Valid::StepCount {
                    steps: self.t_end / self.step,
                    t_end_s: self.t_end,
                    max: self.max_steps,
                    least_s: least,
                },
            );
        }
        Ok(())
    }
}
