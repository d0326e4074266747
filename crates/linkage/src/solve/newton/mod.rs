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
//!
//! The solver is three parts, as rapier keeps a multibody's scratch beside it: the
//! model ([`NewtonModel`]: the tree, the cut joints and cams, the tolerances), fixed
//! once built; the continuation state ([`Continuation`]: the last solution, its
//! derivatives, the assembly mode, the traced range, the factored Jacobian that the
//! next solve starts from), a value the caller holds and passes, so that what a solve
//! depends on is in its signature; and the scratch buffers ([`NewtonWorkspace`]), which
//! carry nothing from one solve to the next. [`Newton`] holds one of each for callers
//! that follow one branch.

use crate::error::Result;
use crate::ids::LinkId;
use crate::model::{Mechanism, Prismatic};
use crate::motion::{LinkMotion, Vec2};

mod branch;
mod cam_rows;
mod iterate;
mod mobility;
mod model;
mod passes;
mod state;

pub use model::NewtonModel;
pub use state::{Continuation, NewtonWorkspace};

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

/// One solve's view of the three parts: the model read, the continuation advanced,
/// the workspace written over.
struct Solver<'a> {
    model: &'a NewtonModel,
    state: &'a mut Continuation,
    work: &'a mut NewtonWorkspace,
}

/// Newton–Raphson position solver with velocity and acceleration from the Jacobian:
/// a model with one continuation and its workspace, for a caller that follows one
/// branch from solve to solve.
#[derive(Clone, Debug)]
pub struct Newton {
    model: NewtonModel,
    state: Continuation,
    work: NewtonWorkspace,
}

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
        let model = NewtonModel::new(m, tolerance, max_iterations)?;
        let state = model.start(start, m.driver.start_rad);
        let work = model.workspace();
        Ok(Self { model, state, work })
    }

    /// Number of unknown coordinates.
    pub fn unknowns(&self) -> usize {
        self.model.unknowns()
    }

    /// Sets the tracked coordinates from a full set of link poses at `input_rad`.
    pub fn set_pose(&mut self, links: &[LinkMotion], input_rad: f64) {
        self.model.set_pose(&mut self.state, links, input_rad);
    }

    /// Solves at `input_rad` with input speed `speed_rad_s` (constant), writing every
    /// link's motion to `links`, from the last solution. Returns a conditioning
    /// estimate in [0, 1].
    pub fn solve_links(
        &mut self,
        input_rad: f64,
        speed_rad_s: f64,
        links: &mut [LinkMotion],
    ) -> Result<f64> {
        let (m, s, w) = (&self.model, &mut self.state, &mut self.work);
        m.solve_links(input_rad, speed_rad_s, links, s, w)
    }

    /// The branch's assembly range once traced and found limited (see
    /// [`Continuation::range`]).
    pub fn range(&self) -> Option<[f64; 2]> {
        self.state.range()
    }

    /// Traces the branch from the current pose both ways to its folds (see
    /// [`NewtonModel::trace_range`]).
    pub fn trace_range(&mut self, links: &mut [LinkMotion]) -> Result<Option<[f64; 2]>> {
        self.model
            .trace_range(links, &mut self.state, &mut self.work)
    }

    /// Degrees of freedom at `input` (see [`NewtonModel::mobility`]).
    pub fn mobility(&mut self, input: f64, links: &mut [LinkMotion]) -> usize {
        self.model
            .mobility(input, links, &mut self.state, &mut self.work)
    }

    /// Iterations used by the last solve (for diagnostics and benchmarks).
    pub fn last_iterations(&self) -> usize {
        self.state.last_iterations()
    }
}
