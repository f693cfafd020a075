//! Transient dynamics: the BDF on the multibody equations, with contact prediction and output
//! at fixed times.
//!
//! **Contact prediction** (SPEC §8). After each accepted step every CONTACT that had no contact
//! at the previous step and has one now is a *new contact*. From its deepest penetration δ and
//! rate δ̇ > 0 the onset is estimated as `t_c = t − δ/δ̇`; the step is rejected and retried to
//! end just after the onset, at `t_c + ONSET_MARGIN·(t − t_c)` (clamped inside the step), and
//! the integrator restarts at order 1 — so contacts begin with a small penetration, at first
//! order, with small steps. Each onset is predicted once; a step too short for a time strictly
//! inside it (a sliver of a few ulps, left before a stop time or a retry target) is kept as
//! it is. The run reports how many steps were rejected for onsets and the largest penetration
//! a contact started with.
//!
//! **Output** frames are interpolated from the BDF history at the output times, so frequent
//! output costs no extra steps; only END is a stop time.

use super::EvaluationError;
use super::bdf::{Bdf, IntegratorError, IntegratorSettings, IntegratorStats};
use super::broad_phase::BroadPhase;
use super::contact_force::{ContactForce, ContactReport};
use super::frame::FrameDynamics;
use super::mbs::{ForceElement, MbsError, MultibodySystem, PartState, StateView};
use std::ops::ControlFlow;
use std::sync::Arc;

/// Where in the step a retried step ends: the fraction of the time from the estimated onset
/// to the rejected step's end. Small enough that a contact starts shallow (δ shrinks by this
/// factor), large enough that the retried step does not end before the contact exists.
pub const ONSET_MARGIN: f64 = 0.05;

/// The progress guard's window: every this many accepted steps, the time reached is compared
/// with the time at the start of the window.
pub const STALL_WINDOW: u64 = 10_000;

/// The progress guard's threshold: a window of [`STALL_WINDOW`] accepted steps that advances
/// time by less than this fraction of the span stops the run with
/// [`SimulationError::NoProgress`] (at that rate the run would need more than 1e9 steps).
pub const STALL_FRACTION: f64 = 1e-5;

/// What to run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicsSettings {
    /// Start time.
    pub start: f64,
    /// End time (> start).
    pub end: f64,
    /// Time between output frames (> 0).
    pub output_step: f64,
    /// The integrator's settings.
    pub integrator: IntegratorSettings,
}

/// One output frame: the time, every part's state, every contact's kinematics and forces.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// Time.
    pub t: f64,
    /// Part states indexed by part id (ground first).
    pub parts: Vec<PartState>,
    /// Per CONTACT (in the order given), its contacts.
    pub contacts: Vec<Vec<ContactReport>>,
    /// Accelerations and constraint reactions, when the system was asked for them
    /// ([`MultibodySystem::set_output_dynamics`]); `None` otherwise.
    pub dynamics: Option<FrameDynamics>,
}

/// What a run did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RunSummary {
    /// The integrator's counters (steps, rejections by cause, Newton iterations, matrices).
    pub integrator: IntegratorStats,
    /// Steps rejected and retried at a contact onset.
    pub rejected_for_contact_onset: u64,
    /// The largest penetration any contact started with (at the first step it existed).
    pub largest_entry_penetration: f64,
    /// Output frames written.
    pub frames: u64,
    /// Force-element evaluations the system's broad phase let through during the run
    /// (elements without bounds included).
    pub broad_phase_evaluated: u64,
    /// Force-element evaluations the broad phase skipped (bounds apart: loads zero).
    pub broad_phase_skipped: u64,
}

/// Where a run is, reported after every accepted step (for a progress display).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// The time reached (end of the last accepted step).
    pub t: f64,
    /// The start time of the run.
    pub start: f64,
    /// The end time of the run.
    pub end: f64,
    /// Accepted steps so far.
    pub steps: u64,
    /// Rejected step attempts so far, whatever the cause (contact onsets included).
    pub rejected: u64,
}

