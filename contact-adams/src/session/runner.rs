//! [`run_model`]: the engine chosen, the analyses planned, the model lowered, the analyses run
//! in order.

use super::analysis::{FrameFilter, run_analysis};
use super::error::{RunError, RunFailure};
use super::report::{AnalysisOutcome, DynamicsTotals, RunReport};
use super::{RunLayout, RunOptions, RunSink};
use crate::dataset::Diagnostic;
use crate::engine_choice::{self, Overrides};
use crate::model::{MeshFile, Model};
use crate::run::lower::{LowerError, LoweredModel, lower};
use crate::run::plan::{AnalysisStep, DegreesOfFreedomError, PlanOverrides, plan_analyses};
use crate::run::redundancy::{redundancy_diagnostics, redundancy_warnings};
use crate::run::request_file::{RequestOutput, units_tag};
use crate::run::requests::RequestSet;
use contact_core::{FacetingTolerance, GeometryEngine, GeometryInstance, WorkCounters};
use contact_solver::contact_force::Analysis;
use contact_solver::kinematics::initial_degrees_of_freedom;
use contact_solver::parallel::{MAX_THREADS, Parallelism};
use std::path::Path;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Runs `model`'s analyses (read from `source`, which the report names) with `options`,
/// delivering its results to `sink` (see the [module docs](super)).
pub fn run_model(
    model: &Model,
    source: &Path,
    options: &RunOptions,
    sink: &mut dyn RunSink,
) -> Result<RunReport, RunError> {
    if !model.has_moving_part() {
        return Err(RunError::NoMovingPart {
            cr_only: model.lines_end_in_cr_only(),
        });
    }
    let overrides = Overrides {
        library: options.engine,
        faceting_tolerance: options.faceting_tolerance,
    };
    let selection = engine_choice::resolve(
        &overrides,
        &|k| std::env::var(k).ok(),
        model.engine_preferences,
    )?;
    sink.engine(&selection).map_err(RunError::Output)?;
    let (threads, by) = match (options.threads, model.preferences.threads) {
        (Some(n), _) => (n, "--threads"),
        (None, Some(n)) => (n.get(), "PREFERENCES/NTHREADS"),
        (None, None) => (1, "the default"),
    };
    if !(1..=MAX_THREADS).contains(&threads) {
        return Err(RunError::ThreadCount { threads, by });
    }
    let parallelism = Parallelism::with_threads(threads).map_err(|source| RunError::Threads {
        threads,
        by,
        source,
    })?;
    let engine = engine_choice::build_engine(selection.library, selection.faceting_tolerance);
    let mut lowering = Lowering {
        model,
        engine: engine.as_ref(),
        parallelism,
        tolerance: selection.faceting_tolerance,
        prepare: Duration::ZERO,
        output_dynamics: !model.requests.is_empty(),
    };
    let steps = plan(model, options, &lowering, sink)?;
    let Some(first) = steps.first() else {
        return Err(RunError::NoAnalysis);
    };
    let first_analysis = solver_analysis(first);
    let current = (first_analysis, lowering.lower(first_analysis)?);
    sink.diagnostics(&redundancy_warnings(model, &current.1.system))
        .map_err(RunError::Output)?;
    let contacts: Vec<String> = model
        .contacts
        .iter()
        .map(|c| format!("CONTACT/{}", c.id))
        .collect();
    let requests = request_output(model, source, &current.1, sink)?;
    sink.start(&RunLayout {
        parts: &current.1.parts,
        contacts: &contacts,
        analyses: &steps,
        requests: requests.as_ref(),
    })
    .map_err(RunError::Output)?;
    let (start, end) = span_of(&steps);
    let mut report = RunReport {
        model: source.to_path_buf(),
        selection,
        threads,
        analyses: Vec::new(),
        failure: None,
        start,
        end,
        wall: Duration::ZERO,
        prepare: Duration::ZERO,
        dynamics: DynamicsTotals::default(),
        output_frames: 0,
        engine_work: WorkCounters::default(),
    };
    let started = Instant::now();
    run_analyses(&steps, &mut lowering, current, sink, &mut report);
    report.wall = started.elapsed();
    report.prepare = lowering.prepare;
    sink.finish(&report).map_err(RunError::Output)?;
    if report.completed() {
        Ok(report)
    } else {
        Err(RunError::Stopped(Box::new(report)))
    }
}

/// Runs `steps` in order from `current` (the model lowered for the first), lowering it again
/// when the analysis mode changes; records each analysis, the totals and the first failure in
/// `report`.
fn run_analyses(
    steps: &[AnalysisStep],
    lowering: &mut Lowering<'_>,
    mut current: (Analysis, LoweredModel),
    sink: &mut dyn RunSink,
    report: &mut RunReport,
) {
    let mut filter = FrameFilter::default();
    for step in steps {
        let analysis = solver_analysis(step);
        if analysis != current.0 {
            for c in &current.1.contacts {
                report.engine_work += c.work();
            }
            match lowering.lower(analysis) {
                Ok(l) => current = (analysis, l),
                Err(e) => {
                    report.failure = Some(RunFailure::Lower(e));
                    break;
                }
            }
        }
        let lowered = &mut current.1;
        filter.skip_repeat = matches!(
            step,
            AnalysisStep::Dynamics { .. } | AnalysisStep::Kinematics { .. }
        );
        if let Some(parts) = &filter.carried {
            lowered.system.start_from(parts);
        }
        let analysis_report = run_analysis(step, lowered, &mut filter, sink);
        if let Some(AnalysisOutcome::Dynamics(summary)) = &analysis_report.outcome {
            report.dynamics.add(summary);
        }
        let error = analysis_report.error.clone();
        report.analyses.push(analysis_report);
        if let Some(error) = error {
            report.failure = Some(RunFailure::Analysis {
                analysis: step.name(),
                error,
            });
            break;
        }
    }
    for c in &current.1.contacts {
        report.engine_work += c.work();
    }
    report.output_frames = filter.frames;
}

