//! The exercise file a teacher writes (RON, `docs/exercises.md`): what the exercise
//! is about, which of its dimensions vary from student to student and within what,
//! the conditions every student's variant must meet, and the questions with their
//! units and tolerances.

use linkage::SceneFile;
use linkage::cam::CamSpec;
use serde::{Deserialize, Serialize};

use super::quantity::Quantity;
use super::unit::Unit;

/// A whole exercise file (written `Exercise( ... )`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Exercise", deny_unknown_fields)]
pub struct ExerciseFile {
    /// Its title, shown to the students.
    pub name: String,
    /// Its title in Chinese (简体中文), shown where the app or the sheet speaks
    /// Chinese; the title above where there is none.
    #[serde(default)]
    pub name_zh: Option<String>,
    /// A short tag (letters, digits, `-`, `_`) carried in every answer code, so that
    /// a code for another exercise is told apart.
    pub id: String,
    /// Whether a student sees at once whether an answer is right.
    pub mode: Mode,
    /// The mechanism or cam the questions are about.
    pub subject: Subject,
    /// The dimensions that differ from student to student.
    #[serde(default)]
    pub vary: Vec<Vary>,
    /// What every variant must meet; a variant that does not is drawn again.
    #[serde(default)]
    pub require: Vec<Requirement>,
    /// The questions, in the order the student answers them.
    pub questions: Vec<Question>,
}

/// Homework (each answer marked at once) or a test (marked only when graded).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Mode {
    /// Each answer is marked right or wrong as soon as it is typed, with the
    /// tolerance shown.
    Homework,
    /// Answers are marked only by the teacher's grading.
    Test,
}

/// What the questions are about.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Subject {
    /// A shipped scene, by its key (`die_cutter`, `slider_crank`, ...).
    Scene(String),
    /// A shipped template, by its key (`four_bar`, `slider_crank`, ...).
    Template(String),
    /// A scene written out in the exercise file.
    SceneFile(Box<SceneFile>),
    /// A disc cam written out in the exercise file (as a cam file's `Cam( ... )`).
    Cam(Box<CamSpec>),
}

/// One dimension that differs from student to student.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Vary {
    /// A pin-to-pin length of a link, named as the app's sliders name it (`AB`, or
    /// `O2-O4` for longer point names), in the scene's length unit.
    Length {
        /// The length's name.
        length: String,
        /// The values it takes.
        values: Values,
    },
    /// The crank's speed, rpm.
    CrankRpm {
        /// The values it takes.
        values: Values,
    },
    /// A cam's base circle radius, mm.
    BaseRadius {
        /// The values it takes.
        values: Values,
    },
    /// A cam follower's stroke h, mm (degrees for an oscillating follower): every
    /// rise's and return's lift, which must be one in the cam as written (so that
    /// the varied program still closes).
    Lift {
        /// The values it takes.
        values: Values,
    },
    /// A translating follower's offset, mm.
    Offset {
        /// The values it takes.
        values: Values,
    },
}

/// The values a varied dimension takes: whole multiples of `step` within the range,
/// each as likely. Whole multiples keep the numbers a student reads round and make a
/// variant the same on every machine (no arithmetic but a product of integers and
/// the step).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Values {
    /// From `min` to `max`, in steps of `step`.
    Range {
        /// The least value.
        min: f64,
        /// The greatest value.
        max: f64,
        /// The spacing of the values.
        step: f64,
    },
    /// Within `spread` (a fraction, 0.1 = ±10 %) of the subject's own value, in
    /// steps of `step`.
    Around {
        /// The relative spread.
        spread: f64,
        /// The spacing of the values.
        step: f64,
    },
}

/// A condition every variant must meet.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Requirement {
    /// A four-bar of this Grashof class.
    Grashof(FourBarClass),
    /// The crank turns fully.
    FullRotation,
    /// The least transmission angle over the cycle is at least this many degrees.
    LeastTransmissionAngleDeg(f64),
    /// The time ratio K is at least this.
    TimeRatioAtLeast(f64),
    /// A cam's largest pressure angle stays within this many degrees.
    PressureAngleAtMostDeg(f64),
}

/// The Grashof classes a requirement can name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum FourBarClass {
    /// The input turns fully, the output rocks.
    CrankRocker,
    /// Both side links turn fully.
    DoubleCrank,
    /// Grashof, both side links rock.
    DoubleRocker,
    /// Not Grashof: no link turns fully.
    TripleRocker,
}

/// One question: a quantity the analyses compute, asked in a unit, graded within a
/// tolerance.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Question {
    /// What is asked.
    pub ask: Quantity,
    /// The unit the answer is given in.
    pub unit: Unit,
    /// How far from the truth an answer may be and still be right.
    pub tolerance: Tolerance,
    /// Points for a right answer.
    #[serde(default = "one_point")]
    pub points: f64,
}

fn one_point() -> f64 {
    1.0
}

/// How far from the truth an answer may be: relative (graphical answers carry a
/// drawing error of a few per cent) or absolute in the question's unit (for a
/// quantity that may be near zero).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Tolerance {
    /// |answer − truth| ≤ this fraction of |truth|.
    Relative(f64),
    /// |answer − truth| ≤ this, in the question's unit.
    Absolute(f64),
}

impl Tolerance {
    /// Whether `answer` is right for `truth` (both in the question's unit).
    pub fn accepts(self, answer: f64, truth: f64) -> bool {
        let error = (answer - truth).abs();
        match self {
            Tolerance::Relative(r) => error <= r * truth.abs(),
            Tolerance::Absolute(a) => error <= a,
        }
    }
}
