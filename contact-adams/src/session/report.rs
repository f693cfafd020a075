//! What a run did: per analysis ([`AnalysisReport`]) and in all ([`RunReport`]), with the
//! summary lines `contact run` prints and the `summary.json` it writes.

use super::error::{AnalysisError, RunFailure};
use crate::engine_choice::EngineSelection;
use crate::run::eigenvalues;
use crate::run::plan::AnalysisStep;
use contact_core::{GeometryLibrary, WorkCounters};
use contact_solver::kinematics::{KinematicsError, KinematicsSummary};
use contact_solver::linear::Linearization;
use contact_solver::simulate::{RunSummary, SimulationError};
use contact_solver::statics::Equilibrium;
use serde_json::{Value, json};
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

/// Whether `error` is the sink refusing a frame with [`std::io::ErrorKind::Interrupted`].
fn is_interruption(error: &AnalysisError) -> bool {
    let io = match error {
        AnalysisError::Output(e)
        | AnalysisError::Dynamics(SimulationError::Output { source: e, .. })
        | AnalysisError::Kinematics(KinematicsError::Output { source: e, .. }) => e,
        _ => return false,
    };
    io.kind() == std::io::ErrorKind::Interrupted
}

/// What a completed analysis computed.
#[derive(Debug, Clone, PartialEq)]
pub enum AnalysisOutcome {
    /// Dynamics: the integrator's counters.
    Dynamics(RunSummary),
    /// Kinematics: frames and Newton iterations.
    Kinematics(KinematicsSummary),
    /// Statics: the equilibrium found.
    Statics(Equilibrium),
    /// Initial conditions: the frame was delivered.
    InitialConditions,
    /// LINEAR/EIGENSOL: the linearization and its eigenvalues.
    Linear(Linearization),
}

/// One analysis of a run.
#[derive(Debug)]
pub struct AnalysisReport {
    /// The analysis as planned.
    pub step: AnalysisStep,
    /// What it computed (`None` when it failed before computing it).
    pub outcome: Option<AnalysisOutcome>,
    /// Why it failed (`None` when it completed).
    pub error: Option<Arc<AnalysisError>>,
    /// Its wall time.
    pub wall: Duration,
}

impl AnalysisReport {
    /// Whether the analysis completed.
    pub fn completed(&self) -> bool {
        self.error.is_none() && self.outcome.is_some()
    }

    /// The line `contact run` prints for a completed analysis (`None` if it failed), e.g.
    /// `ran 2 s of dynamics in 80.1 ms wall (40.05 ms per simulated s): …`; a TRANSIENT's
    /// line starts with its choice.
    pub fn summary_line(&self) -> Option<String> {
        if self.error.is_some() {
            return None;
        }
        let wall_ms = 1e3 * self.wall.as_secs_f64();
        let line = match (&self.step, self.outcome.as_ref()?) {
            (&AnalysisStep::Dynamics { start, end, .. }, AnalysisOutcome::Dynamics(summary)) => {
                let simulated = end - start;
                format!(
                    "ran {simulated} s of dynamics in {wall_ms:.1} ms wall ({:.2} ms per simulated s): {} steps, {} rejected ({} at contact onsets), {} Jacobians; largest entry penetration {:e}",
                    wall_ms / simulated,
                    summary.integrator.steps,
                    summary.integrator.rejected(),
                    summary.rejected_for_contact_onset,
                    summary.integrator.jacobian_evaluations,
                    summary.largest_entry_penetration
                ) + &broad_phase_note(summary)
            }
            (&AnalysisStep::Kinematics { start, end, .. }, AnalysisOutcome::Kinematics(s)) => {
                format!(
                    "ran kinematics from t = {start} to {end} in {wall_ms:.1} ms wall: {} frames, {} Newton iterations on the positions",
                    s.frames, s.iterations
                )
            }
            (&AnalysisStep::Statics { t, .. }, AnalysisOutcome::Statics(found)) => format!(
                "static equilibrium at t = {t} by {} in {wall_ms:.1} ms wall: {} Newton iterations, final imbalance {:e}",
                found.method, found.iterations, found.imbalance
            ),
            (&AnalysisStep::InitialConditions { t }, AnalysisOutcome::InitialConditions) => {
                format!("initial conditions at t = {t} written")
            }
            (AnalysisStep::Linear { .. }, AnalysisOutcome::Linear(linear)) => {
                eigenvalues::summary_line(linear, wall_ms)
            }
            _ => return None,
        };
        Some(match self.step.transient() {
            Some(choice) => format!("{choice}; {line}"),
            None => line,
        })
    }

