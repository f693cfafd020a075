//! `contact run MODEL.adm [MODEL.acf]`: reads, checks and lowers a dataset, runs its dynamics,
//! streams results into `--out`, and prints a summary with the engine that ran.

use crate::dataset::{self, Severity};
use crate::engine_choice::{self, Overrides};
use crate::model::{Analysis as ModelAnalysis, Command, Model, OutputSteps, SimulationSpan};
use crate::run::lower::{LoweredModel, lower};
use crate::run::output::ResultWriter;
use crate::run::progress::RunProgress;
use crate::solver::bdf::{Corrector, IntegratorSettings};
use crate::solver::contact_force::Analysis;
use crate::solver::simulate::{DynamicsSettings, RunSummary, simulate_with_progress};
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
    let (settings, notes) = match dynamics_settings(model, args) {
        Ok(s) => s,
        Err(message) => {
            writeln!(err, "error: {message}")?;
            return Ok(1);
        }
    };
    for note in notes {
        writeln!(err, "note: {note}")?;
    }
    let engine = engine_choice::build_engine(selection.library, selection.faceting_tolerance);
    let prepare_started = Instant::now();
    let meshes = |file: &crate::model::MeshFile| -> Result<GeometryInstance, String> {
        let stl = engine_facet::stl::read_stl(&file.path, false).map_err(|e| e.to_string())?;
        let mut instance =
            GeometryInstance::new(contact_core::Geometry::Mesh(std::sync::Arc::new(stl.mesh)))
                .at(file.pose_part_geometry)
                .labeled(file.label.clone());
        instance.flip_normal = file.flip_normal;
        instance.faceting_tolerance = file.faceting_tolerance;
        Ok(instance)
    };
    let LoweredModel {
        mut system,
        contacts,
        parts,
        ..
    } = match lower(model, engine.as_ref(), Analysis::Dynamics, &meshes) {
        Ok(l) => l,
        Err(e) => {
            writeln!(err, "{e}")?;
            return Ok(1);
        }
    };
    let prepare_s = prepare_started.elapsed().as_secs_f64();
    let threads = args
        .threads
        .or(model.preferences.threads.map(|n| n.get()))
        .unwrap_or(1);
    match crate::solver::parallel::Parallelism::with_threads(threads) {
        Ok(p) => system.set_parallelism(p),
        Err(e) => {
            writeln!(err, "error: --threads {threads}: {e}")?;
            return Ok(1);
        }
    }
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
    let mut writer = ResultWriter::create(&dir, parts, names)?;
    let started = Instant::now();
    let mut write_error = None;
    let mut progress = RunProgress::for_stderr(args.quiet);
    let result = simulate_with_progress(
        &mut system,
        &contacts,
        &settings,
        &mut |frame| {
            writer
                .write(frame)
                .inspect_err(|e| write_error = Some(e.to_string()))
        },
        &mut |p| progress.update(p),
    );
    let wall = started.elapsed().as_secs_f64();
    progress.finish();
    let mut work = WorkCounters::default();
    for c in &contacts {
        work += c.work();
    }
    let simulated = settings.end - settings.start;
    let (status, summary) = match &result {
        Ok(summary) => ("completed".to_string(), *summary),
        Err(e) => (format!("failed: {e}"), RunSummary::default()),
    };
    let report = json!({
        "model": args.model.display().to_string(),
        "engine": selection.library.name(),
        "engine_source": selection.library_source.to_string(),
        "threads": threads,
        "faceting_tolerance": (selection.library == GeometryLibrary::Faceted).then_some(selection.faceting_tolerance.value()),
        "status": status,
        "start": settings.start,
        "end": settings.end,
        "wall_time_s": wall,
        "wall_ms_per_simulated_s": 1e3 * wall / simulated,
        "prepare_s": prepare_s,
        "steps": summary.integrator.steps,
        "rejected_steps": summary.integrator.rejected(),
        "rejected_for_contact_onset": summary.rejected_for_contact_onset,
        "largest_entry_penetration": summary.largest_entry_penetration,
        "newton_iterations": summary.integrator.newton_iterations,
        "jacobian_evaluations": summary.integrator.jacobian_evaluations,
        "lu_factorizations": summary.integrator.lu_factorizations,
        "output_frames": summary.frames,
        "engine_work": {
            "queries": work.queries, "geometry_pairs": work.geometry_pairs,
            "bounding_volume_tests": work.bounding_volume_tests, "primitive_tests": work.primitive_tests,
            "iterations": work.iterations, "contacts": work.contacts,
        },
    });
    let files = writer.finish(&report)?;
    match result {
        Ok(summary) => {
            writeln!(
                out,
                "ran {simulated} s of dynamics in {:.1} ms wall ({:.2} ms per simulated s): {} steps, {} rejected ({} at contact onsets), {} Jacobians; largest entry penetration {:e}",
                1e3 * wall,
                1e3 * wall / simulated,
                summary.integrator.steps,
                summary.integrator.rejected(),
                summary.rejected_for_contact_onset,
                summary.integrator.jacobian_evaluations,
                summary.largest_entry_penetration
            )?;
            writeln!(
                out,
                "results in {}/ (parts.csv, contacts.csv, frames.jsonl, summary.json, contact_force.svg, penetration.svg)",
                writer.dir().display()
            )?;
            Ok(0)
        }
        Err(e) => {
            writeln!(err, "error: the run stopped: {e}")?;
            if let Some(w) = write_error {
                writeln!(err, "error: writing results: {w}")?;
            }
            writeln!(
                err,
                "results up to the failure are in {} ({} files)",
                writer.dir().display(),
                files.len() + 3
            )?;
            Ok(1)
        }
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

/// The dynamics span and integrator settings from the command file's SIMULATE commands (or
/// the flags), with notes on anything interpreted.
fn dynamics_settings(
    model: &Model,
    args: &RunArgs,
) -> Result<(DynamicsSettings, Vec<String>), String> {
    let mut notes = Vec::new();
    let mut integrator = convert(&model.integrator)?;
    let mut end = None;
    let mut output = None;
    let mut time = 0.0;
    for (origin, command) in &model.commands {
        match command {
            Command::Integrator(s) => integrator = convert(s)?,
            Command::Simulate {
                analysis,
                span,
                output: steps,
            } => {
                match analysis {
                    ModelAnalysis::Dynamics | ModelAnalysis::Transient => {}
                    other => {
                        return Err(format!(
                            "{origin}: SIMULATE/{other:?} is not supported yet: only dynamics runs"
                        ));
                    }
                }
                let stop = match span {
                    Some(SimulationSpan::End(t)) => *t,
                    Some(SimulationSpan::Duration(d)) => time + d,
                    None => return Err(format!("{origin}: SIMULATE needs END or DURATION")),
                };
                if end.is_some() {
                    notes.push(format!(
                        "{origin}: consecutive SIMULATE commands run as one span to END = {stop}"
                    ));
                }
                time = stop;
                end = Some(stop);
                output = output.or(*steps);
            }
            Command::Stop => break,
            other => notes.push(format!(
                "{origin}: {other:?} is not applied by this solver yet: it is ignored"
            )),
        }
    }
    let end = args
        .end
        .or(end)
        .ok_or("no END: give --end (or a command file with SIMULATE/DYNAMICS, END = …)")?;
    let output_step = match (args.dtout, args.steps, output) {
        (Some(dt), _, _) => dt,
        (None, Some(n), _) => end / f64::from(n.max(1)),
        (None, None, Some(OutputSteps::Interval(dt))) => dt,
        (None, None, Some(OutputSteps::Steps(n))) => end / f64::from(n.max(1)),
        (None, None, None) => {
            notes.push("no DTOUT or STEPS: writing 100 output steps".into());
            end / 100.0
        }
    };
    Ok((
        DynamicsSettings {
            start: 0.0,
            end,
            output_step,
            integrator,
        },
        notes,
    ))
}

fn convert(s: &crate::model::IntegratorSettings) -> Result<IntegratorSettings, String> {
    let corrector = match s.corrector.as_deref() {
        None | Some("MODIFIED") => Corrector::Modified,
        Some("ORIGINAL") | Some("FULL") => Corrector::Full,
        Some(other) => {
            return Err(format!(
                "INTEGRATOR/CORRECTOR = {other} is not supported (ORIGINAL or MODIFIED)"
            ));
        }
    };
    let settings = IntegratorSettings {
        error: s.error,
        hmax: s.hmax,
        hmin: s.hmin,
        hinit: s.hinit,
        kmax: s.kmax as usize,
        maxit: s.maxit as usize,
        corrector,
    };
    settings
        .validate()
        .map_err(|e| format!("INTEGRATOR: {e}"))?;
    Ok(settings)
}
