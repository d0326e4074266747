//! What the synthesis window's path tab asks for, free of any GUI type: the targets
//! (placed on its canvas, dragged, or typed and pasted as CSV), whether they are
//! timed, and the constraints; and the search and design table they give.

use linkage::synthesis::path::{
    PathConstraints, PathDesign, PathSearch, PathTargets, SearchOptions,
};

use crate::synthesis::Design;

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
            crank_turns: true,
            min_transmission_deg: 0.0,
            one_branch: true,
            seed: 1,
            tolerance: 1e-4,
        }
    }
}

impl PathInputs {
    /// The targets as CSV rows: `x_mm, y_mm` or, timed, `x_mm, y_mm, crank_deg`.
    pub fn to_csv(&self) -> String {
        self.targets
            .iter()
            .map(|t| {
                let [x, y] = t.at_mm;
                if self.timed {
                    format!("{x}, {y}, {}\n", t.crank_deg)
                } else {
                    format!("{x}, {y}\n")
                }
            })
            .collect()
    }

    /// Reads targets from CSV rows (two numbers, or three when timed; blank lines
    /// skipped).
    ///
    /// # Errors
    /// A row that is not that many numbers, named by its line.
    pub fn read_csv(&mut self, text: &str) -> Result<(), String> {
        let width = if self.timed { 3 } else { 2 };
        let rows = crate::synthesis::numbers(text, width)?;
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
    pub fn search(&self) -> Result<PathSearch, String> {
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
        };
        let options = SearchOptions {
            seed: self.seed,
            tolerance: self.tolerance,
            max_evaluations: 1_000_000,
            ..SearchOptions::default()
        };
        PathSearch::new(&targets, &constraints, options).map_err(|e| e.to_string())
    }
}

/// The table and scene of a path design.
pub fn design_of(d: &PathDesign) -> Design {
    let mm = |m: f64| format!("{:.3} mm", m * 1e3);
    let point = |p: [f64; 2]| format!("({:.3}, {:.3}) mm", p[0] * 1e3, p[1] * 1e3);
    let ground = (d.pivot_d[0] - d.pivot_a[0]).hypot(d.pivot_d[1] - d.pivot_a[1]);
    let row = |what: &str, value: String| (what.to_owned(), value);
    Design {
        table: vec![
            row("crank AB", mm(d.crank_m)),
            row("coupler BC", mm(d.coupler_m)),
            row("rocker CD", mm(d.rocker_m)),
            row("ground AD", mm(ground)),
            row("crank pivot A", point(d.pivot_a)),
            row("rocker pivot D", point(d.pivot_d)),
            row("coupler point P from B along BC", point(d.coupler_point_m)),
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
                if d.crank_turns { "yes" } else { "no" }.into(),
            ),
            row(
                "least transmission angle",
                d.min_transmission_deg.map_or_else(
                    || "the travel leaves the branch".into(),
                    |m| format!("{m:.1}°"),
                ),
            ),
        ],
        scene: d.scene(),
        figure: crate::synthesis::Figure::None,
    }
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
        assert!(e.contains("line 3"), "{e}");
        assert_eq!(inputs.targets, before, "a refused paste keeps the targets");
    }
}
