//! What the last edit could not do, kept as data and put into words only when shown.

use std::fmt;

/// A refused edit or a failed action.
#[derive(Clone, Debug, PartialEq)]
pub enum Notice {
    /// A length the chain cannot assemble with at the current input.
    LengthRefused {
        /// The length's slider label.
        label: String,
        /// The value asked for, scene units.
        value: f64,
        /// The scene's length unit.
        unit: &'static str,
        /// The input angle held, deg.
        input_deg: f64,
        /// The cause (which group does not close, or the solver's error).
        why: String,
        /// The nearest value towards `value` that still assembles, if one was found.
        limit: Option<f64>,
    },
    /// Anything else, already in words.
    Text(String),
}

impl fmt::Display for Notice {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::LengthRefused {
                label,
                value,
                unit,
                input_deg,
                why,
                limit: Some(limit),
            } => write!(
                f,
                "{label} = {value:.4} {unit} cannot assemble at input {input_deg:.2} deg: {why}. At this input {label} can go to {limit:.4} {unit}; the last valid pose stays."
            ),
            Self::LengthRefused {
                label,
                value,
                unit,
                why,
                limit: None,
                ..
            } => write!(
                f,
                "{label} = {value:.4} {unit}: {why}; the last valid pose stays."
            ),
            Self::Text(text) => f.write_str(text),
        }
    }
}
