//! Running a model from Rust: the library entry point behind `contact run`.
//!
//! [`run_files`] reads a dataset (and its command file) and runs it; [`load`] and [`run_model`]
//! are its two halves, for a caller that reads the dataset first or builds the
//! [`Model`](crate::model::Model) another way. A run:
//!
//! 1. chooses the geometry engine once ([`engine_choice`](crate::engine_choice): an override in
//!    [`RunOptions`], else the environment, else the dataset's PREFERENCES, else the default);
//! 2. plans the analyses from the command file ([`plan`](crate::run::plan): dynamics,
//!    kinematics, statics, SIMULATE/TRANSIENT, initial conditions, LINEAR/EIGENSOL);
//! 3. lowers the model onto the solver ([`lower`](crate::run::lower)) and runs the analyses in
//!    order, each starting from the state the previous one reached;
//! 4. delivers everything it computes to a [`RunSink`] the caller implements — the engine
//!    chosen, planning notes, every output frame, the eigenvalues of each LINEAR, each
//!    analysis's [`AnalysisReport`] — and returns a [`RunReport`].
//!
//! [`ResultFiles`] is the sink `contact run` uses: it writes `parts.csv`, `contacts.csv`,
//! `frames.jsonl`, the plots and `summary.json` ([`output`](crate::run::output)), and the
//! eigenvalue files ([`eigenvalues`](crate::run::eigenvalues)).
//!
//! # Frames
//! A timed analysis (dynamics, kinematics) that starts where the previous one delivered its
//! last frame does not deliver that frame again; an equilibrium or initial-conditions frame is
//! always delivered. The results are the same bits at every thread count.
//!
//! # Failures
//! A failure before anything runs (unreadable dataset, model errors, an environment variable
//! out of range, a model that cannot be lowered) is a [`RunError`] and the sink sees no frame.
//! An analysis that fails stops the run: the sink still gets [`RunSink::finish`] with the
//! report of what ran, and the call returns [`RunError::Stopped`] carrying that report.
//!
//! ```
//! use contact_adams::session::{RunOptions, RunSink, run_files};
//! use contact_solver::simulate::Frame;
//! use std::path::Path;
//!
//! let ball = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/ball/ball.adm");
//!
//! /// Counts the output frames.
//! struct Count(usize);
//! impl RunSink for Count {
//!     fn frame(&mut self, _frame: &Frame) -> std::io::Result<()> {
//!         self.0 += 1;
//!         Ok(())
//!     }
//! }
//!
//! let mut count = Count(0);
//! // 0.1 s of dynamics (no command file) with 10 output steps: frames at t = 0, 0.01, …, 0.1.
//! let options = RunOptions { end: Some(0.1), steps: Some(10), ..RunOptions::default() };
//! let report = run_files(&ball, None, &options, &mut count)?;
//! assert_eq!(count.0, 11);
//! assert_eq!(report.output_frames, 11);
//! assert!(report.completed());
//! # Ok::<(), contact_adams::session::RunError>(())
//! ```

mod analysis;
mod error;
mod files;
mod report;
mod runner;

pub use error::{AnalysisError, RunError, RunFailure, no_moving_part};
pub use files::ResultFiles;
pub use report::{AnalysisOutcome, AnalysisReport, DynamicsTotals, RunReport};
pub use runner::{check_constraints, run_model};

use crate::dataset::{self, Diagnostic, Loaded, Severity};
use crate::engine_choice::EngineSelection;
use crate::run::plan::AnalysisStep;
use crate::run::request_file::RequestOutput;
use contact_core::{FacetingTolerance, GeometryLibrary};
use contact_solver::linear::Linearization;
use contact_solver::mbs::PartId;
use contact_solver::simulate::{Frame, Progress};
use std::path::Path;

/// What a caller sets for a run; `None` leaves each value to the dataset (or the default).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RunOptions {
    /// The geometry engine; overrides the environment and PREFERENCES.
    pub engine: Option<GeometryLibrary>,
    /// The model-wide faceting tolerance; overrides `MDI_FACETING_TOLERANCE` and PREFERENCES.
    pub faceting_tolerance: Option<FacetingTolerance>,
    /// End time (without a command file, or to override its last END).
    pub end: Option<f64>,
    /// Time between output steps (not with `steps`).
    pub dtout: Option<f64>,
    /// Number of output steps.
    pub steps: Option<u32>,
    /// Threads evaluating contacts and forces (default PREFERENCES/NTHREADS, else 1); the
    /// results are the same bits at every count.
    pub threads: Option<usize>,
    /// A factor on the integrator ERROR of every dynamic analysis (the dataset's and the
    /// command file's INTEGRATOR settings alike; HMAX and the rest unchanged): `0.01` runs the
    /// model a hundred times tighter than written. Range: finite, in `(0, 1]`; `None` is 1.
    pub integrator_error_scale: Option<f64>,
}

