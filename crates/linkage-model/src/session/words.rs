//! Refusals in the user's words: the links by their points, lengths in the scene's
//! unit, the crank's angle in degrees. What the solver keeps as data (a dyad's kind,
//! its assembly margin, link indices) stays out of what the user reads.

use linkage::LinkageError;
use linkage::assembly::AssemblyRanges;
use linkage::dyad::{DyadLabel, Shortfall};
use linkage::error::AssemblyFailure;
use linkage::scene::LengthUnit;
pub use linkage_diagram::numbers::significant;

/// A length given in metres, in `unit` with four significant digits.
pub fn length(m: f64, unit: LengthUnit) -> String {
    let v = m / unit.to_metres();
    format!("{} {}", significant(v, 4), unit_label_of(unit))
}

/// A length unit as shown.
pub fn unit_label_of(unit: linkage::scene::LengthUnit) -> &'static str {
    use linkage::scene::LengthUnit;
    match unit {
        LengthUnit::Metre => "m",
        LengthUnit::Millimetre => "mm",
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
        other => other.to_string(),
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
