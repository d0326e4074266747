//! The units a question is asked and answered in: written as their symbols in the
//! exercise file (`unit: "m/s"`) and typed after an answer (`1.25 m/s`, `1250 mm/s`),
//! converted to and from SI by a factor, so that an answer in another unit of the
//! same kind is converted and one of another kind is refused with the unit expected.

use serde::{Deserialize, Serialize};

/// What a quantity measures; answers convert between units of one kind only.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// m/s.
    Speed,
    /// m/s².
    Acceleration,
    /// rad/s.
    AngularSpeed,
    /// rad/s².
    AngularAcceleration,
    /// m.
    Length,
    /// rad.
    Angle,
    /// N·m.
    Torque,
    /// kg·m².
    Inertia,
    /// A ratio (the time ratio K).
    Ratio,
}

impl Kind {
    /// What it measures, in words for a refusal.
    pub fn words(self) -> &'static str {
        match self {
            Kind::Speed => "a speed",
            Kind::Acceleration => "an acceleration",
            Kind::AngularSpeed => "an angular velocity",
            Kind::AngularAcceleration => "an angular acceleration",
            Kind::Length => "a length",
            Kind::Angle => "an angle",
            Kind::Torque => "a torque",
            Kind::Inertia => "a moment of inertia",
            Kind::Ratio => "a ratio (no unit: \"\")",
        }
    }
}

/// A unit of a question's answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub enum Unit {
    /// m/s.
    MetrePerSecond,
    /// mm/s.
    MillimetrePerSecond,
    /// m/s².
    MetrePerSecondSquared,
    /// mm/s².
    MillimetrePerSecondSquared,
    /// rad/s.
    RadianPerSecond,
    /// rpm (turns a minute).
    Rpm,
    /// rad/s².
    RadianPerSecondSquared,
    /// m.
    Metre,
    /// mm.
    Millimetre,
    /// Degrees.
    Degree,
    /// Radians.
    Radian,
    /// N·m.
    NewtonMetre,
    /// kg·m².
    KilogramSquareMetre,
    /// A plain number.
    One,
}

/// Every unit, for parsing and for the tests.
pub const UNITS: [Unit; 14] = [
    Unit::MetrePerSecond,
    Unit::MillimetrePerSecond,
    Unit::MetrePerSecondSquared,
    Unit::MillimetrePerSecondSquared,
    Unit::RadianPerSecond,
    Unit::Rpm,
    Unit::RadianPerSecondSquared,
    Unit::Metre,
    Unit::Millimetre,
    Unit::Degree,
    Unit::Radian,
    Unit::NewtonMetre,
    Unit::KilogramSquareMetre,
    Unit::One,
];

