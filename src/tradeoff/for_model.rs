//! The per-query trade and its recommendation for a model's own contacts: each CONTACT that
//! touched in the reference run becomes a scene at the run's poses
//! ([`crate::scenes::from_run`]), the sweep measures it against the exact engine, and
//! [`recommend`] picks the fastest engine and tolerance that meets the target. A contact that
//! never touched is reported as such and never measured.

use super::reference_run::RunRecord;
use super::select::{NoRecommendation, Recommendation, recommend};
use super::sweep::{EngineFactory, Sweep, TradeReport, run};
use crate::model::Model;
use crate::scenes::{ModelSceneError, RUN_POSES_PER_CONTACT, from_run};
use contact_core::GeometryEngine;

/// The measured rows of a model's contacts and what they recommend.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelSelection {
    /// The names (`CONTACT/id`) of the contacts measured (those that touched in the reference
    /// run), in model order.
    pub contacts: Vec<String>,
    /// The contacts that never touched in the reference run: not measured.
    pub untouched: Vec<String>,
    /// The reference run's setting, described (`exact`, `faceted FT 10000`).
    pub reference_run: String,
    /// Every row measured (the evidence).
    pub report: TradeReport,
    /// The recommendation, or which contact has none.
    pub recommendation: Result<Recommendation, NoRecommendation>,
}

/// Why a model's trade could not be measured.
#[derive(Debug, thiserror::Error)]
pub enum ModelTradeError {
    /// The target is not a positive finite number.
    #[error(
        "--max-depth-error must be a positive finite number (relative to a contact's size), got {0}"
    )]
    Target(f64),
    /// A contact could not become a scene.
    #[error(transparent)]
    Scenes(#[from] ModelSceneError),
    /// A measurement failed.
    #[error(transparent)]
    Measure(#[from] super::TradeError),
}

/// Measures every contact of `model` that touched in `reference` (a run of that model,
/// [`super::record_run`]) at up to [`RUN_POSES_PER_CONTACT`] of its touching poses plus as
/// many spread ones, with the exact engine and the faceted engine over `sweep` (and `peers`,
/// shown for comparison only), and recommends, per contact and for the model, the fastest
/// engine and faceting tolerance whose depth error — the largest over the contact's poses,
/// relative to the contact's size — is at most `max_depth_error`. With no contact touching,
/// nothing is measured and there is no recommendation
/// ([`NoRecommendation::NothingTouched`]).
pub fn select_for_model(
    model: &Model,
    reference: &RunRecord,
    sweep: &Sweep,
    engines: EngineFactory<'_>,
    peers: &[&dyn GeometryEngine],
    max_depth_error: f64,
    progress: &mut dyn FnMut(&str),
) -> Result<ModelSelection, ModelTradeError> {
    if !(max_depth_error.is_finite() && max_depth_error > 0.0) {
        return Err(ModelTradeError::Target(max_depth_error));
    }
    let scenes = from_run(model, reference, RUN_POSES_PER_CONTACT)?;
    let report = run(&scenes.scenes, sweep, engines, peers, progress)?;
    let contacts: Vec<String> = scenes.scenes.iter().map(|s| s.name.to_string()).collect();
    let recommendation = if contacts.is_empty() {
        Err(NoRecommendation::NothingTouched {
            run: reference.setting.describe(),
        })
    } else {
        recommend(&report.records, &contacts, max_depth_error)
    };
    Ok(ModelSelection {
        contacts,
        untouched: scenes.untouched,
        reference_run: reference.setting.describe(),
        report,
        recommendation,
    })
}
