//! `contact run MODEL.adm [MODEL.acf]`: reads, checks and lowers a dataset, runs the command
//! file's analyses in order (dynamics, kinematics, statics, initial conditions, LINEAR
//! eigenvalues: see [`crate::run::plan`]), streams every frame into `--out` (and the
//! eigenvalues into `eigenvalues.csv`/`.json`, [`crate::run::eigenvalues`]), and prints a
//! summary line per analysis with the engine that ran.

use crate::dataset::{self, Severity};
use crate::engine_choice::{self, Overrides};
use crate::run::eigenvalues::{self, EigenvalueFiles};
use crate::run::lower::{LoweredModel, lower};
use crate::run::output::ResultWriter;
use crate::run::plan::{AnalysisStep, PlanOverrides, plan_analyses};
use crate::run::progress::RunProgress;
use crate::solver::contact_force::Analysis;
use crate::solver::frame::compute_frame;
use crate::solver::kinematics::{KinematicsSettings, initial_degrees_of_freedom, run_kinematics};
use crate::solver::linear::linearize;
use crate::solver::mbs::PartState;
use crate::solver::simulate::{DynamicsSettings, Frame, RunSummary, simulate_with_progress};
use crate::solver::statics::solve_statics;
use contact_core::{FacetingTolerance, GeometryInstance, GeometryLibrary, WorkCounters};
use serde_json::json;
use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;

/// The arguments of `contact run`.
#[derive(Debug, Clone, PartialEq, clap::Args)]
pub struct RunArgs {
    /// The Adams dataset (.adm).
    pub model: PathBuf,
    /// Its command file (.acf): its SIMULATE commands say what to run.
    pub commands: Option<PathBuf>,
    /// The geometry engine: exact or faceted (or an Adams name); overrides PREFERENCES and
    /// the environment.
    #[arg(long)]
    pub engine: Option<String>,
    /// The model-wide faceting tolerance (> 0); overrides PREFERENCES and MDI_FACETING_TOLERANCE.
    #[arg(long)]
    pub faceting_tolerance: Option<f64>,
    /// End time (without a command file, or to override its last END).
    #[arg(long)]
    pub end: Option<f64>,
    /// Time between output steps.
    #[arg(long, conflicts_with = "steps")]
    pub dtout: Option<f64>,
    /// Number of output steps.
    #[arg(long)]
    pub steps: Option<u32>,
    /// The directory results go to (default `out/<model name>`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Threads evaluating contacts and forces (default PREFERENCES/NTHREADS, else 1); the
    /// results are the same bits at every count.
    #[arg(long)]
    pub threads: Option<usize>,
    /// No progress bar (it is drawn on stderr only when stderr is a terminal).
    #[arg(long, short)]
    pub quiet: bool,
}

