//! Why a position is singular, and why a chain has no closed form, as data: the
//! links and numbers involved, worded by `Display` here (the command line's words)
//! and by each edge's own catalogue.

use thiserror::Error;

/// Why a position is singular ([`super::LinkageError::Singular`]).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Singularity {
    /// Two links of a dyad in line: a dead point of the closed form.
    #[error(
        "{} and {} are in line at {point} (a dead point): velocities are undefined",
        links[0],
        links[1]
    )]
    DyadInLine {
        /// The dyad's two links.
        links: [String; 2],
        /// The point of its inner joint.
        point: String,
    },
    /// A dead point of a chain with no dyad to name.
    #[error("the chain is at a dead point: velocities are undefined")]
    DeadPoint,
    /// Newton's Jacobian is singular while it corrects a pose.
    #[error("the loop-closure Jacobian is singular (dead point or unassemblable)")]
    LoopJacobian,
    /// Newton's Jacobian is singular at a converged pose: a dead point of the input.
    #[error("the loop-closure Jacobian is singular: a dead point of this input")]
    InputDeadPoint,
    /// A group's reactions in the force polygons are indeterminate.
    #[error("a group's reactions are indeterminate here (a dead point)")]
    GroupReactions,
    /// The joint reactions of the kinetostatics are indeterminate.
    #[error("the joint reactions are indeterminate here (a dead point of the input)")]
    JointReactions,
    /// A dynamic run's adaptive step shrank to nothing.
    #[error(
        "the step size collapsed at t = {t_s:.9} s (rtol {rtol}, atol {atol}): the motion is not smooth or not assemblable here"
    )]
    StepCollapsed {
        /// Where, s.
        t_s: f64,
        /// The run's relative tolerance.
        rtol: f64,
        /// The run's absolute tolerance.
        atol: f64,
    },
    /// The equivalent inertia at the coordinate is not positive.
    #[error("equivalent inertia J = {j_kg_m2:e}: the coordinate is singular here")]
    NoInertia {
        /// The equivalent inertia, kg m².
        j_kg_m2: f64,
    },
    /// The run's coordinate link is at a dead point while another link is regular.
    #[error(
        "the coordinate `{coordinate}` is at a dead point ({regular}, turning {ratio:.0} times faster, is regular here); let the run switch coordinates"
    )]
    CoordinateDeadPoint {
        /// The coordinate's link.
        coordinate: String,
        /// A link that is regular here.
        regular: String,
        /// How much faster it turns than the coordinate.
        ratio: f64,
    },
}

/// Why a chain has no closed-form decomposition, or an analysis that needs one
/// cannot run ([`super::LinkageError::NotDecomposable`]).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Undecomposable {
    /// Links left over that form no dyad on the links already placed.
    #[error("links {} form no RRR, RRP, RPR or PRP dyad on known links", links.join(", "))]
    NoDyad {
        /// The links not placed.
        links: Vec<String>,
    },
    /// A joint no dyad uses.
    #[error(
        "the joint between `{}` and `{}` is redundant for a dyad chain",
        links[0],
        links[1]
    )]
    RedundantJoint {
        /// The joint's two links.
        links: [String; 2],
    },
    /// A chain for Newton alone with a link that has no starting pose.
    #[error("link `{link}` needs a starting `guess: (x, y, angle)` for the Newton solver")]
    NeedsGuess {
        /// The link.
        link: String,
    },
    /// The path asked for was not built.
    #[error("no solver was built for the {} path", if *newton { "Newton" } else { "closed form" })]
    NoSolver {
        /// Whether the path is Newton's (else the closed form).
        newton: bool,
    },
    /// Force polygons of a chain solved by Newton alone.
    #[error(
        "force polygons need the chain as a crank and dyads; this one is solved by Newton alone"
    )]
    ForcePolygonsNeedDyads,
    /// A force polygon stage that is not statically determinate.
    #[error("a force polygon stage of {links} links has {unknowns} unknowns")]
    ForceStage {
        /// Links in the stage.
        links: usize,
        /// Unknown reaction components.
        unknowns: usize,
    },
    /// Kinetostatics of a chain that is not of one degree of freedom.
    #[error("kinetostatics needs a 1-DOF chain: {equations} equations for {unknowns} unknowns")]
    KinetostaticsDof {
        /// Equations (three per moving link).
        equations: usize,
        /// Unknown reactions and the balancing torque.
        unknowns: usize,
    },
}
