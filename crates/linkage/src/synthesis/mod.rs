//! Dimensional synthesis: a crank-rocker from rocker length, swing and time ratio K
//! ([`crank_rocker()`]), the die cutter's toggle six-bar on it, function generation
//! by Freudenstein's equation ([`function`]), motion generation through three
//! positions ([`motion`]) and four or five ([`burmester`], [`positions`]), path
//! generation ([`path`]), and the rows of a design's report ([`rows`]); the scenes of
//! the designs are written in `scene_build`.

pub mod burmester;
mod crank_rocker;
mod die_cutter;
pub mod function;
pub mod motion;
pub mod path;
pub mod positions;
pub mod rows;
mod scene_build;

/// Why a synthesis gives no linkage (defined with the other leaf error types).
pub use crate::error::DesignRefusal;
pub use crank_rocker::{CrankRocker, crank_rocker};
pub use die_cutter::{
    DieCutterSpec, ToggleSixBar, die_cutter, die_cutter_as_printed, die_cutter_far_angle,
    toggle_six_bar_scene,
};
pub use scene_build::four_bar_scene;
pub(crate) use scene_build::{FourBar, four_bar, plain_link, points};
