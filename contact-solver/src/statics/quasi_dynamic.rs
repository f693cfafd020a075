//! The quasi-dynamic method (EQUILIBRIUM/DYNAMIC): damped dynamics at frozen time until the
//! parts settle, then static Newton.
//!
//! - **Time scale** `T`: `sqrt(L/|g|)` with gravity `g` (the time to fall about one model
//!   length); without gravity `1/ω` with `ω² = max K_ii/M_ii` over the diagonal of the static
//!   Jacobian (the fastest stiffness already acting). No gravity and no stiffness: an error.
//! - **Damping**: every moving part gets a force `−2m·u/T` and a torque `−2·(tr J/3)·ω/T`
//!   ([`AddedDamping`]): critical damping of a motion of period `2πT`, stronger damping for
//!   slower motions. Contacts keep their own damping; the BDF damps the fast contact modes.
//! - **Frozen time**: the model is evaluated at the statics time `t` throughout (MOTIONs and
//!   time functions do not advance); the integrator's own clock runs from 0.
//! - **Settling**: the dynamics run in windows of `T`; at the end of a window where every
//!   part's speed is below `SETTLED_SPEED` (relative: `|u|·T/L`, `|ω|·T`), Newton starts from
//!   the positions reached (velocities zeroed). Its success ends the method; its failure lets
//!   the dynamics run on. After `MAX_WINDOWS` windows, or `MAX_DAMPED_STEPS` steps in all (a
//!   contact whose force steps from facet to facet can hold the steps short for ever), the
//!   method fails with a diagnosis.
//! - **Augmented-Lagrangian contacts** settle on the multipliers they have: the inner update
//!   of the dynamics is off (at rest it chatters — an approach adds `p·δ`, a separation drops
//!   the multiplier from the force — and the settling crawls), and the statics augments the
//!   multipliers once the parts are at rest ([`super::augmented`]).

use super::newton::{self, NewtonFailure, static_jacobian, zero_velocities};
use super::{Equilibrium, StaticsDiagnosis, StaticsError, StaticsMethod, StaticsSettings};
use crate::bdf::{Bdf, IntegratorSettings};
use crate::dae::{DaeSystem, EvaluationError, VariableKind};
use crate::mbs::{ForceElement, Load, MultibodySystem, PartId, StateView};
use nalgebra::{DMatrix, DVector, Matrix3};

/// Speeds below which the parts count as settled (relative, see the module docs).
pub const SETTLED_SPEED: f64 = 1e-3;
/// The most windows of `T` the damped dynamics run.
pub const MAX_WINDOWS: usize = 200;
/// The most steps the damped dynamics take over all windows: a settling body takes a few
/// thousand (a ball or an ellipsoid dropped onto a plane: 4,000–5,000); one that never settles
/// would otherwise run for hours.
pub const MAX_DAMPED_STEPS: u64 = 100_000;

/// Mass-proportional damping on every moving part.
#[derive(Debug)]
pub struct AddedDamping {
    parts: Vec<PartId>,
    linear: Vec<f64>,
    angular: Vec<f64>,
}

impl AddedDamping {
    /// Damping at rate `2/T` for every moving part of `system`.
    pub fn for_system(system: &MultibodySystem, time_scale: f64) -> Self {
        let rate = 2.0 / time_scale;
        let (linear, angular) = system
            .mass_properties()
            .map(|(m, inertia)| (rate * m, rate * inertia.trace() / 3.0))
            .unzip();
        Self {
            parts: system.moving_parts().collect(),
            linear,
            angular,
        }
    }
}

impl ForceElement for AddedDamping {
    fn name(&self) -> &str {
        "quasi-dynamic damping"
    }

    fn parts(&self) -> &[PartId] {
        &self.parts
    }

    fn evaluate(
        &self,
        _t: f64,
        state: &StateView<'_>,
        loads: &mut [Load],
    ) -> Result<(), EvaluationError> {
        for (k, part) in self.parts.iter().enumerate() {
            let s = state.part(*part);
            loads[k] = Load {
                force_w: -s.velocity_w * self.linear[k],
                torque_w: -s.angular_velocity_w * self.angular[k],
            };
        }
        Ok(())
    }

