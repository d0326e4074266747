//! A student's variant: drawn from the exercise and the student's number alone, so
//! that the same number gives the same mechanism on every machine and in the
//! browser; drawn again until the requirements hold and every question has a value.

use linkage::analysis::{GrashofClass, grashof};
use linkage::rng::SplitMix;

use super::Exercise;
use super::error::{DrawFailure, ExerciseError};
use super::file::{FourBarClass, Requirement};
use super::quantity::{Built, Unanswerable, truth_si};
use super::subject::SubjectData;

/// The most variants drawn for one student before the exercise is refused.
pub const MOST_DRAWS: u32 = 500;

/// A student's number: 1 to 32 letters, digits, `-` or `_` (a school's numbers may
/// hold letters); kept as typed, so `007` and `7` are two students.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct StudentId(String);

/// A student's number that is not one.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("student number \"{0}\": 1 to 32 letters, digits, '-' or '_'")]
pub struct BadStudentId(pub String);

impl StudentId {
    /// The number typed, without the spaces around it.
    ///
    /// # Errors
    /// Empty, longer than 32 characters, or with another character.
    pub fn parse(text: &str) -> Result<Self, BadStudentId> {
        let text = text.trim();
        let fits = (1..=32).contains(&text.len())
            && text
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
        if fits {
            Ok(Self(text.to_string()))
        } else {
            Err(BadStudentId(text.to_string()))
        }
    }

