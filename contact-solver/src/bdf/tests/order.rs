//! Order of accuracy at fixed order: the global error must fall like h^k when the step h
//! halves.
//!
//! The problem is Prothero & Robinson's `y′ = λ·(y − sin t) + cos t`, `y(0) = 0`, exact
//! solution `sin t` — the test equation `y′ = λ·y` for the error `y − sin t`, driven by a smooth
//! solution. With `λ = −5` the errors of the start-up steps (taken at orders 1..k−1) decay like
//! `e^{λt}` and are gone (`e^{-50}`) by `t = 10`, so what remains at `t = 10` is the error of the
//! order-k formula alone: `C·h^k`.

use crate::bdf::{Bdf, IntegratorSettings};
use crate::{DaeSystem, EvaluationError, VariableKind};
use nalgebra::{DMatrix, DVector};

struct ProtheroRobinson {
    lambda: f64,
}

impl DaeSystem for ProtheroRobinson {
    fn size(&self) -> usize {
        1
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential]
    }
    fn residual(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        out[0] = yp[0] - self.lambda * (y[0] - t.sin()) - t.cos();
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
        out[(0, 0)] = c - self.lambda;
        Ok(())
    }
}

const END: f64 = 10.0;

/// Global error at `t = 10` with KMAX = k and every step equal to h (HINIT = HMAX = h and an
/// ERROR loose enough, 0.9, that the error test never shortens a step), and the share of steps
/// taken at order k (the others are start-up steps, whose errors have decayed by `t = 10`).
fn global_error(k: usize, h: f64) -> (f64, f64) {
    let mut system = ProtheroRobinson { lambda: -5.0 };
    let settings = IntegratorSettings {
        error: 0.9,
        kmax: k,
        hmax: Some(h),
        hinit: Some(h),
        ..IntegratorSettings::default()
    };
    let y0 = DVector::from_element(1, 0.0);
    let yp0 = DVector::from_element(1, 1.0);
    let mut bdf = Bdf::new(&system, 0.0, y0, yp0, settings).unwrap();
    bdf.set_stop_time(Some(END)).unwrap();
    while bdf.t() < END {
        // A fresh Newton matrix makes each step's linear solve exact, so the loose ERROR (and
        // with it a loose Newton tolerance) leaves only the truncation error.
        bdf.request_newton_matrix();
        bdf.step(&mut system).unwrap();
    }
    assert_eq!(bdf.last_order(), k);
    let stats = bdf.stats();
    assert_eq!(stats.steps_by_order[k + 1..].iter().sum::<u64>(), 0);
    let share = stats.steps_by_order[k] as f64 / stats.steps as f64;
    ((bdf.y()[0] - END.sin()).abs(), share)
}

#[test]
fn observed_order_equals_the_bdf_order() {
    for (k, h) in [
        (1, 0.01),
        (2, 0.01),
        (3, 0.02),
        (4, 0.04),
        (5, 0.025),
        (6, 0.05),
    ] {
        let ((coarse, share_coarse), (fine, share_fine)) =
            (global_error(k, h), global_error(k, h / 2.0));
        let observed = (coarse / fine).log2();
        eprintln!(
            "order {k}: errors {coarse:.3e} {fine:.3e}, observed order {observed:.3}, \
             share at order k {share_coarse:.2} {share_fine:.2}"
        );
        assert!(
            share_coarse > 0.85 && share_fine > 0.85,
            "k = {k}: order not held"
        );
        assert!(
            (observed - k as f64).abs() < 0.2,
            "k = {k}: observed order {observed}"
        );
    }
}
