//! The trade on whole runs: the model run with every candidate engine setting and held to the
//! reference run ([`super::record_reference`]) over its whole motion.
//!
//! The runs compared are the reference and the candidate at the integrator ERROR where the
//! reference has converged ([`converge_reference`]); the wall time is that of the candidate's
//! run at the model's own ERROR.
//!
//! For each candidate, over the output frames both runs have (same times):
//! - **position error**, the *run error* `--max-run-error` bounds: the largest displacement
//!   between the two runs of a point of a moving part within its contact radius ρ (the
//!   farthest its contact geometries reach from its centre of mass at the start, 0 for a part
//!   without any), over every frame and part, divided by the model's size
//!   ([`ModelScale`]). For a part whose centre moved by `Δx` and which turned by `θ` relative
//!   to the reference, that is `|Δx| + 2ρ·sin(θ/2)` (an upper bound, reached when the turn
//!   carries a point along `Δx`), so a wheel turning about a fixed axis counts its rim's error;
//! - **orientation error**: the largest angle between a part's orientations in the two runs,
//!   degrees;
//! - per CONTACT: the peak of its resultant force on I (normal plus friction) and its impulse
//!   (the force's magnitude integrated over the output frames by the trapezoidal rule), each
//!   with its error relative to the reference's (none when the reference's is 0); its onsets
//!   (a frame touching after one that did not) and releases, counted, and the largest time
//!   from a reference onset (release) to the candidate's nearest one (so an extra or a
//!   missing event shifts no other pairing; the counts show it). Onsets and releases are found
//!   between output frames and timed inside them from the deepest point's penetration and
//!   rate at the frame where the contact touches, `t − δ/δ̇` (first order: exact for a
//!   penetration linear in time);
//! - the wall time per simulated second (the analyses' wall time, one thread; the model's
//!   lowering and engine preparation are reported apart).
//!
//! [`select_run`] picks the fastest candidate whose run completed within the target, with the
//! same rule as the per-query [`super::select`]: the exact engine if it meets the target, the
//! faceted engine at its smallest tolerance that does, the faster of the two (the exact engine
//! on a tie), so timing noise never picks a finer tolerance than needed.

use super::integration::{Integration, converge_reference};
use super::reference_run::{RecordError, RunRecord, Setting, TouchingPose, record_run};
use crate::model::Model;
use crate::scenes::{from_model, support};
use contact_core::{FacetingTolerance, GeometryLibrary, Vector3};
use serde::Serialize;
use std::path::Path;

/// One CONTACT of a candidate run against the reference run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactRunErrors {
    /// The contact (`CONTACT/id`).
    pub contact: String,
    /// Its largest resultant force on I over the run (model force units).
    pub peak_force: f64,
    /// `|peak − reference peak| / reference peak`; `None` when the reference never pushed.
    pub peak_force_error: Option<f64>,
    /// Its impulse over the run (force × time).
    pub impulse: f64,
    /// `|impulse − reference impulse| / reference impulse`; `None` when the reference's is 0.
    pub impulse_error: Option<f64>,
    /// Onsets in this run.
    pub onsets: usize,
    /// Onsets in the reference run.
    pub reference_onsets: usize,
    /// The largest time from a reference onset to this run's nearest onset, seconds; `None`
    /// when either run has none.
    pub onset_time_error: Option<f64>,
    /// Releases in this run.
    pub releases: usize,
    /// Releases in the reference run.
    pub reference_releases: usize,
    /// The largest time from a reference release to this run's nearest release, seconds.
    pub release_time_error: Option<f64>,
}

