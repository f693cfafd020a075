//! The trade and the recommendation for a model's own contacts: each CONTACT becomes a scene
//! ([`crate::scenes::from_model`]), the sweep measures it against the exact engine, and
//! [`recommend`] picks the fastest engine and tolerance that meets the target.

use super::select::{NoRecommendation, Recommendation, recommend};
use super::sweep::{EngineFactory, Sweep, TradeReport, run};
use crate::model::Model;
use crate::scenes::{ModelSceneError, from_model};
use contact_core::GeometryEngine;

/// The measured rows of a model's contacts and what they recommend.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelSelection {
    /// The contact names (`CONTACT/id`), in model order.
    pub contacts: Vec<String>,
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

/// Measures every contact of `model` with the exact engine and the faceted engine over
/// `sweep` (and `peers`, shown for comparison only) and recommends, per contact and for the
/// model, the fastest engine and faceting tolerance whose depth error — the largest over the
/// contact's poses, relative to the contact's size — is at most `max_depth_error`.
pub fn select_for_model(
    model: &Model,
    sweep: &Sweep,
    engines: EngineFactory<'_>,
    peers: &[&dyn GeometryEngine],
    max_depth_error: f64,
    progress: &mut dyn FnMut(&str),
) -> Result<ModelSelection, ModelTradeError> {
    if !(max_depth_error.is_finite() && max_depth_error > 0.0) {
        return Err(ModelTradeError::Target(max_depth_error));
    }
    let scenes = from_model(model)?;
    let report = run(&scenes, sweep, engines, peers, progress)?;
    let contacts: Vec<String> = scenes.iter().map(|s| s.name.to_string()).collect();
    let recommendation = recommend(&report.records, &contacts, max_depth_error);
    Ok(ModelSelection {
        contacts,
        report,
        recommendation,
    })
}
