//! The search's encoding of a four-bar up to similarity, as four-bar-rs searches its
//! linkages: a coupler curve's shape depends on five ratios alone (the links and the
//! coupler point against the crank, and the point's angle), and where the curve lies,
//! how it is turned and how large it is (a similarity: four numbers) follows from the
//! targets in closed form once each target has its place on the curve (a Procrustes
//! fit). So the global search runs over 6 to 8 numbers instead of 10, and the ground
//! pivots may lie anywhere the fit puts them: far-off pivots cost nothing to reach.
//!
//! The unit four-bar of a shape has A at the origin and D at (1, 0); the fit maps it
//! onto the targets by z ↦ αz + β with complex α and β, which keeps orientation, so
//! crank angles measured counter-clockwise stay so (a prescribed timing keeps its
//! sense) and the mirror images come from the shape itself (the point's angle and
//! the branch, both searched).

use nalgebra::Complex;

use super::geometry::CouplerFourBar;
use crate::motion::Vec2;

/// Numbers of a shape: ln(ground/crank), ln(coupler/crank), ln(rocker/crank),
/// ln(|BP|/coupler) and the angle of P from B→C. The coupler point is measured
/// against its own link: a small crank with a point far out on a long coupler (|BP|
/// fifty cranks long) is then an ordinary shape, not one past the bounds.
pub const SHAPE: usize = 5;

/// The widest ratio of a link to the crank either way: four-bar-rs searches 1/6 to
/// 6; this is wider, to cranks of a twelfth of the ground.
pub const RATIO: f64 = 12.0;

/// The widest ratio of |BP| to the coupler either way.
pub const POINT_RATIO: f64 = 8.0;

/// The unit four-bar of shape `v` (its first [`SHAPE`] numbers) on branch `left`.
pub fn unit_linkage(v: &[f64], left: bool) -> CouplerFourBar {
    let crank = (-v[0]).exp();
    let coupler = crank * v[1].exp();
    let reach = coupler * v[3].exp();
    CouplerFourBar {
        a: Vec2::zeros(),
        d: Vec2::new(1.0, 0.0),
        crank,
        coupler,
        rocker: crank * v[2].exp(),
        point: Vec2::new(reach * v[4].cos(), reach * v[4].sin()),
        c_left_of_bd: left,
    }
}

/// A similarity z ↦ αz + β of the plane (complex numbers for points).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Similarity {
    /// Turn and scale.
    pub alpha: Complex<f64>,
    /// Shift.
    pub beta: Complex<f64>,
}

/// A point as a complex number.
pub fn complex(p: Vec2) -> Complex<f64> {
    Complex::new(p.x, p.y)
}

/// A complex number as a point.
pub fn point(z: Complex<f64>) -> Vec2 {
    Vec2::new(z.re, z.im)
}

impl Similarity {
    /// Where it maps `p`.
    pub fn apply(&self, p: Vec2) -> Vec2 {
        point(self.alpha * complex(p) + self.beta)
    }

    /// Where it came from: the point that maps to `p` (α is never zero here).
    pub fn invert(&self, p: Vec2) -> Vec2 {
        point((complex(p) - self.beta) / self.alpha)
    }

    /// The four-bar `m` mapped by it: pivots moved, lengths scaled; angles in the
    /// coupler's frame and the branch are kept (the map keeps orientation).
    pub fn linkage(&self, m: &CouplerFourBar) -> CouplerFourBar {
        let s = self.alpha.norm();
        CouplerFourBar {
            a: self.apply(m.a),
            d: self.apply(m.d),
            crank: m.crank * s,
            coupler: m.coupler * s,
            rocker: m.rocker * s,
            point: m.point * s,
            c_left_of_bd: m.c_left_of_bd,
        }
    }

    /// The angle it turns by, rad: a crank angle θ of the unit linkage is θ plus this.
    pub fn turn(&self) -> f64 {
        self.alpha.arg()
    }
}

/// The similarity that maps `from` closest to `to` in the least-squares sense, and
/// the sum of squared misses left. `None` when the `from` points coincide (no turn
/// or scale is defined).
pub fn fit(from: &[Complex<f64>], to: &[Complex<f64>]) -> Option<(Similarity, f64)> {
    let n = from.len() as f64;
    let mean = |z: &[Complex<f64>]| z.iter().sum::<Complex<f64>>() / n;
    let (zf, zt) = (mean(from), mean(to));
    let mut cross = Complex::new(0.0, 0.0);
    let (mut spread_from, mut spread_to) = (0.0, 0.0);
    for (f, t) in from.iter().zip(to) {
        let (df, dt) = (f - zf, t - zt);
        cross += dt * df.conj();
        spread_from += df.norm_sqr();
        spread_to += dt.norm_sqr();
    }
    if !(spread_from > 0.0 && spread_from.is_finite()) {
        return None;
    }
    let alpha = cross / spread_from;
    let left = (spread_to - cross.norm_sqr() / spread_from).max(0.0);
    Some((
        Similarity {
            alpha,
            beta: zt - alpha * zf,
        },
        left,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fit_recovers_a_known_similarity_exactly() {
        let known = Similarity {
            alpha: Complex::new(0.3, -1.7),
            beta: Complex::new(2.0, 5.0),
        };
        let from: Vec<Complex<f64>> = [(0.0, 0.0), (1.0, 0.2), (0.4, 2.0), (-1.0, 0.7)]
            .iter()
            .map(|&(x, y)| Complex::new(x, y))
            .collect();
        let to: Vec<Complex<f64>> = from.iter().map(|z| known.alpha * z + known.beta).collect();
        let (got, left) = fit(&from, &to).expect("points apart");
        assert!((got.alpha - known.alpha).norm() < 1e-12, "{got:?}");
        assert!((got.beta - known.beta).norm() < 1e-12, "{got:?}");
        assert!(left < 1e-20, "{left}");
        assert!(fit(&[from[0]; 3], &to[..3]).is_none());
    }

    #[test]
    fn a_mapped_linkage_traces_the_mapped_curve() {
        let m = unit_linkage(&[0.9, 1.2, 1.0, 0.8, 0.6], true);
        let s = Similarity {
            alpha: Complex::from_polar(2.5, 0.7),
            beta: Complex::new(-1.0, 3.0),
        };
        let w = s.linkage(&m);
        for k in 0..12 {
            let theta = 0.5 * f64::from(k);
            let (Some(p), Some(q)) = (m.point_at(theta), w.point_at(theta + s.turn())) else {
                continue;
            };
            assert!((s.apply(p) - q).norm() < 1e-12, "at {theta}");
        }
    }
}
