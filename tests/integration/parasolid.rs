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

/// A pin from a transmit file (tests/data/parasolid/cam_and_pin.x_t: body PIN, a cylinder of
/// radius 0.02 m and length 0.01 m) lying on its side on a plane, settled by damping for 1 s.
/// Its final axis height with `engine`, and `contact check`'s report.
fn settled_pin(engine: &str) -> (f64, String) {
    let dir = std::env::temp_dir().join(format!("contact-pin-{engine}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let data = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/parasolid");
    std::fs::copy(data.join("cam_and_pin.x_t"), dir.join("cam_and_pin.x_t")).unwrap();
    // RM's z (the body's axis) along world x: REULER 90D, 90D, 0D. The cylinder spans
    // x ∈ [−0.005, 0.005] with its axis at z = 0.0195, 0.5 mm into the plane.
    let adm = "pin on a plane\n\
        UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
        PART/1, GROUND\nMARKER/10, PART = 1\n\
        PART/2, MASS = 1, CM = 20, IP = 1E-4, 1E-4, 1E-4\n\
        MARKER/20, PART = 2, QP = 0, 0, 0.0195\n\
        MARKER/21, PART = 2, QP = -0.005, 0, 0.0195, REULER = 90D, 90D, 0D\n\
        GRAPHICS/1, EXTERNAL, RM = 21, FILE = cam_and_pin.x_t, ELEMENT = PIN\n\
        GRAPHICS/2, PLANE, RM = 10\n\
        CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT, STIFFNESS = 1E6, EXPONENT = 1.5\n\
        , DAMPING = 300, DMAX = 1E-4\n\
        ACCGRAV/ KGRAV = -9.80665\nEND\n";
    std::fs::write(dir.join("pin.adm"), adm).unwrap();
    let contact = |args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_contact"))
            .args(args)
            .arg(dir.join("pin.adm"))
            .args(["--engine", engine])
            .env_remove("MDI_FACETING_TOLERANCE")
            .output()
            .unwrap();
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr)
    };
    let report = contact(&["check"]);
    let out = dir.join("out");
    let run = contact(&[
        "run",
        "--end",
        "1",
        "--dtout",
        "0.5",
        "--out",
        out.to_str().unwrap(),
    ]);
    let parts =
        std::fs::read_to_string(out.join("parts.csv")).unwrap_or_else(|e| panic!("{e}: {run}"));
    let z = parts
        .lines()
        .last()
        .unwrap()
        .split(',')
        .nth(4)
        .unwrap()
        .parse()
        .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    (z, report)
}

/// The exact engine answers a Parasolid body that is exactly a cylinder as the cylinder: the
/// pin rests where the cylinder–plane closed form puts it, `F = k·δ^e = m·g`, to 1e-9 m; the
/// faceted engine answers the tessellated body, within its chord deviation of that.
#[test]
fn a_parasolid_body_that_is_a_cylinder_is_one_for_the_exact_engine() {
    let (exact, report) = settled_pin("exact");
    assert!(errors(&report).is_empty(), "{report}");
    let rest = 0.02 - (9.80665_f64 / 1e6).powf(1.0 / 1.5);
    assert!((exact - rest).abs() < 1e-9, "{exact} against {rest}");
    let (faceted, report) = settled_pin("faceted");
    assert!(errors(&report).is_empty(), "{report}");
    // Chord deviation: the body's bounding-box diagonal over the faceting tolerance.
    let deviation = (0.04_f64.powi(2) * 2.0 + 0.01_f64.powi(2)).sqrt() / 300.0028;
    assert!(
        (faceted - rest).abs() < deviation,
        "{faceted} against {rest}"
    );
    assert!(faceted != exact);
}
