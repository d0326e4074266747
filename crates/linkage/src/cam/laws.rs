//! Cam motion laws, normalised: the follower's rise s(u) from 0 to 1 over the
//! segment's fraction u ∈ [0, 1], with its derivatives v = ds/du, a = d²s/du² and
//! j = d³s/du³. A program scales them by the lift and the segment's cam angle.
//!
//! The trigonometric and polynomial laws are their textbook formulas. The modified
//! trapezoid, modified sine and modified constant velocity are defined by their
//! acceleration — sine quarter-waves and constants joined end to end — and integrated
//! here in closed form piece by piece, their amplitude set so that s(1) = 1: so each
//! value is exact, not a quadrature.

use std::sync::LazyLock;

use serde::{Deserialize, Serialize};

/// A motion law for a rise (a return is a rise run backwards).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Law {
    /// s = u: infinite acceleration at the ends (only for teaching).
    ConstantVelocity,
    /// s = (1 − cos πu)/2: acceleration jumps at the ends.
    SimpleHarmonic,
    /// s = u − sin(2πu)/(2π): acceleration continuous, jerk jumps.
    Cycloidal,
    /// s = 10u³ − 15u⁴ + 6u⁵.
    Polynomial345,
    /// s = 35u⁴ − 84u⁵ + 70u⁶ − 20u⁷: jerk continuous.
    Polynomial4567,
    /// Acceleration: sine ramps over the first and last eighths of each half, constant
    /// between (Neklutin).
    ModifiedTrapezoid,
    /// Acceleration: a sine quarter-wave over the first eighth, a slower one (three
    /// times the period) to the last eighth, mirrored (Kloomok and Muffley).
    ModifiedSine,
    /// Constant velocity over the middle half, reached by a modified-sine
    /// acceleration over the first quarter (MCV 50).
    ModifiedConstantVelocity,
}

/// The normalised motion at one u: s and its first three derivatives by u.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Motion {
    /// Displacement (0 to 1).
    pub s: f64,
    /// ds/du.
    pub v: f64,
    /// d²s/du².
    pub a: f64,
    /// d³s/du³.
    pub j: f64,
}

const PI: f64 = std::f64::consts::PI;

impl Law {
    /// Every law, in the order the textbooks list them.
    pub const ALL: [Self; 8] = [
        Self::ConstantVelocity,
        Self::SimpleHarmonic,
        Self::Cycloidal,
        Self::Polynomial345,
        Self::Polynomial4567,
        Self::ModifiedTrapezoid,
        Self::ModifiedSine,
        Self::ModifiedConstantVelocity,
    ];

    /// The motion at `u`, clamped to [0, 1].
    pub fn at(self, u: f64) -> Motion {
        let u = u.clamp(0.0, 1.0);
        match self {
            Self::ConstantVelocity => Motion {
                s: u,
                v: 1.0,
                a: 0.0,
                j: 0.0,
            },
            Self::SimpleHarmonic => {
                let (sn, cs) = (PI * u).sin_cos();
                Motion {
                    s: 0.5 * (1.0 - cs),
                    v: 0.5 * PI * sn,
                    a: 0.5 * PI * PI * cs,
                    j: -0.5 * PI.powi(3) * sn,
                }
            }
            Self::Cycloidal => {
                let w = 2.0 * PI;
                let (sn, cs) = (w * u).sin_cos();
                Motion {
                    s: u - sn / w,
                    v: 1.0 - cs,
                    a: w * sn,
                    j: w * w * cs,
                }
            }
            Self::Polynomial345 => polynomial(&[0.0, 0.0, 0.0, 10.0, -15.0, 6.0], u),
            Self::Polynomial4567 => polynomial(&[0.0, 0.0, 0.0, 0.0, 35.0, -84.0, 70.0, -20.0], u),
            Self::ModifiedTrapezoid => MODIFIED_TRAPEZOID.at(u),
            Self::ModifiedSine => MODIFIED_SINE.at(u),
            Self::ModifiedConstantVelocity => MODIFIED_CONSTANT_VELOCITY.at(u),
        }
    }

    /// Its name as the textbooks give it.
    pub fn label(self) -> &'static str {
        match self {
            Self::ConstantVelocity => "constant velocity",
            Self::SimpleHarmonic => "simple harmonic",
            Self::Cycloidal => "cycloidal",
            Self::Polynomial345 => "3-4-5 polynomial",
            Self::Polynomial4567 => "4-5-6-7 polynomial",
            Self::ModifiedTrapezoid => "modified trapezoid",
            Self::ModifiedSine => "modified sine",
            Self::ModifiedConstantVelocity => "modified constant velocity",
        }
    }
}

/// s, s', s'', s''' of Σ c_k u^k.
fn polynomial(c: &[f64], u: f64) -> Motion {
    let mut m = Motion::default();
    for (k, &ck) in c.iter().enumerate() {
        let k = k as i32;
        let p = |d: i32| -> f64 {
            if k < d {
                return 0.0;
            }
            let falling: f64 = (0..d).map(|i| f64::from(k - i)).product();
            ck * falling * u.powi(k - d)
        };
        m.s += p(0);
        m.v += p(1);
        m.a += p(2);
        m.j += p(3);
    }
    m
}

