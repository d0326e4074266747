//! LU factorization with partial pivoting of a small dense square matrix, kept in
//! buffers that the Newton solver reuses from one position to the next.
//!
//! The Newton path factors one loop-closure Jacobian (2×2 for a four-bar, 4×4 for
//! a six-bar) at every position. nalgebra's `LU` takes its matrix by value and
//! allocates its permutation, so each factorization cost a copy and two heap
//! allocations, more than the arithmetic itself at these sizes.

use nalgebra::{DMatrix, DVector};

/// An LU factorization `P A = L U` (unit lower `L`), or none yet.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct SmallLu {
    n: usize,
    /// Row-major `L` (below the diagonal) and `U` (on and above it).
    lu: Vec<f64>,
    /// At step `k`, row `k` was swapped with row `pivots[k]`.
    pivots: Vec<usize>,
    /// Determinant of `P`: ±1.
    permutation_sign: f64,
    valid: bool,
}

impl SmallLu {
    /// Factors `a` (square), reusing the buffers.
    pub(crate) fn factor(&mut self, a: &DMatrix<f64>) {
        let n = a.nrows();
        self.n = n;
        self.lu.clear();
        self.lu
            .extend((0..n * n).map(|index| a[(index / n, index % n)]));
        self.pivots.clear();
        self.permutation_sign = 1.0;
        for k in 0..n {
            let pivot = (k..n)
                .max_by(|&i, &j| {
                    self.lu[i * n + k]
                        .abs()
                        .total_cmp(&self.lu[j * n + k].abs())
                })
                .unwrap_or(k);
            self.pivots.push(pivot);
            if pivot != k {
                for c in 0..n {
                    self.lu.swap(k * n + c, pivot * n + c);
                }
                self.permutation_sign = -self.permutation_sign;
            }
            let diagonal = self.lu[k * n + k];
            if diagonal == 0.0 {
                // Singular: the column below is all zero, nothing to eliminate.
                continue;
            }
            for r in k + 1..n {
                let factor = self.lu[r * n + k] / diagonal;
                self.lu[r * n + k] = factor;
                for c in k + 1..n {
                    self.lu[r * n + c] -= factor * self.lu[k * n + c];
                }
            }
        }
        self.valid = true;
    }

    /// Whether a factorization is held.
    pub(crate) fn is_valid(&self) -> bool {
        self.valid
    }

    /// Drops the factorization (its matrix no longer describes the pose).
    pub(crate) fn invalidate(&mut self) {
        self.valid = false;
    }

    /// Determinant of the factored matrix.
    pub(crate) fn determinant(&self) -> f64 {
        (0..self.n)
            .map(|k| self.lu[k * self.n + k])
            .product::<f64>()
            * self.permutation_sign
    }

    /// Solves `A x = b` in place; false (and `b` unspecified) when no factorization
    /// is held or `A` is singular.
    pub(crate) fn solve_mut(&self, b: &mut DVector<f64>) -> bool {
        let n = self.n;
        if !self.valid || b.len() != n || (0..n).any(|k| self.lu[k * n + k] == 0.0) {
            return false;
        }
        for (k, &p) in self.pivots.iter().enumerate() {
            b.swap_rows(k, p);
        }
        for r in 1..n {
            let sum: f64 = (0..r).map(|c| self.lu[r * n + c] * b[c]).sum();
            b[r] -= sum;
        }
        for r in (0..n).rev() {
            let sum: f64 = (r + 1..n).map(|c| self.lu[r * n + c] * b[c]).sum();
            b[r] = (b[r] - sum) / self.lu[r * n + r];
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against nalgebra's LU on matrices that need pivoting, and on a singular one.
    #[test]
    fn matches_nalgebra_lu() {
        let cases = [
            DMatrix::from_row_slice(2, 2, &[0.0, 2.0, 3.0, 1.0]),
            DMatrix::from_row_slice(
                4,
                4,
                &[
                    1e-3, 2.0, -1.0, 0.5, 4.0, -2.0, 0.0, 1.0, -1.5, 0.25, 3.0, 2.0, 0.5, 1.0, 1.0,
                    -3.0,
                ],
            ),
        ];
        let mut lu = SmallLu::default();
        for a in cases {
            lu.factor(&a);
            let reference = a.clone().lu();
            assert!((lu.determinant() - reference.determinant()).abs() < 1e-12);
            let b = DVector::from_fn(a.nrows(), |i, _| 1.0 + i as f64);
            let mut x = b.clone();
            assert!(lu.solve_mut(&mut x));
            assert!((&a * &x - &b).amax() < 1e-12, "residual of {x}");
        }
        lu.factor(&DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 2.0, 4.0]));
        assert_eq!(lu.determinant(), 0.0);
        assert!(!lu.solve_mut(&mut DVector::from_element(2, 1.0)));
        lu.invalidate();
        assert!(!lu.solve_mut(&mut DVector::from_element(2, 1.0)));
    }
}
