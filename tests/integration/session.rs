//! The library entry point (`contact::session`): what a sink receives and in which order, the
//! report, and the typed errors — the same run `contact run` makes, without the CLI.

use contact::dataset::Diagnostic;
use contact::engine_choice::{EngineSelection, Source};
use contact::run::plan::AnalysisStep;
use contact::session::{
    AnalysisError, AnalysisReport, RunError, RunFailure, RunLayout, RunOptions, RunReport, RunSink,
    run_files,
};
use contact::solver::linear::Linearization;
use contact::solver::simulate::Frame;
use contact_core::GeometryLibrary;
use std::path::PathBuf;

fn example(path: &str) -> PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(path)
}

/// Every callback as a line, frames as their time.
#[derive(Debug, Default)]
struct Recorder {
    events: Vec<String>,
    diagnostics: usize,
}

impl RunSink for Recorder {
    fn diagnostics(&mut self, diagnostics: &[Diagnostic]) -> std::io::Result<()> {
        self.diagnostics += diagnostics.len();
        Ok(())
    }
    fn engine(&mut self, selection: &EngineSelection) -> std::io::Result<()> {
        self.events
            .push(format!("engine {}", selection.library.name()));
        Ok(())
    }
    fn start(&mut self, layout: &RunLayout<'_>) -> std::io::Result<()> {
        self.events.push(format!(
            "start {} parts {} contacts {} analyses",
            layout.parts.len(),
            layout.contacts.len(),
            layout.analyses.len()
        ));
        Ok(())
    }
    fn analysis_started(&mut self, step: &AnalysisStep) {
        self.events.push(format!("started {}", step.name()));
    }
    fn frame(&mut self, frame: &Frame) -> std::io::Result<()> {
        self.events.push(format!("frame {}", frame.t));
        Ok(())
    }
    fn eigenvalues(&mut self, linear: &Linearization, _damping: bool) -> std::io::Result<()> {
        self.events
            .push(format!("eigenvalues {}", linear.eigenvalues.len()));
        Ok(())
    }
    fn analysis_finished(&mut self, report: &AnalysisReport) {
        self.events.push(format!(
            "finished {} {}",
            report.step.name(),
            report.completed()
        ));
    }
    fn finish(&mut self, report: &RunReport) -> std::io::Result<()> {
        self.events
            .push(format!("finish {}", report.analyses.len()));
        Ok(())
    }
}

#[test]
fn a_sink_sees_the_engine_the_layout_each_analysis_its_frames_and_the_end_in_order() {
    let mut sink = Recorder::default();
    let options = RunOptions {
        engine: Some(GeometryLibrary::Exact),
        end: Some(0.02),
        steps: Some(2),
        ..RunOptions::default()
    };
    let report = run_files(
        &example("box_rest/box_rest.adm"),
        Some(&example("box_rest/box_rest.acf")),
        &options,
        &mut sink,
    )
    .unwrap();
    // Statics at t = 0, then dynamics from 0: its first frame repeats the equilibrium's time
    // and is not delivered again.
    assert_eq!(
        sink.events,
        [
            "engine exact",
            "start 1 parts 1 contacts 2 analyses",
            "started STATICS",
            "frame 0",
            "finished STATICS true",
            "started DYNAMICS",
            "frame 0.01",
            "frame 0.02",
            "finished DYNAMICS true",
            "finish 2",
        ]
    );
    assert!(report.completed());
    assert_eq!(report.output_frames, 3);
    assert_eq!(report.selection.library_source, Source::Override);
    assert_eq!((report.start, report.end), (0.0, 0.02));
    assert!(report.dynamics.steps > 0);
    let lines: Vec<String> = report
        .analyses
        .iter()
        .filter_map(AnalysisReport::summary_line)
        .collect();
    assert!(
        lines[0].starts_with("static equilibrium at t = 0 by "),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("ran 0.02 s of dynamics in "),
        "{lines:?}"
    );
    assert_eq!(report.to_json()["analyses"][1]["analysis"], "DYNAMICS");
}

#[test]
fn a_linear_analysis_delivers_its_eigenvalues() {
    let mut sink = Recorder::default();
    let report = run_files(
        &example("ball_rest_linear/ball_rest_linear.adm"),
        Some(&example("ball_rest_linear/ball_rest_linear.acf")),
        &RunOptions::default(),
        &mut sink,
    )
    .unwrap();
    let eigenvalues = sink
        .events
        .iter()
        .filter(|e| e.starts_with("eigenvalues"))
        .count();
    assert_eq!(eigenvalues, 2, "{:?}", sink.events);
    assert_eq!(report.analyses.len(), 3);
}

