//! How tightly the trade's runs integrate.
//!
//! Two runs of one model differ by their engines *and* by their integrators' errors: the step
//! sizes an error-controlled integrator picks follow the forces, so a run on another engine
//! takes other steps and carries another integration error. A model with impacts amplifies
//! that error (a bounce that barely happens in one run and not in the other), and at the
//! model's own ERROR it can exceed every engine's difference: the candidates' run errors are
//! then noise, and they do not fall as the faceting tolerance rises.
//!
//! So before the candidates run, the reference run is *converged*: run again at ERROR/10,
//! ERROR/100, … until two successive runs differ by at most a goal (a run error, relative to
//! the model's size). The candidates are then held to the reference at the tighter ERROR of
//! the last pair, each run at that ERROR too, so what is left between them is the engines'
//! difference, resolved down to the *floor*: the run error between that last pair (an upper
//! bound on the error of the coarser run, so on the one used). A candidate whose run error is
//! within the floor is not told apart from the reference.
//!
//! The wall time of each candidate is still measured at the model's own ERROR: that is the
//! speed a user running the model gets.

use super::reference_run::{RecordError, RunRecord, record_run};
use super::whole_run::{ModelScale, compare_runs};
use crate::model::{Command, Model};
use serde::Serialize;
use std::path::Path;

/// The most tightenings tried: ERROR down to `1e-6` of the model's.
pub const MAX_TIGHTENINGS: usize = 6;

/// The tightest integrator ERROR a converging run asks for: below it the step sizes approach
/// the round-off limit of the time variable over long runs.
pub const SMALLEST_ERROR: f64 = 1e-12;

/// One step of the convergence: the reference at `error_scale` against the same run at a
/// tenth of it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct IntegrationLevel {
    /// The factor on the model's ERROR.
    pub error_scale: f64,
    /// The run error (relative to the model's size) between the run at `error_scale` and the
    /// run at `error_scale / 10`.
    pub run_error: f64,
}

/// How the trade's runs were integrated (see the module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Integration {
    /// The goal: the largest run error allowed between two successive tightenings.
    pub goal: f64,
    /// The factor on the model's ERROR every compared run used (1: the model's own).
    pub error_scale: f64,
    /// The run error between the last two tightenings: the reference's own integration
    /// error is at most this; candidates within it are not told apart from the reference.
    /// `None` when not even one tightening could run (the runs are then at the model's own
    /// ERROR and nothing bounds their integration error).
    pub floor: Option<f64>,
    /// True when the floor met the goal; false when the tightenings ran out first (the
    /// floor is then the last one reached).
    pub converged: bool,
    /// The run error, at the model's own ERROR, of the reference run against the converged
    /// one: the integrator's share of the error of a run as the model is written.
    pub at_model_error: f64,
    /// The tightenings, from the model's own ERROR down.
    pub levels: Vec<IntegrationLevel>,
}

/// The reference converged as the module docs say, from `reference` (the run at the model's
/// own ERROR) with `scale`: the run every candidate is held to, and how it was reached.
/// Tightening stops at [`MAX_TIGHTENINGS`], before the model's smallest ERROR (the dataset's
/// or a command's) falls below [`SMALLEST_ERROR`], and at a tightened run that stops early.
pub fn converge_reference(
    model: &Model,
    source: &Path,
    end: Option<f64>,
    reference: &RunRecord,
    scale: &ModelScale,
    goal: f64,
    progress: &mut dyn FnMut(&str),
) -> Result<(RunRecord, Integration), RecordError> {
    let smallest_model_error = model
        .commands
        .iter()
        .filter_map(|(_, c)| match c {
            Command::Integrator(s) => Some(s.error),
            _ => None,
        })
        .fold(model.integrator.error, f64::min);
    let mut levels = Vec::new();
    let mut coarse = reference.clone();
    let mut error_scale = 1.0_f64;
    let mut converged = false;
    for k in 1..=MAX_TIGHTENINGS {
        // A power of ten exactly as written (repeated `0.1 *` would drift in the last bits).
        let next_scale = 10f64.powi(-(k as i32));
        if smallest_model_error * next_scale < SMALLEST_ERROR {
            break;
        }
        progress(&format!(
            "reference run at {next_scale:e} of the model's integrator ERROR"
        ));
        let fine = record_run(model, source, reference.setting, end, next_scale)?;
        if fine.failure.is_some() {
            break;
        }
        let run_error = compare_runs(&fine, &coarse, scale).position_error;
        levels.push(IntegrationLevel {
            error_scale,
            run_error,
        });
        coarse = fine;
        error_scale = next_scale;
        if run_error <= goal {
            converged = true;
            break;
        }
    }
    let at_model_error = if error_scale == 1.0 {
        0.0
    } else {
        compare_runs(&coarse, reference, scale).position_error
    };
    let floor = levels.last().map(|l| l.run_error);
    let integration = Integration {
        goal,
        error_scale,
        floor,
        converged,
        at_model_error,
        levels,
    };
    Ok((coarse, integration))
}
