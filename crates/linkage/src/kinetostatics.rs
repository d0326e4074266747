//! Kinetostatics of a driven chain: the input torque that keeps the crank at its
//! speed, every joint reaction, and the force amplification of the output.
//!
//! The torque is found twice, independently: by virtual work (power balance
//! T ω = Σ dE_kin/dt − Σ P_applied, no reactions involved) and by Newton–Euler (per
//! moving link Σ F = m a_G and Σ M_O = I α + r_G × m a_G about the world origin,
//! solved for all reactions and T at once). They must agree.

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use crate::dynamics::ForceModel;
use crate::error::{LinkageError, Result};
use crate::ids::LinkId;
use crate::model::{CamContact, SceneProblem};
use crate::motion::{Solution, Vec2, cross, perp};
use crate::solve::Kinematics;

/// Which kind of joint a reaction acts in: a revolute carries a force, a prismatic
/// joint a force across its guide and a couple.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum JointKind {
    /// A pin: the reaction is a force.
    Revolute,
    /// A slider on its guide: a force normal to the guide and a couple.
    Prismatic,
    /// A roller on a cam: a force along the contact normal, pushing for contact (a
    /// pull means the follower lifts off unless a spring or a groove holds it).
    CamContact,
}

/// The reaction in one joint.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct JointReaction {
    /// Column-ready name: revolute `POINT_LINKA_LINKB`, prismatic `SLIDER_on_GUIDE`,
    /// cam contact `ROLLER_CAM_FOLLOWER`.
    pub name: String,
    /// The joint's kind: whether `couple` is part of its reaction.
    pub kind: JointKind,
    /// Force on the second link from the first (revolute), on the slider from the
    /// guide (prismatic), or on the follower from the cam, N, as (x, y).
    pub force: (f64, f64),
    /// Prismatic only: the couple on the slider from the guide, N·m (0 for a revolute).
    pub couple: f64,
    /// Cam contacts only: the force along the contact normal, N; negative where the
    /// follower would lift off the cam unless a spring or a groove holds it.
    pub push: Option<f64>,
}

/// Kinetostatic state at one input angle.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct KinetostaticState {
    /// Input angle, rad.
    pub input_rad: f64,
    /// Input torque on the driver from Newton–Euler, N·m.
    pub torque_newton_euler: f64,
    /// Input torque from virtual work (power balance), N·m.
    pub torque_virtual_work: f64,
    /// Every joint reaction: revolutes, prismatic joints, then cam contacts, in scene
    /// order.
    pub joints: Vec<JointReaction>,
    /// Quasi-static force amplification of the output: output force (N, slider) or
    /// torque (N·m, rocker) per N·m of input torque, i.e. 1/|output velocity ratio|;
    /// `None` at a singular position (output velocity ratio zero: a toggle).
    pub amplification: Option<f64>,
}

/// Kinetostatics of the scene of `k`, at its crank speed.
pub struct Kinetostatics {
    forces: ForceModel,
    sol: Solution,
}

impl Kinetostatics {
    /// Builds the force model (springs unstretched at the start position, as in
    /// dynamics).
    ///
    /// # Errors
    /// A kinematics-only scene, a scene with no crank speed, or invalid force data.
    pub fn new(k: &mut Kinematics) -> Result<Self> {
        let m = k.mechanism().clone();
        if m.models == crate::scene::Models::Kinematics {
            return Err(LinkageError::from(SceneProblem::KinematicsOnly {
                scene: m.name.clone(),
            }));
        }
        if m.driver.speed_rad_s == 0.0 {
            return Err(LinkageError::from(SceneProblem::NoCrankSpeed));
        }
        let start = k.solve(m.driver.start_rad)?;
        Ok(Self {
            forces: ForceModel::new(&m, &start)?,
            sol: k.empty_solution(),
        })
    }

    /// The motion that the last [`Self::at`] solved (at the scene's crank speed).
    pub fn solution(&self) -> &Solution {
        &self.sol
    }

