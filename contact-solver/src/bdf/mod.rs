//! A GSTIFF-style BDF integrator for implicit DAEs `F(t, y, y′) = 0`.
//!
//! # Method
//! Backward differentiation formulas of orders 1..KMAX (≤ 6) with variable step and variable
//! order, in **fixed-leading-coefficient** form (Jackson & Sacks-Davis, ACM TOMS 6, 1980; the
//! form of DASSL, Petzold 1982): the history is kept as modified divided differences
//! ([`history`](self) module docs give the formulas) so any step size can follow any other
//! without interpolating the history, while the corrector's leading coefficient
//! `c = (Σ_{j=1..k} 1/j)/h` depends on `h` and `k` only. We chose it over Gear's fixed-coefficient
//! Nordsieck form (GSTIFF's own) because contact runs change the step all the time — retries to
//! the contact onset, steps cut at output times — and the Nordsieck form's interpolated history
//! loses stability under such changes (the reason Adams added WSTIFF); with a fixed leading
//! coefficient the Newton matrix stays reusable across those changes as long as `c` is.
//!
//! Each step:
//! 1. predicts `y⁽⁰⁾`, `y′⁽⁰⁾` from the history polynomial;
//! 2. corrects with modified Newton on `F(t, y, y′⁽⁰⁾ + c·(y − y⁽⁰⁾)) = 0`, reusing the
//!    factorised, scaled Newton matrix `∂F/∂y + c·∂F/∂y′` across iterations and steps; it is
//!    rebuilt when Newton fails with an old matrix or needed 4 or more iterations with it,
//!    when `c` moved out of `[0.6, 1.67]×` its value at factorisation, or on request ([`Bdf::request_newton_matrix`]); a stale matrix's
//!    corrections are damped by `2/(1 + c/c_old)`. Convergence: the rate `ρ` of successive
//!    corrections gives `ρ/(1−ρ)·‖Δ‖ ≤ 0.33·s` (DASSL's test, in the ERROR-weighted norm), with
//!    `ρ` measured within the step on all variables, `‖Δ‖` over the variables [`Corrector`]
//!    names, and `s = 1`, or in steps HMAX holds below the error-controlled size, the last
//!    accepted step's error-test value clamped to `[1e-6, 1]`: the corrector converges to a
//!    third of the local error such steps make, so they do not pile up corrector errors of
//!    ERROR's size (a first correction below `0.0033·s` also converges). `ρ > 0.9` or MAXIT
//!    iterations fail, unless (in such a step) the correction is already within DASSL's
//!    unscaled test (round-off reached). A system with an inner
//!    iteration (augmented Lagrangian) may ask for further passes
//!    ([`DaeSystem::corrector_converged`]);
//! 3. estimates the local error `ck·‖y − y⁽⁰⁾‖` in the weighted RMS norm over the differential
//!    variables only (ERROR relative and absolute), rejects above 1;
//! 4. chooses the next order among `k−1, k, k+1` by comparing the error estimates
//!    `(j+1)·σ_{j+1}·‖∇^{j+1}y‖` of each, and the next step from `r = (2·est + 1e-4)^(−1/(k+1))`:
//!    doubled if `r ≥ 2`, kept if `1 < r < 2`, else cut by `r ∈ [0.5, 0.9]`; capped by HMAX,
//!    stop times and retry targets. After a start or restart the order rises by one and the step
//!    doubles each step until the error estimates say otherwise.
//!
//! On an error-test failure the step is cut by `0.9·r ∈ [0.25, 0.9]`, then by 4 with order
//! `k−1`, then by 4 at order 1; on a convergence or evaluation failure by 4. A step that would
//! fall below HMIN stops with [`IntegratorError::StepSizeTooSmall`], naming the dominant
//! variables and the remedies.
//!
//! # Index-3 DAEs
//! Variables of kind [`VariableKind::Algebraic`] never enter the error test, their Newton
//! columns are scaled by `h^(1−index)` (see `newton_matrix`), and [`Corrector::Full`] weights
//! them by `h^(index−1)` in the convergence test. For Adams' I3 formulation mark positions
//! differential, velocities `Algebraic { index: 2 }` and multipliers `Algebraic { index: 3 }`
//! (as RADAU5's NIND2/NIND3): the error is then tested on displacements only, as Adams does.
//!
//! # Driving it
//! [`Bdf::make_consistent`] computes `y′(t0)` (and index-1 algebraic `y(t0)`) for systems of
//! index ≤ 1; [`Bdf::step`] takes one step and returns the accepted time; [`Bdf::set_stop_time`] makes
//! steps end exactly at a time; [`Bdf::interpolate`] gives the solution anywhere in the last
//! step; [`Bdf::reject_last_step_and_retry_to`] rolls the last step back and restarts at order 1
//! with a step ending at a chosen time (contact onset); [`Bdf::stats`] counts the work.
//!
//! ```
//! use contact_solver::bdf::{Bdf, IntegratorSettings};
//! use contact_solver::{DaeSystem, EvaluationError, VariableKind};
//! use nalgebra::{DMatrix, DVector};
//!
//! /// y′ = −y, as F = y′ + y.
//! struct Decay;
//! impl DaeSystem for Decay {
//!     fn size(&self) -> usize { 1 }
//!     fn variable_kinds(&self) -> Vec<VariableKind> { vec![VariableKind::Differential] }
//!     fn residual(&mut self, _t: f64, y: &DVector<f64>, yp: &DVector<f64>,
//!                 out: &mut DVector<f64>) -> Result<(), EvaluationError> {
//!         out[0] = yp[0] + y[0];
//!         Ok(())
//!     }
//!     fn newton_matrix(&mut self, _t: f64, _y: &DVector<f64>, _yp: &DVector<f64>, c: f64,
//!                      out: &mut DMatrix<f64>) -> Result<(), EvaluationError> {
//!         out[(0, 0)] = 1.0 + c;
//!         Ok(())
//!     }
//! }
//!
//! let settings = IntegratorSettings { error: 1e-6, ..IntegratorSettings::default() };
//! let mut system = Decay;
//! let y0 = DVector::from_element(1, 1.0);
//! let mut bdf = Bdf::new(&system, 0.0, y0.clone(), -y0, settings)?;
//! bdf.set_stop_time(Some(1.0))?;
//! while bdf.t() < 1.0 {
//!     bdf.step(&mut system)?;
//! }
//! assert_eq!(bdf.t(), 1.0);
//! assert!((bdf.y()[0] - (-1.0_f64).exp()).abs() < 1e-5);
//! # Ok::<(), contact_solver::bdf::IntegratorError>(())
//! ```

