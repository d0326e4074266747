//! The integrator choice and the run's settings, validated before anything runs.

use crate::ids::LinkId;
use serde::Serialize;

use crate::error::{LinkageError, Result};

/// Integration method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Method {
    /// The paper's energy increments: ½J₁w₁² = ½J₀w₀² + M₀Δφ, dt = 2Δφ/(w₀ + w₁); first
    /// order, steps of Δφ in the coordinate.
    EnergyIncrement,
    /// Semi-implicit (symplectic) Euler; first order, bounded energy error.
    SemiImplicitEuler,
    /// Classical fourth-order Runge–Kutta, fixed step.
    Rk4,
    /// Implicit midpoint rule, fixed step: A-stable and symplectic, for stiff springs.
    ImplicitMidpoint,
    /// Adaptive Dormand–Prince 5(4) with dense output.
    Dp5,
    /// Adaptive Dormand–Prince 8(5,3) with seventh-order dense output.
    Dop853,
}

impl Method {
    /// Every method, in order of increasing order of accuracy (for tables).
    pub const ALL: [Method; 6] = [
        Method::EnergyIncrement,
        Method::SemiImplicitEuler,
        Method::ImplicitMidpoint,
        Method::Rk4,
        Method::Dp5,
        Method::Dop853,
    ];

    /// Whether the step size follows from rtol/atol.
    pub fn is_adaptive(self) -> bool {
        matches!(self, Method::Dp5 | Method::Dop853)
    }

    /// Short name, as the CLI spells it.
    pub fn label(self) -> &'static str {
        match self {
            Method::EnergyIncrement => "energy",
            Method::SemiImplicitEuler => "euler",
            Method::Rk4 => "rk4",
            Method::ImplicitMidpoint => "implicit",
            Method::Dp5 => "dp5",
            Method::Dop853 => "dop853",
        }
    }

    /// Largest h·|λ| for which the method is stable on an undamped oscillation
    /// (λ on the imaginary axis); `None` for the unconditionally stable implicit rule
    /// and for the energy method, which steps in the coordinate, not in time.
    pub fn stability_limit(self) -> Option<f64> {
        match self {
            // Symplectic Euler on x'' = −ω²x is stable for hω < 2.
            Method::SemiImplicitEuler => Some(2.0),
            // RK4's stability region meets the imaginary axis at 2√2.
            Method::Rk4 => Some(2.0 * std::f64::consts::SQRT_2),
            // Adaptive methods keep themselves stable by shrinking the step; these
            // are where |R(iy)| first exceeds 1 (checked in the tests from the
            // tableaus), for the cost warning. DP5 hugs the imaginary axis only to 1.
            Method::Dp5 => Some(0.997),
            Method::Dop853 => Some(5.96),
            Method::EnergyIncrement | Method::ImplicitMidpoint => None,
        }
    }
}

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
