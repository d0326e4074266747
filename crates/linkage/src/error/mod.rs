//! Errors the solver returns instead of panicking; each names its cause and,
//! where one exists, the valid range.

use thiserror::Error;

use crate::assembly::AssemblyRanges;
use crate::dyad::{DyadLabel, Shortfall};
mod cam_problem;
mod design_refusal;
mod param;
mod run_refusal;
mod scene_problem;
mod singularity;
mod train_field;
mod train_problem;
mod valid;

pub use cam_problem::CamProblem;
pub use design_refusal::DesignRefusal;
pub use param::Param;
pub use run_refusal::{ImplicitFailure, RunRefusal, RunWarning, StabilityLimit};
pub use scene_problem::{LonePoint, MadeJoint, SceneProblem};
pub use singularity::{Singularity, Undecomposable};
pub use train_problem::{
    DriveEnd, DriveTrainProblem, FieldOwner, NameKind, TrainError, TrainField,
};
pub use valid::Valid;

/// Why a chain does not close at an input, as data ([`LinkageError::CannotAssemble`]).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum AssemblyFailure {
    /// A dyad does not close at this input: in words, what falls short (the links
    /// by their points, the distances), never the solver's dyad kind or margin.
    #[error("{}", open_words(dyad, shortfall.as_deref()))]
    DyadOpen {
        /// The dyad.
        dyad: Box<DyadLabel>,
        /// How far from closing: its assembly margin (dimensionless, < 0).
        margin: f64,
        /// What falls short, where the dyad's kind says (pins too far apart, a
        /// guide out of reach).
        shortfall: Option<Box<Shortfall>>,
    },
    /// The branch traced by Newton folds at its ends, dead points of the input.
    #[error(
        "the branch folds (a dead point of the input) at {:.4} and {:.4} deg",
        lo_rad.to_degrees(),
        hi_rad.to_degrees()
    )]
    BranchFolds {
        /// The lower fold, rad (unwrapped).
        lo_rad: f64,
        /// The upper fold, rad (unwrapped).
        hi_rad: f64,
    },
    /// No input angle assembles the chain.
    #[error("no input angle assembles the chain")]
    Nowhere,
}

