//! `contact tradeoff [MODEL.adm]`: the accuracy-against-speed sweep over the scene suite, or
//! over a dataset's own contacts (one scene per CONTACT that touched in a reference run of the
//! model, at the poses where it touched: see [`crate::scenes::from_run`]).

use crate::scenes::{self, Scene};
use crate::tradeoff::{self, EngineFactory, Sweep, Timing, TradeReport};
use contact_core::{FacetingTolerance, GeometryEngine, GeometryLibrary};
use std::io::Write;
use std::path::PathBuf;

/// What `contact tradeoff` was asked to do.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TradeoffArgs {
    /// A dataset whose contacts are the scenes (`None`: the reference suite).
    pub model: Option<PathBuf>,
    /// The dataset's command file (default: the `.acf` beside it, if any).
    pub commands: Option<PathBuf>,
    /// End the reference run here (overrides the command file's last END).
    pub end: Option<f64>,
    /// Scene names (empty: the whole suite, or every contact of the model).
    pub scenes: Vec<String>,
    /// Faceting tolerances (empty: the default sweep).
    pub tolerances: Vec<f64>,
    /// Timed passes over the poses.
    pub rounds: Option<usize>,
    /// Write the records as JSON here.
    pub json: Option<PathBuf>,
    /// Write the records as CSV here.
    pub csv: Option<PathBuf>,
    /// Draw the error-against-time plot here (SVG).
    pub plot: Option<PathBuf>,
}

/// Why `contact tradeoff` failed.
#[derive(Debug, thiserror::Error)]
pub enum TradeoffError {
    /// A scene name not in the suite.
    #[error(
        "no scene named '{0}' (`contact scenes` lists the suite, `contact scenes --kernels` the kernel scenes)"
    )]
    UnknownScene(String),
    /// A contact name not in the model.
    #[error("the model has no contact named '{0}' (its contacts are named CONTACT/id)")]
    UnknownContact(String),
    /// The dataset could not be read or has errors.
    #[error(transparent)]
    Dataset(#[from] crate::dataset::DatasetError),
    /// A contact of the dataset could not become a scene.
    #[error(transparent)]
    Scenes(#[from] crate::scenes::ModelSceneError),
    /// A tolerance out of range.
    #[error("--faceting-tolerance: {0}")]
    Tolerance(#[from] contact_core::InvalidArgument),
    /// A measurement failed.
    #[error(transparent)]
    Measure(#[from] tradeoff::TradeError),
    /// The reference run of the model failed.
    #[error(transparent)]
    Reference(#[from] tradeoff::RecordError),
    /// Writing an output failed.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Serialising JSON failed.
    #[error("cannot serialise the records: {0}")]
    Json(#[from] serde_json::Error),
}

/// Runs the sweep, prints the table to `out` (and progress to `progress`), writes the files
/// asked for, and returns the report.
pub fn run(
    args: &TradeoffArgs,
    engines: EngineFactory<'_>,
    peers: &[&dyn GeometryEngine],
    out: &mut dyn Write,
    progress: &mut dyn FnMut(&str),
) -> Result<TradeReport, TradeoffError> {
    let mut sweep = Sweep::default();
    if !args.tolerances.is_empty() {
        sweep.tolerances = args
            .tolerances
            .iter()
            .map(|&t| FacetingTolerance::new(t))
            .collect::<Result<_, _>>()?;
    }
    let mut untouched = Vec::new();
    let chosen: Vec<Scene> = if let Some(path) = &args.model {
        let model = super::select::load_with_commands(path, args.commands.as_deref())?;
        let named = |name: &str| args.scenes.is_empty() || args.scenes.iter().any(|n| n == name);
        if let Some(unknown) = args.scenes.iter().find(|n| {
            !model
                .contacts
                .iter()
                .any(|c| format!("CONTACT/{}", c.id) == **n)
        }) {
            return Err(TradeoffError::UnknownContact(unknown.clone()));
        }
        let exact = engines(GeometryLibrary::Exact, FacetingTolerance::DEFAULT);
        let reference =
            tradeoff::record_reference(&model, path, exact.as_ref(), &sweep.tolerances, args.end)?;
        let run = scenes::from_run(&model, &reference, scenes::RUN_POSES_PER_CONTACT)?;
        untouched = run
            .untouched
            .into_iter()
            .filter(|n| named(n))
            .map(|n| {
                format!(
                    "{n}: no contact in the reference run ({})",
                    reference.setting.describe()
                )
            })
            .collect();
        run.scenes.into_iter().filter(|s| named(&s.name)).collect()
    } else if args.scenes.is_empty() {
        scenes::suite()
    } else {
        args.scenes
            .iter()
            .map(|n| scenes::scene(n).ok_or_else(|| TradeoffError::UnknownScene(n.clone())))
            .collect::<Result<_, _>>()?
    };
    if let Some(rounds) = args.rounds {
        sweep.timing = Timing {
            rounds: rounds.max(1),
            ..sweep.timing
        };
    }
    let report = tradeoff::run(&chosen, &sweep, engines, peers, progress)?;
    let write = |path: &PathBuf, text: &str| {
        std::fs::write(path, text).map_err(|source| TradeoffError::Write {
            path: path.clone(),
            source,
        })
    };
    // Files first: what was measured is kept even if the terminal has gone away.
    if let Some(path) = &args.json {
        write(path, &tradeoff::json(&report.records)?)?;
    }
    if let Some(path) = &args.csv {
        write(path, &tradeoff::csv(&report.records))?;
    }
    if let Some(path) = &args.plot {
        write(path, &tradeoff::plot(&report.records).to_svg())?;
    }
    let stdout_error = |source| TradeoffError::Write {
        path: PathBuf::from("<stdout>"),
        source,
    };
    out.write_all(tradeoff::table(&report.records).as_bytes())
        .map_err(stdout_error)?;
    for line in &untouched {
        writeln!(out, "{line}").map_err(stdout_error)?;
    }
    for s in &report.skipped {
        writeln!(
            out,
            "skipped: {} with the {} engine (unsupported pair)",
            s.scene, s.engine
        )
        .map_err(stdout_error)?;
    }
    Ok(report)
}
