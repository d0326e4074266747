//! The implicit midpoint rule, for stiff springs.
//!
//! y₁ = y₀ + h f((y₀ + y₁)/2). It is A-stable (no step-size limit from a stiff
//! spring), symplectic and time-reversible (energy error bounded, no drift) and
//! second order. The midpoint m = (y₀ + y₁)/2 solves m = y₀ + (h/2) f(m) by
//! simplified Newton iterations on (x, v) with the Jacobian of f at y₀
//! ([`Rhs::linearise`]). The work w follows explicitly from the converged midpoint.

use super::rhs::{Point, Rhs, State};
use crate::error::{ImplicitFailure, LinkageError, Result, RunRefusal};

/// Newton iterations before the step is declared not converged.
const MAX_ITERATIONS: usize = 25;

/// One implicit midpoint step from `a` over `h`.
pub(crate) fn midpoint(rhs: &mut Rhs, a: &Point, h: f64) -> Result<Point> {
    let (x0, v0) = (a.y[0], a.y[1]);
    let (acc_x, acc_v) = rhs.linearise(a)?;
    // Iteration matrix I − (h/2) ∂f/∂y for (x, v), with ∂f/∂y = [[0, 1], [acc_x, acc_v]].
    let g = 0.5 * h;
    let (m11, m12, m21, m22) = (1.0, -g, -g * acc_x, 1.0 - g * acc_v);
    let det = m11 * m22 - m12 * m21;
    if !(det.is_finite() && det.abs() > 1e-300) {
        return Err(not_converged(a, h, ImplicitFailure::SingularMatrix));
    }
    let mut m: State = std::array::from_fn(|i| a.y[i] + g * a.f[i]);
    // Corrections measured against 1e-12 of the state and of the step's change in v;
    // a stiff spring's accelerations carry round-off above that, so an iteration
    // that stops shrinking at a small size has converged as far as it can.
    let unit = [
        1e-12 * (1.0 + x0.abs()),
        1e-12 * (1.0 + v0.abs() + (g * a.f[1]).abs()),
    ];
    let mut previous = f64::INFINITY;
    for _ in 0..MAX_ITERATIONS {
        let (f, _) = rhs.eval(&m)?;
        let r0 = m[0] - a.y[0] - g * f[0];
        let r1 = m[1] - a.y[1] - g * f[1];
        let d0 = (m22 * r0 - m12 * r1) / det;
        let d1 = (m11 * r1 - m21 * r0) / det;
        m[0] -= d0;
        m[1] -= d1;
        if !(m[0].is_finite() && m[1].is_finite()) {
            break;
        }
        let size = (d0 / unit[0]).abs().max((d1 / unit[1]).abs());
        if size <= 1.0 || (size < 1e4 && size > 0.5 * previous) {
            // The power at the last iterate differs from the converged one by the
            // (negligible) last correction.
            let y = [2.0 * m[0] - x0, 2.0 * m[1] - v0, a.y[2] + h * f[2]];
            return rhs.point(a.t + h, y);
        }
        previous = size;
    }
    Err(not_converged(a, h, ImplicitFailure::NoConvergence))
}

fn not_converged(a: &Point, h: f64, why: ImplicitFailure) -> LinkageError {
    LinkageError::Run(Box::new(RunRefusal::ImplicitNotConverged {
        step_s: h,
        t_s: a.t,
        why,
    }))
}
