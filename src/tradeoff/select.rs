//! Choosing an engine and tolerance from measured rows: the fastest that meets an accuracy
//! target, per contact and for the whole model.

use super::measure::TradeRecord;
use serde::Serialize;

/// A recommendation for one contact (or scene).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Choice {
    /// The contact or scene.
    pub contact: String,
    /// `exact` or `faceted`.
    pub engine: String,
    /// The tolerance, for the faceted engine.
    pub faceting_tolerance: Option<f64>,
    /// Its measured median query time, ns.
    pub query_ns_median: f64,
    /// Its measured depth error (relative to the contact's scale).
    pub depth_error: f64,
}

/// The model-wide recommendation: one engine (PREFERENCES is model-wide) and the tolerance
/// that meets the target on every contact at the least total query time.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelChoice {
    /// `exact` or `faceted`.
    pub engine: String,
    /// The tolerance, for the faceted engine.
    pub faceting_tolerance: Option<f64>,
    /// Sum over the contacts of their median query times, ns.
    pub total_query_ns: f64,
    /// The worst depth error over the contacts.
    pub worst_depth_error: f64,
}

/// True when a row meets the target: it has a reference and its depth error is within
/// `max_depth_error`. A missed or extra contact already counts its whole depth in that error,
/// so a miss on a pose shallower than the target is acceptable and a deeper one is not.
pub fn meets(record: &TradeRecord, max_depth_error: f64) -> bool {
    record.depth_error.is_some_and(|e| e <= max_depth_error)
}

/// The recommendation for `contact`: the exact engine if it meets the target, and the faceted
/// engine at its *smallest* tolerance that meets it (a finer tolerance never costs less: more
/// triangles); of those two candidates, the faster. Timing noise therefore never picks a finer
/// tolerance than needed. Peers are for comparison only.
pub fn select(records: &[TradeRecord], contact: &str, max_depth_error: f64) -> Option<Choice> {
    let meeting = |engine: &'static str| {
        records
            .iter()
            .filter(move |r| r.scene == contact && r.engine == engine && meets(r, max_depth_error))
    };
    let exact = meeting("exact").next();
    let faceted = meeting("faceted").min_by(|a, b| {
        a.faceting_tolerance
            .unwrap_or(0.0)
            .total_cmp(&b.faceting_tolerance.unwrap_or(0.0))
    });
    let best = match (exact, faceted) {
        (Some(e), Some(f)) => Some(if f.query_ns_median < e.query_ns_median {
            f
        } else {
            e
        }),
        (e, f) => e.or(f),
    }?;
    Some(Choice {
        contact: best.scene.clone(),
        engine: best.engine.clone(),
        faceting_tolerance: best.faceting_tolerance,
        query_ns_median: best.query_ns_median,
        depth_error: best.depth_error.unwrap_or(f64::NAN),
    })
}

/// The engine and tolerance meeting the target on every contact in `contacts` at the least
/// total time; `None` when no single setting meets it everywhere. As in [`select`], an engine
/// with tolerances is a candidate only at its smallest tolerance meeting the target
/// everywhere (a finer tolerance never costs less), so timing noise never picks a finer one.
pub fn select_model(
    records: &[TradeRecord],
    contacts: &[String],
    max_depth_error: f64,
) -> Option<ModelChoice> {
    let mut settings: Vec<(String, Option<f64>)> = records
        .iter()
        .filter(|r| selectable(r))
        .map(|r| (r.engine.clone(), r.faceting_tolerance))
        .collect();
    settings.sort_by(|a, b| {
        a.0.cmp(&b.0)
            .then(a.1.unwrap_or(0.0).total_cmp(&b.1.unwrap_or(0.0)))
    });
    settings.dedup();
    let mut candidates = settings
        .into_iter()
        .filter_map(|(engine, tolerance)| {
            let rows: Vec<&TradeRecord> = contacts
                .iter()
                .filter_map(|c| {
                    records.iter().find(|r| {
                        &r.scene == c && r.engine == engine && r.faceting_tolerance == tolerance
                    })
                })
                .collect();
            let complete =
                rows.len() == contacts.len() && rows.iter().all(|r| meets(r, max_depth_error));
            complete.then(|| ModelChoice {
                engine,
                faceting_tolerance: tolerance,
                total_query_ns: rows.iter().map(|r| r.query_ns_median).sum(),
                worst_depth_error: rows
                    .iter()
                    .filter_map(|r| r.depth_error)
                    .fold(0.0, f64::max),
            })
        })
        .collect::<Vec<_>>();
    // Sorted by engine, then tolerance: the first complete setting of each engine is its
    // smallest sufficient tolerance.
    candidates.dedup_by(|later, first| later.engine == first.engine);
    candidates
        .into_iter()
        .min_by(|a, b| a.total_query_ns.total_cmp(&b.total_query_ns))
}

