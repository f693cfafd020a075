//! The sweep: every scene with the exact engine and the faceted engine at each tolerance, and
//! any peers, in one run so the rows compare on the same machine at the same time.

use super::measure::{Reference, Timing, TradeError, TradeRecord, measure};
use crate::scenes::Scene;
use contact_core::{FacetingTolerance, GeometryEngine, GeometryLibrary};
use serde::Serialize;

/// Adams' default tolerance and a decade either side: the default sweep.
pub const DEFAULT_TOLERANCES: [f64; 5] = [100.0, 300.0028, 1000.0, 3000.0, 10000.0];

/// What to run.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// Faceting tolerances for the faceted engine.
    pub tolerances: Vec<FacetingTolerance>,
    /// Query timing.
    pub timing: Timing,
}

impl Default for Sweep {
    fn default() -> Self {
        Self {
            tolerances: DEFAULT_TOLERANCES
                .iter()
                .filter_map(|&t| FacetingTolerance::new(t).ok())
                .collect(),
            timing: Timing::default(),
        }
    }
}

/// A scene an engine could not answer, reported beside the records.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Skipped {
    /// Scene name.
    pub scene: String,
    /// Engine name.
    pub engine: String,
    /// The faceting tolerance, if any.
    pub faceting_tolerance: Option<f64>,
}

/// The sweep's result.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TradeReport {
    /// One row per scene × engine × tolerance that ran.
    pub records: Vec<TradeRecord>,
    /// The combinations an engine does not support.
    pub skipped: Vec<Skipped>,
}

/// Builds an engine for a library and tolerance (the application's engine choice).
pub type EngineFactory<'a> =
    &'a dyn Fn(GeometryLibrary, FacetingTolerance) -> Box<dyn GeometryEngine>;

/// Runs the sweep over `scenes`: the exact engine, the faceted engine at every tolerance, then
/// each peer; `progress` hears each row's label before it is measured.
pub fn run(
    scenes: &[Scene],
    sweep: &Sweep,
    engines: EngineFactory<'_>,
    peers: &[&dyn GeometryEngine],
    progress: &mut dyn FnMut(&str),
) -> Result<TradeReport, TradeError> {
    let mut report = TradeReport::default();
    let exact = engines(GeometryLibrary::Exact, FacetingTolerance::DEFAULT);
    for scene in scenes {
        let reference = Reference::for_scene(scene, exact.as_ref())?;
        let mut one = |engine: &dyn GeometryEngine,
                       tolerance: Option<f64>,
                       report: &mut TradeReport|
         -> Result<(), TradeError> {
            let label = match tolerance {
                Some(t) => format!("{} / {} FT {t}", scene.name, engine.name()),
                None => format!("{} / {}", scene.name, engine.name()),
            };
            progress(&label);
            match measure(scene, engine, tolerance, &reference, &sweep.timing)? {
                Some(record) => report.records.push(record),
                None => report.skipped.push(Skipped {
                    scene: scene.name.to_string(),
                    engine: engine.name().to_string(),
                    faceting_tolerance: tolerance,
                }),
            }
            Ok(())
        };
        one(exact.as_ref(), None, &mut report)?;
        for &tolerance in &sweep.tolerances {
            let faceted = engines(GeometryLibrary::Faceted, tolerance);
            one(faceted.as_ref(), Some(tolerance.value()), &mut report)?;
        }
        for peer in peers {
            one(*peer, None, &mut report)?;
        }
    }
    Ok(report)
}
