//! Parsers for the options that count things (steps, solutions, evaluations, seeds,
//! indices): clap's own reading of `--steps -1` is "unexpected argument '-1' found"
//! (a negative number looks like an option) and of `--steps 2.5` "invalid digit";
//! these name the valid range instead. Each option using one also allows hyphen
//! values, so that a negative number reaches it.

/// What is wrong with a count as typed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CountFault {
    /// A whole number outside the range (or a number too large for one).
    OutOfRange,
    /// A number with a fraction.
    NotWhole,
    /// Not a number at all.
    NotANumber,
}

/// A count refused, with the text typed and the valid range.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{text} {} give {}", match fault {
    CountFault::OutOfRange => "is out of range:",
    CountFault::NotWhole => "is not a whole number:",
    CountFault::NotANumber => "is not a number:",
}, range_words(*least, *most))]
pub struct CountError {
    /// The text typed, trimmed.
    pub text: String,
    /// What is wrong with it.
    pub fault: CountFault,
    /// The least count.
    pub least: u64,
    /// The most.
    pub most: u64,
}

/// "a whole number, at least 2" and similar.
fn range_words(least: u64, most: u64) -> String {
    if most == u64::MAX {
        format!("a whole number, at least {least}")
    } else {
        format!("a whole number from {least} to {most}")
    }
}

/// A whole number from `least` to `most`, or why not, with the range.
fn count(text: &str, least: u64, most: u64) -> Result<u64, CountError> {
    let trimmed = text.trim();
    let refuse = |fault, text: String| CountError {
        text,
        fault,
        least,
        most,
    };
    if let Ok(n) = trimmed.parse::<u64>() {
        return if (least..=most).contains(&n) {
            Ok(n)
        } else {
            Err(refuse(CountFault::OutOfRange, n.to_string()))
        };
    }
    let fault = match trimmed.parse::<f64>() {
        Ok(v) if v.is_finite() && v.fract() != 0.0 => CountFault::NotWhole,
        Ok(v) if v.is_finite() => CountFault::OutOfRange,
        _ => CountFault::NotANumber,
    };
    Err(refuse(fault, trimmed.to_string()))
}

/// At least 1 (a count of positions, designs or evaluations).
pub fn at_least_one(text: &str) -> Result<usize, CountError> {
    count(text, 1, usize::MAX as u64).map(|n| n as usize)
}

/// At least 2 (a sweep's positions: its two ends at least).
pub fn at_least_two(text: &str) -> Result<usize, CountError> {
    count(text, 2, usize::MAX as u64).map(|n| n as usize)
}

/// At least 1, as a 64-bit count.
pub fn at_least_one_u64(text: &str) -> Result<u64, CountError> {
    count(text, 1, u64::MAX)
}

/// Any whole number from 0 (a seed).
pub fn any_u64(text: &str) -> Result<u64, CountError> {
    count(text, 0, u64::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_name_their_range_whatever_is_wrong() {
        assert_eq!(at_least_two("360"), Ok(360));
        for (text, want) in [
            ("-1", "-1 is out of range: give a whole number, at least 2"),
            ("1", "1 is out of range: give a whole number, at least 2"),
            (
                "2.5",
                "2.5 is not a whole number: give a whole number, at least 2",
            ),
            (
                "ten",
                "ten is not a number: give a whole number, at least 2",
            ),
            (
                "1e400",
                "1e400 is not a number: give a whole number, at least 2",
            ),
        ] {
            let e = at_least_two(text).expect_err(text);
            // The message is what the user reads: its wording is the point here.
            assert_eq!(e.to_string(), want, "{text}");
        }
        assert_eq!(any_u64("0"), Ok(0));
        assert_eq!(
            any_u64("-3").map_err(|e| (e.fault, e.least)),
            Err((CountFault::OutOfRange, 0))
        );
    }
}
