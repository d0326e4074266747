//! Starting linkages for timed targets from the dyads one at a time, as the
//! textbooks synthesise a four-bar for prescribed timing (Sandor and Erdman's
//! standard dyad form). With the crank angles known, the crank pivot A fixes
//! everything of the left dyad that is linear: the crank B − A = u e^{iΔ_k} turns
//! by the given Δ_k, and P − B keeps its length |z|, so
//!
//! |P_k − A|² − |P_0 − A|² = 2 Re(u (conj(P_k − A) e^{iΔ_k} − conj(P_0 − A))),
//!
//! linear in the crank u for a given A (least squares over the targets). Where the
//! lengths |P_k − B_k| then differ, A is not a crank pivot: their spread, over a grid
//! of A, is zero at the true pivots (the design's and its cognate's that keeps the
//! timing) and nowhere else. The coupler's turns follow from B_k and P_k, and the
//! right dyad likewise: C = P + y e^{iβ_k} stays |C − D| from a rocker pivot D,
//! linear in y for a given D. So two searches over the plane, each of a few tens of
//! thousands of two-unknown least squares, give the starts that the refinement
//! takes to the targets; the evolution is left for what they miss.

use nalgebra::Complex;

use super::geometry::CouplerFourBar;
use super::polish::Start;
use super::problem::Problem;
use super::shape::{complex, point};
use crate::motion::{Vec2, cross};

/// Grid points along each side of the region.
const GRID: usize = 120;
/// Starting pivots kept from each plane (the smallest local minima of the spread).
const KEPT: usize = 6;

/// A dyad's fit for one fixed pivot: the unknown vector and the spread of the
/// lengths it leaves (root mean square about their mean), in target units.
struct DyadFit {
    vector: Complex<f64>,
    spread: f64,
}

/// The dyad through `points` that turns by `turns` (rad, the first 0) about pivot
/// `pivot`, sign `sense` +1 for a crank (P = A + u e^{iΔ} + z) or −1 for the right
/// dyad (C = P + y e^{iβ}, |C − D| fixed): the vector by least squares.
fn dyad(
    points: &[Complex<f64>],
    turns: &[Complex<f64>],
    pivot: Complex<f64>,
    sense: f64,
) -> Option<DyadFit> {
    let q0 = points[0] - pivot;
    let (mut ata, mut atb) = ([[0.0; 2]; 2], [0.0; 2]);
    for (p, e) in points.iter().zip(turns).skip(1) {
        let q = p - pivot;
        let g = q.conj() * e - q0.conj();
        let row = [2.0 * sense * g.re, -2.0 * sense * g.im];
        let rhs = q.norm_sqr() - q0.norm_sqr();
        for i in 0..2 {
            atb[i] += row[i] * rhs;
            for j in 0..2 {
                ata[i][j] += row[i] * row[j];
            }
        }
    }
    let det = ata[0][0] * ata[1][1] - ata[0][1] * ata[1][0];
    if det.abs() <= 1e-14 * (ata[0][0] * ata[1][1]).abs() || !det.is_finite() {
        return None;
    }
    let vector = Complex::new(
        (atb[0] * ata[1][1] - atb[1] * ata[0][1]) / det,
        (ata[0][0] * atb[1] - ata[1][0] * atb[0]) / det,
    );
    let lengths: Vec<f64> = points
        .iter()
        .zip(turns)
        .map(|(p, e)| (p - pivot - sense * vector * e).norm())
        .collect();
    let mean = lengths.iter().sum::<f64>() / lengths.len() as f64;
    let spread =
        (lengths.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / lengths.len() as f64).sqrt();
    Some(DyadFit { vector, spread })
}

/// The pivots over the region's grid whose dyad spreads least, each a local minimum
/// of the spread, best first, at most [`KEPT`].
fn best_pivots(
    problem: &Problem,
    fit: impl Fn(Complex<f64>) -> Option<DyadFit>,
) -> Vec<(Complex<f64>, DyadFit)> {
    let [lo, hi] = problem.limits.region;
    let at = |i: usize, j: usize| {
        Complex::new(
            lo.x + (hi.x - lo.x) * i as f64 / (GRID - 1) as f64,
            lo.y + (hi.y - lo.y) * j as f64 / (GRID - 1) as f64,
        )
    };
    let spread: Vec<f64> = (0..GRID * GRID)
        .map(|k| fit(at(k / GRID, k % GRID)).map_or(f64::INFINITY, |f| f.spread))
        .collect();
    let mut minima: Vec<(f64, usize)> = (0..GRID * GRID)
        .filter(|&k| {
            let (i, j) = (k / GRID, k % GRID);
            let s = spread[k];
            s.is_finite()
                && (i.saturating_sub(1)..=(i + 1).min(GRID - 1)).all(|a| {
                    (j.saturating_sub(1)..=(j + 1).min(GRID - 1)).all(|b| spread[a * GRID + b] >= s)
                })
        })
        .map(|k| (spread[k], k))
        .collect();
    minima.sort_by(|a, b| a.0.total_cmp(&b.0));
    minima
        .into_iter()
        .take(KEPT)
        .filter_map(|(_, k)| {
            let pivot = at(k / GRID, k % GRID);
            fit(pivot).map(|f| (pivot, f))
        })
        .collect()
}

