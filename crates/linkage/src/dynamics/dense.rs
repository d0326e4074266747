//! Dense output: the state anywhere inside an accepted step, for events and for
//! output on a uniform time grid.

use super::rhs::{Point, State};

/// The continuous extension of one step from `t0` over `h`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Dense {
    /// Cubic Hermite per component from the values and derivatives at both ends
    /// (fixed-step methods). Third order: each component has its own derivative.
    Hermite { a: Point, b: Point },
    /// The method's own interpolant in Hairer's nested form
    /// y(θ) = r0 + θ(r1 + (1−θ)(r2 + θ(r3 + (1−θ)(r4 + …)))), θ = (t − t0)/h.
    Nested {
        t0: f64,
        h: f64,
        /// Coefficients r0… per state component; `terms` of them are used.
        r: [[f64; 8]; 3],
        terms: usize,
    },
}

impl Dense {
    /// The state at `t` (clamped into the step).
    pub fn eval(&self, t: f64) -> State {
        match self {
            Dense::Hermite { a, b } => {
                let h = b.t - a.t;
                if h == 0.0 {
                    return a.y;
                }
                let s = ((t - a.t) / h).clamp(0.0, 1.0);
                let (s2, s3) = (s * s, s * s * s);
                let (h00, h10, h01, h11) = (
                    2.0 * s3 - 3.0 * s2 + 1.0,
                    s3 - 2.0 * s2 + s,
                    -2.0 * s3 + 3.0 * s2,
                    s3 - s2,
                );
                std::array::from_fn(|i| {
                    h00 * a.y[i] + h10 * h * a.f[i] + h01 * b.y[i] + h11 * h * b.f[i]
                })
            }
            Dense::Nested { t0, h, r, terms } => {
                let s = if *h == 0.0 {
                    0.0
                } else {
                    ((t - t0) / h).clamp(0.0, 1.0)
                };
                let s1 = 1.0 - s;
                std::array::from_fn(|i| {
                    // Horner from the innermost term outwards, alternating θ and 1 − θ.
                    let mut acc = 0.0;
                    for k in (1..*terms).rev() {
                        let factor = if k % 2 == 1 { s } else { s1 };
                        acc = factor * (r[i][k] + acc);
                    }
                    r[i][0] + acc
                })
            }
        }
    }
}