mod consistent;
mod error;
mod history;
mod islands;
mod newton_matrix;
mod norms;
pub mod reference;
mod settings;
mod sparse_newton;
mod stats;
mod step;
#[cfg(test)]
mod tests;

pub use error::{Dominant, FailureCause, IntegratorError, REMEDIES};
pub use newton_matrix::NewtonMatrix;
pub use settings::{Corrector, IntegratorSettings};
pub use stats::IntegratorStats;

use crate::{DaeSystem, VariableKind};
use contact_core::InvalidArgument;
use history::History;
use nalgebra::DVector;
use norms::Norms;

/// Whether the integrator is in its start-up phase (order and step rising every step).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Phase {
    StartUp,
    Normal,
}

/// The state a step can be rolled back to.
#[derive(Debug, Clone)]
struct Snapshot {
    t: f64,
    t_prev: f64,
    y: DVector<f64>,
    yp: DVector<f64>,
    order_taken: usize,
    /// The stop time before the step (the step may have reached and cleared it).
    stop_time: Option<f64>,
}

/// A variable-step, variable-order BDF integrator (see the [module docs](self)).
pub struct Bdf {
    settings: IntegratorSettings,
    norms: Norms,
    t: f64,
    t_prev: f64,
    y: DVector<f64>,
    yp: DVector<f64>,
    /// The step size the next attempt tries (0 before the first step).
    h: f64,
    history: Option<History>,
    phase: Phase,
    newton: NewtonMatrix,
    stop_time: Option<f64>,
    retry_target: Option<f64>,
    before_last_step: Option<Snapshot>,
    last_order: usize,
    /// The order the last error test suggested and its estimate (for the retry after a
    /// failed test).
    last_estimate: (usize, f64),
    /// The factor on the Newton tolerance: the last accepted step's error-test value, clamped
    /// (see `step.rs`).
    newton_scale: f64,
    /// Whether HMAX bounds the step being attempted (the error control chose HMAX or more).
    hmax_bound: bool,
    stats: IntegratorStats,
}

