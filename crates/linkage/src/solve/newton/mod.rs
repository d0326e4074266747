//! General Newton–Raphson on the loop-closure constraints.
//!
//! The chain is cut into a spanning tree rooted at ground (driver joint first);
//! the unknowns are the tree joints' relative coordinates (joint angle or slide),
//! and every joint left out of the tree closes a loop with two equations (every cam
//! joint adds one: its follower's coordinate is the program's lift, `cam_rows.rs`). Jacobian
//! columns are the cut joints' relative velocities for a unit rate of one tree
//! coordinate: a turn about that joint or a slide along it, of every link it
//! carries, written directly from the joint points. Velocity
//! solves `J q̇ = -j_in ω_in`; acceleration solves `J q̈ = -b` where `b` is the
//! cut joints' relative acceleration with zero coordinate accelerations (the
//! quadratic-velocity term, Coriolis included).

use nalgebra::{DMatrix, DVector, UnitComplex};

use crate::error::{LinkageError, Result};
use crate::ids::LinkId;
use crate::model::SceneProblem;
use crate::model::{Mechanism, Prismatic};
use crate::motion::{LinkMotion, PointMotion, Vec2, cross, perp};
use crate::small_lu::SmallLu;

mod branch;
mod cam_rows;
mod mobility;

#[derive(Clone, Debug, PartialEq)]
enum TreeKind {
    Revolute {
        on_parent: Vec2,
        on_child: Vec2,
    },
    /// `parent_is_guide`: the slider is the child (else the guide is).
    Prismatic {
        slide: Prismatic,
        parent_is_guide: bool,
    },
}

#[derive(Clone, Debug, PartialEq)]
struct TreeJoint {
    parent: LinkId,
    child: LinkId,
    kind: TreeKind,
    /// World joint point (revolute) or slide contact point, from the last position pass.
    contact: Vec2,
    /// World guide direction (prismatic), from the last position pass.
    u: Vec2,
}

#[derive(Clone, Debug, PartialEq)]
enum Cut {
    Revolute {
        a: LinkId,
        a_local: Vec2,
        b: LinkId,
        b_local: Vec2,
    },
    Prismatic(Prismatic),
}

/// The rotation of one revolute tree joint with the angle it was made for. Newton
/// moves a joint angle by small steps (predictor, corrections), so the next
/// rotation is this one turned by the step through a short series, not a new sine
/// and cosine (those were most of the solver's cost). The input joint is always
/// rotated exactly, since nothing corrects its rotation's round-off.
#[derive(Clone, Copy, Debug, PartialEq)]
struct JointTurn {
    angle: f64,
    rotation: UnitComplex<f64>,
}

/// Largest step taken by the series of [`small_turn`], rad (its first omitted
/// terms are below 1e-20 there).
const SMALL_TURN: f64 = 1.0 / 16.0;

/// `exp(i·step)` for |step| ≤ [`SMALL_TURN`], by the Taylor series of sine and cosine.
#[inline]
fn small_turn(step: f64) -> UnitComplex<f64> {
    let s2 = step * step;
    let sin = step
        * (1.0
            - s2 / 6.0
                * (1.0 - s2 / 20.0 * (1.0 - s2 / 42.0 * (1.0 - s2 / 72.0 * (1.0 - s2 / 110.0)))));
    let cos = 1.0
        - s2 / 2.0
            * (1.0
                - s2 / 12.0
                    * (1.0
                        - s2 / 30.0 * (1.0 - s2 / 56.0 * (1.0 - s2 / 90.0 * (1.0 - s2 / 132.0)))));
    UnitComplex::from_cos_sin_unchecked(cos, sin)
}

impl JointTurn {
    /// A turn with no cached angle: the first request computes it exactly.
    const UNSET: Self = Self {
        angle: f64::NAN,
        rotation: UnitComplex::new_unchecked(nalgebra::Complex { re: 1.0, im: 0.0 }),
    };

