//! Unit tests of the whole-run comparison and choice on hand-made records.

use super::*;
use crate::tradeoff::TouchingPose;
use contact_core::{Isometry3, Point3, UnitQuaternion};

/// A run of one part and one contact: the part at `x(t)` turned by `angle(t)` about z, the
/// contact touching with force `force(t)` where that is positive.
fn record(
    setting: Setting,
    times: &[f64],
    x: impl Fn(f64) -> f64,
    angle: impl Fn(f64) -> f64,
    force: impl Fn(f64) -> f64,
) -> RunRecord {
    let pose = |t: f64| {
        Isometry3::from_parts(
            nalgebra::Translation3::new(x(t), 0.0, 0.0),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), angle(t)),
        )
    };
    RunRecord {
        setting,
        wall_s: 0.5,
        prepare_s: 0.0,
        simulated_s: 1.0,
        failure: None,
        parts: vec![2],
        contacts: vec!["CONTACT/1".into()],
        times: times.to_vec(),
        part_poses: times.iter().map(|&t| vec![pose(t)]).collect(),
        contact_forces: times.iter().map(|&t| vec![force(t)]).collect(),
        touching: vec![
            times
                .iter()
                .filter(|&&t| force(t) > 0.0)
                .map(|&t| TouchingPose {
                    t,
                    pose_world_i: pose(t),
                    pose_world_j: Isometry3::identity(),
                    penetration: 1e-3,
                    penetration_rate: 0.0,
                    normal_w: Vector3::z(),
                    point_w: Point3::origin(),
                })
                .collect(),
        ],
    }
}

fn faceted(t: f64) -> Setting {
    Setting::faceted(FacetingTolerance::new(t).unwrap())
}

#[test]
fn run_error_counts_the_turn_at_the_contact_radius_and_events_pair_with_the_nearest() {
    let times: Vec<f64> = (0..=10).map(|k| 0.1 * f64::from(k)).collect();
    let scale = ModelScale {
        size: 2.0,
        part_radii: vec![0.5],
    };
    // Reference: touching on [0.3, 0.5]; the candidate also touches at 0.8 (an extra onset),
    // is 0.01 ahead in x and turned 0.1 rad at t = 1.
    let reference = record(
        Setting::EXACT,
        &times,
        |t| t,
        |_| 0.0,
        |t| if (0.25..0.55).contains(&t) { 2.0 } else { 0.0 },
    );
    let candidate = record(
        faceted(100.0),
        &times,
        |t| t + 0.01,
        |t| 0.1 * t,
        |t| {
            if (0.25..0.55).contains(&t) || (0.75..0.85).contains(&t) {
                3.0
            } else {
                0.0
            }
        },
    );
    let row = compare_runs(&reference, &candidate, &scale);
    let expected = (0.01 + 2.0 * 0.5 * (0.05_f64).sin()) / 2.0;
    assert!((row.position_error - expected).abs() < 1e-12, "{row:?}");
    assert!((row.orientation_error_deg - 0.1_f64.to_degrees()).abs() < 1e-9);
    assert_eq!(row.frames_compared, 11);
    assert!((row.wall_ms_per_simulated_s - 500.0).abs() < 1e-9);
    let c = &row.contacts[0];
    assert_eq!((c.onsets, c.reference_onsets), (2, 1));
    assert_eq!((c.releases, c.reference_releases), (2, 1));
    // The extra onset at 0.8 does not shift the pairing of the one at 0.3.
    assert!(c.onset_time_error.unwrap() < 1e-12, "{c:?}");
    assert!(c.release_time_error.unwrap() < 1e-12, "{c:?}");
    assert!((c.peak_force_error.unwrap() - 0.5).abs() < 1e-12);
    // Impulse: trapezoids over 0.1 s frames; 2 N on 3 frames gives 0.6 N·s, 3 N on 3 frames
    // and on 1 more 1.2 N·s.
    assert!((c.impulse - 1.2).abs() < 1e-12, "{c:?}");
    assert!((c.impulse_error.unwrap() - 1.0).abs() < 1e-12, "{c:?}");
    // A run held to itself has no error.
    let own = compare_runs(&reference, &reference, &scale);
    assert_eq!((own.position_error, own.orientation_error_deg), (0.0, 0.0));
    assert!(own.reference);
    assert_eq!(own.contacts[0].peak_force_error, Some(0.0));
}

