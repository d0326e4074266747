//! Plots a person can read: round tick values labelled from one end of each axis to
//! the other (egui_plot's default labels only the ticks it finds room for, and on a
//! low plot that left one: 0), values in engineering form (a torque in kN·m with
//! ticks 0, 20, 40, not 0 … 5.172e4 N·m), angles stepped by 15°, 30°, 90°, and the
//! value under the pointer to four digits. Every tab's plots are made here.

use crate::i18n::tr;
use egui_plot::{AxisHints, GridInput, GridMark, Plot};
use linkage_diagram::numbers::{Prefix, significant};

/// A plotted quantity's unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// An SI unit that takes a prefix (N, N·m, J, W, m/s, m/s²): the plot picks the
    /// one that suits its values.
    Si(&'static str),
    /// An angle in degrees, written °: its ticks step by divisors of the turn
    /// (15°, 30°, 90°…).
    Degrees,
    /// A unit written as it is (°/s, rad/s, the scene's mm or m, kg·m²).
    Fixed(&'static str),
    /// A plain number (a ratio, a share, a logarithm).
    None,
}

/// What an axis shows, in words: named in the app's language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AxisWord {
    /// The crank's angle.
    CrankAngle,
    /// The transmission angle.
    TransmissionAngle,
    /// The torque on the input.
    InputTorque,
    /// The logarithm of the output's force per unit input torque.
    Amplification,
    /// The reduced model's torque with the machine at rest.
    ReducedTorqueAtRest,
}

impl AxisWord {
    /// The word in the app's language.
    fn shown(self) -> String {
        match self {
            Self::CrankAngle => tr!("axis.crank_angle"),
            Self::TransmissionAngle => tr!("axis.transmission_angle"),
            Self::InputTorque => tr!("axis.input_torque"),
            Self::Amplification => tr!("axis.amplification"),
            Self::ReducedTorqueAtRest => tr!("axis.reduced_torque_at_rest"),
        }
    }
}

/// What an axis shows: a word of the catalogue, or a name shown as it is (a symbol
/// such as ω or J(q), a name the scene gave, a name already in the app's language).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AxisName<'a> {
    /// A word, in the app's language.
    Word(AxisWord),
    /// Shown as it is.
    AsIs(&'a str),
}

/// An axis: what it shows and in which unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Axis<'a> {
    /// What it shows.
    pub name: AxisName<'a>,
    /// Its unit.
    pub unit: Unit,
}

impl<'a> Axis<'a> {
    /// An axis named `name` as it is (a symbol, a scene's name), in `unit`.
    pub const fn new(name: &'a str, unit: Unit) -> Self {
        Self {
            name: AxisName::AsIs(name),
            unit,
        }
    }

    /// An axis showing `word`, in `unit`.
    pub const fn word(word: AxisWord, unit: Unit) -> Self {
        Self {
            name: AxisName::Word(word),
            unit,
        }
    }
}

/// The crank-angle axis most plots share.
pub const CRANK: Axis<'static> = Axis::word(AxisWord::CrankAngle, Unit::Degrees);

/// A series ready to plot: its values scaled to the axis' prefix, and the axis
/// title with its unit ("input torque (kN·m)").
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The points, y scaled by the prefix.
    pub points: Vec<[f64; 2]>,
    /// The axis title.
    pub title: AxisTitle,
    /// The factor the y values were multiplied by.
    pub factor: f64,
}

/// `data` on `axis`: an SI unit takes the prefix that writes the larger of the
/// middle 96 % of its values between 1 and 1000 (a spike at a dead point does not
/// choose it).
pub fn series(axis: Axis<'_>, data: &[[f64; 2]]) -> Series {
    let prefix = match axis.unit {
        Unit::Si(_) => {
            let [lo, hi] = crate::ui::plot_layout::robust_range(data);
            Prefix::for_magnitude(lo.abs().max(hi.abs()))
        }
        _ => Prefix::NONE,
    };
    Series {
        points: data.iter().map(|&[x, y]| [x, y * prefix.factor]).collect(),
        title: title(axis, prefix),
        factor: prefix.factor,
    }
}

/// An axis title as shown, and whether the axis is an angle in degrees (its ticks
/// step by 15°, 30°, 90°…).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AxisTitle {
    /// The title with its unit: "input torque (kN·m)".
    pub text: String,
    /// Whether the axis' unit is the degree.
    pub degrees: bool,
}

impl AxisTitle {
    /// A title whose axis is not an angle (or has no title: "").
    pub fn plain(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            degrees: false,
        }
    }

    /// A title whose axis is an angle in degrees ("main shaft angle (°)").
    pub fn degrees(text: String) -> Self {
        Self {
            text,
            degrees: true,
        }
    }
}