impl Unit {
    /// The symbol written in files and shown beside an answer.
    pub fn symbol(self) -> &'static str {
        match self {
            Unit::MetrePerSecond => "m/s",
            Unit::MillimetrePerSecond => "mm/s",
            Unit::MetrePerSecondSquared => "m/s^2",
            Unit::MillimetrePerSecondSquared => "mm/s^2",
            Unit::RadianPerSecond => "rad/s",
            Unit::Rpm => "rpm",
            Unit::RadianPerSecondSquared => "rad/s^2",
            Unit::Metre => "m",
            Unit::Millimetre => "mm",
            Unit::Degree => "deg",
            Unit::Radian => "rad",
            Unit::NewtonMetre => "N m",
            Unit::KilogramSquareMetre => "kg m^2",
            Unit::One => "",
        }
    }

    /// The symbol as typed in other common ways (², ·, °, r/min), for parsing.
    fn spellings(self) -> &'static [&'static str] {
        match self {
            Unit::MetrePerSecondSquared => &["m/s²", "m/s2"],
            Unit::MillimetrePerSecondSquared => &["mm/s²", "mm/s2"],
            Unit::RadianPerSecondSquared => &["rad/s²", "rad/s2"],
            Unit::Rpm => &["r/min", "1/min"],
            Unit::Degree => &["°", "degrees"],
            Unit::NewtonMetre => &["N·m", "Nm", "N*m", "N.m"],
            Unit::KilogramSquareMetre => &["kg·m²", "kg m2", "kg*m^2", "kgm^2"],
            _ => &[],
        }
    }

    /// The unit a symbol names (`None` for one it does not know).
    pub fn parse(symbol: &str) -> Option<Unit> {
        let symbol = symbol.trim();
        UNITS
            .into_iter()
            .find(|u| u.symbol() == symbol || u.spellings().contains(&symbol))
    }

    /// What it measures.
    pub fn kind(self) -> Kind {
        match self {
            Unit::MetrePerSecond | Unit::MillimetrePerSecond => Kind::Speed,
            Unit::MetrePerSecondSquared | Unit::MillimetrePerSecondSquared => Kind::Acceleration,
            Unit::RadianPerSecond | Unit::Rpm => Kind::AngularSpeed,
            Unit::RadianPerSecondSquared => Kind::AngularAcceleration,
            Unit::Metre | Unit::Millimetre => Kind::Length,
            Unit::Degree | Unit::Radian => Kind::Angle,
            Unit::NewtonMetre => Kind::Torque,
            Unit::KilogramSquareMetre => Kind::Inertia,
            Unit::One => Kind::Ratio,
        }
    }

    /// Whether it is a thousandth of its SI unit (mm, mm/s, mm/s²).
    fn milli(self) -> bool {
        matches!(
            self,
            Unit::MillimetrePerSecond | Unit::MillimetrePerSecondSquared | Unit::Millimetre
        )
    }

    /// One of this unit in SI (1 for the milli units, which divide by 1000).
    fn si_factor(self) -> f64 {
        match self {
            Unit::Rpm => std::f64::consts::TAU / 60.0,
            Unit::Degree => std::f64::consts::PI / 180.0,
            _ => 1.0,
        }
    }

    /// `value` in this unit, in SI. A thousandth is divided by 1000 (correctly
    /// rounded), not multiplied by 1e-3 (which is not exact): 119 mm/s is the
    /// 0.119 m/s a student would type, to the last bit.
    pub fn to_si(self, value: f64) -> f64 {
        if self.milli() {
            value / 1000.0
        } else {
            value * self.si_factor()
        }
    }

    /// `si` (SI) in this unit.
    pub fn from_si(self, si: f64) -> f64 {
        if self.milli() {
            si * 1000.0
        } else {
            si / self.si_factor()
        }
    }

    /// `value` in `self` converted to `to` (`None` if they measure different things).
    pub fn convert(self, value: f64, to: Unit) -> Option<f64> {
        (self.kind() == to.kind()).then(|| to.from_si(self.to_si(value)))
    }
}

impl From<Unit> for String {
    fn from(unit: Unit) -> String {
        unit.symbol().to_string()
    }
}

impl TryFrom<String> for Unit {
    type Error = String;

    fn try_from(symbol: String) -> Result<Self, String> {
        Unit::parse(&symbol).ok_or_else(|| {
            let known: Vec<String> = UNITS
                .iter()
                .map(|u| format!("\"{}\"", u.symbol()))
                .collect();
            format!("unknown unit \"{symbol}\" (one of {})", known.join(", "))
        })
    }
}

impl std::fmt::Display for Unit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.symbol())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_symbol_and_spelling_parses_back_to_its_unit() {
        for unit in UNITS {
            assert_eq!(Unit::parse(unit.symbol()), Some(unit));
            for s in unit.spellings() {
                assert_eq!(Unit::parse(s), Some(unit), "{s}");
            }
        }
        assert_eq!(Unit::parse("furlong"), None);
    }

    #[test]
    fn conversions_keep_the_kind_and_round_trip() {
        let v = Unit::MillimetrePerSecond.convert(1250.0, Unit::MetrePerSecond);
        assert!((v.expect("as set up") - 1.25).abs() < 1e-15);
        let w = Unit::Rpm
            .convert(60.0, Unit::RadianPerSecond)
            .expect("as set up");
        assert!((w - std::f64::consts::TAU).abs() < 1e-15);
        assert_eq!(Unit::Degree.convert(1.0, Unit::Millimetre), None);
        // As typed: 119 mm/s is the 0.119 m/s a student would type, to the last bit
        // (119 × 1e-3 is 0.11900000000000001).
        assert_eq!(
            Unit::MillimetrePerSecond.convert(119.0, Unit::MetrePerSecond),
            Some(0.119)
        );
        assert_eq!(
            Unit::MetrePerSecond.convert(0.119, Unit::MillimetrePerSecond),
            Some(119.0)
        );
        // As typed: 105 mm/s is the 0.105 m/s a student would type, to the last bit.
        assert_eq!(
            Unit::MillimetrePerSecond.convert(105.0, Unit::MetrePerSecond),
            Some(0.105)
        );
    }
}
