//! [`run_model`]: the engine chosen, the analyses planned, the model lowered, the analyses run
//! in order.

use super::analysis::{FrameFilter, run_analysis};
use super::error::{RunError, RunFailure};
use super::report::{AnalysisOutcome, DynamicsTotals, RunReport};
use super::{RunLayout, RunOptions, RunSink};
use crate::dataset::Diagnostic;
use crate::engine_choice::{self, Overrides};
use crate::model::{MeshFile, Model};
use crate::run::active::{FrameMap, Inactive};
use crate::run::lower::{LowerError, LoweredModel, lower};
use crate::run::plan::{AnalysisStep, DegreesOfFreedomError, PlanOverrides, RunPlan, plan_run};
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
    let plan = plan(model, options, &lowering, sink)?;
    let steps = &plan.steps;
    let Some(first) = steps.first() else {
        return Err(RunError::NoAnalysis);
    };
    // The whole model, lowered for the first analysis: its layout (parts, CONTACTs,
    // constraints) is the output's, whatever is switched off.
    let first_analysis = solver_analysis(first);
    let whole = lowering.lower(first_analysis, &Inactive::default())?;
    sink.diagnostics(&redundancy_warnings(model, &whole.system))
        .map_err(RunError::Output)?;
    let contacts: Vec<String> = model
        .contacts
        .iter()
        .map(|c| format!("CONTACT/{}", c.id))
        .collect();
    let requests = request_output(model, source, &whole, sink)?;
    sink.start(&RunLayout {
        parts: &whole.parts,
        contacts: &contacts,
        analyses: steps,
        requests: requests.as_ref(),
    })
    .map_err(RunError::Output)?;
    let (start, end) = span_of(steps);
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
    let current = Current {
        analysis: first_analysis,
        inactive: Inactive::default(),
        map: None,
        lowered: whole,
    };
    run_analyses(&plan, &mut lowering, current, sink, &mut report);
    report.wall = started.elapsed();
    report.prepare = lowering.prepare;
    sink.finish(&report).map_err(RunError::Output)?;
    if report.completed() {
        Ok(report)
    } else {
        Err(RunError::Stopped(Box::new(report)))
    }
}

/// The model as lowered for the analysis at hand.
struct Current {
    /// The analysis mode it was lowered for.
    analysis: Analysis,
    /// The elements left out.
    inactive: Inactive,
    /// Its frames in the whole model's layout (`None`: nothing is left out).
    map: Option<FrameMap>,
    /// The model on the solver.
    lowered: LoweredModel,
}

/// Runs the plan's steps in order from `current` (the whole model lowered for the first),
/// lowering it again when the analysis mode or the elements switched off change; records each
/// analysis, the totals and the first failure in `report`.
fn run_analyses(
    plan: &RunPlan,
    lowering: &mut Lowering<'_>,
    mut current: Current,
    sink: &mut dyn RunSink,
    report: &mut RunReport,
) {
    let mut filter = FrameFilter::default();
    let whole: Vec<String> = current
        .lowered
        .system
        .constraint_rows()
        .map(|(name, _)| name.to_string())
        .collect();
    for (step, inactive) in plan.steps.iter().zip(&plan.inactive) {
        let analysis = solver_analysis(step);
        if analysis != current.analysis || *inactive != current.inactive {
            for c in &current.lowered.contacts {
                report.engine_work += c.work();
            }
            match lowering.lower(analysis, inactive) {
                Ok(lowered) => {
                    let names: Vec<&str> =
                        lowered.system.constraint_rows().map(|(n, _)| n).collect();
                    let map = FrameMap::new(
                        lowering.model,
                        inactive,
                        whole.iter().map(String::as_str),
                        &names,
                    );
                    if *inactive != current.inactive {
                        sink.elements_switched(inactive);
                    }
                    current = Current {
                        analysis,
                        inactive: inactive.clone(),
                        map,
                        lowered,
                    };
                }
                Err(e) => {
                    report.failure = Some(RunFailure::Lower(e));
                    break;
                }
            }
        }
        let lowered = &mut current.lowered;
        filter.skip_repeat = matches!(
            step,
            AnalysisStep::Dynamics { .. } | AnalysisStep::Kinematics { .. }
        );
        filter.map = current.map.clone();
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
    for c in &current.lowered.contacts {
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
    /// The model without the `inactive` elements, lowered for `analysis` (friction that acts
    /// in dynamics only needs the model lowered for the analysis at hand; the state passes
    /// from one lowering to the next through the parts' states).
    fn lower(
        &mut self,
        analysis: Analysis,
        inactive: &Inactive,
    ) -> Result<LoweredModel, LowerError> {
        let started = Instant::now();
        let read = |f: &MeshFile| read_mesh(f, self.tolerance, self.engine);
        let mut lowered = if inactive.is_empty() {
            lower(self.model, self.engine, analysis, &read)?
        } else {
            lower(&inactive.apply(self.model), self.engine, analysis, &read)?
        };
        lowered.system.set_parallelism(self.parallelism.clone());
        lowered.system.set_output_dynamics(self.output_dynamics);
        self.prepare += started.elapsed();
        Ok(lowered)
    }

    /// The model's degrees of freedom without the `inactive` elements at time `t`
    /// (SIMULATE/TRANSIENT chooses its analysis by them, which the lowered multibody system
    /// knows).
    fn degrees_of_freedom(
        &self,
        t: f64,
        inactive: &Inactive,
    ) -> Result<usize, DegreesOfFreedomError> {
        let read = |f: &MeshFile| read_mesh(f, self.tolerance, self.engine);
        let model = inactive.apply(self.model);
        let lowered = lower(&model, self.engine, Analysis::Quasistatic, &read).map_err(Box::new)?;
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
    let read = |f: &MeshFile| read_mesh(f, FacetingTolerance::DEFAULT, engine);
    match lower(model, engine, Analysis::Dynamics, &read) {
        Ok(lowered) => redundancy_diagnostics(model, &lowered.system, t),
        Err(_) => Vec::new(),
    }
}

/// A mesh file (STL, OBJ, a Parasolid body tessellated at the model-wide `tolerance` unless
/// its GRAPHICS gives one) as a geometry on its part; for the exact engine, a Parasolid body
/// that is exactly one of its primitives is that primitive.
fn read_mesh(
    file: &MeshFile,
    tolerance: FacetingTolerance,
    engine: &dyn GeometryEngine,
) -> Result<GeometryInstance, String> {
    if engine.name() == "exact" {
        if let Some(instance) = crate::parasolid_bodies::exact_instance(file) {
            return Ok(instance);
        }
    }
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
) -> Result<RunPlan, RunError> {
    let overrides = PlanOverrides {
        end: options.end,
        dtout: options.dtout,
        steps: options.steps,
    };
    let mut plan = plan_run(model, overrides, &mut |t, inactive| {
        lowering.degrees_of_freedom(t, inactive)
    })?;
    if let Some(scale) = options.integrator_error_scale {
        if !(scale.is_finite() && scale > 0.0 && scale <= 1.0) {
            return Err(RunError::ErrorScale { scale });
        }
        for step in &mut plan.steps {
            if let AnalysisStep::Dynamics { integrator, .. } = step {
                integrator.error *= scale;
            }
        }
    }
    for note in &plan.notes {
        sink.note(note).map_err(RunError::Output)?;
    }
    Ok(plan)
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
