//! The figures' and sheets' tests, one binary: each file a module. One build and one link
//! instead of one a file: the solver's 35 test files built in 128 s as 35 binaries
//! and in 24 s as one (docs/architecture.md, "CI time").

mod common;
mod construction;
mod course_sheets;
mod every_scene_layout;
mod force_figures;
mod gear_mesh;
mod sheet_numbers;
mod sheet_overlaps;
mod train_schematic;
