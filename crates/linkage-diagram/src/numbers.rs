//! Numbers as an engineer writes them: four significant digits, and a value in an SI
//! unit with the prefix that keeps it between 1 and 1000 (51.72 kN·m, not 5.172e4
//! N·m nor 51721.5 N·m). Shared by the app's plots and readouts, the sheets and the
//! command line's text report.

/// An SI prefix: the factor a value in the base unit is multiplied by to be written
/// with it, and its symbol.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prefix {
    /// What a value in the base unit is multiplied by (1e-3 for k).
    pub factor: f64,
    /// The symbol ("k", "M", "m", "µ", or "" for none).
    pub symbol: &'static str,
}

/// The prefixes an engineer uses, from micro to giga.
const PREFIXES: [(i32, &str); 6] = [(-6, "µ"), (-3, "m"), (0, ""), (3, "k"), (6, "M"), (9, "G")];

impl Prefix {
    /// No prefix.
    pub const NONE: Self = Self {
        factor: 1.0,
        symbol: "",
    };

    /// The prefix that writes `magnitude` (a typical size of the values, such as the
    /// largest) between 1 and 1000; none for zero or a value that is not finite.
    pub fn for_magnitude(magnitude: f64) -> Self {
        let m = magnitude.abs();
        if m == 0.0 || !m.is_finite() {
            return Self::NONE;
        }
        // 999.96 rounds to 1000 at four digits: a value that close takes the next
        // prefix.
        let exponent = ((m * (1.0 + 5e-5)).log10() / 3.0).floor() as i32 * 3;
        let (e, symbol) = PREFIXES
            .iter()
            .copied()
            .min_by_key(|(e, _)| (e - exponent).abs())
            .unwrap_or((0, ""));
        Self {
            factor: 10f64.powi(-e),
            symbol,
        }
    }

    /// `unit` with the prefix ("kN·m").
    pub fn unit(self, unit: &str) -> String {
        format!("{}{unit}", self.symbol)
    }
}

/// `v` to `digits` significant digits, without trailing zeros (51.72, 0.1234, 120).
pub fn significant(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{}", if v == 0.0 { 0.0 } else { v });
    }
    let decimals = (digits - 1 - v.abs().log10().floor() as i32).max(0) as usize;
    let t = format!("{v:.decimals$}");
    let t = if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.')
    } else {
        &t
    };
    if t == "-0" { "0".into() } else { t.into() }
}

/// `value` in the base SI `unit` (N, N·m, J, W), written with four significant
/// digits and the prefix that suits it: "51.72 kN·m".
pub fn si(value: f64, unit: &str) -> String {
    let p = Prefix::for_magnitude(value);
    format!("{} {}", significant(value * p.factor, 4), p.unit(unit))
}

/// Relative size below which a value is the round-off of the values beside it.
pub const ROUND_OFF: f64 = 1e-9;

/// `value` as [`si`] writes it, or "0 unit" where it is below `scale` ×
/// [`ROUND_OFF`]: a computation whose values are of size `scale` leaves such a value
/// as its round-off (1e-17 m/s beside velocities of 0.1 m/s is a zero, not
/// "0.00000000001 µm/s").
pub fn si_beside(value: f64, scale: f64, unit: &str) -> String {
    if value.abs() <= scale.abs() * ROUND_OFF {
        return format!("0 {unit}");
    }
    si(value, unit)
}

/// A length unit's symbol ("mm", "m").
pub fn unit_symbol(unit: linkage::scene::LengthUnit) -> &'static str {
    match unit {
        linkage::scene::LengthUnit::Metre => "m",
        linkage::scene::LengthUnit::Millimetre => "mm",
    }
}

/// An angle in degrees to four significant digits, with the degree sign ("42.58°");
/// the round-off of a turn (below 360° × [`ROUND_OFF`]) as 0°.
pub fn degrees(deg: f64) -> String {
    if deg.abs() <= 360.0 * ROUND_OFF {
        return "0°".into();
    }
    format!("{}°", significant(deg, 4))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The issue's own numbers: the die cutter's peak torque and flywheel, a
    /// force from a sheet, a small acceleration.
    #[test]
    fn values_take_the_prefix_that_keeps_them_between_one_and_a_thousand() {
        assert_eq!(si(51_721.5, "N·m"), "51.72 kN·m");
        assert_eq!(si(15_915.0, "N·m"), "15.92 kN·m");
        assert_eq!(si(2_028_973.220_8, "N"), "2.029 MN");
        assert_eq!(si(-0.004_2, "m/s²"), "-4.2 mm/s²");
        assert_eq!(si(999.99, "N"), "1 kN");
        assert_eq!(si(0.0, "N"), "0 N");
        assert_eq!(si(12.0, "J"), "12 J");
    }

    #[test]
    fn round_off_beside_the_values_prints_as_zero() {
        assert_eq!(si_beside(1e-17, 0.1, "m/s"), "0 m/s");
        assert_eq!(si_beside(-3e-11, 0.1, "m/s"), "0 m/s");
        assert_eq!(si_beside(1.275e-3, 0.1, "m/s"), "1.275 mm/s");
        assert_eq!(degrees(42.5815), "42.58°");
        assert_eq!(degrees(-179.94), "-179.9°");
        assert_eq!(degrees(0.0), "0°");
        assert_eq!(degrees(-1.053e-14), "0°");
    }

    #[test]
    fn significant_digits_without_trailing_zeros() {
        assert_eq!(significant(51.7215, 4), "51.72");
        assert_eq!(significant(0.123_456, 4), "0.1235");
        assert_eq!(significant(120.0, 4), "120");
        assert_eq!(significant(-0.000_01, 2), "-0.00001");
        assert_eq!(significant(-0.000_001, 1), "-0.000001");
        assert_eq!(significant(f64::NAN, 4), "NaN");
    }
}
