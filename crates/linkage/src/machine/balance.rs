//! Counterweights on the links pivoted to the frame (the crank, a rocker) that
//! balance the shaking force best: in the mean square, or at its peak.
//!
//! A counterweight of mass-radius `c` (a vector in the link's coordinates, from its
//! ground pivot) on a link turning at θ, ω, α adds `R(θ) (ω² c − α J c)` to the force
//! on the frame (J turns by 90°): its centrifugal and tangential inertia forces. The
//! force is affine in the counterweights, F(φ) = F₀(φ) + Σ A_L(φ) c_L, so
//! - the mean square is least for the least-squares `c` (for the crank alone at a
//!   constant speed, `c = −mean(R(φ)ᵀ F(φ)) / ω²`: it cancels the part of the force
//!   that turns with the crank, the rotating mass and half the reciprocating one of a
//!   slider-crank);
//! - the peak is least for the minimax `c`, found by Lawson's iteration: weighted
//!   least squares with each position's weight grown by its residual's size, which
//!   converges to the Chebyshev (minimax) solution.

use nalgebra::{DMatrix, DVector, Rotation2};
use serde::Serialize;

use super::shaking::Shaking;
use crate::error::{LinkageError, Result};
use crate::ids::LinkId;
use crate::model::{Mechanism, SceneProblem};
use crate::motion::Vec2;
use crate::solve::Kinematics;

/// What the counterweights minimise.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum BalanceAim {
    /// The shaking force's root mean square over the cycle.
    Rms,
    /// The shaking force's largest magnitude over the cycle.
    Peak,
}

/// A counterweight on one link pivoted to the frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Counterweight {
    /// The link.
    pub link: LinkId,
    /// Mass times radius, kg·m.
    pub mass_radius_kg_m: f64,
    /// Its direction in the link's coordinates from the pivot, rad.
    pub angle_rad: f64,
    /// Its place on the link, m (link coordinates): at the link's farthest point's
    /// distance from the pivot.
    pub at_m: [f64; 2],
    /// Its mass at that place, kg.
    pub mass_kg: f64,
}

/// Lawson's iterations at most, and the relative change of the peak that ends them.
const LAWSON_ITERATIONS: usize = 2000;
const LAWSON_TOLERANCE: f64 = 1e-12;

/// The counterweights on `links` of `k`'s mechanism that minimise `aim` over the
/// cycle `s` (from [`super::shaking`] of the same mechanism).
///
/// # Errors
/// A link not pivoted to the frame, or a position of the cycle that does not solve.
pub fn counterweights(
    k: &mut Kinematics,
    s: &Shaking,
    links: &[LinkId],
    aim: BalanceAim,
) -> Result<Vec<Counterweight>> {
    let m = k.mechanism().clone();
    let pivots = links
        .iter()
        .map(|&l| ground_pivot(&m, l))
        .collect::<Result<Vec<Vec2>>>()?;
    let (a, f0) = system(k, s, links)?;
    let c = match aim {
        BalanceAim::Rms => weighted_least_squares(&a, &f0, &vec![1.0; s.cycle.len()]),
        BalanceAim::Peak => minimax(&a, &f0),
    };
    Ok(links
        .iter()
        .zip(&pivots)
        .enumerate()
        .map(|(i, (&link, &pivot))| place(&m, link, pivot, Vec2::new(c[2 * i], c[2 * i + 1])))
        .collect())
}

/// The link's ground pivot in its own coordinates.
fn ground_pivot(m: &Mechanism, link: LinkId) -> Result<Vec2> {
    m.revolutes
        .iter()
        .find_map(|rv| {
            if rv.a == link && rv.b == m.ground {
                Some(rv.a_local)
            } else if rv.b == link && rv.a == m.ground {
                Some(rv.b_local)
            } else {
                None
            }
        })
        .ok_or_else(|| {
            LinkageError::from(SceneProblem::NotPivoted {
                link: m.links[link].name.clone(),
            })
        })
}

