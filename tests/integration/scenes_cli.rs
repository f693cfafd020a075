//! `contact scenes` prints the suite, the kernel scenes and the closed-form answers.

use contact::cli::scenes::{Listing, run};

#[test]
fn scenes_lists_the_suite_and_prints_closed_form_answers() {
    let mut out = Vec::new();
    run(&[], false, Listing::Suite, &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert_eq!(text.lines().count(), contact::scenes::NAMES.len());
    let mut out = Vec::new();
    run(&[], false, Listing::Kernels, &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert_eq!(text.lines().count(), contact::scenes::KERNEL_NAMES.len());
    assert!(text.starts_with("cylinder_box "), "{text}");
    let mut out = Vec::new();
    run(
        &["sphere_plane".to_string()],
        true,
        Listing::Suite,
        &mut out,
    )
    .unwrap();
    let text = String::from_utf8(out).unwrap();
    // Header plus one row per pose in contact: all but the separated and the near ones.
    let rows: Vec<&str> = text.lines().skip(1).collect();
    let separated = 2 * contact::scenes::POSES_PER_SPECIAL_DEPTH;
    assert_eq!(rows.len(), contact::scenes::POSES - separated, "{text}");
    let err = run(
        &["nope".to_string()],
        false,
        Listing::Suite,
        &mut Vec::new(),
    )
    .unwrap_err();
    assert_eq!(
        err.to_string(),
        "no scene named 'nope' (`contact scenes` lists the suite, `contact scenes --kernels` the kernel scenes)"
    );
}