/// An axis title with its unit and prefix, its name in the app's language.
pub fn title(axis: Axis<'_>, prefix: Prefix) -> AxisTitle {
    let name = match axis.name {
        AxisName::Word(word) => word.shown(),
        AxisName::AsIs(name) => name.to_owned(),
    };
    let text = match axis.unit {
        Unit::Si(u) => format!("{name} ({})", prefix.unit(u)),
        Unit::Degrees => format!("{name} (°)"),
        Unit::Fixed(u) => format!("{name} ({u})"),
        Unit::None => name,
    };
    AxisTitle {
        text,
        degrees: axis.unit == Unit::Degrees,
    }
}

/// About how many ticks an axis gets.
const TICKS: f64 = 5.0;

/// A round step near `raw`: 1, 2, 2.5 or 5 times a power of ten; for an angle in
/// degrees from 10° up, a divisor of the turn (15, 30, 45, 60, 90, 180).
pub fn nice_step(raw: f64, angle: bool) -> f64 {
    if !(raw.is_finite() && raw > 0.0) {
        return 1.0;
    }
    if angle && (7.5..=180.0).contains(&raw) {
        let steps = [10.0, 15.0, 30.0, 45.0, 60.0, 90.0, 180.0];
        return steps
            .into_iter()
            .find(|&s| s >= raw * 0.75)
            .unwrap_or(180.0);
    }
    let power = 10f64.powf(raw.log10().floor());
    let mantissa = raw / power;
    let nice = [1.0, 2.0, 2.5, 5.0, 10.0]
        .into_iter()
        .find(|&m| m >= mantissa * 0.75)
        .unwrap_or(10.0);
    nice * power
}

/// The ticks between `lo` and `hi`: every multiple of a round step, about
/// [`TICKS`] of them, and no step below `least_step` (so that a narrow plot's labels
/// stand far enough apart to be drawn).
pub fn ticks(lo: f64, hi: f64, angle: bool, least_step: f64) -> Vec<GridMark> {
    let mut step = nice_step((hi - lo) / TICKS, angle);
    if step < least_step {
        // nice_step gives at least three quarters of what it is asked for.
        step = nice_step(least_step / 0.75, angle);
    }
    if !(hi > lo && step > 0.0) || (hi - lo) / step > 100.0 {
        return Vec::new();
    }
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last)
        .map(|k| GridMark {
            value: k as f64 * step,
            step_size: step,
        })
        .collect()
}

/// A tick's value with the decimals its step needs (none for 20, one for 2.5).
pub fn tick_text(mark: GridMark) -> String {
    let step = mark.step_size;
    let decimals = if step > 0.0 && step.is_finite() {
        let power = step.log10().floor();
        // 2.5, 0.25: one more digit than the power of ten (none for 25 or 250).
        let extra = if ((step / 10f64.powf(power)) - 2.5).abs() < 1e-9 {
            1.0
        } else {
            0.0
        };
        (extra - power).max(0.0) as usize
    } else {
        0
    };
    let text = format!("{:.*}", decimals, mark.value);
    if text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        "0".into()
    } else {
        text
    }
}

/// The ticks of an axis whose labels are drawn in full from `label_gap` points apart:
/// no closer (a cam's four plots side by side in a laptop's pane, 150 points wide,
/// had ticks every 60° 25 points apart, their labels faded out to nothing).
fn grid(input: GridInput, angle: bool, label_gap: f32) -> Vec<GridMark> {
    // base_step_size is the plot's units across GRID_LEAST points.
    let least = input.base_step_size * f64::from(label_gap / GRID_LEAST);
    ticks(input.bounds.0, input.bounds.1, angle, least)
}

/// The least spacing of grid lines, points (egui_plot's own default, set here
/// because [`grid`] reads its units per this spacing).
const GRID_LEAST: f32 = 8.0;
/// The spacing of tick labels along x and along y, points: hidden below the first,
/// in full from the second.
const X_LABEL_GAP: [f32; 2] = [24.0, 30.0];
const Y_LABEL_GAP: [f32; 2] = [12.0, 18.0];

/// A plot `height` high, keyed by `id`, with the readable axes: its titles, round
/// ticks labelled from end to end, the value under the pointer to four digits.
pub fn plot<'a>(
    id: impl std::hash::Hash + std::fmt::Debug,
    height: f32,
    x_title: &AxisTitle,
    y_title: &AxisTitle,
) -> Plot<'a> {
    let (x_angle, y_angle) = (x_title.degrees, y_title.degrees);
    let (x_title, y_title) = (x_title.text.as_str(), y_title.text.as_str());
    let axis = |hints: AxisHints<'a>, title: &str| {
        hints
            .label(title.to_owned())
            .formatter(|mark, _| tick_text(mark))
    };
    let (x_name, y_name) = (x_title.to_owned(), y_title.to_owned());
    Plot::new(id)
        .height(height)
        .allow_scroll(false)
        .grid_spacing(GRID_LEAST..=300.0)
        .x_grid_spacer(move |i| grid(i, x_angle, X_LABEL_GAP[1]))
        .y_grid_spacer(move |i| grid(i, y_angle, Y_LABEL_GAP[1]))
        .custom_x_axes(vec![
            axis(AxisHints::new_x(), x_title).label_spacing(X_LABEL_GAP[0]..=X_LABEL_GAP[1]),
        ])
        .custom_y_axes(vec![
            axis(AxisHints::new_y(), y_title).label_spacing(Y_LABEL_GAP[0]..=Y_LABEL_GAP[1]),
        ])
        .label_formatter(move |hover| {
            let p = pointer(hover);
            Some(format!(
                "{x_name} {}\n{y_name} {}",
                significant(p.x, 4),
                significant(p.y, 4)
            ))
        })
}

