//! What the last edit could not do, kept as data and put into words only when shown.

use std::fmt;

use linkage::LinkageError;
use linkage::error::Valid;
use linkage::scene::LengthUnit;
use linkage_diagram::words::Lang;

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
        /// What it is.
        what: ValueKind,
        /// The value asked for.
        value: f64,
        /// What it must be.
        valid: Valid,
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
        /// The edit.
        what: EditSubject,
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

/// A value a notice refuses, by what it sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ValueKind {
    /// A spring's constant, N/m.
    SpringConstant,
    /// A link's mass, kg.
    Mass,
    /// A cam segment's lift, in the scene's length unit.
    CamLift,
    /// The crank's angle, deg.
    InputAngle,
}

/// An edit a notice says could not be made, by what it changed.
#[derive(Clone, Debug, PartialEq)]
pub enum EditSubject {
    /// A spring's constant, the spring by its two points.
    SpringConstant {
        /// Its points.
        ends: [String; 2],
    },
    /// A link's mass.
    Mass {
        /// The link.
        link: String,
    },
    /// The assembly branch flipped at a point.
    Branch {
        /// The point.
        point: String,
    },
    /// A cam joint's program or roller.
    Cam {
        /// The cam's link.
        cam: String,
        /// The follower's link.
        follower: String,
    },
    /// A synthesised design put in place of the scene.
    Design,
    /// The scene put back as opened.
    Reset,
}

/// The notice in English, lengths in metres (the command line's and the tests'
/// words; the app words it in the user's language and unit).
impl fmt::Display for Notice {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.words(LengthUnit::Metre, Lang::English))
    }
}

impl fmt::Display for PointRefusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.words(LengthUnit::Metre, Lang::English))
    }
}
