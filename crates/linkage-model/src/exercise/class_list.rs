//! The class list: a CSV (as a learning platform or a spreadsheet exports it) whose
//! first column holds the students' numbers; a first row whose first cell holds no
//! digit (a header: `student`, `学号`) is skipped.

use super::variant::{BadStudentId, StudentId};

/// Why a class list was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ClassListError {
    /// Not CSV.
    #[error("line {line}: {message}")]
    Csv {
        /// Line, from 1.
        line: u64,
        /// What the reader says.
        message: String,
    },
    /// A first cell that is not a student number.
    #[error("line {line}: {why}{}", if *line == 1 { " (a header row's first cell holds no digit)" } else { "" })]
    Student {
        /// Line, from 1.
        line: u64,
        /// Why.
        why: BadStudentId,
    },
    /// A number listed twice.
    #[error("line {line}: student {student} is listed twice")]
    Twice {
        /// Line, from 1.
        line: u64,
        /// The number.
        student: StudentId,
    },
    /// No students.
    #[error("the class list names no student")]
    Empty,
}

/// The students in `text`, in its order.
///
/// # Errors
/// A row that is not CSV, a first cell that is not a student number (but for a
/// header), a number listed twice, or no student at all.
pub fn class_list(text: &str) -> Result<Vec<StudentId>, ClassListError> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let mut students: Vec<StudentId> = Vec::new();
    for (row, record) in reader.records().enumerate() {
        let record = record.map_err(|e| ClassListError::Csv {
            line: e.position().map_or(0, |p| p.line()),
            message: e.to_string(),
        })?;
        let line = record.position().map_or(row as u64 + 1, |p| p.line());
        let cell = record.get(0).unwrap_or_default();
        if cell.trim().is_empty() && record.len() <= 1 {
            continue;
        }
        if row == 0 && !cell.chars().any(|c| c.is_ascii_digit()) {
            continue;
        }
        match StudentId::parse(cell) {
            Ok(s) if students.contains(&s) => {
                return Err(ClassListError::Twice { line, student: s });
            }
            Ok(s) => students.push(s),
            Err(why) => return Err(ClassListError::Student { line, why }),
        }
    }
    if students.is_empty() {
        return Err(ClassListError::Empty);
    }
    Ok(students)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_header_is_skipped_and_the_first_column_read() {
        let list =
            class_list("学号,name\n2023001,Li Lei\n2023002,Han Meimei\n").expect("as set up");
        let numbers: Vec<&str> = list.iter().map(StudentId::as_str).collect();
        assert_eq!(numbers, ["2023001", "2023002"]);
    }

    #[test]
    fn a_bad_number_or_one_listed_twice_is_named_with_its_line() {
        let bad = class_list("student\n2023001\nno such!\n").expect_err("refused");
        assert!(
            matches!(bad, ClassListError::Student { line: 3, .. }),
            "{bad:?}"
        );
        let twice = class_list("1\n2\n1\n").expect_err("refused");
        assert!(
            matches!(twice, ClassListError::Twice { line: 3, .. }),
            "{twice:?}"
        );
        assert_eq!(class_list("student\n"), Err(ClassListError::Empty));
    }
}
