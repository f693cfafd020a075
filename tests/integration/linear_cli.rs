//! LINEAR/EIGENSOL from a command file: `contact run` of the ball_rest_linear example writes
//! `eigenvalues.csv`, `eigenvalues.json` and a summary line per LINEAR, and the reader refuses
//! the LINEAR analyses it does not model.

use crate::{errors, printed};
use contact::dataset::read_str;
use std::path::{Path, PathBuf};

fn example(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(path)
}

#[test]
fn the_ball_rest_linear_example_writes_the_eigenvalues_before_and_after_statics() {
    let out = std::env::temp_dir().join(format!("contact-linear-cli-{}", std::process::id()));
    std::fs::remove_dir_all(&out).ok();
    let args = contact::cli::run::RunArgs {
        model: example("ball_rest_linear/ball_rest_linear.adm"),
        commands: Some(example("ball_rest_linear/ball_rest_linear.acf")),
        engine: None,
        faceting_tolerance: None,
        end: None,
        dtout: None,
        steps: None,
        out: Some(out.clone()),
        threads: None,
        quiet: true,
    };
    let (mut stdout, mut stderr) = (Vec::new(), Vec::new());
    let code = contact::cli::run::run(&args, &mut stdout, &mut stderr).unwrap();
    let (stdout, stderr) = (
        String::from_utf8(stdout).unwrap(),
        String::from_utf8(stderr).unwrap(),
    );
    assert_eq!(code, 0, "{stderr}");
    let lines: Vec<&str> = stdout
        .lines()
        .filter(|l| l.starts_with("eigenvalues at t = 0"))
        .collect();
    assert_eq!(lines.len(), 2, "{stdout}");
    assert!(
        lines[0].contains("6 degrees of freedom, 12 eigenvalues, no eigenvalue away from zero"),
        "{stdout}"
    );
    assert!(lines[1].contains("0 unstable"), "{stdout}");
    assert!(
        stdout.contains("eigenvalues.csv, eigenvalues.json)"),
        "{stdout}"
    );

    // analysis, time, index, real, imaginary, frequency, damping_ratio
    let text = std::fs::read_to_string(out.join("eigenvalues.csv")).unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 24);
    let number = |v: &str| v.parse::<f64>().unwrap();
    // Before the statics the ball is in the air: every eigenvalue is zero.
    for row in &rows[..12] {
        assert_eq!(row[0], "1");
        assert_eq!((number(row[3]), number(row[4])), (0.0, 0.0), "{row:?}");
        assert_eq!(row[6], "", "no damping ratio for s = 0");
    }
    // After it, the vertical pair of the contact: |s|² = k·e·δ^(e−1)/m, σ = −c/2m.
    let (m, k, e, c) = (1.0_f64, 1e6_f64, 1.5_f64, 50.0_f64);
    let delta = (m * 9.81 / k).powf(1.0 / e);
    let omega = (k * e * delta.powf(e - 1.0) / m).sqrt();
    let top = &rows[22];
    assert_eq!(top[0], "2");
    let (re, im) = (number(top[3]), number(top[4]));
    // The bound of the library test (forward-difference contact partials) is 4.1e-6.
    assert!(
        (re.hypot(im) - omega).abs() < 4.2e-6 * omega,
        "{top:?} vs {omega}"
    );
    assert!((re + c / (2.0 * m)).abs() < 1e-9 * 25.0, "{top:?}");
    assert!(
        (number(top[5]) - omega / std::f64::consts::TAU).abs() < 4.2e-6 * omega,
        "{top:?}"
    );
    assert_eq!(number(rows[23][4]), -im);

    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("eigenvalues.json")).unwrap())
            .unwrap();
    let analyses = json["analyses"].as_array().unwrap();
    assert_eq!(analyses.len(), 2);
    assert_eq!(analyses[1]["degrees_of_freedom"], 6);
    assert_eq!(analyses[1]["eigenvalues"][10]["real"].as_f64(), Some(re));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let names: Vec<&str> = summary["analyses"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a["analysis"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["LINEAR", "STATICS", "LINEAR"]);
    assert_eq!(summary["analyses"][2]["eigenvalues"], 12);
    assert_eq!(summary["analyses"][2]["status"], "completed");
    std::fs::remove_dir_all(&out).ok();
}

fn read_acf(acf: &str) -> contact::dataset::Loaded {
    read_str(
        "linear\nPART/1, GROUND\nEND\n",
        crate::data_dir().join("linear.adm"),
        Some((acf, Path::new("linear.acf"))),
    )
}

#[test]
fn linear_statemat_and_mkb_are_errors_and_output_options_are_reported_ignored() {
    let loaded = read_acf("linear\nLINEAR/STATEMAT\nLINEAR/MKB\nLINEAR/ NODAMPIN\nSTOP\n");
    let errors = errors(&loaded);
    assert_eq!(errors.len(), 3, "{errors:?}");
    assert!(
        errors[0].contains("linear.acf:2:")
            && errors[0].contains("LINEAR/STATEMAT is not modelled: only LINEAR/EIGENSOL"),
        "{errors:?}"
    );
    assert!(
        errors[1].contains("LINEAR/MKB is not modelled"),
        "{errors:?}"
    );
    assert!(errors[2].contains("EIGENSOL"), "{errors:?}");

    let loaded = read_acf("linear\nLIN/EIGEN, NODAMP, NOVECTOR, COORDS = 1, 6\nSTOP\n");
    assert!(!loaded.has_errors(), "{:?}", printed(&loaded));
    let warnings = printed(&loaded);
    assert!(
        warnings
            .iter()
            .any(|w| w.contains("linear.acf:2:") && w.contains("COORDS is not modelled")),
        "{warnings:?}"
    );
    assert_eq!(
        loaded.model.commands.first().map(|(_, c)| c.clone()),
        Some(contact::model::Command::Linear { damping: false })
    );
}
