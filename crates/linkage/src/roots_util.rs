//! Root refinement over brackets found on a grid: Brent–Dekker (zeroin).
//!
//! Written here rather than taken from the `roots` crate: its 0.0.8 Brent returns a
//! stale iterate on convergence and missed the slider-crank's dead centre at 2π
//! (regression test `slider_crank_dead_centre_at_two_pi`).

/// A root of `f` in `[a, b]` where `f(a)` and `f(b)` differ in sign, to about
/// 4 ulp of the root; `None` without a sign change or with non-finite values.
pub fn refine(a: f64, b: f64, mut f: impl FnMut(f64) -> f64) -> Option<f64> {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = (f(a), f(b));
    if !(fa.is_finite() && fb.is_finite()) || fa * fb > 0.0 {
        return None;
    }
    let (mut c, mut fc) = (a, fa);
    let (mut d, mut e) = (b - a, b - a);
    for _ in 0..200 {
        if (fb > 0.0) == (fc > 0.0) && fb != 0.0 {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa) = (b, fb);
            (b, fb) = (c, fc);
            (c, fc) = (a, fa);
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 1e-300;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Some(b);
        }
        if e.abs() < tol || fa.abs() <= fb.abs() {
            d = m;
            e = m;
        } else {
            // Inverse quadratic interpolation, or secant when only two points differ.
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * m * s, 1.0 - s)
            } else {
                let (q, r) = (fa / fc, fb / fc);
                (
                    s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0)),
                    (q - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
        if !fb.is_finite() {
            return None;
        }
    }
    Some(b)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Against closed-form roots: simple, cubic (flat) and at a bracket end.
    #[test]
    fn brent_finds_known_roots_to_ulps() {
        let r = refine(0.0, 2.0, |x| x * x - 2.0).unwrap_or(f64::NAN);
        assert!((r - 2f64.sqrt()).abs() <= 4.0 * f64::EPSILON, "{r}");
        let r = refine(6.0, 6.5, f64::sin).unwrap_or(f64::NAN);
        assert!((r - std::f64::consts::TAU).abs() <= 1e-15 * 8.0, "{r}");
        // A cubic zero is flat: f ~ 1e-16 already 5e-6 away, so ask only for that.
        let r = refine(-1.0, 0.7, |x: f64| (x - 0.1).powi(3)).unwrap_or(f64::NAN);
        assert!((r - 0.1).abs() < 1e-5, "{r}");
        assert_eq!(refine(0.0, 1.0, |x| x), Some(0.0));
        assert_eq!(refine(1.0, 2.0, |x| x), None);
    }
}
