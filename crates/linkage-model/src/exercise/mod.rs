//! Exercises for a class: a teacher's exercise file ([`file`]) turns a scene or a cam
//! into one variant per student ([`variant`]: the varied dimensions drawn from the
//! student's number), with questions whose true values the analyses compute
//! ([`quantity`]); a student's answers travel as a short answer code ([`code`]) that
//! the teacher grades ([`grade`]). `docs/exercises.md` documents the file.

pub mod class_list;
pub mod code;
pub mod error;
pub mod file;
pub mod grade;
pub mod quantity;
pub mod sheet;
pub mod subject;
pub mod unit;
pub mod variant;
pub mod words;

#[cfg(test)]
mod tests;

pub use error::{DrawFailure, ExerciseError};
pub use file::{ExerciseFile, Mode, Question, Requirement, Tolerance, Values, Vary};
pub use quantity::Quantity;
pub use subject::SubjectData;
pub use unit::Unit;
pub use variant::{StudentId, Variant};

use quantity::{Unanswerable, truth_si};

/// An exercise read and checked: its file, its subject as the solver reads it, each
/// varied dimension's values, and its fingerprint (which an answer code carries, so
/// that a code made for another version of the file is told apart).
#[derive(Clone, Debug)]
pub struct Exercise {
    /// The file as written.
    pub file: ExerciseFile,
    /// The subject before any variation.
    pub subject: SubjectData,
    /// Per varied dimension: the first whole multiple, how many, the step.
    grids: Vec<(i64, i64, f64)>,
    /// FNV-1a (32 bits) of the file written out again.
    fingerprint: u32,
}

impl Exercise {
    /// Reads and checks an exercise file.
    ///
    /// # Errors
    /// A syntax error (line and column), an id, subject, varied dimension, unit,
    /// tolerance or question that is refused, named.
    pub fn parse(text: &str) -> Result<Self, ExerciseError> {
        let file: ExerciseFile = ron::from_str(text).map_err(|e| ExerciseError::Syntax {
            line: e.span.start.line,
            column: e.span.start.col,
            message: e.code.to_string(),
        })?;
        Self::new(file)
    }

    /// Checks an exercise.
    ///
    /// # Errors
    /// As [`Self::parse`], but for syntax.
    pub fn new(file: ExerciseFile) -> Result<Self, ExerciseError> {
        let id_fits = (1..=24).contains(&file.id.len())
            && file
                .id
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
        if !id_fits {
            return Err(ExerciseError::Id(file.id.clone()));
        }
        if file.questions.is_empty() {
            return Err(ExerciseError::NoQuestions);
        }
        let subject = SubjectData::of(&file.subject)?;
        let grids = file
            .vary
            .iter()
            .enumerate()
            .map(|(i, v)| subject::grid(v.values(), subject.value(v, i + 1)?, i + 1))
            .collect::<Result<Vec<_>, _>>()?;
        // Built once for both checks (a mechanism's report is made once, if asked).
        let mut built = subject.build().map_err(ExerciseError::Subject)?;
        check_questions(&file, &mut built)?;
        check_requirements(&file, &built)?;
        Ok(Self {
            grids,
            fingerprint: fingerprint(&file),
            file,
            subject,
        })
    }

    /// Its title in `lang`: the Chinese one where the file gives one.
    pub fn title(&self, lang: linkage_diagram::words::Lang) -> &str {
        match (&self.file.name_zh, lang) {
            (Some(zh), linkage_diagram::words::Lang::Chinese) => zh,
            _ => &self.file.name,
        }
    }

    /// Its fingerprint.
    pub fn fingerprint(&self) -> u32 {
        self.fingerprint
    }

    /// The unit of the varied dimension `vary` of this exercise's subject: the
    /// scene's length unit, rpm, mm, or degrees for an oscillating follower's lift.
    pub fn vary_unit(&self, vary: &Vary) -> &'static str {
        match (&self.subject, vary) {
            (SubjectData::Scene(scene), Vary::Length { .. }) => {
                linkage_diagram::numbers::unit_symbol(scene.length_unit)
            }
            (_, Vary::CrankRpm { .. }) => "rpm",
            (SubjectData::Cam(cam), Vary::Lift { .. })
                if matches!(cam.follower, linkage::cam::FollowerSpec::Oscillating { .. }) =>
            {
                "deg"
            }
            _ => "mm",
        }
    }

    /// The values the varied dimension number `index` (from 0) takes: the first,
    /// the last, the step and how many.
    pub fn value_range(&self, index: usize) -> Option<(f64, f64, f64, i64)> {
        let &(first, count, step) = self.grids.get(index)?;
        Some((
            first as f64 * step,
            (first + count - 1) as f64 * step,
            step,
            count,
        ))
    }
}