/// The model lowered for one analysis mode at a time, on one engine.
struct Lowering<'a> {
    model: &'a Model,
    engine: &'a dyn GeometryEngine,
    parallelism: Parallelism,
    /// The model-wide faceting tolerance (Parasolid bodies are tessellated at it).
    tolerance: FacetingTolerance,
    /// Wall time spent lowering so far.
    prepare: Duration,
    /// Whether frames carry accelerations and reactions (the model has REQUESTs).
    output_dynamics: bool,
}

impl Lowering<'_> {
    /// The model lowered for `analysis` (friction that acts in dynamics only needs the model
    /// lowered for the analysis at hand; the state passes from one lowering to the next
    /// through the parts' states).
    fn lower(&mut self, analysis: Analysis) -> Result<LoweredModel, LowerError> {
        let started = Instant::now();
        let read = |f: &MeshFile| read_mesh(f, self.tolerance);
        let mut lowered = lower(self.model, self.engine, analysis, &read)?;
        lowered.system.set_parallelism(self.parallelism.clone());
        lowered.system.set_output_dynamics(self.output_dynamics);
        self.prepare += started.elapsed();
        Ok(lowered)
    }

    /// The model's degrees of freedom at time `t` (SIMULATE/TRANSIENT chooses its analysis by
    /// them, which the lowered multibody system knows).
    fn degrees_of_freedom(&self, t: f64) -> Result<usize, DegreesOfFreedomError> {
        let read = |f: &MeshFile| read_mesh(f, self.tolerance);
        let lowered =
            lower(self.model, self.engine, Analysis::Quasistatic, &read).map_err(Box::new)?;
        Ok(initial_degrees_of_freedom(&lowered.system, t)?)
    }
}

/// The model's REQUESTs ready to write (`None` when it has none), with a note when
/// `OUTPUT/REQSAVE` is absent: Adams then writes no `.req` file, and neither does this run.
fn request_output(
    model: &Model,
    source: &Path,
    lowered: &LoweredModel,
    sink: &mut dyn RunSink,
) -> Result<Option<RequestOutput>, RunError> {
    if model.requests.is_empty() {
        return Ok(None);
    }
    let variables = model
        .variables
        .iter()
        .map(|v| (v.id, v.function.clone()))
        .collect();
    let set = RequestSet::new(
        model,
        lowered.system.constraint_rows().map(|(name, _)| name),
        lowered.markers.clone(),
        Arc::new(variables),
    );
    let stem = source
        .file_stem()
        .map_or_else(|| "model".into(), |s| s.to_string_lossy().into_owned());
    let reqsave = model.output_flags.contains(&"REQSAVE");
    let file_name = format!("{stem}.req");
    if !reqsave {
        sink.note(&format!(
            "no OUTPUT/REQSAVE: {file_name} is not written (as Adams writes none); the {} REQUESTs go to requests.csv",
            model.requests.len()
        ))
        .map_err(RunError::Output)?;
    }
    Ok(Some(RequestOutput {
        set,
        title: model.title.clone(),
        units_tag: units_tag(&model.units),
        reqsave,
        file_name,
    }))
}

/// What `contact check` says of the model's constraints: the equations found redundant at the
/// initial configuration (warnings at their statements) and an inconsistent redundancy (an
/// error naming the joints), from the model lowered with `engine` as `contact run` lowers it
/// for dynamics (meshes at the default faceting tolerance: the constraints do not depend on
/// it), assembled at `t`. A model that does not lower gives nothing here: `contact run`
/// reports why.
pub fn check_constraints(model: &Model, engine: &dyn GeometryEngine, t: f64) -> Vec<Diagnostic> {
    let read = |f: &MeshFile| read_mesh(f, FacetingTolerance::DEFAULT);
    match lower(model, engine, Analysis::Dynamics, &read) {
        Ok(lowered) => redundancy_diagnostics(model, &lowered.system, t),
        Err(_) => Vec::new(),
    }
}

/// A mesh file (STL, OBJ, a Parasolid body tessellated at the model-wide `tolerance` unless
/// its GRAPHICS gives one) as a geometry on its part.
fn read_mesh(file: &MeshFile, tolerance: FacetingTolerance) -> Result<GeometryInstance, String> {
    let geometry = crate::parasolid_bodies::mesh_geometry(file, tolerance)?;
    let mut instance = GeometryInstance::new(geometry)
        .at(file.pose_part_geometry)
        .labeled(file.label.clone());
    instance.flip_normal = file.flip_normal;
    instance.faceting_tolerance = file.faceting_tolerance;
    Ok(instance)
}

/// The analyses of the run, its notes delivered to `sink`.
fn plan(
    model: &Model,
    options: &RunOptions,
    lowering: &Lowering<'_>,
    sink: &mut dyn RunSink,
) -> Result<Vec<AnalysisStep>, RunError> {
    let overrides = PlanOverrides {
        end: options.end,
        dtout: options.dtout,
        steps: options.steps,
    };
    let (steps, notes) = plan_analyses(model, overrides, &mut |t| lowering.degrees_of_freedom(t))?;
    for note in notes {
        sink.note(&note).map_err(RunError::Output)?;
    }
    Ok(steps)
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
