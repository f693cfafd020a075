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

/// The files of one corpus folder of the fuzz crate.
fn corpus(name: &str) -> Vec<std::path::PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz/corpus")
        .join(name);
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    assert!(
        files.len() >= 3,
        "only {} seeds in {}",
        files.len(),
        dir.display()
    );
    files
}

#[test]
fn every_command_seed_is_read_and_planned_without_panic() {
    use contact::run::plan::{PlanOverrides, plan_analyses};
    let dataset = include_str!("../../examples/ball/ball.adm");
    for path in corpus("commands") {
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        let loaded = read_str(dataset, "ball.adm", Some((&text, &path)));
        if !loaded.has_errors() {
            let _ = plan_analyses(&loaded.model, PlanOverrides::default(), &mut |_| Ok(6));
        }
    }
}

#[test]
fn every_mesh_seed_reads_or_is_refused_without_panic() {
    use contact_core::mesh_file::read_mesh_geometry;
    let mut read = 0;
    for path in corpus("stl").into_iter().chain(corpus("obj")) {
        if read_mesh_geometry(&path).is_ok() {
            read += 1;
        }
    }
    // The hand-written seeds (a tetrahedron and cubes) are valid solids.
    assert!(read >= 5, "only {read} mesh seeds read");
}

#[test]
fn every_pose_seed_parses_or_is_refused_with_its_line() {
    use contact::cli::query::parse_poses;
    for path in corpus("poses") {
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        if let Err((line, reason)) = parse_poses(&text) {
            let lines = text.split('\n').count();
            assert!(
                line >= 1 && line <= lines,
                "{}: line {line}: {reason}",
                path.display()
            );
        }
    }
}
