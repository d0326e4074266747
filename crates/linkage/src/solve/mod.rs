//! Solving a position: closed-form Assur dyads ([`ClosedForm`], one file per dyad
//! kind), Newton–Raphson on the loop-closure constraints ([`Newton`]), several inputs
//! at once in SIMD lanes ([`LaneSolution`]), and [`Kinematics`], which picks the path
//! and answers every caller. Private modules; this is what the rest of the crate and
//! its users see.

mod closed_form;
mod kinematics;
mod lanes;
mod newton;

pub use closed_form::ClosedForm;
pub(crate) use closed_form::{Failure, Group, Prp, Rpr, Rrp, Rrr, TANGENT_SLACK, finish_solution};
pub use kinematics::{Closure, Kinematics, PathKind};
pub use lanes::{LaneSolution, link_lane, point_lane};
pub use newton::{Continuation, Newton, NewtonModel, NewtonWorkspace};
