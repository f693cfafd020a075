//! One step: predictor, modified-Newton corrector, error test, order and step-size choice,
//! and the retry logic after failures.

use super::error::{FailureCause, IntegratorError};
use super::history::{History, StepCoefficients};
use super::settings::Corrector;
use super::{Bdf, Phase, Snapshot};
use crate::DaeSystem;
use nalgebra::DVector;

/// A step whose size stays within this factor of the size the Newton matrix was built for
/// reuses it (DASSL: `(1 − r)/(1 + r)` with `r = 0.25`, i.e. `c` within `[0.6, 1.67]`).
const CJ_RATIO_LIMIT: f64 = 0.6;
/// Newton stops when `ρ/(1−ρ)·‖Δ‖ ≤ 0.33` (DASSL's constant), i.e. the remaining correction is
/// a third of the error tolerance.
const NEWTON_TOLERANCE: f64 = 0.33;
/// In a step that HMAX holds below the size the error control asks for, the Newton tolerance is
/// `NEWTON_TOLERANCE` times the last accepted step's error-test value `err ∈ [0, 1]`
/// (`ck·‖y − y⁽⁰⁾‖`, 1 at the ERROR limit), clamped to `[NEWTON_SCALE_FLOOR, 1]`: the corrector
/// converges to a third of the local error such steps actually make, not of the error they are
/// allowed. Their local errors are far below ERROR; a corrector left at a third of ERROR adds an
/// error of that size at every step, which grows with the number of steps (HMAX = 1e-5 was less
/// accurate than no HMAX). Steps the error control sizes keep DASSL's test (their `err` is O(1)
/// by construction; iterating deeper there only moves results by round-off-sized amounts that
/// change the step sequence). Below the floor the iteration would chase round-off.
const NEWTON_SCALE_FLOOR: f64 = 1e-6;
/// Newton counts as diverging when successive corrections shrink by less than this.
const MAX_RATE: f64 = 0.9;
/// A step that needed more Newton iterations than this with an old matrix asks for a fresh one
/// at the next step (slow convergence).
const SLOW_ITERATIONS: usize = 4;
/// Most convergence or evaluation failures of one step before giving up (DASSL's 10).
const MAX_CONVERGENCE_FAILURES: u32 = 10;
/// A step to a stop time may exceed HMAX by this factor: the round-off of times that are sums
/// of many HMAX steps (ulp(t)/HMAX is 1e-10 at t = 5 with HMAX = 1e-5).
const HMAX_ROUNDOFF: f64 = 1.0 + 1e-9;
/// Most failed attempts of one step in all.
const MAX_FAILURES: u32 = 20;

/// The outcome of a converged corrector with its error estimates.
struct Converged {
    y: DVector<f64>,
    yp: DVector<f64>,
    /// `e = y − y⁽⁰⁾`.
    e: DVector<f64>,
}

/// Error estimates at orders `k−1` (if `k > 1`), `k`, and the order the test suggests.
struct Estimates {
    /// Scaled estimate at order k (`erk`), and at k−1 (`erkm1`).
    erk: f64,
    erkm1: Option<f64>,
    /// `(k+1)·erk` and `k·erkm1`: the terms compared for order selection.
    terk: f64,
    terkm1: Option<f64>,
    /// Order the error test suggests (k or k−1) and its estimate.
    knew: usize,
    est: f64,
    /// The error test's value (fails above 1).
    err: f64,
}

