//! The trade on the examples' own motion: the reference run's touching poses are measured
//! (geneva_primitives' pin on its slot walls, which the old approach-direction poses never
//! reached), the per-query recommendations keep their kind (the exact engine on the ball, the
//! faceted engine on the cam's curves), the reference run held to itself has no error, and
//! the other candidates' run errors fall as the faceting tolerance rises. Runs are cut short
//! (`end`) to keep the debug build's test time modest.

use contact::engine_choice::build_engine;
use contact::model::Model;
use contact::tradeoff::{self, RunRecord, RunTrade, Setting, Sweep, Timing};
use contact_core::{FacetingTolerance, GeometryLibrary};
use std::path::{Path, PathBuf};

/// The run error the reference runs are converged to: `contact select`'s goal for a target of
/// 1e-2 of the model's size.
const GOAL: f64 = 1e-2 * contact::cli::select::RUN_FLOOR_GOAL;

fn sweep(tolerances: &[f64]) -> Sweep {
    Sweep {
        tolerances: tolerances
            .iter()
            .map(|&t| FacetingTolerance::new(t).unwrap())
            .collect(),
        timing: Timing {
            rounds: 1,
            min_sample_ns: 0,
        },
    }
}

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name)
        .join(format!("{name}.adm"))
}

/// The example (with the command file beside it) and its reference run up to `end`.
fn reference(name: &str, tolerances: &[f64], end: f64) -> (Model, PathBuf, RunRecord) {
    let path = example(name);
    let model = contact::cli::select::load_with_commands(&path, None).unwrap();
    let exact = build_engine(GeometryLibrary::Exact, FacetingTolerance::DEFAULT);
    let run = tradeoff::record_reference(
        &model,
        &path,
        exact.as_ref(),
        &sweep(tolerances).tolerances,
        Some(end),
    )
    .unwrap();
    (model, path, run)
}

/// The reference run held to itself has no error at all; returns the candidates' run errors
/// by rising tolerance after checking that each run completed.
fn faceted_run_errors(trade: &RunTrade) -> Vec<f64> {
    let reference = trade.rows.iter().find(|r| r.reference).unwrap();
    assert_eq!(reference.setting, Setting::EXACT);
    assert_eq!(reference.position_error, 0.0);
    assert_eq!(reference.orientation_error_deg, 0.0);
    for c in &reference.contacts {
        assert!(c.peak_force_error.is_none_or(|e| e == 0.0), "{c:?}");
        assert!(c.impulse_error.is_none_or(|e| e == 0.0), "{c:?}");
        assert_eq!(c.onsets, c.reference_onsets);
        assert!(c.onset_time_error.is_none_or(|e| e == 0.0), "{c:?}");
        assert!(c.release_time_error.is_none_or(|e| e == 0.0), "{c:?}");
    }
    let faceted: Vec<_> = trade.rows.iter().filter(|r| !r.reference).collect();
    assert!(faceted.iter().all(|r| r.failure.is_none()), "{faceted:?}");
    assert!(
        faceted
            .iter()
            .all(|r| r.frames_compared == reference.frames_compared)
    );
    faceted.iter().map(|r| r.position_error).collect()
}

#[test]
fn geneva_primitives_measures_its_pin_on_the_slot_walls() {
    let tolerances = [100.0, 1000.0, 10000.0];
    let (model, _, run) = reference("geneva_primitives", &tolerances, 0.6);
    assert_eq!(run.setting, Setting::EXACT);
    assert!(run.failure.is_none());
    let touching = run.touching[0].len();
    assert!(
        touching > 10,
        "the pin touches the slot walls in 0.6 s: {touching} frames"
    );
    // The per-query trade at the run's poses: resolved contacts, and a faceted error that is
    // measured, not 0.
    let selection = tradeoff::select_for_model(
        &model,
        &run,
        &sweep(&tolerances),
        &build_engine,
        &[],
        0.05,
        &mut |_| {},
    )
    .unwrap();
    assert_eq!(selection.contacts, ["CONTACT/1"]);
    assert!(selection.untouched.is_empty());
    let rows = &selection.report.records;
    let exact = rows.iter().find(|r| r.engine == "exact").unwrap();
    assert_eq!(exact.poses, 2 * touching.min(50));
    assert!(exact.resolved_contacts > 0, "{exact:?}");
    let coarse = rows
        .iter()
        .find(|r| r.faceting_tolerance == Some(100.0))
        .unwrap();
    assert!(coarse.depth_error.unwrap() > 1e-3, "{coarse:?}");
    // The engines' difference at every tolerance is within the pin's chord deviation (one
    // faceting band, relative to the contact's size as the depth error is).
    for r in rows.iter().filter(|r| r.engine == "faceted") {
        let band = r.resolved_depth / tradeoff::RESOLVED_BANDS;
        assert!(r.depth_error.unwrap() <= band, "{r:?}");
    }
    let held = tradeoff::compare_runs(&run, &run, &tradeoff::model_scale(&model, &run).unwrap());
    assert_eq!(held.position_error, 0.0);
}

