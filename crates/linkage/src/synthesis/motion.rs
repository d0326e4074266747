//! Motion generation through three prescribed positions of a body (Burmester's
//! construction for three positions): each moving pivot chosen on the body (a
//! circle point) takes three places in the world, and its fixed pivot (the centre
//! point) is the centre of the circle through them, so a crank from there carries
//! it through all three. Two moving pivots give a four-bar whose coupler is the
//! body. The poles of each pair of positions (the points that stay put from one
//! to the other) are given for drawing the construction.

use serde::Serialize;

use crate::Kinematics;
use crate::drawing::{Drawing, DrawingLink, DrawingPoint};
use crate::error::DesignRefusal;
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::model::Mechanism;
use crate::motion::{Vec2, cross};

/// A position of the body: where its reference point is and how it is turned.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BodyPose {
    /// The reference point in the world, m.
    pub at: [f64; 2],
    /// The body's angle, rad (counter-clockwise).
    pub angle_rad: f64,
}

impl BodyPose {
    /// Where the body point `local` (body coordinates, m) is in this position.
    pub fn place(&self, local: Vec2) -> Vec2 {
        let (s, c) = self.angle_rad.sin_cos();
        Vec2::new(
            self.at[0] + c * local.x - s * local.y,
            self.at[1] + s * local.x + c * local.y,
        )
    }
}

/// The pole of the displacement from `a` to `b`: the point of the plane that the
/// body's motion leaves where it is; `None` for a pure translation (at infinity).
pub fn pole(a: &BodyPose, b: &BodyPose) -> Option<Vec2> {
    let turn = b.angle_rad - a.angle_rad;
    let (s, c) = turn.sin_cos();
    if s.abs() < 1e-12 && c > 0.0 {
        return None;
    }
    // x = pb + R(turn)(x − pa): solve (I − R) x = pb − R pa.
    let (pa, pb) = (Vec2::new(a.at[0], a.at[1]), Vec2::new(b.at[0], b.at[1]));
    let rhs = pb - Vec2::new(c * pa.x - s * pa.y, s * pa.x + c * pa.y);
    let det = (1.0 - c) * (1.0 - c) + s * s;
    Some(Vec2::new(
        ((1.0 - c) * rhs.x - s * rhs.y) / det,
        (s * rhs.x + (1.0 - c) * rhs.y) / det,
    ))
}

/// The centre of the circle through `p`, `q`, `r`, or `None` where they are in a
/// line (the centre is at infinity).
fn circumcentre(p: Vec2, q: Vec2, r: Vec2) -> Option<Vec2> {
    let (u, v) = (q - p, r - p);
    let d = 2.0 * cross(&u, &v);
    let scale = u.norm_squared().max(v.norm_squared());
    if d.abs() <= 1e-12 * scale {
        return None;
    }
    let (uu, vv) = (u.norm_squared(), v.norm_squared());
    Some(p + Vec2::new(v.y * uu - u.y * vv, u.x * vv - v.x * uu) / d)
}

/// A motion generator's scene and how closely the solver moves it through the
/// positions.
#[derive(Clone, Debug, PartialEq)]
pub struct MotionCheck {
    /// The four-bar as a scene, starting in the first position.
    pub scene: crate::SceneFile,
    /// Largest miss of the body's reference point, m.
    pub miss_m: f64,
    /// Largest miss of the body's angle, rad.
    pub miss_rad: f64,
}

/// A four-bar whose coupler carries the body through three or more positions.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MotionFourBar {
    /// The positions (three; four or five from [`crate::synthesis::burmester`]).
    pub poses: Vec<BodyPose>,
    /// The moving pivots, in body coordinates, m.
    pub moving: [[f64; 2]; 2],
    /// Their fixed pivots (the centre points), m.
    pub fixed: [[f64; 2]; 2],
    /// The poles of each pair of positions, P12, P13, ..., P23, ... in that order
    /// (`None`: a translation), m.
    pub poles: Vec<Option<[f64; 2]>>,
}

/// The poles of every pair of `poses`: P12, P13, ..., P23, ... (`None`: a translation).
pub fn poles_of(poses: &[BodyPose]) -> Vec<Option<[f64; 2]>> {
    let n = poses.len();
    (0..n)
        .flat_map(|a| (a + 1..n).map(move |b| (a, b)))
        .map(|(a, b)| pole(&poses[a], &poses[b]).map(|p| [p.x, p.y]))
        .collect()
}

