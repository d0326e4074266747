//! Analyses of any 1-DOF chain: assembly range, limit positions of every output
//! (found by Brent root-finding on the output's velocity ratio, bracketed on a grid),
//! strokes, swings, time ratio K, Grashof class, transmission angle and toggles, and
//! the timing diagram of every output against the main shaft.

mod grashof;
mod limits;
mod outputs;
mod peaks;
mod report;
mod time_ratio;
mod timing;
mod toggles;
mod transmission;

pub use crate::assembly::AssemblyRanges;
pub use crate::ranges::{assembly_ranges_of, sweep_range};
pub use grashof::{Grashof, GrashofClass, grashof};
pub use limits::{Extreme, LimitPosition, limit_positions};
pub use outputs::{Output, outputs};
pub use peaks::{OutputPeaks, Peak, output_peaks};
pub use report::{Report, report};
pub use time_ratio::{Stroke, TimeRatioNote, time_ratio};
pub use timing::{TimingDiagram, TimingLane, timing, timing_lane, timing_of_sweep};
pub use toggles::{Tangency, Toggle, ToggleRatio};
pub use transmission::{
    CollinearJoint, TransmissionAngle, collinear_joints, transmission_angle, transmission_angle_at,
};

const TAU: f64 = std::f64::consts::TAU;
/// Velocity ratio below which an output counts as at rest, per radian of input and,
/// for a slider, per metre of the mechanism's size: dimensionless, so that a 50 µm
/// mechanism rests exactly when its 50 m twin does (round-off of a ratio of order 1 is
/// 1e-16; a real limit's neighbours on the grid have ratios of 1e-3 and up).
const RESTING_RATE: f64 = 1e-9;