    /// The analysis's entry in `summary.json`'s `analyses`.
    pub fn to_json(&self) -> Value {
        let mut report = match (&self.step, &self.outcome) {
            (
                &AnalysisStep::Dynamics { start, end, .. },
                Some(AnalysisOutcome::Dynamics(summary)),
            ) => json!({"start": start, "end": end, "steps": summary.integrator.steps,
                        "rejected_steps": summary.integrator.rejected(),
                        "newton_iterations": summary.integrator.newton_iterations}),
            (
                &AnalysisStep::Kinematics { start, end, .. },
                Some(AnalysisOutcome::Kinematics(s)),
            ) => {
                json!({"start": start, "end": end, "newton_iterations": s.iterations})
            }
            (&AnalysisStep::Statics { t, .. }, Some(AnalysisOutcome::Statics(found))) => {
                json!({"t": t, "method": found.method.to_string(),
                       "newton_iterations": found.iterations, "imbalance": found.imbalance})
            }
            (&AnalysisStep::Linear { t, settings }, Some(AnalysisOutcome::Linear(linear))) => {
                json!({"t": t, "degrees_of_freedom": linear.degrees_of_freedom,
                       "damping": settings.damping, "eigenvalues": linear.eigenvalues.len(),
                       "unstable": eigenvalues::unstable(linear),
                       "files": ["eigenvalues.csv", "eigenvalues.json"]})
            }
            (
                &(AnalysisStep::Dynamics { start, end, .. }
                | AnalysisStep::Kinematics { start, end, .. }),
                _,
            ) => json!({"start": start, "end": end}),
            (
                &(AnalysisStep::Statics { t, .. }
                | AnalysisStep::InitialConditions { t }
                | AnalysisStep::Linear { t, .. }),
                _,
            ) => json!({"t": t}),
        };
        if let Some(fields) = report.as_object_mut() {
            fields.insert("analysis".into(), json!(self.step.name()));
            if let Some(choice) = self.step.transient() {
                fields.insert("requested".into(), json!("TRANSIENT"));
                fields.insert(
                    "degrees_of_freedom".into(),
                    json!(choice.degrees_of_freedom),
                );
                fields.insert("reason".into(), json!(choice.to_string()));
            }
            let status = match &self.error {
                None => "completed".to_string(),
                Some(e) if is_interruption(e) => "interrupted".to_string(),
                Some(e) => format!("failed: {e}"),
            };
            fields.insert("status".into(), json!(status));
        }
        report
    }
}

/// `; broad phase skipped S of N force-element evaluations (P %)` when it skipped any, else
/// empty (the line of a model without far contacts is unchanged).
fn broad_phase_note(summary: &RunSummary) -> String {
    let (evaluated, skipped) = (summary.broad_phase_evaluated, summary.broad_phase_skipped);
    if skipped == 0 {
        return String::new();
    }
    let all = evaluated + skipped;
    format!(
        "; broad phase skipped {skipped} of {all} force-element evaluations ({:.1} %)",
        100.0 * skipped as f64 / all as f64
    )
}

/// The counters of every dynamics analysis of a run, added up.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct DynamicsTotals {
    /// Accepted integrator steps.
    pub steps: u64,
    /// Rejected integrator steps.
    pub rejected: u64,
    /// Of those, rejected because a contact started acting within the step.
    pub rejected_for_contact_onset: u64,
    /// The largest penetration at a contact's first step.
    pub largest_entry_penetration: f64,
    /// Corrector Newton iterations.
    pub newton_iterations: u64,
    /// Jacobian evaluations.
    pub jacobian_evaluations: u64,
    /// LU factorizations.
    pub lu_factorizations: u64,
    /// Force-element evaluations the broad phase let through.
    pub broad_phase_evaluated: u64,
    /// Force-element evaluations the broad phase skipped.
    pub broad_phase_skipped: u64,
}

impl DynamicsTotals {
    /// Adds one dynamics analysis.
    pub fn add(&mut self, summary: &RunSummary) {
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
        self.broad_phase_evaluated += summary.broad_phase_evaluated;
        self.broad_phase_skipped += summary.broad_phase_skipped;
    }

