//! Parsers for the options that count things (steps, solutions, evaluations, seeds,
//! indices): clap's own reading of `--steps -1` is "unexpected argument '-1' found"
//! (a negative number looks like an option) and of `--steps 2.5` "invalid digit";
//! these name the valid range instead. Each option using one also allows hyphen
//! values, so that a negative number reaches it.

/// A whole number from `least` to `most`, or why not, with the range.
fn count(text: &str, least: u64, most: u64) -> Result<u64, String> {
    let range = if most == u64::MAX {
        format!("a whole number, at least {least}")
    } else {
        format!("a whole number from {least} to {most}")
    };
    let trimmed = text.trim();
    if let Ok(n) = trimmed.parse::<u64>() {
        return if (least..=most).contains(&n) {
            Ok(n)
        } else {
            Err(format!("{n} is out of range: give {range}"))
        };
    }
    match trimmed.parse::<f64>() {
        Ok(v) if v.is_finite() && v.fract() != 0.0 => {
            Err(format!("{trimmed} is not a whole number: give {range}"))
        }
        Ok(v) if v.is_finite() => Err(format!("{trimmed} is out of range: give {range}")),
        _ => Err(format!("{trimmed} is not a number: give {range}")),
    }
}

/// At least 1 (a count of positions, designs or evaluations).
pub fn at_least_one(text: &str) -> Result<usize, String> {
    count(text, 1, usize::MAX as u64).map(|n| n as usize)
}

/// At least 2 (a sweep's positions: its two ends at least).
pub fn at_least_two(text: &str) -> Result<usize, String> {
    count(text, 2, usize::MAX as u64).map(|n| n as usize)
}

/// At least 1, as a 64-bit count.
pub fn at_least_one_u64(text: &str) -> Result<u64, String> {
    count(text, 1, u64::MAX)
}

/// Any whole number from 0 (a seed).
pub fn any_u64(text: &str) -> Result<u64, String> {
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
            assert_eq!(at_least_two(text), Err(want.to_string()), "{text}");
        }
        assert_eq!(any_u64("0"), Ok(0));
        assert!(any_u64("-3").is_err_and(|e| e.contains("at least 0")));
    }
}