    fn partials(
        &self,
        _t: f64,
        _state: &StateView<'_>,
    ) -> Option<Result<DMatrix<f64>, EvaluationError>> {
        let p = self.parts.len();
        let mut partials = DMatrix::zeros(6 * p, 12 * p);
        for k in 0..p {
            partials
                .fixed_view_mut::<3, 3>(6 * k, 12 * k + 6)
                .copy_from(&(Matrix3::identity() * -self.linear[k]));
            partials
                .fixed_view_mut::<3, 3>(6 * k + 3, 12 * k + 9)
                .copy_from(&(Matrix3::identity() * -self.angular[k]));
        }
        Some(Ok(partials))
    }
}

/// The system evaluated at a fixed time whatever time the integrator asks for.
struct FrozenTime<'a> {
    system: &'a mut MultibodySystem,
    t: f64,
}

impl DaeSystem for FrozenTime<'_> {
    fn size(&self) -> usize {
        self.system.size()
    }

    fn variable_kinds(&self) -> Vec<VariableKind> {
        self.system.variable_kinds()
    }

    fn absolute_scales(&self) -> Vec<f64> {
        self.system.absolute_scales()
    }

    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        self.system.residual(self.t, y, yp, out)
    }

    fn newton_matrix(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        self.system.newton_matrix(self.t, y, yp, c, out)
    }

    fn attempt_started(&mut self, _t_new: f64, h: f64) {
        self.system.attempt_started(self.t, h);
    }

    /// No inner iteration while the parts settle: augmented-Lagrangian multipliers stay as
    /// they are and are augmented after the settling, at rest ([`super::augmented`]).
    fn corrector_converged(&mut self, _t: f64, _y: &DVector<f64>, _yp: &DVector<f64>) -> bool {
        false
    }

    fn step_accepted(&mut self, _t: f64, y: &DVector<f64>, yp: &DVector<f64>) {
        self.system.step_accepted(self.t, y, yp);
    }
}

/// The time scale `T` of the module docs at the assembled start `y` (velocities zero).
fn time_scale(
    system: &mut MultibodySystem,
    t: f64,
    y: &DVector<f64>,
) -> Result<f64, EvaluationError> {
    let g = system.gravity_w.norm();
    if g > 0.0 {
        return Ok((system.length_scale() / g).sqrt());
    }
    let jacobian = static_jacobian(system, t, y, 0.0)?;
    let mut omega_squared: f64 = 0.0;
    for (k, (mass, inertia)) in system.mass_properties().enumerate() {
        for c in 0..3 {
            omega_squared = omega_squared
                .max(jacobian[(6 * k + c, 6 * k + c)] / mass)
                .max(jacobian[(6 * k + 3 + c, 6 * k + 3 + c)] / inertia[(c, c)]);
        }
    }
    if omega_squared > 0.0 && omega_squared.is_finite() {
        Ok(1.0 / omega_squared.sqrt())
    } else {
        Err(EvaluationError {
            element: "EQUILIBRIUM/DYNAMIC".into(),
            message: "the quasi-dynamic method needs gravity or a stiffness acting at the start to set its time scale".into(),
            fatal: true,
        })
    }
}

/// The quasi-dynamic method from the assembled start `start` (velocities zero) at time `t`.
/// `newton_failure` is the static Newton's failure when this runs as the fallback.
pub fn settle(
    system: &mut MultibodySystem,
    t: f64,
    start: &DVector<f64>,
    settings: &StaticsSettings,
    newton_failure: Option<NewtonFailure>,
) -> Result<Equilibrium, StaticsError> {
    let prior = newton_failure.as_ref().map_or(0, |f| f.iterations);
    let scale = match time_scale(system, t, start) {
        Ok(s) => s,
        Err(e) => {
            let cause = match &newton_failure {
                Some(f) => format!("static Newton: {f}; quasi-dynamic: {e}"),
                None => format!("quasi-dynamic: {e}"),
            };
            let diagnosis = StaticsDiagnosis::at(system, t, start, cause, prior);
            return Err(StaticsError::NotConverged(Box::new(diagnosis)));
        }
    };
    system
        .forces
        .push(Box::new(AddedDamping::for_system(system, scale)));
    let outcome = damped_dynamics(system, t, start, settings, scale);
    system.forces.pop();
    let why = newton_failure.map(|f| f.to_string());
    match outcome {
        Ok((y, iterations, imbalance, steps, duration)) => Ok(Equilibrium {
            y,
            method: StaticsMethod::QuasiDynamic {
                newton_failure: why,
                steps,
                duration,
            },
            iterations: prior + iterations,
            imbalance,
        }),
        Err((y, cause, iterations)) => {
            let cause = match why {
                Some(w) => format!("static Newton: {w}; quasi-dynamic: {cause}"),
                None => format!("quasi-dynamic: {cause}"),
            };
            let diagnosis = StaticsDiagnosis::at(system, t, &y, cause, prior + iterations);
            Err(StaticsError::NotConverged(Box::new(diagnosis)))
        }
    }
}

