//! The panels, one file each.

pub mod accuracy;
pub mod builder_bodies;
pub mod builder_canvas;
pub mod builder_forces;
pub mod builder_panel;
pub mod centres;
pub mod construction;
pub mod control_map;
pub mod controls;
pub mod drawing;
pub mod files;
pub mod layout;
pub mod plots;
pub mod point_drag;
pub mod polygon_paint;
pub mod polygons;
pub mod report;
pub mod scene_picker;
pub mod sheet;
pub mod synthesis;
pub mod synthesis_figure;
pub mod synthesis_path;
pub mod typeset;
pub mod viewport;
