//! The chain as Newton sees it, fixed once built: a spanning tree from the ground
//! (the driver's joint first), the joints cut to close its loops, the cam joints, and
//! the tolerances; with the entry points that solve it from a [`Continuation`] the
//! caller holds, in a [`NewtonWorkspace`] it lends.

use super::state::{Continuation, NewtonWorkspace};
use super::{Cut, Solver, TreeJoint, TreeKind};
use crate::error::{LinkageError, Result};
use crate::ids::LinkId;
use crate::model::{Mechanism, SceneProblem};
use crate::motion::LinkMotion;

/// The model of the loop-closure equations: what every solve of one mechanism
/// shares, never changed by solving.
#[derive(Clone, Debug)]
pub struct NewtonModel {
    pub(super) tree: Vec<TreeJoint>,
    /// `moved_by[link * tree.len() + k]`: tree joint `k` lies on the path from ground
    /// to `link`, so a rate of `k` moves `link`.
    pub(super) moved_by: Vec<bool>,
    pub(super) cuts: Vec<Cut>,
    /// Cam joints: a row each after the cut joints' (`cam_rows.rs`).
    pub(super) cams: Vec<crate::model::CamJoint>,
    pub(super) ground: LinkId,
    /// Largest residual accepted, as a share of the size (and rad).
    pub(super) tolerance: f64,
    /// Largest residual accepted when Newton stalls at round-off (as a share of the
    /// size, and rad).
    pub(super) stall_residual: f64,
    /// The mechanism's size, m: residuals in metres count relative to it, so that a
    /// 50 µm chain converges exactly as its 50 m twin does.
    pub(super) size_m: f64,
    pub(super) max_iterations: usize,
}

impl NewtonModel {
    /// Builds the tree and cut joints of `m`.
    ///
    /// # Errors
    /// A tolerance that is not finite and positive; a chain with unconnected links or
    /// whose loop equations do not match its unknowns.
    pub fn new(m: &Mechanism, tolerance: f64, max_iterations: usize) -> Result<Self> {
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(LinkageError::invalid(
                crate::error::Param::NewtonTolerance,
                tolerance,
                crate::error::Valid::Positive,
            ));
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
        Ok(Self {
            tree,
            moved_by,
            cuts,
            cams: m.cams.clone(),
            ground: m.ground,
            tolerance: tolerance.max(8.0 * f64::EPSILON),
            stall_residual: 1e-12,
            size_m: m.size_m,
            max_iterations,
        })
    }

    /// Number of unknown coordinates.
    pub fn unknowns(&self) -> usize {
        self.tree.len() - 1
    }

    /// The state at a full set of link poses `links` at `input_rad` (from the closed
    /// form or the scene's guesses): the branch the solves then follow.
    pub fn start(&self, links: &[LinkMotion], input_rad: f64) -> Continuation {
        let mut state = Continuation::zeros(self.unknowns(), self.tree.len());
        self.set_pose(&mut state, links, input_rad);
        state
    }

    /// Buffers for solving this model.
    pub fn workspace(&self) -> NewtonWorkspace {
        NewtonWorkspace::new(self.unknowns(), self.tree.len())
    }

    /// Sets the tracked coordinates from a full set of link poses at `input_rad`.
    pub fn set_pose(&self, state: &mut Continuation, links: &[LinkMotion], input_rad: f64) {
        for (k, t) in self.tree.iter().enumerate().skip(1) {
            let (p, c) = (&links[t.parent], &links[t.child]);
            state.q[k - 1] = match &t.kind {
                TreeKind::Revolute { .. } => (p.rotation.inverse() * c.rotation).angle(),
                TreeKind::Prismatic { slide, .. } => {
                    let (s, g) = (&links[slide.slider], &links[slide.guide]);
                    (s.world(&slide.slider_local) - g.world(&slide.through_local))
                        .dot(&(g.rotation * slide.direction_local))
                }
            };
        }
        state.dq.fill(0.0);
        state.ddq.fill(0.0);
        state.jerk.fill(0.0);
        state.steady_steps = 0;
        state.lu.invalidate();
        state.last_input = Some(input_rad);
    }

    /// Solves at `input_rad` with input speed `speed_rad_s` (constant), writing every
    /// link's motion to `links`: from `state` (continued to the input, or corrected in
    /// place at the same input), which is left at the solution. Returns a conditioning
    /// estimate in [0, 1].
    ///
    /// # Errors
    /// A non-finite input or speed; no convergence; a singular Jacobian; an input
    /// outside the traced range; a step that would change the assembly mode.
    pub fn solve_links(
        &self,
        input_rad: f64,
        speed_rad_s: f64,
        links: &mut [LinkMotion],
        state: &mut Continuation,
        work: &mut NewtonWorkspace,
    ) -> Result<f64> {
        self.solver(state, work)
            .solve_links(input_rad, speed_rad_s, links)
    }

    /// Traces the branch of `state`'s pose both ways from its input, and from then on
    /// solves from `state` only inside the range found (an input outside it is refused
    /// with the range named). Returns the range, or `None` when the input turns fully.
    ///
    /// # Errors
    /// The start pose itself does not solve.
    pub fn trace_range(
        &self,
        links: &mut [LinkMotion],
        state: &mut Continuation,
        work: &mut NewtonWorkspace,
    ) -> Result<Option<[f64; 2]>> {
        self.solver(state, work).trace_range(links)
    }

    /// Degrees of freedom of the chain near `state`'s coordinates at `input` (the
    /// least null-space dimension of [J | j_in] at two nearby poses); `state`'s
    /// coordinates are kept, its factored Jacobian dropped.
    pub fn mobility(
        &self,
        input: f64,
        links: &mut [LinkMotion],
        state: &mut Continuation,
        work: &mut NewtonWorkspace,
    ) -> usize {
        self.solver(state, work).mobility(input, links)
    }

    fn solver<'a>(
        &'a self,
        state: &'a mut Continuation,
        work: &'a mut NewtonWorkspace,
    ) -> Solver<'a> {
        Solver {
            model: self,
            state,
            work,
        }
    }
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
