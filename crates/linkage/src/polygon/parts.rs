//! The polygons' data: which quantity, which component, a term's symbol, a term
//! with its vector and what is known of it, and a vector equation.

use std::fmt;

use serde::{Serialize, Serializer};

use crate::dyad::GroupLabel;
use crate::motion::Vec2;

/// Velocity or acceleration.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Quantity {
    /// v.
    Velocity,
    /// a.
    Acceleration,
}

/// Which part of a point's (relative) motion a term is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Component {
    /// The whole vector.
    Whole,
    /// The normal (centripetal) part, towards the centre of rotation: ^n.
    Normal,
    /// The tangential part, at right angles to the radius: ^t.
    Tangential,
    /// The Coriolis part, 2 ω × v_rel of a point riding a turning guide: ^k.
    Coriolis,
    /// The sliding part along a moving guide: ^r.
    Sliding,
}

/// A term's symbol as data: `v_CB` is the velocity of C relative to B, whole;
/// `a_C^n` the normal acceleration of C (relative to the frame). Text is made where
/// it is shown ([`fmt::Display`] gives the ASCII form `v_CB`, `a_C^n`).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Symbol {
    /// Velocity or acceleration.
    pub quantity: Quantity,
    /// The point (its name; `C'` is the point of a guide under the slider's C).
    pub point: String,
    /// The point it is relative to; `None` relative to the frame.
    pub relative_to: Option<String>,
    /// Which part.
    pub component: Component,
}

impl Symbol {
    pub(super) fn new(
        accel: bool,
        point: &str,
        relative_to: Option<&str>,
        component: Component,
    ) -> Self {
        Self {
            quantity: if accel {
                Quantity::Acceleration
            } else {
                Quantity::Velocity
            },
            point: point.to_string(),
            relative_to: relative_to.map(str::to_string),
            component,
        }
    }

    /// The subscript: the point, then the one it is relative to (`CB`).
    pub fn subscript(&self) -> String {
        format!(
            "{}{}",
            self.point,
            self.relative_to.as_deref().unwrap_or("")
        )
    }

    /// The superscript letter of the component (`n`, `t`, `k`, `r`), if any.
    pub fn superscript(&self) -> Option<char> {
        match self.component {
            Component::Whole => None,
            Component::Normal => Some('n'),
            Component::Tangential => Some('t'),
            Component::Coriolis => Some('k'),
            Component::Sliding => Some('r'),
        }
    }

    /// The letter of the quantity (`v`, `a`).
    pub fn letter(&self) -> char {
        match self.quantity {
            Quantity::Velocity => 'v',
            Quantity::Acceleration => 'a',
        }
    }
}

impl fmt::Display for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}_{}", self.letter(), self.subscript())?;
        match self.superscript() {
            Some(c) => write!(f, "^{c}"),
            None => Ok(()),
        }
    }
}

/// In JSON a symbol is its ASCII text (`v_CB`), as scripts reading `linkage at` expect.
fn symbol_text<S: Serializer>(symbol: &Symbol, out: S) -> Result<S::Ok, S::Error> {
    out.collect_str(symbol)
}

/// One vector of a polygon equation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Term {
    /// Its symbol (in JSON as text: `v_CB`, `a_C^t`; `^k` Coriolis, `^r` sliding).
    #[serde(serialize_with = "symbol_text")]
    pub symbol: Symbol,
    /// The vector, m/s or m/s².
    pub vector: [f64; 2],
    /// Its length.
    pub magnitude: f64,
    /// Its direction, rad.
    pub direction_rad: f64,
    /// Magnitude known before the group is solved.
    pub magnitude_known: bool,
    /// Direction known before the group is solved.
    pub direction_known: bool,
    /// Its direction as the table states it (in JSON as English words: `perp CD`,
    /// `along guide`, `C to D`).
    #[serde(serialize_with = "direction_text")]
    pub direction: TermDirection,
}

/// The direction a polygon's table gives a term, as data: each edge words it in
/// its reader's language (the sheets and the app through their catalogues).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TermDirection {
    /// From point `from` towards point `to` (a normal acceleration).
    Towards {
        /// Where it starts.
        from: String,
        /// Where it points.
        to: String,
    },
    /// Perpendicular to the line through points `a` and `b`.
    Perpendicular {
        /// One point of the line.
        a: String,
        /// The other.
        b: String,
    },
    /// Known from the groups solved before (a point's motion).
    Known,
    /// Known: the motion of the point of link `guide` that lies at `point`.
    GuidePoint {
        /// The guide link's name.
        guide: String,
        /// The point it lies under.
        point: String,
    },
    /// The Coriolis term's: 2 ω of the guide × the relative velocity.
    Coriolis,
    /// Along the slider's guide.
    AlongGuide,
}

/// The English words: `C to D`, `perp CD`, `known`, `along guide`.
impl fmt::Display for TermDirection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Towards { from, to } => write!(f, "{from} to {to}"),
            Self::Perpendicular { a, b } => write!(f, "perp {a}{b}"),
            Self::Known => f.write_str("known"),
            Self::GuidePoint { guide, point } => write!(f, "known ({guide} point at {point})"),
            Self::Coriolis => f.write_str("Coriolis: 2 omega_guide x v_rel"),
            Self::AlongGuide => f.write_str("along guide"),
        }
    }
}

/// In JSON a direction is its English words, as scripts reading `linkage at` expect.
fn direction_text<S: Serializer>(d: &TermDirection, out: S) -> Result<S::Ok, S::Error> {
    out.collect_str(d)
}

/// One vector equation: sum of `lhs` = sum of `rhs`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct VectorEquation {
    /// Velocity or acceleration (in JSON `velocity`, `acceleration`).
    pub kind: Quantity,
    /// The group it solves.
    pub group: GroupLabel,
    /// The equation in symbols.
    pub equation: String,
    /// Left side terms.
    pub lhs: Vec<Term>,
    /// Right side terms.
    pub rhs: Vec<Term>,
}

impl VectorEquation {
    /// The largest magnitude among its terms: the scale its round-off is judged by.
    pub fn largest_term(&self) -> f64 {
        self.lhs
            .iter()
            .chain(&self.rhs)
            .map(|t| t.magnitude)
            .fold(0.0, f64::max)
    }

    /// |Σlhs − Σrhs|: zero up to round-off for a solved position.
    pub fn residual(&self) -> f64 {
        let sum = |t: &[Term]| {
            t.iter().fold(Vec2::zeros(), |acc, t| {
                acc + Vec2::new(t.vector[0], t.vector[1])
            })
        };
        (sum(&self.lhs) - sum(&self.rhs)).norm()
    }
}