#[test]
fn a_failing_analysis_stops_the_run_with_its_report_and_a_typed_error() {
    let dir = std::env::temp_dir().join(format!("contact-session-fail-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (adm, acf) = (dir.join("falling.adm"), dir.join("falling.acf"));
    std::fs::write(
        &adm,
        "falling part\nPART/1, GROUND\nMARKER/10, PART = 1\n\
         PART/2, MASS = 1, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2\n\
         ACCGRAV/ KGRAV = -9.81\nEND\n",
    )
    .unwrap();
    std::fs::write(
        &acf,
        "falling.adm\nfalling\nSIMULATE/DYNAMICS, END = 0.1, DTOUT = 0.01\nSIMULATE/STATICS\nSTOP\n",
    )
    .unwrap();
    let mut sink = Recorder::default();
    let error = run_files(&adm, Some(&acf), &RunOptions::default(), &mut sink).unwrap_err();
    assert_eq!(sink.diagnostics, 1, "the missing UNITS warning");
    let RunError::Stopped(report) = &error else {
        panic!("{error}");
    };
    let Some(RunFailure::Analysis {
        analysis,
        error: cause,
    }) = &report.failure
    else {
        panic!("{:?}", report.failure);
    };
    assert_eq!(*analysis, "STATICS");
    assert!(matches!(**cause, AnalysisError::Statics(_)), "{cause:?}");
    assert!(
        error
            .to_string()
            .starts_with("the run stopped: SIMULATE/STATICS: statics did not converge"),
        "{error}"
    );
    // The dynamics' 11 frames were delivered, and the sink was told the run ended.
    assert_eq!(report.output_frames, 11);
    assert_eq!(sink.events.last().map(String::as_str), Some("finish 2"));
    assert!(report.analyses[0].completed() && !report.analyses[1].completed());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_dataset_with_errors_runs_nothing() {
    let dir = std::env::temp_dir().join(format!("contact-session-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let adm = dir.join("bad.adm");
    std::fs::write(&adm, "bad\nPART/1, GROUND\nMARKER/1, PART = 7\nEND\n").unwrap();
    let mut sink = Recorder::default();
    let error = run_files(&adm, None, &RunOptions::default(), &mut sink).unwrap_err();
    assert!(matches!(error, RunError::ModelErrors), "{error}");
    assert_eq!(error.to_string(), "the model has errors: nothing was run");
    assert_eq!(sink.diagnostics, 2);
    assert!(sink.events.is_empty(), "{:?}", sink.events);
    let missing = run_files(
        &dir.join("missing.adm"),
        None,
        &RunOptions::default(),
        &mut sink,
    )
    .unwrap_err();
    assert!(matches!(missing, RunError::Dataset(_)), "{missing}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Two SIMULATE commands keep their own END and output step; the second starts where the
/// first ended, whose last frame is not written twice. Without PREFERENCES the engine is the
/// default, and the report says so.
#[test]
fn each_simulate_writes_at_its_own_output_step() {
    let adm = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/adams-tests/Revolute_Case02/test_Revolute_Case02.adm");
    let dir = std::env::temp_dir().join(format!("contact-spans-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let acf = dir.join("spans.acf");
    std::fs::write(
        &acf,
        "test_Revolute_Case02.adm\nspans\nsimulate/dynamics, end = 0.02, dtout = 0.01\n\
         simulate/dynamics, end = 0.023, dtout = 0.001\nstop\n",
    )
    .unwrap();
    let mut sink = Recorder::default();
    let report = run_files(&adm, Some(&acf), &RunOptions::default(), &mut sink).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let frames: Vec<String> = sink
        .events
        .iter()
        .filter_map(|e| e.strip_prefix("frame "))
        .map(|t| format!("{:.4}", t.parse::<f64>().unwrap()))
        .collect();
    assert_eq!(
        frames,
        ["0.0000", "0.0100", "0.0200", "0.0210", "0.0220", "0.0230"]
    );
    assert_eq!(report.analyses.len(), 2);
    assert_eq!(report.selection.library_source, Source::Default);
}

/// A factor on the integrator ERROR tightens every dynamic analysis (more steps for the same
/// span); one out of `(0, 1]` is refused before anything runs, naming its range.
#[test]
fn an_integrator_error_scale_tightens_the_dynamics_and_is_range_checked() {
    let run = |scale: Option<f64>| {
        let options = RunOptions {
            engine: Some(GeometryLibrary::Exact),
            end: Some(0.5),
            integrator_error_scale: scale,
            ..RunOptions::default()
        };
        run_files(
            &example("ball/ball.adm"),
            None,
            &options,
            &mut Recorder::default(),
        )
    };
    let own = run(None).unwrap().dynamics.steps;
    let tight = run(Some(1e-2)).unwrap().dynamics.steps;
    assert!(
        tight > own,
        "{tight} steps at 1e-2 × ERROR, {own} at the model's"
    );
    for bad in [0.0, -1e-3, 1.5, f64::NAN] {
        let e = run(Some(bad)).unwrap_err();
        assert!(
            matches!(e, RunError::ErrorScale { .. }) && e.to_string().contains("(0, 1]"),
            "{bad}: {e}"
        );
    }
}