/// Runs the command; returns the process exit code (0 success, 1 failure). Problems go to
/// `err`, the summary to `out`.
pub fn run(args: &RunArgs, out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<u8> {
    let loaded = match dataset::read(&args.model, args.commands.as_deref()) {
        Ok(loaded) => loaded,
        Err(e) => {
            writeln!(err, "error: {e}")?;
            return Ok(1);
        }
    };
    for d in &loaded.diagnostics {
        writeln!(err, "{d}")?;
    }
    if loaded
        .diagnostics
        .iter()
        .any(|d| d.severity == Severity::Error)
    {
        writeln!(err, "the model has errors: nothing was run")?;
        return Ok(1);
    }
    let model = &loaded.model;
    let overrides = match overrides(args) {
        Ok(o) => o,
        Err(message) => {
            writeln!(err, "error: {message}")?;
            return Ok(1);
        }
    };
    let selection = match engine_choice::resolve(
        &overrides,
        &|k| std::env::var(k).ok(),
        Some(&model.preferences),
    ) {
        Ok(s) => s,
        Err(e) => {
            writeln!(err, "error: {e}")?;
            return Ok(1);
        }
    };
    writeln!(out, "{selection}")?;
    let threads = args
        .threads
        .or(model.preferences.threads.map(|n| n.get()))
        .unwrap_or(1);
    let parallelism = match crate::solver::parallel::Parallelism::with_threads(threads) {
        Ok(p) => p,
        Err(e) => {
            writeln!(err, "error: --threads {threads}: {e}")?;
            return Ok(1);
        }
    };
    let engine = engine_choice::build_engine(selection.library, selection.faceting_tolerance);
    let meshes = |file: &crate::model::MeshFile| -> Result<GeometryInstance, String> {
        let geometry =
            contact_core::mesh_file::read_mesh_geometry(&file.path).map_err(|e| e.to_string())?;
        let mut instance = GeometryInstance::new(geometry)
            .at(file.pose_part_geometry)
            .labeled(file.label.clone());
        instance.flip_normal = file.flip_normal;
        instance.faceting_tolerance = file.faceting_tolerance;
        Ok(instance)
    };
    let plan = PlanOverrides {
        end: args.end,
        dtout: args.dtout,
        steps: args.steps,
    };
    // SIMULATE/TRANSIENT chooses its analysis by the degrees of freedom of the constraints,
    // which the lowered multibody system knows.
    let mut transient_dof = |t: f64| -> Result<usize, String> {
        let lowered = lower(model, engine.as_ref(), Analysis::Quasistatic, &meshes)
            .map_err(|e| e.to_string())?;
        initial_degrees_of_freedom(&lowered.system, t).map_err(|e| e.to_string())
    };
    let (steps, notes) = match plan_analyses(model, plan, &mut transient_dof) {
        Ok(s) => s,
        Err(message) => {
            writeln!(err, "error: {message}")?;
            return Ok(1);
        }
    };
    for note in notes {
        writeln!(err, "note: {note}")?;
    }
    // Friction that acts in dynamics only needs the model lowered for the analysis at hand;
    // the state passes from one lowering to the next through the parts' states.
    let mut prepare_s = 0.0;
    let mut lower_for = |analysis: Analysis| -> Result<LoweredModel, String> {
        let started = Instant::now();
        let mut lowered =
            lower(model, engine.as_ref(), analysis, &meshes).map_err(|e| e.to_string())?;
        lowered.system.set_parallelism(parallelism.clone());
        prepare_s += started.elapsed().as_secs_f64();
        Ok(lowered)
    };
    let first_analysis = solver_analysis(&steps[0]);
    let mut current = match lower_for(first_analysis) {
        Ok(l) => (first_analysis, l),
        Err(e) => {
            writeln!(err, "{e}")?;
            return Ok(1);
        }
    };
    let dir = args.out.clone().unwrap_or_else(|| {
        PathBuf::from("out").join(
            args.model
                .file_stem()
                .map_or_else(|| "model".into(), |s| s.to_string_lossy().into_owned()),
        )
    });
    let names: Vec<String> = model
        .contacts
        .iter()
        .map(|c| format!("CONTACT/{}", c.id))
        .collect();
    let mut sink = FrameSink {
        writer: ResultWriter::create(&dir, current.1.parts.clone(), names)?,
        last_t: None,
        skip_repeat: false,
        carried: None,
        write_error: None,
        frames: 0,
        eigenvalues: EigenvalueFiles::default(),
    };
    let started = Instant::now();
    let mut work = WorkCounters::default();
    let mut totals = DynamicsTotals::default();
    let mut reports = Vec::new();
    let mut lines = Vec::new();
    let mut failure = None;
    for step in &steps {
        let analysis = solver_analysis(step);
        if analysis != current.0 {
            for c in &current.1.contacts {
                work += c.work();
            }
            match lower_for(analysis) {
                Ok(l) => current = (analysis, l),
                Err(e) => {
                    failure = Some(e);
                    break;
                }
            }
        }
        let lowered = &mut current.1;
        sink.skip_repeat = matches!(
            step,
            AnalysisStep::Dynamics { .. } | AnalysisStep::Kinematics { .. }
        );
        if let Some(parts) = &sink.carried {
            lowered.system.start_from(parts);
        }
        let outcome = run_step(step, lowered, &mut sink, &mut totals, args.quiet);
        reports.push(outcome.report);
        match outcome.result {
            Ok(line) => lines.push(line),
            Err(e) => {
                failure = Some(format!("SIMULATE/{}: {e}", step.name()));
                break;
            }
        }
    }
    for c in &current.1.contacts {
        work += c.work();
    }
    let wall = started.elapsed().as_secs_f64();
    let (start, end) = span_of(&steps);
    let simulated = end - start;
    let status = match &failure {
        None => "completed".to_string(),
        Some(e) => format!("failed: {e}"),
    };
    let report = json!({
        "model": args.model.display().to_string(),
        "engine": selection.library.name(),
        "engine_source": selection.library_source.to_string(),
        "threads": threads,
        "faceting_tolerance": (selection.library == GeometryLibrary::Faceted).then_some(selection.faceting_tolerance.value()),
        "status": status,
        "start": start,
        "end": end,
        "wall_time_s": wall,
        "wall_ms_per_simulated_s": (simulated > 0.0).then(|| 1e3 * wall / simulated),
        "prepare_s": prepare_s,
        "analyses": reports,
        "steps": totals.steps,
        "rejected_steps": totals.rejected,
        "rejected_for_contact_onset": totals.rejected_for_contact_onset,
        "largest_entry_penetration": totals.largest_entry_penetration,
        "newton_iterations": totals.newton_iterations,
        "jacobian_evaluations": totals.jacobian_evaluations,
        "lu_factorizations": totals.lu_factorizations,
        "output_frames": sink.frames,
        "engine_work": {
            "queries": work.queries, "geometry_pairs": work.geometry_pairs,
            "bounding_volume_tests": work.bounding_volume_tests, "primitive_tests": work.primitive_tests,
            "iterations": work.iterations, "contacts": work.contacts,
        },
    });
    let files = sink.writer.finish(&report)?;
    for line in &lines {
        writeln!(out, "{line}")?;
    }
    match failure {
        None => {
            let linear = if sink.eigenvalues.is_empty() {
                ""
            } else {
                ", eigenvalues.csv, eigenvalues.json"
            };
            writeln!(
                out,
                "results in {}/ (parts.csv, contacts.csv, frames.jsonl, summary.json, contact_force.svg, penetration.svg{linear})",
                sink.writer.dir().display()
            )?;
            Ok(0)
        }
        Some(e) => {
            writeln!(err, "error: the run stopped: {e}")?;
            if let Some(w) = sink.write_error {
                writeln!(err, "error: writing results: {w}")?;
            }
            writeln!(
                err,
                "results up to the failure are in {} ({} files)",
                sink.writer.dir().display(),
                files.len() + 3
            )?;
            Ok(1)
        }
    }
}

/// The contact analysis mode a step's model is lowered for (LINEAR linearizes the equations
/// of motion, where DYNAMICS_ONLY friction acts).
fn solver_analysis(step: &AnalysisStep) -> Analysis {
    match step {
        AnalysisStep::Dynamics { .. } | AnalysisStep::Linear { .. } => Analysis::Dynamics,
        _ => Analysis::Quasistatic,
    }
}

/// The first and last time of the run.
fn span_of(steps: &[AnalysisStep]) -> (f64, f64) {
    let times = |step: &AnalysisStep| match *step {
        AnalysisStep::Dynamics { start, end, .. } | AnalysisStep::Kinematics { start, end, .. } => {
            (start, end)
        }
        AnalysisStep::Statics { t, .. }
        | AnalysisStep::InitialConditions { t }
        | AnalysisStep::Linear { t, .. } => (t, t),
    };
    let start = steps.first().map_or(0.0, |s| times(s).0);
    let end = steps.iter().map(|s| times(s).1).fold(start, f64::max);
    (start, end)
}

/// Frames into the result files. A timed analysis (dynamics, kinematics) that starts where the
/// previous one wrote its last frame does not write its first frame again; an equilibrium or
/// initial-conditions frame is always written. The last frame's part states start the next
/// analysis.
struct FrameSink {
    writer: ResultWriter,
    last_t: Option<f64>,
    skip_repeat: bool,
    carried: Option<Vec<PartState>>,
    write_error: Option<String>,
    frames: u64,
    eigenvalues: EigenvalueFiles,
}

impl FrameSink {
    fn write(&mut self, frame: &Frame) -> std::io::Result<()> {
        self.carried = Some(frame.parts.clone());
        if self.skip_repeat && self.last_t == Some(frame.t) {
            return Ok(());
        }
        self.last_t = Some(frame.t);
        self.frames += 1;
        let written = self.writer.write(frame);
        if let Err(e) = &written {
            self.write_error = Some(e.to_string());
        }
        written
    }
}

/// What one analysis did: its summary line or its failure, and its part of `summary.json`.
struct StepOutcome {
    result: Result<String, String>,
    report: serde_json::Value,
}

/// Runs one analysis on `lowered`, writing its frames into `sink`.
fn run_step(
    step: &AnalysisStep,
    lowered: &mut LoweredModel,
    sink: &mut FrameSink,
    totals: &mut DynamicsTotals,
    quiet: bool,
) -> StepOutcome {
    let started = Instant::now();
    let LoweredModel {
        system, contacts, ..
    } = lowered;
    let (result, mut report) = match *step {
        AnalysisStep::Dynamics {
            start,
            end,
            output_step,
            integrator,
            ..
        } => {
            let settings = DynamicsSettings {
                start,
                end,
                output_step,
                integrator,
            };
            let mut progress = RunProgress::for_stderr(quiet);
            let result = simulate_with_progress(
                system,
                contacts,
                &settings,
                &mut |frame| sink.write(frame),
                &mut |p| progress.update(p),
            );
            progress.finish();
            let wall = started.elapsed().as_secs_f64();
            match result {
                Ok(summary) => {
                    totals.add(&summary);
                    let simulated = end - start;
                    (
                        Ok(format!(
                            "ran {simulated} s of dynamics in {:.1} ms wall ({:.2} ms per simulated s): {} steps, {} rejected ({} at contact onsets), {} Jacobians; largest entry penetration {:e}",
                            1e3 * wall,
                            1e3 * wall / simulated,
                            summary.integrator.steps,
                            summary.integrator.rejected(),
                            summary.rejected_for_contact_onset,
                            summary.integrator.jacobian_evaluations,
                            summary.largest_entry_penetration
                        )),
                        json!({"start": start, "end": end, "steps": summary.integrator.steps,
                               "rejected_steps": summary.integrator.rejected(),
                               "newton_iterations": summary.integrator.newton_iterations}),
                    )
                }
                Err(e) => (Err(e.to_string()), json!({"start": start, "end": end})),
            }
        }
        AnalysisStep::Kinematics {
            start,
            end,
            output_step,
            ..
        } => {
            let settings = KinematicsSettings {
                start,
                end,
                output_step,
            };
            let result = run_kinematics(system, contacts, &settings, &mut |frame, _| {
                sink.write(frame)
            });
            match result {
                Ok(summary) => (
                    Ok(format!(
                        "ran kinematics from t = {start} to {end} in {:.1} ms wall: {} frames, {} Newton iterations on the positions",
                        1e3 * started.elapsed().as_secs_f64(),
                        summary.frames,
                        summary.iterations
                    )),
                    json!({"start": start, "end": end, "newton_iterations": summary.iterations}),
                ),
                Err(e) => (Err(e.to_string()), json!({"start": start, "end": end})),
            }
        }
        AnalysisStep::Statics { t, settings } => {
            let y = system.given_state().clone();
            match solve_statics(system, t, &y, &settings) {
                Ok(found) => {
                    let written = compute_frame(system, contacts, t, &found.y)
                        .map_err(|e| e.to_string())
                        .and_then(|frame| sink.write(&frame).map_err(|e| e.to_string()));
                    let report = json!({"t": t, "method": found.method.to_string(),
                        "newton_iterations": found.iterations, "imbalance": found.imbalance});
                    let line = format!(
                        "static equilibrium at t = {t} by {} in {:.1} ms wall: {} Newton iterations, final imbalance {:e}",
                        found.method,
                        1e3 * started.elapsed().as_secs_f64(),
                        found.iterations,
                        found.imbalance
                    );
                    (written.map(|()| line), report)
                }
                Err(e) => (Err(e.to_string()), json!({"t": t})),
            }
        }
        AnalysisStep::InitialConditions { t } => {
            let written = system
                .compute_initial_state(t)
                .map_err(|e| e.to_string())
                .and_then(|initial| {
                    compute_frame(system, contacts, t, &initial.y).map_err(|e| e.to_string())
                })
                .and_then(|frame| sink.write(&frame).map_err(|e| e.to_string()));
            (
                written.map(|()| format!("initial conditions at t = {t} written")),
                json!({"t": t}),
            )
        }
        AnalysisStep::Linear { t, settings } => {
            // The state reached so far, assembled and with consistent velocities (the
            // multipliers are solved for by the linearization itself).
            let mut y = system.given_state().clone();
            let linear = system
                .assemble(t, &mut y)
                .and_then(|_| system.project_velocities(t, &mut y))
                .map_err(|e| e.to_string())
                .and_then(|()| linearize(system, t, &y, &settings).map_err(|e| e.to_string()));
            match linear {
                Ok(linear) => {
                    let dir = sink.writer.dir().to_path_buf();
                    let written = sink
                        .eigenvalues
                        .record(&dir, &linear, settings.damping)
                        .map_err(|e| e.to_string());
                    let wall_ms = 1e3 * started.elapsed().as_secs_f64();
                    let report = json!({"t": t, "degrees_of_freedom": linear.degrees_of_freedom,
                        "damping": settings.damping, "eigenvalues": linear.eigenvalues.len(),
                        "unstable": eigenvalues::unstable(&linear),
                        "files": ["eigenvalues.csv", "eigenvalues.json"]});
                    (
                        written.map(|_| eigenvalues::summary_line(&linear, wall_ms)),
                        report,
                    )
                }
                Err(e) => (Err(e), json!({"t": t})),
            }
        }
    };
    let result = match step.transient() {
        Some(choice) => result.map(|line| format!("{choice}; {line}")),
        None => result,
    };
    if let Some(fields) = report.as_object_mut() {
        fields.insert("analysis".into(), json!(step.name()));
        if let Some(choice) = step.transient() {
            fields.insert("requested".into(), json!("TRANSIENT"));
            fields.insert(
                "degrees_of_freedom".into(),
                json!(choice.degrees_of_freedom),
            );
            fields.insert("reason".into(), json!(choice.to_string()));
        }
        let status = match &result {
            Ok(_) => "completed".to_string(),
            Err(e) => format!("failed: {e}"),
        };
        fields.insert("status".into(), json!(status));
    }
    StepOutcome { result, report }
}

/// The counters of every dynamics analysis of a run, added up.
#[derive(Debug, Clone, Copy, Default)]
struct DynamicsTotals {
    steps: u64,
    rejected: u64,
    rejected_for_contact_onset: u64,
    largest_entry_penetration: f64,
    newton_iterations: u64,
    jacobian_evaluations: u64,
    lu_factorizations: u64,
}

impl DynamicsTotals {
    /// Adds one dynamics analysis.
    fn add(&mut self, summary: &RunSummary) {
        let s = &summary.integrator;
        self.steps += s.steps;
        self.rejected += s.rejected();
        self.rejected_for_contact_onset += summary.rejected_for_contact_onset;
        self.largest_entry_penetration = self
            .largest_entry_penetration
            .max(summary.largest_entry_penetration);
        self.newton_iterations += s.newton_iterations;
        self.jacobian_evaluations += s.jacobian_evaluations;
        self.lu_factorizations += s.lu_factorizations;
    }
}

fn overrides(args: &RunArgs) -> Result<Overrides, String> {
    let library = args
        .engine
        .as_deref()
        .map(GeometryLibrary::parse)
        .transpose()
        .map_err(|e| format!("--engine: {e}"))?;
    let faceting_tolerance = args
        .faceting_tolerance
        .map(FacetingTolerance::new)
        .transpose()
        .map_err(|e| format!("--faceting-tolerance: {e}"))?;
    Ok(Overrides {
        library,
        faceting_tolerance,
    })
}