    /// The force elements the reactions are solved against.
    pub fn forces(&self) -> &ForceModel {
        &self.forces
    }

    /// The state at input angle `input_rad` at the scene's crank speed.
    ///
    /// # Errors
    /// Where the chain does not assemble, or where the reactions are indeterminate
    /// (the Newton–Euler system is singular: a dead point of the input).
    pub fn at(&mut self, k: &mut Kinematics, input_rad: f64) -> Result<KinetostaticState> {
        let omega = k.mechanism().driver.speed_rad_s;
        k.solve_into(input_rad, omega, &mut self.sol)?;
        crate::overflow::check(k, &self.sol)?;
        let m = k.mechanism();
        let sol = &self.sol;
        let applied = self.forces.applied_loads(sol);
        let inertia = self.forces.inertia_loads(sol);
        // Virtual work: T ω + Σ P_applied = Σ dE/dt over the moving links.
        let moving: Vec<LinkId> = m.moving_links().collect();
        let power_needed: f64 = moving
            .iter()
            .map(|&l| inertia[l].power - applied[l].power)
            .sum();
        let torque_virtual_work = power_needed / omega;

        // Newton–Euler: unknowns (Fx, Fy) per revolute, (N, C) per prismatic, N per
        // cam contact, T.
        let row_of = |link: LinkId| moving.iter().position(|&l| l == link).map(|i| 3 * i);
        let n = unknown_count(m);
        if 3 * moving.len() != n {
            return Err(LinkageError::NotDecomposable(
                crate::error::Undecomposable::KinetostaticsDof {
                    equations: 3 * moving.len(),
                    unknowns: n,
                },
            ));
        }
        // Each cam's contact, once for the matrix and the reactions.
        let contacts: Vec<CamContact> = m
            .cams
            .iter()
            .map(|c| c.contact(sol.links[c.cam].angle_rad()))
            .collect();
        let a = reaction_matrix(m, sol, &moving, &contacts);
        let mut b = DVector::<f64>::zeros(n);
        for &l in &moving {
            let r = row_of(l).unwrap_or(0);
            b[r] = inertia[l].force.x - applied[l].force.x;
            b[r + 1] = inertia[l].force.y - applied[l].force.y;
            b[r + 2] = inertia[l].moment - applied[l].moment;
        }
        let x = a.lu().solve(&b).ok_or_else(|| LinkageError::Singular {
            input_deg: input_rad.to_degrees(),
            reason: crate::error::Singularity::JointReactions,
        })?;
        let joints = reactions(m, sol, &x, &contacts);
        Ok(KinetostaticState {
            input_rad,
            torque_newton_euler: x[n - 1],
            torque_virtual_work,
            joints,
            amplification: amplification(m, sol, omega),
        })
    }
}

/// The Newton–Euler system's unknowns: (Fx, Fy) per revolute, (N, C) per prismatic
/// joint, N per cam contact, then the input torque.
fn unknown_count(m: &crate::Mechanism) -> usize {
    2 * m.revolutes.len() + 2 * m.sliders.len() + m.cams.len() + 1
}