impl Bdf {
    /// Takes one step and returns the time reached. The new point is [`Bdf::t`],
    /// [`Bdf::y`], [`Bdf::yp`]; the system's [`DaeSystem::step_accepted`] has been called.
    /// On error the integrator stays at the last accepted point.
    pub fn step(&mut self, system: &mut dyn DaeSystem) -> Result<f64, IntegratorError> {
        if self.history.is_none() {
            let h = self.initial_step()?;
            self.h = h;
            self.history = Some(History::restart(&self.y, &self.yp, h, self.settings.kmax));
        }
        let snapshot = Snapshot {
            t: self.t,
            t_prev: self.t_prev,
            y: self.y.clone(),
            yp: self.yp.clone(),
            order_taken: 0,
            stop_time: self.stop_time,
        };
        self.norms.set_weights(&self.y);
        let mut convergence_failures = 0u32;
        let mut error_failures = 0u32;
        let mut failures = 0u32;
        loop {
            let (h, t_new) = self.capped_step();
            let result = self.attempt(system, h, t_new);
            let cause = match result {
                Ok(order) => {
                    let mut snapshot = snapshot;
                    snapshot.order_taken = order;
                    self.before_last_step = Some(snapshot);
                    return Ok(self.t);
                }
                Err(Retry::SameStep) => continue,
                Err(Retry::Failed(cause)) => cause,
            };
            failures += 1;
            let shrink = match &cause {
                FailureCause::ErrorTest { .. } => {
                    error_failures += 1;
                    self.stats.rejected_error_test += 1;
                    None
                }
                FailureCause::Convergence { .. }
                | FailureCause::SingularMatrix
                | FailureCause::InnerIterations { .. } => {
                    convergence_failures += 1;
                    self.stats.rejected_convergence += 1;
                    Some(0.25)
                }
                FailureCause::Evaluation(e) if e.fatal => {
                    self.stats.rejected_evaluation += 1;
                    return Err(IntegratorError::Stopped {
                        t: self.t,
                        source: e.clone(),
                    });
                }
                FailureCause::Evaluation(_) | FailureCause::NonFinite { .. } => {
                    convergence_failures += 1;
                    self.stats.rejected_evaluation += 1;
                    Some(0.25)
                }
            };
            self.phase = Phase::Normal;
            if convergence_failures >= MAX_CONVERGENCE_FAILURES || failures >= MAX_FAILURES {
                return Err(IntegratorError::RepeatedFailures {
                    t: self.t,
                    h,
                    failures,
                    cause,
                });
            }
            let new_h = match shrink {
                Some(factor) => h * factor,
                None => self.after_error_failure(h, error_failures),
            };
            let hmin = self.hmin();
            if new_h < hmin {
                return Err(IntegratorError::StepSizeTooSmall {
                    t: self.t,
                    h: new_h,
                    hmin,
                    failures,
                    cause,
                });
            }
            self.h = new_h;
        }
    }

    /// The effective HMIN: the setting, or the round-off limit `4·ε·max(|t|, |h|)`.
    fn hmin(&self) -> f64 {
        let roundoff = 4.0 * f64::EPSILON * self.t.abs().max(self.h.abs());
        self.settings.hmin.unwrap_or(0.0).max(roundoff)
    }

    /// HINIT, or `0.5/‖y′₀‖` capped by `1e-3` of the span to the stop time and by HMAX.
    fn initial_step(&mut self) -> Result<f64, IntegratorError> {
        if let Some(hinit) = self.settings.hinit {
            return Ok(hinit);
        }
        let span = self.retry_target.or(self.stop_time).map(|s| s - self.t);
        self.norms.set_weights(&self.y);
        let yp_norm = self.norms.error_norm(&self.yp);
        let mut h = match (span, self.settings.hmax) {
            (Some(span), _) => 1e-3 * span,
            (None, Some(hmax)) => hmax,
            (None, None) if yp_norm > 0.0 => 0.5 / yp_norm,
            (None, None) => return Err(IntegratorError::NoInitialStep),
        };
        if yp_norm * h > 0.5 {
            h = 0.5 / yp_norm;
        }
        if let Some(hmax) = self.settings.hmax {
            h = h.min(hmax);
        }
        Ok(h.max(self.hmin()))
    }

    /// The step to attempt, capped by HMAX and by the nearest stop time or retry target, and
    /// the time it ends at (exactly the stop time when capped by it).
    fn capped_step(&mut self) -> (f64, f64) {
        let mut h = self.h;
        self.hmax_bound = false;
        if let Some(hmax) = self.settings.hmax {
            self.hmax_bound = h >= hmax;
            h = h.min(hmax);
        }
        self.norms.test_index_two(self.hmax_bound);
        let stop = match (self.stop_time, self.retry_target) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        if let Some(stop) = stop {
            let to_stop = stop - self.t;
            // Land on the stop time instead of leaving a sliver of less than 1% of a step:
            // take the whole span when HMAX allows it (up to round-off in the times), else
            // split it in two equal steps. A sliver step would divide the Newton corrections
            // of the positions by its size in the velocities (`y′ = c·(y − ψ)`, c ~ 1/h).
            let hmax = self.settings.hmax.unwrap_or(f64::INFINITY);
            if to_stop <= h || (h * 1.01 >= to_stop && to_stop <= hmax * HMAX_ROUNDOFF) {
                self.h = to_stop;
                return (to_stop, stop);
            }
            if h * 1.01 >= to_stop {
                self.h = 0.5 * to_stop;
                return (self.h, self.t + self.h);
            }
        }
        self.h = h;
        (h, self.t + h)
    }

