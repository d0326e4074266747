//! The panels, one file each.

pub mod accuracy;
pub mod centres;
pub mod construction;
pub mod control_map;
pub mod controls;
pub mod drawing;
pub mod drawing_bodies;
pub mod drawing_canvas;
pub mod drawing_forces;
pub mod drawing_panel;
pub mod files;
pub mod flywheel_plots;
pub mod force_polygons;
pub mod layout;
pub mod panels;
pub mod plot_layout;
pub mod plots;
pub mod point_drag;
pub mod polygon_paint;
pub mod polygons;
pub mod report;
pub mod scene_picker;
pub mod sheet;
pub mod synthesis;
pub mod typeset;
pub mod viewport;