/// The whole 2 s run, both engagements, over the default sweep: at the model's own ERROR
/// (1e-4) the pin's bounces in the slot make the integrator's error larger than any engine's
/// difference (the reference itself moves by more than 1e-2 of the model's size), so the
/// runs are compared where the reference has converged, and there the faceted runs' errors
/// fall at every step of the tolerance.
#[test]
fn geneva_primitives_whole_runs_converge_once_the_reference_has() {
    let tolerances = [100.0, 300.0028, 1000.0, 3000.0, 10000.0];
    let path = example("geneva_primitives");
    let model = contact::cli::select::load_with_commands(&path, None).unwrap();
    let exact = build_engine(GeometryLibrary::Exact, FacetingTolerance::DEFAULT);
    let run = tradeoff::record_reference(
        &model,
        &path,
        exact.as_ref(),
        &sweep(&tolerances).tolerances,
        None,
    )
    .unwrap();
    let trade = tradeoff::trade_runs(
        &model,
        &path,
        &run,
        &sweep(&tolerances).tolerances,
        None,
        GOAL,
        &mut |_| {},
    )
    .unwrap();
    let integration = &trade.integration;
    assert!(integration.converged, "{integration:?}");
    assert!(integration.floor.unwrap() <= GOAL, "{integration:?}");
    assert!(integration.error_scale < 1.0, "{integration:?}");
    assert!(integration.at_model_error > 1e-2, "{integration:?}");
    let errors = faceted_run_errors(&trade);
    assert!(
        errors.windows(2).all(|w| w[1] < w[0]),
        "run errors by rising FT: {errors:?}"
    );
    assert!(errors[0] > 1e-3, "{errors:?}");
    // The coarsest tolerances are resolved: well above the floor.
    let rows: Vec<_> = trade.rows.iter().filter(|r| !r.reference).collect();
    assert!(!rows[0].within_floor && !rows[1].within_floor, "{rows:?}");
    // A target only the finest candidates meet picks one of them.
    let choice = tradeoff::select_run(&trade.rows, 1e-5).unwrap();
    assert!(
        choice.setting == Setting::EXACT || choice.setting.faceting_tolerance >= Some(3000.0),
        "{choice:?}"
    );
}

#[test]
fn cam_follower_keeps_the_faceted_recommendation_and_converges_over_whole_runs() {
    let tolerances = [100.0, 300.0028, 1000.0, 3000.0, 10000.0];
    // The whole run: one turn of the cam.
    let (model, path, run) = reference("cam_follower", &tolerances, 1.0);
    assert_eq!(run.setting, Setting::EXACT);
    // The roller never leaves the cam: every frame touches.
    assert_eq!(run.touching[0].len(), run.times.len());
    // On curves the exact engine iterates (hundreds of µs in a debug build) where the
    // polylines answer in tens: the faceted engine at its smallest tolerance, as before.
    let selection = tradeoff::select_for_model(
        &model,
        &run,
        &sweep(&[100.0, 1000.0]),
        &build_engine,
        &[],
        0.01,
        &mut |_| {},
    )
    .unwrap();
    let r = selection.recommendation.unwrap();
    assert_eq!(
        (r.model.engine.as_str(), r.model.faceting_tolerance),
        ("faceted", Some(100.0))
    );
    let trade = tradeoff::trade_runs(
        &model,
        &path,
        &run,
        &sweep(&tolerances).tolerances,
        Some(1.0),
        GOAL,
        &mut |_| {},
    )
    .unwrap();
    assert!(trade.integration.converged, "{:?}", trade.integration);
    let errors = faceted_run_errors(&trade);
    assert!(
        errors.windows(2).all(|w| w[1] < w[0]),
        "run errors by rising FT: {errors:?}"
    );
    assert!(!trade.rows[1].within_floor, "{:?}", trade.rows[1]);
}

