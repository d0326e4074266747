//! Adaptive embedded Runge–Kutta steps: Dormand–Prince 5(4) and 8(5,3), with their
//! error estimates, step-size control and dense output.
//!
//! Written here rather than taken from a crate because the right-hand side is a
//! kinematic solve that can fail (beyond an assembly limit): a failed stage must
//! reject the step and shrink it, not panic or poison the state with NaN. The ODE
//! crates we looked at (ode_solvers, differential-equations) take infallible
//! right-hand sides and do not expose a step's interpolant, which the events and the
//! coordinate switch need.

use super::dense::Dense;
use super::rhs::{Point, Rhs, State};
use super::tableaus::{DOP853_A, DOP853_BHH, DOP853_D, DOP853_E5, DP5_A, DP5_D, DP5_E};
use crate::error::Result;

/// Which embedded pair.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Pair {
    Dp5,
    Dop853,
}

impl Pair {
    /// 1 / (order of the error estimate + 1), the step-size exponent.
    fn error_exponent(self) -> f64 {
        match self {
            Pair::Dp5 => 1.0 / 5.0,
            Pair::Dop853 => 1.0 / 8.0,
        }
    }

    /// Step-size limits (smallest and largest factor) and PI weight β.
    fn control(self) -> (f64, f64, f64) {
        match self {
            Pair::Dp5 => (0.2, 10.0, 0.04),
            // Growth capped at 4 rather than Hairer's 6: on the flipper this cut the
            // rejected steps (12 evaluations each) more than it added accepted ones.
            Pair::Dop853 => (1.0 / 3.0, 4.0, 0.04),
        }
    }
}

/// Safety factor on the predicted step (0.8, as MATLAB's ode45; Hairer uses 0.9):
/// the error estimates of this smooth but strongly varying problem swing enough that
/// the margin pays for itself in fewer rejections.
const SAFETY: f64 = 0.8;

/// Step-size controller state: a PI controller (Gustafsson) that remembers the last
/// accepted error, which damps the accept/reject see-saw of a pure I controller when
/// an error estimate happens to pass near zero.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Controller {
    err_old: f64,
    after_reject: bool,
}

impl Default for Controller {
    fn default() -> Self {
        Self {
            err_old: 1e-4,
            after_reject: false,
        }
    }
}

/// Tolerances: x must be within atol + rtol·|x| per step, and v within
/// atol·rate + rtol·|v|, where `rate` is the run's own rate scale (1/s): an absolute
/// tolerance on a speed in rad/s would be loose for a fast small machine and tight
/// for a slow large one, and the same machine at another scale would take other steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tolerance {
    pub rtol: f64,
    pub atol: f64,
    /// The run's rate scale, 1/s (see [`rate_scale`](super::run)).
    pub rate: f64,
}

impl Tolerance {
    /// The absolute part of the tolerance of component `i` (0: x, rad; 1: v, rad/s).
    fn absolute(&self, i: usize) -> f64 {
        if i == 0 {
            self.atol
        } else {
            self.atol * self.rate
        }
    }

    /// RMS over x and v of the error scaled by the tolerance (w is not controlled:
    /// it follows from x and v).
    fn norm(&self, err: &State, y0: &State, y1: &State) -> f64 {
        let sum: f64 = (0..2)
            .map(|i| {
                let scale = self.absolute(i) + self.rtol * y0[i].abs().max(y1[i].abs());
                (err[i] / scale).powi(2)
            })
            .sum();
        (sum / 2.0).sqrt()
    }
}

/// The stage derivatives of one step (16 for DOP853 with dense output).
pub(crate) struct Stages {
    k: [State; 16],
}

impl Default for Stages {
    fn default() -> Self {
        Self { k: [[0.0; 3]; 16] }
    }
}

/// An attempted step.
pub(crate) enum Attempt {
    /// Accepted: the end point, the scaled error (≤ 1) and the next step size.
    Accepted { end: Point, error: f64, h_next: f64 },
    /// Rejected (error too large or a stage could not be solved): retry with `h_next`.
    Rejected { h_next: f64 },
}

