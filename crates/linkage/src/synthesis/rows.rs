//! The synthesis inputs as a user writes them, read by one parser for the CLI's files
//! and the app's text fields alike: rows of comma-separated numbers, with blank lines,
//! `#` comments and a header line (a first row that is not numbers) skipped.

use thiserror::Error;

/// A row that is not what the synthesis asks for.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
#[error("line {line}: {text:?} is not {width} comma-separated numbers")]
pub struct RowError {
    /// The row's line, from 1.
    pub line: usize,
    /// The row as written, trimmed.
    pub text: String,
    /// How many numbers a row holds.
    pub width: usize,
}

/// The rows of `width` finite numbers in `text`.
///
/// # Errors
/// The first row that is not `width` finite numbers (a header excepted), by its line.
pub fn read_rows(text: &str, width: usize) -> Result<Vec<Vec<f64>>, RowError> {
    let skipped = |line: &str| line.is_empty() || line.starts_with('#');
    let header = text.lines().position(|l| !skipped(l.trim())).unwrap_or(0);
    let mut rows = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if skipped(line) {
            continue;
        }
        let numbers: Result<Vec<f64>, _> = line.split(',').map(|c| c.trim().parse()).collect();
        match numbers {
            Ok(v) if v.len() == width && v.iter().all(|x| x.is_finite()) => rows.push(v),
            Err(_) if i == header => {}
            _ => {
                return Err(RowError {
                    line: i + 1,
                    text: line.to_string(),
                    width,
                });
            }
        }
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_header_comments_and_blank_lines_are_skipped() {
        let text = "x_mm, y_mm\n# from the drawing\n\n1, 2\n 3 ,4 \n";
        assert_eq!(read_rows(text, 2), Ok(vec![vec![1.0, 2.0], vec![3.0, 4.0]]));
    }

    #[test]
    fn a_bad_row_after_the_first_is_named_by_its_line() {
        let err = read_rows("1, 2, 3\n\n4, x, 6\n", 3).expect_err("refused");
        assert_eq!((err.line, err.text.as_str()), (3, "4, x, 6"));
        let short = read_rows("1, 2\n3\n", 2).expect_err("refused");
        assert_eq!(short.line, 2);
        let infinite = read_rows("1, inf\n1, 2\n", 2).expect_err("refused");
        assert_eq!(infinite.line, 1);
    }
}
