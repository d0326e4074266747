//! Refusals in the user's words: the links by their points, lengths in the scene's
//! unit, the crank's angle in degrees. What the solver keeps as data (a dyad's kind,
//! its assembly margin, link indices) stays out of what the user reads.

use linkage::LinkageError;
use linkage::assembly::AssemblyRanges;
use linkage::dyad::{DyadLabel, GroupLabel, Shortfall};
use linkage::error::{AssemblyFailure, RunRefusal, RunWarning, StabilityLimit};
use linkage::scene::LengthUnit;
pub use linkage_diagram::numbers::significant;

/// A length given in metres, in `unit` with four significant digits.
pub fn length(m: f64, unit: LengthUnit) -> String {
    let v = m / unit.to_metres();
    format!("{} {}", significant(v, 4), unit_label_of(unit))
}

/// A length unit as shown.
pub fn unit_label_of(unit: linkage::scene::LengthUnit) -> &'static str {
    linkage_diagram::numbers::unit_symbol(unit)
}

/// A group of the chain by its links and joint ("coupler and rocker, joined at C"),
/// in the words of the force polygons' titles, not by the solver's dyad kind.
pub fn group(label: &GroupLabel) -> String {
    match label {
        GroupLabel::Dyad(d) => {
            linkage_diagram::words::dyad(linkage_diagram::words::Lang::English, d)
        }
        GroupLabel::Numbered(g) => format!("group {g}"),
    }
}

/// A dyad that does not close: what falls short, or its links by name.
pub fn open(dyad: &DyadLabel, shortfall: Option<&Shortfall>, unit: LengthUnit) -> String {
    match shortfall {
        Some(s) => s.words(&|m| length(m, unit)),
        None => {
            let [a, b] = &dyad.links;
            format!("{a} and {b} cannot be joined at {}", dyad.inner_point)
        }
    }
}

/// A solver's error as the user reads it: an assembly failure with the distances
/// that do not fit at the crank's angle and where the crank can go; the others as
/// the solver words them (they name the user's links and values already).
pub fn error(e: &LinkageError, unit: LengthUnit) -> String {
    match e {
        LinkageError::CannotAssemble {
            input_deg,
            reason,
            reachable,
        } => {
            let why = match reason {
                AssemblyFailure::DyadOpen {
                    dyad, shortfall, ..
                } => open(dyad, shortfall.as_deref(), unit),
                other => other.to_string(),
            };
            format!(
                "at crank {}°, {why}; {}",
                significant(*input_deg, 4),
                reach(reachable)
            )
        }
        LinkageError::Run(r) => run_refusal(r),
        other => other.to_string(),
    }
}

/// The app's name of the method that has no stability limit, as its integrator
/// menu lists it.
fn implicit_choice() -> String {
    format!(
        "choose “{}” in the integrator menu",
        linkage::dynamics::Method::ImplicitMidpoint.label()
    )
}

/// A stiffness limit in the app's words.
fn limit_words(l: &StabilityLimit) -> String {
    format!(
        "the stiffest mode, |λ| = {} 1/s, keeps {} stable only below a step of {} s",
        significant(l.stiffness_per_s, 4),
        l.method.label(),
        significant(l.h_limit_s, 3)
    )
}

/// Why a dynamic run was refused or stopped, and which control to change.
pub fn run_refusal(r: &RunRefusal) -> String {
    match r {
        RunRefusal::StepBudgetSpent {
            t_end_s,
            max_steps,
            reached_t_s,
            stiff,
        } => {
            let advice = match stiff {
                Some(l) => format!(
                    "the motion is stiff ({}): {}",
                    limit_words(l),
                    implicit_choice()
                ),
                None => "loosen the tolerances or take a larger step".to_string(),
            };
            format!(
                "the run took {max_steps} steps, the most one run may take, and reached only t = {} s of {} s: {advice}",
                significant(*reached_t_s, 4),
                significant(*t_end_s, 4)
            )
        }
        RunRefusal::StepBeyondStability { step_s, limit, .. } => format!(
            "a step of {} s is too long: {}; take a shorter step or {}",
            significant(*step_s, 4),
            limit_words(limit),
            implicit_choice()
        ),
        RunRefusal::ImplicitNotConverged { step_s, t_s, why } => format!(
            "the implicit midpoint rule did not converge at t = {} s with a step of {} s ({why}): take a shorter step",
            significant(*t_s, 4),
            significant(*step_s, 4)
        ),
    }
}

/// A warning about a finished run, in the app's words.
pub fn run_warning(w: &RunWarning) -> String {
    match w {
        RunWarning::Stiff { mean_step_s, limit } => format!(
            "stiff: the mean step, {} s, is set by the stability limit, not by the tolerances ({}); {} for a run without that limit",
            significant(*mean_step_s, 3),
            limit_words(limit),
            implicit_choice()
        ),
    }
}

/// Where the crank can go, in degrees.
pub fn reach(r: &AssemblyRanges) -> String {
    if r.full_rotation {
        return "the crank turns a full circle".into();
    }
    if r.intervals.is_empty() {
        return "the chain assembles at no crank angle".into();
    }
    let spans: Vec<String> = r
        .intervals
        .iter()
        .map(|[a, b]| {
            format!(
                "{}° to {}°",
                significant(a.to_degrees(), 5),
                significant(b.to_degrees(), 5)
            )
        })
        .collect();
    format!("the crank reaches {}", spans.join(" or "))
}

#[cfg(test)]
mod tests {
    use linkage::dynamics::{Method, Settings, simulate};
    use linkage::{Kinematics, Mechanism};

    use super::*;

    /// The gravity flipper with its spring a thousand times stiffer than shipped.
    fn stiff_flipper() -> Kinematics {
        let b = crate::catalog::BUILTIN_SCENES
            .iter()
            .find(|b| b.key == "gravity_flipper")
            .expect("shipped");
        let text = b.text.replace("k_n_per_m: 1500.0", "k_n_per_m: 1e7");
        Kinematics::new(Mechanism::from_ron(&text).expect("parses")).expect("builds")
    }

    /// A fixed RK4 step beyond the stiff spring's stability limit, and an adaptive
    /// run whose cost the stiffness sets: the user reads the app's integrator menu,
    /// never a command-line option.
    #[test]
    fn a_run_refused_or_warned_for_its_stiffness_names_the_apps_controls() {
        let k = stiff_flipper();
        let mut fixed = Settings::new(Method::Rk4);
        (fixed.step, fixed.t_end) = (5e-3, 0.5);
        let refused = simulate(&k, &fixed).expect_err("beyond the limit");
        let words = error(&refused, LengthUnit::Millimetre);
        assert!(
            words.contains("“implicit” in the integrator menu") && !words.contains("--"),
            "{words}"
        );
        let mut loose = Settings::new(Method::Dop853);
        (loose.rtol, loose.atol) = (1e-3, 1e-3);
        let run = simulate(&k, &loose).expect("runs");
        let warned: Vec<String> = run.stats.warnings.iter().map(run_warning).collect();
        assert!(!warned.is_empty(), "no warning");
        for w in warned {
            assert!(w.contains("integrator menu") && !w.contains("--"), "{w}");
        }
    }
}