#[test]
fn ball_keeps_the_exact_recommendation_and_its_faceted_runs_agree_to_round_off() {
    let tolerances = [100.0, 1000.0];
    let (model, path, run) = reference("ball", &tolerances, 0.6);
    assert_eq!(run.setting, Setting::EXACT);
    assert!(!run.touching[0].is_empty(), "the ball lands within 0.6 s");
    let selection = tradeoff::select_for_model(
        &model,
        &run,
        &sweep(&[100.0]),
        &build_engine,
        &[],
        0.01,
        &mut |_| {},
    )
    .unwrap();
    let r = selection.recommendation.unwrap();
    assert_eq!(r.model.engine, "exact");
    let trade = tradeoff::trade_runs(
        &model,
        &path,
        &run,
        &sweep(&tolerances).tolerances,
        Some(0.6),
        GOAL,
        &mut |_| {},
    )
    .unwrap();
    // The faceted engine answers a sphere on a plane with the smooth sphere's support point,
    // so its runs match the exact one to round-off at every tolerance: nothing left to fall.
    let errors = faceted_run_errors(&trade);
    assert!(errors.iter().all(|&e| e < 1e-12), "{errors:?}");
    let bounce = &trade.rows[1].contacts[0];
    assert_eq!(bounce.onsets, bounce.reference_onsets);
    assert!(bounce.peak_force_error.unwrap() < 1e-9, "{bounce:?}");
    // Over the whole 2 s the step sequences part at round-off and the runs then differ by the
    // integrator's error: every faceted run is within the converged reference's floor, which
    // the report says rather than ranking them.
    let (model, path, run) = reference("ball", &tolerances, 2.0);
    let trade = tradeoff::trade_runs(
        &model,
        &path,
        &run,
        &sweep(&tolerances).tolerances,
        Some(2.0),
        GOAL,
        &mut |_| {},
    )
    .unwrap();
    assert!(trade.integration.converged, "{:?}", trade.integration);
    let faceted: Vec<_> = trade.rows.iter().filter(|r| !r.reference).collect();
    assert!(faceted.iter().all(|r| r.within_floor), "{faceted:?}");
}

#[test]
fn select_and_tradeoff_commands_write_the_run_trade_and_measure_at_the_run_poses() {
    let dir = std::env::temp_dir().join(format!("contact-select-runs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let args = contact::cli::select::SelectArgs {
        model: example("cam_follower"),
        commands: None,
        end: Some(0.3),
        max_depth_error: None,
        max_run_error: Some(1e-2),
        tolerances: vec![100.0, 1000.0],
        rounds: Some(1),
        json: Some(dir.join("select.json")),
        csv: Some(dir.join("runs.csv")),
        plot: Some(dir.join("runs.svg")),
    };
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code =
        contact::cli::select::run(&args, &build_engine, &mut out, &mut err, &mut |_| {}).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert_eq!(code, 0, "{text}{}", String::from_utf8_lossy(&err));
    assert!(text.contains("whole runs against the exact run"), "{text}");
    assert!(text.contains("model (whole runs): "), "{text}");
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("select.json")).unwrap()).unwrap();
    assert_eq!(doc["reference_run"]["engine"], "exact");
    assert!(doc.get("per_query").is_none());
    let rows = doc["runs"]["trade"]["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    for row in rows {
        for field in [
            "engine",
            "faceting_tolerance",
            "reference",
            "failure",
            "frames_compared",
            "position_error",
            "orientation_error_deg",
            "wall_ms_per_simulated_s",
            "prepare_ms",
            "contacts",
        ] {
            assert!(row.get(field).is_some(), "{field} missing: {row}");
        }
    }
    assert!(doc["runs"]["recommendation"]["engine"].is_string());
    let csv = std::fs::read_to_string(dir.join("runs.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 3, "{csv}");
    assert!(
        std::fs::read_to_string(dir.join("runs.svg"))
            .unwrap()
            .starts_with("<svg")
    );
    // No target at all is refused before anything runs.
    let none = contact::cli::select::SelectArgs {
        max_run_error: None,
        ..args
    };
    let mut err = Vec::new();
    let code =
        contact::cli::select::run(&none, &build_engine, &mut Vec::new(), &mut err, &mut |_| {})
            .unwrap();
    assert_eq!(code, 1);
    assert!(String::from_utf8(err).unwrap().contains("--max-run-error"));
    // `contact tradeoff MODEL.adm` measures at the reference run's poses too.
    let args = contact::cli::tradeoff::TradeoffArgs {
        model: Some(example("geneva_primitives")),
        end: Some(0.6),
        tolerances: vec![300.0028],
        rounds: Some(1),
        ..Default::default()
    };
    let mut out = Vec::new();
    let report =
        contact::cli::tradeoff::run(&args, &build_engine, &[], &mut out, &mut |_| {}).unwrap();
    let faceted = report
        .records
        .iter()
        .find(|r| r.engine == "faceted")
        .unwrap();
    assert!(faceted.depth_error.unwrap() > 1e-3, "{faceted:?}");
}