    /// The rotation by `angle`; `exact` forces a fresh sine and cosine.
    #[inline]
    fn to(&mut self, angle: f64, exact: bool) -> UnitComplex<f64> {
        if angle != self.angle {
            let step = angle - self.angle;
            self.rotation = if !exact && step.abs() <= SMALL_TURN {
                let mut turned = self.rotation * small_turn(step);
                turned.renormalize_fast();
                turned
            } else {
                UnitComplex::new(angle)
            };
            self.angle = angle;
        }
        self.rotation
    }
}

/// Newton–Raphson position solver with velocity and acceleration from the Jacobian.
#[derive(Clone, Debug)]
pub struct Newton {
    tree: Vec<TreeJoint>,
    /// Rotation of each tree joint (unused for prismatic ones), see [`JointTurn`].
    turns: Vec<JointTurn>,
    /// `moved_by[link * tree.len() + k]`: tree joint `k` lies on the path from ground
    /// to `link`, so a rate of `k` moves `link`.
    moved_by: Vec<bool>,
    cuts: Vec<Cut>,
    /// Cam joints: a row each after the cut joints' (`cam_rows.rs`).
    cams: Vec<crate::model::CamJoint>,
    ground: LinkId,
    /// Largest residual accepted, as a share of the size (and rad).
    tolerance: f64,
    /// Largest residual accepted when Newton stalls at round-off (as a share of the
    /// size, and rad).
    stall_residual: f64,
    /// The mechanism's size, m: residuals in metres count relative to it, so that a
    /// 50 µm chain converges exactly as its 50 m twin does.
    size_m: f64,
    max_iterations: usize,
    /// Unknown coordinates (tree joints after the driver).
    q: DVector<f64>,
    /// dq/d(input) and d²q/d(input)² at the last solution.
    dq: DVector<f64>,
    ddq: DVector<f64>,
    /// d³q/d(input)³ estimated from the last two accepted steps' q'' (zero until there
    /// are two), for a third-order predictor.
    jerk: DVector<f64>,
    /// Accepted continuation steps since the pose was set or a step was refused.
    steady_steps: u32,
    /// The input of the last solution, unwrapped along the branch followed.
    last_input: Option<f64>,
    /// The branch's assembly range (unwrapped, holding the start) once traced and
    /// found limited: inputs are then taken inside it (see `branch.rs`).
    range: Option<[f64; 2]>,
    /// Sign of det J at the last solution (0 before the first): the assembly mode.
    det_sign: f64,
    /// |det J| over the product of its column norms at the last solution.
    conditioning: f64,
    jac: DMatrix<f64>,
    /// LU of the Jacobian at the last converged pose, reused by chord iterations.
    lu: SmallLu,
    rhs: DVector<f64>,
    rates: Vec<f64>,
    /// Reused buffers: acceleration bias, residual, saved state, predictor step.
    col_buf: Vec<f64>,
    res_buf: Vec<f64>,
    saved: (DVector<f64>, DVector<f64>, DVector<f64>),
    increment: DVector<f64>,
    /// Iterations used by the last solve (for diagnostics and benchmarks).
    pub last_iterations: usize,
}

/// The link at the other end of a joint between links `a` and `b`, seen from `from`;
/// `None` when the joint does not touch `from`.
fn across(a: LinkId, b: LinkId, from: LinkId) -> Option<LinkId> {
    if a == from {
        Some(b)
    } else if b == from {
        Some(a)
    } else {
        None
    }
}

/// Largest change of any coordinate the predictor may make in one step (rad, or for a
/// sliding joint metres per metre of the mechanism's size).
const MAX_PREDICTED_CHANGE: f64 = 0.2;

/// Largest step of the input between two Newton solves on one branch, rad.
const CONTINUATION_STEP: f64 = 2.0 * std::f64::consts::PI / 180.0;

/// Shortest step an ordinary solve halves down to before it gives up, rad.
const MIN_STEP: f64 = 1e-7;

