//! The corrector's inner-iteration hook ([`DaeSystem::corrector_converged`]), the place where
//! the augmented Lagrangian of SPEC §5 iterates its multipliers inside the corrector.
//!
//! The oracle: `y′ = −y + a` with the inner iteration `a ← y/2` run to its fixed point inside
//! every step integrates `y′ = −y/2`, whose solution is `e^{−t/2}`; without the hook's passes
//! (the system asked once per attempt) the answer would lag by one iterate.

use crate::bdf::{Bdf, FailureCause, IntegratorError, IntegratorSettings};
use crate::{DaeSystem, EvaluationError, VariableKind};
use nalgebra::{DMatrix, DVector};

/// `y′ = −y + a`, with `a` the system's own state, iterated to `a = y/2` by the hook.
struct HalfFeedback {
    a: f64,
    attempts: u64,
}

impl DaeSystem for HalfFeedback {
    fn size(&self) -> usize {
        1
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        out[0] = yp[0] + y[0] - self.a;
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        _y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        out[(0, 0)] = c + 1.0;
        Ok(())
    }
    fn attempt_started(&mut self, _t_new: f64, _h: f64) {
        self.attempts += 1;
    }
    fn corrector_converged(&mut self, _t: f64, y: &DVector<f64>, _yp: &DVector<f64>) -> bool {
        let target = 0.5 * y[0];
        let off = (self.a - target).abs() > 1e-13;
        self.a = target;
        off
    }
}

#[test]
fn the_inner_iteration_runs_to_its_fixed_point_inside_each_step() {
    let mut system = HalfFeedback {
        a: 0.5,
        attempts: 0,
    };
    let settings = IntegratorSettings {
        error: 1e-8,
        ..IntegratorSettings::default()
    };
    let y0 = DVector::from_element(1, 1.0);
    let yp0 = DVector::from_element(1, -0.5);
    let mut bdf = Bdf::new(&system, 0.0, y0, yp0, settings).unwrap();
    bdf.set_stop_time(Some(2.0)).unwrap();
    while bdf.t() < 2.0 {
        bdf.step(&mut system).unwrap();
        // The accepted point satisfies the final equations: a = y/2 to the hook's tolerance.
        assert!((system.a - 0.5 * bdf.y()[0]).abs() <= 1e-13);
    }
    let stats = bdf.stats();
    eprintln!("inner iteration: y(2) = {}, {stats:?}", bdf.y()[0]);
    assert!(
        (bdf.y()[0] - (-1.0_f64).exp()).abs() < 30.0 * 1e-8,
        "y(2) = {}",
        bdf.y()[0]
    );
    assert!(stats.inner_iterations >= stats.steps, "{stats:?}");
    // attempt_started was called once per attempt, accepted or rejected.
    let attempts = stats.steps + stats.rejected_error_test + stats.rejected_convergence;
    assert!(
        system.attempts >= attempts,
        "{} < {attempts}",
        system.attempts
    );
}

/// An inner iteration that never settles.
struct Restless;
impl DaeSystem for Restless {
    fn size(&self) -> usize {
        1
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        out[0] = yp[0] + y[0];
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        _y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        out[(0, 0)] = c + 1.0;
        Ok(())
    }
    fn corrector_converged(&mut self, _t: f64, _y: &DVector<f64>, _yp: &DVector<f64>) -> bool {
        true
    }
}

#[test]
fn an_inner_iteration_that_never_settles_is_a_diagnosed_failure() {
    let mut system = Restless;
    let one = DVector::from_element(1, 1.0);
    let mut bdf = Bdf::new(
        &system,
        0.0,
        one.clone(),
        -one,
        IntegratorSettings::default(),
    )
    .unwrap();
    bdf.set_stop_time(Some(1.0)).unwrap();
    let error = bdf.step(&mut system).unwrap_err();
    assert!(
        matches!(
            error,
            IntegratorError::RepeatedFailures {
                cause: FailureCause::InnerIterations { passes: 10 },
                ..
            }
        ),
        "{error:?}"
    );
    assert!(
        error.to_string().contains("augmented-Lagrangian"),
        "{error}"
    );
}
