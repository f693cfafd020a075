//! Why a run did not complete: [`RunError`], with the analysis failure that stopped a run
//! ([`RunFailure`], [`AnalysisError`]).

use super::report::RunReport;
use crate::dataset::DatasetError;
use crate::engine_choice::EnvironmentError;
use crate::run::lower::LowerError;
use crate::run::plan::PlanError;
use contact_solver::EvaluationError;
use contact_solver::kinematics::KinematicsError;
use contact_solver::linear::LinearError;
use contact_solver::mbs::MbsError;
use contact_solver::parallel::MAX_THREADS;
use contact_solver::simulate::SimulationError;
use contact_solver::statics::StaticsError;
use std::sync::Arc;

/// Why a run did not complete.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The dataset or command file could not be read.
    #[error(transparent)]
    Dataset(#[from] DatasetError),
    /// The dataset has errors (delivered to [`RunSink::diagnostics`](super::RunSink::diagnostics)).
    #[error("the model has errors: nothing was run")]
    ModelErrors,
    /// The model has no moving part (only ground): every analysis needs one.
    #[error("{}", no_moving_part(*.cr_only))]
    NoMovingPart {
        /// The file's lines end in CR only, so it was read as one title line.
        cr_only: bool,
    },
    /// An environment variable choosing the engine is out of range.
    #[error(transparent)]
    Environment(#[from] EnvironmentError),
    /// The thread count is out of range.
    #[error("{by} = {threads} is out of range: must be in [1, {MAX_THREADS}]")]
    ThreadCount {
        /// The thread count asked for.
        threads: usize,
        /// Where it came from: `--threads` or `PREFERENCES/NTHREADS`.
        by: &'static str,
    },
    /// The thread pool could not be built.
    #[error("{by} = {threads}: the thread pool could not be built: {source}")]
    Threads {
        /// The thread count asked for.
        threads: usize,
        /// Where it came from: `--threads` or `PREFERENCES/NTHREADS`.
        by: &'static str,
        /// Why the pool was not built.
        source: rayon::ThreadPoolBuildError,
    },
    /// The factor on the integrator ERROR is out of range.
    #[error("the integrator error scale {scale} is out of range: must be finite and in (0, 1]")]
    ErrorScale {
        /// The factor asked for.
        scale: f64,
    },
    /// The command file's analyses could not be planned.
    #[error(transparent)]
    Plan(#[from] PlanError),
    /// The plan has no analysis to run.
    #[error("the command file runs no analysis")]
    NoAnalysis,
    /// The model could not be lowered onto the solver for its first analysis.
    #[error(transparent)]
    Lower(#[from] LowerError),
    /// The sink failed outside an analysis ([`RunSink::start`](super::RunSink::start),
    /// [`RunSink::finish`](super::RunSink::finish), or passing on the diagnostics).
    #[error(transparent)]
    Output(std::io::Error),
    /// An analysis failed and the run stopped; the report says what ran (its `failure` is set).
    #[error("the run stopped: {}", stopped_by(.0))]
    Stopped(Box<RunReport>),
}

/// The message for a model with no moving part; `cr_only` adds why a file can look empty.
pub fn no_moving_part(cr_only: bool) -> String {
    let mut message = String::from(
        "the model has no moving part: nothing to simulate (add a PART with MASS, CM and IP)",
    );
    if cr_only {
        message.push_str(
            "; the file's lines end in CR only (classic Mac OS), so it was read as one title line: save it with LF or CRLF line endings",
        );
    }
    message
}

/// The failure in a stopped run's report (empty if the report has none).
fn stopped_by(report: &RunReport) -> String {
    report
        .failure
        .as_ref()
        .map_or_else(String::new, ToString::to_string)
}

/// What stopped a run once its analyses had started.
#[derive(Debug, thiserror::Error)]
pub enum RunFailure {
    /// An analysis failed.
    #[error("SIMULATE/{analysis}: {error}")]
    Analysis {
        /// The analysis's name as in SIMULATE (`DYNAMICS`, `LINEAR`, …).
        analysis: &'static str,
        /// Why (shared with the analysis's [`AnalysisReport`](super::AnalysisReport)).
        error: Arc<AnalysisError>,
    },
    /// The model could not be lowered again for the next analysis (friction that acts in
    /// dynamics only changes the lowered model between analyses).
    #[error(transparent)]
    Lower(LowerError),
}

/// Why one analysis failed.
#[derive(Debug, thiserror::Error)]
pub enum AnalysisError {
    /// The dynamics integration stopped.
    #[error(transparent)]
    Dynamics(#[from] SimulationError),
    /// The kinematics stopped.
    #[error(transparent)]
    Kinematics(#[from] KinematicsError),
    /// No static equilibrium was found.
    #[error(transparent)]
    Statics(#[from] StaticsError),
    /// The initial conditions could not be assembled, or the state to linearize at.
    #[error(transparent)]
    Assembly(#[from] MbsError),
    /// A frame's forces could not be evaluated.
    #[error(transparent)]
    Frame(#[from] EvaluationError),
    /// The equations of motion could not be linearized.
    #[error(transparent)]
    Linear(#[from] LinearError),
    /// The sink refused a frame or the eigenvalues.
    #[error(transparent)]
    Output(#[from] std::io::Error),
}