/// Dyad fits a call of [`timed_starts`] makes, counted as evaluations.
pub fn fits(problem: &Problem) -> u64 {
    (GRID * GRID * (1 + KEPT)) as u64 * u64::from(problem.timing.is_some())
}

/// Starting four-bars for the timed targets of `problem`: for each of the best crank
/// pivots, each of the best rocker pivots for its coupler's turns; their nine
/// numbers, branch and crank angles at the targets.
pub fn timed_starts(problem: &Problem) -> Vec<Start> {
    let Some(timing) = problem.timing.as_deref() else {
        return vec![];
    };
    let points: Vec<Complex<f64>> = problem.targets.iter().map(|p| complex(*p)).collect();
    let crank_turns: Vec<Complex<f64>> = timing
        .iter()
        .map(|d| Complex::from_polar(1.0, *d))
        .collect();
    let mut starts = Vec::new();
    for (a, left) in best_pivots(problem, |a| dyad(&points, &crank_turns, a, 1.0)) {
        let u = left.vector;
        let pins_b: Vec<Complex<f64>> = crank_turns.iter().map(|e| a + u * e).collect();
        // The coupler's turn from the first target: that of P − B.
        let arm0 = points[0] - pins_b[0];
        let coupler_turns: Vec<Complex<f64>> = points
            .iter()
            .zip(&pins_b)
            .map(|(p, b)| {
                let arm = (p - b) / arm0;
                arm / arm.norm()
            })
            .collect();
        if coupler_turns.iter().any(|t| !t.re.is_finite()) {
            continue;
        }
        for (d, right) in best_pivots(problem, |d| dyad(&points, &coupler_turns, d, -1.0)) {
            if let Some(start) = four_bar(a, u, d, right.vector, &points, timing) {
                starts.push(start);
            }
        }
    }
    starts
}

/// The four-bar of crank pivot `a`, crank `u` (at the first target), rocker pivot
/// `d` and C − P = `y` (at the first target), with its crank angles at the targets.
fn four_bar(
    a: Complex<f64>,
    u: Complex<f64>,
    d: Complex<f64>,
    y: Complex<f64>,
    points: &[Complex<f64>],
    timing: &[f64],
) -> Option<Start> {
    let b0 = point(a + u);
    let c0 = point(points[0] + y);
    let p0 = point(points[0]);
    let coupler = (c0 - b0).norm();
    if !(coupler > 0.0 && u.norm() > 0.0) {
        return None;
    }
    let x = (c0 - b0) / coupler;
    let rel = p0 - b0;
    let m = CouplerFourBar {
        a: point(a),
        d: point(d),
        crank: u.norm(),
        coupler,
        rocker: (c0 - point(d)).norm(),
        point: Vec2::new(rel.dot(&x), rel.dot(&Vec2::new(-x.y, x.x))),
        c_left_of_bd: cross(&(point(d) - b0), &(c0 - b0)) > 0.0,
    };
    let first = u.arg();
    Some((
        m.params(),
        m.c_left_of_bd,
        timing.iter().map(|t| first + t).collect(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synthesis::path::{PathConstraints, PathTargets};

    /// Timed targets of a known crank-rocker: among the starts, one has its crank
    /// pivot within two grid steps of the true one (or of the cognate's that keeps
    /// the timing, the family's third pivot), in the targets' normalised frame.
    #[test]
    fn the_dyads_give_a_start_at_the_true_crank_pivot() {
        let m = CouplerFourBar::from_params(&[0.0, 0.0, 4.0, 0.5, 1.2, 3.6, 3.0, 1.5, 1.1], true);
        let degrees: Vec<f64> = (0..8).map(|k| 10.0 + 40.0 * f64::from(k)).collect();
        let targets = PathTargets {
            points_m: degrees
                .iter()
                .map(|d| {
                    m.point_at(d.to_radians())
                        .map(Into::into)
                        .unwrap_or([0.0; 2])
                })
                .collect(),
            crank_deg: Some(degrees),
        };
        let problem =
            super::super::normalise(&targets, &PathConstraints::default()).expect("valid targets");
        let norm = |p: Vec2| (p - problem.centre) / problem.scale;
        let w = complex(m.point) / m.coupler;
        let o = point(complex(m.a) + w * (complex(m.d) - complex(m.a)));
        let step = 8.0 / (GRID - 1) as f64;
        let starts = timed_starts(&problem);
        assert!(!starts.is_empty());
        let nearest = starts
            .iter()
            .map(|(p, _, _)| {
                let a = Vec2::new(p[0], p[1]);
                (a - norm(m.a)).norm().min((a - norm(o)).norm())
            })
            .fold(f64::INFINITY, f64::min);
        assert!(nearest <= 2.0 * step, "{nearest} vs a step of {step}");
    }
}
