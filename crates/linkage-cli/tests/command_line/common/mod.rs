//! What the CLI tests share: the path of a shipped scene and a run of the binary.
#![allow(dead_code)]

use std::process::Command;

/// The path of `assets/scenes/FILE`.
pub fn scene(file: &str) -> String {
    format!("{}/../../assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"))
}

/// The path of `FILE` from the repository's root.
pub fn repo(file: &str) -> String {
    format!("{}/../../{file}", env!("CARGO_MANIFEST_DIR"))
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

/// Runs `linkage ARGS --svg FILE` in a scratch folder of its own; returns (exit code,
/// every A4 page's SVG in order, stderr): a sheet of several pages writes FILE,
/// FILE-2, FILE-3 ….
pub fn run_sheet(args: &[&str]) -> (Option<i32>, Vec<String>, String) {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static RUNS: AtomicUsize = AtomicUsize::new(0);
    let run = RUNS.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("linkage-sheet-{}-{run}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let file = dir.join("sheet.svg");
    let mut all = args.to_vec();
    let path = file.display().to_string();
    all.extend(["--svg", path.as_str()]);
    let (code, _, err) = run_linkage(&all);
    let mut pages = Vec::new();
    for i in 1.. {
        let page = if i == 1 {
            file.clone()
        } else {
            dir.join(format!("sheet-{i}.svg"))
        };
        match std::fs::read_to_string(&page) {
            Ok(text) => pages.push(text),
            Err(_) => break,
        }
    }
    std::fs::remove_dir_all(&dir).expect("clean up");
    (code, pages, err)
}