impl Bdf {
    /// An integrator at `(t0, y0, y′0)` for `system`. `y′0` need not be consistent for the
    /// algebraic variables; for the differential ones it sets the first predictor (an
    /// inconsistent value costs rejected first steps, not accuracy). Errors: invalid settings,
    /// a length other than `system.size()`, or a non-finite entry.
    pub fn new(
        system: &dyn DaeSystem,
        t0: f64,
        y0: DVector<f64>,
        yp0: DVector<f64>,
        settings: IntegratorSettings,
    ) -> Result<Self, IntegratorError> {
        settings.validate()?;
        let n = system.size();
        let kinds = system.variable_kinds();
        if kinds.len() != n {
            return Err(IntegratorError::InvalidInitialState {
                what: format!(
                    "variable_kinds() has {} entries, size() is {n}",
                    kinds.len()
                ),
            });
        }
        if let Some(bad) = kinds
            .iter()
            .find(|k| matches!(k, VariableKind::Algebraic { index } if !(1..=3).contains(index)))
        {
            return Err(IntegratorError::InvalidInitialState {
                what: format!("{bad:?}: an algebraic variable's index must be in 1..=3"),
            });
        }
        let scales = DVector::from_vec(system.absolute_scales());
        if scales.len() != n {
            return Err(IntegratorError::InvalidInitialState {
                what: format!(
                    "absolute_scales() has {} entries, size() is {n}",
                    scales.len()
                ),
            });
        }
        if let Some(i) = scales.iter().position(|s| !(s.is_finite() && *s > 0.0)) {
            return Err(IntegratorError::InvalidInitialState {
                what: format!(
                    "absolute_scales()[{i}] = {:?} must be finite and > 0",
                    scales[i]
                ),
            });
        }
        for (name, v) in [("y0", &y0), ("yp0", &yp0)] {
            if v.len() != n {
                return Err(IntegratorError::InvalidInitialState {
                    what: format!("{name} has length {}, the system has size {n}", v.len()),
                });
            }
            if let Some(i) = v.iter().position(|x| !x.is_finite()) {
                return Err(IntegratorError::InvalidInitialState {
                    what: format!("{name}[{i}] = {:?} is not finite", v[i]),
                });
            }
        }
        if !t0.is_finite() {
            return Err(IntegratorError::InvalidInitialState {
                what: format!("t0 = {t0:?} is not finite"),
            });
        }
        Ok(Self {
            settings,
            norms: Norms::new(kinds, scales, settings.error),
            t: t0,
            t_prev: t0,
            y: y0,
            yp: yp0,
            h: 0.0,
            history: None,
            phase: Phase::StartUp,
            newton: NewtonMatrix::new(n),
            stop_time: None,
            retry_target: None,
            before_last_step: None,
            last_order: 0,
            last_estimate: (1, 0.0),
            newton_scale: 1.0,
            hmax_bound: false,
            stats: IntegratorStats::default(),
        })
    }

    /// Time of the last accepted point.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Solution at [`Bdf::t`].
    pub fn y(&self) -> &DVector<f64> {
        &self.y
    }

    /// Derivative at [`Bdf::t`] (from the corrector: `y′⁽⁰⁾ + c·(y − y⁽⁰⁾)`).
    pub fn yp(&self) -> &DVector<f64> {
        &self.yp
    }

    /// The step size the next attempt will try (before HMAX and stop-time capping); 0 before
    /// the first step.
    pub fn next_step_size(&self) -> f64 {
        self.h
    }

    /// The order of the last accepted step (0 before the first).
    pub fn last_order(&self) -> usize {
        self.last_order
    }

    /// Start of the last accepted step (equal to [`Bdf::t`] before the first).
    pub fn t_previous(&self) -> f64 {
        self.t_prev
    }

    /// The settings in force.
    pub fn settings(&self) -> &IntegratorSettings {
        &self.settings
    }

    /// Work counters.
    pub fn stats(&self) -> &IntegratorStats {
        &self.stats
    }

