//! A fixed-step BDF2 driver for the tests only (not a product integrator): it runs the I3
//! equations with plain Newton so the tests can check dynamics before the BDF is merged.

use super::*;
use crate::dae::DaeSystem;
use nalgebra::DMatrix;

/// Integrates from consistent `(y0, yp0)` at `t0` with `steps` steps of `h` (the first one
/// implicit Euler, then BDF2), calling `observe(t, y)` after each step. Newton is modified
/// (one matrix per step, factored once) to keep debug-mode tests fast. Panics if Newton
/// fails: it is a test helper.
pub(super) fn integrate_bdf2(
    system: &mut MultibodySystem,
    t0: f64,
    start: &InitialState,
    h: f64,
    steps: usize,
    mut observe: impl FnMut(f64, &DVector<f64>),
) -> DVector<f64> {
    let n = system.size();
    let mut previous = start.y.clone() - &start.yp * h; // only used as a predictor on step 1
    let mut current = start.y.clone();
    let mut residual = DVector::zeros(n);
    let mut matrix = DMatrix::zeros(n, n);
    for step in 1..=steps {
        let t = t0 + step as f64 * h;
        // y′ = c (y − ψ): implicit Euler on the first step, BDF2 afterwards.
        let (c, psi) = if step == 1 {
            (1.0 / h, current.clone())
        } else {
            (1.5 / h, (&current * 4.0 - &previous) / 3.0)
        };
        let mut y = &current * 2.0 - &previous;
        let mut converged = false;
        system
            .newton_matrix(t, &y, &((&y - &psi) * c), c, &mut matrix)
            .unwrap();
        let factored = matrix.clone().lu();
        for _ in 0..30 {
            let yp = (&y - &psi) * c;
            system.residual(t, &y, &yp, &mut residual).unwrap();
            let delta = factored.solve(&(-&residual)).unwrap();
            y += &delta;
            let small = delta
                .iter()
                .zip(y.iter())
                .all(|(d, v)| d.abs() <= 1e-10 * (1.0 + v.abs()));
            if small {
                converged = true;
                break;
            }
        }
        assert!(converged, "Newton did not converge at t = {t}");
        previous = current;
        current = y;
        observe(t, &current);
    }
    current
}
