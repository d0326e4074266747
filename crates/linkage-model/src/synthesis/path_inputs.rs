//! What the synthesis window's path tab asks for, free of any GUI type: the targets
//! (placed on its canvas, dragged, or typed and pasted as CSV), whether they are
//! timed, and the constraints; and the search and design table they give.

use linkage::synthesis::path::{
    PathConstraints, PathDesign, PathLinkage, PathSearch, PathTargets, SearchOptions, TargetOrder,
    TurnsWith,
};
use linkage::synthesis::rows::{RowError, read_rows};

use crate::synthesis::design::{Design, Figure};

/// One target, in the units the window shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Target {
    /// Where, mm.
    pub at_mm: [f64; 2],
    /// The crank angle there, deg (used when the targets are timed).
    pub crank_deg: f64,
}

/// The path tab's inputs.
#[derive(Clone, Debug, PartialEq)]
pub struct PathInputs {
    /// The targets in order.
    pub targets: Vec<Target>,
    /// The crank angles are prescribed.
    pub timed: bool,
    /// Untimed targets may be met in any order (else in the order given).
    pub any_order: bool,
    /// The crank must turn through a whole revolution.
    pub crank_turns: bool,
    /// Least transmission angle over the travel, deg.
    pub min_transmission_deg: f64,
    /// The targets on one branch.
    pub one_branch: bool,
    /// Seed of the search.
    pub seed: u64,
    /// Within tolerance: largest miss over the targets' size.
    pub tolerance: f64,
}

impl Default for PathInputs {
    fn default() -> Self {
        // Eight points of a crank-rocker's coupler curve every 45° of its crank,
        // rounded to 0.1 mm (so no four-bar meets them exactly).
        let at = [
            [98.2, 205.8],
            [104.4, 280.9],
            [40.0, 294.0],
            [-36.8, 244.4],
            [-78.8, 161.0],
            [-72.6, 87.7],
            [-27.4, 61.5],
            [36.4, 106.6],
        ];
        Self {
            targets: at
                .iter()
                .zip(0..)
                .map(|(&at_mm, k)| Target {
                    at_mm,
                    crank_deg: 10.0 + 45.0 * f64::from(k),
                })
                .collect(),
            timed: false,
            any_order: false,
            crank_turns: false,
            min_transmission_deg: 0.0,
            one_branch: true,
            seed: 1,
            tolerance: 1e-4,
        }
    }
}

impl PathInputs {
    /// The targets as CSV rows: `x_mm, y_mm` or, timed, `x_mm, y_mm, crank_deg`.
    /// Places are written to 1e-7 of the targets' extent (a clicked target carries
    /// sixteen digits that no one reads, and its row would wrap), angles to 1e-6 deg.
    pub fn to_csv(&self) -> String {
        let extent = self
            .targets
            .iter()
            .flat_map(|t| t.at_mm)
            .map(f64::abs)
            .fold(0.0, f64::max);
        let places = decimals_for(extent, 1e-7);
        let write = |v: f64, d: usize| trimmed(&format!("{v:.d$}"));
        self.targets
            .iter()
            .map(|t| {
                let [x, y] = t.at_mm.map(|v| write(v, places));
                if self.timed {
                    format!("{x}, {y}, {}\n", write(t.crank_deg, 6))
                } else {
                    format!("{x}, {y}\n")
                }
            })
            .collect()
    }

    /// Reads targets from CSV rows (two numbers, or three when timed), as
    /// `linkage synth path` reads its file: blank lines, `#` comments and a header
    /// skipped.
    ///
    /// # Errors
    /// A row that is not that many numbers, named by its line.
    pub fn read_csv(&mut self, text: &str) -> Result<(), RowError> {
        let width = if self.timed { 3 } else { 2 };
        let rows = read_rows(text, width)?;
        let targets = rows
            .iter()
            .enumerate()
            .map(|(k, v)| Target {
                at_mm: [v[0], v[1]],
                crank_deg: v.get(2).copied().unwrap_or(30.0 * k as f64),
            })
            .collect();
        self.targets = targets;
        Ok(())
    }

    /// Adds a target at `at_mm`, its crank angle 30° after the last one's.
    pub fn add(&mut self, at_mm: [f64; 2]) {
        let crank_deg = self.targets.last().map_or(0.0, |t| t.crank_deg + 30.0);
        self.targets.push(Target { at_mm, crank_deg });
    }

    /// The search these inputs ask for.
    ///
    /// # Errors
    /// Targets or constraints the search refuses, with the cause and valid range.
    pub fn search(&self) -> Result<PathSearch, linkage::LinkageError> {
        let targets = PathTargets {
            points_m: self
                .targets
                .iter()
                .map(|t| t.at_mm.map(|v| v * 1e-3))
                .collect(),
            crank_deg: self
                .timed
                .then(|| self.targets.iter().map(|t| t.crank_deg).collect()),
        };
        let constraints = PathConstraints {
            crank_turns: self.crank_turns,
            min_transmission_deg: self.min_transmission_deg,
            ground_region_m: None,
            one_branch: self.one_branch,
            order: if self.any_order {
                TargetOrder::Any
            } else {
                TargetOrder::AsGiven
            },
        };
        let options = SearchOptions {
            seed: self.seed,
            tolerance: self.tolerance,
            max_evaluations: 1_000_000,
            ..SearchOptions::default()
        };
        PathSearch::new(&targets, &constraints, options)
    }
}

/// Which four-bar of a design's family: the design, or one of its two cognates.
pub type Member = usize;

