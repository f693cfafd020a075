//! `contact select MODEL.adm --max-run-error X --max-depth-error E`: runs the model once (the
//! reference run), then, with `--max-depth-error`, measures its contacts at the poses where they
//! touched over the faceting-tolerance sweep and recommends, per contact and for the model, the
//! fastest engine and tolerance whose depth error meets the target; with `--max-run-error`,
//! runs the model with every candidate and recommends the fastest whose whole run stays
//! within the target of the reference run. The measured rows are printed as evidence.

use crate::dataset;
use crate::model::Model;
use crate::tradeoff::{self, EngineFactory, RunRecord, Sweep, Timing};
use contact_core::{FacetingTolerance, GeometryLibrary};
use serde_json::json;
use std::fmt::Write as _;
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
    /// The per-query target: the largest depth error allowed over a contact's poses (those of
    /// the reference run and their spread), as a fraction of the contact's size (its smallest
    /// half-extent; 0.01 = 1%).
    #[arg(long)]
    pub max_depth_error: Option<f64>,
    /// The whole-run target: the largest part position error over the run, against the
    /// reference run, as a fraction of the model's size.
    #[arg(long)]
    pub max_run_error: Option<f64>,
    /// Faceting tolerances to sweep, comma-separated (default 100,300.0028,1000,3000,10000).
    #[arg(long, value_delimiter = ',')]
    pub tolerances: Vec<f64>,
    /// Timed passes over the poses (default 5).
    #[arg(long)]
    pub rounds: Option<usize>,
    /// Write the evidence and the recommendations as JSON here (schema in the README).
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write the whole-run rows as CSV here (one line per candidate and contact).
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Draw run error against wall time per simulated second here (SVG).
    #[arg(long)]
    pub plot: Option<PathBuf>,
}

/// Runs the command: the reference run, then the per-query trade at its poses (with
/// `--max-depth-error`) and the trade on whole runs (with `--max-run-error`); prints the
/// evidence tables and the recommendations, writes the files asked for, and returns the exit
/// code (0: a recommendation for every target given; 1: none for some target, or an error,
/// said on `err`).
pub fn run(
    args: &SelectArgs,
    engines: EngineFactory<'_>,
    out: &mut dyn Write,
    err: &mut dyn Write,
    progress: &mut dyn FnMut(&str),
) -> std::io::Result<u8> {
    if !targets_valid(args, err)? {
        return Ok(1);
    }
    let model = match load_with_commands(&args.model, args.commands.as_deref()) {
        Ok(model) => model,
        Err(e) => {
            writeln!(err, "error: {e}")?;
            return Ok(1);
        }
    };
    let Some(sweep) = sweep_of(args, err)? else {
        return Ok(1);
    };
    progress("the reference run");
    let Some(reference) = reference_run(&model, &args.model, &sweep, engines, args.end, err)?
    else {
        return Ok(1);
    };
    let mut doc = serde_json::Map::new();
    doc.insert("model".into(), json!(args.model.display().to_string()));
    doc.insert("reference_run".into(), json!(reference.setting));
    let mut code = 0;
    let mut text = String::new();
    if let Some(target) = args.max_depth_error {
        match per_query(&model, &reference, &sweep, engines, target, progress) {
            Ok((value, printed, failure)) => {
                doc.insert("per_query".into(), value);
                text.push_str(&printed);
                if let Some(failure) = failure {
                    writeln!(err, "error: {failure}")?;
                    code = 1;
                }
            }
            Err(e) => {
                writeln!(err, "error: {e}")?;
                return Ok(1);
            }
        }
    }
    if let Some(target) = args.max_run_error {
        let Some((value, failed)) = whole_runs(
            args, &model, &reference, &sweep, target, &mut text, progress, err,
        )?
        else {
            return Ok(1);
        };
        doc.insert("runs".into(), value);
        if failed {
            code = 1;
        }
    }
    if let Some(path) = &args.json {
        let json = serde_json::to_string_pretty(&doc).map_err(std::io::Error::other)?;
        if !write_file(path, &json, err)? {
            return Ok(1);
        }
    }
    out.write_all(text.as_bytes())?;
    Ok(code)
}

/// The targets: at least one given, each positive and finite; false (said on `err`) when not.
fn targets_valid(args: &SelectArgs, err: &mut dyn Write) -> std::io::Result<bool> {
    let positive = |x: f64| x.is_finite() && x > 0.0;
    if args.max_depth_error.is_none() && args.max_run_error.is_none() {
        writeln!(
            err,
            "error: give --max-run-error, --max-depth-error or both"
        )?;
        return Ok(false);
    }
    for (name, target) in [
        ("--max-depth-error", args.max_depth_error),
        ("--max-run-error", args.max_run_error),
    ] {
        if let Some(t) = target.filter(|&t| !positive(t)) {
            writeln!(
                err,
                "error: {name} must be a positive finite number, got {t}"
            )?;
            return Ok(false);
        }
    }
    Ok(true)
}

/// The sweep the arguments ask for (`--tolerances`, `--rounds`); `None` (said on `err`) for a
/// tolerance out of range.
fn sweep_of(args: &SelectArgs, err: &mut dyn Write) -> std::io::Result<Option<Sweep>> {
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
                return Ok(None);
            }
        }
    }
    if let Some(rounds) = args.rounds {
        sweep.timing = Timing {
            rounds: rounds.max(1),
            ..sweep.timing
        };
    }
    Ok(Some(sweep))
}