    /// The share of force-element evaluations the broad phase skipped, in `[0, 1]`
    /// (`skipped / (evaluated + skipped)`; 0 when there were none).
    pub fn broad_phase_skipped_share(&self) -> f64 {
        let all = self.broad_phase_evaluated + self.broad_phase_skipped;
        if all == 0 {
            0.0
        } else {
            self.broad_phase_skipped as f64 / all as f64
        }
    }
}

/// What a run did.
#[derive(Debug)]
pub struct RunReport {
    /// The dataset run (as given).
    pub model: PathBuf,
    /// The engine and faceting tolerance used, with where each came from.
    pub selection: EngineSelection,
    /// Threads evaluating contacts and forces.
    pub threads: usize,
    /// Each analysis run, in order (up to the one that failed).
    pub analyses: Vec<AnalysisReport>,
    /// What stopped the run (`None` when every analysis completed).
    pub failure: Option<RunFailure>,
    /// The first time of the run.
    pub start: f64,
    /// The last time of the run.
    pub end: f64,
    /// Wall time of the analyses (lowering included, reading the dataset not).
    pub wall: Duration,
    /// Wall time spent lowering the model (geometry prepared for the engine included).
    pub prepare: Duration,
    /// The dynamics analyses' counters, added up.
    pub dynamics: DynamicsTotals,
    /// Frames delivered to the sink.
    pub output_frames: u64,
    /// The geometry engine's work over the run.
    pub engine_work: WorkCounters,
}

impl RunReport {
    /// Whether the run was interrupted: the sink refused a frame with
    /// [`std::io::ErrorKind::Interrupted`] (as [`ResultFiles`](super::ResultFiles) does once its
    /// interrupt flag is set, by SIGINT or SIGTERM in `contact run`).
    pub fn interrupted(&self) -> bool {
        matches!(&self.failure, Some(RunFailure::Analysis { error, .. }) if is_interruption(error))
    }

    /// Whether every analysis completed.
    pub fn completed(&self) -> bool {
        self.failure.is_none()
    }

    /// The run as `summary.json` holds it: the engine and where it came from, the status, the
    /// span and wall times, each analysis ([`AnalysisReport::to_json`]), the dynamics totals,
    /// the frames delivered and the engine's work.
    pub fn to_json(&self) -> Value {
        let (wall, simulated) = (self.wall.as_secs_f64(), self.end - self.start);
        let status = match &self.failure {
            None => "completed".to_string(),
            Some(_) if self.interrupted() => "interrupted".to_string(),
            Some(e) => format!("failed: {e}"),
        };
        let selection = &self.selection;
        let work = &self.engine_work;
        let totals = &self.dynamics;
        json!({
            "model": self.model.display().to_string(),
            "engine": selection.library.name(),
            "engine_source": selection.library_source.to_string(),
            "threads": self.threads,
            "faceting_tolerance": (selection.library == GeometryLibrary::Faceted).then_some(selection.faceting_tolerance.value()),
            "status": status,
            "start": self.start,
            "end": self.end,
            "wall_time_s": wall,
            "wall_ms_per_simulated_s": (simulated > 0.0).then(|| 1e3 * wall / simulated),
            "prepare_s": self.prepare.as_secs_f64(),
            "analyses": self.analyses.iter().map(AnalysisReport::to_json).collect::<Vec<_>>(),
            "steps": totals.steps,
            "rejected_steps": totals.rejected,
            "rejected_for_contact_onset": totals.rejected_for_contact_onset,
            "largest_entry_penetration": totals.largest_entry_penetration,
            "newton_iterations": totals.newton_iterations,
            "jacobian_evaluations": totals.jacobian_evaluations,
            "lu_factorizations": totals.lu_factorizations,
            "broad_phase": {
                "evaluated": totals.broad_phase_evaluated, "skipped": totals.broad_phase_skipped,
                "skipped_share": totals.broad_phase_skipped_share(),
            },
            "output_frames": self.output_frames,
            "engine_work": {
                "queries": work.queries, "geometry_pairs": work.geometry_pairs,
                "bounding_volume_tests": work.bounding_volume_tests, "primitive_tests": work.primitive_tests,
                "iterations": work.iterations, "contacts": work.contacts,
            },
        })
    }
}
