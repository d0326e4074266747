//! From linkage to machine: what driving a mechanism at speed asks of its motor and
//! flywheel. The torque a crank turning at a constant speed needs over one cycle
//! (inertia forces and loads), and the flywheel the energy method sizes from it.

mod flywheel;
mod gauss;
mod torque;

pub use flywheel::{CyclePoint, FlywheelSizing, InertiaRange, size_flywheel};
