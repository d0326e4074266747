//! The drive in a scene file: a motor on the driver through a gear ratio or a gear
//! train, with its own inertia and a flywheel on the crank or on the motor shaft.
//!
//! ```ron
//! drive: Some((
//!     motor: Linear(no_load_rpm: 1500.0, rated_torque_n_m: 549.0, rated_rpm: 1450.0),
//!     gear_ratio: 29.0,
//!     motor_inertia_kg_m2: 0.05,
//!     flywheel_kg_m2: 48.0,
//!     flywheel_on: Motor,
//! )),
//! ```
//!
//! With a train in place of the bare ratio, the ratio is the train's and its members'
//! inertias join the crank's (docs/trains.md, "A train in a scene's drive"):
//!
//! ```ron
//! drive: Some((
//!     motor: Linear(no_load_rpm: 1500.0, rated_torque_n_m: 549.0, rated_rpm: 1450.0),
//!     train: Some((motor_member: "motor", crank_member: "crank", train: (/* a train file */))),
//!     flywheel_kg_m2: 48.0,
//!     flywheel_on: Motor,
//! )),
//! ```

use serde::{Deserialize, Serialize};

use crate::gears::train_file::TrainFile;

/// The motor's torque against its speed, on its own shaft.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum MotorSpec {
    /// The same torque at every speed, N·m.
    Constant {
        /// Torque, N·m.
        torque_n_m: f64,
    },
    /// A straight line through the no-load speed (zero torque) and the rated point,
    /// as an induction motor runs near its rated speed.
    Linear {
        /// Speed at which the torque falls to zero, rpm.
        no_load_rpm: f64,
        /// Torque at the rated speed, N·m.
        rated_torque_n_m: f64,
        /// Rated speed, rpm (below the no-load speed).
        rated_rpm: f64,
    },
    /// Torque against speed, `(rpm, N·m)` in rising speed, joined by straight lines;
    /// outside the table the end values hold.
    Table {
        /// The points.
        points: Vec<(f64, f64)>,
    },
}

/// Which shaft the flywheel is on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Shaft {
    /// The crank (the driver link).
    #[default]
    Crank,
    /// The motor shaft, turning `gear_ratio` times faster.
    Motor,
}

/// A motor driving the driver link through a gear, with inertias.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DriveSpec {
    /// The motor's characteristic.
    pub motor: MotorSpec,
    /// Motor turns per crank turn (a reduction is > 1); with a train, the train's
    /// ratio is used and this may be left out (or must agree with it).
    #[serde(default = "one")]
    pub gear_ratio: f64,
    /// The gears, belts and chains between the motor and the crank, in place of a
    /// bare ratio.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub train: Option<Box<DriveTrainSpec>>,
    /// The motor rotor's inertia, kg·m² (on the motor shaft).
    #[serde(default)]
    pub motor_inertia_kg_m2: f64,
    /// The flywheel's inertia, kg·m², on `flywheel_on`.
    #[serde(default)]
    pub flywheel_kg_m2: f64,
    /// The shaft the flywheel is on.
    #[serde(default)]
    pub flywheel_on: Shaft,
}

/// A gear train as a drive: which of its members the motor turns and which is the
/// crank.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DriveTrainSpec {
    /// The member on the motor's shaft.
    pub motor_member: String,
    /// The member fixed to the crank (the scene's driver link).
    pub crank_member: String,
    /// The train (the file format of docs/trains.md). Its inputs set which members
    /// are held (an input of 0 rpm); its one turning input's speed is only a scale.
    pub train: TrainFile,
}

fn one() -> f64 {
    1.0
}