// The piecewise laws, joined once: joining evaluates every piece's end (two sines
// each), which per call made a modified-sine point cost eight sines instead of two,
// and the cam feed's cam evaluates its law some thousands of times per edit.
static MODIFIED_TRAPEZOID: LazyLock<Pieces> = LazyLock::new(Pieces::modified_trapezoid);
static MODIFIED_SINE: LazyLock<Pieces> = LazyLock::new(Pieces::modified_sine);
static MODIFIED_CONSTANT_VELOCITY: LazyLock<Pieces> =
    LazyLock::new(Pieces::modified_constant_velocity);

/// One piece of a piecewise acceleration: a(u) = c0 + c1 sin(ω (u − u0) + φ) on
/// [u0, u1], with the velocity and displacement it starts from.
#[derive(Clone, Copy, Debug)]
struct Piece {
    u0: f64,
    u1: f64,
    c0: f64,
    c1: f64,
    omega: f64,
    phi: f64,
    /// sin φ and cos φ, made once with the piece.
    sin_cos_phi: (f64, f64),
    v0: f64,
    s0: f64,
}

impl Piece {
    /// The motion at `u` in this piece, by the closed-form integrals of a(u).
    fn at(&self, u: f64) -> Motion {
        let x = u - self.u0;
        let (c0, c1, w, f) = (self.c0, self.c1, self.omega, self.phi);
        if c1 == 0.0 || w == 0.0 {
            return Motion {
                s: self.s0 + self.v0 * x + 0.5 * c0 * x * x,
                v: self.v0 + c0 * x,
                a: c0,
                j: 0.0,
            };
        }
        let (sn, cs) = (w * x + f).sin_cos();
        let (sn0, cs0) = self.sin_cos_phi;
        Motion {
            s: self.s0 + self.v0 * x + 0.5 * c0 * x * x - c1 / w * ((sn - sn0) / w - cs0 * x),
            v: self.v0 + c0 * x - c1 / w * (cs - cs0),
            a: c0 + c1 * sn,
            j: c1 * w * cs,
        }
    }
}

/// A law given by its piecewise acceleration, scaled so that s(1) = 1.
struct Pieces(Vec<Piece>);

impl Pieces {
    /// Joins pieces given as (u1, c0, c1, ω, φ) from u = 0, carrying v and s across,
    /// then scales the acceleration so that the rise ends at 1.
    fn joined(spec: &[(f64, f64, f64, f64, f64)]) -> Self {
        let mut pieces = Vec::with_capacity(spec.len());
        let (mut u0, mut v0, mut s0) = (0.0, 0.0, 0.0);
        for &(u1, c0, c1, omega, phi) in spec {
            let p = Piece {
                u0,
                u1,
                c0,
                c1,
                omega,
                phi,
                sin_cos_phi: phi.sin_cos(),
                v0,
                s0,
            };
            let end = p.at(u1);
            (u0, v0, s0) = (u1, end.v, end.s);
            pieces.push(p);
        }
        let scale = 1.0 / s0;
        for p in &mut pieces {
            p.c0 *= scale;
            p.c1 *= scale;
            p.v0 *= scale;
            p.s0 *= scale;
        }
        Self(pieces)
    }

    fn at(&self, u: f64) -> Motion {
        let p = self
            .0
            .iter()
            .find(|p| u <= p.u1)
            .unwrap_or_else(|| self.0.last().expect("a law has pieces"));
        p.at(u)
    }

    /// Quarter sine waves of period 1/2 over the first and last eighths, the
    /// constant acceleration between, on each half.
    fn modified_trapezoid() -> Self {
        let w = 4.0 * PI;
        Self::joined(&[
            (0.125, 0.0, 1.0, w, 0.0),
            (0.375, 1.0, 0.0, 0.0, 0.0),
            (0.625, 0.0, 1.0, w, 0.5 * PI),
            (0.875, -1.0, 0.0, 0.0, 0.0),
            (1.0, 0.0, 1.0, w, PI + 0.5 * PI),
        ])
    }

    /// A quarter sine wave of period 1/2 to the peak at 1/8, then one of period 3/2
    /// down through zero at 1/2 to the trough at 7/8, then back to zero at 1.
    fn modified_sine() -> Self {
        let (fast, slow) = (4.0 * PI, 4.0 * PI / 3.0);
        Self::joined(&[
            (0.125, 0.0, 1.0, fast, 0.0),
            (0.875, 0.0, 1.0, slow, 0.5 * PI),
            (1.0, 0.0, 1.0, fast, PI + 0.5 * PI),
        ])
    }

    /// A modified-sine acceleration over the first quarter (peak at 1/16), constant
    /// velocity over the middle half, the mirror over the last quarter.
    fn modified_constant_velocity() -> Self {
        let (fast, slow) = (8.0 * PI, 8.0 * PI / 3.0);
        Self::joined(&[
            (0.0625, 0.0, 1.0, fast, 0.0),
            (0.25, 0.0, 1.0, slow, 0.5 * PI),
            (0.75, 0.0, 0.0, 0.0, 0.0),
            (0.9375, 0.0, -1.0, slow, 0.0),
            (1.0, 0.0, -1.0, fast, 0.5 * PI),
        ])
    }
}
