//! Function generation: a four-bar whose output rocker angle φ follows a prescribed
//! function of its input crank angle θ, by Freudenstein's equation. With the ground
//! pivots A at the origin and D at (d, 0), crank AB = a at θ, coupler BC = b and
//! rocker DC = c at φ, the loop closes exactly when
//!
//! K1 cos φ − K2 cos θ + K3 = cos(θ − φ),
//! K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac),
//!
//! which is linear in K1, K2, K3: three precision points (θᵢ, φᵢ) give them exactly,
//! more give them by least squares (of the equation's residual). The linkage then
//! matches the function at the precision points; between them it misses by the
//! structural error, which [`structural_error`] measures on the solved linkage.

use nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use serde::Serialize;

use crate::error::DesignRefusal;
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::scene::SceneFile;

/// A prescribed input and output angle pair, rad.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PrecisionPoint {
    /// Crank angle θ, rad (from A→D).
    pub input_rad: f64,
    /// Rocker angle φ, rad (from A→D).
    pub output_rad: f64,
}

/// A four-bar for function generation. A negative crank or rocker length means the
/// link points the other way: the vector from its pivot is `length · (cos, sin)` of
/// the prescribed angle, as Freudenstein's equation has it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct FunctionFourBar {
    /// Freudenstein's K1 = d/a, K2 = d/c, K3.
    pub k: [f64; 3],
    /// Crank a (signed), coupler b, rocker c (signed), ground d.
    pub lengths: [f64; 4],
}

/// The Chebyshev spacing of `n` precision points over `[x0, x1]`: the nodes of the
/// degree-n Chebyshev polynomial, which make the largest structural error of a
/// polynomial-like fit least.
pub fn chebyshev_spacing(x0: f64, x1: f64, n: usize) -> Vec<f64> {
    (1..=n)
        .map(|j| {
            let t = std::f64::consts::PI * (2 * j - 1) as f64 / (2 * n) as f64;
            0.5 * (x0 + x1) - 0.5 * (x1 - x0) * t.cos()
        })
        .collect()
}

/// The four-bar with ground `ground_m` through `points`: exact for three points,
/// least squares for more.
///
/// # Errors
/// Fewer than three points, a value that is not finite, points that do not fix the
/// constants (two with the same angles), or constants that make no linkage (a
/// zero-length crank or rocker, or a coupler whose square is not positive).
pub fn freudenstein(points: &[PrecisionPoint], ground_m: f64) -> Result<FunctionFourBar> {
    check(points, ground_m)?;
    let row = |p: &PrecisionPoint| {
        (
            [p.output_rad.cos(), -p.input_rad.cos(), 1.0],
            (p.input_rad - p.output_rad).cos(),
        )
    };
    let k = if points.len() == 3 {
        let mut m = Matrix3::zeros();
        let mut rhs = Vector3::zeros();
        for (i, p) in points.iter().enumerate() {
            let (r, y) = row(p);
            m.set_row(i, &nalgebra::RowVector3::from(r));
            rhs[i] = y;
        }
        m.lu().solve(&rhs).map(|k| [k[0], k[1], k[2]])
    } else {
        let n = points.len();
        let mut m = DMatrix::zeros(n, 3);
        let mut rhs = DVector::zeros(n);
        for (i, p) in points.iter().enumerate() {
            let (r, y) = row(p);
            for (j, v) in r.into_iter().enumerate() {
                m[(i, j)] = v;
            }
            rhs[i] = y;
        }
        // QR keeps the least-squares solve as well conditioned as the points allow.
        let qr = m.qr();
        let qty = qr.q().transpose() * rhs;
        qr.r()
            .solve_upper_triangular(&qty)
            .map(|k| [k[0], k[1], k[2]])
    };
    let k = k
        .filter(|k| k.iter().all(|v| v.is_finite()))
        .ok_or_else(|| {
            LinkageError::invalid(
                Param::PrecisionPoints,
                points.len() as f64,
                Valid::DistinctPoints,
            )
        })?;
    lengths(k, ground_m)
}

fn check(points: &[PrecisionPoint], ground_m: f64) -> Result<()> {
    if points.len() < 3 {
        return Err(LinkageError::invalid(
            Param::PrecisionPoints,
            points.len() as f64,
            Valid::AtLeast(3),
        ));
    }
    if !(ground_m.is_finite() && ground_m > 0.0) {
        return Err(LinkageError::invalid(
            Param::GroundLength,
            ground_m,
            Valid::PositiveLength,
        ));
    }
    match points
        .iter()
        .flat_map(|p| [p.input_rad, p.output_rad])
        .find(|v| !v.is_finite())
    {
        Some(v) => Err(LinkageError::invalid(
            Param::PrecisionPointAngle,
            v,
            Valid::FiniteAngle,
        )),
        None => Ok(()),
    }
}

/// The link lengths of Freudenstein's constants with ground `d`.
fn lengths(k: [f64; 3], d: f64) -> Result<FunctionFourBar> {
    let [k1, k2, k3] = k;
    let tiny = 1e-12;
    if k1.abs() < tiny || k2.abs() < tiny {
        return Err(DesignRefusal::InfiniteLink { k1, k2 }.into());
    }
    let (a, c) = (d / k1, d / k2);
    let b2 = a * a + c * c + d * d - 2.0 * a * c * k3;
    if b2.is_nan() || b2 <= tiny * d * d {
        return Err(DesignRefusal::NoCoupler {
            k,
            coupler_squared: b2,
        }
        .into());
    }
    Ok(FunctionFourBar {
        k,
        lengths: [a, b2.sqrt(), c, d],
    })
}

