//! Errors for bad input: every variant names the argument, the value and the allowed range.

use thiserror::Error;

/// A value given for a named argument is outside its allowed range.
///
/// This is the one error shape for every scalar argument in the crate (geometry sizes, contact
/// parameters, preferences), so messages read the same everywhere:
/// `STIFFNESS = -1 is out of range: must be > 0`.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{argument} = {value} is out of range: must be {allowed}")]
pub struct InvalidArgument {
    /// The argument's name as the user wrote it (Adams keyword where there is one).
    pub argument: &'static str,
    /// The value given, printed at round-trip precision.
    pub value: String,
    /// The allowed range, e.g. `> 0` or `in [0, 1]`.
    pub allowed: String,
}

impl InvalidArgument {
    /// Builds the error for a numeric value.
    pub fn new(argument: &'static str, value: f64, allowed: impl Into<String>) -> Self {
        Self {
            argument,
            value: format!("{value:?}"),
            allowed: allowed.into(),
        }
    }

    /// Builds the error for a non-numeric value (a count, a name, a list).
    pub fn with_text(
        argument: &'static str,
        value: impl Into<String>,
        allowed: impl Into<String>,
    ) -> Self {
        Self {
            argument,
            value: value.into(),
            allowed: allowed.into(),
        }
    }
}

/// Checks `value` is finite and `> 0`.
pub(crate) fn positive(argument: &'static str, value: f64) -> Result<f64, InvalidArgument> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(InvalidArgument::new(argument, value, "finite and > 0"))
    }
}

/// Checks `value` is finite and `>= 0`.
pub(crate) fn non_negative(argument: &'static str, value: f64) -> Result<f64, InvalidArgument> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(InvalidArgument::new(argument, value, "finite and >= 0"))
    }
}

/// Checks `value` is finite.
pub(crate) fn finite(argument: &'static str, value: f64) -> Result<f64, InvalidArgument> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(InvalidArgument::new(argument, value, "finite"))
    }
}
