//! Andrews' squeezing mechanism (index 3, 27 unknowns) against the Bari IVP test set's
//! reference angles at `t = 0.03`.

use crate::DaeSystem;
use crate::bdf::reference::{ANDREWS_ANGLES_AT_0_03 as Q_REF, Andrews};
use crate::bdf::{Bdf, Corrector, IntegratorSettings};
use nalgebra::DVector;

/// Integrates to `t = 0.03` and returns the angles and the largest constraint residual seen
/// at an accepted step.
fn integrate(error: f64, corrector: Corrector) -> (DVector<f64>, f64, Bdf) {
    let mut system = Andrews;
    let (y0, yp0) = Andrews::initial_state();
    let settings = IntegratorSettings {
        error,
        corrector,
        ..IntegratorSettings::default()
    };
    let mut bdf = Bdf::new(&system, 0.0, y0, yp0, settings).unwrap();
    bdf.set_stop_time(Some(0.03)).unwrap();
    let mut worst_constraint = 0.0_f64;
    while bdf.t() < 0.03 {
        bdf.step(&mut system).unwrap();
        worst_constraint = worst_constraint.max(Andrews::constraint_residual(bdf.y()));
    }
    assert_eq!(bdf.t(), 0.03);
    (bdf.y().rows(0, 7).into_owned(), worst_constraint, bdf)
}

#[test]
fn initial_values_are_consistent() {
    // The published initial state satisfies F(0, y0, y0′) = 0 (an independent check that the
    // equations were transcribed right).
    let (y0, yp0) = Andrews::initial_state();
    let mut out = DVector::zeros(27);
    Andrews.residual(0.0, &y0, &yp0, &mut out).unwrap();
    assert!(
        out.rows(21, 6).amax() < 1e-14,
        "g(q0) = {}",
        out.rows(21, 6)
    );
    assert!(
        out.rows(14, 7).amax() < 1e-8,
        "dynamics residual = {}",
        out.rows(14, 7)
    );
}

#[test]
fn angles_at_t_003_match_the_test_set_reference() {
    for corrector in [Corrector::Modified, Corrector::Full] {
        let (q, worst_constraint, bdf) = integrate(1e-6, corrector);
        // Error relative to the size of each angle (the test set's mixed error, atol = rtol):
        // ERROR = 1e-6 per step over ~10² steps should give better than 1e-3.
        let error = (0..7)
            .map(|i| (q[i] - Q_REF[i]).abs() / (Q_REF[i].abs() + 1.0))
            .fold(0.0_f64, f64::max);
        let stats = bdf.stats();
        eprintln!(
            "andrews {corrector:?}: mixed error {error:.2e}, constraint {worst_constraint:.1e}, {stats:?}"
        );
        assert!(
            error < 1e-3,
            "{corrector:?}: q(0.03) = {q}, error {error:e}"
        );
        // Index-3 positions satisfy the constraints to Newton precision at every step: angle
        // corrections converge to a fraction of ERROR·(|q| + 1) and the lever arms are ≤ 0.04 m.
        assert!(
            worst_constraint < 0.1 * 1e-6,
            "constraint residual {worst_constraint:e}"
        );
    }
}

#[test]
fn tightening_error_converges_to_the_reference() {
    let error_of = |tol: f64| {
        let (q, _, _) = integrate(tol, Corrector::Modified);
        (0..7)
            .map(|i| (q[i] - Q_REF[i]).abs() / (Q_REF[i].abs() + 1.0))
            .fold(0.0, f64::max)
    };
    let (loose, tight) = (error_of(1e-4), error_of(1e-7));
    eprintln!("andrews: error at ERROR=1e-4: {loose:.2e}, at 1e-7: {tight:.2e}");
    assert!(tight < loose / 10.0, "loose {loose:e}, tight {tight:e}");
}
