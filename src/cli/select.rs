//! `contact select MODEL.adm --max-depth-error E`: measures the model's own contacts over the
//! faceting-tolerance sweep and recommends, per contact and for the model, the fastest engine
//! and tolerance whose depth error meets the target, with the measured rows as evidence.

use crate::dataset;
use crate::tradeoff::{self, EngineFactory, Sweep, Timing};
use contact_core::FacetingTolerance;
use serde_json::json;
use std::io::Write;
use std::path::PathBuf;

/// The arguments of `contact select`.
#[derive(Debug, Clone, PartialEq, clap::Args)]
pub struct SelectArgs {
    /// The Adams dataset (.adm).
    pub model: PathBuf,
    /// The accuracy target: the largest depth error allowed over a contact's poses, as a
    /// fraction of the contact's size (its smallest half-extent; 0.01 = 1%).
    #[arg(long)]
    pub max_depth_error: f64,
    /// Faceting tolerances to sweep, comma-separated (default 100,300.0028,1000,3000,10000).
    #[arg(long, value_delimiter = ',')]
    pub tolerances: Vec<f64>,
    /// Timed passes over the poses (default 5).
    #[arg(long)]
    pub rounds: Option<usize>,
    /// Write the evidence and the recommendation as JSON here.
    #[arg(long)]
    pub json: Option<PathBuf>,
}

/// Runs the command: prints the evidence table, the per-contact choices and the model's, and
/// returns the exit code (0: a recommendation exists; 1: none, or an error, said on `err`).
pub fn run(
    args: &SelectArgs,
    engines: EngineFactory<'_>,
    out: &mut dyn Write,
    err: &mut dyn Write,
    progress: &mut dyn FnMut(&str),
) -> std::io::Result<u8> {
    let model = match dataset::load(&args.model, None) {
        Ok((model, _warnings)) => model,
        Err(e) => {
            writeln!(err, "error: {e}")?;
            return Ok(1);
        }
    };
    let mut sweep = Sweep::default();
    if !args.tolerances.is_empty() {
        match args
            .tolerances
            .iter()
            .map(|&t| FacetingTolerance::new(t))
            .collect::<Result<Vec<_>, _>>()
        {
            Ok(t) => sweep.tolerances = t,
            Err(e) => {
                writeln!(err, "error: --tolerances: {e}")?;
                return Ok(1);
            }
        }
    }
    if let Some(rounds) = args.rounds {
        sweep.timing = Timing {
            rounds: rounds.max(1),
            ..sweep.timing
        };
    }
    let selection = match tradeoff::select_for_model(
        &model,
        &sweep,
        engines,
        &[],
        args.max_depth_error,
        progress,
    ) {
        Ok(s) => s,
        Err(e) => {
            writeln!(err, "error: {e}")?;
            return Ok(1);
        }
    };
    if let Some(path) = &args.json {
        let (recommendation, failure) = match &selection.recommendation {
            Ok(r) => (serde_json::to_value(r).ok(), None),
            Err(e) => (None, Some(e.to_string())),
        };
        let doc = json!({
            "model": args.model.display().to_string(),
            "max_depth_error": args.max_depth_error,
            "depth_error_relative_to": "each contact's size: the smallest half-extent of its bounded geometries",
            "contacts": selection.contacts,
            "recommendation": recommendation,
            "no_recommendation": failure,
            "records": selection.report.records,
        });
        let text = serde_json::to_string_pretty(&doc).map_err(std::io::Error::other)?;
        if let Err(e) = std::fs::write(path, text) {
            writeln!(err, "error: cannot write {}: {e}", path.display())?;
            return Ok(1);
        }
    }
    out.write_all(tradeoff::table(&selection.report.records).as_bytes())?;
    writeln!(
        out,
        "\ntarget: depth error <= {:e} of each contact's size",
        args.max_depth_error
    )?;
    match &selection.recommendation {
        Ok(r) => {
            for c in &r.contacts {
                writeln!(
                    out,
                    "{} (depth error {:.2e}, median {:.0} ns)",
                    c.describe(),
                    c.depth_error,
                    c.query_ns_median
                )?;
            }
            let m = &r.model;
            let setting = match m.faceting_tolerance {
                Some(t) => format!("{} engine, faceting tolerance {t}", m.engine),
                None => format!("{} engine", m.engine),
            };
            writeln!(
                out,
                "model: {setting} (worst depth error {:.2e}, {:.0} ns per step over all contacts)",
                m.worst_depth_error, m.total_query_ns
            )?;
            Ok(0)
        }
        Err(e) => {
            writeln!(err, "error: {e}")?;
            Ok(1)
        }
    }
}
