//! `contact scenes` prints the suite and the closed-form answers.

#[test]
fn scenes_lists_the_suite_and_prints_closed_form_answers() {
    let mut out = Vec::new();
    contact::cli::scenes::run(&[], false, &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert_eq!(text.lines().count(), contact::scenes::NAMES.len());
    let mut out = Vec::new();
    contact::cli::scenes::run(&["sphere_plane".to_string()], true, &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    // Header plus one row per pose in contact: all but the separated and the near ones.
    let rows: Vec<&str> = text.lines().skip(1).collect();
    let separated = 2 * contact::scenes::POSES_PER_SPECIAL_DEPTH;
    assert_eq!(rows.len(), contact::scenes::POSES - separated, "{text}");
    let err = contact::cli::scenes::run(&["nope".to_string()], false, &mut Vec::new()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "no scene named 'nope' (run `contact scenes` for the list)"
    );
}