/// The rows of F(φ) = F₀(φ) + A(φ) c over the cycle: A with two rows per position
/// and two columns per link, F₀ stacked likewise.
fn system(
    k: &mut Kinematics,
    s: &Shaking,
    links: &[LinkId],
) -> Result<(DMatrix<f64>, DVector<f64>)> {
    let w = k.mechanism().driver.speed_rad_s;
    let n = s.cycle.len();
    let mut a = DMatrix::<f64>::zeros(2 * n, 2 * links.len());
    let mut f0 = DVector::<f64>::zeros(2 * n);
    let mut sol = k.empty_solution();
    for (i, p) in s.cycle.iter().enumerate() {
        k.solve_into(p.angle_rad, w, &mut sol)?;
        f0[2 * i] = p.force_n[0];
        f0[2 * i + 1] = p.force_n[1];
        for (j, &l) in links.iter().enumerate() {
            let motion = &sol.links[l];
            let (w2, alpha) = (motion.omega_rad_s.powi(2), motion.alpha_rad_s2);
            let turn = Rotation2::new(motion.rotation.angle());
            // R(θ) (ω² I − α J): the columns for c_x and c_y.
            for (col, unit, normal) in [(0, Vec2::x(), Vec2::y()), (1, Vec2::y(), -Vec2::x())] {
                let v = turn * (unit * w2 - normal * alpha);
                a[(2 * i, 2 * j + col)] = v.x;
                a[(2 * i + 1, 2 * j + col)] = v.y;
            }
        }
    }
    Ok((a, f0))
}

/// The `c` minimising Σ wᵢ |F₀ᵢ + Aᵢ c|² (weights per position).
fn weighted_least_squares(a: &DMatrix<f64>, f0: &DVector<f64>, weights: &[f64]) -> DVector<f64> {
    let mut aw = a.clone();
    let mut bw = -f0.clone();
    for (i, &w) in weights.iter().enumerate() {
        let s = w.sqrt();
        for r in [2 * i, 2 * i + 1] {
            aw.row_mut(r).scale_mut(s);
            bw[r] *= s;
        }
    }
    // Least squares by the SVD: a counterweight the force cannot see (a link at
    // rest) gets none rather than an arbitrary one.
    aw.svd(true, true)
        .solve(&bw, 1e-12)
        .unwrap_or_else(|_| DVector::zeros(a.ncols()))
}

/// The size of the force at each position for counterweights `c`.
fn residuals(a: &DMatrix<f64>, f0: &DVector<f64>, c: &DVector<f64>) -> Vec<f64> {
    let r = f0 + a * c;
    (0..r.len() / 2)
        .map(|i| r[2 * i].hypot(r[2 * i + 1]))
        .collect()
}

/// Lawson's iteration for the minimax `c`.
fn minimax(a: &DMatrix<f64>, f0: &DVector<f64>) -> DVector<f64> {
    let n = f0.len() / 2;
    let mut weights = vec![1.0 / n as f64; n];
    let mut best = weighted_least_squares(a, f0, &weights);
    let mut best_peak = peak(&residuals(a, f0, &best));
    for _ in 0..LAWSON_ITERATIONS {
        let c = weighted_least_squares(a, f0, &weights);
        let e = residuals(a, f0, &c);
        let p = peak(&e);
        let improved = p < best_peak;
        if improved {
            let settled = best_peak - p <= LAWSON_TOLERANCE * best_peak;
            best = c;
            best_peak = p;
            if settled {
                break;
            }
        }
        let total: f64 = weights.iter().zip(&e).map(|(w, e)| w * e).sum();
        if !(total > 0.0 && total.is_finite()) {
            break;
        }
        for (w, e) in weights.iter_mut().zip(&e) {
            *w *= e / total;
        }
    }
    best
}

fn peak(e: &[f64]) -> f64 {
    e.iter().copied().fold(0.0, f64::max)
}

/// The counterweight `c` on `link`, placed at the link's farthest point's distance
/// from its pivot.
fn place(m: &Mechanism, link: LinkId, pivot: Vec2, c: Vec2) -> Counterweight {
    let radius = m.links[link]
        .points
        .iter()
        .map(|(_, p)| (p - pivot).norm())
        .fold(0.0, f64::max);
    let angle = c.y.atan2(c.x);
    let at = pivot + Vec2::new(angle.cos(), angle.sin()) * radius;
    Counterweight {
        link,
        mass_radius_kg_m: c.norm(),
        angle_rad: angle,
        at_m: [at.x, at.y],
        mass_kg: if radius > 0.0 { c.norm() / radius } else { 0.0 },
    }
}

/// `m` with each counterweight added to its link as a point mass.
pub fn with_counterweights(m: &Mechanism, weights: &[Counterweight]) -> Mechanism {
    let mut out = m.clone();
    for c in weights {
        super::shaking::add_point_mass(
            &mut out,
            c.link,
            c.mass_kg,
            Vec2::new(c.at_m[0], c.at_m[1]),
        );
    }
    out
}
