//! The integrator choice and the run's settings, validated before anything runs.

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
        let invalid = |name: &str, value: f64, valid: &str| {
            Err(LinkageError::InvalidParameter {
                name: name.into(),
                value,
                valid: valid.into(),
            })
        };
        if self.method.is_adaptive() {
            if !(self.rtol.is_finite() && self.rtol >= 1e-15 && self.rtol < 1.0) {
                return invalid("rtol", self.rtol, "must be in [1e-15, 1)");
            }
            if !(self.atol.is_finite() && self.atol > 0.0) {
                return invalid("atol", self.atol, "must be finite and > 0");
            }
            if !(self.step.is_finite() && self.step >= 0.0) {
                return invalid(
                    "max step",
                    self.step,
                    "must be finite and >= 0 s (0: no limit)",
                );
            }
        } else if !(self.step > 0.0 && self.step.is_finite()) {
            return invalid(
                "step",
                self.step,
                "must be finite and > 0 (s, or rad for the energy method)",
            );
        }
        if !(self.t_end > 0.0 && self.t_end.is_finite()) {
            return invalid("t_end", self.t_end, "must be finite and > 0 s");
        }
        if !self.q_dot0.is_finite() {
            return invalid("initial speed", self.q_dot0, "must be finite");
        }
        if let Some(dt) = self.output_dt {
            if !(dt > 0.0 && dt.is_finite()) {
                return invalid("output dt", dt, "must be finite and > 0 s");
            }
            if self.t_end / dt > MAX_OUTPUT_SAMPLES {
                let least = self.t_end / MAX_OUTPUT_SAMPLES;
                return invalid(
                    "output dt",
                    dt,
                    &format!(
                        "gives {:.3e} samples over t_end = {} s; at most {MAX_OUTPUT_SAMPLES:.0e}: make it at least {least:.3e} s",
                        self.t_end / dt,
                        self.t_end
                    ),
                );
            }
        }
        let fixed_time_step = !self.method.is_adaptive() && self.method != Method::EnergyIncrement;
        if fixed_time_step && self.t_end / self.step > self.max_steps as f64 {
            let least = self.t_end / self.max_steps as f64;
            return invalid(
                "step",
                self.step,
                &format!(
                    "takes {:.3e} steps to t_end = {} s; at most {}: make it at least {least:.3e} s or shorten the run",
                    self.t_end / self.step,
                    self.t_end,
                    self.max_steps
                ),
            );
        }
        Ok(())
    }
}
