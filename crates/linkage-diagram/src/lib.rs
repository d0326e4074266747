//! `linkage-diagram`: the figures of one linkage position as a textbook draws them,
//! laid out once for every place they are shown — the app's panes (egui), the SVG
//! sheet (`linkage diagram`, the app's export) — so that what a student hands in is
//! what the app showed.
//!
//! - [`label`]: typeset labels (`v` with subscript `CB`, superscript `n`) as runs of
//!   text, and an approximate measure for places without a font engine.
//! - [`polygon_figure`]: the velocity or acceleration polygon of a position as
//!   arrows and named vertices, in m/s or m/s².
//! - [`layout`]: a figure fitted to a pane in pixels, with arrow heads, a round
//!   scale bar and labels placed clear of each other and of the arrow heads
//!   ([`placement`]).
//! - [`pose_figure`]: the mechanism's links, joints and instant centres.
//! - [`construction`]: one vector equation constructed step by step (known terms,
//!   the unknowns' direction lines, their crossing).
//! - [`force_figure`]: one stage's force polygon (an Assur group or the crank) as
//!   arrows in newtons, with its table of forces and couples.
//! - [`cycle_table`]: the table of the cycle as CSV a student pastes (degrees,
//!   the scene's length unit, columns named with units): the app's and the CLI's.
//! - [`train_schematic`]: a gear train as the textbooks draw it, from its file.
//! - [`svg`]: an A4 sheet of the chosen figures and the vector-equation tables;
//!   `png` (feature `png`) renders it.

#![warn(missing_docs)]
#![forbid(unsafe_code)]

#[cfg(feature = "dxf")]
pub mod cam_dxf;
pub mod construction;
pub mod course;
pub mod course_report;
pub mod cycle_table;
pub mod figure;
pub mod force_figure;
pub mod gear_profile;
pub mod geometry;
pub mod label;
pub mod layout;
pub mod numbers;
pub mod pages;
#[cfg(feature = "pdf")]
pub mod pdf;
pub mod placement;
#[cfg(feature = "png")]
pub mod png;
pub mod polygon_figure;
pub mod pose_figure;
pub mod pose_layout;
pub mod refusal;
pub mod svg;
pub mod svg_cam;
pub mod svg_course;
mod svg_draw;
mod svg_follower;
mod svg_forces;
mod svg_plan;
pub mod svg_report;
pub mod svg_task;
pub mod svg_timing;
pub mod train_schematic;
pub mod words;

pub use force_figure::ForceFigure;
pub use geometry::{Pt, Rect};
pub use label::{Label, Run, Script};
pub use layout::{Figure, LaidArrow, LaidLabel, LaidPolygon, layout_polygon};
pub use polygon_figure::{Arrow, ArrowStyle, PolygonFigure, Vertex};
