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
    /// Column-major like nalgebra: `L` below the diagonal, `U` on and above it;
    /// entry (row r, column c) at `r + c·n`.
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
        self.lu.extend_from_slice(a.as_slice());
        self.pivots.clear();
        self.permutation_sign = 1.0;
        let lu = &mut self.lu[..];
        for k in 0..n {
            let column = &lu[k * n..(k + 1) * n];
            let mut pivot = k;
            for r in k + 1..n {
                if column[r].abs() > column[pivot].abs() {
                    pivot = r;
                }
            }
            self.pivots.push(pivot);
            if pivot != k {
                for c in 0..n {
                    lu.swap(k + c * n, pivot + c * n);
                }
                self.permutation_sign = -self.permutation_sign;
            }
            let diagonal = lu[k + k * n];
            if diagonal == 0.0 {
                // Singular: the column below is all zero, nothing to eliminate.
                continue;
            }
            for r in k + 1..n {
                lu[r + k * n] /= diagonal;
            }
            for c in k + 1..n {
                let upper = lu[k + c * n];
                for r in k + 1..n {
                    lu[r + c * n] -= lu[r + k * n] * upper;
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
            .map(|k| self.lu[k + k * self.n])
            .product::<f64>()
            * self.permutation_sign
    }

    /// Solves `A x = b` in place; false (and `b` unspecified) when no factorization
    /// is held or `A` is singular.
    pub(crate) fn solve_mut(&self, b: &mut DVector<f64>) -> bool {
        let n = self.n;
        let lu = &self.lu[..];
        let b = b.as_mut_slice();
        if !self.valid || b.len() != n || (0..n).any(|k| lu[k + k * n] == 0.0) {
            return false;
        }
        for (k, &p) in self.pivots.iter().enumerate() {
            b.swap(k, p);
        }
        // Forward, then back substitution, column by column.
        for c in 0..n {
            let x = b[c];
            for r in c + 1..n {
                b[r] -= lu[r + c * n] * x;
            }
        }
        for c in (0..n).rev() {
            b[c] /= lu[c + c * n];
            let x = b[c];
            for r in 0..c {
                b[r] -= lu[r + c * n] * x;
            }
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