/// A recommendation for every contact of a model and for the model as a whole.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Recommendation {
    /// The target: largest depth error, relative to each contact's size.
    pub max_depth_error: f64,
    /// The fastest setting meeting the target, per contact, in the order asked.
    pub contacts: Vec<Choice>,
    /// One engine and tolerance for the whole model (PREFERENCES is model-wide).
    pub model: ModelChoice,
}

/// Why no recommendation exists.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NoRecommendation {
    /// No measured setting meets the target on this contact.
    #[error(
        "{contact}: no engine and faceting tolerance meets a depth error of {max_depth_error:e} \
         (best measured: {})",
        best.map_or_else(|| "none with a reference".to_string(), |e| format!("{e:.2e}"))
    )]
    Contact {
        /// The contact (scene) name.
        contact: String,
        /// The target.
        max_depth_error: f64,
        /// The smallest depth error any exact or faceted row reached on it, if any had a
        /// reference.
        best: Option<f64>,
    },
    /// Every contact has a setting, but no single one serves them all.
    #[error(
        "no single engine and faceting tolerance meets a depth error of {max_depth_error:e} on \
         every contact: {}",
        .choices.join(", ")
    )]
    Model {
        /// The target.
        max_depth_error: f64,
        /// Each contact's own choice, as `contact: engine FT`.
        choices: Vec<String>,
    },
    /// No contact of the model touched in the reference run: nothing was measured.
    #[error(
        "no contact in the reference run ({run}): no contact was measured, so nothing can be \
         recommended (run longer, or start the parts closer)"
    )]
    NothingTouched {
        /// The reference run's setting, described.
        run: String,
    },
}

