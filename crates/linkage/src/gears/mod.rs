//! Involute spur gears in their own layer: one gear's geometry ([`Gear`]: its
//! circles, tooth thickness at any radius, undercut, a pointed tip), a meshing pair
//! ([`GearPair`]: working pressure angle, centre distance, contact ratio and the
//! checks), and the involute function ([`involute`]) under both. Nothing here
//! depends on the linkage solver.

mod error;
mod gear;
pub mod involute;
mod pair;

pub use error::{GearError, GearParam, Member};
pub use gear::{Gear, GearKind, GearSpec, least_teeth_without_undercut, limits};
pub use pair::{CentreDistance, GearPair, MAX_WORKING_ANGLE_DEG, PairIssue, PairSpec};
