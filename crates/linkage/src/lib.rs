//! `linkage`: a headless planar-linkage solver.
//!
//! Mechanisms come from scene files ([`scene`]) and are validated into a
//! [`Mechanism`]. [`Kinematics`] solves any input angle by one of two paths that
//! agree to round-off: closed-form Assur dyads ([`ClosedForm`]) and Newton–Raphson
//! on the loop-closure constraints ([`Newton`]). The closed form also solves four
//! inputs at once in SIMD lanes ([`LaneSolution`]). [`analysis`] finds assembly ranges,
//! limit positions, strokes, time ratio, Grashof class, transmission angle and
//! toggles; [`polygon`] gives the velocity and acceleration polygon terms and
//! [`instant_centres`] the instant centres by Kennedy's theorem;
//! [`synthesis`] designs crank-rockers from swing and time ratio; [`share`] packs a
//! scene into a link and back; [`machine`] sizes the flywheel, finds the steady state
//! with a motor and the shaking force.

#![warn(missing_docs)]
#![forbid(unsafe_code)]

pub mod analysis;
mod angles;
pub mod assembly;
pub mod branch_points;
pub mod cam;
pub mod drawing;
pub mod dyad;
pub mod dynamics;
pub mod error;
pub mod extremum;
pub mod force_polygon;
pub mod gears;
pub mod ids;
pub mod instant_centres;
pub mod integrator;
pub mod kinetostatics;
pub mod machine;
pub mod model;
pub mod motion;
pub mod overflow;
pub mod polygon;
mod ranges;
pub mod real;
pub mod rng;
pub mod roots_util;
pub mod scene;
mod scene_cam;
mod scene_drive;
pub mod scene_scale;
pub mod share;
mod small_lu;
mod solve;
pub mod sweep;
pub mod synthesis;
mod unique_map;

pub use error::{DesignRefusal, LinkageError, Result, SceneProblem};
pub use ids::{LinkId, PointId};
pub use model::Mechanism;
pub use motion::{LinkMotion, PointMotion, SlideMotion, Solution, Vec2};
pub use real::{LANES, Lanes};
pub use scene::SceneFile;
pub use solve::{
    ClosedForm, Closure, Continuation, Kinematics, LaneSolution, Newton, NewtonModel,
    NewtonWorkspace, PathKind, link_lane, point_lane,
};