/// The recommendation for `contacts` from measured rows: [`select`] per contact, then
/// [`select_model`]. The first contact without a setting that meets the target is the error.
pub fn recommend(
    records: &[TradeRecord],
    contacts: &[String],
    max_depth_error: f64,
) -> Result<Recommendation, NoRecommendation> {
    let choices = contacts
        .iter()
        .map(|c| {
            select(records, c, max_depth_error).ok_or_else(|| NoRecommendation::Contact {
                contact: c.clone(),
                max_depth_error,
                best: records
                    .iter()
                    .filter(|r| &r.scene == c && selectable(r))
                    .filter_map(|r| r.depth_error)
                    .min_by(f64::total_cmp),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    let model = select_model(records, contacts, max_depth_error).ok_or_else(|| {
        NoRecommendation::Model {
            max_depth_error,
            choices: choices.iter().map(Choice::describe).collect(),
        }
    })?;
    Ok(Recommendation {
        max_depth_error,
        contacts: choices,
        model,
    })
}

impl Choice {
    /// `contact: engine` or `contact: faceted FT t`.
    pub fn describe(&self) -> String {
        match self.faceting_tolerance {
            Some(t) => format!("{}: {} FT {t}", self.contact, self.engine),
            None => format!("{}: {}", self.contact, self.engine),
        }
    }
}

fn selectable(r: &TradeRecord) -> bool {
    r.engine == "exact" || r.engine == "faceted"
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tradeoff::measure::{ReferenceSource, WorkPerQuery};

    fn row(scene: &str, engine: &str, ft: Option<f64>, err: f64, ns: f64) -> TradeRecord {
        TradeRecord {
            scene: scene.into(),
            engine: engine.into(),
            faceting_tolerance: ft,
            reference: ReferenceSource::ClosedForm,
            depth_error: Some(err),
            normal_error_deg: Some(0.0),
            point_error: Some(0.0),
            resolved_depth: 0.0,
            resolved_contacts: 1,
            missed_contacts: 0,
            extra_contacts: 0,
            query_ns_median: ns,
            query_ns_p95: ns,
            prepare_ms: 0.0,
            prepared_bytes: 0,
            triangles: 0,
            poses: 1,
            work: WorkPerQuery::default(),
        }
    }

    #[test]
    fn exact_wins_when_faster_and_more_accurate() {
        let rows = vec![
            row("a", "exact", None, 1e-13, 40.0),
            row("a", "faceted", Some(300.0), 5e-3, 900.0),
            row("a", "faceted", Some(1000.0), 5e-4, 2500.0),
            row("a", "parry", None, 1e-3, 10.0),
        ];
        let c = select(&rows, "a", 0.01).unwrap();
        assert_eq!((c.engine.as_str(), c.faceting_tolerance), ("exact", None));
    }

    #[test]
    fn faceted_at_the_smallest_sufficient_tolerance_when_faster() {
        let rows = vec![
            row("m", "exact", None, 1e-12, 90_000.0),
            row("m", "faceted", Some(100.0), 2e-2, 500.0),
            row("m", "faceted", Some(300.0), 6e-3, 800.0),
            row("m", "faceted", Some(1000.0), 2e-3, 2000.0),
        ];
        let c = select(&rows, "m", 0.01).unwrap();
        assert_eq!(
            (c.engine.as_str(), c.faceting_tolerance),
            ("faceted", Some(300.0))
        );
        assert!(select(&rows, "m", 1e-14).is_none());
        // Model-wide: one setting for both contacts at the least total time.
        let mut all = rows.clone();
        all.extend([
            row("a", "exact", None, 1e-13, 40.0),
            row("a", "faceted", Some(300.0), 9e-3, 700.0),
        ]);
        all.push(row("a", "faceted", Some(1000.0), 1e-3, 1500.0));
        let model = select_model(&all, &["m".into(), "a".into()], 0.01).unwrap();
        assert_eq!(
            (model.engine.as_str(), model.faceting_tolerance),
            ("faceted", Some(300.0))
        );
        assert_eq!(model.total_query_ns, 1500.0);
        // A finer tolerance measured faster (timing noise) is not taken for the model.
        let noisy = vec![
            row("m", "exact", None, 1e-12, 90_000.0),
            row("m", "faceted", Some(100.0), 4e-3, 900.0),
            row("m", "faceted", Some(300.0), 2e-3, 600.0),
        ];
        let model = select_model(&noisy, &["m".into()], 0.01).unwrap();
        assert_eq!(model.faceting_tolerance, Some(100.0));
        assert_eq!(
            select(&noisy, "m", 0.01).unwrap().faceting_tolerance,
            Some(100.0)
        );
    }

    #[test]
    fn recommend_breaks_ties_towards_exact_and_names_the_contact_without_a_candidate() {
        // A tie in time: the exact engine (its error is the smaller by construction).
        let tie = vec![
            row("t", "exact", None, 1e-12, 700.0),
            row("t", "faceted", Some(100.0), 4e-3, 700.0),
        ];
        let r = recommend(&tie, &["t".into()], 0.01).unwrap();
        assert_eq!(r.contacts[0].engine, "exact");
        assert_eq!(
            (r.model.engine.as_str(), r.model.total_query_ns),
            ("exact", 700.0)
        );
        // Two faceted tolerances meeting the target at the same time: the smaller.
        let level = vec![
            row("f", "faceted", Some(300.0), 1e-3, 500.0),
            row("f", "faceted", Some(100.0), 2e-3, 500.0),
        ];
        let r = recommend(&level, &["f".into()], 0.01).unwrap();
        assert_eq!(r.contacts[0].faceting_tolerance, Some(100.0));
        assert_eq!(r.model.faceting_tolerance, Some(100.0));
        // No candidate: the first contact without one is named, with the best error seen.
        let mut rows = tie.clone();
        rows.push(row("u", "faceted", Some(100.0), 3e-2, 10.0));
        rows.push(row("u", "parry", None, 1e-6, 5.0));
        let e = recommend(&rows, &["t".into(), "u".into()], 0.01).unwrap_err();
        assert_eq!(
            e,
            NoRecommendation::Contact {
                contact: "u".into(),
                max_depth_error: 0.01,
                best: Some(3e-2),
            }
        );
        assert_eq!(
            e.to_string(),
            "u: no engine and faceting tolerance meets a depth error of 1e-2 (best measured: 3.00e-2)"
        );
        // Rows without a reference (no depth error measured): the message says so.
        let mut unmeasured = row("v", "faceted", Some(100.0), 0.0, 10.0);
        unmeasured.depth_error = None;
        let e = recommend(&[unmeasured], &["v".into()], 0.01).unwrap_err();
        assert_eq!(
            e.to_string(),
            "v: no engine and faceting tolerance meets a depth error of 1e-2 (best measured: none with a reference)"
        );
        // Each contact has a setting but no single one serves both.
        let split = vec![
            row("a", "exact", None, 1e-12, 100.0),
            row("b", "faceted", Some(100.0), 1e-3, 100.0),
        ];
        let e = recommend(&split, &["a".into(), "b".into()], 0.01).unwrap_err();
        assert!(matches!(e, NoRecommendation::Model { .. }), "{e}");
        assert!(
            e.to_string().ends_with("a: exact, b: faceted FT 100"),
            "{e}"
        );
    }
}
