//! Root refinement (Brent's method from the `roots` crate) over brackets found on a grid.

/// Convergence: bracket narrower than 1e-14 rad or an exact zero, at most 200 iterations.
struct Tight;

impl roots::Convergency<f64> for Tight {
    fn is_root_found(&mut self, y: f64) -> bool {
        y == 0.0
    }
    fn is_converged(&mut self, x1: f64, x2: f64) -> bool {
        (x1 - x2).abs() <= 1e-14 * (1.0 + x1.abs())
    }
    fn is_iteration_limit_reached(&mut self, iter: usize) -> bool {
        iter >= 200
    }
}

/// A root of `f` in `[a, b]` where `f(a)` and `f(b)` differ in sign; `None` when `f`
/// is not finite inside the bracket or Brent gives up.
pub(crate) fn refine(a: f64, b: f64, mut f: impl FnMut(f64) -> f64) -> Option<f64> {
    let mut conv = Tight;
    let root = roots::find_root_brent(a, b, |x| f(x), &mut conv).ok()?;
    root.is_finite().then_some(root)
}

/// Indices `k` where `values[k]` and `values[k + 1]` have opposite signs (a zero at
/// `values[k] == 0` counts once, on its left).
pub(crate) fn sign_changes(values: &[f64]) -> Vec<usize> {
    (0..values.len().saturating_sub(1))
        .filter(|&k| {
            let (a, b) = (values[k], values[k + 1]);
            a.is_finite() && b.is_finite() && ((a < 0.0 && b >= 0.0) || (a > 0.0 && b <= 0.0))
        })
        .collect()
}