/// One candidate's whole run against the reference run. The JSON schema of `contact select
/// --json`'s `runs.rows` (see the README).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunRow {
    /// The engine and tolerance.
    #[serde(flatten)]
    pub setting: Setting,
    /// True for the reference run itself (its errors are 0 by definition).
    pub reference: bool,
    /// Why the run stopped early, if it did (its errors cover the frames it reached, and it
    /// never meets a target).
    pub failure: Option<String>,
    /// Output frames compared (the frames both runs have).
    pub frames_compared: usize,
    /// The run error: the largest displacement of a point of a part within its contact
    /// radius, over time and parts, relative to the model's size (see the module docs).
    pub position_error: f64,
    /// Largest part orientation error over time and parts, degrees.
    pub orientation_error_deg: f64,
    /// Wall time of the analyses per simulated second, ms.
    pub wall_ms_per_simulated_s: f64,
    /// Wall time of lowering the model (engine preparation included), ms.
    pub prepare_ms: f64,
    /// True when its run error is within the integration floor
    /// ([`Integration::floor`]): this candidate is not told apart from the reference.
    pub within_floor: bool,
    /// Per CONTACT, in model order.
    pub contacts: Vec<ContactRunErrors>,
}

impl RunRow {
    /// True when the run completed and its run error is within `max_run_error`.
    pub fn meets(&self, max_run_error: f64) -> bool {
        self.failure.is_none() && self.position_error <= max_run_error
    }
}

/// The lengths the run errors are measured with.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelScale {
    /// The model's size: the diagonal of the box around every bounded contact geometry at the
    /// initial configuration and every moving part's centre of mass over the reference run.
    pub size: f64,
    /// Per moving part (in the run's order), its contact radius ρ: the farthest a corner of
    /// the world box of one of its bounded contact geometries is from its centre of mass at
    /// the start (0 for a part without contact geometry).
    pub part_radii: Vec<f64>,
}

/// Every candidate's run against the reference.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunTrade {
    /// The reference run's setting.
    pub reference: Setting,
    /// The model's size and its parts' contact radii ([`model_scale`]).
    pub scale: ModelScale,
    /// Simulated time of the reference run, seconds.
    pub simulated_s: f64,
    /// How tightly the compared runs were integrated.
    pub integration: Integration,
    /// One row per candidate: the exact engine (when it is a candidate), then the faceted
    /// engine by tolerance.
    pub rows: Vec<RunRow>,
}

/// Why the whole-run trade could not be measured.
#[derive(Debug, thiserror::Error)]
pub enum RunTradeError {
    /// The model's contacts could not be read (for its size).
    #[error(transparent)]
    Scenes(#[from] crate::scenes::ModelSceneError),
    /// A candidate's run could not start.
    #[error(transparent)]
    Record(#[from] RecordError),
    /// The model has no size to measure errors against.
    #[error("the model has no extent: no moving part and no bounded contact geometry")]
    NoSize,
    /// No contact touched in the reference run: the candidates' runs could differ only in
    /// round-off, which is no evidence for any engine or tolerance.
    #[error(
        "no contact in the reference run ({run}): the runs cannot tell the engines apart, so \
         nothing can be recommended (run longer, or start the parts closer)"
    )]
    NothingTouched {
        /// The reference run's setting, described.
        run: String,
    },
}

