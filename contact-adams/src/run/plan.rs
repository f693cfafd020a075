//! The analyses a run performs, in order, from the command file's SIMULATE commands (or the
//! `contact run` flags), with the INTEGRATOR and EQUILIBRIUM settings in force at each.
//!
//! - SIMULATE/DYNAMICS and SIMULATE/KINEMATICS run from the current time to END (or for
//!   DURATION), each with its own DTOUT or STEPS; the next SIMULATE starts from the state the
//!   last one reached (its first frame, a repeat of the last one written, is not written again).
//! - SIMULATE/TRANSIENT runs kinematics when the model has zero degrees of freedom and dynamics
//!   otherwise, as in Adams. The degrees of freedom are `6n − rank(Φ_v)` at the model's
//!   configuration assembled at the TRANSIENT's start time (`n` moving parts, `Φ_v` the
//!   constraint Jacobian of joints, JPRIMs and MOTIONs): the rank, not the count of equations,
//!   since redundant constraints are common (a planar slider-crank built from revolute joints
//!   has more equations than coordinates). The step records the choice ([`TransientChoice`]) so
//!   the run summary can say which analysis ran and why.
//! - SIMULATE/STATICS finds the equilibrium at the current time; a following analysis starts
//!   from it (Adams: dynamics after statics starts from equilibrium, at rest).
//! - SIMULATE/INITIAL_CONDITIONS writes the assembled initial state at the current time.
//! - LINEAR/EIGENSOL linearizes at the state reached so far, at the current time: after a
//!   SIMULATE/STATICS the equilibrium, after a SIMULATE/DYNAMICS its last state, first in the
//!   file the initial state ([`contact_solver::linear`]). It ends a span of SIMULATEs.
//! - ACTIVATE/DEACTIVATE switch elements on and off from the next analysis on; each analysis
//!   records the elements switched off at its start ([`RunPlan::inactive`], see
//!   [`super::active`]).
//! - Without SIMULATE commands: dynamics from 0 to `--end`.

use crate::dataset::Origin;
use crate::model::{Analysis as ModelAnalysis, EquilibriumSettings, Model, OutputSteps};
use crate::run::active::Inactive;
use crate::run::lower::LowerError;
use contact_core::InvalidArgument;
use contact_solver::bdf::{Corrector, IntegratorSettings};
use contact_solver::linear::LinearSettings;
use contact_solver::mbs::MbsError;
use contact_solver::statics::StaticsSettings;
use planner::Planner;

mod planner;

/// Why a SIMULATE/TRANSIENT ran as kinematics or as dynamics.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TransientChoice {
    /// The model's degrees of freedom where the TRANSIENT starts: 6 per moving part minus the
    /// rank of the constraint Jacobian.
    pub degrees_of_freedom: usize,
}

impl TransientChoice {
    /// The analysis the TRANSIENT runs: KINEMATICS with zero degrees of freedom, else DYNAMICS.
    pub fn analysis(&self) -> &'static str {
        if self.degrees_of_freedom == 0 {
            "KINEMATICS"
        } else {
            "DYNAMICS"
        }
    }
}

impl std::fmt::Display for TransientChoice {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.degrees_of_freedom {
            0 => write!(
                f,
                "SIMULATE/TRANSIENT ran as KINEMATICS: the model has 0 degrees of freedom (its joints and MOTIONs fix every part)"
            ),
            1 => write!(
                f,
                "SIMULATE/TRANSIENT ran as DYNAMICS: the model has 1 degree of freedom"
            ),
            dof => write!(
                f,
                "SIMULATE/TRANSIENT ran as DYNAMICS: the model has {dof} degrees of freedom"
            ),
        }
    }
}

/// One analysis of a run.
#[derive(Debug, Clone, PartialEq)]
pub enum AnalysisStep {
    /// Transient dynamics.
    Dynamics {
        /// Start time.
        start: f64,
        /// End time.
        end: f64,
        /// Time between frames.
        output_step: f64,
        /// The integrator's settings.
        integrator: IntegratorSettings,
        /// Set when a SIMULATE/TRANSIENT chose dynamics.
        transient: Option<TransientChoice>,
    },
    /// Kinematics of a zero-DOF model.
    Kinematics {
        /// Start time.
        start: f64,
        /// End time.
        end: f64,
        /// Time between frames.
        output_step: f64,
        /// Set when a SIMULATE/TRANSIENT chose kinematics.
        transient: Option<TransientChoice>,
    },
    /// Static equilibrium at time `t`.
    Statics {
        /// Time.
        t: f64,
        /// EQUILIBRIUM (with the integrator for the quasi-dynamic method).
        settings: StaticsSettings,
    },
    /// The assembled initial conditions at time `t`.
    InitialConditions {
        /// Time.
        t: f64,
    },
    /// LINEAR/EIGENSOL: the eigenvalues at the state reached so far, at time `t`.
    Linear {
        /// Time.
        t: f64,
        /// NODAMPIN.
        settings: LinearSettings,
    },
}