/// Why a run stopped.
#[derive(Debug, thiserror::Error)]
pub enum SimulationError {
    /// The settings are out of range.
    #[error("{0}")]
    Settings(String),
    /// The initial conditions could not be found.
    #[error("initial conditions: {0}")]
    Initial(#[from] MbsError),
    /// The integrator failed (its message carries the diagnosis and remedies).
    #[error("at t = {t:?}: {source}")]
    Integrator {
        /// The last accepted time.
        t: f64,
        /// The failure.
        source: IntegratorError,
    },
    /// The model reached a state it cannot represent (a part of a 2-D contact left its plane):
    /// the run stopped; `t` is the end of the last accepted step, the diagnosis says when the
    /// state was found.
    #[error("{source} (the last accepted step ended at t = {t:?})")]
    Stopped {
        /// The end of the last accepted step.
        t: f64,
        /// The element's diagnosis.
        source: EvaluationError,
    },
    /// A force element failed outside the integrator (while writing output).
    #[error("at t = {t:?}: {source}")]
    Evaluation {
        /// Time.
        t: f64,
        /// The failure.
        source: EvaluationError,
    },
    /// Time stopped advancing: the last [`STALL_WINDOW`] accepted steps advanced time by less
    /// than [`STALL_FRACTION`] of the span, so the run would not end in a bounded time.
    #[error(
        "at t = {t:?}: the run is not advancing: the last {STALL_WINDOW} steps advanced time by {advanced:?} in all, less than {STALL_FRACTION:e} of the span {span:?} (mean step {:?}); the model is too stiff for its steps (an extreme STICTION_TRANSITION_VELOCITY, STIFFNESS or DAMPING) or HMAX is too small: soften it, loosen ERROR, or raise HMAX",
        advanced / STALL_WINDOW as f64
    )]
    NoProgress {
        /// The last accepted time.
        t: f64,
        /// Time advanced over the window.
        advanced: f64,
        /// The run's span (`end − start`).
        span: f64,
    },
    /// The output sink failed.
    #[error("writing results at t = {t:?}: {source}")]
    Output {
        /// Time.
        t: f64,
        /// The failure.
        source: std::io::Error,
    },
}

/// Runs dynamics from `settings.start` to `settings.end`, calling `sink` with a frame at the
/// start and every `output_step`. Frames already given to `sink` stay given when a later step
/// fails: the error says where the run stopped.
pub fn simulate(
    system: &mut MultibodySystem,
    contacts: &[Arc<ContactForce>],
    settings: &DynamicsSettings,
    sink: &mut dyn FnMut(&Frame) -> std::io::Result<()>,
) -> Result<RunSummary, SimulationError> {
    simulate_with_progress(system, contacts, settings, sink, &mut |_| {
        ControlFlow::Continue(())
    })
}

