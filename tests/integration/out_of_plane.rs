//! A 2-D contact whose part leaves the plane stops the run with a diagnosis naming the contact,
//! the part and the time, and keeps every output step computed before it (SPEC §3, §8).

use contact::cli::run::{RunArgs, run};

/// The disk's out-of-plane speed in `tests/data/out_of_plane_circle.adm` (VZ).
const VZ: f64 = 2e-6;
const DTOUT: f64 = 0.01;

/// The number after `key` in `text` (up to a space, colon, comma or parenthesis).
fn number_after(text: &str, key: &str) -> f64 {
    let start = text
        .find(key)
        .unwrap_or_else(|| panic!("no '{key}' in: {text}"))
        + key.len();
    let rest = &text[start..];
    let end = rest.find([' ', ':', ',', ')']).unwrap_or(rest.len());
    rest[..end]
        .parse()
        .unwrap_or_else(|e| panic!("'{}': {e}", &rest[..end]))
}

#[test]
fn a_circle_drifting_off_its_line_stops_the_run_naming_contact_part_and_time() {
    let out = std::env::temp_dir().join(format!("contact-out-of-plane-{}", std::process::id()));
    let args = RunArgs {
        model: crate::data_dir().join("out_of_plane_circle.adm"),
        commands: None,
        engine: None,
        faceting_tolerance: None,
        end: Some(1.0),
        dtout: Some(DTOUT),
        steps: None,
        out: Some(out.clone()),
        threads: None,
        quiet: true,
    };
    let (mut stdout, mut stderr) = (Vec::new(), Vec::new());
    let code = run(&args, &mut stdout, &mut stderr).unwrap();
    let err = String::from_utf8(stderr).unwrap();
    assert_eq!(code, 1, "the run must fail: {err}");
    assert!(err.contains("CONTACT/1: PART/2 left the plane"), "{err}");
    let t_left = number_after(&err, "left the plane of this 2-D contact at t = ");
    let t_accepted = number_after(&err, "the last accepted step ended at t = ");
    assert!(t_accepted < t_left, "{err}");
    // The disk drifts at VZ (nothing acts along z), so the reported plane offset is VZ·t at the
    // reported time: the diagnosis describes the state it names.
    let offset = number_after(&err, "offset by ");
    assert!(
        (offset - VZ * t_left).abs() <= 1e-9 * VZ,
        "{offset} vs {}",
        VZ * t_left
    );
    // It stopped where one of the two tolerances was crossed (angle 1e-6 rad, offset 1e-6·L),
    // not at the first step: the contact ran in plane for a while.
    let angle = number_after(&err, "the planes are ");
    let after_offset = &err[err.find("offset by ").unwrap()..];
    let offset_tolerance = number_after(after_offset, "(tolerance ");
    assert!(angle > 1e-6 || offset > offset_tolerance, "{err}");
    assert!(t_left > 0.1, "{err}");

    // Every output step up to the last accepted step is in the files, and nothing after it.
    let csv = std::fs::read_to_string(out.join("parts.csv")).unwrap();
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let expected = (t_accepted / DTOUT + 1e-9).floor() as usize + 1;
    assert_eq!(rows.len(), expected, "rows up to t = {t_accepted}");
    for (k, row) in rows.iter().enumerate() {
        assert!((row[0] - k as f64 * DTOUT).abs() < 1e-12, "{row:?}");
        // z of the CM drifts at VZ: the outputs are the states the run computed.
        assert!((row[4] - VZ * row[0]).abs() < 1e-12, "{row:?}");
    }
    let frames = std::fs::read_to_string(out.join("frames.jsonl")).unwrap();
    assert_eq!(frames.lines().count(), expected);
    std::fs::remove_dir_all(&out).ok();
}