impl AnalysisStep {
    /// The analysis's name as in SIMULATE.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Dynamics { .. } => "DYNAMICS",
            Self::Kinematics { .. } => "KINEMATICS",
            Self::Statics { .. } => "STATICS",
            Self::InitialConditions { .. } => "INITIAL_CONDITIONS",
            Self::Linear { .. } => "LINEAR",
        }
    }

    /// Why a SIMULATE/TRANSIENT ran as this analysis (`None` when it was asked for by name).
    pub fn transient(&self) -> Option<TransientChoice> {
        match self {
            Self::Dynamics { transient, .. } | Self::Kinematics { transient, .. } => *transient,
            Self::Statics { .. } | Self::InitialConditions { .. } | Self::Linear { .. } => None,
        }
    }
}

/// The flags of `contact run` that override the command file.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PlanOverrides {
    /// `--end`: the end of the last timed analysis (or of the dynamics without a command file).
    pub end: Option<f64>,
    /// `--dtout`.
    pub dtout: Option<f64>,
    /// `--steps`.
    pub steps: Option<u32>,
}

/// The most output frames one timed analysis may write (about 1 GB of `parts.csv`,
/// `contacts.csv` and `frames.jsonl` for a small model). A span whose `span / output step`
/// exceeds it is refused before any file is opened; raise DTOUT (or lower STEPS).
pub const MAX_OUTPUT_FRAMES: u64 = 1_000_000;

/// The smallest INTEGRATOR/HMAX allowed, as a fraction of the span it integrates: below it the
/// run needs more than 1e10 steps (and below `f64::EPSILON` of the span a step does not
/// advance time at all).
pub const MIN_HMAX_FRACTION: f64 = 1e-10;

/// A timed span being collected from consecutive SIMULATEs.
struct Span {
    /// The SIMULATE that started it (none without a command file).
    origin: Option<Origin>,
    analysis: ModelAnalysis,
    start: f64,
    end: f64,
    output: Option<OutputSteps>,
    integrator: IntegratorSettings,
    transient: Option<TransientChoice>,
    /// The elements switched off when it started.
    inactive: Inactive,
}

/// Why a run's analyses could not be planned.
#[derive(Debug, thiserror::Error)]
pub enum PlanError {
    /// INTEGRATOR/CORRECTOR names a corrector the solver does not have.
    #[error("INTEGRATOR/CORRECTOR = {corrector} is not supported (ORIGINAL or MODIFIED)")]
    Corrector {
        /// The name given.
        corrector: String,
    },
    /// An INTEGRATOR setting is out of range.
    #[error("INTEGRATOR: {0}")]
    Integrator(InvalidArgument),
    /// A SIMULATE/TRANSIENT's degrees of freedom could not be counted.
    #[error("{origin}: SIMULATE/TRANSIENT: {source}")]
    Transient {
        /// The command.
        origin: Origin,
        /// Why.
        source: DegreesOfFreedomError,
    },
    /// A timed SIMULATE has neither END nor DURATION.
    #[error("{origin}: SIMULATE needs END or DURATION")]
    NoSpan {
        /// The command.
        origin: Origin,
    },
    /// No command file (or one without analyses) and no end time given.
    #[error("no END: give --end (or a command file with SIMULATE/DYNAMICS, END = …)")]
    NoEnd,
    /// A timed analysis's end is not finite or not after its start.
    #[error("{}{} is out of range: the end must be finite and after the start time {start:?}", at(.origin), setting(by, *end))]
    Span {
        /// The SIMULATE command (none without a command file).
        origin: Option<Origin>,
        /// What set the end: `END`, `DURATION` or `--end`.
        by: &'static str,
        /// Start time.
        start: f64,
        /// End time.
        end: f64,
    },
    /// A timed analysis's output step is not finite and positive.
    #[error("{}{by} gives an output step of {output_step:?}: it must be finite and > 0", at(.origin))]
    OutputStep {
        /// The SIMULATE command (none without a command file).
        origin: Option<Origin>,
        /// What set the output step: `DTOUT`, `STEPS`, `--dtout` or `--steps`.
        by: &'static str,
        /// The output step.
        output_step: f64,
    },
    /// A timed analysis would write more than [`MAX_OUTPUT_FRAMES`] frames.
    #[error(
        "{}{by}: a span of {span:?} at an output step of {output_step:?} makes {frames:.3e} output frames, more than the bound of {MAX_OUTPUT_FRAMES} per analysis: {}",
        at(.origin), frames_remedy(by, *span)
    )]
    TooManyFrames {
        /// The SIMULATE command (none without a command file).
        origin: Option<Origin>,
        /// What set the output step: `DTOUT`, `STEPS`, `--dtout` or `--steps`.
        by: &'static str,
        /// `end − start`.
        span: f64,
        /// The output step.
        output_step: f64,
        /// `span / output_step`.
        frames: f64,
    },
    /// An analysis would run with a MOTION on a deactivated JOINT.
    #[error(
        "{origin}: MOTION/{motion} drives JOINT/{joint}, which is deactivated: deactivate the MOTION too"
    )]
    OrphanMotion {
        /// The analysis command.
        origin: Origin,
        /// The MOTION.
        motion: u32,
        /// Its JOINT.
        joint: u32,
    },
    /// INTEGRATOR/HMAX is too small for the span to be integrated in a bounded number of steps.
    #[error(
        "{}INTEGRATOR/HMAX = {hmax:?} over a span of {span:?} needs more than 1e10 steps: HMAX must be >= {:?} (the span × {MIN_HMAX_FRACTION:e})",
        at(.origin), span * MIN_HMAX_FRACTION
    )]
    HmaxTooSmall {
        /// The SIMULATE command (none without a command file).
        origin: Option<Origin>,
        /// HMAX.
        hmax: f64,
        /// `end − start`.
        span: f64,
    },
}

