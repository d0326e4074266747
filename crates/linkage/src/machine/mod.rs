//! From linkage to machine: what driving a mechanism at speed asks of its motor and
//! flywheel. The torque a crank turning at a constant speed needs over one cycle
//! (inertia forces and loads), the flywheel the energy method sizes from it, and the
//! real speed through the cycle with the scene's motor and flywheel, and the shaking
//! force and moment on the frame with the crank counterweight that lessens them.

mod balance;
mod flywheel;
mod gauss;
mod shaking;
mod steady;
mod torque;

pub use balance::{BalanceAim, Counterweight, counterweights, with_counterweights};
pub use flywheel::{CyclePoint, FlywheelSizing, InertiaRange, size_flywheel};
pub use shaking::{SHAKING_SAMPLES, Shaking, ShakingPoint, shaking};
pub use steady::{SpeedPoint, SteadyState, steady_state};
