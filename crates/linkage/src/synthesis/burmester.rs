//! Motion generation through four and five positions (Burmester theory). A crank
//! from centre point m (world) to circle point a (body frame) carries the body
//! through positions (Rᵢ, dᵢ) when a's places Rᵢa + dᵢ are all at one distance
//! from m. Subtracting the first position's equation from the others leaves
//! equations linear in a:
//!
//! 2 a · (Rᵢᵀ(dᵢ − m) − R₁ᵀ(d₁ − m)) = |d₁ − m|² − |dᵢ − m|²,  i = 2..n.
//!
//! With four positions that is three equations in two unknowns: a exists exactly
//! where their 3×3 determinant Δ(m) vanishes, a cubic curve in m (the centre-point
//! curve, through the six poles). Any two of its points make a four-bar. With five
//! positions m must lie on the curves of positions 1234 and 1235 at once: the two
//! cubics meet in nine points, three of them the common poles P12, P13, P23 and two
//! the circular points at infinity, leaving at most four real Burmester points.

use serde::Serialize;

use super::motion::{BodyPose, MotionFourBar, poles_of};
use crate::error::DesignRefusal;
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::motion::Vec2;

/// One row of the linear equations in a: the coefficients and the right-hand side.
fn row(first: &BodyPose, other: &BodyPose, m: Vec2) -> ([f64; 2], f64) {
    let back = |p: &BodyPose| {
        let (s, c) = p.angle_rad.sin_cos();
        let d = Vec2::new(p.at[0], p.at[1]) - m;
        (
            Vec2::new(c * d.x + s * d.y, -s * d.x + c * d.y),
            d.norm_squared(),
        )
    };
    let ((u1, n1), (ui, ni)) = (back(first), back(other));
    let k = (ui - u1) * 2.0;
    ([k.x, k.y], n1 - ni)
}

/// Δ(m) for the first four of `poses`: zero on the centre-point curve.
pub fn centre_condition(poses: &[BodyPose], m: Vec2) -> f64 {
    let r = |i: usize| row(&poses[0], &poses[i], m);
    let (([a, b], c), ([d, e], f), ([g, h], i)) = (r(1), r(2), r(3));
    a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
}

/// The circle point (body frame) of centre point `m`: least squares over the
/// positions' equations, exact where m is a centre point of all of them. `None`
/// where the equations do not fix it (m at a pole of every pair).
pub fn circle_point(poses: &[BodyPose], m: Vec2) -> Option<Vec2> {
    let (mut ata, mut atb) = ([[0.0; 2]; 2], [0.0; 2]);
    for p in &poses[1..] {
        let ([x, y], rhs) = row(&poses[0], p, m);
        ata[0][0] += x * x;
        ata[0][1] += x * y;
        ata[1][1] += y * y;
        atb[0] += x * rhs;
        atb[1] += y * rhs;
    }
    let det = ata[0][0] * ata[1][1] - ata[0][1] * ata[0][1];
    if det.abs() <= 1e-14 * (ata[0][0] * ata[1][1]).max(f64::MIN_POSITIVE) {
        return None;
    }
    Some(Vec2::new(
        (ata[1][1] * atb[0] - ata[0][1] * atb[1]) / det,
        (ata[0][0] * atb[1] - ata[0][1] * atb[0]) / det,
    ))
}

/// A point of the centre-point curve near `guess`, by Newton's method along the
/// gradient of Δ (the nearest point to first order); `None` if it does not settle.
pub fn onto_curve(poses: &[BodyPose], guess: Vec2) -> Option<Vec2> {
    let scale = size(poses);
    let mut m = guess;
    for _ in 0..50 {
        let f = centre_condition(poses, m);
        let g = gradient(|q| centre_condition(poses, q), m, scale);
        let g2 = g.norm_squared();
        if g2 == 0.0 || !f.is_finite() {
            return None;
        }
        let step = g * (f / g2);
        m -= step;
        if step.norm() <= 1e-14 * scale.max(m.norm()) {
            return Some(m);
        }
    }
    None
}