/// [`simulate`], calling `progress` after every accepted step (contact-onset retries
/// included). `progress` must be cheap: it runs once per step; a display throttles itself.
///
/// `progress` returning [`ControlFlow::Break`] ends the run at that step: the output frames
/// due up to it are delivered, then the step's own state as one more frame (off the output
/// grid unless it falls on it), and the run returns [`SimulationError::Output`] with
/// [`std::io::ErrorKind::Interrupted`] (or the sink's own error for that frame).
pub fn simulate_with_progress(
    system: &mut MultibodySystem,
    contacts: &[Arc<ContactForce>],
    settings: &DynamicsSettings,
    sink: &mut dyn FnMut(&Frame) -> std::io::Result<()>,
    progress: &mut dyn FnMut(&Progress) -> ControlFlow<()>,
) -> Result<RunSummary, SimulationError> {
    check_settings(settings)?;
    let DynamicsSettings {
        start,
        end,
        output_step,
        integrator,
    } = *settings;
    let initial = system.compute_initial_state(start)?;
    let mut bdf = Bdf::new(system, start, initial.y, initial.yp, integrator)
        .map_err(|source| SimulationError::Integrator { t: start, source })?;
    let mut summary = RunSummary::default();
    let (evaluated_before, skipped_before) = system.broad_phase_counts();
    let framer = Framer::new(contacts);
    let mut frame = framer.at(system, start, bdf.y())?;
    {
        let view = StateView::new(&frame.parts);
        for c in contacts {
            c.record_accepted(&view);
        }
    }
    let mut active: Vec<bool> = frame.contacts.iter().map(|c| !c.is_empty()).collect();
    attach_dynamics(system, &mut frame, bdf.y())?;
    sink(&frame).map_err(|source| SimulationError::Output { t: start, source })?;
    summary.frames += 1;
    let schedule = OutputSchedule {
        start,
        end,
        step: output_step,
        count: ((end - start) / output_step).round().max(1.0) as u64,
    };
    let mut next_output = 1u64;
    // Steps end exactly at END; output frames come from the BDF's interpolating polynomial, so
    // frequent output does not shorten the steps.
    bdf.set_stop_time(Some(end))
        .map_err(|source| SimulationError::Integrator { t: start, source })?;
    let mut stall = StallWatch {
        window_start: start,
        window_steps: 0,
        span: end - start,
    };
    while next_output <= schedule.count {
        let (t, frame_now) =
            step_with_onset_retry(system, &mut bdf, &framer, &active, &mut summary)?;
        frame = frame_now;
        record_entries(&frame, &mut active, &mut summary);
        stall.step_taken(t)?;
        let stats = bdf.stats();
        let stop = progress(&Progress {
            t,
            start,
            end,
            steps: stats.steps,
            rejected: stats.rejected(),
        })
        .is_break();
        let written_at = write_due_outputs(
            system,
            &bdf,
            &framer,
            &frame,
            &schedule,
            &mut next_output,
            sink,
            &mut summary,
        )?;
        if stop {
            if written_at != Some(t) {
                attach_dynamics(system, &mut frame, bdf.y())?;
                sink(&frame).map_err(|source| SimulationError::Output { t, source })?;
            }
            return Err(stopped_on_request(t));
        }
    }
    summary.integrator = *bdf.stats();
    let (evaluated, skipped) = system.broad_phase_counts();
    summary.broad_phase_evaluated = evaluated - evaluated_before;
    summary.broad_phase_skipped = skipped - skipped_before;
    Ok(summary)
}

/// One accepted step; a contact that began inside it (`active` says which touched before)
/// sends the step back to end just after the earliest onset, once. Returns the time reached
/// and its frame.
fn step_with_onset_retry(
    system: &mut MultibodySystem,
    bdf: &mut Bdf,
    framer: &Framer<'_>,
    active: &[bool],
    summary: &mut RunSummary,
) -> Result<(f64, Frame), SimulationError> {
    let t_before = bdf.t();
    let mut t = bdf
        .step(system)
        .map_err(|source| integrator_failure(t_before, source))?;
    let mut frame = framer.at(system, t, bdf.y())?;
    let onset = earliest_onset(&frame, active);
    if onset.is_finite()
        && let Some(retry) = retry_time(onset, t_before, t)
    {
        // State kept per accepted step goes back with the step, before the retry.
        for c in framer.contacts {
            c.rolled_back();
        }
        t = bdf
            .reject_last_step_and_retry_to(system, retry)
            .map_err(|source| integrator_failure(t_before, source))?;
        summary.rejected_for_contact_onset += 1;
        frame = framer.at(system, t, bdf.y())?;
    }
    Ok((t, frame))
}

/// The progress guard: every [`STALL_WINDOW`] steps the run must have advanced by at least
/// [`STALL_FRACTION`] of its span.
struct StallWatch {
    window_start: f64,
    window_steps: u64,
    span: f64,
}

impl StallWatch {
    /// Counts a step that reached `t`; [`SimulationError::NoProgress`] when a window ends
    /// having advanced too little.
    fn step_taken(&mut self, t: f64) -> Result<(), SimulationError> {
        self.window_steps += 1;
        if self.window_steps == STALL_WINDOW {
            let advanced = t - self.window_start;
            if advanced < STALL_FRACTION * self.span {
                return Err(SimulationError::NoProgress {
                    t,
                    advanced,
                    span: self.span,
                });
            }
            (self.window_start, self.window_steps) = (t, 0);
        }
        Ok(())
    }
}