/// The model's size and each moving part's contact radius, from the model's contact geometry
/// at its initial configuration and the reference run (see [`ModelScale`]).
pub fn model_scale(model: &Model, reference: &RunRecord) -> Result<ModelScale, RunTradeError> {
    let mut lo = Vector3::repeat(f64::INFINITY);
    let mut hi = Vector3::repeat(f64::NEG_INFINITY);
    for frame in &reference.part_poses {
        for pose in frame {
            lo = lo.inf(&pose.translation.vector);
            hi = hi.sup(&pose.translation.vector);
        }
    }
    let mut part_radii = vec![0.0_f64; reference.parts.len()];
    let start = reference.part_poses.first();
    let scenes = if model.contacts.is_empty() {
        Vec::new()
    } else {
        from_model(model)?
    };
    for (scene, c) in scenes.iter().zip(&model.contacts) {
        let Some(initial) = scene.poses.first() else {
            continue;
        };
        let placed = scene
            .i
            .iter()
            .map(|g| (g, initial.pose_world_i, c.i_part))
            .chain(scene.j.iter().map(|g| (g, initial.pose_world_j, c.j_part)));
        for (g, pose, part) in placed {
            let at = pose * g.pose_part_geometry;
            let (mut glo, mut ghi) = (Vector3::zeros(), Vector3::zeros());
            let bounded = (0..3).all(|k| {
                let e = Vector3::ith(k, 1.0);
                match (
                    support(&g.geometry, &at, &e),
                    support(&g.geometry, &at, &-e),
                ) {
                    (Some(h), Some(l)) => {
                        ghi[k] = h;
                        glo[k] = -l;
                        true
                    }
                    _ => false,
                }
            });
            if !bounded {
                continue;
            }
            lo = lo.inf(&glo);
            hi = hi.sup(&ghi);
            let index = reference.parts.iter().position(|&p| p == part);
            if let (Some(index), Some(start)) = (index, start) {
                let centre = start[index].translation.vector;
                let reach = (0..8)
                    .map(|corner| {
                        let pick = |k: usize| {
                            if corner & (1 << k) == 0 {
                                glo[k]
                            } else {
                                ghi[k]
                            }
                        };
                        (Vector3::new(pick(0), pick(1), pick(2)) - centre).norm()
                    })
                    .fold(0.0, f64::max);
                part_radii[index] = part_radii[index].max(reach);
            }
        }
    }
    let size = (hi - lo).norm();
    if size.is_finite() && size > 0.0 {
        Ok(ModelScale { size, part_radii })
    } else {
        Err(RunTradeError::NoSize)
    }
}

/// Holds `candidate` to `reference` (two runs of one model) with `scale` (see the module
/// docs).
pub fn compare_runs(reference: &RunRecord, candidate: &RunRecord, scale: &ModelScale) -> RunRow {
    let pairs = common_frames(&reference.times, &candidate.times);
    let (mut position, mut orientation) = (0.0_f64, 0.0_f64);
    for &(r, c) in &pairs {
        let poses = reference.part_poses[r].iter().zip(&candidate.part_poses[c]);
        for (k, (a, b)) in poses.enumerate() {
            if a == b {
                continue;
            }
            let turn = a.rotation.angle_to(&b.rotation);
            let rho = scale.part_radii.get(k).copied().unwrap_or(0.0);
            let moved = (a.translation.vector - b.translation.vector).norm();
            position = position.max(moved + 2.0 * rho * (0.5 * turn).sin());
            orientation = orientation.max(turn);
        }
    }
    let contacts = reference
        .contacts
        .iter()
        .enumerate()
        .map(|(k, name)| contact_errors(name, k, reference, candidate))
        .collect();
    RunRow {
        setting: candidate.setting,
        reference: candidate.setting == reference.setting,
        failure: candidate.failure.clone(),
        frames_compared: pairs.len(),
        position_error: position / scale.size,
        orientation_error_deg: orientation.to_degrees(),
        wall_ms_per_simulated_s: 1e3 * candidate.wall_per_simulated_s(),
        prepare_ms: 1e3 * candidate.prepare_s,
        within_floor: false,
        contacts,
    }
}

/// Index pairs `(reference, candidate)` of the frames at the same time.
fn common_frames(reference: &[f64], candidate: &[f64]) -> Vec<(usize, usize)> {
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()));
    let (mut r, mut c, mut out) = (0, 0, Vec::new());
    while r < reference.len() && c < candidate.len() {
        if same(reference[r], candidate[c]) {
            out.push((r, c));
            r += 1;
            c += 1;
        } else if reference[r] < candidate[c] {
            r += 1;
        } else {
            c += 1;
        }
    }
    out
}

/// A contact's force and events in one run.
struct ContactHistory {
    peak: f64,
    impulse: f64,
    onsets: Vec<f64>,
    releases: Vec<f64>,
}

