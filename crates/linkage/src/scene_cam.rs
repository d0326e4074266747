//! A cam joint in a scene file: a disc cam on one link (its shaft pinned to ground)
//! drives a follower link through a roller, so that a cam and a linkage on one main
//! shaft are one mechanism.
//!
//! ```ron
//! cams: [(
//!     cam: "crank",          // the cam turns with this link, about its ground pin
//!     follower: "arm",       // pinned to ground (an arm) or a slider on ground
//!     roller: "R",           // the follower's point at the roller's centre
//!     roller_radius: 12.0,   // scene length unit
//!     rest: 100.0,           // the arm's angle (or the slider's travel) at zero lift
//!     phase: 0.0,            // the cam link's angle where the program begins
//!     segments: [
//!         Rise(law: Cycloidal, lift: 12.0, deg: 120.0),
//!         Dwell(deg: 60.0),
//!         Return(law: ModifiedSine, lift: 12.0, deg: 120.0),
//!         Dwell(deg: 60.0),
//!     ],
//! )],
//! ```
//!
//! The program is the follower's motion, not the cam's shape: the profile is what
//! the roller's path leaves on the turning cam (kinematic inversion). Segment angles
//! are degrees of cam; a lift is degrees of an arm, or the scene's length unit for a
//! slider, as in cam files.

use serde::{Deserialize, Serialize};

use crate::cam::SegmentSpec;

/// One cam joint: the cam's link, the follower, its roller and the program.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CamJointSpec {
    /// The link that carries the cam; pinned to ground, whose pin is the cam's centre.
    pub cam: String,
    /// The follower: a link pinned to ground (an oscillating arm) or the slider of a
    /// prismatic joint on ground (a translating follower).
    pub follower: String,
    /// The follower's point at the roller's centre.
    pub roller: String,
    /// The roller's radius (scene length unit).
    pub roller_radius: f64,
    /// The follower at zero lift: an arm's angle (its x-axis, scene angle unit), or a
    /// slider's travel along its guide from the guide's `through` point (scene length
    /// unit).
    pub rest: f64,
    /// The cam link's angle (scene angle unit) at which the program begins.
    #[serde(default)]
    pub phase: f64,
    /// The program over one turn of the cam.
    pub segments: Vec<SegmentSpec>,
}