/// The Newton–Euler system's matrix: three rows per moving link (force x, y, moment
/// about the origin), a column per unknown (see [`unknown_count`]).
fn reaction_matrix(
    m: &crate::Mechanism,
    sol: &Solution,
    moving: &[LinkId],
    contacts: &[CamContact],
) -> DMatrix<f64> {
    let row_of = |link: LinkId| moving.iter().position(|&l| l == link).map(|i| 3 * i);
    let (nr, np) = (m.revolutes.len(), m.sliders.len());
    let n = unknown_count(m);
    let mut a = DMatrix::<f64>::zeros(n, n);
    // A force f at point p on `link` in unknown column `col` (times the unknown).
    let put = |a: &mut DMatrix<f64>, link: LinkId, col: usize, f: Vec2, p: Vec2| {
        if let Some(r) = row_of(link) {
            a[(r, col)] += f.x;
            a[(r + 1, col)] += f.y;
            a[(r + 2, col)] += cross(&p, &f);
        }
    };
    for (j, rv) in m.revolutes.iter().enumerate() {
        let p = sol.points[rv.point].position;
        for (axis, unit) in [(0, Vec2::x()), (1, Vec2::y())] {
            put(&mut a, rv.b, 2 * j + axis, unit, p);
            put(&mut a, rv.a, 2 * j + axis, -unit, p);
        }
    }
    for (j, sl) in m.sliders.iter().enumerate() {
        let p = sol.points[sl.point].position;
        let normal = perp(&sl.direction(&sol.links));
        let col = 2 * nr + 2 * j;
        put(&mut a, sl.slider, col, normal, p);
        put(&mut a, sl.guide, col, -normal, p);
        if let Some(r) = row_of(sl.slider) {
            a[(r + 2, col + 1)] += 1.0;
        }
        if let Some(r) = row_of(sl.guide) {
            a[(r + 2, col + 1)] -= 1.0;
        }
    }
    for (j, (cam, contact)) in m.cams.iter().zip(contacts).enumerate() {
        let col = 2 * nr + 2 * np + j;
        put(&mut a, cam.follower, col, contact.normal, contact.roller);
        put(&mut a, cam.cam, col, -contact.normal, contact.point);
    }
    if let Some(r) = row_of(m.driver.link) {
        a[(r + 2, n - 1)] = 1.0;
    }
    a
}

/// Every joint's reaction from the solved unknowns `x`: revolutes, prismatic joints,
/// then cam contacts.
fn reactions(
    m: &crate::Mechanism,
    sol: &Solution,
    x: &DVector<f64>,
    contacts: &[CamContact],
) -> Vec<JointReaction> {
    let nr = m.revolutes.len();
    let name = |link: LinkId| m.links[link].name.as_str();
    let mut joints = Vec::with_capacity(nr + m.sliders.len());
    for (j, rv) in m.revolutes.iter().enumerate() {
        joints.push(JointReaction {
            name: format!("{}_{}_{}", m.points[rv.point].name, name(rv.a), name(rv.b)),
            kind: JointKind::Revolute,
            force: (x[2 * j], x[2 * j + 1]),
            couple: 0.0,
            push: None,
        });
    }
    for (j, sl) in m.sliders.iter().enumerate() {
        let normal = perp(&sl.direction(&sol.links));
        joints.push(JointReaction {
            name: format!("{}_on_{}", name(sl.slider), name(sl.guide)),
            kind: JointKind::Prismatic,
            force: (normal.x * x[2 * nr + 2 * j], normal.y * x[2 * nr + 2 * j]),
            couple: x[2 * nr + 2 * j + 1],
            push: None,
        });
    }
    let first_cam = 2 * nr + 2 * m.sliders.len();
    for (j, (cam, contact)) in m.cams.iter().zip(contacts).enumerate() {
        let normal = contact.normal;
        let push = x[first_cam + j];
        joints.push(JointReaction {
            name: format!(
                "{}_{}_{}",
                m.points[cam.roller].name,
                name(cam.cam),
                name(cam.follower)
            ),
            kind: JointKind::CamContact,
            force: (normal.x * push, normal.y * push),
            couple: 0.0,
            push: Some(push),
        });
    }
    joints
}

/// 1/|output velocity ratio| of the scene's output (its slider if it has one, else
/// its angle), `None` below 1e-9 of the chain's size per radian (a toggle).
fn amplification(m: &crate::Mechanism, sol: &Solution, omega: f64) -> Option<f64> {
    let out = m.output;
    // (output velocity ratio, the scale a toggle's ratio is small against)
    let (ratio, scale) = match m.sliders.iter().position(|s| s.slider == out) {
        Some(i) => (sol.slides[i].velocity_m_s / omega, m.size_m),
        None => (sol.links[out].omega_rad_s / omega, 1.0),
    };
    if ratio.abs() < 1e-9 * scale || !ratio.is_finite() {
        return None;
    }
    Some(1.0 / ratio.abs())
}
