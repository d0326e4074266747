//! Why a scene describes no valid mechanism, as data
//! ([`crate::LinkageError::SceneInvalid`]): the links, points and joints it names, and
//! the numbers that were wrong. Worded in `Display` only, so that a caller (a test, the
//! app's editor) matches the case and its names, and the text is made where it is
//! shown.

use std::fmt;

use thiserror::Error;

use crate::dyad::DyadKind;

/// A scene that parses but describes no mechanism that can be solved, by section:
/// the links and their points, the joints, the driver and branches, the forces, and
/// what the solver finds when it builds the chain.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SceneProblem {
    /// Not exactly one ground link.
    #[error("exactly one link must have `ground: true`, found {found}")]
    GroundCount {
        /// How many links say `ground: true`.
        found: usize,
    },
    /// Every point at the origin: no length sets the mechanism's size.
    #[error("all points are at the origin: the mechanism has no size")]
    NoSize,
    /// A link with an empty name.
    #[error("link #{number} has an empty name")]
    UnnamedLink {
        /// Its place in the scene's list, from 1.
        number: usize,
    },
    /// Two links with one name.
    #[error("two links are named `{link}`")]
    DuplicateLink {
        /// The name.
        link: String,
    },
    /// A link that lists no points.
    #[error("link `{link}` has no points")]
    LinkWithoutPoints {
        /// The link.
        link: String,
    },
    /// Two joints of a link at one place.
    #[error("link `{link}` has zero length between its joints `{a}` and `{b}`")]
    ZeroLength {
        /// The link.
        link: String,
        /// One joint.
        a: String,
        /// The other.
        b: String,
    },
    /// Two joints of a link so close beside the mechanism's size that round-off
    /// swallows their distance.
    #[error(
        "link `{link}`: joints `{a}` and `{b}` are {gap_m:.3e} m apart, below 1e-12 of the \
         mechanism's size {size_m:.3e} m, set by point `{farthest_point}` of link \
         `{farthest_link}`; lengths so far apart cannot be solved together (is that point a \
         typo?)"
    )]
    LengthLost {
        /// The link.
        link: String,
        /// One joint.
        a: String,
        /// The other.
        b: String,
        /// Their distance, m.
        gap_m: f64,
        /// The mechanism's size, m.
        size_m: f64,
        /// The point farthest from the origin, which sets the size.
        farthest_point: String,
        /// Its link.
        farthest_link: String,
    },
    /// A section names a link the scene does not have.
    #[error("{context} names link `{name}`, which does not exist (links: {})", known.join(", "))]
    UnknownLink {
        /// Where the name was met (`driver`, `slider #1`, ...).
        context: String,
        /// The name.
        name: String,
        /// The links there are.
        known: Vec<String>,
    },
    /// A section names a point that is not on the link it must be on.
    #[error("{context}: point `{point}` is not on link `{link}`")]
    PointNotOnLink {
        /// Where the name was met.
        context: String,
        /// The point.
        point: String,
        /// The link it should be on.
        link: String,
    },
    /// A prismatic joint whose slider is its own guide.
    #[error("{context}: slider and guide are the same link")]
    SliderOnItsGuide {
        /// Which slider.
        context: String,
    },
    /// The count of links and joints does not give one degree of freedom.
    #[error(
        "the chain has mobility {mobility} (3 x {moving} moving links - 2 x {joints} joints - \
         {cams} cam contacts); a \
         single-input mechanism needs exactly 1. Joints are made by a point name shared between \
         links; these points are on one link only: {}",
        lone_points_hint(lone, made)
    )]
    Mobility {
        /// Grübler's count.
        mobility: i64,
        /// Moving links.
        moving: usize,
        /// Joints (revolute and prismatic).
        joints: usize,
        /// Cam contacts (one constraint each).
        cams: usize,
        /// Points on one link only, where a joint may be missing (a misspelt name).
        lone: Vec<LonePoint>,
        /// The joints made, to compare with the drawing.
        made: Vec<MadeJoint>,
    },
    /// A cam joint that cannot be built.
    #[error("cam joint `{joint}`: {problem}")]
    Cam {
        /// The joint, `cam/follower`.
        joint: String,
        /// Why.
        problem: crate::error::CamProblem,
    },
    /// The driver is the frame.
    #[error("the driver cannot be the ground link")]
    DriverIsGround,
    /// The driver has no pivot on the frame.
    #[error("driver link `{link}` shares no point with ground, so it cannot be a crank")]
    DriverNotOnGround {
        /// The driver.
        link: String,
    },
    /// A `branches` key that is no point.
    #[error("branch key `{name}` is not a point name")]
    UnknownBranchKey {
        /// The key.
        name: String,
    },
    /// A branch that names a point the scene does not have.
    #[error("branch of `{of}` names unknown point `{name}`")]
    BranchNamesUnknownPoint {
        /// The dyad's inner joint.
        of: String,
        /// The unknown name.
        name: String,
    },
    /// A force element (spring, damper, force, torque) names an unknown point.
    #[error("{element} names unknown point `{name}`")]
    ForceNamesUnknownPoint {
        /// The kind of element.
        element: String,
        /// The name.
        name: String,
    },
    /// A force element names an unknown link.
    #[error("{element} names unknown link `{name}`")]
    ForceNamesUnknownLink {
        /// The kind of element.
        element: String,
        /// The name.
        name: String,
    },
    /// A branch set on a point that does not exist.
    #[error("no point named `{point}` to set a branch on")]
    NoPointForBranch {
        /// The name asked for.
        point: String,
    },
    /// The closed form meets a link whose joints of a dyad coincide.
    #[error("link `{link}` has zero length between its {which} joints")]
    DyadZeroLength {
        /// The link.
        link: String,
        /// Which joints, in words (`two`, `pin and slider`).
        which: String,
    },
    /// A dyad without a branch in `branches`.
    #[error("the {kind} dyad with inner joint `{joint}` needs an assembly branch in `branches`")]
    MissingBranch {
        /// The dyad's kind.
        kind: DyadKind,
        /// Its inner joint.
        joint: String,
    },
    /// An RRR branch whose ends are not the dyad's end joints.
    #[error(
        "branch of `{joint}` must name its end joints: Left(\"{a}\", \"{c}\") or Right(\"{a}\", \"{c}\")"
    )]
    BranchEnds {
        /// The inner joint.
        joint: String,
        /// One end joint.
        a: String,
        /// The other.
        c: String,
    },
    /// An RRR branch given as Along or Against.
    #[error(
        "branch of RRR joint `{joint}` must be Left(\"{a}\", \"{c}\") or Right(..), not Along/Against"
    )]
    BranchNotASide {
        /// The inner joint.
        joint: String,
        /// One end joint.
        a: String,
        /// The other.
        c: String,
    },
    /// A sliding dyad's branch given as Left or Right.
    #[error("branch of {joint_kind} `{joint}` must be Along or Against{}", along_hint(*kind))]
    BranchNotAlong {
        /// The dyad's kind.
        kind: DyadKind,
        /// How the joint is named to the user (`slider joint`, `sliding joint`).
        joint_kind: String,
        /// The joint.
        joint: String,
    },
    /// Joints repeat a constraint: the chain moves with more than one freedom.
    #[error(
        "the chain moves with {dof} degrees of freedom, though counting links and joints gives \
         1: some joints are redundant (they repeat a constraint the others already impose, like \
         a brace between two points of one rigid link), so the driver alone does not fix the pose"
    )]
    RedundantJoints {
        /// The freedoms found at the start position.
        dof: usize,
    },
    /// Loop closure does not give as many equations as unknowns.
    #[error("loop closure gives {equations} equations for {unknowns} unknowns")]
    EquationCount {
        /// Equations.
        equations: usize,
        /// Unknowns.
        unknowns: usize,
    },
    /// A link joined to nothing that reaches the frame.
    #[error("link `{link}` is not connected to the chain")]
    Unconnected {
        /// The link.
        link: String,
    },
    /// A dynamics scene without a link's mass, centroid or inertia.
    #[error(
        "link `{link}` needs `{field}` for dynamics (a Dynamics scene needs mass, centroid and inertia on every moving link)"
    )]
    MissingInertia {
        /// The link.
        link: String,
        /// The missing field: `mass`, `centroid` or `inertia`.
        field: &'static str,
    },
    /// Dynamics with no mass anywhere.
    #[error("no link has a mass: there is nothing to integrate")]
    Massless,
    /// Kinetostatics asked of a kinematics-only scene.
    #[error(
        "scene `{scene}` models kinematics only: declare `models: Kinetostatics` with its masses and forces for torques and reactions"
    )]
    KinematicsOnly {
        /// The scene's name.
        scene: String,
    },
    /// Kinetostatics with the crank at rest.
    #[error("kinetostatics needs a crank speed: the driver's `speed` is 0")]
    NoCrankSpeed,
    /// A counterweight asked for on a link that turns about no ground pivot.
    #[error(
        "`{link}` turns about no ground pivot: a counterweight goes on a link pivoted \
         to the frame (the crank, a rocker)"
    )]
    NotPivoted {
        /// The link's name.
        link: String,
    },
    /// A drawing whose chain assembles elsewhere than drawn.
    #[error("the chain does not assemble as drawn at {point}")]
    NotAsDrawn {
        /// The first point off its drawn place.
        point: String,
    },
    /// The drive's gear train cannot drive the crank.
    #[error("the drive's train: {0}")]
    DriveTrain(super::DriveTrainProblem),
    /// The scene could not be written as RON.
    #[error("cannot write scene: {why}")]
    CannotWrite {
        /// The writer's message.
        why: String,
    },
}