/// y0 + h Σ a_j k_j over the first `n` stages.
fn combine(y0: &State, h: f64, a: &[f64], k: &[State], n: usize) -> State {
    std::array::from_fn(|i| {
        let s: f64 = a.iter().zip(k).take(n).map(|(aj, kj)| aj * kj[i]).sum();
        y0[i] + h * s
    })
}

/// Evaluates the stages `range` in order, each at y0 + h Σ a_ij k_j over the stages
/// before it (row i of `rows`).
fn eval_stages<const N: usize>(
    rhs: &mut Rhs,
    a: &Point,
    h: f64,
    rows: &[[f64; N]],
    range: std::ops::Range<usize>,
    st: &mut Stages,
) -> Result<()> {
    for (i, row) in rows.iter().enumerate().take(range.end).skip(range.start) {
        let y = combine(&a.y, h, row, &st.k, i);
        st.k[i] = rhs.eval(&y)?.0;
    }
    Ok(())
}

/// One step of `pair` from `a` with size `h`. After a rejection growth is capped,
/// as the error model has just been wrong.
pub(crate) fn step(
    rhs: &mut Rhs,
    pair: Pair,
    tol: &Tolerance,
    a: &Point,
    h: f64,
    ctl: &mut Controller,
    st: &mut Stages,
) -> Attempt {
    let shrink = Attempt::Rejected { h_next: 0.25 * h };
    let result: Result<(Point, f64)> = match pair {
        Pair::Dp5 => dp5(rhs, tol, a, h, st),
        Pair::Dop853 => dop853(rhs, tol, a, h, st),
    };
    let Ok((end, error)) = result else {
        return shrink;
    };
    if !error.is_finite() {
        return shrink;
    }
    let (min_factor, max_factor, beta) = pair.control();
    let alpha = pair.error_exponent() - 0.75 * beta;
    if error <= 1.0 {
        let e = error.max(1e-10);
        let grow = (SAFETY * e.powf(-alpha) * ctl.err_old.powf(beta)).clamp(min_factor, max_factor);
        let grow = if ctl.after_reject {
            grow.min(1.0)
        } else {
            grow
        };
        *ctl = Controller {
            err_old: e.max(1e-4),
            after_reject: false,
        };
        Attempt::Accepted {
            end,
            error,
            h_next: h * grow,
        }
    } else {
        ctl.after_reject = true;
        let shrink = (SAFETY * error.powf(-alpha)).clamp(min_factor, 0.9);
        Attempt::Rejected { h_next: h * shrink }
    }
}

fn dp5(rhs: &mut Rhs, tol: &Tolerance, a: &Point, h: f64, st: &mut Stages) -> Result<(Point, f64)> {
    st.k[0] = a.f;
    eval_stages(rhs, a, h, &DP5_A, 1..7, st)?;
    let y1 = combine(&a.y, h, &DP5_A[6], &st.k, 6);
    // Stage 7 was evaluated at y1: its reduction is the end point's.
    let reduced = rhs.reduce_here(&y1)?;
    let err = combine(&[0.0; 3], h, &DP5_E, &st.k, 7);
    let end = Point {
        t: a.t + h,
        y: y1,
        f: st.k[6],
        reduced,
    };
    Ok((end, tol.norm(&err, &a.y, &y1)))
}

