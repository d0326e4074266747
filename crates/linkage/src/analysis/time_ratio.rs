//! The time ratio K of an output with two limits on a turning input, and which stroke
//! it measures.

use super::TAU;
use super::limits::{Extreme, LimitPosition};
use serde::Serialize;

/// Which stroke of an output: from its minimum to its maximum, or back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    /// Minimum to maximum.
    Rising,
    /// Maximum to minimum.
    Falling,
}

/// Which output the time ratio K refers to and which stroke is slower, or why the
/// report has no K; worded by `Display` (and so serialized).
#[derive(Clone, Debug, PartialEq)]
pub enum TimeRatioNote {
    /// The two strokes of `output`: crank angles spent rising and falling, rad.
    Strokes {
        /// The output's name.
        output: String,
        /// The slower stroke.
        slower: Stroke,
        /// Crank angle from the minimum to the maximum, rad.
        rising_rad: f64,
        /// Crank angle from the maximum back to the minimum, rad.
        falling_rad: f64,
    },
    /// The main output has not exactly two limit positions.
    NotTwoLimits,
    /// The input does not turn fully.
    InputDoesNotTurn,
}

impl std::fmt::Display for TimeRatioNote {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Strokes {
                output,
                slower,
                rising_rad,
                falling_rad,
            } => write!(
                f,
                "{output}: {} stroke is slower; crank turns {:.3} deg rising, {:.3} deg falling; \
                 angle between limit positions theta = {:.3} deg",
                match slower {
                    Stroke::Rising => "rising (min to max)",
                    Stroke::Falling => "falling (max to min)",
                },
                rising_rad.to_degrees(),
                falling_rad.to_degrees(),
                (rising_rad - std::f64::consts::PI).abs().to_degrees()
            ),
            Self::NotTwoLimits => {
                f.write_str("the main output does not have exactly two limit positions")
            }
            Self::InputDoesNotTurn => {
                f.write_str("the input does not turn fully, so no time ratio")
            }
        }
    }
}

impl Serialize for TimeRatioNote {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// Time ratio K of an output with exactly two limits on a fully turning input (slower
/// stroke angle / faster stroke angle), with its strokes.
pub fn time_ratio(limits: &[LimitPosition], speed_rad_s: f64) -> Option<(f64, TimeRatioNote)> {
    let [a, b] = limits else { return None };
    let (max, min) = if a.kind == Extreme::Max {
        (a, b)
    } else {
        (b, a)
    };
    if max.kind == min.kind {
        return None;
    }
    let rising = if speed_rad_s >= 0.0 {
        (max.input_rad - min.input_rad).rem_euclid(TAU)
    } else {
        (min.input_rad - max.input_rad).rem_euclid(TAU)
    };
    let falling = TAU - rising;
    let k = rising.max(falling) / rising.min(falling);
    let slower = if rising > falling {
        Stroke::Rising
    } else {
        Stroke::Falling
    };
    Some((
        k,
        TimeRatioNote::Strokes {
            output: max.output.clone(),
            slower,
            rising_rad: rising,
            falling_rad: falling,
        },
    ))
}
