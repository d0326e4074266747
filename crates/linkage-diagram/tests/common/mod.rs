//! What the figure tests share: every scene file and inputs over its range.
#![allow(dead_code)]

use linkage::{Kinematics, Mechanism};

/// Every scene file in `assets/scenes` (read from the directory), by file name.
pub fn scenes() -> Vec<(String, Mechanism)> {
    let dir = format!("{}/../../assets/scenes", env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("scene directory")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .collect();
    files.sort();
    assert!(files.len() >= 6, "only {} scenes in {dir}", files.len());
    files
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("readable");
            let m = Mechanism::from_ron(&text).unwrap_or_else(|e| panic!("{p:?}: {e}"));
            (
                p.file_name().expect("name").to_string_lossy().into_owned(),
                m,
            )
        })
        .collect()
}

/// `n` inputs over the scene's sweep range (a full turn or the assembly interval).
pub fn inputs(k: &Kinematics, n: usize) -> Vec<f64> {
    let ([a, b], full) = linkage::sweep::sweep_range(k).expect("assembles");
    let div = if full { n } else { n - 1 };
    (0..n)
        .map(|i| a + (b - a) * i as f64 / div as f64)
        .collect()
}
