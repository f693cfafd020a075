//! Measuring one engine (at one faceting tolerance) on one scene: errors against the reference,
//! query time, preparation time and size, work.

use super::band::resolved_depth;
use super::compare::{PoseErrors, compare};
use crate::scenes::Scene;
use contact_core::{
    Contact, FacetingTolerance, GeometryEngine, PrepareError, QueryError, WorkCounters,
};
use serde::Serialize;
use std::time::Instant;

/// Where a scene's reference answers come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ReferenceSource {
    /// The scene's closed form.
    ClosedForm,
    /// The exact engine.
    ExactEngine,
    /// No reference: errors are not reported.
    None,
}

/// The reference answers of a scene, one list per pose.
#[derive(Debug, Clone)]
pub struct Reference {
    /// Where they come from.
    pub source: ReferenceSource,
    /// The contacts at each pose (empty lists when `source` is `None`).
    pub answers: Vec<Vec<Contact>>,
}

impl Reference {
    /// The closed form if the scene has one, else the exact engine's answers (if it supports
    /// the scene), else none.
    pub fn for_scene(scene: &Scene, exact: &dyn GeometryEngine) -> Result<Self, TradeError> {
        if let Some(f) = scene.closed_form {
            return Ok(Self {
                source: ReferenceSource::ClosedForm,
                answers: scene.poses.iter().map(|p| f(scene, p)).collect(),
            });
        }
        let pair = match exact.prepare(&scene.i, &scene.j) {
            Ok(pair) => pair,
            Err(PrepareError::Unsupported(_)) => {
                return Ok(Self {
                    source: ReferenceSource::None,
                    answers: vec![Vec::new(); scene.poses.len()],
                });
            }
            Err(source) => {
                return Err(TradeError::Prepare {
                    scene: scene.name.to_string(),
                    engine: exact.name(),
                    source: Box::new(source),
                });
            }
        };
        let mut work = WorkCounters::default();
        let answers = scene
            .poses
            .iter()
            .map(|p| {
                let mut out = Vec::new();
                pair.query(&p.pose_world_i, &p.pose_world_j, &mut out, &mut work)
                    .map(|()| out)
                    .map_err(|source| TradeError::Query {
                        scene: scene.name.to_string(),
                        engine: exact.name(),
                        source: Box::new(source),
                    })
            })
            .collect::<Result<_, _>>()?;
        Ok(Self {
            source: ReferenceSource::ExactEngine,
            answers,
        })
    }
}

/// How long to time queries.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timing {
    /// Timed passes over all poses; each pose gives one sample per pass.
    pub rounds: usize,
    /// Each sample repeats its query until at least this many nanoseconds have passed, so that
    /// clock resolution and call overhead stay below 1% of fast queries.
    pub min_sample_ns: u64,
}

impl Default for Timing {
    fn default() -> Self {
        Self {
            rounds: 5,
            min_sample_ns: 20_000,
        }
    }
}

/// Average work per query.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct WorkPerQuery {
    /// Geometry pairs examined.
    pub geometry_pairs: f64,
    /// Bounding-volume tests.
    pub bounding_volume_tests: f64,
    /// Primitive tests (triangle pairs, analytic evaluations).
    pub primitive_tests: f64,
    /// Iterations of iterative methods.
    pub iterations: f64,
    /// Contacts returned.
    pub contacts: f64,
}

/// One row of the trade: a scene, an engine and its tolerance. The JSON schema of
/// `contact tradeoff --json` is an array of these (see the README).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TradeRecord {
    /// Scene name.
    pub scene: String,
    /// `exact`, `faceted`, or a peer's name (`parry`).
    pub engine: String,
    /// The faceting tolerance; `None` (JSON null) for engines without one.
    pub faceting_tolerance: Option<f64>,
    /// Where the reference answers came from.
    pub reference: ReferenceSource,
    /// Largest depth error over the poses, relative to the scene's scale (None: no reference).
    pub depth_error: Option<f64>,
    /// Largest normal error over the resolved contacts (reference depth above
    /// [`Self::resolved_depth`]), degrees; None without a reference or without a resolved
    /// contact.
    pub normal_error_deg: Option<f64>,
    /// Largest contact-point error over the resolved contacts, relative to the scene's scale.
    pub point_error: Option<f64>,
    /// The depth, relative to the scene's scale, above which a contact counts as resolved:
    /// [`RESOLVED_BANDS`](super::RESOLVED_BANDS) faceting bands
    /// ([`faceting_band`](super::faceting_band)), 0 for engines without facets.
    pub resolved_depth: f64,
    /// Matched reference contacts deeper than `resolved_depth`, summed over the poses.
    pub resolved_contacts: usize,
    /// Reference contacts not returned, summed over the poses.
    pub missed_contacts: usize,
    /// Contacts returned that the reference does not have, summed over the poses.
    pub extra_contacts: usize,
    /// Median time of one query, nanoseconds.
    pub query_ns_median: f64,
    /// 95th percentile time of one query, nanoseconds.
    pub query_ns_p95: f64,
    /// Time to prepare the pair, milliseconds.
    pub prepare_ms: f64,
    /// Heap bytes held by the prepared pair.
    pub prepared_bytes: usize,
    /// Triangles held by the prepared pair.
    pub triangles: usize,
    /// Poses measured.
    pub poses: usize,
    /// Average work per query.
    pub work: WorkPerQuery,
}

