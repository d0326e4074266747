//! The repository's Rust sources, read by the tests that check what the app shows
//! against them (every character has a face, every catalogue key is used).

/// Every `.rs` file under the folders `dirs` (relative to the repository's root),
/// as (its path from the root, its text), sorted by path.
pub fn rust_sources(dirs: &[&str]) -> Vec<(String, String)> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut folders: Vec<std::path::PathBuf> = dirs.iter().map(|d| root.join(d)).collect();
    let mut out = Vec::new();
    while let Some(dir) = folders.pop() {
        for entry in std::fs::read_dir(&dir).expect("source dir").flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let name = path
                    .strip_prefix(root)
                    .expect("under the root")
                    .to_string_lossy()
                    .into_owned();
                out.push((name, std::fs::read_to_string(&path).expect("source")));
            }
        }
    }
    out.sort();
    out
}
