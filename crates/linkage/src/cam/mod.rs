//! Cams: motion laws and the programs they make over a cam's turn.
//!
//! - [`Law`]: the normalised motion laws (dwell aside) with their derivatives.
//! - [`Program`]: segments (rise, dwell, return) over the turn, the follower's motion
//!   at any cam angle, the continuity at every join, the laws' peak coefficients.
//! - [`DiscCam`]: a disc cam with a translating or oscillating follower: pitch curve,
//!   profile, pressure angle and radii of curvature at any cam angle; the smallest
//!   base circle for a pressure-angle limit, the contact force and the least preload;
//!   the follower's outline at a cam angle, as figures draw it ([`FollowerOutline`]).
//! - [`Geneva`]: the external Geneva wheel, an intermittent indexer.
//! - [`CamSpec`]: a cam file (RON, millimetres and degrees) and its [`CamDesign`].

mod disc;
mod extremes;
mod geneva;
mod laws;
mod outline;
mod program;
mod sizing;
mod spec;
mod table;

pub use disc::{CamPoint, DiscCam, Face, Follower};
pub(crate) use disc::{pitch_on_turning_cam, turn};
pub use extremes::{CamExtremes, Extreme};
pub use geneva::{Geneva, GenevaMotion};
pub use laws::{Law, Motion};
pub use outline::FollowerOutline;
pub use program::{
    Continuity, FollowerMotion, Join, PeakCoefficients, Program, Segment, SegmentKind,
    peak_coefficients,
};
pub use sizing::{Contact, FollowerLoad};
pub(crate) use spec::segments_of;
pub use spec::{CamDesign, CamSpec, FaceSpec, FollowerSpec, SegmentSpec};
pub use table::{CAM_TABLE_HEADER, cam_table_row};