/// Shortest step when tracing a branch to its folds, rad: the fold is located to
/// about twice this (the tests ask for 1e-6 rad).
const FOLD_STEP: f64 = 1e-10;

impl Newton {
    /// Builds the tree and cut joints and the starting pose. `start` gives every
    /// link's pose at the scene's start input (from the closed form or the scene's
    /// guesses); the solver then tracks the branch by continuity.
    pub fn new(
        m: &Mechanism,
        start: &[LinkMotion],
        tolerance: f64,
        max_iterations: usize,
    ) -> Result<Self> {
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(LinkageError::InvalidParameter {
                name: "Newton tolerance".into(),
                value: tolerance,
                valid: "must be finite and > 0".into(),
            });
        }
        let (tree, cuts) = spanning_tree(m)?;
        let unknowns = tree.len() - 1;
        let equations = 2 * cuts.len() + m.cams.len();
        if equations != unknowns {
            return Err(LinkageError::from(SceneProblem::EquationCount {
                equations,
                unknowns,
            }));
        }
        let moved_by = moved_by(&tree, m.links.len());
        let mut solver = Self {
            turns: vec![JointTurn::UNSET; tree.len()],
            moved_by,
            tree,
            cuts,
            cams: m.cams.clone(),
            ground: m.ground,
            tolerance: tolerance.max(8.0 * f64::EPSILON),
            stall_residual: 1e-12,
            size_m: m.size_m,
            max_iterations,
            q: DVector::zeros(unknowns),
            dq: DVector::zeros(unknowns),
            ddq: DVector::zeros(unknowns),
            jerk: DVector::zeros(unknowns),
            steady_steps: 0,
            last_input: None,
            range: None,
            det_sign: 0.0,
            conditioning: 1.0,
            jac: DMatrix::zeros(unknowns, unknowns),
            lu: SmallLu::default(),
            rhs: DVector::zeros(unknowns),
            rates: vec![0.0; 2 * unknowns.max(1)],
            col_buf: vec![0.0; equations],
            res_buf: vec![0.0; equations],
            saved: (
                DVector::zeros(unknowns),
                DVector::zeros(unknowns),
                DVector::zeros(unknowns),
            ),
            increment: DVector::zeros(unknowns),
            last_iterations: 0,
        };
        solver.set_pose(start, m.driver.start_rad);
        Ok(solver)
    }

    /// Keeps joint angles in (-π, π]: they only enter through sin/cos, and a large
    /// angle would cost digits there.
    fn wrap_angles(&mut self) {
        for (k, t) in self.tree.iter().enumerate().skip(1) {
            if matches!(t.kind, TreeKind::Revolute { .. }) {
                let q = &mut self.q[k - 1];
                *q -= (*q / std::f64::consts::TAU).round() * std::f64::consts::TAU;
            }
        }
    }

    /// Number of unknown coordinates.
    pub fn unknowns(&self) -> usize {
        self.q.len()
    }

    /// Sets the tracked coordinates from a full set of link poses at `input_rad`.
    pub fn set_pose(&mut self, links: &[LinkMotion], input_rad: f64) {
        for (k, t) in self.tree.iter().enumerate().skip(1) {
            let (p, c) = (&links[t.parent], &links[t.child]);
            self.q[k - 1] = match &t.kind {
                TreeKind::Revolute { .. } => (p.rotation.inverse() * c.rotation).angle(),
                TreeKind::Prismatic { slide, .. } => {
                    let (s, g) = (&links[slide.slider], &links[slide.guide]);
                    (s.world(&slide.slider_local) - g.world(&slide.through_local))
                        .dot(&(g.rotation * slide.direction_local))
                }
            };
        }
        self.dq.fill(0.0);
        self.ddq.fill(0.0);
        self.jerk.fill(0.0);
        self.steady_steps = 0;
        self.lu.invalidate();
        self.last_input = Some(input_rad);
    }

    /// Places every link for coordinates `q` (driver angle `input`); velocities untouched.
    fn position_pass(&mut self, input: f64, links: &mut [LinkMotion]) {
        links[self.ground] = LinkMotion::default();
        for k in 0..self.tree.len() {
            let q = if k == 0 { input } else { self.q[k - 1] };
            let t = &mut self.tree[k];
            let parent = links[t.parent];
            let child = &mut links[t.child];
            match &t.kind {
                TreeKind::Revolute {
                    on_parent,
                    on_child,
                } => {
                    let j = parent.world(on_parent);
                    child.rotation = parent.rotation * self.turns[k].to(q, k == 0);
                    child.origin.position = j - child.rotation * on_child;
                    t.contact = j;
                }
                TreeKind::Prismatic {
                    slide,
                    parent_is_guide: true,
                } => {
                    let u = parent.rotation * slide.direction_local;
                    let p = parent.world(&slide.through_local) + u * q;
                    child.rotation = parent.rotation * slide.relative;
                    child.origin.position = p - child.rotation * slide.slider_local;
                    (t.contact, t.u) = (p, u);
                }
                TreeKind::Prismatic {
                    slide,
                    parent_is_guide: false,
                } => {
                    child.rotation = parent.rotation * slide.relative.inverse();
                    let u = child.rotation * slide.direction_local;
                    let through = parent.world(&slide.slider_local) - u * q;
                    child.origin.position = through - child.rotation * slide.through_local;
                    (t.contact, t.u) = (through, u);
                }
            }
        }
    }

    /// Sets every link's velocity and acceleration for coordinate rates `rate(k)` and
    /// second derivatives `accel(k)` (k = 0 is the driver), positions fixed.
    fn motion_pass(
        &self,
        links: &mut [LinkMotion],
        rate: impl Fn(usize) -> f64,
        accel: impl Fn(usize) -> f64,
    ) {
        links[self.ground] = LinkMotion::default();
        for (k, t) in self.tree.iter().enumerate() {
            let parent = links[t.parent];
            let (qd, qdd) = (rate(k), accel(k));
            let child = &mut links[t.child];
            let (omega, alpha, local, pin) = match &t.kind {
                TreeKind::Revolute { on_child, .. } => (
                    parent.omega_rad_s + qd,
                    parent.alpha_rad_s2 + qdd,
                    *on_child,
                    parent.material_point_at(&t.contact),
                ),
                TreeKind::Prismatic {
                    slide,
                    parent_is_guide,
                } => {
                    let (sign, local) = if *parent_is_guide {
                        (1.0, slide.slider_local)
                    } else {
                        (-1.0, slide.through_local)
                    };
                    let base = parent.material_point_at(&t.contact);
                    let pin = PointMotion {
                        position: t.contact,
                        velocity: base.velocity + t.u * (sign * qd),
                        acceleration: base.acceleration
                            + perp(&t.u) * (2.0 * parent.omega_rad_s * sign * qd)
                            + t.u * (sign * qdd),
                    };
                    (parent.omega_rad_s, parent.alpha_rad_s2, local, pin)
                }
            };
            *child = LinkMotion::from_pin(child.rotation, omega, alpha, &local, &pin);
        }
    }

    /// Cut-joint residuals (positions), written to `out`; returns the max-norm.
    fn residual(&self, links: &[LinkMotion], out: &mut [f64]) -> f64 {
        let mut worst: f64 = 0.0;
        let per_m = 1.0 / self.size_m;
        for (c, cut) in self.cuts.iter().enumerate() {
            let (r0, r1) = match cut {
                Cut::Revolute {
                    a,
                    a_local,
                    b,
                    b_local,
                } => {
                    let d = links[*a].world(a_local) - links[*b].world(b_local);
                    (d.x, d.y)
                }
                Cut::Prismatic(s) => {
                    let (sl, g) = (&links[s.slider], &links[s.guide]);
                    let u = g.rotation * s.direction_local;
                    let d = sl.world(&s.slider_local) - g.world(&s.through_local);
                    let turn = ((g.rotation * s.relative).inverse() * sl.rotation).angle();
                    (cross(&u, &d), turn)
                }
            };
            out[2 * c] = r0;
            out[2 * c + 1] = r1;
            let r1_relative = match cut {
                Cut::Revolute { .. } => r1 * per_m,
                Cut::Prismatic(_) => r1,
            };
            worst = worst.max(r0.abs() * per_m).max(r1_relative.abs());
        }
        worst.max(self.cam_residuals(links, out, 2 * self.cuts.len()))
    }

    /// Second time derivative of the cut residuals (the acceleration bias `b` when the
    /// coordinates' second derivatives are zero).
    fn cut_accelerations(&self, links: &[LinkMotion], out: &mut [f64]) {
        for (c, cut) in self.cuts.iter().enumerate() {
            let (r0, r1) = match cut {
                Cut::Revolute {
                    a,
                    a_local,
                    b,
                    b_local,
                } => {
                    let (pa, pb) = (links[*a].point(a_local), links[*b].point(b_local));
                    let d = pa.acceleration - pb.acceleration;
                    (d.x, d.y)
                }
                Cut::Prismatic(s) => {
                    let (sl, g) = (&links[s.slider], &links[s.guide]);
                    let u = g.rotation * s.direction_local;
                    let (p, q) = (sl.point(&s.slider_local), g.point(&s.through_local));
                    let d = p.position - q.position;
                    let dd = p.velocity - q.velocity;
                    let u_dot = perp(&u) * g.omega_rad_s;
                    let u_ddot = perp(&u) * g.alpha_rad_s2 - u * (g.omega_rad_s * g.omega_rad_s);
                    let ddd = p.acceleration - q.acceleration;
                    (
                        cross(&u_ddot, &d) + 2.0 * cross(&u_dot, &dd) + cross(&u, &ddd),
                        sl.alpha_rad_s2 - g.alpha_rad_s2,
                    )
                }
            };
            out[2 * c] = r0;
            out[2 * c + 1] = r1;
        }
        self.cam_accelerations(links, out, 2 * self.cuts.len());
    }

    /// Velocity of the material point at `p` of `link`, and the link's angular
    /// velocity, for a unit rate of tree joint `k` with every other coordinate still:
    /// a turn about the joint or a slide along its guide, if `k` carries the link.
    #[inline]
    fn unit_rate(&self, k: usize, link: LinkId, p: &Vec2) -> (Vec2, f64) {
        if !self.moved_by[link.index() * self.tree.len() + k] {
            return (Vec2::zeros(), 0.0);
        }
        let t = &self.tree[k];
        match &t.kind {
            TreeKind::Revolute { .. } => (perp(&(p - t.contact)), 1.0),
            TreeKind::Prismatic {
                parent_is_guide, ..
            } => (t.u * if *parent_is_guide { 1.0 } else { -1.0 }, 0.0),
        }
    }

    /// Jacobian of the cut residuals at the current positions (columns: unknowns) and,
    /// in `self.rates`, the driver's column. Each column is the cut joints' relative
    /// velocity for a unit rate of one tree joint, written directly from the joint
    /// points (what a velocity pass with that one rate would give, without the pass).
    fn build_jacobian(&mut self, links: &[LinkMotion]) {
        for (c, cut) in self.cuts.iter().enumerate() {
            // The cut's points and guide direction are the same for every column.
            let (first, second, guide_dir) = match cut {
                Cut::Revolute {
                    a,
                    a_local,
                    b,
                    b_local,
                } => (
                    (*a, links[*a].world(a_local)),
                    (*b, links[*b].world(b_local)),
                    None,
                ),
                Cut::Prismatic(s) => (
                    (s.slider, links[s.slider].world(&s.slider_local)),
                    (s.guide, links[s.guide].world(&s.through_local)),
                    Some(links[s.guide].rotation * s.direction_local),
                ),
            };
            for k in 0..self.tree.len() {
                let (v_first, w_first) = self.unit_rate(k, first.0, &first.1);
                let (v_second, w_second) = self.unit_rate(k, second.0, &second.1);
                let (r0, r1) = match guide_dir {
                    None => (v_first.x - v_second.x, v_first.y - v_second.y),
                    // Slider point on the guide line: d/dt cross(u, p - q), and the
                    // slider's turn relative to the guide.
                    Some(u) => (
                        cross(&(perp(&u) * w_second), &(first.1 - second.1))
                            + cross(&u, &(v_first - v_second)),
                        w_first - w_second,
                    ),
                };
                if k == 0 {
                    self.rates[2 * c] = r0;
                    self.rates[2 * c + 1] = r1;
                } else {
                    self.jac[(2 * c, k - 1)] = r0;
                    self.jac[(2 * c + 1, k - 1)] = r1;
                }
            }
        }
        self.cam_jacobian_rows(links, 2 * self.cuts.len());
    }

    /// Solves at `input_rad` with input speed `speed_rad_s` (constant), writing every
    /// link's motion to `links`. Returns a conditioning estimate in [0, 1].
    pub fn solve_links(
        &mut self,
        input_rad: f64,
        speed_rad_s: f64,
        links: &mut [LinkMotion],
    ) -> Result<f64> {
        if !input_rad.is_finite() || !speed_rad_s.is_finite() {
            return Err(LinkageError::InvalidParameter {
                name: "input".into(),
                value: if input_rad.is_finite() {
                    speed_rad_s
                } else {
                    input_rad
                },
                valid: "input angle and speed must be finite".into(),
            });
        }
        let target = self.target(input_rad)?;
        if self.last_input == Some(target) {
            // The same input again (or the pose was just set): correct in place.
            self.correct(target, links)?;
            self.update_derivatives(links)?;
        } else {
            // Inside a traced range the branch is known to reach its folds: follow it
            // as close to them as the trace did.
            let min_step = if self.range.is_some() {
                FOLD_STEP
            } else {
                MIN_STEP
            };
            self.continue_to(target, links, min_step)
                .map_err(|stop| stop.error)?;
        }
        // Final motion at the real speed: q̇ = ω q', q̈ = ω² q'' (constant input speed).
        let w = speed_rad_s;
        self.motion_pass(
            links,
            |k| if k == 0 { w } else { w * self.dq[k - 1] },
            |k| if k == 0 { 0.0 } else { w * w * self.ddq[k - 1] },
        );
        Ok(self.conditioning)
    }

    /// Newton iterations at fixed input from the current `q`.
    fn correct(&mut self, input: f64, links: &mut [LinkMotion]) -> Result<()> {
        let mut res = std::mem::take(&mut self.res_buf);
        let outcome = self.iterate(input, links, &mut res);
        self.res_buf = res;
        outcome
    }

    /// The Newton loop of [`Self::correct`], with the residual buffer passed in.
    ///
    /// The first iterations reuse the LU of the previous converged pose (chord
    /// Newton): the predictor leaves an error of order h³ and the old Jacobian is off by
    /// order h, so each chord step gains about three digits; when a step gains less
    /// than one, a fresh Jacobian is factored and iterations are Newton's again.
    fn iterate(&mut self, input: f64, links: &mut [LinkMotion], res: &mut [f64]) -> Result<()> {
        let mut previous = f64::INFINITY;
        let mut fresh = !self.lu.is_valid();
        for iter in 0..=self.max_iterations {
            self.position_pass(input, links);
            let worst = self.residual(links, res);
            // Growing residual after a few steps: diverging (no solution near here).
            if !worst.is_finite() || (iter >= 4 && worst > previous) {
                return Err(LinkageError::NewtonDiverged {
                    input_deg: input.to_degrees(),
                    iterations: iter,
                    residual: worst,
                    tolerance: self.tolerance,
                });
            }
            let slow = worst > 0.1 * previous;
            previous = worst;
            if worst <= self.tolerance {
                self.last_iterations = iter;
                return Ok(());
            }
            if iter == self.max_iterations {
                return Err(LinkageError::NewtonDiverged {
                    input_deg: input.to_degrees(),
                    iterations: iter,
                    residual: worst,
                    tolerance: self.tolerance,
                });
            }
            if !fresh && (slow || iter >= 3) {
                self.lu.invalidate();
                // Judge divergence from here on by true Newton steps only.
                previous = f64::INFINITY;
            }
            if !self.lu.is_valid() {
                self.refactor(links);
                fresh = true;
            }
            let mut solved = self.newton_step(res);
            if !solved && !fresh {
                // The stale factorization is singular; the fresh one may not be.
                self.refactor(links);
                fresh = true;
                solved = self.newton_step(res);
            }
            if !solved {
                return Err(LinkageError::Singular {
                    input_deg: input.to_degrees(),
                    reason: "the loop-closure Jacobian is singular (dead point or unassemblable)"
                        .into(),
                });
            }
            self.q += &self.rhs;
            // Near a dead point J is ill-conditioned and the residual floor can sit above
            // the tolerance; a step at round-off level means Newton has converged anyway.
            if fresh && self.rhs.amax() <= 4.0 * f64::EPSILON * (1.0 + self.q.amax()) {
                self.position_pass(input, links);
                // ...but only at a solution: outside the assembly range Newton also
                // stalls, at a least-residual pose that closes nothing.
                let worst = self.residual(links, res);
                if worst <= self.stall_residual {
                    self.last_iterations = iter + 1;
                    return Ok(());
                }
                return Err(LinkageError::NewtonDiverged {
                    input_deg: input.to_degrees(),
                    iterations: iter + 1,
                    residual: worst,
                    tolerance: self.tolerance,
                });
            }
        }
        Err(LinkageError::NewtonDiverged {
            input_deg: input.to_degrees(),
            iterations: self.max_iterations,
            residual: f64::NAN,
            tolerance: self.tolerance,
        })
    }

    /// Builds and factors the Jacobian at the current positions.
    fn refactor(&mut self, links: &mut [LinkMotion]) {
        self.build_jacobian(links);
        self.lu.factor(&self.jac);
    }

    /// Solves `J Δ = −res` into `self.rhs` with the held factorization; false if singular.
    fn newton_step(&mut self, res: &[f64]) -> bool {
        self.rhs.iter_mut().zip(res).for_each(|(r, v)| *r = -v);
        self.lu.solve_mut(&mut self.rhs)
    }

    /// Computes dq/d(input) and d²q/d(input)² at the converged pose.
    fn update_derivatives(&mut self, links: &mut [LinkMotion]) -> Result<()> {
        let n = self.q.len();
        self.build_jacobian(links);
        self.lu.factor(&self.jac);
        let det = self.lu.determinant();
        self.det_sign = det.signum();
        let norms: f64 = self.jac.column_iter().map(|c| c.norm()).product();
        self.conditioning = if norms > 0.0 {
            (det.abs() / norms).min(1.0)
        } else {
            1.0
        };
        for r in 0..n {
            self.rhs[r] = -self.rates[r];
        }
        if !self.lu.solve_mut(&mut self.rhs) {
            return Err(LinkageError::Singular {
                input_deg: self.last_input.unwrap_or(0.0).to_degrees(),
                reason: "the loop-closure Jacobian is singular: a dead point of this input".into(),
            });
        }
        self.dq.copy_from(&self.rhs);
        self.motion_pass(
            links,
            |k| if k == 0 { 1.0 } else { self.dq[k - 1] },
            |_| 0.0,
        );
        let mut bias = std::mem::take(&mut self.col_buf);
        self.cut_accelerations(links, &mut bias);
        self.rhs.iter_mut().zip(&bias).for_each(|(r, b)| *r = -b);
        self.col_buf = bias;
        self.lu.solve_mut(&mut self.rhs);
        self.ddq.copy_from(&self.rhs);
        Ok(())
    }
}

