//! The whole Newton matrix against a central difference of the residual.

use super::*;
use crate::dae::{DaeSystem, VariableKind};
use nalgebra::DMatrix;

/// `∂F/∂y + c ∂F/∂y′` by central differences of the residual.
fn difference_matrix(
    system: &mut MultibodySystem,
    t: f64,
    y: &DVector<f64>,
    yp: &DVector<f64>,
    c: f64,
) -> DMatrix<f64> {
    let n = system.size();
    let mut matrix = DMatrix::zeros(n, n);
    let (mut plus, mut minus) = (DVector::zeros(n), DVector::zeros(n));
    for column in 0..n {
        let h = 1e-6 * y[column].abs().max(1.0);
        let (mut y_plus, mut y_minus) = (y.clone(), y.clone());
        y_plus[column] += h;
        y_minus[column] -= h;
        system.residual(t, &y_plus, yp, &mut plus).unwrap();
        system.residual(t, &y_minus, yp, &mut minus).unwrap();
        let mut d_y = (&plus - &minus) / (2.0 * h);
        let h = 1e-6 * yp[column].abs().max(1.0);
        let (mut yp_plus, mut yp_minus) = (yp.clone(), yp.clone());
        yp_plus[column] += h;
        yp_minus[column] -= h;
        system.residual(t, y, &yp_plus, &mut plus).unwrap();
        system.residual(t, y, &yp_minus, &mut minus).unwrap();
        d_y += (&plus - &minus) * (c / (2.0 * h));
        matrix.set_column(column, &d_y);
    }
    matrix
}

#[test]
fn newton_matrix_matches_a_difference_of_the_residual_with_every_element() {
    let cases = [(1, Formulation::I3), (3, Formulation::Si2)];
    for (seed, formulation) in cases {
        let mut system = every_element_system(seed, formulation);
        let (y, yp) = random_state(&system, seed + 50);
        let (t, c) = (0.37, 250.0);
        let n = system.size();
        let mut analytic = DMatrix::zeros(n, n);
        system.newton_matrix(t, &y, &yp, c, &mut analytic).unwrap();
        let difference = difference_matrix(&mut system, t, &y, &yp, c);
        // Entries relative to the largest entry of their row (rows mix units).
        let mut worst = (0.0, 0, 0);
        for row in 0..n {
            let scale = difference.row(row).amax().max(1e-12);
            for column in 0..n {
                let error = (analytic[(row, column)] - difference[(row, column)]).abs() / scale;
                if error > worst.0 {
                    worst = (error, row, column);
                }
            }
        }
        assert!(
            worst.0 < 1e-6,
            "seed {seed} {formulation:?}: worst relative error {:e} at ({}, {}) of {n}: analytic {} difference {}",
            worst.0,
            worst.1,
            worst.2,
            analytic[(worst.1, worst.2)],
            difference[(worst.1, worst.2)]
        );
    }
}

#[test]
fn variable_kinds_follow_the_layout() {
    for (formulation, lambda_index) in [(Formulation::I3, 3), (Formulation::Si2, 2)] {
        let system = every_element_system(3, formulation);
        let layout = *system.layout();
        let m = layout.constraint_rows();
        let kinds = system.variable_kinds();
        let eta_rows = if formulation == Formulation::Si2 {
            m
        } else {
            0
        };
        assert_eq!(kinds.len(), 14 * 3 + m + eta_rows);
        // Positions are always error-tested; velocities under SI2 only (under I3 with
        // constraints they are index-2 variables, as in Adams).
        assert!(
            kinds[..7 * 3]
                .iter()
                .all(|k| *k == VariableKind::Differential)
        );
        let velocity = if formulation == Formulation::Si2 {
            VariableKind::Differential
        } else {
            VariableKind::Algebraic { index: 2 }
        };
        assert!(kinds[7 * 3..13 * 3].iter().all(|k| *k == velocity));
        let lambda = &kinds[layout.lambda_offset()..layout.lambda_offset() + m];
        assert!(lambda.iter().all(|k| *k
            == VariableKind::Algebraic {
                index: lambda_index
            }));
        for part in system.moving_parts() {
            assert_eq!(
                kinds[layout.mu_offset(part)],
                VariableKind::Algebraic { index: 2 }
            );
        }
        let eta = &kinds[14 * 3 + m..];
        assert_eq!(eta.len(), eta_rows);
        assert!(
            eta.iter()
                .all(|k| *k == VariableKind::Algebraic { index: 2 })
        );
    }
}

#[test]
fn the_sparse_entries_sum_to_the_dense_matrix() {
    // Every element kind, both formulations: the triplets, summed in the order written, are
    // the dense matrix entry for entry (the same additions in the same order).
    for (seed, formulation) in [(1, Formulation::I3), (3, Formulation::Si2)] {
        let mut system = every_element_system(seed, formulation);
        let (y, yp) = random_state(&system, seed + 50);
        let (t, c) = (0.37, 250.0);
        let n = system.size();
        let mut dense = DMatrix::zeros(n, n);
        system.newton_matrix(t, &y, &yp, c, &mut dense).unwrap();
        let mut entries = Vec::new();
        system.newton_entries(t, &y, &yp, c, &mut entries).unwrap();
        let mut summed = DMatrix::<f64>::zeros(n, n);
        let mut written = DMatrix::from_element(n, n, false);
        for &(i, j, v) in &entries {
            summed[(i, j)] = if written[(i, j)] {
                summed[(i, j)] + v
            } else {
                v
            };
            written[(i, j)] = true;
        }
        for j in 0..n {
            for i in 0..n {
                assert!(
                    summed[(i, j)] == dense[(i, j)],
                    "seed {seed} {formulation:?} ({i}, {j}): {} against {}",
                    summed[(i, j)],
                    dense[(i, j)]
                );
                if dense[(i, j)] != 0.0 {
                    assert!(written[(i, j)], "({i}, {j}) nonzero but not written");
                }
            }
        }
        // Sparse: far fewer positions written than n² (triplets repeat a position where
        // several elements act on the same pair of parts).
        let positions = written.iter().filter(|&&w| w).count();
        assert!(
            positions < n * n / 2,
            "{} triplets at {positions} of {} positions",
            entries.len(),
            n * n
        );
    }
}

#[test]
fn the_storage_is_chosen_by_size_unless_set() {
    let mut system = every_element_system(1, Formulation::I3);
    assert!(system.size() < crate::mbs::SPARSE_FROM_SIZE);
    assert_eq!(
        DaeSystem::newton_storage(&system),
        crate::NewtonStorage::Dense
    );
    system.set_newton_storage(Some(crate::NewtonStorage::Sparse));
    assert_eq!(
        DaeSystem::newton_storage(&system),
        crate::NewtonStorage::Sparse
    );
}
