//! Writing the trade: a text table, CSV, JSON and an error-against-time plot.

use super::measure::{ReferenceSource, TradeRecord};
use crate::svg_plot::{Plot, Scale, Series};
use std::fmt::Write;

fn opt(v: Option<f64>) -> String {
    v.map_or_else(|| "-".to_string(), |x| format!("{x:.2e}"))
}

/// A fixed-width table, one row per record, for terminals and the README. `ref` says what the
/// errors are measured against: the scene's closed form, the exact engine (whose own errors are
/// then 0 by definition), or nothing.
pub fn table(records: &[TradeRecord]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<27} {:<8} {:>9} {:<7} {:>10} {:>10} {:>10} {:>6} {:>11} {:>11} {:>9} {:>9}",
        "scene",
        "engine",
        "FT",
        "ref",
        "depth err",
        "normal °",
        "point err",
        "missed",
        "median ns",
        "p95 ns",
        "prep ms",
        "triangles"
    );
    for r in records {
        let ft = r
            .faceting_tolerance
            .map_or_else(|| "-".to_string(), |t| format!("{t}"));
        let _ = writeln!(
            out,
            "{:<27} {:<8} {:>9} {:<7} {:>10} {:>10} {:>10} {:>6} {:>11.0} {:>11.0} {:>9.3} {:>9}",
            r.scene,
            r.engine,
            ft,
            match r.reference {
                ReferenceSource::ClosedForm => "closed",
                ReferenceSource::ExactEngine => "exact",
                ReferenceSource::None => "none",
            },
            opt(r.depth_error),
            opt(r.normal_error_deg),
            opt(r.point_error),
            r.missed_contacts,
            r.query_ns_median,
            r.query_ns_p95,
            r.prepare_ms,
            r.triangles
        );
    }
    out
}

/// CSV with a header; empty fields where a value does not apply.
pub fn csv(records: &[TradeRecord]) -> String {
    let mut out = String::from(
        "scene,engine,faceting_tolerance,reference,depth_error,normal_error_deg,point_error,resolved_depth,resolved_contacts,missed_contacts,extra_contacts,query_ns_median,query_ns_p95,prepare_ms,prepared_bytes,triangles,poses,geometry_pairs_per_query,bounding_volume_tests_per_query,primitive_tests_per_query,iterations_per_query,contacts_per_query\n",
    );
    let f = |v: Option<f64>| v.map_or_else(String::new, |x| format!("{x:?}"));
    for r in records {
        let reference = serde_json::to_value(r.reference)
            .ok()
            .and_then(|v| v.as_str().map(str::to_string))
            .unwrap_or_default();
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{:?},{},{},{},{:?},{:?},{:?},{},{},{},{:?},{:?},{:?},{:?},{:?}",
            r.scene,
            r.engine,
            f(r.faceting_tolerance),
            reference,
            f(r.depth_error),
            f(r.normal_error_deg),
            f(r.point_error),
            r.resolved_depth,
            r.resolved_contacts,
            r.missed_contacts,
            r.extra_contacts,
            r.query_ns_median,
            r.query_ns_p95,
            r.prepare_ms,
            r.prepared_bytes,
            r.triangles,
            r.poses,
            r.work.geometry_pairs,
            r.work.bounding_volume_tests,
            r.work.primitive_tests,
            r.work.iterations,
            r.work.contacts
        );
    }
    out
}

/// The records as a JSON array (the schema documented in the README).
pub fn json(records: &[TradeRecord]) -> Result<String, serde_json::Error> {
    serde_json::to_string_pretty(records)
}

/// Depth error against median query time, log–log: one curve per scene over the faceted
/// tolerances, the exact engine's rows as one more series, peers as one series each.
pub fn plot(records: &[TradeRecord]) -> Plot {
    let mut series: Vec<Series> = Vec::new();
    let mut push = |name: String, x: f64, y: Option<f64>| {
        let Some(y) = y else { return };
        match series.iter_mut().find(|s| s.name == name) {
            Some(s) => s.points.push((x, y)),
            None => series.push(Series {
                name,
                points: vec![(x, y)],
                line: true,
            }),
        }
    };
    for r in records.iter().filter(|r| r.engine == "faceted") {
        push(
            format!("{} (faceted)", r.scene),
            r.query_ns_median,
            r.depth_error,
        );
    }
    for r in records.iter().filter(|r| r.engine != "faceted") {
        push(
            format!("{} engine", r.engine),
            r.query_ns_median,
            r.depth_error,
        );
    }
    for s in &mut series {
        if !s.name.ends_with("(faceted)") {
            s.line = false;
        }
    }
    Plot {
        title: "Accuracy against speed: depth error vs query time".into(),
        x_label: "median query time (ns)".into(),
        y_label: "worst depth error / scene scale".into(),
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series,
        note: None,
    }
}