/// The gradient of `f` at `m` by central differences.
fn gradient(f: impl Fn(Vec2) -> f64, m: Vec2, scale: f64) -> Vec2 {
    let h = 1e-7 * scale.max(m.norm());
    Vec2::new(
        (f(m + Vec2::new(h, 0.0)) - f(m - Vec2::new(h, 0.0))) / (2.0 * h),
        (f(m + Vec2::new(0.0, h)) - f(m - Vec2::new(0.0, h))) / (2.0 * h),
    )
}

/// The spread of the positions' reference points (at least 1e-9 m).
fn size(poses: &[BodyPose]) -> f64 {
    let first = Vec2::new(poses[0].at[0], poses[0].at[1]);
    poses
        .iter()
        .map(|p| (Vec2::new(p.at[0], p.at[1]) - first).norm())
        .fold(1e-9, f64::max)
}

/// A square grid of `n`×`n` cells, `half` each way around `centre`.
struct Grid {
    centre: Vec2,
    half: f64,
    n: usize,
}

impl Grid {
    /// The side of a cell.
    fn step(&self) -> f64 {
        2.0 * self.half / self.n as f64
    }

    /// The node (i, j), 0 to n each.
    fn at(&self, i: usize, j: usize) -> Vec2 {
        let step = self.step();
        self.centre + Vec2::new(-self.half + step * i as f64, -self.half + step * j as f64)
    }

    /// `f` at every node, once, indexed [i][j].
    fn sample<T>(&self, f: impl Fn(Vec2) -> T) -> Vec<Vec<T>> {
        (0..=self.n)
            .map(|i| (0..=self.n).map(|j| f(self.at(i, j))).collect())
            .collect()
    }
}

/// The centre-point curve of four positions within the square `half` around the
/// positions' centroid, as short segments (marching squares on an `n`×`n` grid),
/// for drawing.
pub fn centre_curve(poses: &[BodyPose], half: f64, n: usize) -> Vec<[[f64; 2]; 2]> {
    let centre = poses
        .iter()
        .fold(Vec2::zeros(), |s, p| s + Vec2::new(p.at[0], p.at[1]))
        / poses.len() as f64;
    let grid = Grid { centre, half, n };
    let at = |i: usize, j: usize| grid.at(i, j);
    let values = grid.sample(|m| centre_condition(poses, m));
    let mut segments = vec![];
    for i in 0..n {
        for j in 0..n {
            let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
            let crossings: Vec<Vec2> = (0..4)
                .filter_map(|k| {
                    let (p, q) = (corners[k], corners[(k + 1) % 4]);
                    let (fp, fq) = (values[p.0][p.1], values[q.0][q.1]);
                    ((fp < 0.0) != (fq < 0.0)).then(|| {
                        let t = fp / (fp - fq);
                        at(p.0, p.1) + (at(q.0, q.1) - at(p.0, p.1)) * t
                    })
                })
                .collect();
            for pair in crossings.chunks_exact(2) {
                segments.push([pair[0].into(), pair[1].into()]);
            }
        }
    }
    segments
}

/// A crank of a motion generator: its centre point and circle point.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Crank {
    /// The fixed pivot, world, m.
    pub centre: [f64; 2],
    /// The moving pivot, body frame, m.
    pub circle: [f64; 2],
}

/// The Burmester points of five positions: the centre points of all five (at most
/// four), each with its circle point.
///
/// # Errors
/// Not five positions, or a value that is not finite.
pub fn burmester_points(poses: &[BodyPose]) -> Result<Vec<Crank>> {
    check_poses(poses, 5)?;
    let s = size(poses);
    let quartets = [&poses[..4], &[poses[0], poses[1], poses[2], poses[4]][..]];
    let f = |m: Vec2| {
        [
            centre_condition(quartets[0], m),
            centre_condition(quartets[1], m),
        ]
    };
    // Seeds: grid cells where both conditions change sign, out to 20 sizes away
    // (each node evaluated once).
    let common: Vec<Vec2> = poles_of(&poses[..3])
        .into_iter()
        .flatten()
        .map(Vec2::from)
        .collect();
    let mut found: Vec<Vec2> = vec![];
    let grid = Grid {
        centre: Vec2::new(poses[0].at[0], poses[0].at[1]),
        half: 20.0 * s,
        n: 200,
    };
    let values = grid.sample(f);
    for i in 0..grid.n {
        for j in 0..grid.n {
            let vals = [
                values[i][j],
                values[i + 1][j],
                values[i][j + 1],
                values[i + 1][j + 1],
            ];
            let changes =
                |k: usize| vals.iter().any(|v| v[k] < 0.0) && vals.iter().any(|v| v[k] >= 0.0);
            if !(changes(0) && changes(1)) {
                continue;
            }
            let middle = grid.at(i, j) + Vec2::repeat(0.5 * grid.step());
            let Some(m) = newton2(&f, middle, s) else {
                continue;
            };
            let near = |q: &Vec2| (q - m).norm() <= 1e-6 * s;
            if !found.iter().any(near) && !common.iter().any(|p| (p - m).norm() <= 1e-4 * s) {
                found.push(m);
            }
        }
    }
    Ok(found
        .into_iter()
        .filter_map(|m| {
            let a = circle_point(poses, m)?;
            Some(Crank {
                centre: m.into(),
                circle: a.into(),
            })
        })
        .collect())
}

