//! The numbers a user sets: a slider to drag (Shift for a tenth of the speed; a
//! logarithmic scale where the range spans decades), a box to type into, and the
//! label. Each row has an id of its own (the caller's key), so that a row keeps its
//! focus and its text while the panel around it changes (a slider appearing above
//! it, a message, the top bar). Typed text is taken when the user presses Enter or
//! leaves the box (Escape cancels): a value in the valid range is set whole, with
//! every digit typed; text that is not a number, or a number outside the range, is
//! refused under the row with the valid range, and the value stays as it was.

use std::ops::RangeInclusive;

use eframe::egui;

use crate::i18n::tr;

/// What a number is, for its row.
#[derive(Clone, Debug)]
pub struct NumberSpec<'a> {
    /// What names it, shown beside it and in a refusal (e.g. `AB`, `k F-G (N/m)`).
    pub label: &'a str,
    /// Its unit as the user types it (refusals name it), or "".
    pub unit: &'a str,
    /// The values it takes.
    pub range: RangeInclusive<f64>,
    /// Whether the slider is logarithmic (a range over decades: the same drag is
    /// the same ratio anywhere along it). A range from 0 keeps 0 at its left end.
    pub logarithmic: bool,
    /// Whether a typed value outside the range wraps into it (a crank's full turn:
    /// -45° is 315°) instead of being refused.
    pub wraps: bool,
}

impl<'a> NumberSpec<'a> {
    /// A number on a linear slider.
    pub fn new(label: &'a str, unit: &'a str, range: RangeInclusive<f64>) -> Self {
        Self {
            label,
            unit,
            range,
            logarithmic: false,
            wraps: false,
        }
    }

    /// The same on a logarithmic slider.
    pub fn logarithmic(self) -> Self {
        Self {
            logarithmic: true,
            ..self
        }
    }

    /// The same, a typed value wrapping into the range (a full turn).
    pub fn wrapping(self) -> Self {
        Self {
            wraps: true,
            ..self
        }
    }

    /// The value of typed `text` for this number ([`parse`]), wrapped into the
    /// range where it wraps.
    ///
    /// # Errors
    /// Why the text is refused.
    pub fn take(&self, text: &str) -> Result<f64, Refusal> {
        let (lo, hi) = (*self.range.start(), *self.range.end());
        if !self.wraps || hi <= lo {
            return parse(text, self.unit, &self.range);
        }
        let v = parse(text, self.unit, &(f64::NEG_INFINITY..=f64::INFINITY))?;
        Ok(lo + (v - lo).rem_euclid(hi - lo))
    }
}

/// What the user did to a number this frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NumberInput {
    /// Nothing.
    None,
    /// Dragged the slider to this value (more frames of the drag may follow).
    Dragged(f64),
    /// Typed this value and pressed Enter or left the box.
    Typed(f64),
}

impl NumberInput {
    /// The value set, by a drag or by typing.
    pub fn value(self) -> Option<f64> {
        match self {
            Self::None => None,
            Self::Dragged(v) | Self::Typed(v) => Some(v),
        }
    }
}

/// Why typed text was not taken.
#[derive(Clone, Debug, PartialEq)]
pub enum Refusal {
    /// The text is not a number.
    NotANumber {
        /// What was typed.
        text: String,
    },
    /// The number is outside the valid range.
    OutOfRange {
        /// The number typed.
        value: f64,
        /// The valid range.
        range: [f64; 2],
    },
}

impl Refusal {
    /// The refusal as the row shows it: the number's name, what was wrong, the
    /// valid range, and the value kept.
    pub fn words(&self, spec: &NumberSpec<'_>, kept: f64) -> String {
        let unit = |v: f64| with_unit(&format_value(v), spec.unit);
        let (lo, hi) = (*spec.range.start(), *spec.range.end());
        let why = match self {
            Self::NotANumber { text } => tr!("number.not_a_number", text = text),
            Self::OutOfRange { value, .. } => tr!("number.out_of_range", value = unit(*value)),
        };
        tr!(
            "number.refused",
            label = spec.label,
            why = why,
            lo = format_value(lo),
            hi = unit(hi),
            kept = unit(kept)
        )
    }
}

fn with_unit(number: &str, unit: &str) -> String {
    match unit {
        "" => number.to_owned(),
        "°" => format!("{number}°"),
        _ => format!("{number} {unit}"),
    }
}