    /// As typed.
    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl std::fmt::Display for StudentId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// One student's variant.
#[derive(Clone, Debug, PartialEq)]
pub struct Variant {
    /// The student.
    pub student: StudentId,
    /// Each varied dimension's value, in its own unit, in the file's order.
    pub values: Vec<f64>,
    /// Each question's true value, in the question's unit.
    pub truths: Vec<f64>,
    /// How many variants were drawn to find this one.
    pub draws: u32,
    /// The subject with the values written in.
    pub subject: SubjectData,
}

/// FNV-1a, 64 bits: the student's seed from the exercise's id and the number
/// (written out: a hash whose value no release of a crate may change). Not from the
/// whole file: a title mended after the variants went out changes none of them;
/// changed ranges give each student other values from the same draws.
fn seed(id: &str, student: &StudentId) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in id
        .as_bytes()
        .iter()
        .chain(b":")
        .chain(student.as_str().as_bytes())
    {
        h ^= u64::from(*b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

impl Exercise {
    /// The variant of `student`.
    ///
    /// # Errors
    /// No variant meets the requirements and answers every question within
    /// [`MOST_DRAWS`] draws (one draw where nothing varies): the failure seen most.
    pub fn variant(&self, student: &StudentId) -> Result<Variant, ExerciseError> {
        let mut rng = SplitMix::new(seed(&self.file.id, student));
        let most = if self.file.vary.is_empty() {
            1
        } else {
            MOST_DRAWS
        };
        let mut failures: Vec<(DrawFailure, u32)> = Vec::new();
        for draw in 1..=most {
            let values: Vec<f64> = self
                .grids
                .iter()
                .map(|&(first, count, step)| {
                    let i = rng.below(count as usize) as i64;
                    (first + i) as f64 * step
                })
                .collect();
            match self.try_variant(&values) {
                Ok((subject, truths)) => {
                    return Ok(Variant {
                        student: student.clone(),
                        values,
                        truths,
                        draws: draw,
                        subject,
                    });
                }
                Err(f) => match failures.iter_mut().find(|(seen, _)| same_cause(seen, &f)) {
                    Some((_, n)) => *n += 1,
                    None => failures.push((f, 1)),
                },
            }
        }
        let (cause, times) = failures
            .into_iter()
            .max_by_key(|(_, n)| *n)
            .expect("a draw failed");
        Err(ExerciseError::NoVariant {
            student: student.to_string(),
            draws: most,
            cause,
            times,
        })
    }

    /// The subject with `values` written in, and every question's truth, or why not.
    fn try_variant(&self, values: &[f64]) -> Result<(SubjectData, Vec<f64>), DrawFailure> {
        let mut subject = self.subject.clone();
        for (i, (vary, &v)) in self.file.vary.iter().zip(values).enumerate() {
            subject
                .set(vary, i + 1, v)
                .map_err(|e| DrawFailure::Subject(e.to_string()))?;
        }
        let mut built = subject.build().map_err(DrawFailure::Subject)?;
        for r in &self.file.require {
            check(*r, &mut built)?;
        }
        if passes_a_change_point(&mut built)? {
            return Err(DrawFailure::ChangePoint);
        }
        let truths = self.file.questions.iter().enumerate().map(|(i, q)| {
            truth_si(&q.ask, &mut built)
                .map(|si| q.unit.from_si(si))
                .map_err(|why| DrawFailure::Question {
                    question: i + 1,
                    why,
                })
        });
        Ok((subject, truths.collect::<Result<_, _>>()?))
    }
}

/// Two failures of one cause (the numbers measured aside).
fn same_cause(a: &DrawFailure, b: &DrawFailure) -> bool {
    match (a, b) {
        (
            DrawFailure::Requirement { requirement: x, .. },
            DrawFailure::Requirement { requirement: y, .. },
        ) => x == y,
        (DrawFailure::Question { question: x, .. }, DrawFailure::Question { question: y, .. }) => {
            x == y
        }
        (DrawFailure::Subject(_), DrawFailure::Subject(_))
        | (DrawFailure::ChangePoint, DrawFailure::ChangePoint) => true,
        _ => false,
    }
}

/// Whether a mechanism whose crank turns fully folds flat somewhere in the turn (a
/// branch point: a change-point four-bar, a slider-crank with its rod as long as its
/// crank), where its assembly can switch and strokes and speeds are not what a
/// student works out. A cam never does.
fn passes_a_change_point(built: &mut Built) -> Result<bool, DrawFailure> {
    if matches!(built, Built::Cam(_)) {
        return Ok(false);
    }
    let report = built
        .report()
        .map_err(|why| DrawFailure::Subject(why.to_string()))?;
    Ok(report.full_rotation && !report.branch_points.is_empty())
}

/// Whether `built` meets `r`.
fn check(r: Requirement, built: &mut Built) -> Result<(), DrawFailure> {
    let fail = |measured| DrawFailure::Requirement {
        requirement: r,
        measured,
    };
    let unanswered = |why: Unanswerable| DrawFailure::Subject(why.to_string());
    match r {
        Requirement::Grashof(class) => {
            let Built::Mechanism { kinematics, .. } = built else {
                return Err(fail(None));
            };
            let found = grashof(kinematics).map(|g| g.class);
            if found.is_some_and(|c| is_class(c, class)) {
                Ok(())
            } else {
                Err(fail(None))
            }
        }
        Requirement::FullRotation => {
            if built.report().map_err(unanswered)?.full_rotation {
                Ok(())
            } else {
                Err(fail(None))
            }
        }
        Requirement::LeastTransmissionAngleDeg(least) => {
            let report = built.report().map_err(unanswered)?;
            let min = report
                .transmission_angle_rad
                .as_ref()
                .map(|t| t.min.to_degrees());
            if min.is_some_and(|m| m >= least) {
                Ok(())
            } else {
                Err(fail(min))
            }
        }
        Requirement::TimeRatioAtLeast(least) => {
            let k = built.report().map_err(unanswered)?.time_ratio;
            if k.is_some_and(|k| k >= least) {
                Ok(())
            } else {
                Err(fail(k))
            }
        }
        Requirement::PressureAngleAtMostDeg(most) => {
            let q = super::quantity::Quantity::LargestPressureAngle;
            let largest = truth_si(&q, built).map_err(unanswered)?.to_degrees();
            if largest <= most {
                Ok(())
            } else {
                Err(fail(Some(largest)))
            }
        }
    }
}

fn is_class(found: GrashofClass, wanted: FourBarClass) -> bool {
    matches!(
        (found, wanted),
        (GrashofClass::CrankRocker, FourBarClass::CrankRocker)
            | (GrashofClass::DoubleCrank, FourBarClass::DoubleCrank)
            | (GrashofClass::DoubleRocker, FourBarClass::DoubleRocker)
            | (GrashofClass::TripleRocker, FourBarClass::TripleRocker)
    )
}
