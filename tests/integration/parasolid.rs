//! `contact check` on FRS5 (tests/data/frs5, a copy of the public dataset), whose CONTACTs are between
//! Parasolid bodies of one transmit file and primitives: the faceted engine answers every one
//! and nothing about the geometry is an error; the exact engine refuses each CONTACT that has
//! a Parasolid body, naming the faceted engine.

use std::path::PathBuf;
use std::process::Command;

fn frs5() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/frs5/FRS5_doe_8_LAUL_analysis.adm")
}

fn check(engine: Option<&str>) -> String {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_contact"));
    cmd.arg("check")
        .arg(frs5())
        .env_remove("MDI_FACETING_TOLERANCE");
    if let Some(e) = engine {
        cmd.arg("--engine").arg(e);
    }
    let out = cmd.output().unwrap();
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn errors(report: &str) -> Vec<&str> {
    report.lines().filter(|l| l.contains(": error: ")).collect()
}

#[test]
fn the_faceted_engine_answers_every_frs5_contact_between_parasolid_bodies() {
    let report = check(None);
    assert!(report.contains("contacts: 110"), "{report}");
    assert!(report.contains("engine: faceted"), "{report}");
    for e in errors(&report) {
        for word in ["GRAPHICS", "CONTACT", "Parasolid", "xmt_txt", "body"] {
            assert!(!e.contains(word), "{e}");
        }
    }
}

/// The CONTACTs whose IGEOM or JGEOM lists a `GRAPHICS/…, EXTERNAL`, counted from the
/// dataset's text line by line (statements start in column 1, continuations with a comma).
fn contacts_with_external_graphics() -> usize {
    let text = std::fs::read_to_string(frs5()).unwrap();
    let mut statements: Vec<Vec<&str>> = Vec::new();
    for line in text.lines().skip(1) {
        let line = line.split('!').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        match statements.last_mut() {
            Some(s) if line.starts_with(',') => s.push(line),
            _ => statements.push(vec![line]),
        }
    }
    let external: Vec<&str> = statements
        .iter()
        .filter(|s| s[0].starts_with("GRAPHICS/") && s.iter().any(|l| l.contains("EXTERNAL")))
        .map(|s| &s[0]["GRAPHICS/".len()..])
        .collect();
    statements
        .iter()
        .filter(|s| s[0].starts_with("CONTACT/"))
        .filter(|s| {
            s.iter().any(|l| {
                let l = l.trim_start_matches(',').trim();
                (l.starts_with("IGEOM") || l.starts_with("JGEOM"))
                    && l.split(['=', ','])
                        .skip(1)
                        .any(|id| external.contains(&id.trim()))
            })
        })
        .count()
}

#[test]
fn the_exact_engine_refuses_frs5_parasolid_bodies_naming_the_faceted_engine() {
    let report = check(Some("exact"));
    let expected = contacts_with_external_graphics();
    assert_eq!(expected, 84, "FRS5's CONTACTs with an EXTERNAL graphic");
    let refused: Vec<&str> = errors(&report)
        .into_iter()
        .filter(|e| e.contains("CONTACT/"))
        .collect();
    assert_eq!(
        refused
            .iter()
            .map(|e| e.split("CONTACT/").nth(1).and_then(|s| s.split(':').next()))
            .collect::<std::collections::BTreeSet<_>>()
            .len(),
        expected,
        "{report}"
    );
    for e in refused {
        assert!(
            e.contains("of the Parasolid file FRS5_doe_8_LAUL_analysis.xmt_txt")
                && e.contains("the faceted engine answers it"),
            "{e}"
        );
    }
}