/// The value of typed `text`: a number as Rust writes it (`300`, `0.125`, `1e3`,
/// `-45`), with a comma for the decimal point where there is no point, and the
/// number's unit after it if the user typed it.
///
/// # Errors
/// The refusal: not a number, or outside `range`.
pub fn parse(text: &str, unit: &str, range: &RangeInclusive<f64>) -> Result<f64, Refusal> {
    let trimmed = text.trim();
    let number = trimmed
        .strip_suffix(unit.trim())
        .filter(|_| !unit.trim().is_empty())
        .unwrap_or(trimmed)
        .trim();
    let number = if number.contains('.') {
        number.to_owned()
    } else {
        number.replace(',', ".")
    };
    let value = number
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| Refusal::NotANumber {
            text: trimmed.to_owned(),
        })?;
    if range.contains(&value) {
        Ok(value)
    } else {
        Err(Refusal::OutOfRange {
            value,
            range: [*range.start(), *range.end()],
        })
    }
}

/// A value as the box shows it: six significant digits without trailing zeros
/// (117.658, 0.125, 1500), or in powers of ten where that would be long (1e-8).
pub fn format_value(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor();
    if !(-3.0..7.0).contains(&magnitude) {
        let text = format!("{v:.3e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = trim_zeros(mantissa);
        return format!("{mantissa}e{exponent}");
    }
    let decimals = (5.0 - magnitude).max(0.0) as usize;
    trim_zeros(&format!("{v:.decimals$}")).to_owned()
}

fn trim_zeros(text: &str) -> &str {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        text
    }
}

/// Width of the number box: room for a value of [`format_value`]'s longest common
/// form (`-1234.56`) in the body font, so that no digit is cut (the touch style's
/// larger font cut "552.41" to "552.4" in a fixed 64 points).
fn box_width(ui: &egui::Ui) -> f32 {
    text_width(ui, "-00000.00") + 2.0 * ui.spacing().button_padding.x
}
/// Shift-drag moves the value this much slower than a plain drag.
const FINE: f64 = 0.1;

/// What a row keeps between frames: the slider's own value last frame (what
/// egui's slider made of the pointer), for Shift's fine drag.
#[derive(Clone, Copy, Debug, Default)]
struct DragMemory {
    raw: f64,
}

/// A row: the slider, the box and the label, keyed by `key` (its id under the
/// panel's). Where the row is too narrow for all three the label goes above them.
/// Returns the slider's response (where it is) and what the user did.
pub fn slider_row(
    ui: &mut egui::Ui,
    key: impl std::hash::Hash + std::fmt::Debug,
    spec: &NumberSpec<'_>,
    value: f64,
) -> (egui::Response, NumberInput) {
    ui.push_id(key, |ui| {
        let label_width = text_width(ui, spec.label);
        let room = ui.available_width();
        let spacing = 2.0 * ui.spacing().item_spacing.x;
        let number = box_width(ui);
        let beside = room >= 90.0 + number + label_width + spacing;
        if !beside {
            ui.label(spec.label);
        }
        let row = ui.scope_id();
        let inner = ui.horizontal(|ui| {
            let label_room = if beside { label_width } else { 0.0 };
            ui.spacing_mut().slider_width =
                (ui.available_width() - number - label_room - spacing).max(60.0);
            let (slider, dragged) = slider(ui, row, spec, value);
            let (_, typed) = number_box(ui, row, spec, value);
            if beside {
                ui.label(spec.label);
            }
            (slider, typed.or(dragged))
        });
        refusal_line(ui, row, spec, value);
        let (slider, input) = inner.inner;
        (slider, input.unwrap_or(NumberInput::None))
    })
    .inner
}

fn text_width(ui: &egui::Ui, text: &str) -> f32 {
    egui::WidgetText::from(text)
        .into_galley(
            ui,
            Some(egui::TextWrapMode::Extend),
            f32::INFINITY,
            egui::TextStyle::Body,
        )
        .size()
        .x
}