/// Everything that can go wrong between a scene file and a solved position.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum LinkageError {
    /// The scene text is not valid RON for the scene format.
    #[error("scene syntax error at line {line}, column {column}: {message}")]
    SceneSyntax {
        /// 1-based line of the offending token.
        line: usize,
        /// 1-based column of the offending token.
        column: usize,
        /// What the parser expected or found.
        message: String,
    },
    /// The scene parsed but describes no valid mechanism.
    #[error("invalid scene: {0}")]
    SceneInvalid(Box<SceneProblem>),
    /// The synthesis requirements give no linkage.
    #[error("no design: {0}")]
    NoDesign(Box<DesignRefusal>),
    /// The steady state of a scene with no motor (no `drive` section).
    #[error("the steady state needs a motor: give the scene a `drive` section")]
    NeedsMotor,
    /// A dynamic run refused, or stopped, for its settings.
    #[error(transparent)]
    Run(Box<RunRefusal>),
    /// A numeric parameter is outside its valid range (or not finite).
    #[error("{param} = {value} is invalid: {valid}")]
    InvalidParameter {
        /// The parameter.
        param: Param,
        /// The value given.
        value: f64,
        /// What it must be.
        valid: Valid,
    },
    /// The chain cannot be assembled at this input.
    #[error("cannot assemble at input {input_deg:.4} deg: {reason}; {reachable}")]
    CannotAssemble {
        /// Input angle asked for, in degrees.
        input_deg: f64,
        /// Which group failed and why.
        reason: AssemblyFailure,
        /// The input ranges over which the chain does assemble.
        reachable: AssemblyRanges,
    },
    /// The chain sits exactly on a dead point: velocities are undefined there.
    #[error("singular position at input {input_deg:.4} deg: {reason}")]
    Singular {
        /// Input angle, in degrees.
        input_deg: f64,
        /// Why: which links are in line, or which equations are indeterminate.
        reason: Singularity,
    },
    /// Newton–Raphson did not reach the tolerance.
    #[error(
        "Newton solver did not converge at input {input_deg:.4} deg: residual {residual:.3e} of the mechanism's size after {iterations} iterations (tolerance {tolerance:.1e})"
    )]
    NewtonDiverged {
        /// Input angle, in degrees.
        input_deg: f64,
        /// Iterations used.
        iterations: usize,
        /// Largest constraint residual left, as a share of the mechanism's size (or in
        /// radians, for a slider's turn).
        residual: f64,
        /// Tolerance asked for.
        tolerance: f64,
    },
    /// The Newton solution moved to a different assembly branch between two steps.
    #[error(
        "branch jump at input {input_deg:.4} deg: Newton would pass to the other assembly mode (det J changes sign): a dead point"
    )]
    BranchJump {
        /// Input angle, in degrees.
        input_deg: f64,
    },
    /// The chain has no closed-form decomposition into dyads.
    #[error("no closed-form dyad decomposition: {0}")]
    NotDecomposable(Undecomposable),
    /// The input speed is so high that velocities or accelerations overflow (are no
    /// longer finite numbers) somewhere on the cycle.
    #[error(
        "the input speed {speed_rad_s:e} rad/s makes velocities or accelerations overflow: at most {most_rad_s:.1e} rad/s"
    )]
    SpeedOverflow {
        /// The speed asked for, rad/s.
        speed_rad_s: f64,
        /// The largest speed whose velocities and accelerations stay finite over the
        /// cycle, rad/s (with a factor of two to spare).
        most_rad_s: f64,
    },
    /// A link that cannot serve as the coordinate of a dynamic run.
    #[error(
        "link `{link}` cannot be the coordinate: it has no revolute joint to ground (links that can: {})",
        candidates.join(", ")
    )]
    NotACoordinate {
        /// The link asked for.
        link: String,
        /// The moving links with a revolute joint to ground.
        candidates: Vec<String>,
    },
    /// A machine analysis (flywheel, steady state) of a chain whose input does not
    /// turn a full cycle.
    #[error("the input does not turn a full cycle ({reachable}): {needs} needs a crank")]
    NotACrank {
        /// What was asked for.
        needs: MachineAnalysis,
        /// Where the chain does assemble.
        reachable: AssemblyRanges,
    },
}

/// A machine analysis over one turn of the crank, named in a refusal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MachineAnalysis {
    /// Flywheel sizing by the energy method.
    Flywheel,
    /// The periodic steady state with a motor.
    SteadyState,
    /// The shaking force and moment over a cycle.
    Shaking,
}

impl std::fmt::Display for MachineAnalysis {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Flywheel => "flywheel sizing",
            Self::SteadyState => "the steady state",
            Self::Shaking => "the shaking force over a cycle",
        })
    }
}

impl LinkageError {
    /// `param` = `value` refused: it must be `valid`.
    pub fn invalid(param: Param, value: f64, valid: Valid) -> Self {
        Self::InvalidParameter {
            param,
            value,
            valid,
        }
    }
}

/// Shorthand for results carrying a [`LinkageError`].
pub type Result<T> = std::result::Result<T, LinkageError>;

// Boxed: the problems carry names, and an unboxed one would make every `Result` of the
// solver as large as its largest problem.
impl From<SceneProblem> for LinkageError {
    fn from(problem: SceneProblem) -> Self {
        Self::SceneInvalid(Box::new(problem))
    }
}

impl From<DesignRefusal> for LinkageError {
    fn from(refusal: DesignRefusal) -> Self {
        Self::NoDesign(Box::new(refusal))
    }
}

/// A dyad that does not close, in words: its shortfall, or its links by name.
fn open_words(dyad: &DyadLabel, shortfall: Option<&Shortfall>) -> String {
    match shortfall {
        Some(s) => s.to_string(),
        None => {
            let [a, b] = &dyad.links;
            format!("{a} and {b} cannot be joined at {}", dyad.inner_point)
        }
    }
}