    /// Makes every later step end at or before `stop` and land on it exactly (output times,
    /// the end time, a MOTION's kink); once a step lands on it the stop time is cleared, so
    /// the caller sets the next one. `None` removes it. Error if `stop` is not finite or not
    /// after [`Bdf::t`].
    pub fn set_stop_time(&mut self, stop: Option<f64>) -> Result<(), IntegratorError> {
        if let Some(s) = stop
            && !(s.is_finite() && s > self.t)
        {
            return Err(IntegratorError::InvalidTarget {
                argument: "stop time",
                value: s,
                t: self.t,
            });
        }
        self.stop_time = stop;
        Ok(())
    }

    /// Asks for a fresh Newton matrix at the next iteration (e.g. a contact became active, so
    /// the old matrix lacks its stiffness).
    pub fn request_newton_matrix(&mut self) {
        self.newton.invalidate();
    }

    /// The solution and its derivative at `t` inside the last accepted step
    /// `[t_previous, t]`, from the BDF interpolating polynomial of that step's order (dense
    /// output, accurate to the order of the step). Before the first step only `t = t0` is valid.
    pub fn interpolate(&self, t: f64) -> Result<(DVector<f64>, DVector<f64>), IntegratorError> {
        let span = (self.t - self.t_prev).abs();
        let slack = 1e-12 * span.max(self.t.abs());
        if !(t >= self.t_prev - slack && t <= self.t + slack) {
            return Err(IntegratorError::OutsideLastStep {
                t,
                from: self.t_prev,
                to: self.t,
            });
        }
        let mut y = self.y.clone();
        let mut yp = self.yp.clone();
        if let Some(history) = &self.history
            && history.kold > 0
            && t != self.t
        {
            history.interpolate(self.t, t, &mut y, &mut yp);
        }
        Ok((y, yp))
    }

    /// Rolls back the last accepted step and restarts at order 1 from the point before it,
    /// with a first step that ends exactly at `t_target` (SPEC §8 contact prediction). Returns
    /// the time reached by that step, as [`Bdf::step`] does. `t_target` must lie after the
    /// restored time; steps keep ending at or before it until it is reached (HMAX or the error
    /// test may split it into several steps). The system is not told of the roll-back: state it
    /// updated in [`DaeSystem::step_accepted`] is the caller's to restore. A step can be rolled
    /// back once; error [`IntegratorError::NothingToReject`] otherwise.
    pub fn reject_last_step_and_retry_to(
        &mut self,
        system: &mut dyn DaeSystem,
        t_target: f64,
    ) -> Result<f64, IntegratorError> {
        let Some(snapshot) = self.before_last_step.take() else {
            return Err(IntegratorError::NothingToReject);
        };
        if !(t_target.is_finite() && t_target > snapshot.t) {
            let t = snapshot.t;
            self.before_last_step = Some(snapshot);
            return Err(IntegratorError::InvalidTarget {
                argument: "retry target",
                value: t_target,
                t,
            });
        }
        self.stats.steps = self.stats.steps.saturating_sub(1);
        let order = snapshot.order_taken.min(6);
        self.stats.steps_by_order[order] = self.stats.steps_by_order[order].saturating_sub(1);
        self.stats.rejected_by_caller += 1;
        self.t = snapshot.t;
        self.t_prev = snapshot.t_prev;
        self.y = snapshot.y;
        self.yp = snapshot.yp;
        self.stop_time = snapshot.stop_time;
        let h = t_target - self.t;
        self.h = h;
        self.history = Some(History::restart(&self.y, &self.yp, h, self.settings.kmax));
        self.phase = Phase::StartUp;
        self.retry_target = Some(t_target);
        self.last_order = 0;
        self.step(system)
    }

    /// Restarts at order 1 from the current point with first step `h` (after a discontinuity
    /// the caller handled itself, e.g. a changed MOTION). Error if `h` is not finite and > 0.
    pub fn restart(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(InvalidArgument::new("restart step", h, "finite and > 0").into());
        }
        self.h = h;
        self.history = Some(History::restart(&self.y, &self.yp, h, self.settings.kmax));
        self.phase = Phase::StartUp;
        self.before_last_step = None;
        Ok(())
    }
}