impl PlanError {
    /// The command the error is about, when it has one.
    pub fn origin(&self) -> Option<&Origin> {
        match self {
            Self::Transient { origin, .. }
            | Self::NoSpan { origin }
            | Self::OrphanMotion { origin, .. } => Some(origin),
            Self::Span { origin, .. }
            | Self::OutputStep { origin, .. }
            | Self::TooManyFrames { origin, .. }
            | Self::HmaxTooSmall { origin, .. } => origin.as_ref(),
            Self::Corrector { .. } | Self::Integrator(_) | Self::NoEnd => None,
        }
    }
}

/// How to bring a span's output frames within [`MAX_OUTPUT_FRAMES`], for the setting `by`.
fn frames_remedy(by: &str, span: f64) -> String {
    if by.eq_ignore_ascii_case("steps") || by == "--steps" {
        format!("lower {by} to at most {MAX_OUTPUT_FRAMES}")
    } else {
        format!(
            "raise {by} to at least {:?}",
            span / MAX_OUTPUT_FRAMES as f64
        )
    }
}

/// A setting as written: `--end 2.0` for a flag, `END = 2.0` for a command's argument.
fn setting(by: &str, value: f64) -> String {
    if by.starts_with("--") {
        format!("{by} {value:?}")
    } else {
        format!("{by} = {value:?}")
    }
}

/// `"file:line:col: "` for a located error, else nothing.
fn at(origin: &Option<Origin>) -> String {
    origin
        .as_ref()
        .map_or_else(String::new, |o| format!("{o}: "))
}