impl FunctionFourBar {
    /// Crank pin B and rocker pin C at crank angle `input_rad` and rocker angle
    /// `output_rad`, m (A at the origin, D at (d, 0)).
    pub fn pins(&self, input_rad: f64, output_rad: f64) -> ([f64; 2], [f64; 2]) {
        let [a, _, c, d] = self.lengths;
        (
            [a * input_rad.cos(), a * input_rad.sin()],
            [d + c * output_rad.cos(), c * output_rad.sin()],
        )
    }

    /// Whether C lies left of the line from B to D at these angles: the assembly
    /// branch (the scene's `Left("B", "D")`).
    pub fn c_left_of_bd(&self, input_rad: f64, output_rad: f64) -> bool {
        let ([bx, by], [cx, cy]) = self.pins(input_rad, output_rad);
        let d = self.lengths[3];
        (d - bx) * (cy - by) - (-by) * (cx - bx) > 0.0
    }

    /// The rocker angle at crank angle `input_rad` on the branch `left` (see
    /// [`FunctionFourBar::c_left_of_bd`]), or `None` where the chain does not close.
    /// Closed form: C = D + c(cos φ, sin φ) at distance b from B gives
    /// P cos φ + Q sin φ = R.
    pub fn output_at(&self, input_rad: f64, left: bool) -> Option<f64> {
        let [a, b, c, d] = self.lengths;
        let (ex, ey) = (d - a * input_rad.cos(), -a * input_rad.sin());
        let (p, q) = (2.0 * c * ex, 2.0 * c * ey);
        let r = b * b - ex * ex - ey * ey - c * c;
        let h = p.hypot(q);
        if h == 0.0 || (r / h).abs() > 1.0 {
            return None;
        }
        let (base, spread) = (q.atan2(p), (r / h).acos());
        [base + spread, base - spread]
            .into_iter()
            .find(|&phi| self.c_left_of_bd(input_rad, phi) == left)
    }
}

/// The structural error of `linkage` at the precision points: the largest
/// |φ(θᵢ) − φᵢ| on the branch of the first point, rad (angles compared modulo a
/// turn); `None` where the chain does not close at one of them.
pub fn structural_error(linkage: &FunctionFourBar, points: &[PrecisionPoint]) -> Option<f64> {
    let first = points.first()?;
    let left = linkage.c_left_of_bd(first.input_rad, first.output_rad);
    points.iter().try_fold(0.0f64, |worst, p| {
        let phi = linkage.output_at(p.input_rad, left)?;
        Some(worst.max(angle_between(phi, p.output_rad)))
    })
}

/// The structural error of `linkage` over crank angles `range` (rad): the
/// generated output on the branch of `first` less the desired output
/// `desired(θ)`, wrapped into ±π, at `samples + 1` evenly spaced angles as
/// `[θ, error]` pairs (rad); angles where the chain does not close are left out.
pub fn error_curve(
    linkage: &FunctionFourBar,
    first: PrecisionPoint,
    range: [f64; 2],
    desired: impl Fn(f64) -> f64,
    samples: usize,
) -> Vec<[f64; 2]> {
    let left = linkage.c_left_of_bd(first.input_rad, first.output_rad);
    let tau = std::f64::consts::TAU;
    (0..=samples)
        .filter_map(|k| {
            let theta = range[0] + (range[1] - range[0]) * k as f64 / samples.max(1) as f64;
            let phi = linkage.output_at(theta, left)?;
            let e = (phi - desired(theta) + std::f64::consts::PI).rem_euclid(tau)
                - std::f64::consts::PI;
            Some([theta, e])
        })
        .collect()
}

/// |x − y| modulo a turn, rad.
fn angle_between(x: f64, y: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    let d = (x - y).rem_euclid(tau);
    d.min(tau - d)
}

impl FunctionFourBar {
    /// The four-bar as a scene (metres, crank at 60 rpm), starting at precision point
    /// `start` on its branch. The crank's input angle is θ, plus a half turn where
    /// the crank length is negative; likewise the rocker's angle and φ.
    pub fn scene(&self, start: PrecisionPoint) -> SceneFile {
        let [a, b, c, d] = self.lengths;
        let half_turn = if a < 0.0 { std::f64::consts::PI } else { 0.0 };
        let mut scene = super::four_bar(&super::FourBar {
            pivot_a: [0.0, 0.0],
            pivot_d: [d, 0.0],
            lengths_m: [a.abs(), b, c.abs()],
            start_deg: (start.input_rad + half_turn).to_degrees(),
            c_left_of_bd: self.c_left_of_bd(start.input_rad, start.output_rad),
            coupler_point: None,
        });
        let [k1, k2, k3] = self.k;
        scene.name = "Function generator (Freudenstein)".into();
        scene.description = format!(
            "Four-bar from Freudenstein's equation: K1 = {k1:.6}, K2 = {k2:.6}, K3 = {k3:.6}; AB = {:.6} m, BC = {b:.6} m, CD = {:.6} m, AD = {d:.6} m.",
            a.abs(),
            c.abs()
        );
        scene
    }
}
