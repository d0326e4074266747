//! Dynamics of 1-DOF mechanisms by the reduction of the flipper paper: the chain is
//! reduced to its input coordinate q with equivalent inertia J(q), its slope dJ/dq
//! and equivalent moment M(q, q̇, t), so that
//!
//! ```text
//! J(q) q̈ + ½ J'(q) q̇² = M(q, q̇, t)
//! ```
//!
//! All three come from one kinematic solution at unit input speed: there velocities
//! are the velocity ratios v' = dv/dq and accelerations (with q̈ = 0) are dv'/dq.
//! Only what a scene declares is evaluated ([`ForceModel`]), and a scene that asks
//! for dynamics must give every moving link a mass, centroid and inertia.

mod forces;
mod integrate;

pub use forces::{EnergyTerms, ForceModel, Reduced};
pub use integrate::{Method, RunStats, Sample, SimEvent, Simulation, simulate};
