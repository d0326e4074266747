//! The command line's tests, one binary: each file a module. One build and one link
//! instead of one a file: the solver's 35 test files built in 128 s as 35 binaries
//! and in 24 s as one (docs/architecture.md, "CI time").

mod cam;
mod chinese_names;
mod cli;
mod cli_strict_input;
mod common;
mod course_report;
mod dead_points;
mod diagram;
mod exercise;
mod gears;
mod messages_found_by_fuzzing;
mod share;
mod timing;