/// The four-bar through `poses` with moving pivots `moving` (body coordinates, m).
///
/// # Errors
/// A value that is not finite, two moving pivots at one place, a moving pivot whose
/// three places are in a line (its centre point is at infinity: a slider, not a
/// crank), or a fixed pivot on its own moving pivot.
pub fn three_positions(poses: [BodyPose; 3], moving: [[f64; 2]; 2]) -> Result<MotionFourBar> {
    let values = poses
        .iter()
        .flat_map(|p| [p.at[0], p.at[1], p.angle_rad])
        .chain(moving.iter().flatten().copied());
    if let Some(v) = values.into_iter().find(|v| !v.is_finite()) {
        return Err(LinkageError::invalid(
            Param::PoseOrMovingPivot,
            v,
            Valid::FiniteNumbers,
        ));
    }
    let local = moving.map(|m| Vec2::new(m[0], m[1]));
    if (local[0] - local[1]).norm() < 1e-12 {
        return Err(DesignRefusal::MovingPivotsCoincide.into());
    }
    let mut fixed = [[0.0; 2]; 2];
    for (k, m) in local.iter().enumerate() {
        let [p, q, r] = poses.map(|pose| pose.place(*m));
        let centre = circumcentre(p, q, r).ok_or_else(|| {
            LinkageError::from(DesignRefusal::CentreAtInfinity {
                number: k + 1,
                at: [m.x, m.y],
            })
        })?;
        if (centre - p).norm() < 1e-9 * (q - p).norm().max(1e-9) {
            return Err(DesignRefusal::MovingPivotIsPole { number: k + 1 }.into());
        }
        fixed[k] = [centre.x, centre.y];
    }
    Ok(MotionFourBar {
        poses: poses.to_vec(),
        moving,
        fixed,
        poles: poles_of(&poses),
    })
}

impl MotionFourBar {
    /// The four-bar drawn in the first position: fixed pivots A0, B0, moving pivots
    /// A, B, the body's reference point P on the coupler, the crank A0A driving.
    pub fn drawing(&self) -> Drawing {
        let first = &self.poses[0];
        let place = |m: [f64; 2]| first.place(Vec2::new(m[0], m[1]));
        let point = |name: &str, at: Vec2, ground: bool| DrawingPoint {
            name: name.into(),
            at,
            ground,
        };
        let title = match self.poses.len() {
            3 => "Three-position motion generator",
            4 => "Four-position motion generator",
            _ => "Five-position motion generator",
        };
        let mut s = Drawing::new(title);
        s.length_unit = crate::scene::LengthUnit::Metre;
        s.points = vec![
            point("A0", Vec2::new(self.fixed[0][0], self.fixed[0][1]), true),
            point("B0", Vec2::new(self.fixed[1][0], self.fixed[1][1]), true),
            point("A", place(self.moving[0]), false),
            point("B", place(self.moving[1]), false),
            point("P", Vec2::new(first.at[0], first.at[1]), false),
        ];
        s.links = vec![
            DrawingLink::new("crank", vec![0, 2]),
            DrawingLink::new("coupler", vec![2, 3, 4]),
            DrawingLink::new("rocker", vec![1, 3]),
        ];
        s.driver = Some(0);
        s.output = Some(2);
        s
    }

    /// The crank's input angle at position `i` (the scene of [`MotionFourBar::drawing`]
    /// starts at 0 in the first), rad.
    pub fn input_at(&self, i: usize) -> f64 {
        let a0 = Vec2::new(self.fixed[0][0], self.fixed[0][1]);
        let m = Vec2::new(self.moving[0][0], self.moving[0][1]);
        let dir = |k: usize| {
            let d = self.poses[k].place(m) - a0;
            d.y.atan2(d.x)
        };
        dir(i) - dir(0)
    }

    /// The four-bar's scene, moved by the general solver (on the branch of the first
    /// position) to each position: the largest miss of the body's reference point
    /// and angle, zero to round-off unless a position needs the chain's other
    /// assembly (a branch defect).
    ///
    /// # Errors
    /// The chain does not build, or does not assemble at a position's crank angle.
    pub fn check(&self) -> Result<MotionCheck> {
        let scene = self.drawing().to_scene().map_err(|e| match e {
            crate::drawing::DrawingProblem::Invalid(e) => e,
            _ => DesignRefusal::DrawingIncomplete.into(),
        })?;
        let mut k = Kinematics::new(Mechanism::from_scene(&scene)?)?;
        let p = k
            .mechanism()
            .point_index("P")
            .ok_or(DesignRefusal::PartMissing {
                part: "coupler point P",
            })?;
        let coupler = k
            .mechanism()
            .link_index("coupler")
            .ok_or(DesignRefusal::PartMissing { part: "coupler" })?;
        let mut worst = (0.0f64, 0.0f64);
        for (i, pose) in self.poses.iter().enumerate() {
            let s = k.solve(self.input_at(i))?;
            let at = s.points[p].position;
            let miss = (at - Vec2::new(pose.at[0], pose.at[1])).norm();
            let turn = s.links[coupler].angle_rad() - (pose.angle_rad - self.poses[0].angle_rad);
            let turn = (turn + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                - std::f64::consts::PI;
            worst = (worst.0.max(miss), worst.1.max(turn.abs()));
        }
        Ok(MotionCheck {
            scene,
            miss_m: worst.0,
            miss_rad: worst.1,
        })
    }
}