/// The four-bar `member` of `d`'s family (0: the design; 1, 2: its cognates), if
/// it has one.
pub fn member_of(d: &PathDesign, member: Member) -> Option<&PathLinkage> {
    match member {
        0 => Some(&d.linkage),
        k => d.cognates.get(k - 1).map(|c| &c.linkage),
    }
}

/// What a cognate's crank turns with: a few words for the list, a sentence for the
/// table.
pub fn turns_with(t: TurnsWith, long: bool) -> &'static str {
    match (t, long) {
        (TurnsWith::Crank, false) => "turns with the crank",
        (TurnsWith::Coupler, false) => "turns with the coupler",
        (TurnsWith::Rocker, false) => "turns with the rocker",
        (TurnsWith::Crank, true) => "turns with the design's crank (the same timing)",
        (TurnsWith::Coupler, true) => "turns with the design's coupler",
        (TurnsWith::Rocker, true) => "turns with the design's rocker",
    }
}

/// The table and scene of the four-bar `member` of `d`'s family.
pub fn design_of(d: &PathDesign, member: Member) -> Option<Design> {
    let l = member_of(d, member)?;
    let mm = |m: f64| format!("{:.3} mm", m * 1e3);
    let point = |p: [f64; 2]| format!("({:.3}, {:.3}) mm", p[0] * 1e3, p[1] * 1e3);
    let ground = (l.pivot_d[0] - l.pivot_a[0]).hypot(l.pivot_d[1] - l.pivot_a[1]);
    let row = |what: &str, value: String| (what.to_owned(), value);
    let mut table = vec![
        row("Grashof class", l.grashof.to_string()),
        row("crank AB", mm(l.crank_m)),
        row("coupler BC", mm(l.coupler_m)),
        row("rocker CD", mm(l.rocker_m)),
        row("ground AD", mm(ground)),
        row("crank pivot A", point(l.pivot_a)),
        row("rocker pivot D", point(l.pivot_d)),
        row("coupler point P from B along BC", point(l.coupler_point_m)),
        row(
            "largest miss",
            format!(
                "{} ({:.1e} of the targets' size)",
                mm(d.max_error_m),
                d.relative_error
            ),
        ),
        row(
            "crank turns fully",
            if l.crank_turns { "yes" } else { "no" }.into(),
        ),
        row(
            "least transmission angle",
            l.min_transmission_deg.map_or_else(
                || "the travel leaves the branch".into(),
                |m| format!("{m:.1}°"),
            ),
        ),
    ];
    if let Some(c) = member.checked_sub(1).and_then(|k| d.cognates.get(k)) {
        table.insert(
            0,
            row("cognate: its crank", turns_with(c.turns_with, true).into()),
        );
    }
    let scene = match member {
        0 => d.scene(),
        k => d.cognate_scene(k - 1)?,
    };
    Some(Design {
        table,
        scene,
        figure: Figure::None,
    })
}

/// Decimal places that show `share` of `extent` (none for an extent of zero or
/// less, as many as a double holds at most).
fn decimals_for(extent: f64, share: f64) -> usize {
    if !(extent > 0.0 && extent.is_finite()) {
        return 6;
    }
    (-(extent * share).log10()).ceil().clamp(0.0, 17.0) as usize
}

/// A decimal number without trailing zeros (and without a trailing point, or the
/// sign of a zero).
fn trimmed(text: &str) -> String {
    let t = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        text
    };
    if t == "-0" { "0".into() } else { t.into() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_round_trips_and_names_a_bad_line() {
        let mut inputs = PathInputs {
            timed: true,
            ..PathInputs::default()
        };
        let text = inputs.to_csv();
        let before = inputs.targets.clone();
        inputs.read_csv(&text).expect("reads its own CSV");
        assert_eq!(inputs.targets, before);
        let e = inputs
            .read_csv("1, 2, 3\n\n4, x, 6\n")
            .expect_err("refused");
        assert_eq!(e.line, 3);
        assert_eq!(inputs.targets, before, "a refused paste keeps the targets");
    }

    /// A targets file that `linkage synth path` reads (a header, a comment) reads the
    /// same when pasted into the app.
    #[test]
    fn a_targets_file_the_cli_reads_pastes_into_the_app() {
        let mut inputs = PathInputs::default();
        let text = "x_mm, y_mm\n# traced from the drawing\n10, 20\n\n30, 40.5\n";
        inputs.read_csv(text).expect("reads the CLI's file");
        let at: Vec<[f64; 2]> = inputs.targets.iter().map(|t| t.at_mm).collect();
        assert_eq!(at, [[10.0, 20.0], [30.0, 40.5]]);
    }

    /// A clicked target's sixteen digits are written to 1e-7 of the targets' extent,
    /// from a micrometre mechanism to a metre one, each row short enough for one line
    /// of the text field, and read back within that.
    #[test]
    fn clicked_targets_are_written_short_at_every_scale() {
        for scale in [1e-3, 1.0, 1e3] {
            let mut inputs = PathInputs::default();
            for t in &mut inputs.targets {
                t.at_mm = t.at_mm.map(|v| (v + 0.123_456_789_012_345) * scale);
            }
            let before = inputs.targets.clone();
            let text = inputs.to_csv();
            let longest = text.lines().map(str::len).max().unwrap_or(0);
            assert!(longest <= 30, "scale {scale}: {text}");
            inputs.read_csv(&text).expect("reads its own CSV");
            let extent = before
                .iter()
                .flat_map(|t| t.at_mm)
                .map(f64::abs)
                .fold(0.0, f64::max);
            for (a, b) in inputs.targets.iter().zip(&before) {
                for k in 0..2 {
                    assert!(
                        (a.at_mm[k] - b.at_mm[k]).abs() <= 1e-7 * extent,
                        "scale {scale}: {text}"
                    );
                }
            }
        }
    }
}
