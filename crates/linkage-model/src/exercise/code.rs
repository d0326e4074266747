//! The answer code: a line of text that a student pastes into an e-mail or a
//! learning platform, holding the exercise's id and fingerprint, the student's
//! number and the answers, with a CRC-32 against accidental edits:
//!
//! `LX1:die-slider:1A2B3C4D:2023105:1.52/-0.87//12.5:9F3A21C0`
//!
//! The answers are in the questions' units, in the file's order, an empty field for a
//! question not answered; decimals as Rust writes an `f64` (shortest that reads back
//! the same), so that a code read back gives the very numbers typed.

use super::Exercise;
use super::unit::Unit;
use super::variant::{BadStudentId, StudentId};

/// What every answer code starts with (the format's version).
pub const PREFIX: &str = "LX1";

/// A student's answers to one exercise.
#[derive(Clone, Debug, PartialEq)]
pub struct AnswerSheet {
    /// The student.
    pub student: StudentId,
    /// Per question, in its unit (`None`: not answered).
    pub answers: Vec<Option<f64>>,
}

/// Why a line is not a valid answer code for this exercise.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CodeError {
    /// No answer code in the line.
    #[error("no answer code (it starts with {PREFIX}:)")]
    NotACode,
    /// The checksum does not match: the code was changed or cut.
    #[error("the code is damaged (its checksum does not match): copy it again whole")]
    Damaged,
    /// A code for another exercise.
    #[error("the code is for exercise \"{0}\"")]
    OtherExercise(String),
    /// A code for another version of this exercise's file.
    #[error("the code is for another version of this exercise's file")]
    OtherVersion,
    /// The student's number is not one.
    #[error("{0}")]
    Student(#[from] BadStudentId),
    /// Not as many answers as questions.
    #[error("the code holds {found} answers, the exercise asks {expected} questions")]
    AnswerCount {
        /// Answers in the code.
        found: usize,
        /// Questions asked.
        expected: usize,
    },
    /// An answer that is not a finite number.
    #[error("answer {question} \"{text}\" is not a number")]
    Answer {
        /// Which question, from 1.
        question: usize,
        /// The text.
        text: String,
    },
}

impl Exercise {
    /// The answer code of `sheet`.
    pub fn answer_code(&self, sheet: &AnswerSheet) -> String {
        let answers: Vec<String> = sheet
            .answers
            .iter()
            .map(|a| a.map_or_else(String::new, |v| format!("{v}")))
            .collect();
        let body = format!(
            "{PREFIX}:{}:{:08X}:{}:{}",
            self.file.id,
            self.fingerprint(),
            sheet.student,
            answers.join("/")
        );
        let crc = crc32fast::hash(body.as_bytes());
        format!("{body}:{crc:08X}")
    }

    /// The answers in the code found in `line` (the code may stand among other text,
    /// as in a CSV row or an e-mail).
    ///
    /// # Errors
    /// No code, a damaged one, one for another exercise or version of it, a bad
    /// student number, answers missing or not numbers.
    pub fn read_code(&self, line: &str) -> Result<AnswerSheet, CodeError> {
        let start = line
            .find(&format!("{PREFIX}:"))
            .ok_or(CodeError::NotACode)?;
        let code: &str = line[start..]
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';' || c == '"')
            .next()
            .unwrap_or_default();
        let (body, crc) = code.rsplit_once(':').ok_or(CodeError::Damaged)?;
        let crc = u32::from_str_radix(crc, 16).map_err(|_| CodeError::Damaged)?;
        if crc32fast::hash(body.as_bytes()) != crc {
            return Err(CodeError::Damaged);
        }
        let fields: Vec<&str> = body.split(':').collect();
        let [_, id, fingerprint, student, answers] = fields[..] else {
            return Err(CodeError::Damaged);
        };
        if id != self.file.id {
            return Err(CodeError::OtherExercise(id.to_string()));
        }
        if u32::from_str_radix(fingerprint, 16) != Ok(self.fingerprint()) {
            return Err(CodeError::OtherVersion);
        }
        let student = StudentId::parse(student)?;
        let answers = read_answers(answers, self.file.questions.len())?;
        Ok(AnswerSheet { student, answers })
    }
}

fn read_answers(text: &str, expected: usize) -> Result<Vec<Option<f64>>, CodeError> {
    let fields: Vec<&str> = text.split('/').collect();
    if fields.len() != expected {
        return Err(CodeError::AnswerCount {
            found: fields.len(),
            expected,
        });
    }
    fields
        .iter()
        .enumerate()
        .map(|(i, f)| match f.trim() {
            "" => Ok(None),
            t => t
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .map(Some)
                .ok_or_else(|| CodeError::Answer {
                    question: i + 1,
                    text: t.to_string(),
                }),
        })
        .collect()
}

/// Why a typed answer was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TypedAnswerError {
    /// No number.
    #[error("\"{0}\" is not a number")]
    NotANumber(String),
    /// A unit that is not known or measures something else.
    #[error("\"{typed}\" is not a unit of this answer: give it in {expected}")]
    Unit {
        /// The unit typed.
        typed: String,
        /// The question's unit.
        expected: Unit,
    },
}

/// A typed answer (`1.25`, `1250 mm/s`, `1,25 m/s`) in the question's unit `unit`:
/// a number, then a unit of the same kind (converted) or none (the question's).
///
/// # Errors
/// No finite number, or a unit unknown or of another kind (with the unit expected).
pub fn typed_answer(text: &str, unit: Unit) -> Result<f64, TypedAnswerError> {
    let text = text.trim();
    let split = text
        .char_indices()
        .find(|&(i, c)| !(c.is_ascii_digit() || "+-.,eE".contains(c)) || (i > 0 && c == ' '))
        .map_or(text.len(), |(i, _)| i);
    let (number, symbol) = text.split_at(split);
    // A decimal comma (as typed in much of Europe) where there is no point.
    let number = if number.contains('.') {
        number.to_string()
    } else {
        number.replace(',', ".")
    };
    let value: f64 = number
        .trim()
        .parse()
        .ok()
        .filter(|v: &f64| v.is_finite())
        .ok_or_else(|| TypedAnswerError::NotANumber(text.to_string()))?;
    let symbol = symbol.trim();
    if symbol.is_empty() {
        return Ok(value);
    }
    Unit::parse(symbol)
        .and_then(|typed| typed.convert(value, unit))
        .ok_or_else(|| TypedAnswerError::Unit {
            typed: symbol.to_string(),
            expected: unit,
        })
}
