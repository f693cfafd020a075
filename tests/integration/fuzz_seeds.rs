//! Every seed of the fuzz corpus (`fuzz/corpus/parse/`) goes through the lexer and parser — and
//! the whole lowering — without a panic, so the corpus stays a working regression suite.

use contact::dataset::{FileKind, parse_only, read_str};
use std::path::Path;

#[test]
fn every_seed_parses_and_lowers_without_panic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus/parse");
    let mut seeds = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        for kind in [FileKind::Dataset, FileKind::Commands] {
            let parsed = parse_only(&text, kind);
            assert!(parsed.statements.len() + parsed.problems.len() <= text.lines().count() + 1);
        }
        let loaded = read_str(&text, &path, None);
        // Every diagnostic points inside the file.
        let lines = u32::try_from(text.split('\n').count()).unwrap();
        for d in &loaded.diagnostics {
            assert!(d.origin.loc.line >= 1 && d.origin.loc.line <= lines, "{d}");
        }
        seeds += 1;
    }
    assert!(seeds >= 10, "only {seeds} seeds in {}", dir.display());
}