    /// The step after the `failures`-th error-test failure in a row (DASSL): first by the
    /// estimate, `0.9·r ∈ [0.25, 0.9]`, at the suggested order; then by 4 at that order; then by
    /// 4 at order 1.
    fn after_error_failure(&mut self, h: f64, failures: u32) -> f64 {
        let Some(history) = self.history.as_mut() else {
            return h * 0.25;
        };
        let (knew, est) = self.last_estimate;
        match failures {
            1 => {
                history.k = knew;
                let r = 0.9 * (2.0 * est + 1e-4).powf(-1.0 / (knew as f64 + 1.0));
                h * r.clamp(0.25, 0.9)
            }
            2 => {
                history.k = knew;
                h * 0.25
            }
            _ => {
                history.k = 1;
                h * 0.25
            }
        }
    }

    /// One attempt of size `h` ending at `t_new`: Ok(order) when accepted.
    fn attempt(&mut self, system: &mut dyn DaeSystem, h: f64, t_new: f64) -> Result<usize, Retry> {
        let Some(mut history) = self.history.take() else {
            return Err(Retry::Failed(FailureCause::SingularMatrix));
        };
        let coefficients = history.begin_step(h);
        system.attempt_started(t_new, h);
        let outcome = self.correct(system, &history, coefficients, h, t_new);
        match outcome {
            Ok(converged) => {
                let estimates = self.estimate(&history, &converged.e, coefficients);
                self.last_estimate = (estimates.knew, estimates.est);
                if estimates.err > 1.0 {
                    history.restore(h);
                    self.history = Some(history);
                    let dominant =
                        self.norms
                            .dominant(&converged.e, h, self.settings.corrector, false);
                    return Err(Retry::Failed(FailureCause::ErrorTest { dominant }));
                }
                let order = history.k;
                self.accept(system, &mut history, converged, &estimates, h, t_new);
                self.history = Some(history);
                Ok(order)
            }
            Err(retry) => {
                history.restore(h);
                self.history = Some(history);
                Err(retry)
            }
        }
    }

    /// Modified Newton on `F(t, y, y′⁽⁰⁾ + c·(y − y⁽⁰⁾)) = 0` from the predictor, repeated
    /// while the system's inner iteration ([`DaeSystem::corrector_converged`], e.g. the
    /// augmented-Lagrangian update) asks for it, at most MAXIT passes.
    fn correct(
        &mut self,
        system: &mut dyn DaeSystem,
        history: &History,
        coefficients: StepCoefficients,
        h: f64,
        t_new: f64,
    ) -> Result<Converged, Retry> {
        let n = self.y.len();
        let cj = coefficients.cj;
        let mut state = Converged {
            y: DVector::zeros(n),
            yp: DVector::zeros(n),
            e: DVector::zeros(n),
        };
        history.predict(&mut state.y, &mut state.yp);
        let ratio = cj / self.newton.cj;
        if !self.newton.is_factorised() || !(CJ_RATIO_LIMIT..=1.0 / CJ_RATIO_LIMIT).contains(&ratio)
        {
            self.newton.invalidate();
        }
        let mut passes = 0;
        loop {
            self.newton_iterations(system, &mut state, cj, h, t_new)?;
            if !system.corrector_converged(t_new, &state.y, &state.yp) {
                return Ok(state);
            }
            passes += 1;
            self.stats.inner_iterations += 1;
            if passes >= self.settings.maxit {
                return Err(Retry::Failed(FailureCause::InnerIterations { passes }));
            }
        }
    }

