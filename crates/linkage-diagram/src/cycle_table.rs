//! The table of the cycle that a student pastes into a report, as CSV: the input in
//! degrees on whole multiples of a step (0°, 1°, 2°, ... by default), lengths in the
//! scene's unit, every column named with its unit, plain decimals to six significant
//! digits, and round-off printed as 0. The one writer behind the app's CSV export
//! and `linkage sweep` and `linkage at` (JSON stays SI, for programs).

use linkage::scene::LengthUnit;
use linkage::sweep::{Grid, SweepInfo, sweep_each_on, sweep_range};
use linkage::{Kinematics, LinkageError, Mechanism, Solution};

use crate::numbers::{ROUND_OFF, significant, unit_symbol};

/// Significant digits of every number in the table: a length of 1234.56 mm keeps
/// its hundredths, and a pasted column sums without visible loss.
const DIGITS: i32 = 6;

/// The step of the table's input, degrees, unless the user asks for another.
pub const DEFAULT_STEP_DEG: f64 = 1.0;

/// The smallest step a table takes, degrees: 36 000 rows a turn.
pub const MIN_STEP_DEG: f64 = 0.01;

/// How the table writes a mechanism's motion: its lengths' unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CycleTable {
    unit: LengthUnit,
}

impl CycleTable {
    /// A table with lengths (and their rates) in `unit`.
    pub fn new(unit: LengthUnit) -> Self {
        Self { unit }
    }

    /// The column names, each with its unit: `input (deg)`, then `B x (mm)`, `B y
    /// (mm)`, `B vx (mm/s)`, ... `B ay (mm/s^2)` per named point, then `rod angle
    /// (deg)`, `rod omega (rad/s)`, `rod alpha (rad/s^2)` per moving link.
    pub fn header(&self, m: &Mechanism) -> Vec<String> {
        let u = unit_symbol(self.unit);
        let mut h = vec!["input (deg)".to_string()];
        for p in &m.points {
            let n = &p.name;
            h.extend([
                format!("{n} x ({u})"),
                format!("{n} y ({u})"),
                format!("{n} vx ({u}/s)"),
                format!("{n} vy ({u}/s)"),
                format!("{n} ax ({u}/s^2)"),
                format!("{n} ay ({u}/s^2)"),
            ]);
        }
        for l in m.moving_links() {
            let n = &m.links[l].name;
            h.extend([
                format!("{n} angle (deg)"),
                format!("{n} omega (rad/s)"),
                format!("{n} alpha (rad/s^2)"),
            ]);
        }
        h
    }

    /// One row matching [`Self::header`]; `angles` are the link angles unwrapped
    /// along the sweep. A full turn's input is written between 0° and 360°.
    pub fn row(&self, m: &Mechanism, s: &Solution, angles: &[f64]) -> Vec<String> {
        let per = 1.0 / self.unit.to_metres();
        let moving: Vec<_> = m.moving_links().collect();
        let scales = Scales::of(s, &moving);
        let mut row = vec![plain(input_degrees(s.input_rad), 360.0)];
        for p in &s.points {
            row.extend([
                plain(p.position.x * per, scales.length * per),
                plain(p.position.y * per, scales.length * per),
                plain(p.velocity.x * per, scales.speed * per),
                plain(p.velocity.y * per, scales.speed * per),
                plain(p.acceleration.x * per, scales.acceleration * per),
                plain(p.acceleration.y * per, scales.acceleration * per),
            ]);
        }
        for l in moving {
            row.extend([
                plain(angles[l].to_degrees(), 360.0),
                plain(s.links[l].omega_rad_s, scales.omega),
                plain(s.links[l].alpha_rad_s2, scales.alpha),
            ]);
        }
        row
    }

    /// The table of the cycle (or the input's range between its dead points) on the
    /// whole multiples of `step_deg`, as CSV text with its header.
    ///
    /// # Errors
    /// A step outside [`MIN_STEP_DEG`] to 360°, or the solver's error.
    pub fn csv(&self, k: &mut Kinematics, step_deg: f64) -> Result<String, LinkageError> {
        let mut out = csv_line(&self.header(k.mechanism()));
        self.each_row(k, step_deg, |cells| {
            out.push_str(&csv_line(cells));
            Ok::<(), LinkageError>(())
        })?;
        Ok(out)
    }

