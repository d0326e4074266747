//! Why a cam joint cannot be built, as data (a leaf: the scene's problems name it
//! without depending on the cam joints' conversion).

use thiserror::Error;

/// Why a cam joint cannot be built, beside the names and numbers every section checks.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum CamProblem {
    /// The cam's link has no pin on the frame to turn about.
    #[error("the cam's link `{link}` has no pin on ground to turn about")]
    CamNotOnGround {
        /// The link.
        link: String,
    },
    /// The follower is the frame or the cam's own link.
    #[error("the follower `{link}` must be a moving link other than the cam's")]
    FollowerNotSeparate {
        /// The link.
        link: String,
    },
    /// The follower is neither pinned to ground nor a slider on a ground guide.
    #[error("the follower `{link}` must be pinned to ground (an arm) or slide on a ground guide")]
    FollowerNotGuided {
        /// The link.
        link: String,
    },
    /// The roller sits on an arm's pivot: it would not move.
    #[error("the roller `{point}` sits on the arm's ground pin, so the cam cannot move it")]
    RollerOnPivot {
        /// The roller's point.
        point: String,
    },
    /// Somewhere in the turn the roller reaches over the cam's centre: no cam is left.
    #[error(
        "the roller's centre comes within {closest_m:.4e} m of the cam's centre at cam angle \
         {at_deg:.1} deg, not more than its radius {roller_m:.4e} m: no cam is left there; \
         move the follower out or lower the lift"
    )]
    RollerOverCentre {
        /// The least distance of the roller's centre from the cam's, m.
        closest_m: f64,
        /// Where, deg of the cam's link.
        at_deg: f64,
        /// The roller's radius, m.
        roller_m: f64,
    },
}
