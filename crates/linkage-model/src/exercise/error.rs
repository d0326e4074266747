//! Why an exercise file, a student's number or a class's variants were refused, as
//! data; worded by `Display` for the command line.

use super::file::Requirement;
use super::quantity::Unanswerable;
use super::unit::{Kind, Unit};

/// What is wrong with an exercise file, or why no variant could be drawn.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ExerciseError {
    /// The file is not an exercise file.
    #[error("line {line}, column {column}: {message}")]
    Syntax {
        /// Line, from 1.
        line: usize,
        /// Column, from 1.
        column: usize,
        /// What the parser expected.
        message: String,
    },
    /// The id is empty, too long or has other characters than letters, digits, `-`
    /// and `_`.
    #[error("id \"{0}\": 1 to 24 letters, digits, '-' or '_'")]
    Id(String),
    /// No questions.
    #[error("the exercise asks no questions")]
    NoQuestions,
    /// A shipped scene or template that does not exist.
    #[error("there is no shipped {folder} \"{key}\" (one of {})", known.join(", "))]
    UnknownSubject {
        /// "scene" or "template".
        folder: &'static str,
        /// The key given.
        key: String,
        /// The keys there are.
        known: Vec<String>,
    },
    /// The subject itself is refused by the solver.
    #[error("the subject is refused: {0}")]
    Subject(String),
    /// A varied length the scene does not have.
    #[error("vary {index}: there is no length \"{length}\" (the lengths: {})", known.join(", "))]
    UnknownLength {
        /// Which vary entry, from 1.
        index: usize,
        /// The name given.
        length: String,
        /// The lengths there are.
        known: Vec<String>,
    },
    /// A dimension that the subject does not have (a cam's for a mechanism, or the
    /// other way round; a cam segment with no lift; an offset of an oscillating
    /// follower).
    #[error("vary {index}: the subject has no such dimension ({why})")]
    NoDimension {
        /// Which vary entry, from 1.
        index: usize,
        /// What is missing.
        why: &'static str,
    },
    /// A range that holds no value, or a step or spread that is not positive.
    #[error("vary {index}: {why}")]
    Values {
        /// Which vary entry, from 1.
        index: usize,
        /// What is wrong.
        why: &'static str,
    },
    /// A question's unit measures something else than the quantity.
    #[error("question {question}: unit \"{unit}\" does not measure {} (give one of {})", kind.words(), units_of(*kind))]
    UnitKind {
        /// Which question, from 1.
        question: usize,
        /// The unit given.
        unit: Unit,
        /// What the quantity measures.
        kind: Kind,
    },
    /// A crank angle that is not finite or lies outside one turn either way.
    #[error("question {question}: crank angle {deg} deg: give one within -360 to 360 deg")]
    CrankAngle {
        /// Which question, from 1.
        question: usize,
        /// The angle given, degrees.
        deg: f64,
    },
    /// A requirement the subject cannot be held to (Grashof's classes of a
    /// mechanism with no four-bar loop on its crank, a cam's pressure angle of a
    /// mechanism, or the other way round).
    #[error("require {index}: {why}")]
    Requirement {
        /// Which requirement, from 1.
        index: usize,
        /// Why it does not apply.
        why: &'static str,
    },
    /// A tolerance that is not finite and positive, or points that are not.
    #[error("question {question}: the tolerance and the points must be finite and positive")]
    Tolerance {
        /// Which question, from 1.
        question: usize,
    },
    /// A question that names what the subject does not have.
    #[error("question {question}: {why}")]
    Question {
        /// Which question, from 1.
        question: usize,
        /// Why it has no value.
        why: Unanswerable,
    },
    /// No variant met the requirements within the draws allowed.
    #[error("no variant for student {student} in {draws} draws: {cause} ({times} of the draws)")]
    NoVariant {
        /// The student.
        student: String,
        /// How many variants were drawn.
        draws: u32,
        /// What failed most often.
        cause: DrawFailure,
        /// How often it failed.
        times: u32,
    },
}

/// Why one drawn variant was not taken.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DrawFailure {
    /// The solver refused the varied subject.
    #[error("the varied subject is refused: {0}")]
    Subject(String),
    /// A requirement is not met (`measured`: the value it was held against, in the
    /// requirement's own unit, where there is one).
    #[error("{} is not met{}", requirement_words(.requirement), measured_words(*.measured))]
    Requirement {
        /// The requirement.
        requirement: Requirement,
        /// What the variant has.
        measured: Option<f64>,
    },
    /// The variant folds flat somewhere in its turn.
    #[error(
        "the variant folds flat somewhere in its turn (a change point, where its assembly can switch and its answers are not defined)"
    )]
    ChangePoint,
    /// A question has no value on the variant.
    #[error("question {question}: {why}")]
    Question {
        /// Which question, from 1.
        question: usize,
        /// Why.
        why: Unanswerable,
    },
}

/// The units of `kind`, quoted, for a refusal.
fn units_of(kind: Kind) -> String {
    let units: Vec<String> = super::unit::UNITS
        .iter()
        .filter(|u| u.kind() == kind)
        .map(|u| format!("\"{}\"", u.symbol()))
        .collect();
    units.join(", ")
}

/// A requirement in words (`least transmission angle >= 30 deg`).
pub fn requirement_words(r: &Requirement) -> String {
    match r {
        Requirement::Grashof(class) => format!("Grashof class {class:?}"),
        Requirement::FullRotation => "the crank's full rotation".into(),
        Requirement::LeastTransmissionAngleDeg(d) => format!("least transmission angle >= {d} deg"),
        Requirement::TimeRatioAtLeast(k) => format!("time ratio K >= {k}"),
        Requirement::PressureAngleAtMostDeg(d) => format!("largest pressure angle <= {d} deg"),
    }
}

fn measured_words(measured: Option<f64>) -> String {
    measured.map_or_else(String::new, |v| format!(" (a variant had {v:.4})"))
}
