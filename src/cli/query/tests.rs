//! `contact query`'s parsing and output.

use super::*;

fn args(poses: &Path, engine: EngineName, json: bool) -> QueryArgs {
    QueryArgs {
        geometry_i: "sphere:r=1".into(),
        geometry_j: "plane".into(),
        poses: poses.to_path_buf(),
        engine,
        faceting_tolerance: 300.0028,
        repeat: 2,
        json,
        peer: None,
        accept_open: false,
    }
}

fn poses_file(name: &str, text: &str) -> PathBuf {
    let path =
        std::env::temp_dir().join(format!("contact-query-{name}-{}.csv", std::process::id()));
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_sphere_on_a_plane_prints_one_contact_per_touching_pose_with_timings() {
    let path = poses_file("two", "0 0 0.9 1 0 0 0\n# lifted clear\n0,0,3,1,0,0,0\n");
    let (mut out, mut warn) = (Vec::new(), Vec::new());
    let s = run(
        &args(&path, EngineName::Faceted, false),
        &mut out,
        &mut warn,
    )
    .unwrap();
    let text = String::from_utf8(out).unwrap();
    let rows: Vec<&str> = text.lines().filter(|l| l.starts_with("0,")).collect();
    assert_eq!(rows.len(), 1, "{text}");
    let depth: f64 = rows[0].split(',').nth(4).unwrap().parse().unwrap();
    assert!((depth - 0.1).abs() < 0.002, "{depth}");
    assert!(!text.lines().any(|l| l.starts_with("1,")), "{text}");
    assert!(text.contains("# median query"));
    assert_eq!(s.work.queries, 4);
    let mut json = Vec::new();
    run(
        &args(&path, EngineName::Faceted, true),
        &mut json,
        &mut warn,
    )
    .unwrap();
    let json = String::from_utf8(json).unwrap();
    assert!(
        json.starts_with("{\"poses\":[") && json.contains("\"penetration\":"),
        "{json}"
    );
}

#[test]
fn bad_specs_poses_and_engines_are_errors_that_say_where() {
    let e = parse_geometry("sphere:r=-1", false).unwrap_err();
    assert!(e.to_string().contains("RADIUS = -1.0"), "{e}");
    let e = parse_geometry("cube:x=1", false).unwrap_err();
    assert!(e.to_string().contains("unknown shape 'cube'"), "{e}");
    let e = parse_geometry("box:x=1,y=2", false).unwrap_err();
    assert!(e.to_string().contains("missing z"), "{e}");
    assert_eq!(parse_poses("1 2 3\n").unwrap_err().0, 1);
    assert_eq!(parse_poses("# c\n1 2 3 0 0 0 0\n").unwrap_err().0, 2);
    // The exact engine answers the same query: a unit sphere 0.1 deep in the plane.
    let path = poses_file("one", "0 0 0.9 1 0 0 0\n");
    let (mut out, mut warn) = (Vec::new(), Vec::new());
    run(&args(&path, EngineName::Exact, false), &mut out, &mut warn).unwrap();
    let text = String::from_utf8(out).unwrap();
    let row: Vec<&str> = text.lines().nth(1).unwrap().split(',').collect();
    let depth: f64 = row[4].parse().unwrap();
    assert!((depth - 0.1).abs() < 1e-15, "{text}");
    assert_eq!(&row[5..8], &["0.0", "0.0", "1.0"], "{text}");
}