/// `Ok((equilibrium y, Newton iterations, imbalance, steps, duration))` or
/// `Err((last y, cause, Newton iterations))`.
type DampedOutcome = Result<(DVector<f64>, usize, f64, u64, f64), (DVector<f64>, String, usize)>;

/// Integrates the damped dynamics window by window, trying Newton whenever the parts have
/// settled. The damping element is already in the system.
fn damped_dynamics(
    system: &mut MultibodySystem,
    t: f64,
    start: &DVector<f64>,
    settings: &StaticsSettings,
    scale: f64,
) -> DampedOutcome {
    let mut y = start.clone();
    let (acceleration, lambda) = match system.compute_accelerations_and_multipliers(t, &y) {
        Ok(a) => a,
        Err(e) => return Err((y, e.to_string(), 0)),
    };
    let layout = *system.layout();
    y.rows_mut(layout.lambda_offset(), layout.constraint_rows())
        .copy_from(&lambda);
    let mut yp = DVector::zeros(layout.size());
    for (k, part) in system.moving_parts().enumerate() {
        yp.rows_mut(layout.velocity_offset(part), 6)
            .copy_from(&acceleration.rows(6 * k, 6));
    }
    let integrator = IntegratorSettings {
        hmax: Some(settings.integrator.hmax.map_or(scale, |h| h.min(scale))),
        ..settings.integrator
    };
    let mut frozen = FrozenTime { system, t };
    let mut bdf = match Bdf::new(&frozen, 0.0, y.clone(), yp, integrator) {
        Ok(b) => b,
        Err(e) => return Err((y, e.to_string(), 0)),
    };
    let mut iterations = 0;
    let mut last_failure = String::from("the parts never settled");
    for window in 1..=MAX_WINDOWS {
        let stop = window as f64 * scale;
        if let Err(e) = bdf.set_stop_time(Some(stop)) {
            return Err((bdf.y().clone(), e.to_string(), iterations));
        }
        while bdf.t() < stop {
            if let Err(e) = bdf.step(&mut frozen) {
                let mut last = bdf.y().clone();
                zero_velocities(frozen.system, &mut last);
                return Err((last, format!("the damped dynamics failed: {e}"), iterations));
            }
            if bdf.stats().steps >= MAX_DAMPED_STEPS {
                let mut last = bdf.y().clone();
                let speed = frozen.system.relative_speed(&last, scale);
                zero_velocities(frozen.system, &mut last);
                let cause = format!(
                    "the damped dynamics took {MAX_DAMPED_STEPS} steps and reached {:e} of \
                     {MAX_WINDOWS} windows of T = {scale:e} (last step {:e}, relative speed \
                     {speed:e}): the parts do not settle, as where a contact's force steps from \
                     facet to facet (a faceted body resting on a vertex or an edge); try a \
                     finer faceting tolerance, the exact engine, or more contact damping",
                    bdf.t() / scale,
                    bdf.t() - bdf.t_previous(),
                );
                return Err((last, cause, iterations));
            }
        }
        if frozen.system.relative_speed(bdf.y(), scale) > SETTLED_SPEED {
            continue;
        }
        let mut trial = bdf.y().clone();
        zero_velocities(frozen.system, &mut trial);
        match newton::solve(frozen.system, t, &mut trial, settings, false) {
            Ok(report) => {
                return Ok((
                    trial,
                    iterations + report.iterations,
                    report.imbalance,
                    bdf.stats().steps,
                    bdf.t(),
                ));
            }
            Err(failure) => {
                iterations += failure.iterations;
                last_failure = format!("Newton after settling: {failure}");
            }
        }
    }
    let mut last = bdf.y().clone();
    zero_velocities(frozen.system, &mut last);
    Err((
        last,
        format!(
            "not settled to equilibrium within {MAX_WINDOWS} windows of T = {scale:e} ({last_failure})"
        ),
        iterations,
    ))
}