#[test]
fn select_run_takes_the_faster_of_exact_and_the_smallest_sufficient_tolerance() {
    let row = |setting: Setting, error: f64, ms: f64, failure: Option<&str>| RunRow {
        setting,
        reference: setting == Setting::EXACT,
        failure: failure.map(str::to_string),
        frames_compared: 1,
        position_error: error,
        orientation_error_deg: 0.0,
        wall_ms_per_simulated_s: ms,
        prepare_ms: 0.0,
        within_floor: false,
        contacts: Vec::new(),
    };
    let rows = vec![
        row(Setting::EXACT, 0.0, 100.0, None),
        row(faceted(100.0), 2e-2, 5.0, None),
        row(faceted(1000.0), 4e-3, 9.0, None),
        // Faster but finer: timing noise, never taken over the smaller sufficient tolerance.
        row(faceted(3000.0), 1e-3, 8.0, None),
    ];
    let choice = select_run(&rows, 1e-2).unwrap();
    assert_eq!(choice.setting, faceted(1000.0));
    // A tighter target: only the exact engine (the reference) meets it.
    let choice = select_run(&rows, 1e-4).unwrap();
    assert_eq!(choice.setting, Setting::EXACT);
    assert!(choice.reference);
    // A run that stopped never meets a target; with nothing left, the best completed error.
    let stopped = vec![
        row(faceted(100.0), 0.0, 1.0, Some("diverged")),
        row(faceted(300.0), 5e-2, 2.0, None),
    ];
    let e = select_run(&stopped, 1e-2).unwrap_err();
    assert_eq!(e.best, Some(5e-2));
    assert_eq!(
        e.to_string(),
        "no engine and faceting tolerance meets a run error of 1e-2 (best measured: 5.00e-2)"
    );
}

/// The record of a contact whose penetration grows and shrinks at 1 m/s, touching from `on`
/// to `off` (between output frames 0.1 s apart).
fn timed_contact(setting: Setting, on: f64, off: f64) -> RunRecord {
    let times: Vec<f64> = (0..=10).map(|k| 0.1 * f64::from(k)).collect();
    let mut run = record(
        setting,
        &times,
        |_| 0.0,
        |_| 0.0,
        |t| {
            if (on..=off).contains(&t) { 1.0 } else { 0.0 }
        },
    );
    for p in &mut run.touching[0] {
        // Approaching while nearer the onset, separating while nearer the release.
        let (depth, rate) = if p.t - on < off - p.t {
            (p.t - on, 1.0)
        } else {
            (off - p.t, -1.0)
        };
        p.penetration = depth;
        p.penetration_rate = rate;
    }
    run
}

#[test]
fn onsets_and_releases_are_timed_between_the_output_frames() {
    let scale = ModelScale {
        size: 1.0,
        part_radii: vec![0.0],
    };
    // Touching on [0.27, 0.52] against [0.28, 0.515]: the frames see both at 0.3 and 0.6.
    let reference = timed_contact(Setting::EXACT, 0.27, 0.52);
    let candidate = timed_contact(faceted(100.0), 0.28, 0.515);
    let c = &compare_runs(&reference, &candidate, &scale).contacts[0];
    assert_eq!((c.onsets, c.reference_onsets), (1, 1));
    assert!((c.onset_time_error.unwrap() - 0.01).abs() < 1e-12, "{c:?}");
    assert!(
        (c.release_time_error.unwrap() - 0.005).abs() < 1e-12,
        "{c:?}"
    );
}
