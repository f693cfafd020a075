//! `contact select MODEL.adm --max-depth-error E`: runs the model once (the reference run),
//! measures its contacts at the poses where they touched over the faceting-tolerance sweep and
//! recommends, per contact and for the model, the fastest engine and tolerance whose depth
//! error meets the target, with the measured rows as evidence.

use crate::dataset;
use crate::model::Model;
use crate::tradeoff::{self, EngineFactory, RunRecord, Sweep, Timing};
use contact_core::{FacetingTolerance, GeometryLibrary};
use serde_json::json;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The arguments of `contact select`.
#[derive(Debug, Clone, PartialEq, clap::Args)]
pub struct SelectArgs {
    /// The Adams dataset (.adm).
    pub model: PathBuf,
    /// Its command file (.acf); default: the file beside the dataset with its name and the
    /// extension `.acf`, if there is one.
    pub commands: Option<PathBuf>,
    /// End the runs here (overrides the command file's last END; needed without one).
    #[arg(long)]
    pub end: Option<f64>,
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
    let model = match load_with_commands(&args.model, args.commands.as_deref()) {
        Ok(model) => model,
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
    let Some(reference) = reference_run(&model, &args.model, &sweep, engines, args.end, err)?
    else {
        return Ok(1);
    };
    let selection = match tradeoff::select_for_model(
        &model,
        &reference,
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
            "reference_run": selection.reference_run,
            "contacts": selection.contacts,
            "untouched": selection.untouched,
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
    for c in &selection.untouched {
        writeln!(
            out,
            "{c}: no contact in the reference run ({}): not measured",
            selection.reference_run
        )?;
    }
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

/// Reads `adm` with `commands`, or with the command file beside it (same name, `.acf`) when
/// none is given and that file exists.
pub fn load_with_commands(
    adm: &Path,
    commands: Option<&Path>,
) -> Result<Model, dataset::DatasetError> {
    let beside = adm.with_extension("acf");
    let commands = commands.or_else(|| beside.is_file().then_some(beside.as_path()));
    dataset::load(adm, commands).map(|(model, _warnings)| model)
}

/// The reference run of `model` for `sweep` (said on `err` and `None` when it fails).
pub fn reference_run(
    model: &Model,
    source: &Path,
    sweep: &Sweep,
    engines: EngineFactory<'_>,
    end: Option<f64>,
    err: &mut dyn Write,
) -> std::io::Result<Option<RunRecord>> {
    let exact = engines(GeometryLibrary::Exact, FacetingTolerance::DEFAULT);
    match tradeoff::record_reference(model, source, exact.as_ref(), &sweep.tolerances, end) {
        Ok(record) => Ok(Some(record)),
        Err(e) => {
            writeln!(err, "error: {e}")?;
            Ok(None)
        }
    }
}
