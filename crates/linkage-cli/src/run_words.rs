//! A dynamic run's refusals and warnings in this command line's words: what to
//! change is named by its option (`--method implicit`, `--dt`, `--rtol`/`--atol`),
//! which the solver does not know. The app words the same data for its controls
//! (linkage-model's `session/words.rs`) and the solver's `Display` for neither:
//! matches of the same shape, by design, one per edge.

use linkage::error::{RunRefusal, RunWarning};

/// Why the run was refused or stopped, and the option to change.
pub(crate) fn refusal(r: &RunRefusal) -> String {
    match r {
        RunRefusal::StepBudgetSpent {
            t_end_s,
            max_steps,
            reached_t_s,
            stiff,
        } => {
            let advice = match stiff {
                // The limit's own words (the stiffest mode, the step the method
                // allows) name no option.
                Some(l) => format!("the motion is stiff ({l}): use --method implicit"),
                None => "loosen rtol/atol or take a larger step".to_string(),
            };
            format!(
                "t_end = {t_end_s} is invalid: the run took {max_steps} steps (the most this run may take) and reached only t = {reached_t_s:.6e} s: {advice}"
            )
        }
        RunRefusal::StepBeyondStability {
            step_s,
            limit,
            h_lambda,
        } => format!(
            "step = {step_s} is invalid: below {:.3e} s, the stability limit of {} for the stiffest mode here (|λ| = {:.4e} 1/s, h|λ| < {h_lambda:.3}); or use --method implicit, which has no limit",
            limit.h_limit_s,
            limit.method.label(),
            limit.stiffness_per_s
        ),
        RunRefusal::ImplicitNotConverged { step_s, t_s, why } => format!(
            "step = {step_s} is invalid: small enough for the implicit midpoint rule to converge at t = {t_s:.6} s ({why}): try a smaller --dt"
        ),
    }
}

/// A warning about the finished run, and the option that avoids its cost.
pub(crate) fn warning(w: &RunWarning) -> String {
    match w {
        RunWarning::Stiff { mean_step_s, limit } => format!(
            "stiff: the mean step {mean_step_s:.3e} s of {} is set by its stability limit {:.3e} s (stiffest mode |λ| = {:.4e} 1/s at the start), not by rtol; --method implicit has no such limit",
            limit.method.label(),
            limit.h_limit_s,
            limit.stiffness_per_s
        ),
    }
}

#[cfg(test)]
mod tests {
    use linkage::dynamics::Method;
    use linkage::error::StabilityLimit;

    use super::*;

    fn rk4_limit() -> StabilityLimit {
        StabilityLimit {
            method: Method::Rk4,
            stiffness_per_s: 608.6,
            h_limit_s: 4.647e-3,
        }
    }

    /// The command line names its own options, as before the solver spoke in data.
    #[test]
    fn the_command_line_names_its_options() {
        let beyond = refusal(&RunRefusal::StepBeyondStability {
            step_s: 5e-3,
            limit: rk4_limit(),
            h_lambda: 2.828,
        });
        assert_eq!(
            beyond,
            "step = 0.005 is invalid: below 4.647e-3 s, the stability limit of rk4 for the stiffest mode here (|λ| = 6.0860e2 1/s, h|λ| < 2.828); or use --method implicit, which has no limit"
        );
        let spent = refusal(&RunRefusal::StepBudgetSpent {
            t_end_s: 1.0,
            max_steps: 1000,
            reached_t_s: 0.25,
            stiff: Some(rk4_limit()),
        });
        assert!(spent.ends_with("use --method implicit"), "{spent}");
        let implicit = refusal(&RunRefusal::ImplicitNotConverged {
            step_s: 0.5,
            t_s: 0.0,
            why: linkage::error::ImplicitFailure::NoConvergence,
        });
        assert!(implicit.ends_with("try a smaller --dt"), "{implicit}");
        let stiff = warning(&RunWarning::Stiff {
            mean_step_s: 4e-3,
            limit: rk4_limit(),
        });
        assert!(
            stiff.ends_with("--method implicit has no such limit"),
            "{stiff}"
        );
    }
}
