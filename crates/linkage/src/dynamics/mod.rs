//! Dynamics of 1-DOF mechanisms by the reduction of the flipper paper: the chain is
//! reduced to one coordinate q with equivalent inertia J(q), its slope dJ/dq and
//! equivalent moment M(q, q̇, t), so that
//!
//! ```text
//! J(q) q̈ + ½ J'(q) q̇² = M(q, q̇, t)
//! ```
//!
//! All three come from one kinematic solution at unit coordinate speed: there
//! velocities are the velocity ratios v' = dv/dq and accelerations (with q̈ = 0) are
//! dv'/dq. Only what a scene declares is evaluated ([`ForceModel`]), and a scene that
//! asks for dynamics must give every moving link a mass, centroid and inertia.
//!
//! The coordinate starts as the scene's driver angle; near its dead point (where J
//! would grow without bound) the run switches to the angle of another pivoted link
//! that is regular there, so a run can pass through the dead point.

mod adaptive;
mod dense;
mod fixed;
mod forces;
mod implicit;
mod load_terms;
mod output;
mod rhs;
mod run;
mod settings;
mod tableaus;
pub mod tradeoff;

pub use forces::{EnergyTerms, ForceModel, Load, Reduced};
pub use load_terms::{Action, InertiaTerm, LoadSource, LoadTerm};
pub use output::{RunStats, Sample, SimEvent, Simulation};
pub use run::{Run, simulate};
pub use settings::{MAX_OUTPUT_SAMPLES, MAX_STEPS, Method, Settings};