/// END finite and after START, DTOUT finite and positive.
fn check_settings(settings: &DynamicsSettings) -> Result<(), SimulationError> {
    let DynamicsSettings {
        start,
        end,
        output_step,
        ..
    } = *settings;
    if !(start.is_finite() && end.is_finite() && end > start) {
        return Err(SimulationError::Settings(format!(
            "END = {end:?} must be finite and > START = {start:?}"
        )));
    }
    if !(output_step.is_finite() && output_step > 0.0) {
        return Err(SimulationError::Settings(format!(
            "DTOUT = {output_step:?} must be finite and > 0"
        )));
    }
    Ok(())
}

/// Output frames from states: the parts, and the reports of the contacts whose bounds meet
/// (the others have no contact; their own `reports` would say so).
struct Framer<'a> {
    contacts: &'a [Arc<ContactForce>],
    broad: BroadPhase,
}

impl<'a> Framer<'a> {
    fn new(contacts: &'a [Arc<ContactForce>]) -> Self {
        let broad = BroadPhase::of_elements(contacts.iter().map(|c| {
            (
                ForceElement::parts(c.as_ref()),
                ForceElement::bounds(c.as_ref()),
            )
        }));
        Self { contacts, broad }
    }

    /// The frame at time `t` and state `y` (no dynamics yet).
    fn at(
        &self,
        system: &MultibodySystem,
        t: f64,
        y: &nalgebra::DVector<f64>,
    ) -> Result<Frame, SimulationError> {
        let parts = system
            .part_states(y)
            .map_err(|source| SimulationError::Evaluation { t, source })?;
        let view = StateView::new(&parts);
        let mut reports = vec![Vec::new(); self.contacts.len()];
        for k in self.broad.candidates(&parts) {
            reports[k] = self.contacts[k]
                .reports(t, &view)
                .map_err(|source| SimulationError::Evaluation { t, source })?;
        }
        Ok(Frame {
            t,
            parts,
            contacts: reports,
            dynamics: None,
        })
    }
}

/// The frame's accelerations and reactions at state `y`, when the system outputs them.
fn attach_dynamics(
    system: &MultibodySystem,
    frame: &mut Frame,
    y: &nalgebra::DVector<f64>,
) -> Result<(), SimulationError> {
    if system.output_dynamics() {
        let t = frame.t;
        frame.dynamics = Some(
            system
                .frame_dynamics(t, y)
                .map_err(|source| SimulationError::Evaluation { t, source })?,
        );
    }
    Ok(())
}

/// The output times: `start + k·step` for k < `count`, END for the last.
struct OutputSchedule {
    start: f64,
    end: f64,
    step: f64,
    count: u64,
}

impl OutputSchedule {
    fn time(&self, k: u64) -> f64 {
        if k >= self.count {
            self.end
        } else {
            self.start + k as f64 * self.step
        }
    }
}

/// Writes every output frame due by the step just taken to `frame`'s time (the step's own
/// frame, or one interpolated from the BDF's polynomial); returns the time of the last one
/// written.
#[expect(
    clippy::too_many_arguments,
    reason = "the run loop's state it reads and advances, passed apart rather than bundled for one call"
)]
fn write_due_outputs(
    system: &MultibodySystem,
    bdf: &Bdf,
    framer: &Framer<'_>,
    frame: &Frame,
    schedule: &OutputSchedule,
    next_output: &mut u64,
    sink: &mut dyn FnMut(&Frame) -> std::io::Result<()>,
    summary: &mut RunSummary,
) -> Result<Option<f64>, SimulationError> {
    let t = frame.t;
    let mut written_at = None;
    while *next_output <= schedule.count && schedule.time(*next_output) <= t {
        let t_out = schedule.time(*next_output);
        let (mut output, y) = if t_out == t {
            (frame.clone(), bdf.y().clone())
        } else {
            let (y, _) = bdf
                .interpolate(t_out)
                .map_err(|source| SimulationError::Integrator { t, source })?;
            (framer.at(system, t_out, &y)?, y)
        };
        attach_dynamics(system, &mut output, &y)?;
        sink(&output).map_err(|source| SimulationError::Output { t: t_out, source })?;
        summary.frames += 1;
        *next_output += 1;
        written_at = Some(t_out);
    }
    Ok(written_at)
}

