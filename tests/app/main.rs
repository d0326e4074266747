//! The app's tests, in one test binary: each linked eframe, wgpu and kittest on its
//! own when they were twelve (about 400 MB and a link each in a debug build). One
//! module per subject; `common` holds the harnesses and pointer events they share.

mod common;

mod chinese_names;
mod commands;
mod drawing;
mod every_control;
mod exercise;
mod file_actions;
mod gear_lab;
mod gear_train;
mod gl_shaders;
mod keystrokes;
mod labels;
mod layout_grid;
mod machine;
mod newton_only_scene;
mod path_synthesis_ui;
mod playback;
mod point_edit;
mod polygon_snapshots;
mod screens;
mod synthesis;
mod system_file_dialog;
mod ui;
mod undo;