    /// Newton iterations from `state` until converged (Ok) or failed.
    fn newton_iterations(
        &mut self,
        system: &mut dyn DaeSystem,
        state: &mut Converged,
        cj: f64,
        h: f64,
        t_new: f64,
    ) -> Result<(), Retry> {
        let corrector = self.settings.corrector;
        let start_norm = self.norms.convergence_norm(&state.y, h, corrector);
        let mut fresh = false;
        // The rate estimate s = ρ/(1−ρ) starts pessimistic at every step, so a step needs a
        // second iteration (a measured rate) unless its first correction is already 300× below
        // the tolerance. DASSL carries s over from the previous step; with index-3 systems that
        // accepted one-iteration steps whose velocities and multipliers had not converged (the
        // Modified test sees displacements only), which cost 3.5× the steps and 60× the energy
        // drift on the pendulum test.
        let mut rate_factor = 100.0;
        let mut delta = DVector::zeros(state.y.len());
        let mut old_norm = 0.0;
        for m in 0..self.settings.maxit {
            self.stats.residual_evaluations += 1;
            system
                .residual(t_new, &state.y, &state.yp, &mut delta)
                .map_err(|err| Retry::Failed(FailureCause::Evaluation(err)))?;
            if let Some(index) = delta.iter().position(|v| !v.is_finite()) {
                return Err(Retry::Failed(FailureCause::NonFinite { index }));
            }
            if !self.newton.is_factorised() {
                self.stats.jacobian_evaluations += 1;
                let kinds = self.norms.kinds().to_vec();
                self.newton
                    .refresh(system, t_new, &state.y, &state.yp, cj, h, &kinds)
                    .map_err(Retry::Failed)?;
                self.stats.lu_factorizations += 1;
                fresh = true;
            }
            if cj != self.newton.cj {
                // A matrix built for another c: damp the correction (DASSL).
                delta *= 2.0 / (1.0 + cj / self.newton.cj);
            }
            if !self.newton.solve(&mut delta) {
                return Err(Retry::Failed(FailureCause::SingularMatrix));
            }
            self.stats.newton_iterations += 1;
            if let Some(index) = delta.iter().position(|v| !v.is_finite()) {
                return Err(Retry::Failed(FailureCause::NonFinite { index }));
            }
            state.y -= &delta;
            state.e -= &delta;
            state.yp.axpy(-cj, &delta, 1.0);
            let norm = self.norms.convergence_norm(&delta, h, corrector);
            // The rate is a property of the whole iteration: measure it on every variable
            // (algebraic ones weighted by h^(index−1)) even when the stopping test looks at the
            // differential ones only. Measured on displacements alone it was noisy near
            // convergence and triggered 4× the Newton-matrix refreshes on the pendulum.
            let rate_norm = self.norms.convergence_norm(&delta, h, Corrector::Full);
            if m == 0 {
                old_norm = rate_norm;
                if norm <= 100.0 * f64::EPSILON * start_norm {
                    return Ok(());
                }
            } else {
                let rate = (rate_norm / old_norm).powf(1.0 / m as f64);
                if rate > MAX_RATE {
                    // Stalled below the unscaled tolerance: converged to round-off.
                    if self.hmax_bound && 100.0 * norm <= NEWTON_TOLERANCE {
                        return Ok(());
                    }
                    return self.not_converged(fresh, &delta, h);
                }
                rate_factor = rate / (1.0 - rate);
            }
            let scale = if self.hmax_bound {
                self.newton_scale
            } else {
                1.0
            };
            if rate_factor * norm <= NEWTON_TOLERANCE * scale {
                if m + 1 >= SLOW_ITERATIONS && !fresh {
                    self.newton.invalidate();
                }
                return Ok(());
            }
            // Out of iterations but within the unscaled tolerance: as converged as DASSL's test.
            if self.hmax_bound
                && m + 1 == self.settings.maxit
                && rate_factor * norm <= NEWTON_TOLERANCE
            {
                return Ok(());
            }
        }
        self.not_converged(fresh, &delta, h)
    }

    /// A Newton failure: with an old matrix, retry the same step with a new one; with a fresh
    /// matrix, the attempt fails.
    fn not_converged(&mut self, fresh: bool, delta: &DVector<f64>, h: f64) -> Result<(), Retry> {
        if fresh {
            let dominant = self.norms.dominant(delta, h, self.settings.corrector, true);
            Err(Retry::Failed(FailureCause::Convergence { dominant }))
        } else {
            self.newton.invalidate();
            Err(Retry::SameStep)
        }
    }