/// What a run knows once the model is lowered, before the first analysis: what each frame
/// holds.
#[derive(Debug, Clone, Copy)]
pub struct RunLayout<'a> {
    /// The moving parts: each frame's `parts[id.0]` is the part with the Adams id beside it.
    pub parts: &'a [(PartId, u32)],
    /// The contacts by name (`CONTACT/3`), in the order of each frame's `contacts`.
    pub contacts: &'a [String],
    /// The analyses the run performs, in order.
    pub analyses: &'a [AnalysisStep],
    /// The model's REQUESTs and how their files are written (`None` when it has none); each
    /// frame then carries the accelerations and reactions they read.
    pub requests: Option<&'a RequestOutput>,
}

/// Where a run delivers what it computes; only [`frame`](Self::frame) has no default.
///
/// Callbacks come in this order: [`diagnostics`](Self::diagnostics) ([`run_files`] only),
/// [`engine`](Self::engine), [`note`](Self::note)s, [`start`](Self::start); then per analysis
/// [`analysis_started`](Self::analysis_started), [`progress`](Self::progress) and
/// [`frame`](Self::frame)s (or [`eigenvalues`](Self::eigenvalues)),
/// [`analysis_finished`](Self::analysis_finished); last [`finish`](Self::finish), also after
/// an analysis failed. An error from a frame or the eigenvalues fails the analysis; an error
/// from `start` or `finish` fails the run with [`RunError::Output`].
pub trait RunSink {
    /// The dataset's diagnostics (warnings, and the errors that stop the run).
    fn diagnostics(&mut self, _diagnostics: &[Diagnostic]) -> std::io::Result<()> {
        Ok(())
    }

    /// The engine and faceting tolerance chosen, with where each came from.
    fn engine(&mut self, _selection: &EngineSelection) -> std::io::Result<()> {
        Ok(())
    }

    /// A planning note (an assumed output step, a TRANSIENT's choice, an ignored option).
    fn note(&mut self, _note: &str) -> std::io::Result<()> {
        Ok(())
    }

    /// The model is lowered and the first analysis is about to start.
    fn start(&mut self, _layout: &RunLayout<'_>) -> std::io::Result<()> {
        Ok(())
    }

    /// An analysis starts.
    fn analysis_started(&mut self, _step: &AnalysisStep) {}

    /// The elements switched off by DEACTIVATE changed: `inactive` holds for the frames that
    /// follow (called before the analysis that first runs without them or with them again).
    fn elements_switched(&mut self, _inactive: &crate::run::active::Inactive) {}

    /// Where a dynamics analysis is, after every accepted integrator step (keep it cheap).
    fn progress(&mut self, _progress: &Progress) {}

    /// Whether the run should end now (polled after every accepted dynamics step, with
    /// [`progress`](Self::progress)): a dynamics analysis then delivers its state at that step
    /// as a last [`frame`](Self::frame) and stops as interrupted, whatever the output step.
    fn stop_requested(&self) -> bool {
        false
    }

    /// One output frame.
    fn frame(&mut self, frame: &Frame) -> std::io::Result<()>;

    /// A LINEAR analysis's eigenvalues, computed with damping or without (NODAMPIN).
    fn eigenvalues(&mut self, _linear: &Linearization, _damping: bool) -> std::io::Result<()> {
        Ok(())
    }

    /// An analysis ended (completed or failed).
    fn analysis_finished(&mut self, _report: &AnalysisReport) {}

    /// The run ended; `report.failure` says whether it completed.
    fn finish(&mut self, _report: &RunReport) -> std::io::Result<()> {
        Ok(())
    }
}

/// Reads `model` (and `commands`, its command file) and hands its diagnostics to `sink`;
/// refuses a dataset with errors ([`RunError::ModelErrors`]). The first half of [`run_files`].
pub fn load(
    model: &Path,
    commands: Option<&Path>,
    sink: &mut dyn RunSink,
) -> Result<Loaded, RunError> {
    let loaded = dataset::read(model, commands)?;
    sink.diagnostics(&loaded.diagnostics)
        .map_err(RunError::Output)?;
    if loaded
        .diagnostics
        .iter()
        .any(|d| d.severity == Severity::Error)
    {
        return Err(RunError::ModelErrors);
    }
    Ok(loaded)
}

/// Reads `model` (and `commands`, its command file) with [`load`] and runs it with
/// [`run_model`].
pub fn run_files(
    model: &Path,
    commands: Option<&Path>,
    options: &RunOptions,
    sink: &mut dyn RunSink,
) -> Result<RunReport, RunError> {
    let loaded = load(model, commands, sink)?;
    run_model(&loaded.model, model, options, sink)
}
