//! Writing the whole-run trade: a text table, CSV (one line per candidate and contact) and a
//! plot of run error against wall time. The JSON is [`RunTrade`] serialised (schema in the
//! README).

use super::integration::Integration;
use super::whole_run::{ContactRunErrors, RunRow, RunTrade};
use crate::svg_plot::{Plot, Scale, Series};
use std::fmt::Write;

fn opt(v: Option<f64>) -> String {
    v.map_or_else(|| "-".to_string(), |x| format!("{x:.2e}"))
}

fn ft(row: &RunRow) -> String {
    row.setting
        .faceting_tolerance
        .map_or_else(|| "-".to_string(), |t| format!("{t}"))
}

/// How the compared runs were integrated, in one line.
pub fn integration_line(i: &Integration) -> String {
    let at = if i.error_scale == 1.0 {
        "the model's own integrator ERROR".to_string()
    } else {
        format!("{:e} of the model's integrator ERROR", i.error_scale)
    };
    let floor = match (i.floor, i.converged) {
        (Some(f), true) => format!("floor {f:.2e} (goal {:.0e})", i.goal),
        (Some(f), false) => format!(
            "floor {f:.2e}, short of the goal {:.0e} after {} tightenings",
            i.goal,
            i.levels.len()
        ),
        (None, _) => "no floor: no tightened run completed".to_string(),
    };
    let model = if i.error_scale == 1.0 {
        String::new()
    } else {
        format!(
            "; at the model's own ERROR the reference itself is off by {:.2e}",
            i.at_model_error
        )
    };
    format!("runs compared at {at}, {floor}{model}")
}

/// A fixed-width table: one line per candidate (run error, orientation error, wall time per
/// simulated second), then one per candidate and contact (peak force and impulse with their
/// relative errors, onsets and releases with their largest time errors).
pub fn run_table(trade: &RunTrade) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "whole runs against the {} run ({:.3} s simulated; model size {:.4e})",
        trade.reference.describe(),
        trade.simulated_s,
        trade.scale.size
    );
    let _ = writeln!(out, "{}", integration_line(&trade.integration));
    let _ = writeln!(
        out,
        "{:<8} {:>9} {:>10} {:>10} {:>12} {:>9} {:>7}  status",
        "engine", "FT", "run err", "orient °", "ms per sim s", "prep ms", "frames"
    );
    for r in &trade.rows {
        let status = match (&r.failure, r.reference, r.within_floor) {
            (Some(f), _, _) => format!("stopped: {f}"),
            (None, true, _) => "reference".to_string(),
            (None, false, true) => "completed, within the floor".to_string(),
            (None, false, false) => "completed".to_string(),
        };
        let _ = writeln!(
            out,
            "{:<8} {:>9} {:>10.2e} {:>10.2e} {:>12.1} {:>9.1} {:>7}  {status}",
            r.setting.engine.name(),
            ft(r),
            r.position_error,
            r.orientation_error_deg,
            r.wall_ms_per_simulated_s,
            r.prepare_ms,
            r.frames_compared,
        );
    }
    let _ = writeln!(
        out,
        "\n{:<12} {:<8} {:>9} {:>10} {:>9} {:>10} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "contact",
        "engine",
        "FT",
        "peak F",
        "peak err",
        "impulse",
        "imp err",
        "onsets",
        "onset Δt",
        "releases",
        "rel Δt"
    );
    for r in &trade.rows {
        for c in &r.contacts {
            let _ = writeln!(
                out,
                "{:<12} {:<8} {:>9} {:>10.3e} {:>9} {:>10.3e} {:>9} {:>9} {:>9} {:>9} {:>9}",
                c.contact,
                r.setting.engine.name(),
                ft(r),
                c.peak_force,
                opt(c.peak_force_error),
                c.impulse,
                opt(c.impulse_error),
                format!("{}/{}", c.onsets, c.reference_onsets),
                opt(c.onset_time_error),
                format!("{}/{}", c.releases, c.reference_releases),
                opt(c.release_time_error),
            );
        }
    }
    out
}

/// CSV with a header, one line per candidate and contact (the run-level columns repeat on
/// each of a candidate's lines; a model without contacts has one line per candidate with the
/// contact columns empty). Empty fields where a value does not apply.
pub fn run_csv(trade: &RunTrade) -> String {
    let mut out = String::from(
        "engine,faceting_tolerance,reference,failure,frames_compared,position_error,orientation_error_deg,wall_ms_per_simulated_s,prepare_ms,within_floor,contact,peak_force,peak_force_error,impulse,impulse_error,onsets,reference_onsets,onset_time_error,releases,reference_releases,release_time_error\n",
    );
    let f = |v: Option<f64>| v.map_or_else(String::new, |x| format!("{x:?}"));
    for r in &trade.rows {
        let head = format!(
            "{},{},{},{},{},{:?},{:?},{:?},{:?},{}",
            r.setting.engine.name(),
            f(r.setting.faceting_tolerance),
            r.reference,
            r.failure
                .as_deref()
                .map_or_else(String::new, |s| format!("\"{}\"", s.replace('"', "'"))),
            r.frames_compared,
            r.position_error,
            r.orientation_error_deg,
            r.wall_ms_per_simulated_s,
            r.prepare_ms,
            r.within_floor
        );
        if r.contacts.is_empty() {
            let _ = writeln!(out, "{head},,,,,,,,,,,");
        }
        for c in &r.contacts {
            let ContactRunErrors {
                contact,
                peak_force,
                peak_force_error,
                impulse,
                impulse_error,
                onsets,
                reference_onsets,
                onset_time_error,
                releases,
                reference_releases,
                release_time_error,
            } = c;
            let _ = writeln!(
                out,
                "{head},{contact},{peak_force:?},{},{impulse:?},{},{onsets},{reference_onsets},{},{releases},{reference_releases},{}",
                f(*peak_force_error),
                f(*impulse_error),
                f(*onset_time_error),
                f(*release_time_error),
            );
        }
    }
    out
}

/// Run error against wall time per simulated second, log–log: the faceted engine's
/// candidates as one curve over the tolerances, the exact engine as a point. A run error of 0
/// (the reference run itself) has no place on a log axis and is left out.
pub fn run_plot(trade: &RunTrade) -> Plot {
    let mut faceted = Series {
        name: "faceted engine (by tolerance)".into(),
        points: Vec::new(),
        line: true,
    };
    let mut exact = Series {
        name: "exact engine".into(),
        points: Vec::new(),
        line: false,
    };
    for r in trade.rows.iter().filter(|r| r.failure.is_none()) {
        let point = (r.wall_ms_per_simulated_s, r.position_error);
        match r.setting.faceting_tolerance {
            Some(_) => faceted.points.push(point),
            None => exact.points.push(point),
        }
    }
    Plot {
        title: format!(
            "Whole runs: run error vs wall time (against the {} run)",
            trade.reference.describe()
        ),
        x_label: "wall time per simulated second (ms)".into(),
        y_label: "run error (part displacement / model size)".into(),
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series: vec![faceted, exact],
        note: Some(match trade.integration.floor {
            Some(f) => format!(
                "runs at {:e} × the model's ERROR; floor {f:.2e}",
                trade.integration.error_scale
            ),
            None => "runs at the model's ERROR; no floor".to_string(),
        }),
    }
}
