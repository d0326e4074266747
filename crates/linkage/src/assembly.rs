//! Where a chain assembles: its input intervals as data, the grid the analyses
//! sample them on, and their wording. A leaf module: the solver's errors carry these
//! ranges, and the kinematics, Newton's branch tracing and the analyses fill them.

use serde::Serialize;

const TAU: f64 = std::f64::consts::TAU;
/// Grid used to bracket roots over a full turn: 0.5 deg.
pub(crate) const GRID: usize = 720;

/// Input intervals (rad) over which the chain assembles on its branch.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AssemblyRanges {
    /// True when the input turns fully (a crank).
    pub full_rotation: bool,
    /// Intervals `[start, end]` in rad, ascending within [0, 2π) (end may pass 2π).
    pub intervals: Vec<[f64; 2]>,
}

impl AssemblyRanges {
    /// A full turn.
    pub fn full_turn() -> Self {
        Self {
            full_rotation: true,
            intervals: vec![[0.0, TAU]],
        }
    }

    /// The one interval `[lo, hi]` (unwrapped, any turn), started within [0, 2π).
    pub fn between(lo: f64, hi: f64) -> Self {
        let a = lo.rem_euclid(TAU);
        Self {
            full_rotation: false,
            intervals: vec![[a, a + (hi - lo)]],
        }
    }

    /// The interval holding input `x` (any turn), else the first; `None` when the
    /// chain assembles nowhere.
    pub fn containing(&self, x: f64) -> Option<[f64; 2]> {
        let x = x.rem_euclid(TAU);
        let holds = |[a, b]: &&[f64; 2]| (*a <= x && x <= *b) || (*a <= x + TAU && x + TAU <= *b);
        self.intervals
            .iter()
            .find(holds)
            .or(self.intervals.first())
            .copied()
    }

    /// Grid over the ranges: for a full turn one closed loop from `start`, else each
    /// interval shrunk by a hair (the ends are dead points where velocities are
    /// undefined).
    pub(crate) fn grids(&self, start: f64) -> Vec<Vec<f64>> {
        if self.full_rotation {
            // Offset by a fraction of a step: scenes start at symmetric angles (0, 90
            // deg) where limits often sit exactly, and a root on a grid point has no
            // sign change.
            const OFFSET: f64 = 0.3713;
            return vec![
                (0..=GRID)
                    .map(|i| start + TAU * (i as f64 + OFFSET) / GRID as f64)
                    .collect(),
            ];
        }
        self.intervals
            .iter()
            .map(|&[a, b]| {
                let n = ((b - a) / TAU * GRID as f64).ceil().max(16.0) as usize;
                let eps = 1e-9 * (b - a);
                (0..=n)
                    .map(|i| a + eps + (b - a - 2.0 * eps) * i as f64 / n as f64)
                    .collect()
            })
            .collect()
    }
}

/// "reachable input range: 34.30..117.70 deg" and similar.
impl std::fmt::Display for AssemblyRanges {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.full_rotation {
            return f.write_str("the chain assembles at every input angle");
        }
        if self.intervals.is_empty() {
            return f.write_str("the chain assembles at no input angle (check link lengths)");
        }
        f.write_str("reachable input range: ")?;
        for (n, [a, b]) in self.intervals.iter().enumerate() {
            if n > 0 {
                f.write_str(" or ")?;
            }
            write!(f, "{:.2}..{:.2} deg", a.to_degrees(), b.to_degrees())?;
        }
        Ok(())
    }
}