    /// Hands each row of the table on the multiples of `step_deg` to `visit`, as it is
    /// solved (memory stays flat for any step).
    ///
    /// # Errors
    /// A step outside [`MIN_STEP_DEG`] to 360°, the solver's error, or `visit`'s.
    pub fn each_row<E: From<LinkageError>>(
        &self,
        k: &mut Kinematics,
        step_deg: f64,
        mut visit: impl FnMut(&[String]) -> Result<(), E>,
    ) -> Result<SweepInfo, E> {
        let grid = grid(k, step_deg)?;
        sweep_each_on(k, grid, |m, s, angles| visit(&self.row(m, s, angles)))
    }
}

/// The inputs of a table on the multiples of `step_deg`.
///
/// # Errors
/// A step outside [`MIN_STEP_DEG`] to 360°, or an input that assembles nowhere.
pub fn grid(k: &Kinematics, step_deg: f64) -> Result<Grid, LinkageError> {
    use linkage::error::{Param, Valid};
    if !(MIN_STEP_DEG..=360.0).contains(&step_deg) {
        return Err(LinkageError::invalid(
            Param::SweepStepDeg,
            step_deg,
            Valid::Between(MIN_STEP_DEG, 360.0),
        ));
    }
    let (range, full) = sweep_range(k)?;
    Ok(Grid::multiples(range, full, step_deg.to_radians()))
}

/// An input angle as the table writes it: a turn's angles between 0° and 360°.
fn input_degrees(rad: f64) -> f64 {
    let d = rad.to_degrees().rem_euclid(360.0);
    // 359.9999999999 is 0 again, once rounded to the table's digits.
    if (360.0 - d) < 360.0 * ROUND_OFF {
        0.0
    } else {
        d
    }
}

/// The sizes of a row's values of each kind, in SI, against which their round-off
/// is measured: the largest of the kind, and at least what the mechanism's size and
/// its links' fastest rate make of it (a row where every link's angular
/// acceleration is round-off, a crank at constant speed at a dead point, still has
/// ω² as its scale).
struct Scales {
    length: f64,
    speed: f64,
    acceleration: f64,
    omega: f64,
    alpha: f64,
}

impl Scales {
    fn of(s: &Solution, moving: &[linkage::LinkId]) -> Self {
        let largest =
            |values: &mut dyn Iterator<Item = f64>| values.map(f64::abs).fold(0.0, f64::max);
        let length = largest(&mut s.points.iter().map(|p| p.position.norm()));
        let omega = largest(&mut moving.iter().map(|&l| s.links[l].omega_rad_s))
            .max(s.input_speed_rad_s.abs());
        Self {
            length,
            speed: largest(&mut s.points.iter().map(|p| p.velocity.norm())).max(length * omega),
            acceleration: largest(&mut s.points.iter().map(|p| p.acceleration.norm()))
                .max(length * omega * omega),
            omega,
            alpha: largest(&mut moving.iter().map(|&l| s.links[l].alpha_rad_s2)).max(omega * omega),
        }
    }
}

/// `v` as a plain decimal (no exponent) to [`DIGITS`] significant digits, or 0 where
/// it is below `scale` × [`ROUND_OFF`]: the round-off of values of that size.
pub fn plain(v: f64, scale: f64) -> String {
    if v.abs() <= scale.abs() * ROUND_OFF {
        return "0".into();
    }
    significant(v, DIGITS)
}

/// One CSV line: a cell holding a comma, a quote or a line break is quoted, with its
/// quotes doubled (RFC 4180).
pub fn csv_line(cells: &[String]) -> String {
    let mut line = String::new();
    for (i, c) in cells.iter().enumerate() {
        if i > 0 {
            line.push(',');
        }
        if c.contains([',', '"', '\n', '\r']) {
            line.push('"');
            line.push_str(&c.replace('"', "\"\""));
            line.push('"');
        } else {
            line.push_str(c);
        }
    }
    line.push('\n');
    line
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_numbers_have_no_exponent_and_round_off_is_zero() {
        assert_eq!(plain(8.326e-17, 0.12), "0");
        assert_eq!(plain(0.127_512_34, 0.12), "0.127512");
        assert_eq!(plain(-8.3e9, 8.3e9), "-8300000000");
        assert_eq!(plain(1.234_567e-5, 1e-5), "0.0000123457");
        assert!((input_degrees(-90f64.to_radians()) - 270.0).abs() < 1e-9);
    }

    #[test]
    fn cells_with_commas_or_quotes_are_quoted() {
        let cells = ["a".to_string(), "b, c".into(), "say \"x\"".into()];
        assert_eq!(csv_line(&cells), "a,\"b, c\",\"say \"\"x\"\"\"\n");
    }
}
