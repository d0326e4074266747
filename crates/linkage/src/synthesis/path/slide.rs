//! Placing a curve on targets whose places on it are known only roughly: Gauss–Newton
//! on the similarity and the places together, each target sliding along the curve
//! ("point-to-plane" iterative closest points). For fixed places the best similarity
//! of the misses across the curve (the component along it is taken up by sliding)
//! is a linear least-squares problem in four unknowns; each place then moves by its
//! miss along the tangent. Plain closest points (point-to-point) converge linearly and
//! slowly along a gently curved arc, and a coarse cost that stops early scores the
//! true linkage worse than impostors nearby; this converges quadratically where the
//! targets lie on the curve.

use nalgebra::{Complex, Matrix4, Vector4};

use super::geometry::CouplerFourBar;
use super::shape::{Similarity, complex, fit};

/// Places of targets on a curve sampled at evenly spaced crank angles: fractional
/// sample indices x, at crank angle `start + step·x`, kept within `0..=last` and in
/// order.
pub struct Places<'a> {
    /// The unit curve.
    pub unit: &'a CouplerFourBar,
    /// Crank angle at index 0, rad.
    pub start: f64,
    /// Crank angle per index, rad (negative for a clockwise travel).
    pub step: f64,
    /// The last index.
    pub last: f64,
}

impl Places<'_> {
    fn angle(&self, x: f64) -> f64 {
        self.start + self.step * x
    }

    /// The curve's point and its derivative per index at index `x`.
    fn point_and_tangent(&self, x: f64) -> Option<(Complex<f64>, Complex<f64>)> {
        let (p, tangent) = self.unit.point_and_tangent_at(self.angle(x))?;
        Some((complex(p), complex(tangent * self.step)))
    }

    /// `rounds` Gauss–Newton steps from places `x` and similarity `sim`; returns the
    /// similarity fitted at the final places and its sum of squared misses, with `x`
    /// moved. `None` where the curve does not close at a place.
    pub fn slide(
        &self,
        targets: &[Complex<f64>],
        x: &mut [f64],
        mut sim: Similarity,
        rounds: usize,
    ) -> Option<(Similarity, f64)> {
        let n = x.len();
        let mut points = vec![Complex::new(0.0, 0.0); n];
        let mut tangents = vec![Complex::new(0.0, 0.0); n];
        for _ in 0..rounds {
            for i in 0..n {
                (points[i], tangents[i]) = self.point_and_tangent(x[i])?;
            }
            if let Some(better) = across(&points, &tangents, targets, &sim) {
                sim = better;
            }
            self.slide_places(&points, &tangents, targets, &sim, x);
        }
        for i in 0..n {
            points[i] = complex(self.unit.point_at(self.angle(x[i]))?);
        }
        fit(&points, targets)
    }

    /// Moves each place by its miss along the curve's tangent, within its neighbours'
    /// places (the order holds) and by at most one sample.
    fn slide_places(
        &self,
        points: &[Complex<f64>],
        tangents: &[Complex<f64>],
        targets: &[Complex<f64>],
        sim: &Similarity,
        x: &mut [f64],
    ) {
        let n = x.len();
        for i in 0..n {
            let along = sim.alpha * tangents[i];
            let reach = along.norm_sqr();
            if reach.is_nan() || reach <= 0.0 {
                continue;
            }
            let miss = sim.alpha * points[i] + sim.beta - targets[i];
            let dx = (-(along.conj() * miss).re / reach).clamp(-1.0, 1.0);
            let lo = if i == 0 { 0.0 } else { x[i - 1] };
            let hi = if i + 1 == n { self.last } else { x[i + 1] };
            x[i] = (x[i] + dx).clamp(lo.min(hi), hi.max(lo));
        }
    }
}

/// The similarity that best fits the misses across the curve at each point (normal
/// to `tangents`): four unknowns (α and β), one equation per target. `None` when
/// the normals leave it undetermined.
fn across(
    points: &[Complex<f64>],
    tangents: &[Complex<f64>],
    targets: &[Complex<f64>],
    sim: &Similarity,
) -> Option<Similarity> {
    let mut normal_eq = Matrix4::zeros();
    let mut rhs = Vector4::zeros();
    for ((z, tangent), t) in points.iter().zip(tangents).zip(targets) {
        let along = sim.alpha * tangent;
        let len = along.norm();
        if len.is_nan() || len <= 0.0 {
            continue;
        }
        // The world normal at the point: the tangent turned a quarter.
        let normal = Complex::new(-along.im, along.re) / len;
        let q = normal.conj() * z;
        let row = Vector4::new(q.re, -q.im, normal.re, normal.im);
        normal_eq += row * row.transpose();
        rhs += row * (normal.conj() * t).re;
    }
    let solved = normal_eq.cholesky()?.solve(&rhs);
    let alpha = Complex::new(solved[0], solved[1]);
    (alpha.norm() > 0.0 && solved.iter().all(|v| v.is_finite())).then_some(Similarity {
        alpha,
        beta: Complex::new(solved[2], solved[3]),
    })
}
