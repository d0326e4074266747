//! Involute spur gears in their own layer: one gear's geometry ([`Gear`]: its
//! circles, tooth thickness at any radius, undercut, a pointed tip), a meshing pair
//! ([`GearPair`]: working pressure angle, centre distance, contact ratio and the
//! checks), the involute function ([`involute`]) under both, and gear trains
//! ([`Train`]: a train file's members, gears, meshes and belt or chain stages; every
//! member's speed from the inputs, Willis' converted ratios, a planetary set's
//! assembly conditions); the tooth as cut, by a rack ([`generation`]) or, for an
//! internal gear, a pinion cutter ([`shaper`]). Nothing here depends on the linkage
//! solver.

mod error;
mod gear;
pub mod generation;
pub mod involute;
mod mesh_pose;
mod pair;
pub mod shaper;
mod train;
mod train_assembly;
pub mod train_file;
mod train_results;
mod train_rows;
mod train_torques;

pub use error::{GearError, GearParam, Member};
pub use gear::{
    Gear, GearKind, GearSpec, LEAST_TIP_THICKNESS_MODULES, least_teeth_without_undercut, limits,
};
pub use mesh_pose::MeshPose;
pub use pair::{CentreDistance, GearPair, MAX_WORKING_ANGLE_DEG, PairIssue, PairSpec};
pub use train::{AssemblyCheck, MemberSpeed, Train, TrainError, TrainSolution, WillisRatio};
pub use train_torques::{MemberTorque, TrainTorques};