fn history(run: &RunRecord, k: usize) -> ContactHistory {
    let force = |i: usize| run.contact_forces[i].get(k).copied().unwrap_or(0.0);
    let touched: &[TouchingPose] = run.touching.get(k).map_or(&[], Vec::as_slice);
    let at = |t: f64| {
        touched
            .binary_search_by(|p| p.t.total_cmp(&t))
            .ok()
            .map(|i| &touched[i])
    };
    let mut h = ContactHistory {
        peak: 0.0,
        impulse: 0.0,
        onsets: Vec::new(),
        releases: Vec::new(),
    };
    for i in 0..run.times.len() {
        h.peak = h.peak.max(force(i));
        if i > 0 {
            let dt = run.times[i] - run.times[i - 1];
            h.impulse += 0.5 * dt * (force(i) + force(i - 1));
            let (before, after) = (run.times[i - 1], run.times[i]);
            match (at(before), at(after)) {
                (None, Some(p)) => h.onsets.push(event_time(p, -1.0, before, after)),
                (Some(p), None) => h.releases.push(event_time(p, 1.0, before, after)),
                _ => {}
            }
        }
    }
    h
}

/// When the contact touched at `p` began (`direction` −1: before `p`) or ended (+1: after
/// it), from its penetration and rate at `p` as the solver's onset prediction does:
/// `p.t − δ/δ̇` or `p.t + δ/(−δ̇)`, clamped to the frames `[before, after]` around the event;
/// the frame after it where the rate says nothing (a contact not approaching at its onset).
fn event_time(p: &TouchingPose, direction: f64, before: f64, after: f64) -> f64 {
    let closing = -direction * p.penetration_rate;
    if closing > 0.0 && p.penetration.is_finite() {
        (p.t + direction * p.penetration / closing).clamp(before, after)
    } else {
        after
    }
}

fn contact_errors(
    name: &str,
    k: usize,
    reference: &RunRecord,
    candidate: &RunRecord,
) -> ContactRunErrors {
    let (r, c) = (history(reference, k), history(candidate, k));
    let relative = |x: f64, x_ref: f64| (x_ref > 0.0).then(|| (x - x_ref).abs() / x_ref);
    // Each reference event to the candidate's nearest event of the same kind: an extra or a
    // missing event then shifts no other pairing.
    let paired = |candidate: &[f64], reference: &[f64]| {
        reference
            .iter()
            .filter_map(|t_ref| candidate.iter().map(|t| (t - t_ref).abs()).reduce(f64::min))
            .reduce(f64::max)
    };
    ContactRunErrors {
        contact: name.to_string(),
        peak_force: c.peak,
        peak_force_error: relative(c.peak, r.peak),
        impulse: c.impulse,
        impulse_error: relative(c.impulse, r.impulse),
        onsets: c.onsets.len(),
        reference_onsets: r.onsets.len(),
        onset_time_error: paired(&c.onsets, &r.onsets),
        releases: c.releases.len(),
        reference_releases: r.releases.len(),
        release_time_error: paired(&c.releases, &r.releases),
    }
}