/// The goal the reference run is converged to, as a fraction of the run-error target: a
/// thousandth, so that the target is met or missed by far more than the integrator's share,
/// and the candidates' errors are resolved well below the target.
pub const RUN_FLOOR_GOAL: f64 = 1e-3;

/// The trade on whole runs against `target`: its table and recommendation appended to `text`,
/// its CSV and plot written where asked; the JSON value and whether no candidate met the
/// target, or `None` (said on `err`) when the runs or a file failed.
#[expect(
    clippy::too_many_arguments,
    reason = "the command's inputs and its two outputs, passed as the command holds them"
)]
fn whole_runs(
    args: &SelectArgs,
    model: &Model,
    reference: &RunRecord,
    sweep: &Sweep,
    target: f64,
    text: &mut String,
    progress: &mut dyn FnMut(&str),
    err: &mut dyn Write,
) -> std::io::Result<Option<(serde_json::Value, bool)>> {
    let trade = match tradeoff::trade_runs(
        model,
        &args.model,
        reference,
        &sweep.tolerances,
        args.end,
        target * RUN_FLOOR_GOAL,
        progress,
    ) {
        Ok(trade) => trade,
        Err(e) => {
            writeln!(err, "error: {e}")?;
            return Ok(None);
        }
    };
    let choice = tradeoff::select_run(&trade.rows, target);
    if let Some(path) = &args.csv {
        if !write_file(path, &tradeoff::run_csv(&trade), err)? {
            return Ok(None);
        }
    }
    if let Some(path) = &args.plot {
        if !write_file(path, &tradeoff::run_plot(&trade).to_svg(), err)? {
            return Ok(None);
        }
    }
    text.push_str(&tradeoff::run_table(&trade));
    let own = trade.integration.at_model_error;
    if own > target {
        let _ = writeln!(
            text,
            "\nnote: at the model's own integrator ERROR the reference run itself is off by \
             {own:.2e}, more than the target: the integrator, not the engine, limits this \
             model's runs (tighten INTEGRATOR/ERROR)"
        );
    }
    let _ = writeln!(
        text,
        "\ntarget: run error (largest part displacement) <= {target:e} of the model's size"
    );
    match &choice {
        Ok(c) => {
            let _ = writeln!(
                text,
                "model (whole runs): {} (run error {:.2e}, {:.1} ms per simulated second{})",
                c.setting.describe(),
                c.position_error,
                c.wall_ms_per_simulated_s,
                if c.reference {
                    "; the reference run itself"
                } else {
                    ""
                }
            );
        }
        Err(e) => {
            writeln!(err, "error: {e}")?;
        }
    }
    let failed = choice.is_err();
    let value = json!({
        "max_run_error": target,
        "run_error": "the largest displacement between the runs of a point of a part within its contact radius, over time and parts, relative to the model's size (scale.size)",
        "trade": trade,
        "recommendation": choice.as_ref().ok(),
        "no_recommendation": choice.as_ref().err().map(ToString::to_string),
    });
    Ok(Some((value, failed)))
}

/// Writes `text` to `path`; false (said on `err`) when it cannot.
fn write_file(path: &Path, text: &str, err: &mut dyn Write) -> std::io::Result<bool> {
    match std::fs::write(path, text) {
        Ok(()) => Ok(true),
        Err(e) => {
            writeln!(err, "error: cannot write {}: {e}", path.display())?;
            Ok(false)
        }
    }
}

/// The per-query trade at the reference run's poses: its JSON, its printed evidence and
/// recommendation, and why there is no recommendation, if there is none.
fn per_query(
    model: &Model,
    reference: &RunRecord,
    sweep: &Sweep,
    engines: EngineFactory<'_>,
    target: f64,
    progress: &mut dyn FnMut(&str),
) -> Result<(serde_json::Value, String, Option<String>), tradeoff::ModelTradeError> {
    let selection =
        tradeoff::select_for_model(model, reference, sweep, engines, &[], target, progress)?;
    let (recommendation, failure) = match &selection.recommendation {
        Ok(r) => (serde_json::to_value(r).ok(), None),
        Err(e) => (None, Some(e.to_string())),
    };
    let value = json!({
        "max_depth_error": target,
        "depth_error_relative_to": "each contact's size: the smallest half-extent of its bounded geometries",
        "contacts": selection.contacts,
        "untouched": selection.untouched,
        "recommendation": recommendation,
        "no_recommendation": failure,
        "records": selection.report.records,
    });
    let mut text = tradeoff::table(&selection.report.records);
    for c in &selection.untouched {
        let _ = writeln!(
            text,
            "{c}: no contact in the reference run ({}): not measured",
            selection.reference_run
        );
    }
    let _ = writeln!(
        text,
        "\ntarget: depth error <= {target:e} of each contact's size"
    );
    if let Ok(r) = &selection.recommendation {
        for c in &r.contacts {
            let _ = writeln!(
                text,
                "{} (depth error {:.2e}, median {:.0} ns)",
                c.describe(),
                c.depth_error,
                c.query_ns_median
            );
        }
        let m = &r.model;
        let setting = match m.faceting_tolerance {
            Some(t) => format!("{} engine, faceting tolerance {t}", m.engine),
            None => format!("{} engine", m.engine),
        };
        let _ = writeln!(
            text,
            "model: {setting} (worst depth error {:.2e}, {:.0} ns per step over all contacts)",
            m.worst_depth_error, m.total_query_ns
        );
    }
    text.push('\n');
    Ok((value, text, failure))
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
