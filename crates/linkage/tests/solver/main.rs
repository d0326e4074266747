//! The solver's integration tests, one binary: each file a module. One build and one link
//! instead of one a file: the solver's 35 test files built in 128 s as 35 binaries
//! and in 24 s as one (docs/architecture.md, "CI time").

mod balance;
mod cam_disc;
mod cam_joint;
mod cam_laws;
mod cam_outline;
mod cam_random;
mod cam_sizing;
mod common;
mod degenerate_chains;
mod derivatives_and_paths;
mod drawing;
mod drive_train;
mod dynamics_bounded;
mod dynamics_extremes;
mod dynamics_flipper;
mod errors_and_classes;
mod every_scale;
mod flywheel;
mod force_polygons;
mod function_synthesis;
mod fuzz_scenes;
mod gear_trains;
mod gears;
mod geneva;
mod instant_centres;
mod kinetostatics;
mod lanes;
mod motion_synthesis;
mod newton_only_folds;
mod newton_only_triad;
mod newton_parts;
mod path_synthesis;
mod pendulum_exact;
mod properties;
mod seed1_paper_cup_oracle;
mod seed2_die_cutter;
mod seed3_flipper;
mod shaking;
mod steady_state;
mod strict_scene_input;
mod train_random;
