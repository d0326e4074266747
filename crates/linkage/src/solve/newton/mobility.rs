//! The chain's true mobility, from the rank of its constraint Jacobian.
//!
//! Counting links and joints (Grübler) is fooled by redundant joints: a five-bar (two
//! degrees of freedom) with a brace between two points of one rigid link counts as 1.
//! The Jacobian of the loop closures with respect to every tree coordinate, the input
//! included, has a null space of the true mobility's dimension. At a dead point of the
//! input only the columns without the input lose rank, so that alone is not mistaken
//! for a second freedom; a change point, where a chain is momentarily 2-DOF, is a
//! single pose, so the rank is taken at two unrelated poses and the smaller
//! deficiency counts.

use nalgebra::DMatrix;

use super::{Solver, TreeKind};
use crate::motion::LinkMotion;

/// Singular values below this fraction of the largest count as zero.
const RANK_TOLERANCE: f64 = 1e-9;

impl Solver<'_> {
    /// Degrees of freedom of the chain (1 for a mechanism with one input), from the
    /// constraint Jacobian's rank at the current coordinates and at a shaken copy of
    /// them (the poses need not close: the rank is generic).
    pub(super) fn mobility(&mut self, input: f64, links: &mut [LinkMotion]) -> usize {
        let saved = self.state.q.clone();
        let mut least = usize::MAX;
        for shake in [0.0, 0.37] {
            for (k, t) in self.model.tree.iter().enumerate().skip(1) {
                if matches!(t.kind, TreeKind::Revolute { .. }) {
                    self.state.q[k - 1] = saved[k - 1] + shake * (k as f64).sin();
                }
            }
            self.position_pass(input + shake, links);
            self.build_jacobian(links);
            least = least.min(self.null_space_dimension());
        }
        self.state.q.copy_from(&saved);
        self.state.lu.invalidate();
        least
    }

    /// Dimension of the null space of [driver column | J] as last built.
    pub(super) fn null_space_dimension(&self) -> usize {
        let (rows, n) = (self.work.jac.nrows(), self.work.jac.ncols());
        let full = DMatrix::from_fn(rows, n + 1, |r, c| {
            if c == 0 {
                self.work.rates[r]
            } else {
                self.work.jac[(r, c - 1)]
            }
        });
        let values = full.singular_values();
        let largest = values.max();
        let rank = values
            .iter()
            .filter(|&&s| s > RANK_TOLERANCE * largest)
            .count();
        n + 1 - rank
    }
}
