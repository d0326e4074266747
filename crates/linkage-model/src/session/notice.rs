//! What the last edit could not do, kept as data and put into words only when shown.

use std::fmt;

use linkage::LinkageError;
use linkage::scene::LengthUnit;

use super::limit::NotAssembled;
use super::params::LengthError;

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
        /// Which group does not close, or the solver's error.
        why: NotAssembled,
        /// The nearest value towards `value` that still assembles, if one was found.
        limit: Option<f64>,
    },
    /// A length that is no length (not positive, or its points gone).
    LengthInvalid(LengthError),
    /// A value outside its valid range (or not a number).
    InvalidValue {
        /// What it is, with its unit ("spring constant (N/m)").
        what: &'static str,
        /// The value asked for.
        value: f64,
        /// The valid range in words.
        valid: &'static str,
    },
    /// A cam segment's angle that leaves the next segment none.
    CamSpanRefused {
        /// The segment, from 0.
        segment: usize,
        /// The angle asked for, deg.
        deg: f64,
        /// Its angle and the next one's together, deg.
        room_deg: f64,
    },
    /// The crank cannot go to the angle asked for.
    InputRefused(LinkageError),
    /// A point cannot go where it was dragged.
    PointRefused {
        /// The point's name.
        name: String,
        /// Where it was asked to go, scene units.
        to: [f64; 2],
        /// The scene's length unit.
        unit: &'static str,
        /// Why not.
        why: PointRefusal,
    },
    /// The scene an edit made does not build or solve.
    EditRefused {
        /// The edit, in words ("flipping the branch at C").
        what: String,
        /// The solver's error.
        why: LinkageError,
    },
    /// Undo or redo holds a scene that does not build here.
    HistoryRefused {
        /// Undo (else redo).
        undo: bool,
        /// The solver's error.
        why: LinkageError,
    },
}

/// Why a point cannot go where it was dragged.
#[derive(Clone, Debug, PartialEq)]
pub enum PointRefusal {
    /// The place is not finite.
    NotFinite,
    /// No link carries a point of that name.
    NoSuchPoint,
    /// The chain does not assemble with the point there.
    NotAssembled(NotAssembled),
    /// The point slides on a guide and was dragged off its line.
    OffGuide,
    /// The chain assembles there only on the other branch.
    OtherBranch,
}

impl Notice {
    /// The notice as the user reads it, lengths in the scene's `unit`: the links
    /// by their points, the crank's angle in degrees, never the solver's terms.
    pub fn words(&self, unit: LengthUnit) -> String {
        use super::words::{error, significant};
        match self {
            Self::LengthRefused {
                label,
                value,
                unit: shown,
                input_deg,
                why,
                limit,
            } => {
                let why = why.words(unit);
                let at = significant(*input_deg, 4);
                let value = significant(*value, 5);
                match limit {
                    Some(limit) => format!(
                        "{label} = {value} {shown} does not fit at crank {at}°: {why}. At this \
                         crank angle {label} can go to {} {shown}; the last valid pose stays.",
                        significant(*limit, 5)
                    ),
                    None => {
                        format!("{label} = {value} {shown}: {why}; the last valid pose stays.")
                    }
                }
            }
            Self::LengthInvalid(why) => why.to_string(),
            Self::InvalidValue { what, value, valid } => {
                format!("{what} = {value} is invalid: {valid}; nothing changed")
            }
            Self::CamSpanRefused {
                segment,
                deg,
                room_deg,
            } => format!(
                "segment {} of the cam cannot span {}°: the next segment gives it room, \
                 so it must lie between 0 and {}° (exclusive); nothing changed",
                segment + 1,
                significant(*deg, 5),
                significant(*room_deg, 5)
            ),
            Self::InputRefused(why) => error(why, unit),
            Self::PointRefused { name, why, .. } if *why == PointRefusal::NoSuchPoint => {
                format!("there is no point named {name}")
            }
            Self::PointRefused {
                name,
                to,
                unit: shown,
                why,
            } => {
                let why = match why {
                    PointRefusal::NotAssembled(n) => n.words(unit),
                    other => other.to_string(),
                };
                format!(
                    "{name} cannot go to ({:.2}, {:.2}) {shown}: {why}",
                    to[0], to[1]
                )
            }
            Self::EditRefused { what, why } => format!("{what}: {}", error(why, unit)),
            Self::HistoryRefused { undo, why } => {
                let what = if *undo { "undo" } else { "redo" };
                format!("cannot {what}: {}", error(why, unit))
            }
        }
    }
}

impl fmt::Display for Notice {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.words(LengthUnit::Metre))
    }
}

impl fmt::Display for PointRefusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NotFinite => f.write_str("the place is not finite"),
            Self::NoSuchPoint => f.write_str("no link carries such a point"),
            Self::NotAssembled(why) => write!(f, "{why}"),
            Self::OffGuide => {
                f.write_str("it slides on a guide, so it can move only along the guide's line")
            }
            Self::OtherBranch => f.write_str(
                "the chain assembles there only on its other branch (flip the branch first)",
            ),
        }
    }
}