/// Newton's method on the two conditions from `m`; `None` if it does not settle.
fn newton2(f: &impl Fn(Vec2) -> [f64; 2], mut m: Vec2, scale: f64) -> Option<Vec2> {
    for _ in 0..60 {
        let v = f(m);
        let h = 1e-7 * scale.max(m.norm());
        let dx = f(m + Vec2::new(h, 0.0));
        let dy = f(m + Vec2::new(0.0, h));
        let (a, b) = ((dx[0] - v[0]) / h, (dy[0] - v[0]) / h);
        let (c, d) = ((dx[1] - v[1]) / h, (dy[1] - v[1]) / h);
        let det = a * d - b * c;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let step = Vec2::new((d * v[0] - b * v[1]) / det, (a * v[1] - c * v[0]) / det);
        m -= step;
        if step.norm() <= 1e-13 * scale.max(m.norm()) {
            return Some(m);
        }
    }
    None
}

fn check_poses(poses: &[BodyPose], n: usize) -> Result<()> {
    if poses.len() != n {
        return Err(LinkageError::invalid(
            Param::Positions,
            poses.len() as f64,
            Valid::Exactly(n),
        ));
    }
    let values = poses.iter().flat_map(|p| [p.at[0], p.at[1], p.angle_rad]);
    if let Some(v) = values.into_iter().find(|v| !v.is_finite()) {
        return Err(LinkageError::invalid(Param::Pose, v, Valid::FiniteNumbers));
    }
    Ok(())
}

/// The four-bar of two cranks through `poses` (four or five).
///
/// # Errors
/// Not four or five positions, a value that is not finite, or two cranks on one
/// moving pivot.
pub fn four_bar_of(poses: &[BodyPose], cranks: [Crank; 2]) -> Result<MotionFourBar> {
    check_poses(poses, poses.len().clamp(4, 5))?;
    if (Vec2::from(cranks[0].circle) - Vec2::from(cranks[1].circle)).norm() < 1e-12 {
        return Err(DesignRefusal::CranksShareMovingPivot.into());
    }
    Ok(MotionFourBar {
        poses: poses.to_vec(),
        moving: cranks.map(|c| c.circle),
        fixed: cranks.map(|c| c.centre),
        poles: poles_of(poses),
    })
}

/// The four-bar through four positions whose fixed pivots are the points of the
/// centre-point curve nearest `near` (world, m).
///
/// # Errors
/// Not four positions, a value that is not finite, a point from which the curve is
/// not found, or one whose circle point is not fixed (a pole).
pub fn four_positions(poses: &[BodyPose], near: [[f64; 2]; 2]) -> Result<MotionFourBar> {
    check_poses(poses, 4)?;
    let crank = |k: usize| -> Result<Crank> {
        let m = onto_curve(poses, Vec2::from(near[k])).ok_or_else(|| {
            LinkageError::from(DesignRefusal::NoCentrePointNear {
                number: k + 1,
                near: near[k],
            })
        })?;
        let a = circle_point(poses, m)
            .ok_or_else(|| LinkageError::from(DesignRefusal::FixedPivotIsPole { number: k + 1 }))?;
        Ok(Crank {
            centre: m.into(),
            circle: a.into(),
        })
    };
    four_bar_of(poses, [crank(0)?, crank(1)?])
}
