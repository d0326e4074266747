//! Why a dynamic run is refused or warned about, as data: the numbers and the method
//! involved, so that each edge words what to change in its own terms (the command
//! line names its options, the app its controls). The solver's own words here name
//! no option of either.

use std::fmt;

use serde::Serialize;
use thiserror::Error;

use crate::integrator::Method;

/// An explicit method's limit on its step for the stiffest mode of a run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StabilityLimit {
    /// The method.
    pub method: Method,
    /// The stiffest mode's |λ| at the start, 1/s.
    pub stiffness_per_s: f64,
    /// The largest stable step, s.
    pub h_limit_s: f64,
}

impl StabilityLimit {
    /// The limit `method` sets for a stiffest mode of `stiffness_per_s`; `None` for a
    /// method without one (the implicit rule, the energy method).
    pub fn of(method: Method, stiffness_per_s: f64) -> Option<Self> {
        method.stability_limit().map(|h_lambda| Self {
            method,
            stiffness_per_s,
            h_limit_s: h_lambda / stiffness_per_s,
        })
    }
}

impl fmt::Display for StabilityLimit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "|λ| = {:.4e} 1/s; {} is stable only below h = {:.3e} s",
            self.stiffness_per_s,
            self.method.label(),
            self.h_limit_s
        )
    }
}

/// Why the implicit midpoint rule's step failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImplicitFailure {
    /// Its iteration matrix is singular.
    SingularMatrix,
    /// Its Newton iteration did not converge.
    NoConvergence,
}

impl fmt::Display for ImplicitFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::SingularMatrix => "singular iteration matrix",
            Self::NoConvergence => "the Newton iteration did not converge",
        })
    }
}

/// Why a dynamic run stopped or was refused before its first step.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum RunRefusal {
    /// The run took the most steps it may and reached only `reached_t_s`.
    #[error(
        "t_end = {t_end_s} is invalid: the run took {max_steps} steps (the most this run may take) and reached only t = {reached_t_s:.6e} s: {}",
        budget_advice(stiff)
    )]
    StepBudgetSpent {
        /// The end time asked for, s.
        t_end_s: f64,
        /// The most steps the run may take.
        max_steps: usize,
        /// Where it got to, s.
        reached_t_s: f64,
        /// The stiffness's limit where that, not the tolerances, set the steps.
        stiff: Option<StabilityLimit>,
    },
    /// A fixed explicit step beyond its method's stability limit.
    #[error(
        "step = {step_s} is invalid: below {:.3e} s, the stability limit of {} for the stiffest mode here (|λ| = {:.4e} 1/s, h|λ| < {h_lambda:.3}); an implicit method has no limit",
        limit.h_limit_s,
        limit.method.label(),
        limit.stiffness_per_s
    )]
    StepBeyondStability {
        /// The step asked for, s.
        step_s: f64,
        /// The limit.
        limit: StabilityLimit,
        /// The method's largest stable h|λ|.
        h_lambda: f64,
    },
    /// The implicit midpoint rule did not converge at `t_s` with step `step_s`.
    #[error(
        "step = {step_s} is invalid: small enough for the implicit midpoint rule to converge at t = {t_s:.6} s ({why}): take a smaller step"
    )]
    ImplicitNotConverged {
        /// The step, s.
        step_s: f64,
        /// Where, s.
        t_s: f64,
        /// Why.
        why: ImplicitFailure,
    },
}

/// What a run that spent its step budget should change, in the solver's words.
fn budget_advice(stiff: &Option<StabilityLimit>) -> String {
    match stiff {
        Some(limit) => {
            format!("the motion is stiff ({limit}): an implicit method has no such limit")
        }
        None => "loosen the tolerances or take a larger step".to_string(),
    }
}

/// A warning about a finished run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum RunWarning {
    /// An adaptive method's mean step sat near its stability limit: the stiffness,
    /// not the tolerances, set the run's cost.
    Stiff {
        /// The run's mean step, s.
        mean_step_s: f64,
        /// The limit.
        limit: StabilityLimit,
    },
}

impl fmt::Display for RunWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Stiff { mean_step_s, limit } => write!(
                f,
                "stiff: the mean step {mean_step_s:.3e} s of {} is set by its stability limit {:.3e} s (stiffest mode |λ| = {:.4e} 1/s at the start), not by the tolerances; an implicit method has no such limit",
                limit.method.label(),
                limit.h_limit_s,
                limit.stiffness_per_s
            ),
        }
    }
}