/// Runs `model` (read from `source`) with every candidate — the exact engine when the
/// reference run is the exact engine's (it then answers every contact), and the faceted
/// engine at each of `tolerances` — up to `end` when given, and holds each to `reference`
/// (a run of that model at its own ERROR, [`super::record_reference`]) converged to `goal`
/// ([`converge_reference`]): each candidate runs twice, at the model's own ERROR for its wall
/// time and at the converged ERROR for its errors (once when those are the same). `progress`
/// hears each run before it starts. A reference run in which no contact touched is
/// [`RunTradeError::NothingTouched`]: nothing is run.
pub fn trade_runs(
    model: &Model,
    source: &Path,
    reference: &RunRecord,
    tolerances: &[FacetingTolerance],
    end: Option<f64>,
    goal: f64,
    progress: &mut dyn FnMut(&str),
) -> Result<RunTrade, RunTradeError> {
    if reference.touching.iter().all(Vec::is_empty) {
        return Err(RunTradeError::NothingTouched {
            run: reference.setting.describe(),
        });
    }
    let scale = model_scale(model, reference)?;
    let (converged, integration) =
        converge_reference(model, source, end, reference, &scale, goal, progress)?;
    let mut candidates = Vec::new();
    if reference.setting.engine == GeometryLibrary::Exact {
        candidates.push(Setting::EXACT);
    }
    let mut sorted = tolerances.to_vec();
    sorted.sort_by(|a, b| a.value().total_cmp(&b.value()));
    sorted.dedup();
    candidates.extend(sorted.into_iter().map(Setting::faceted));
    let mut rows = Vec::with_capacity(candidates.len());
    for setting in candidates {
        let (timed, held) = if setting == reference.setting {
            (reference.clone(), converged.clone())
        } else {
            progress(&format!("run with {}", setting.describe()));
            let timed = record_run(model, source, setting, end, 1.0)?;
            let held = if integration.error_scale == 1.0 {
                timed.clone()
            } else {
                progress(&format!(
                    "run with {} at {:e} of the model's integrator ERROR",
                    setting.describe(),
                    integration.error_scale
                ));
                record_run(model, source, setting, end, integration.error_scale)?
            };
            (timed, held)
        };
        let mut row = compare_runs(&converged, &held, &scale);
        row.failure = timed.failure.clone().or_else(|| {
            held.failure.as_ref().map(|f| {
                format!(
                    "at {:e} of the model's integrator ERROR: {f}",
                    integration.error_scale
                )
            })
        });
        row.within_floor =
            !row.reference && integration.floor.is_some_and(|f| row.position_error <= f);
        row.wall_ms_per_simulated_s = 1e3 * timed.wall_per_simulated_s();
        row.prepare_ms = 1e3 * timed.prepare_s;
        rows.push(row);
    }
    Ok(RunTrade {
        reference: reference.setting,
        scale,
        simulated_s: reference.simulated_s,
        integration,
        rows,
    })
}

/// The whole-run recommendation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunChoice {
    /// The target: largest run (position) error, relative to the model's size.
    pub max_run_error: f64,
    /// The chosen engine and tolerance.
    #[serde(flatten)]
    pub setting: Setting,
    /// Its run error.
    pub position_error: f64,
    /// Its wall time per simulated second, ms.
    pub wall_ms_per_simulated_s: f64,
    /// True when the choice is the reference run itself.
    pub reference: bool,
}

/// Why no candidate run meets the target.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "no engine and faceting tolerance meets a run error of {max_run_error:e} (best measured: {})",
    best.map_or_else(|| "no completed run".to_string(), |e| format!("{e:.2e}"))
)]
pub struct NoRunRecommendation {
    /// The target.
    pub max_run_error: f64,
    /// The smallest run error of a completed run, if any completed.
    pub best: Option<f64>,
}

/// The fastest candidate meeting `max_run_error` (see the module docs for the rule).
pub fn select_run(rows: &[RunRow], max_run_error: f64) -> Result<RunChoice, NoRunRecommendation> {
    let meeting = |engine: GeometryLibrary| {
        rows.iter()
            .filter(move |r| r.setting.engine == engine && r.meets(max_run_error))
    };
    let exact = meeting(GeometryLibrary::Exact).next();
    let faceted = meeting(GeometryLibrary::Faceted).min_by(|a, b| {
        let t = |r: &RunRow| r.setting.faceting_tolerance.unwrap_or(0.0);
        t(a).total_cmp(&t(b))
    });
    let best = match (exact, faceted) {
        (Some(e), Some(f)) => {
            if f.wall_ms_per_simulated_s < e.wall_ms_per_simulated_s {
                Some(f)
            } else {
                Some(e)
            }
        }
        (e, f) => e.or(f),
    };
    best.map(|r| RunChoice {
        max_run_error,
        setting: r.setting,
        position_error: r.position_error,
        wall_ms_per_simulated_s: r.wall_ms_per_simulated_s,
        reference: r.reference,
    })
    .ok_or_else(|| NoRunRecommendation {
        max_run_error,
        best: rows
            .iter()
            .filter(|r| r.failure.is_none())
            .map(|r| r.position_error)
            .min_by(f64::total_cmp),
    })
}

#[cfg(test)]
#[path = "whole_run_tests.rs"]
mod tests;