fn dop853(
    rhs: &mut Rhs,
    tol: &Tolerance,
    a: &Point,
    h: f64,
    st: &mut Stages,
) -> Result<(Point, f64)> {
    st.k[0] = a.f;
    eval_stages(rhs, a, h, &DOP853_A, 1..12, st)?;
    let y1 = combine(&a.y, h, &DOP853_A[12], &st.k, 12);
    let (f1, reduced) = rhs.eval(&y1)?;
    st.k[12] = f1;
    // Hairer's combined estimate: the fifth-order error, damped where the third-order
    // one says the fifth-order one is pessimistic.
    let err5 = combine(&[0.0; 3], h, &DOP853_E5, &st.k, 12);
    let b = &DOP853_A[12];
    let err3: State = std::array::from_fn(|i| {
        let s: f64 = b
            .iter()
            .zip(&st.k)
            .take(12)
            .map(|(bj, kj)| bj * kj[i])
            .sum();
        h * (s
            - DOP853_BHH[0] * st.k[0][i]
            - DOP853_BHH[1] * st.k[8][i]
            - DOP853_BHH[2] * st.k[11][i])
    });
    let (n5, n3) = (
        tol.norm(&err5, &a.y, &y1).powi(2),
        tol.norm(&err3, &a.y, &y1).powi(2),
    );
    let error = if n5 == 0.0 && n3 == 0.0 {
        0.0
    } else {
        n5 / (n5 + 0.01 * n3).sqrt()
    };
    let end = Point {
        t: a.t + h,
        y: y1,
        f: f1,
        reduced,
    };
    Ok((end, error))
}

/// The dense output of the step just accepted from `a` to `b` (DOP853: three more
/// evaluations; DP5: none).
pub(crate) fn dense(
    rhs: &mut Rhs,
    pair: Pair,
    a: &Point,
    b: &Point,
    st: &mut Stages,
) -> Result<Dense> {
    let h = b.t - a.t;
    let mut r = [[0.0; 8]; 3];
    let terms = match pair {
        Pair::Dp5 => {
            let d = combine(&[0.0; 3], h, &DP5_D, &st.k, 7);
            for i in 0..3 {
                let diff = b.y[i] - a.y[i];
                let bspl = h * a.f[i] - diff;
                r[i][..5].copy_from_slice(&[a.y[i], diff, bspl, diff - h * b.f[i] - bspl, d[i]]);
            }
            5
        }
        Pair::Dop853 => {
            eval_stages(rhs, a, h, &DOP853_A, 13..16, st)?;
            let d: [State; 4] =
                std::array::from_fn(|row| combine(&[0.0; 3], h, &DOP853_D[row], &st.k, 16));
            for i in 0..3 {
                let diff = b.y[i] - a.y[i];
                let bspl = h * a.f[i] - diff;
                r[i] = [
                    a.y[i],
                    diff,
                    bspl,
                    diff - h * b.f[i] - bspl,
                    d[0][i],
                    d[1][i],
                    d[2][i],
                    d[3][i],
                ];
            }
            8
        }
    };
    Ok(Dense::Nested {
        t0: a.t,
        h,
        r,
        terms,
    })
}

/// A first step size from the start's scale and curvature (Hairer's rule, one
/// evaluation), so that the caller need not guess one.
pub(crate) fn initial_step(
    rhs: &mut Rhs,
    pair: Pair,
    tol: &Tolerance,
    a: &Point,
    t_span: f64,
) -> f64 {
    let scaled = |v: &State| -> f64 {
        let s: f64 = (0..2)
            .map(|i| (v[i] / (tol.absolute(i) + tol.rtol * a.y[i].abs())).powi(2))
            .sum();
        (s / 2.0).sqrt()
    };
    let (d0, d1) = (scaled(&a.y), scaled(&a.f));
    // Hairer's fallback of 1e-6 s, in the run's own time scale.
    let tiny = 1e-6 / tol.rate;
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        tiny
    } else {
        0.01 * d0 / d1
    }
    .min(t_span);
    let y1: State = std::array::from_fn(|i| a.y[i] + h0 * a.f[i]);
    let Ok((f1, _)) = rhs.eval(&y1) else {
        return h0;
    };
    let diff: State = std::array::from_fn(|i| f1[i] - a.f[i]);
    let d2 = scaled(&diff) / h0;
    let order = 1.0 / pair.error_exponent();
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(tiny)
    } else {
        (0.01 / d1.max(d2)).powf(1.0 / order)
    };
    (100.0 * h0).min(h1).min(t_span)
}
