//! `INTEGRATOR/` settings: ERROR, HMAX, HMIN, HINIT, KMAX, MAXIT and CORRECTOR, validated.

use contact_core::InvalidArgument;

/// Which variables the Newton corrector must have converged before it stops iterating
/// (Adams `CORRECTOR`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Corrector {
    /// Adams `CORRECTOR=ORIGINAL`: every variable takes part in the convergence test; an
    /// algebraic variable of index `i` is weighted by `h^(i−1)` (as RADAU5 does), so multipliers
    /// whose corrections grow like `1/h²` near small steps do not stall the test.
    Full,
    /// Adams `CORRECTOR=MODIFIED`: only the variables in the local error test
    /// ([`VariableKind::Differential`](crate::VariableKind::Differential)) must have
    /// converged; in steps HMAX holds below the error-controlled size, the index-2 variables of
    /// a system with index-3 ones (a mechanism's velocities under I3, which the next steps'
    /// positions are integrated from) too. Adams switches to it automatically for models with
    /// contacts; it is the default.
    #[default]
    Modified,
}

/// The integrator's controls, with Adams' names and defaults. Build with
/// [`IntegratorSettings::default`], change fields, then call [`IntegratorSettings::validate`]
/// (the integrator calls it too).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IntegratorSettings {
    /// ERROR: the local error tolerance of the weighted RMS norm
    /// `sqrt(mean((e_i / (ERROR·(|y_i| + s_i)))²))` over the differential variables, relative
    /// and, times the system's absolute scale `s_i` (default 1,
    /// [`DaeSystem::absolute_scales`](crate::DaeSystem::absolute_scales)), absolute.
    /// Default `1e-3` (Adams). Range: finite, `0 < ERROR < 1`.
    pub error: f64,
    /// HMAX: the largest step. `None` means no limit (Adams' default is the output step, which
    /// the caller sets through this field). Range: finite, `> 0`, and `≥ hmin` when both are set.
    pub hmax: Option<f64>,
    /// HMIN: the smallest step; a step that would have to fall below it stops the run with
    /// [`IntegratorError::StepSizeTooSmall`](super::IntegratorError::StepSizeTooSmall).
    /// `None` means the round-off limit `4·ε·max(|t|, |h|)`. Range: finite, `> 0`.
    pub hmin: Option<f64>,
    /// HINIT: the first step. `None` means `0.5/‖y′₀‖` (weighted RMS) capped by HMAX and by
    /// `1e-3` of the span to the first stop time. Range: finite, `> 0`, within `[hmin, hmax]`.
    pub hinit: Option<f64>,
    /// KMAX: the highest BDF order used. Default 6 (Adams). Range `1..=6`; BDF of order 7 and
    /// higher is not zero-stable. KMAX = 2 is a remedy for hard contact (A-stable up to order 2).
    pub kmax: usize,
    /// MAXIT: the most Newton iterations per step attempt before the attempt counts as a
    /// convergence failure. Default 10 (Adams). Range `1..=100`.
    pub maxit: usize,
    /// CORRECTOR: which variables must converge. Default [`Corrector::Modified`].
    pub corrector: Corrector,
}

impl Default for IntegratorSettings {
    fn default() -> Self {
        Self {
            error: 1e-3,
            hmax: None,
            hmin: None,
            hinit: None,
            kmax: 6,
            maxit: 10,
            corrector: Corrector::Modified,
        }
    }
}

impl IntegratorSettings {
    /// Checks every field against its documented range; the error names the argument (Adams
    /// keyword), the value and the range.
    pub fn validate(&self) -> Result<(), InvalidArgument> {
        if !(self.error.is_finite() && self.error > 0.0 && self.error < 1.0) {
            return Err(InvalidArgument::new(
                "ERROR",
                self.error,
                "finite and in (0, 1)",
            ));
        }
        for (name, value) in [
            ("HMAX", self.hmax),
            ("HMIN", self.hmin),
            ("HINIT", self.hinit),
        ] {
            if let Some(v) = value
                && !(v.is_finite() && v > 0.0)
            {
                return Err(InvalidArgument::new(name, v, "finite and > 0"));
            }
        }
        if let (Some(hmin), Some(hmax)) = (self.hmin, self.hmax)
            && hmin > hmax
        {
            return Err(InvalidArgument::new(
                "HMIN",
                hmin,
                format!("<= HMAX = {hmax:?}"),
            ));
        }
        if let Some(hinit) = self.hinit {
            if let Some(hmax) = self.hmax
                && hinit > hmax
            {
                return Err(InvalidArgument::new(
                    "HINIT",
                    hinit,
                    format!("<= HMAX = {hmax:?}"),
                ));
            }
            if let Some(hmin) = self.hmin
                && hinit < hmin
            {
                return Err(InvalidArgument::new(
                    "HINIT",
                    hinit,
                    format!(">= HMIN = {hmin:?}"),
                ));
            }
        }
        if !(1..=6).contains(&self.kmax) {
            return Err(InvalidArgument::with_text(
                "KMAX",
                self.kmax.to_string(),
                "in 1..=6",
            ));
        }
        if !(1..=100).contains(&self.maxit) {
            return Err(InvalidArgument::with_text(
                "MAXIT",
                self.maxit.to_string(),
                "in 1..=100",
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_adams_and_valid() {
        let s = IntegratorSettings::default();
        assert_eq!((s.error, s.kmax, s.maxit), (1e-3, 6, 10));
        assert_eq!(s.corrector, Corrector::Modified);
        assert!(s.validate().is_ok());
    }

    #[test]
    fn each_out_of_range_value_is_named() {
        let base = IntegratorSettings::default();
        let cases: Vec<(IntegratorSettings, &str)> = vec![
            (IntegratorSettings { error: 0.0, ..base }, "ERROR = 0.0"),
            (
                IntegratorSettings {
                    error: f64::NAN,
                    ..base
                },
                "ERROR = NaN",
            ),
            (
                IntegratorSettings {
                    hmax: Some(-1.0),
                    ..base
                },
                "HMAX = -1.0",
            ),
            (
                IntegratorSettings {
                    hmin: Some(0.0),
                    ..base
                },
                "HMIN = 0.0",
            ),
            (
                IntegratorSettings {
                    hmin: Some(2.0),
                    hmax: Some(1.0),
                    ..base
                },
                "HMIN = 2.0 is out of range: must be <= HMAX = 1.0",
            ),
            (
                IntegratorSettings {
                    hinit: Some(2.0),
                    hmax: Some(1.0),
                    ..base
                },
                "HINIT = 2.0",
            ),
            (
                IntegratorSettings { kmax: 7, ..base },
                "KMAX = 7 is out of range: must be in 1..=6",
            ),
            (IntegratorSettings { kmax: 0, ..base }, "KMAX = 0"),
            (IntegratorSettings { maxit: 0, ..base }, "MAXIT = 0"),
        ];
        for (settings, expected) in cases {
            let message = settings.validate().unwrap_err().to_string();
            assert!(
                message.starts_with(expected),
                "{message} does not start with {expected}"
            );
        }
    }
}
