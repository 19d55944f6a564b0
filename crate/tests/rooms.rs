//! The crate's rooms stay small enough to read whole: no source or test file over 800 lines
//! (functions over 120 lines are clippy's `too_many_lines`, set in clippy.toml).

use std::path::Path;

/// Longest file, in lines.
const MOST_LINES: usize = 800;

/// Every `.rs` file under `dir`, with its line count.
fn files(dir: &Path, out: &mut Vec<(String, usize)>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let lines = std::fs::read_to_string(&path).unwrap().lines().count();
            out.push((path.display().to_string(), lines));
        }
    }
}

#[test]
fn no_crate_file_is_over_800_lines() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut all = Vec::new();
    for dir in ["src", "tests", "benches"] {
        if root.join(dir).is_dir() {
            files(&root.join(dir), &mut all);
        }
    }
    assert!(all.len() > 50, "found {} files", all.len());
    let over: Vec<_> = all.into_iter().filter(|(_, n)| *n > MOST_LINES).collect();
    assert!(over.is_empty(), "over {MOST_LINES} lines: {over:?}");
}