/// The slider; with Shift held, a drag moves the value a tenth as fast (egui's
/// slider puts the value under the pointer; the row takes a tenth of that move).
fn slider(
    ui: &mut egui::Ui,
    row: egui::Id,
    spec: &NumberSpec<'_>,
    value: f64,
) -> (egui::Response, Option<NumberInput>) {
    let id = row.with("drag");
    let mut raw = value;
    let mut slider = egui::Slider::new(&mut raw, spec.range.clone())
        .show_value(false)
        .logarithmic(spec.logarithmic);
    if spec.logarithmic && *spec.range.start() <= 0.0 {
        // 0 at the left end, then the decades from a ten-thousandth of the top.
        slider = slider.smallest_positive(spec.range.end() * 1e-4);
    }
    let r = ui.add(slider).accessible_name(spec.label);
    let last = ui.data(|d| d.get_temp::<DragMemory>(id));
    ui.data_mut(|d| d.insert_temp(id, DragMemory { raw }));
    if !r.changed() {
        return (r, None);
    }
    let fine = ui.input(|i| i.modifiers.shift_only());
    let next = match last {
        Some(DragMemory { raw: before }) if fine && r.dragged() && !r.drag_started() => {
            fine_step(value, before, raw, spec.logarithmic)
        }
        _ => raw,
    };
    let next = next.clamp(*spec.range.start(), *spec.range.end());
    (r, Some(NumberInput::Dragged(next)))
}

/// `value` moved by a tenth of the slider's move from `before` to `after`: in
/// ratio on a logarithmic slider (where both are positive), else in difference.
fn fine_step(value: f64, before: f64, after: f64, logarithmic: bool) -> f64 {
    if logarithmic && value > 0.0 && before > 0.0 && after > 0.0 {
        value * (after / before).powf(FINE)
    } else {
        value + FINE * (after - before)
    }
}

/// The box's text while it is being typed into.
#[derive(Clone, Debug, Default)]
struct Typing {
    text: String,
}

/// The box: the value, or while focused the text being typed. Returns it and the
/// typed value when the user presses Enter or leaves the box; a refusal is kept
/// under the `row`'s id.
fn number_box(
    ui: &mut egui::Ui,
    row: egui::Id,
    spec: &NumberSpec<'_>,
    value: f64,
) -> (egui::Response, Option<NumberInput>) {
    let id = row.with("box");
    let focused = ui.memory(|m| m.has_focus(id));
    let mut text = if focused {
        ui.data(|d| d.get_temp::<Typing>(id))
            .map_or_else(|| format_value(value), |t| t.text)
    } else {
        format_value(value)
    };
    let r = ui
        .add(
            egui::TextEdit::singleline(&mut text)
                .id(id)
                .desired_width(box_width(ui)),
        )
        .accessible_name(spec.label);
    if r.gained_focus() {
        ui.data_mut(|d| d.remove::<Refusal>(row));
    }
    if r.has_focus() {
        ui.data_mut(|d| d.insert_temp(id, Typing { text: text.clone() }));
        return (r, None);
    }
    ui.data_mut(|d| d.remove::<Typing>(id));
    let escaped = ui.input(|i| i.key_pressed(egui::Key::Escape));
    // Typed and left, or set whole without the keyboard (a screen reader's value).
    let set = (r.lost_focus() && !escaped) || r.changed();
    if !set || text == format_value(value) {
        return (r, None);
    }
    match spec.take(&text) {
        Ok(v) => (r, Some(NumberInput::Typed(v))),
        Err(refusal) => {
            ui.data_mut(|d| d.insert_temp(row, refusal));
            (r, None)
        }
    }
}

/// The row's last refusal, until the user types into the box again.
fn refusal_line(ui: &mut egui::Ui, row: egui::Id, spec: &NumberSpec<'_>, value: f64) {
    if let Some(words) = refusal_words(ui, row, spec, value) {
        ui.colored_label(ui.visuals().warn_fg_color, words);
    }
}

/// The row's last refusal in words, if it has one.
fn refusal_words(
    ui: &egui::Ui,
    row: egui::Id,
    spec: &NumberSpec<'_>,
    value: f64,
) -> Option<String> {
    ui.data(|d| d.get_temp::<Refusal>(row))
        .map(|refusal| refusal.words(spec, value))
}

/// A box alone, with no slider (the cam panel's lift and roller): the same typing,
/// refusal and stable id as a row's. Returns the box's response.
pub fn boxed(
    ui: &mut egui::Ui,
    key: impl std::hash::Hash + std::fmt::Debug,
    spec: &NumberSpec<'_>,
    value: f64,
) -> (egui::Response, NumberInput) {
    ui.push_id(key, |ui| {
        let row = ui.scope_id();
        let inner = ui.horizontal(|ui| {
            let typed = number_box(ui, row, spec, value);
            ui.label(spec.label);
            typed
        });
        refusal_line(ui, row, spec, value);
        let (field, typed) = inner.inner;
        (field, typed.unwrap_or(NumberInput::None))
    })
    .inner
}

