//! Why a gear train is refused, as data: a name undefined or twice, a number out of
//! range, gears that cannot mesh, inputs that do not fix the train (a leaf, so that a
//! scene's drive can carry it in [`super::SceneProblem`]).

use serde::Serialize;

pub use super::train_field::{FieldOwner, NameKind, TrainField};
use thiserror::Error;

/// Why a train is refused.
#[derive(Clone, Debug, Error, PartialEq, Serialize)]
pub enum TrainError {
    /// A name used but not defined.
    #[error("{what} names `{name}`, which is not one of the train's {kind}")]
    Unknown {
        /// Where the name is used (a gear's `member`).
        what: TrainField,
        /// The name.
        name: String,
        /// What it must be one of.
        kind: NameKind,
    },
    /// A name defined twice.
    #[error("`{name}` is defined twice")]
    Duplicate {
        /// The name.
        name: String,
    },
    /// A number outside its range.
    #[error("{what} {value} is outside the range {min} … {max}")]
    OutOfRange {
        /// Which number (a gear's `teeth`).
        what: TrainField,
        /// The value.
        value: f64,
        /// The least allowed.
        min: f64,
        /// The largest allowed.
        max: f64,
    },
    /// Two gears in mesh whose axes are held by members that turn apart.
    #[error(
        "gears `{a}` and `{b}` cannot mesh: their axes are held by `{a_axis}` and `{b_axis}`, \
         which keep no fixed distance (a planet's axis is held by its carrier, and meshes \
         with gears on the carrier's axis)"
    )]
    AxesApart {
        /// One gear.
        a: String,
        /// The other.
        b: String,
        /// The member holding the first's axis.
        a_axis: String,
        /// The member holding the other's.
        b_axis: String,
    },
    /// An internal gear with no more teeth than the external gear it meshes with.
    #[error(
        "internal gear `{ring}` ({ring_teeth} teeth) must have more teeth than `{mate}` ({mate_teeth}) inside it"
    )]
    RingTooSmall {
        /// The internal gear.
        ring: String,
        /// Its teeth.
        ring_teeth: u32,
        /// The external gear inside it.
        mate: String,
        /// Its teeth.
        mate_teeth: u32,
    },
    /// A train with no member that turns.
    #[error("a train needs at least one member that turns")]
    NoMembers,
    /// Two internal gears in mesh.
    #[error(
        "gears `{a}` and `{b}` are both internal: an internal gear meshes with an external one"
    )]
    BothInternal {
        /// One gear.
        a: String,
        /// The other.
        b: String,
    },
    /// Not as many inputs as the train's degrees of freedom.
    #[error("the train has {dof} degree(s) of freedom: give {dof} input speed(s) ({given} given)")]
    Inputs {
        /// The degrees of freedom.
        dof: usize,
        /// The inputs given.
        given: usize,
    },
    /// The inputs fix some members twice and others not at all, or contradict the
    /// meshes (two inputs on members the gears tie together).
    #[error(
        "the inputs do not fix the train: `{member}` is left free or tied to another input; \
         give the inputs on members the gears do not tie together"
    )]
    InputsTied {
        /// A member the inputs leave undetermined or over-determined.
        member: String,
    },
    /// Efficiencies given for a train whose meshes or stages close a loop: the load
    /// splits between the loop's paths as the parts' stiffness says, which the file
    /// does not, so the losses cannot be apportioned.
    #[error(
        "the train's meshes or stages close a loop (gears tying members already tied), \
         so the load's split between its paths, and the losses, depend on the parts' \
         stiffness: leave out the efficiencies, or the mesh or stage that closes the loop"
    )]
    LossesIndeterminate,
    /// With its efficiencies the train locks itself: no choice of the side each mesh
    /// drives agrees with the torques it gives.
    #[error(
        "with these efficiencies the train locks itself: no direction of the power \
         through its meshes and stages agrees with the torques it gives (a closed \
         differential or a high ratio with low efficiencies); check the efficiencies, \
         or drive it from another member"
    )]
    SelfLocking,
    /// A load on a member whose speed is given: it goes straight to what drives or
    /// holds that member, through no gear.
    #[error(
        "the load is on `{member}`, whose speed is given: load a member the train drives \
         (one without an input)"
    )]
    LoadWhereSpeedGiven {
        /// The member.
        member: String,
    },
}

/// Which end of a drive's train a name is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum DriveEnd {
    /// The member on the motor's shaft (`motor_member`).
    Motor,
    /// The member fixed to the crank (`crank_member`).
    Crank,
}

impl DriveEnd {
    /// The scene file's key for it.
    pub fn key(self) -> &'static str {
        match self {
            Self::Motor => "motor_member",
            Self::Crank => "crank_member",
        }
    }
}

/// Why a scene's drive train cannot drive its crank
/// ([`super::SceneProblem::DriveTrain`]).
#[derive(Clone, Debug, Error, PartialEq, Serialize)]
pub enum DriveTrainProblem {
    /// The train itself is refused.
    #[error("{0}")]
    Train(TrainError),
    /// `motor_member` or `crank_member` names no member of the train.
    #[error("`{}` names `{name}`, which is not a member of the train (members: {})", end.key(), known.join(", "))]
    NoSuchMember {
        /// Which end.
        end: DriveEnd,
        /// The name given.
        name: String,
        /// The train's members.
        known: Vec<String>,
    },
    /// A second input that turns: the motor would not set the crank's speed alone.
    #[error(
        "`{member}` is given {rpm} rpm: a drive's train is turned by the motor alone; its \
         other inputs hold members still (0 rpm)"
    )]
    SecondInput {
        /// The member.
        member: String,
        /// Its speed given, rpm.
        rpm: f64,
    },
    /// The motor's or the crank's member stands still with the inputs given.
    #[error("`{name}` ({}) stands still with the train's inputs: no ratio to the crank", end.key())]
    StandsStill {
        /// Which end.
        end: DriveEnd,
        /// The member.
        name: String,
    },
    /// A `gear_ratio` given beside the train that is not the train's.
    #[error("`gear_ratio` {given} is not the train's {train}: leave it out where a train is given")]
    RatioContradicts {
        /// The ratio given.
        given: f64,
        /// The train's ratio (motor turns per crank turn).
        train: f64,
    },
}