    /// Error estimates at orders k and k−1 (k−2 for the decision), DASSL block 4.
    fn estimate(
        &self,
        history: &History,
        e: &DVector<f64>,
        coefficients: StepCoefficients,
    ) -> Estimates {
        let k = history.k;
        let norm = |v: &DVector<f64>| self.norms.error_norm(v);
        let enorm = norm(e);
        let erk = history.sigma(k) * enorm;
        let terk = (k as f64 + 1.0) * erk;
        let mut estimates = Estimates {
            erk,
            erkm1: None,
            terk,
            terkm1: None,
            knew: k,
            est: erk,
            err: coefficients.ck * enorm,
        };
        if k > 1 {
            let mut delta = &history.phi[k] + e;
            let erkm1 = history.sigma(k - 1) * norm(&delta);
            let terkm1 = k as f64 * erkm1;
            estimates.erkm1 = Some(erkm1);
            estimates.terkm1 = Some(terkm1);
            let lower = if k > 2 {
                delta += &history.phi[k - 1];
                let terkm2 = (k as f64 - 1.0) * history.sigma(k - 2) * norm(&delta);
                terkm1.max(terkm2) <= terk
            } else {
                terkm1 <= 0.5 * terk
            };
            if lower {
                estimates.knew = k - 1;
                estimates.est = erkm1;
            }
        }
        estimates
    }

    /// Accepts the step: new order and step size (DASSL block 5), history update, bookkeeping.
    fn accept(
        &mut self,
        system: &mut dyn DaeSystem,
        history: &mut History,
        converged: Converged,
        estimates: &Estimates,
        h: f64,
        t_new: f64,
    ) {
        let k = history.k;
        let kmax = self.settings.kmax;
        let raised_last_step = k == history.kold + 1;
        history.kold = k;
        history.hold = h;
        if estimates.knew + 1 == k || k == kmax {
            self.phase = Phase::Normal;
        }
        let (k_next, h_next) = if self.phase == Phase::StartUp {
            (k + 1, 2.0 * h)
        } else {
            let (k_next, est) =
                self.choose_order(history, &converged.e, estimates, raised_last_step);
            let r = (2.0 * est + 1e-4).powf(-1.0 / (k_next as f64 + 1.0));
            let h_next = if r >= 2.0 {
                2.0 * h
            } else if r <= 1.0 {
                h * r.clamp(0.5, 0.9)
            } else {
                h
            };
            (k_next, h_next)
        };
        self.newton_scale = estimates.err.clamp(NEWTON_SCALE_FLOOR, 1.0);
        history.accept(&converged.e, k, kmax);
        history.k = k_next;
        self.h = h_next;
        self.t_prev = self.t;
        self.t = t_new;
        self.y = converged.y;
        self.yp = converged.yp;
        self.last_order = k;
        self.stats.steps += 1;
        self.stats.steps_by_order[k] += 1;
        if self.retry_target.is_some_and(|target| t_new >= target) {
            self.retry_target = None;
        }
        if self.stop_time.is_some_and(|stop| t_new >= stop) {
            self.stop_time = None;
        }
        system.step_accepted(self.t, &self.y, &self.yp);
    }

    /// The order for the next step and its error estimate (DASSL block 5): lower if the test
    /// suggested it; otherwise, after `k+1` steps of constant size and not right after a raise,
    /// compare the estimates at `k−1`, `k`, `k+1`.
    fn choose_order(
        &self,
        history: &History,
        e: &DVector<f64>,
        estimates: &Estimates,
        raised_last_step: bool,
    ) -> (usize, f64) {
        let k = history.k;
        if estimates.knew + 1 == k {
            return (k - 1, estimates.est);
        }
        if k == self.settings.kmax || k + 1 >= history.ns || raised_last_step {
            return (k, estimates.est);
        }
        let erkp1 = self.norms.error_norm(&(e - &history.phi[k + 1])) / (k as f64 + 2.0);
        let terkp1 = (k as f64 + 2.0) * erkp1;
        match (estimates.terkm1, estimates.erkm1) {
            (Some(terkm1), Some(erkm1)) if terkm1 <= estimates.terk.min(terkp1) => (k - 1, erkm1),
            (Some(_), _) if terkp1 < estimates.terk => (k + 1, erkp1),
            (None, _) if terkp1 < 0.5 * estimates.terk => (k + 1, erkp1),
            _ => (k, estimates.erk),
        }
    }
}

/// How a failed attempt continues.
pub(super) enum Retry {
    /// Same step again (the Newton matrix was stale and has been dropped).
    SameStep,
    /// The attempt failed for this cause.
    Failed(FailureCause),
}