/// A box in a table's cell, its row naming it (the cam's segments): the label is
/// the box's accessible name only, and a refusal is returned in words for the
/// table to show under it (in the cell it would widen the column and run out of
/// the pane unread).
pub fn cell(
    ui: &mut egui::Ui,
    key: impl std::hash::Hash + std::fmt::Debug,
    spec: &NumberSpec<'_>,
    value: f64,
) -> (egui::Response, NumberInput, Option<String>) {
    ui.push_id(key, |ui| {
        let row = ui.scope_id();
        let inner = ui.horizontal(|ui| {
            let typed = number_box(ui, row, spec, value);
            if !spec.unit.is_empty() {
                ui.label(spec.unit);
            }
            typed
        });
        let (field, typed) = inner.inner;
        let refusal = refusal_words(ui, row, spec, value);
        (field, typed.unwrap_or(NumberInput::None), refusal)
    })
    .inner
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every way a student writes a number is read whole; what is not a number or
    /// is out of range is refused with why.
    #[test]
    fn typed_numbers_are_read_whole_or_refused() {
        let r = 0.0..=1e5;
        for (text, want) in [
            ("300", 300.0),
            (" 0.125 ", 0.125),
            ("1e3", 1000.0),
            ("0,5", 0.5),
            ("300 N/m", 300.0),
        ] {
            assert_eq!(parse(text, "N/m", &r), Ok(want), "{text}");
        }
        assert_eq!(parse("-45", "°", &(-180.0..=180.0)), Ok(-45.0));
        assert_eq!(parse("-45°", "°", &(-180.0..=180.0)), Ok(-45.0));
        assert!(matches!(
            parse("3OO", "", &r),
            Err(Refusal::NotANumber { .. })
        ));
        assert!(matches!(parse("", "", &r), Err(Refusal::NotANumber { .. })));
        assert!(matches!(
            parse("nan", "", &r),
            Err(Refusal::NotANumber { .. })
        ));
        assert_eq!(
            parse("2e5", "", &r),
            Err(Refusal::OutOfRange {
                value: 2e5,
                range: [0.0, 1e5]
            })
        );
    }

    /// The refusal names the number, the valid range with its unit, and what was
    /// kept.
    #[test]
    fn a_refusal_names_the_range_and_the_value_kept() {
        let spec = NumberSpec::new("k F-G (N/m)", "N/m", 0.0..=150_000.0);
        let words = Refusal::OutOfRange {
            value: 2e5,
            range: [0.0, 1.5e5],
        }
        .words(&spec, 1500.0);
        assert_eq!(
            words,
            "k F-G (N/m): 200000 N/m is outside the range 0 … 150000 N/m; kept 1500 N/m"
        );
    }

    #[test]
    fn values_show_six_significant_digits_without_trailing_zeros() {
        assert_eq!(format_value(117.658_123), "117.658");
        assert_eq!(format_value(0.125), "0.125");
        assert_eq!(format_value(1500.0), "1500");
        assert_eq!(format_value(-45.0), "-45");
        assert_eq!(format_value(1e-8), "1e-8");
        assert_eq!(format_value(0.0), "0");
        // What the box shows reads back as the same value to six digits.
        for v in [0.31, 117.658, 2.5e-3, 1234.5, 98_765.4] {
            let back: f64 = format_value(v).parse().expect("a number");
            assert!((back - v).abs() <= 1e-5 * v.abs(), "{v}");
        }
    }

    /// A full turn's angle wraps: -45° is 315°, 1e3° is 280°.
    #[test]
    fn a_full_turn_wraps_what_is_typed() {
        let crank = NumberSpec::new("crank", "°", 0.0..=360.0).wrapping();
        assert_eq!(crank.take("-45"), Ok(315.0));
        assert_eq!(crank.take("1e3"), Ok(280.0));
        assert!(crank.take("x").is_err());
    }

    /// Shift's fine step: a tenth of the move, in ratio on a logarithmic slider.
    #[test]
    fn a_fine_step_is_a_tenth_of_the_move() {
        assert!((fine_step(100.0, 100.0, 190.0, false) - 109.0).abs() < 1e-12);
        let logged = fine_step(100.0, 100.0, 1000.0, true);
        assert!((logged - 100.0 * 10f64.powf(0.1)).abs() < 1e-9);
    }
}