/// Why a measurement failed.
#[derive(Debug, thiserror::Error)]
pub enum TradeError {
    /// Preparing failed for a reason other than an unsupported pair.
    #[error("scene {scene}, {engine} engine: {source}")]
    Prepare {
        /// Scene name.
        scene: String,
        /// Engine name.
        engine: &'static str,
        /// The engine's error (boxed: it may carry a geometry's label).
        source: Box<PrepareError>,
    },
    /// A query failed.
    #[error("scene {scene}, {engine} engine: {source}")]
    Query {
        /// Scene name.
        scene: String,
        /// Engine name.
        engine: &'static str,
        /// The engine's error (boxed: query errors carry their reproducer).
        source: Box<QueryError>,
    },
}

/// Measures `engine` on `scene` against `reference`. `Ok(None)` when the engine does not
/// support the scene (the caller reports it as skipped).
pub fn measure(
    scene: &Scene,
    engine: &dyn GeometryEngine,
    faceting_tolerance: Option<f64>,
    reference: &Reference,
    timing: &Timing,
) -> Result<Option<TradeRecord>, TradeError> {
    let started = Instant::now();
    let pair = match engine.prepare(&scene.i, &scene.j) {
        Ok(pair) => pair,
        Err(PrepareError::Unsupported(_)) => return Ok(None),
        Err(source) => {
            return Err(TradeError::Prepare {
                scene: scene.name.to_string(),
                engine: engine.name(),
                source: Box::new(source),
            });
        }
    };
    let prepare_ms = started.elapsed().as_secs_f64() * 1e3;
    let stats = pair.stats();
    let query_error = |source: QueryError| TradeError::Query {
        scene: scene.name.to_string(),
        engine: engine.name(),
        source: Box::new(source),
    };

    // Accuracy and work: one untimed pass.
    let resolved = faceting_tolerance
        .and_then(|t| FacetingTolerance::new(t).ok())
        .map_or(0.0, |t| resolved_depth(&scene.i, &scene.j, t));
    let mut errors = PoseErrors::default();
    let mut work = WorkCounters::default();
    let mut out = Vec::new();
    for (pose, expected) in scene.poses.iter().zip(&reference.answers) {
        pair.query(&pose.pose_world_i, &pose.pose_world_j, &mut out, &mut work)
            .map_err(query_error)?;
        errors = errors.max(compare(&out, expected, scene.scale, resolved));
    }
    let n = scene.poses.len().max(1) as f64;
    let per_query = |c: u64| c as f64 / n;

    // Time: per pose, repeat until the sample is long enough; many samples per pose.
    let mut samples = Vec::with_capacity(scene.poses.len() * timing.rounds);
    let mut scratch = WorkCounters::default();
    for _ in 0..timing.rounds {
        for pose in &scene.poses {
            let mut reps = 0u64;
            let t0 = Instant::now();
            loop {
                pair.query(
                    &pose.pose_world_i,
                    &pose.pose_world_j,
                    &mut out,
                    &mut scratch,
                )
                .map_err(query_error)?;
                reps += 1;
                if t0.elapsed().as_nanos() as u64 >= timing.min_sample_ns {
                    break;
                }
            }
            samples.push(t0.elapsed().as_nanos() as f64 / reps as f64);
        }
    }
    samples.sort_by(f64::total_cmp);
    let has_reference = reference.source != ReferenceSource::None;
    Ok(Some(TradeRecord {
        scene: scene.name.to_string(),
        engine: engine.name().to_string(),
        faceting_tolerance,
        reference: reference.source,
        depth_error: has_reference.then_some(errors.depth),
        normal_error_deg: (has_reference && errors.resolved > 0).then_some(errors.normal_deg),
        point_error: (has_reference && errors.resolved > 0).then_some(errors.point),
        resolved_depth: resolved / scene.scale,
        resolved_contacts: errors.resolved,
        missed_contacts: errors.missed,
        extra_contacts: errors.extra,
        query_ns_median: percentile(&samples, 0.5),
        query_ns_p95: percentile(&samples, 0.95),
        prepare_ms,
        prepared_bytes: stats.bytes,
        triangles: stats.triangles,
        poses: scene.poses.len(),
        work: WorkPerQuery {
            geometry_pairs: per_query(work.geometry_pairs),
            bounding_volume_tests: per_query(work.bounding_volume_tests),
            primitive_tests: per_query(work.primitive_tests),
            iterations: per_query(work.iterations),
            contacts: per_query(work.contacts),
        },
    }))
}

/// The `q` quantile of sorted samples (nearest rank); NaN when empty.
pub fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let rank = (q * sorted.len() as f64).ceil() as usize;
    sorted[rank.clamp(1, sorted.len()) - 1]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_rank_percentiles() {
        let s: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(percentile(&s, 0.5), 50.0);
        assert_eq!(percentile(&s, 0.95), 95.0);
        assert_eq!(percentile(&s[..1], 0.95), 1.0);
        assert!(percentile(&[], 0.5).is_nan());
    }
}
