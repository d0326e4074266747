//! What the CLI tests share: the path of a shipped scene and a run of the binary.
#![allow(dead_code)]

use std::process::Command;

/// The path of `assets/scenes/FILE`.
pub fn scene(file: &str) -> String {
    format!("{}/../../assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"))
}

/// Runs `linkage ARGS`; returns (exit code, stdout, stderr).
pub fn run_linkage(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_linkage"))
        .args(args)
        .output()
        .expect("run linkage");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}
