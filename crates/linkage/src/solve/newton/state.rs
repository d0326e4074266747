//! What a solve starts from and what it writes over: the continuation state, a value
//! the caller holds (the last solution and everything derived from it that the next
//! solve uses), and the workspace (buffers that every solve fills before it reads
//! them, so that they carry nothing from one solve to the next).

use nalgebra::{DMatrix, DVector, UnitComplex};

use crate::motion::Vec2;
use crate::small_lu::SmallLu;

/// The rotation of one revolute tree joint with the angle it was made for. Newton
/// moves a joint angle by small steps (predictor, corrections), so the next
/// rotation is this one turned by the step through a short series, not a new sine
/// and cosine (those were most of the solver's cost). The input joint is always
/// rotated exactly, since nothing corrects its rotation's round-off.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct JointTurn {
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
    pub(super) const UNSET: Self = Self {
        angle: f64::NAN,
        rotation: UnitComplex::new_unchecked(nalgebra::Complex { re: 1.0, im: 0.0 }),
    };

    /// The rotation by `angle`; `exact` forces a fresh sine and cosine.
    #[inline]
    pub(super) fn to(&mut self, angle: f64, exact: bool) -> UnitComplex<f64> {
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

/// Where a branch was left: the last solution, its derivatives with respect to the
/// input, the assembly mode, the traced range and the factored Jacobian that the next
/// solve's first iterations reuse. A solve from a copy of this value gives the same
/// result, to the bit, whatever was solved before.
#[derive(Clone, Debug)]
pub struct Continuation {
    /// Unknown coordinates (tree joints after the driver).
    pub(super) q: DVector<f64>,
    /// dq/d(input) and d²q/d(input)² at the last solution.
    pub(super) dq: DVector<f64>,
    pub(super) ddq: DVector<f64>,
    /// d³q/d(input)³ estimated from the last two accepted steps' q'' (zero until there
    /// are two), for a third-order predictor.
    pub(super) jerk: DVector<f64>,
    /// Accepted continuation steps since the pose was set or a step was refused.
    pub(super) steady_steps: u32,
    /// The input of the last solution, unwrapped along the branch followed.
    pub(super) last_input: Option<f64>,
    /// The branch's assembly range (unwrapped, holding the start) once traced and
    /// found limited: inputs are then taken inside it (see `branch.rs`).
    pub(super) range: Option<[f64; 2]>,
    /// Sign of det J at the last solution (0 before the first): the assembly mode.
    pub(super) det_sign: f64,
    /// |det J| over the product of its column norms at the last solution.
    pub(super) conditioning: f64,
    /// Rotation of each tree joint at the last coordinates (unused for prismatic
    /// ones), see [`JointTurn`]: the next rotations are these turned by small steps.
    pub(super) turns: Vec<JointTurn>,
    /// LU of the Jacobian at the last converged pose, reused by chord iterations.
    pub(super) lu: SmallLu,
    /// Iterations used by the last solve.
    pub(super) last_iterations: usize,
}

impl Continuation {
    /// A state at coordinates zero for `unknowns` coordinates and `joints` tree
    /// joints (the caller sets the pose next).
    pub(super) fn zeros(unknowns: usize, joints: usize) -> Self {
        Self {
            q: DVector::zeros(unknowns),
            dq: DVector::zeros(unknowns),
            ddq: DVector::zeros(unknowns),
            jerk: DVector::zeros(unknowns),
            steady_steps: 0,
            last_input: None,
            range: None,
            det_sign: 0.0,
            conditioning: 1.0,
            turns: vec![JointTurn::UNSET; joints],
            lu: SmallLu::default(),
            last_iterations: 0,
        }
    }

    /// The traced assembly range of this branch, unwrapped (holding the start input),
    /// when it is limited.
    pub fn range(&self) -> Option<[f64; 2]> {
        self.range
    }

    /// The input of the last solution, rad, unwrapped along the branch followed.
    pub fn last_input(&self) -> Option<f64> {
        self.last_input
    }

    /// Iterations used by the last solve (for diagnostics and benchmarks).
    pub fn last_iterations(&self) -> usize {
        self.last_iterations
    }
}

/// Buffers a solve fills before it reads them: the Jacobian and its right-hand sides,
/// residuals, the predictor's step and the state saved while a step is tried, and the
/// tree joints' world points and guide directions from the last position pass.
#[derive(Clone, Debug)]
pub struct NewtonWorkspace {
    pub(super) jac: DMatrix<f64>,
    pub(super) rhs: DVector<f64>,
    /// The driver's Jacobian column (the input's rate), from the last Jacobian built.
    pub(super) rates: Vec<f64>,
    /// Acceleration bias and residual.
    pub(super) col_buf: Vec<f64>,
    pub(super) res_buf: Vec<f64>,
    /// q, dq and ddq before a continuation step, put back when it fails.
    pub(super) saved: (DVector<f64>, DVector<f64>, DVector<f64>),
    /// The predictor's step.
    pub(super) increment: DVector<f64>,
    /// World joint point (revolute) or slide contact point of each tree joint.
    pub(super) contacts: Vec<Vec2>,
    /// World guide direction of each prismatic tree joint.
    pub(super) guides: Vec<Vec2>,
}

impl NewtonWorkspace {
    /// Buffers for `unknowns` coordinates and `joints` tree joints; the model has as
    /// many equations as unknowns (`NewtonModel::new` refuses any other chain).
    pub(super) fn new(unknowns: usize, joints: usize) -> Self {
        Self {
            jac: DMatrix::zeros(unknowns, unknowns),
            rhs: DVector::zeros(unknowns),
            rates: vec![0.0; 2 * unknowns.max(1)],
            col_buf: vec![0.0; unknowns],
            res_buf: vec![0.0; unknowns],
            saved: (
                DVector::zeros(unknowns),
                DVector::zeros(unknowns),
                DVector::zeros(unknowns),
            ),
            increment: DVector::zeros(unknowns),
            contacts: vec![Vec2::zeros(); joints],
            guides: vec![Vec2::zeros(); joints],
        }
    }
}
