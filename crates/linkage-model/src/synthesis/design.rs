//! A synthesis tab's design as the app shows it: its table (quantity, value in
//! words), its figure and the scene it opens as; and the small helpers every tab's
//! table is written with. A leaf of the synthesis modules.

use linkage::scene::LengthUnit;
use linkage::synthesis::positions::PositionsError;
use linkage::synthesis::rows::RowError;
use linkage::{LinkageError, SceneFile};
use linkage_diagram::refusal;
use linkage_diagram::words::Lang;
use thiserror::Error;

use crate::session::words::mw;

/// Why a tab has no design, as data; the window words it.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum SynthError {
    /// The solver's synthesis refused the requirements.
    #[error(transparent)]
    Solver(#[from] LinkageError),
    /// Typed rows that are not numbers.
    #[error(transparent)]
    Rows(#[from] RowError),
    /// Positions no four-bar is designed through.
    #[error(transparent)]
    Positions(#[from] PositionsError),
    /// A function generator's specification the points cannot be placed for.
    #[error(transparent)]
    Function(#[from] FunctionSpecError),
    /// The path tab designs by its search, not at once.
    #[error("a path design comes from its search: press Search")]
    PathIsSearched,
    /// The design chosen does not open as a scene.
    #[error("the design does not solve: {0}")]
    DoesNotSolve(LinkageError),
}

/// Why a function generator's precision points cannot be placed.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum FunctionSpecError {
    /// Not 3 to 10 points.
    #[error("{0} precision points: 3 to 10")]
    PointCount(usize),
    /// An empty or infinite range of x.
    #[error("x from {0} to {1}: the range must be finite and not empty")]
    EmptyRange(f64, f64),
    /// A crank or rocker that does not turn.
    #[error("a crank or rocker span of 0°: it must turn")]
    NoSpan,
    /// The function is not finite somewhere over the range.
    #[error("{function} is not defined over x from {x0} to {x1}")]
    Undefined {
        /// The function, as the tab names it.
        function: String,
        /// The range's start.
        x0: f64,
        /// The range's end.
        x1: f64,
    },
    /// The function is equal at both ends: no rise to map.
    #[error("{0} is equal at both ends of the range")]
    EqualEnds(String),
}

impl SynthError {
    /// Why the tab has no design, in `lang`.
    pub fn words(&self, lang: Lang) -> String {
        match self {
            Self::Solver(e) => refusal::error(lang, e, LengthUnit::Metre),
            Self::Rows(e) => refusal::rows(lang, e),
            Self::Positions(e) => refusal::positions(lang, e),
            Self::Function(e) => e.words(lang),
            Self::PathIsSearched => mw!(lang, "synthesis.path_is_searched"),
            Self::DoesNotSolve(e) => mw!(
                lang,
                "synthesis.does_not_solve",
                why = refusal::error(lang, e, LengthUnit::Metre)
            ),
        }
    }
}

impl FunctionSpecError {
    /// Why a function generator's inputs give no design, in `lang`.
    pub fn words(&self, lang: Lang) -> String {
        match self {
            Self::PointCount(n) => mw!(lang, "synthesis.point_count", count = n),
            Self::EmptyRange(x0, x1) => mw!(lang, "synthesis.empty_range", x0 = x0, x1 = x1),
            Self::NoSpan => mw!(lang, "synthesis.no_span"),
            Self::Undefined { function, x0, x1 } => mw!(
                lang,
                "synthesis.undefined",
                function = function,
                x0 = x0,
                x1 = x1
            ),
            Self::EqualEnds(function) => {
                mw!(lang, "synthesis.equal_ends", function = function)
            }
        }
    }
}

/// A design: its table (quantity, value in words) and its scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Design {
    /// What the design is, row by row.
    pub table: Vec<(String, String)>,
    /// What to draw beside the table.
    pub figure: Figure,
    /// The scene it opens as.
    pub scene: SceneFile,
}

/// A figure of a design.
#[derive(Clone, Debug, PartialEq)]
pub enum Figure {
    /// None.
    None,
    /// A function generator's structural error: `[crank deg, error deg]`.
    ErrorCurve(Vec<[f64; 2]>),
    /// A motion generator's construction.
    Construction(Construction),
}

/// A motion generator's construction, mm.
#[derive(Clone, Debug, PartialEq)]
pub struct Construction {
    /// Each position: the body's reference point and its angle, rad.
    pub positions: Vec<([f64; 2], f64)>,
    /// The poles of the pairs of positions that turn.
    pub poles: Vec<[f64; 2]>,
    /// Segments of the centre-point curve(s).
    pub curve: Vec<[[f64; 2]; 2]>,
    /// The Burmester points (five positions).
    pub burmester: Vec<[f64; 2]>,
    /// The fixed pivots.
    pub fixed: [[f64; 2]; 2],
    /// The moving pivots in the first position.
    pub moving: [[f64; 2]; 2],
}

/// A length in m as the tables write it: mm to 1 µm.
pub(crate) fn mm(m: f64) -> String {
    format!("{:.3} mm", m * 1e3)
}

/// An angle in rad as the tables write it: degrees to 0.001°.
pub(crate) fn deg(rad: f64) -> String {
    format!("{:.3}°", rad.to_degrees())
}

/// One row of a table: the quantity and its value in words.
pub(crate) fn row(what: &str, value: String) -> (String, String) {
    (what.to_owned(), value)
}