/// A point on one link only ([`SceneProblem::Mobility`]).
#[derive(Debug, Clone, PartialEq)]
pub struct LonePoint {
    /// The point.
    pub point: String,
    /// The one link that lists it.
    pub link: String,
}

impl fmt::Display for LonePoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}` (on `{}`)", self.point, self.link)
    }
}

/// A joint the scene's names made ([`SceneProblem::Mobility`]).
#[derive(Debug, Clone, PartialEq)]
pub enum MadeJoint {
    /// A revolute joint: a point shared by links `a` and `b`.
    Pin {
        /// The shared point.
        point: String,
        /// One link.
        a: String,
        /// The other.
        b: String,
    },
    /// A prismatic joint of the slider `link`.
    Slider {
        /// The sliding link.
        link: String,
    },
}

impl fmt::Display for MadeJoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Pin { point, a, b } => write!(f, "`{point}` ({a}-{b})"),
            Self::Slider { link } => write!(f, "slider `{link}`"),
        }
    }
}

/// The points where a joint may be missing, or the joints made when none is lone.
fn lone_points_hint(lone: &[LonePoint], made: &[MadeJoint]) -> String {
    let list = |items: Vec<String>| items.join(", ");
    if lone.is_empty() {
        let made = list(made.iter().map(ToString::to_string).collect());
        format!("none; the joints made are {made}")
    } else {
        list(lone.iter().map(ToString::to_string).collect())
    }
}

/// What an RRP dyad's branch means, said after its refusal.
fn along_hint(kind: DyadKind) -> &'static str {
    match kind {
        DyadKind::Rrp => " (its side along the guide)",
        _ => "",
    }
}