/// Where the pointer is over the plot.
fn pointer(hover: &egui_plot::HoverPosition<'_>) -> egui_plot::PlotPoint {
    match hover {
        egui_plot::HoverPosition::NearDataPoint { position, .. }
        | egui_plot::HoverPosition::Elsewhere { position } => *position,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whatever a plot's range, its ticks are round, there are three to seven of
    /// them, and the first and last lie within a step of the range's ends: an axis
    /// is labelled from end to end.
    #[test]
    fn ticks_are_round_and_reach_both_ends_of_any_range() {
        for (lo, hi) in [
            (-6_000.0, 58_000.0),
            (0.0, 1.0),
            (-0.0031, 0.0042),
            (117.0, 152.0),
            (1e5, 1e5 + 3.0),
            (-120.0, 7_000.0),
        ] {
            let marks = ticks(lo, hi, false, 0.0);
            assert!((3..=7).contains(&marks.len()), "{lo}..{hi}: {marks:?}");
            let step = marks[0].step_size;
            assert!(marks[0].value - lo <= step, "{lo}..{hi}: first {marks:?}");
            assert!(hi - marks[marks.len() - 1].value <= step, "{lo}..{hi}");
            let mantissa = step / 10f64.powf(step.log10().floor());
            assert!(
                [1.0, 2.0, 2.5, 5.0]
                    .iter()
                    .any(|m| (m - mantissa).abs() < 1e-9),
                "{step}"
            );
        }
    }

    /// A narrow plot's ticks stand at least as far apart as its labels need.
    #[test]
    fn a_narrow_axis_takes_a_longer_step() {
        let turn: Vec<f64> = ticks(0.0, 360.0, true, 72.0)
            .iter()
            .map(|m| m.value)
            .collect();
        assert_eq!(turn, [0.0, 90.0, 180.0, 270.0, 360.0]);
        for (lo, hi, least) in [(0.0, 1.0, 0.3), (-6e3, 5.8e4, 2.1e4), (0.0, 360.0, 200.0)] {
            let marks = ticks(lo, hi, lo == 0.0 && hi == 360.0, least);
            assert!(marks.len() >= 2, "{lo}..{hi}: {marks:?}");
            assert!(marks[0].step_size >= least, "{lo}..{hi}: {marks:?}");
        }
    }

    #[test]
    fn a_turn_is_ticked_in_divisors_of_the_turn() {
        let steps: Vec<f64> = ticks(0.0, 360.0, true, 0.0)
            .iter()
            .map(|m| m.value)
            .collect();
        assert_eq!(steps, [0.0, 60.0, 120.0, 180.0, 240.0, 300.0, 360.0]);
        let marks = ticks(34.3, 117.7, true, 0.0);
        assert_eq!(marks[0].step_size, 15.0);
    }

    #[test]
    fn tick_text_has_the_decimals_its_step_needs() {
        let mark = |value, step_size| GridMark { value, step_size };
        assert_eq!(tick_text(mark(20_000.0, 10_000.0)), "20000");
        assert_eq!(tick_text(mark(2.5, 2.5)), "2.5");
        assert_eq!(tick_text(mark(0.75, 0.25)), "0.75");
        assert_eq!(tick_text(mark(750.0, 250.0)), "750");
        assert_eq!(tick_text(mark(75.0, 25.0)), "75");
        assert_eq!(tick_text(mark(-1e-17, 0.1)), "0");
    }

    /// The die cutter's torque reads in kN·m, a crank angle stays in degrees.
    #[test]
    fn a_torque_takes_its_prefix_and_an_angle_none() {
        let torque = [[0.0, -6_000.0], [90.0, 51_720.0], [180.0, 100.0]];
        let s = series(Axis::word(AxisWord::InputTorque, Unit::Si("N·m")), &torque);
        assert_eq!(s.title, AxisTitle::plain("input torque (kN·m)"));
        assert!((s.points[1][1] - 51.72).abs() < 1e-12);
        let s = series(CRANK, &torque);
        assert_eq!(s.title, AxisTitle::degrees("crank angle (°)".into()));
    }
}
