//! The right-hand side of the reduced equation in the current integration coordinate,
//! and the switch to another coordinate near a dead point of the current one.
//!
//! The state is y = (x, v, w): the coordinate (a link's angle), its rate, and the work
//! done so far by non-conservative elements. Carrying w as a state integrates the
//! energy balance to the method's own order instead of by a separate quadrature.

use super::forces::{ForceModel, Reduced, unit_solution};
use crate::error::{LinkageError, Result};
use crate::ids::LinkId;
use crate::motion::Solution;
use crate::solve::Kinematics;

/// State (x, v, w) in the current coordinate.
pub(crate) type State = [f64; 3];

/// A state with its time, derivative and reduction: what a step starts from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Point {
    pub t: f64,
    pub y: State,
    /// dy/dt at y.
    pub f: State,
    pub reduced: Reduced,
}

/// A coordinate's velocity ratio above this (some other pivoted link turns this many
/// times faster) means the coordinate nears a dead point: J grows as the square of
/// the ratio, so the step size would collapse.
const SWITCH_RATIO: f64 = 2.0;

/// Without switching, a velocity ratio above this is reported as a dead point.
const DEAD_POINT_RATIO: f64 = 1e3;

/// The reduced model in the current coordinate, with its cost counters.
pub(crate) struct Rhs {
    /// Kinematics driven by the current coordinate.
    pub k: Kinematics,
    pub forces: ForceModel,
    /// Unit-speed solution of the last kinematic solve.
    pub sol: Solution,
    /// Links that can serve as coordinate (revolute to ground).
    candidates: Vec<LinkId>,
    /// Whether to switch coordinates near a dead point (else a dead point is an error).
    allow_switch: bool,
    /// Coordinate of the position in `sol` (NaN before the first solve).
    solved_at: f64,
    /// Reductions for the integrator.
    pub evaluations: usize,
    /// All kinematic solves (reductions, events, output, Jacobians).
    pub solves: usize,
}

impl Rhs {
    pub fn new(k: Kinematics, forces: ForceModel, allow_switch: bool) -> Self {
        let m = k.mechanism();
        let candidates = m
            .moving_links()
            .filter(|&l| m.ground_pivot_of(l).is_some())
            .collect();
        Self {
            sol: k.empty_solution(),
            k,
            forces,
            candidates,
            allow_switch,
            solved_at: f64::NAN,
            evaluations: 0,
            solves: 0,
        }
    }

    /// The link whose angle is the current coordinate.
    pub fn coordinate_link(&self) -> LinkId {
        self.k.mechanism().driver.link
    }

    /// Solves the position at coordinate `x` into `self.sol` (unit rate).
    pub fn solve_position(&mut self, x: f64) -> Result<()> {
        self.solves += 1;
        self.solved_at = f64::NAN;
        unit_solution(&mut self.k, x, &mut self.sol)?;
        self.solved_at = x;
        Ok(())
    }

    /// Makes `self.sol` hold the position at `x`, solving only if it does not yet.
    pub fn ensure_position(&mut self, x: f64) -> Result<()> {
        if self.solved_at != x {
            self.solve_position(x)?;
        }
        Ok(())
    }

    /// The partial derivatives (∂q̈/∂x, ∂q̈/∂v) at `a`: ∂/∂x by a forward difference
    /// (one evaluation), ∂/∂v from the reduction at `a`'s position (J does not depend
    /// on v, so no solve). For the implicit rule's Newton matrix and the stiffness.
    pub fn linearise(&mut self, a: &Point) -> Result<(f64, f64)> {
        let (x0, v0) = (a.y[0], a.y[1]);
        let dv = 1e-7 * (1.0 + v0.abs());
        self.ensure_position(x0)?;
        let r_dv = self.reduce_here(&[x0, v0 + dv, a.y[2]])?;
        let acc_v = (r_dv.acceleration(v0 + dv) - a.f[1]) / dv;
        let dx = 1e-7 * (1.0 + x0.abs());
        let (f_dx, _) = self.eval(&[x0 + dx, v0, a.y[2]])?;
        let acc_x = (f_dx[1] - a.f[1]) / dx;
        Ok((acc_x, acc_v))
    }

    /// Reduction at the position already in `self.sol`, refusing a singular J.
    pub fn reduce_here(&self, y: &State) -> Result<Reduced> {
        let r = self.forces.reduce(&self.sol, y[1]);
        if !(r.j > 0.0 && r.j.is_finite()) {
            return Err(LinkageError::Singular {
                input_deg: y[0].to_degrees(),
                reason: crate::error::Singularity::NoInertia { j_kg_m2: r.j },
            });
        }
        Ok(r)
    }

    /// One evaluation of dy/dt at `y` (one kinematic solve).
    pub fn eval(&mut self, y: &State) -> Result<(State, Reduced)> {
        self.evaluations += 1;
        self.solve_position(y[0])?;
        let r = self.reduce_here(y)?;
        Ok((derivative(y, &r), r))
    }

    /// A [`Point`] at (t, y), one evaluation.
    pub fn point(&mut self, t: f64, y: State) -> Result<Point> {
        let (f, reduced) = self.eval(&y)?;
        Ok(Point { t, y, f, reduced })
    }

    /// When another pivoted link turns more than [`SWITCH_RATIO`] times faster than
    /// the coordinate at `p`, makes the fastest one the
    /// coordinate and returns `p` expressed in it. Its angle is regular where the
    /// current one has a dead point, so J stays bounded.
    pub fn switch_if_needed(&mut self, p: &Point) -> Result<Option<Point>> {
        if self.candidates.len() < 2 {
            return Ok(None);
        }
        self.ensure_position(p.y[0])?;
        let fastest = self
            .candidates
            .iter()
            .map(|&l| (l, self.sol.links[l].omega_rad_s.abs()))
            .max_by(|a, b| a.1.total_cmp(&b.1));
        let Some((link, ratio)) = fastest else {
            return Ok(None);
        };
        if ratio <= SWITCH_RATIO || link == self.coordinate_link() {
            return Ok(None);
        }
        if !self.allow_switch {
            // J has grown by the square of the ratio: the motion can only creep up to
            // the dead point in this coordinate, so say so instead of stalling there.
            if ratio > DEAD_POINT_RATIO {
                let m = self.k.mechanism();
                return Err(LinkageError::Singular {
                    input_deg: p.y[0].to_degrees(),
                    reason: crate::error::Singularity::CoordinateDeadPoint {
                        coordinate: m.links[self.coordinate_link()].name.clone(),
                        regular: m.links[link].name.clone(),
                        ratio,
                    },
                });
            }
            return Ok(None);
        }
        let omega = self.sol.links[link].omega_rad_s;
        let x = self.sol.links[link].angle_rad();
        self.k = self.k.redriven(link, &self.sol)?;
        let y = [x, omega * p.y[1], p.y[2]];
        Ok(Some(self.point(p.t, y)?))
    }
}

/// dy/dt = (v, q̈, non-conservative power).
pub(crate) fn derivative(y: &State, r: &Reduced) -> State {
    [y[1], r.acceleration(y[1]), r.m_nonconservative() * y[1]]
}