/// The earliest onset `t − δ/δ̇` among the contacts that touch at `frame` and did not at the
/// step before (`active`), each from its deepest point while it approaches; infinite when none.
fn earliest_onset(frame: &Frame, active: &[bool]) -> f64 {
    frame
        .contacts
        .iter()
        .zip(active)
        .filter(|(now, was)| !**was && !now.is_empty())
        .filter_map(|(now, _)| {
            let deepest = now
                .iter()
                .max_by(|a, b| a.contact.penetration.total_cmp(&b.contact.penetration))?;
            (deepest.penetration_rate > 0.0)
                .then(|| frame.t - deepest.contact.penetration / deepest.penetration_rate)
        })
        .fold(f64::INFINITY, f64::min)
}

/// Records the penetration each newly touching contact entered with, and which touch now.
fn record_entries(frame: &Frame, active: &mut [bool], summary: &mut RunSummary) {
    for (k, now) in frame.contacts.iter().enumerate() {
        if !active[k] {
            let entry = now
                .iter()
                .map(|r| r.contact.penetration)
                .fold(0.0, f64::max);
            summary.largest_entry_penetration = summary.largest_entry_penetration.max(entry);
        }
        active[k] = !now.is_empty();
    }
}

/// The error of a run ended on request (its progress callback returned
/// [`ControlFlow::Break`]) at the step ending at `t`.
fn stopped_on_request(t: f64) -> SimulationError {
    SimulationError::Output {
        t,
        source: std::io::Error::new(
            std::io::ErrorKind::Interrupted,
            "stopped on request: the run ended at this step",
        ),
    }
}

/// Where a step `[t_before, t]` in which a contact appeared is retried to end, given the
/// estimated onset `onset = t − δ/δ̇`: just after the onset, `onset + ONSET_MARGIN·(t − onset)`,
/// clamped to `[t_before + ONSET_MARGIN·(t − t_before), t]` (an onset estimated before the step
/// or after its end). `None` when no time strictly inside the step is representable (a sliver
/// of a few ulps left before a stop time or a retry target): the contact then starts within
/// that sliver, and the step is kept.
pub fn retry_time(onset: f64, t_before: f64, t: f64) -> Option<f64> {
    let retry =
        (onset + ONSET_MARGIN * (t - onset)).clamp(t_before + ONSET_MARGIN * (t - t_before), t);
    (retry > t_before && retry < t).then_some(retry)
}

/// The run's error for an integrator failure after the accepted time `t_before`: a fatal
/// evaluation stops the run with the element's own diagnosis.
fn integrator_failure(t_before: f64, source: IntegratorError) -> SimulationError {
    match source {
        IntegratorError::Stopped { t, source } => SimulationError::Stopped { t, source },
        source => SimulationError::Integrator {
            t: t_before,
            source,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::retry_time;

    #[test]
    fn a_retry_ends_inside_the_step_or_not_at_all() {
        // An onset inside the step: just after it.
        let r = retry_time(0.5, 0.0, 1.0).unwrap();
        assert!((r - 0.525).abs() < 1e-15);
        // Before the step (t_c ≤ t_before) or at its end: clamped inside it.
        assert_eq!(retry_time(-3.0, 0.0, 1.0), Some(0.05));
        assert_eq!(retry_time(1.0, 0.0, 1.0), None);
        // A step of one ulp (the run that stopped at t = 0.6389867355375749 with "retry
        // target out of range"): no time inside it, so no retry.
        let t_before = 0.6389867355375749_f64;
        let t = f64::from_bits(t_before.to_bits() + 1);
        assert_eq!(retry_time(t_before - 1e-9, t_before, t), None);
        // A few ulps: a time strictly inside, or none.
        for ulps in 2..8 {
            let t = f64::from_bits(t_before.to_bits() + ulps);
            let retry = retry_time(t_before - 1e-12, t_before, t);
            assert!(
                retry.is_none_or(|r| r > t_before && r < t),
                "{ulps}: {retry:?}"
            );
        }
    }
}