/// Why a model's degrees of freedom could not be counted (for a SIMULATE/TRANSIENT).
#[derive(Debug, thiserror::Error)]
pub enum DegreesOfFreedomError {
    /// The model could not be lowered onto the solver.
    #[error(transparent)]
    Lower(#[from] Box<LowerError>),
    /// Its configuration could not be assembled.
    #[error(transparent)]
    Assembly(#[from] MbsError),
}

/// The analyses of `model`'s command file, in order, with notes on anything interpreted (see
/// [`plan_run`], which also gives the elements each analysis runs without).
pub fn plan_analyses(
    model: &Model,
    overrides: PlanOverrides,
    degrees_of_freedom: &mut dyn FnMut(f64) -> Result<usize, DegreesOfFreedomError>,
) -> Result<(Vec<AnalysisStep>, Vec<String>), PlanError> {
    let plan = plan_run(model, overrides, &mut |t, _| degrees_of_freedom(t))?;
    Ok((plan.steps, plan.notes))
}

/// A run's analyses, with the elements each runs without.
#[derive(Debug, Clone, PartialEq)]
pub struct RunPlan {
    /// The analyses, in order.
    pub steps: Vec<AnalysisStep>,
    /// Per analysis, the elements DEACTIVATE has switched off by its start.
    pub inactive: Vec<Inactive>,
    /// Notes on anything interpreted, each ACTIVATE/DEACTIVATE's effect among them.
    pub notes: Vec<String>,
    /// What each ACTIVATE/DEACTIVATE does, at the command.
    pub switches: Vec<(Origin, String)>,
}

/// The analyses of `model`'s command file, in order, each with the elements switched off
/// (ACTIVATE/DEACTIVATE take effect at the next analysis, as in Adams), and notes.
///
/// `degrees_of_freedom(t, inactive)` gives the model's degrees of freedom, without the
/// `inactive` elements, at its configuration assembled at time `t`; it is asked only for a
/// SIMULATE/TRANSIENT (at that command's start time). An analysis that would run with an
/// active MOTION on a deactivated JOINT is refused.
pub fn plan_run(
    model: &Model,
    overrides: PlanOverrides,
    degrees_of_freedom: &mut dyn FnMut(f64, &Inactive) -> Result<usize, DegreesOfFreedomError>,
) -> Result<RunPlan, PlanError> {
    let mut planner = Planner::new(model, overrides)?;
    for (origin, command) in &model.commands {
        if planner
            .command(origin, command, &mut *degrees_of_freedom)?
            .is_break()
        {
            break;
        }
    }
    planner.finish()
}

/// The step of a finished span; `last` when `--end` may override its END. Refuses a span
/// that is empty or not finite, an output step that is not positive, more than
/// [`MAX_OUTPUT_FRAMES`] frames, and a dynamics HMAX below [`MIN_HMAX_FRACTION`] of the span,
/// all before any result file is opened.
fn finish(
    span: Span,
    overrides: PlanOverrides,
    notes: &mut Vec<String>,
    last: bool,
) -> Result<(AnalysisStep, Inactive), PlanError> {
    let (end, end_by) = match overrides.end {
        Some(end) if last => (end, "--end"),
        _ => (
            span.end,
            if span.origin.is_some() {
                "END"
            } else {
                "--end"
            },
        ),
    };
    if !(span.start.is_finite() && end.is_finite() && end > span.start) {
        return Err(PlanError::Span {
            origin: span.origin,
            by: end_by,
            start: span.start,
            end,
        });
    }
    let duration = end - span.start;
    let (output_step, by) = match (overrides.dtout, overrides.steps, span.output) {
        (Some(dt), _, _) => (dt, "--dtout"),
        (None, Some(n), _) => (duration / f64::from(n), "--steps"),
        (None, None, Some(OutputSteps::Interval(dt))) => (dt, "DTOUT"),
        (None, None, Some(OutputSteps::Steps(n))) => (duration / f64::from(n), "STEPS"),
        (None, None, None) => {
            notes.push("no DTOUT or STEPS: writing 100 output steps".into());
            (duration / 100.0, "the default of 100 steps")
        }
    };
    if !(output_step.is_finite() && output_step > 0.0) {
        return Err(PlanError::OutputStep {
            origin: span.origin,
            by,
            output_step,
        });
    }
    let frames = duration / output_step;
    // Both finite and positive: `frames` is a number or +inf (an overflow), never NaN.
    if frames > MAX_OUTPUT_FRAMES as f64 {
        return Err(PlanError::TooManyFrames {
            origin: span.origin,
            by,
            span: duration,
            output_step,
            frames,
        });
    }
    if span.analysis != ModelAnalysis::Kinematics
        && let Some(hmax) = span.integrator.hmax
        && hmax < duration * MIN_HMAX_FRACTION
    {
        return Err(PlanError::HmaxTooSmall {
            origin: span.origin,
            hmax,
            span: duration,
        });
    }
    let step = match span.analysis {
        ModelAnalysis::Kinematics => AnalysisStep::Kinematics {
            start: span.start,
            end,
            output_step,
            transient: span.transient,
        },
        _ => AnalysisStep::Dynamics {
            start: span.start,
            end,
            output_step,
            integrator: span.integrator,
            transient: span.transient,
        },
    };
    Ok((step, span.inactive))
}

/// The solver's EQUILIBRIUM settings.
fn convert_equilibrium(s: &EquilibriumSettings, integrator: IntegratorSettings) -> StaticsSettings {
    StaticsSettings {
        tlimit: s.tlimit,
        alimit: s.alimit,
        maxit: s.maxit as usize,
        error: s.error,
        imbalance: s.imbalance,
        stability: s.stability,
        dynamic: s.dynamic,
        integrator,
    }
}

/// The solver's INTEGRATOR settings.
pub fn convert_integrator(
    s: &crate::model::IntegratorSettings,
) -> Result<IntegratorSettings, PlanError> {
    let corrector = match s.corrector.as_deref() {
        None | Some("MODIFIED") => Corrector::Modified,
        Some("ORIGINAL") | Some("FULL") => Corrector::Full,
        Some(other) => {
            return Err(PlanError::Corrector {
                corrector: other.to_string(),
            });
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
    settings.validate().map_err(PlanError::Integrator)?;
    Ok(settings)
}

#[cfg(test)]
#[path = "plan_tests.rs"]
mod tests;
