//! Grading: each answer against its student's own variant's truth within the
//! question's tolerance; a class's answer codes read line by line, a line that is
//! not a valid code reported and the rest graded; the grades as a CSV a learning
//! platform imports.

use linkage_diagram::numbers::significant;

use super::Exercise;
use super::code::{AnswerSheet, CodeError};
use super::error::ExerciseError;
use super::variant::{StudentId, Variant};

/// One answer graded.
#[derive(Clone, Debug, PartialEq)]
pub struct Marked {
    /// The answer, in the question's unit (`None`: not answered).
    pub answer: Option<f64>,
    /// The truth, in the question's unit.
    pub truth: f64,
    /// Answer − truth (`None`: not answered).
    pub error: Option<f64>,
    /// Within the tolerance.
    pub right: bool,
}

/// One student's grade.
#[derive(Clone, Debug, PartialEq)]
pub struct Grade {
    /// The student.
    pub student: StudentId,
    /// Each question.
    pub marked: Vec<Marked>,
    /// Points for the right answers.
    pub score: f64,
    /// Points for all right.
    pub out_of: f64,
    /// On the class list but no code came.
    pub no_code: bool,
}

/// A line of the answers that was not graded.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LineError {
    /// Not a valid code.
    #[error("{0}")]
    Code(#[from] CodeError),
    /// A student not on the class list.
    #[error("student {0} is not on the class list")]
    NotOnList(StudentId),
    /// A second code from a student: the later one is graded.
    #[error("student {0} sent another code later, which is graded instead")]
    Superseded(StudentId),
    /// The student's variant could not be drawn.
    #[error("{0}")]
    Variant(ExerciseError),
}

/// A class graded.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ClassGrades {
    /// Every student's grade, in the class list's order (else the codes').
    pub grades: Vec<Grade>,
    /// The lines not graded, by line number from 1.
    pub problems: Vec<(usize, LineError)>,
}

impl Exercise {
    /// `sheet` graded against `variant` (the variant of the sheet's student).
    pub fn grade(&self, sheet: &AnswerSheet, variant: &Variant) -> Grade {
        let marked: Vec<Marked> = self
            .file
            .questions
            .iter()
            .zip(&variant.truths)
            .enumerate()
            .map(|(i, (q, &truth))| {
                let answer = sheet.answers.get(i).copied().flatten();
                Marked {
                    answer,
                    truth,
                    error: answer.map(|a| a - truth),
                    right: answer.is_some_and(|a| q.tolerance.accepts(a, truth)),
                }
            })
            .collect();
        let points = self.file.questions.iter().map(|q| q.points);
        let score = points
            .clone()
            .zip(&marked)
            .filter(|(_, m)| m.right)
            .map(|(p, _)| p)
            .sum();
        Grade {
            student: sheet.student.clone(),
            marked,
            score,
            out_of: points.sum(),
            no_code: false,
        }
    }

    /// Grades the codes in `text` (one a line, or a CSV with a column of them; a
    /// first line with no code is taken for a header). With a class list, a code
    /// from a student not on it is reported and every listed student without one
    /// gets a grade of nothing answered.
    pub fn grade_class(&self, text: &str, class: Option<&[StudentId]>) -> ClassGrades {
        let mut out = ClassGrades::default();
        let mut sheets: Vec<(usize, AnswerSheet)> = Vec::new();
        for (n, line) in text.lines().enumerate().map(|(i, l)| (i + 1, l)) {
            if line.trim().is_empty() {
                continue;
            }
            match self.read_code(line) {
                Err(CodeError::NotACode) if n == 1 => {}
                Err(e) => out.problems.push((n, e.into())),
                Ok(sheet) if class.is_some_and(|c| !c.contains(&sheet.student)) => {
                    out.problems.push((n, LineError::NotOnList(sheet.student)));
                }
                Ok(sheet) => {
                    if let Some(i) = sheets.iter().position(|(_, s)| s.student == sheet.student) {
                        let (earlier, _) = sheets.remove(i);
                        out.problems
                            .push((earlier, LineError::Superseded(sheet.student.clone())));
                    }
                    sheets.push((n, sheet));
                }
            }
        }
        let order: Vec<StudentId> = match class {
            Some(c) => c.to_vec(),
            None => sheets.iter().map(|(_, s)| s.student.clone()).collect(),
        };
        for student in order {
            let found = sheets.iter().find(|(_, s)| s.student == student);
            let none = AnswerSheet {
                student: student.clone(),
                answers: Vec::new(),
            };
            let (line, sheet) = found.map_or((0, &none), |(n, s)| (*n, s));
            match self.variant(&student) {
                Ok(v) => out.grades.push(Grade {
                    no_code: found.is_none(),
                    ..self.grade(sheet, &v)
                }),
                Err(e) => out.problems.push((line, LineError::Variant(e))),
            }
        }
        out.problems.sort_by_key(|(n, _)| *n);
        out
    }

    /// The grades as CSV: the student, each question's answer, truth, error and
    /// right (1 or 0), the score, the points possible and a note.
    pub fn grades_csv(&self, grades: &[Grade]) -> String {
        let mut w = csv::Writer::from_writer(Vec::new());
        let mut header = vec!["student".to_string()];
        for (i, q) in self.file.questions.iter().enumerate() {
            let unit = if q.unit.symbol().is_empty() {
                String::new()
            } else {
                format!(" ({})", q.unit)
            };
            for what in ["answer", "truth", "error"] {
                header.push(format!("q{} {what}{unit}", i + 1));
            }
            header.push(format!("q{} right", i + 1));
        }
        header.extend(["score", "out of", "note"].map(String::from));
        let _ = w.write_record(&header);
        let number = |v: Option<f64>| v.map_or_else(String::new, |v| significant(v, 6));
        for g in grades {
            let mut row = vec![g.student.to_string()];
            for m in &g.marked {
                row.push(number(m.answer));
                row.push(number(Some(m.truth)));
                row.push(number(m.error));
                row.push(if m.right { "1" } else { "0" }.into());
            }
            row.push(significant(g.score, 6));
            row.push(significant(g.out_of, 6));
            row.push(if g.no_code { "no code" } else { "" }.into());
            let _ = w.write_record(&row);
        }
        String::from_utf8(w.into_inner().unwrap_or_default()).unwrap_or_default()
    }
}
