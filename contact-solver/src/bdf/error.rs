//! Why an integration stopped: typed errors that carry a diagnosis.

use crate::EvaluationError;
use contact_core::InvalidArgument;

/// The remedies SPEC §8 and the Adams contact document give for a run that cannot continue.
pub const REMEDIES: &str = "remedies: lower the contact stiffness, loosen INTEGRATOR/ERROR, \
set INTEGRATOR/KMAX=2, set a smaller INTEGRATOR/HMAX, avoid extreme friction \
(transition velocities well above ERROR), or use the SI2 formulation";

/// One variable that dominates a failure: its index in `y` and its weighted size (the local
/// error or Newton correction divided by its tolerance weight; above 1 means over tolerance).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dominant {
    /// Index of the variable in `y`.
    pub index: usize,
    /// Weighted size: |value| / (ERROR·(|y| + s)), s the variable's absolute scale, the quantity the test compares with 1.
    pub weighted: f64,
}

/// Formats the dominant variables as `y[3] (4.1), y[7] (2.0)`.
fn list(dominant: &[Dominant]) -> String {
    let parts: Vec<String> = dominant
        .iter()
        .map(|d| format!("y[{}] ({:.3e})", d.index, d.weighted))
        .collect();
    if parts.is_empty() {
        "none".to_string()
    } else {
        parts.join(", ")
    }
}

/// Why the last failed step attempt failed.
#[derive(Debug, Clone, PartialEq)]
pub enum FailureCause {
    /// The local error test failed; the variables with the largest weighted error.
    ErrorTest {
        /// Largest contributors to the error norm.
        dominant: Vec<Dominant>,
    },
    /// Newton did not converge; the variables with the largest weighted last correction.
    Convergence {
        /// Largest contributors to the last Newton correction.
        dominant: Vec<Dominant>,
    },
    /// The system could not evaluate its equations.
    Evaluation(EvaluationError),
    /// The residual or the solution held a NaN or an infinity at variable `index`.
    NonFinite {
        /// Index of the first non-finite entry.
        index: usize,
    },
    /// The scaled Newton matrix was singular to working precision.
    SingularMatrix,
    /// The system's inner iteration ([`DaeSystem::corrector_converged`](crate::DaeSystem::corrector_converged),
    /// e.g. the augmented Lagrangian) still asked for more after MAXIT corrector passes.
    InnerIterations {
        /// Corrector passes made.
        passes: usize,
    },
}

impl std::fmt::Display for FailureCause {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::ErrorTest { dominant } => {
                write!(
                    f,
                    "local error test failed; largest weighted errors: {}",
                    list(dominant)
                )
            }
            Self::Convergence { dominant } => write!(
                f,
                "Newton corrector did not converge; largest weighted corrections: {}",
                list(dominant)
            ),
            Self::Evaluation(e) => write!(f, "the equations could not be evaluated: {e}"),
            Self::NonFinite { index } => write!(f, "non-finite value (NaN or inf) in y[{index}]"),
            Self::SingularMatrix => write!(f, "the Newton matrix is singular"),
            Self::InnerIterations { passes } => write!(
                f,
                "the inner (augmented-Lagrangian) iteration did not settle in {passes} corrector passes"
            ),
        }
    }
}

/// An integration that cannot continue. Every variant carries the time reached and the step
/// size, and prints the remedies ([`REMEDIES`]); the accepted steps before it stay valid.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum IntegratorError {
    /// Invalid settings (the argument, value and allowed range).
    #[error("invalid INTEGRATOR setting: {0}")]
    Settings(#[from] InvalidArgument),
    /// The initial state does not fit the system: wrong length or a non-finite entry.
    #[error("invalid initial state: {what}")]
    InvalidInitialState {
        /// What is wrong (names the vector and the entry).
        what: String,
    },
    /// No first step size can be chosen: no HINIT, no HMAX, no stop time, and `y′₀ = 0`.
    #[error(
        "cannot choose the first step: give INTEGRATOR/HINIT or HMAX, or set a stop time \
         (y'(t0) is zero so it sets no time scale)"
    )]
    NoInitialStep,
    /// A requested time is not ahead of the current time (or not finite).
    #[error("{argument} = {value:?} is out of range: must be finite and > t = {t:?}")]
    InvalidTarget {
        /// `stop time` or `retry target`.
        argument: &'static str,
        /// The time asked for.
        value: f64,
        /// The integrator's time.
        t: f64,
    },
    /// Interpolation was asked outside the last step.
    #[error("interpolation at t = {t:?} is out of range: must be in [{from:?}, {to:?}]")]
    OutsideLastStep {
        /// The time asked for.
        t: f64,
        /// Start of the last accepted step.
        from: f64,
        /// End of the last accepted step.
        to: f64,
    },
    /// [`Bdf::make_consistent`](super::Bdf::make_consistent) could not make the start consistent.
    #[error("cannot make the initial point at t = {t:?} consistent: {reason}")]
    InconsistentStart {
        /// The initial time.
        t: f64,
        /// Why (index > 1, not converged, evaluation failure, already started).
        reason: String,
    },
    /// There is no accepted step to roll back (or it was already rolled back).
    #[error("no accepted step to reject: take a step first (a step can be rolled back once)")]
    NothingToReject,
    /// The step size would have to fall below HMIN to satisfy the error test or converge.
    #[error(
        "at t = {t:?} the step size h = {h:.3e} fell below HMIN = {hmin:.3e} after {failures} \
         consecutive failures; last cause: {cause}; {REMEDIES}"
    )]
    StepSizeTooSmall {
        /// Time of the last accepted point.
        t: f64,
        /// The step size that would be needed.
        h: f64,
        /// The effective HMIN.
        hmin: f64,
        /// Consecutive failed attempts of this step.
        failures: u32,
        /// Why the last attempt failed.
        cause: FailureCause,
    },
    /// The system reported a state it cannot represent at any step size
    /// ([`EvaluationError::fatal`]): the run stops at the last accepted point.
    #[error("stopped after t = {t:?}: {source}")]
    Stopped {
        /// Time of the last accepted point.
        t: f64,
        /// The system's diagnosis.
        source: EvaluationError,
    },
    /// Too many consecutive failed attempts for one step (10 convergence or evaluation
    /// failures, or 20 in all).
    #[error(
        "at t = {t:?} with h = {h:.3e}: {failures} consecutive failed attempts; last cause: \
         {cause}; {REMEDIES}"
    )]
    RepeatedFailures {
        /// Time of the last accepted point.
        t: f64,
        /// The last step size tried.
        h: f64,
        /// Consecutive failed attempts.
        failures: u32,
        /// Why the last attempt failed.
        cause: FailureCause,
    },
}
