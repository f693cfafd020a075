//! One analysis of a run on the lowered model, its frames passed through [`FrameFilter`].

use super::RunSink;
use super::error::AnalysisError;
use super::report::{AnalysisOutcome, AnalysisReport};
use crate::run::active::FrameMap;
use crate::run::lower::LoweredModel;
use crate::run::plan::AnalysisStep;
use contact_solver::contact_force::ContactForce;
use contact_solver::frame::compute_frame;
use contact_solver::kinematics::{KinematicsSettings, run_kinematics};
use contact_solver::linear::{LinearSettings, linearize};
use contact_solver::mbs::{MultibodySystem, PartState};
use contact_solver::simulate::{
    DynamicsSettings, Frame, RunSummary, SimulationError, simulate_with_progress,
};
use contact_solver::statics::solve_statics;
use std::cell::RefCell;
use std::ops::ControlFlow;
use std::sync::Arc;
use std::time::Instant;

/// Frames on their way to the sink. A timed analysis (dynamics, kinematics) that starts where
/// the previous one delivered its last frame does not deliver it again; an equilibrium or
/// initial-conditions frame is always delivered. The last frame's part states start the next
/// analysis.
#[derive(Debug, Default)]
pub(super) struct FrameFilter {
    last_t: Option<f64>,
    /// Skip a frame at the time of the last one delivered (set per analysis).
    pub(super) skip_repeat: bool,
    /// The part states of the last frame computed.
    pub(super) carried: Option<Vec<PartState>>,
    /// Frames delivered.
    pub(super) frames: u64,
    /// The frames of a model with elements switched off, in the whole model's layout.
    pub(super) map: Option<FrameMap>,
}

impl FrameFilter {
    /// Passes `frame` to `sink` unless it repeats the last one.
    fn deliver(&mut self, frame: &Frame, sink: &mut dyn RunSink) -> std::io::Result<()> {
        self.carried = Some(frame.parts.clone());
        if self.skip_repeat && self.last_t == Some(frame.t) {
            return Ok(());
        }
        self.last_t = Some(frame.t);
        self.frames += 1;
        match &self.map {
            Some(map) => sink.frame(&map.remap(frame)),
            None => sink.frame(frame),
        }
    }
}

/// Runs `step` on `lowered`, delivering its frames (or eigenvalues) to `sink`.
pub(super) fn run_analysis(
    step: &AnalysisStep,
    lowered: &mut LoweredModel,
    filter: &mut FrameFilter,
    sink: &mut dyn RunSink,
) -> AnalysisReport {
    let started = Instant::now();
    sink.analysis_started(step);
    let (outcome, error) = match compute(step, lowered, filter, sink) {
        Ok(outcome) => (Some(outcome), None),
        Err(failed) => {
            let (outcome, error) = *failed;
            (outcome, Some(error))
        }
    };
    let report = AnalysisReport {
        step: step.clone(),
        outcome,
        error: error.map(Arc::new),
        wall: started.elapsed(),
    };
    sink.analysis_finished(&report);
    report
}

/// A failed analysis: what it computed before failing, if anything, and why (boxed: the
/// outcome is large and failures are rare).
type Failed = Box<(Option<AnalysisOutcome>, AnalysisError)>;

/// The analysis proper.
fn compute(
    step: &AnalysisStep,
    lowered: &mut LoweredModel,
    filter: &mut FrameFilter,
    sink: &mut dyn RunSink,
) -> Result<AnalysisOutcome, Failed> {
    let fail = |e: AnalysisError| Box::new((None, e));
    let LoweredModel {
        system, contacts, ..
    } = lowered;
    match *step {
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
            dynamics(system, contacts, &settings, filter, sink)
                .map(AnalysisOutcome::Dynamics)
                .map_err(|e| fail(e.into()))
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
            run_kinematics(system, contacts, &settings, &mut |frame, _| {
                filter.deliver(frame, sink)
            })
            .map(AnalysisOutcome::Kinematics)
            .map_err(|e| fail(e.into()))
        }
        AnalysisStep::Statics { t, settings } => {
            let y = system.given_state().clone();
            let found = solve_statics(system, t, &y, &settings).map_err(|e| fail(e.into()))?;
            let written = compute_frame(system, contacts, t, &found.y)
                .map_err(AnalysisError::from)
                .and_then(|frame| Ok(filter.deliver(&frame, sink)?));
            let outcome = AnalysisOutcome::Statics(found);
            match written {
                Ok(()) => Ok(outcome),
                Err(e) => Err(Box::new((Some(outcome), e))),
            }
        }
        AnalysisStep::InitialConditions { t } => {
            let initial = system
                .compute_initial_state(t)
                .map_err(|e| fail(e.into()))?;
            let frame =
                compute_frame(system, contacts, t, &initial.y).map_err(|e| fail(e.into()))?;
            filter.deliver(&frame, sink).map_err(|e| fail(e.into()))?;
            Ok(AnalysisOutcome::InitialConditions)
        }
        AnalysisStep::Linear { t, settings } => linear(system, t, &settings, sink),
    }
}

/// A dynamics analysis: frames through `filter` to `sink`, progress to `sink`, which may ask
/// the run to stop.
fn dynamics(
    system: &mut MultibodySystem,
    contacts: &[Arc<ContactForce>],
    settings: &DynamicsSettings,
    filter: &mut FrameFilter,
    sink: &mut dyn RunSink,
) -> Result<RunSummary, SimulationError> {
    // Frames and progress both go to the sink, from two callbacks that never nest.
    let sink = RefCell::new(sink);
    simulate_with_progress(
        system,
        contacts,
        settings,
        &mut |frame| filter.deliver(frame, &mut **sink.borrow_mut()),
        &mut |p| {
            let mut sink = sink.borrow_mut();
            sink.progress(p);
            if sink.stop_requested() {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        },
    )
}

/// A linearization at the state reached so far, assembled and with consistent velocities
/// (the multipliers are solved for by the linearization itself); its eigenvalues to `sink`.
fn linear(
    system: &mut MultibodySystem,
    t: f64,
    settings: &LinearSettings,
    sink: &mut dyn RunSink,
) -> Result<AnalysisOutcome, Failed> {
    let fail = |e: AnalysisError| Box::new((None, e));
    let mut y = system.given_state().clone();
    system
        .assemble(t, &mut y)
        .and_then(|_| system.project_velocities(t, &mut y))
        .map_err(|e| fail(e.into()))?;
    let linear = linearize(system, t, &y, settings).map_err(|e| fail(e.into()))?;
    let written = sink.eigenvalues(&linear, settings.damping);
    let outcome = AnalysisOutcome::Linear(linear);
    match written {
        Ok(()) => Ok(outcome),
        Err(e) => Err(Box::new((Some(outcome), e.into()))),
    }
}