/// Each requirement applies to the subject: Grashof's classes to a mechanism with
/// a four-bar loop on its crank, a mechanism's to a mechanism, a cam's to a cam.
fn check_requirements(file: &ExerciseFile, built: &quantity::Built) -> Result<(), ExerciseError> {
    for (i, r) in file.require.iter().enumerate() {
        let why = match (r, built) {
            (Requirement::PressureAngleAtMostDeg(_), quantity::Built::Cam(_)) => None,
            (Requirement::PressureAngleAtMostDeg(_), _) => {
                Some("a cam's requirement: the subject is a mechanism")
            }
            (_, quantity::Built::Cam(_)) => Some("a mechanism's requirement: the subject is a cam"),
            (Requirement::Grashof(_), quantity::Built::Mechanism { kinematics, .. })
                if linkage::analysis::grashof(kinematics).is_none() =>
            {
                Some(
                    "Grashof's classes are a four-bar's: this mechanism has no four-bar loop on its crank",
                )
            }
            _ => None,
        };
        if let Some(why) = why {
            return Err(ExerciseError::Requirement { index: i + 1, why });
        }
    }
    Ok(())
}

/// Each question's unit measures its quantity, its tolerance and points are
/// positive, and it names only what the subject has (asked of the subject as
/// written: a pose where it does not assemble is left to the variants).
fn check_questions(file: &ExerciseFile, built: &mut quantity::Built) -> Result<(), ExerciseError> {
    for (i, q) in file.questions.iter().enumerate() {
        let question = i + 1;
        if q.unit.kind() != q.ask.kind() {
            return Err(ExerciseError::UnitKind {
                question,
                unit: q.unit,
                kind: q.ask.kind(),
            });
        }
        if let Some(deg) = q
            .ask
            .crank_deg()
            .filter(|d| !(d.is_finite() && d.abs() <= 360.0))
        {
            return Err(ExerciseError::CrankAngle { question, deg });
        }
        let positive = |x: f64| x.is_finite() && x > 0.0;
        let tolerance = match q.tolerance {
            Tolerance::Relative(r) | Tolerance::Absolute(r) => r,
        };
        if !(positive(tolerance) && positive(q.points)) {
            return Err(ExerciseError::Tolerance { question });
        }
        if let Err(
            why @ (Unanswerable::NoPoint { .. }
            | Unanswerable::NoLink { .. }
            | Unanswerable::Frame(_)
            | Unanswerable::NoOutput { .. }
            | Unanswerable::WrongSubject(_)),
        ) = truth_si(&q.ask, built)
        {
            return Err(ExerciseError::Question { question, why });
        }
    }
    Ok(())
}

/// Whether `text` is an exercise file (its first word, past comments, is
/// `Exercise`), so that a file opened or dropped goes to the exercise desk.
pub fn is_exercise_file(text: &str) -> bool {
    text.lines()
        .map(str::trim)
        .find(|l| !l.is_empty() && !l.starts_with("//"))
        .is_some_and(|l| l.starts_with("Exercise"))
}

/// The fingerprint of what an answer means: the subject, what varies, the
/// requirements, and each question's quantity and unit, written out again. The
/// title, the mode, the tolerances and the points are not in it: a teacher who
/// mends a title or widens a tolerance after the codes came in still grades them.
fn fingerprint(file: &ExerciseFile) -> u32 {
    let asked: Vec<(&Quantity, Unit)> = file.questions.iter().map(|q| (&q.ask, q.unit)).collect();
    let meaning = (&file.subject, &file.vary, &file.require, asked);
    fnv1a32(ron::to_string(&meaning).unwrap_or_default().as_bytes())
}

/// FNV-1a, 32 bits (written out: a fingerprint no crate's release may change).
pub(crate) fn fnv1a32(bytes: &[u8]) -> u32 {
    bytes.iter().fold(0x811c_9dc5_u32, |h, b| {
        (h ^ u32::from(*b)).wrapping_mul(0x0100_0193)
    })
}

impl Vary {
    /// The values it takes.
    pub fn values(&self) -> &Values {
        match self {
            Vary::Length { values, .. }
            | Vary::CrankRpm { values }
            | Vary::BaseRadius { values }
            | Vary::Lift { values }
            | Vary::Offset { values } => values,
        }
    }

    /// Its name as the student reads it (`AB`, `crank speed`, `base radius`, ...).
    pub fn label(&self) -> String {
        match self {
            Vary::Length { length, .. } => length.clone(),
            Vary::CrankRpm { .. } => "crank speed".into(),
            Vary::BaseRadius { .. } => "base radius".into(),
            Vary::Lift { .. } => "stroke h".into(),
            Vary::Offset { .. } => "offset".into(),
        }
    }
}