/// The chain as a tree from the ground, breadth first, the driver's pivot first,
/// and the joints left over (cut) to close its loops.
fn spanning_tree(m: &Mechanism) -> Result<(Vec<TreeJoint>, Vec<Cut>)> {
    let n = m.links.len();
    let mut visited = vec![false; n];
    visited[m.ground] = true;
    let mut used_rev = vec![false; m.revolutes.len()];
    let mut used_pri = vec![false; m.sliders.len()];
    let mut tree = vec![revolute_joint(m, m.driver.pivot, m.ground)];
    used_rev[m.driver.pivot] = true;
    visited[m.driver.link] = true;
    let mut queue = std::collections::VecDeque::from([m.ground, m.driver.link]);
    while let Some(l) = queue.pop_front() {
        for (r, rv) in m.revolutes.iter().enumerate() {
            let Some(other) = across(rv.a, rv.b, l) else {
                continue;
            };
            if used_rev[r] || visited[other] {
                continue;
            }
            used_rev[r] = true;
            visited[other] = true;
            tree.push(revolute_joint(m, r, l));
            queue.push_back(other);
        }
        for (p, s) in m.sliders.iter().enumerate() {
            let Some(other) = across(s.slider, s.guide, l) else {
                continue;
            };
            if used_pri[p] || visited[other] {
                continue;
            }
            used_pri[p] = true;
            visited[other] = true;
            tree.push(TreeJoint {
                parent: l,
                child: other,
                kind: TreeKind::Prismatic {
                    slide: s.clone(),
                    parent_is_guide: s.guide == l,
                },
                contact: Vec2::zeros(),
                u: Vec2::zeros(),
            });
            queue.push_back(other);
        }
    }
    if let Some(l) = visited.iter().position(|v| !v) {
        return Err(LinkageError::from(SceneProblem::Unconnected {
            link: m.links[l].name.clone(),
        }));
    }
    let mut cuts: Vec<Cut> = m
        .revolutes
        .iter()
        .enumerate()
        .filter(|(r, _)| !used_rev[*r])
        .map(|(_, rv)| Cut::Revolute {
            a: rv.a,
            a_local: rv.a_local,
            b: rv.b,
            b_local: rv.b_local,
        })
        .collect();
    cuts.extend(
        m.sliders
            .iter()
            .enumerate()
            .filter(|(p, _)| !used_pri[*p])
            .map(|(_, s)| Cut::Prismatic(s.clone())),
    );
    Ok((tree, cuts))
}

/// Revolute `r` as a joint of the tree, from `parent` to the link across it.
fn revolute_joint(m: &Mechanism, r: usize, parent: LinkId) -> TreeJoint {
    let rv = &m.revolutes[r];
    let (child, on_parent, on_child) = if rv.a == parent {
        (rv.b, rv.a_local, rv.b_local)
    } else {
        (rv.a, rv.b_local, rv.a_local)
    };
    TreeJoint {
        parent,
        child,
        kind: TreeKind::Revolute {
            on_parent,
            on_child,
        },
        contact: Vec2::zeros(),
        u: Vec2::zeros(),
    }
}

/// For every link and tree joint, whether the joint moves the link: `[link * joints +
/// joint]`. The tree is built breadth first, so a parent's path is known before its
/// child's.
fn moved_by(tree: &[TreeJoint], links: usize) -> Vec<bool> {
    let mut moved_by = vec![false; links * tree.len()];
    for (k, t) in tree.iter().enumerate() {
        for j in 0..tree.len() {
            moved_by[t.child.index() * tree.len() + j] =
                moved_by[t.parent.index() * tree.len() + j];
        }
        moved_by[t.child.index() * tree.len() + k] = true;
    }
    moved_by
}
