//! Why a dynamic run was refused or stopped, and which of the app's controls to
//! change: the integrator menu, the step, the tolerances.

use linkage::dynamics::Method;
use linkage::error::{ImplicitFailure, RunRefusal, RunWarning, StabilityLimit};

use crate::numbers::significant;
use crate::words::{Lang, sw};

/// The advice to choose the method that has no stability limit, by its name in the
/// integrator menu.
fn implicit_choice(lang: Lang) -> String {
    sw!(
        lang,
        "refusal.choose_implicit",
        method = Method::ImplicitMidpoint.label()
    )
}

/// A stiffness limit: the stiffest mode and the step the method is stable below.
fn limit_words(lang: Lang, l: &StabilityLimit) -> String {
    sw!(
        lang,
        "refusal.stability_limit",
        stiffness = significant(l.stiffness_per_s, 4),
        method = l.method.label(),
        step = significant(l.h_limit_s, 3)
    )
}

/// Why a dynamic run was refused or stopped, and which control to change.
pub fn run_refusal(lang: Lang, r: &RunRefusal) -> String {
    match r {
        RunRefusal::StepBudgetSpent {
            t_end_s,
            max_steps,
            reached_t_s,
            stiff,
        } => {
            let advice = match stiff {
                Some(l) => sw!(
                    lang,
                    "refusal.stiff_advice",
                    limit = limit_words(lang, l),
                    choice = implicit_choice(lang)
                ),
                None => sw!(lang, "refusal.loosen"),
            };
            sw!(
                lang,
                "refusal.step_budget",
                steps = max_steps,
                reached = significant(*reached_t_s, 4),
                end = significant(*t_end_s, 4),
                advice = advice
            )
        }
        RunRefusal::StepBeyondStability { step_s, limit, .. } => sw!(
            lang,
            "refusal.step_too_long",
            step = significant(*step_s, 4),
            limit = limit_words(lang, limit),
            choice = implicit_choice(lang)
        ),
        RunRefusal::ImplicitNotConverged { step_s, t_s, why } => sw!(
            lang,
            "refusal.implicit_failed",
            t = significant(*t_s, 4),
            step = significant(*step_s, 4),
            why = implicit_failure(lang, *why)
        ),
    }
}

/// Why the implicit rule's iteration failed.
fn implicit_failure(lang: Lang, f: ImplicitFailure) -> String {
    match f {
        ImplicitFailure::SingularMatrix => sw!(lang, "refusal.singular_matrix"),
        ImplicitFailure::NoConvergence => sw!(lang, "refusal.no_convergence"),
    }
}

/// A warning about a finished run.
pub fn run_warning(lang: Lang, w: &RunWarning) -> String {
    match w {
        RunWarning::Stiff { mean_step_s, limit } => sw!(
            lang,
            "refusal.stiff_warning",
            mean = significant(*mean_step_s, 3),
            limit = limit_words(lang, limit),
            choice = implicit_choice(lang)
        ),
    }
}
