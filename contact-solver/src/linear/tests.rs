//! Unit tests of the pieces: sorting and pairing, the null-space basis, the state matrix, and
//! the errors.

use super::eigen::{eigenvalues_of, state_matrix};
use super::*;
use crate::mbs::{MultibodyBuilder, PartSpec};
use nalgebra::{Complex, Isometry3, Matrix3, Vector3};

#[test]
fn eigenvalues_sort_by_frequency_then_real_part_and_keep_conjugate_pairs_together() {
    let c = |re: f64, im: f64| Complex::new(re, im);
    // Two pairs with the same |s| and real part (a repeated mode), a real pair, a zero.
    let values = [
        c(-1.0, 2.0),
        c(-1.0, -2.0),
        c(3.0, 0.0),
        c(-3.0, 0.0),
        c(-1.0, 2.0),
        c(-1.0, -2.0),
        c(0.0, 0.0),
        c(0.0, 0.5),
        c(0.0, -0.5),
    ];
    let sorted = sorted_eigenvalues(&values);
    let got: Vec<(f64, f64)> = sorted.iter().map(|e| (e.real, e.imaginary)).collect();
    assert_eq!(
        got,
        vec![
            (0.0, 0.0),
            (0.0, 0.5),
            (0.0, -0.5),
            (-1.0, 2.0),
            (-1.0, -2.0),
            (-1.0, 2.0),
            (-1.0, -2.0),
            (-3.0, 0.0),
            (3.0, 0.0),
        ]
    );
    assert_eq!(sorted[0].damping_ratio, None);
    assert_eq!(sorted[1].damping_ratio, Some(0.0));
    let root5 = 5.0_f64.sqrt();
    assert!((sorted[3].damping_ratio.unwrap() - 1.0 / root5).abs() < 1e-15);
    assert!((sorted[3].frequency - root5 / (2.0 * std::f64::consts::PI)).abs() < 1e-15);
    assert_eq!(sorted[7].damping_ratio, Some(1.0));
    assert_eq!(sorted[8].damping_ratio, Some(-1.0));
}

#[test]
fn the_null_space_basis_is_orthonormal_spans_the_kernel_and_ignores_redundant_rows() {
    // Two parts (12 columns); rows: part 1's x and its rotation about z (an angle row, large
    // entries in the length-scaled metric), and the same x row again (redundant).
    let length = 1e3;
    let mut phi = DMatrix::zeros(3, 12);
    phi[(0, 0)] = 1.0;
    phi[(0, 5)] = 250.0;
    phi[(1, 5)] = 1.0;
    phi[(2, 0)] = 2.0;
    phi[(2, 5)] = 500.0;
    let n = null_space_basis(&phi, length);
    assert_eq!(n.shape(), (12, 10));
    assert!((&phi * &n).amax() < 1e-12 * 500.0);
    assert!((n.transpose() * &n - DMatrix::identity(10, 10)).amax() < 1e-14);
    // No rows: everything is free.
    assert_eq!(
        null_space_basis(&DMatrix::zeros(0, 6), 1.0),
        DMatrix::identity(6, 6)
    );
    // Six independent rows on one part: nothing is free.
    assert_eq!(
        null_space_basis(&DMatrix::identity(6, 6), 1.0).shape(),
        (6, 0)
    );
}

#[test]
fn the_state_matrix_gives_the_closed_form_eigenvalues_of_two_coupled_masses() {
    // m1 = 2, m2 = 1, springs k between ground–1 and 1–2: K = k[[2, −1], [−1, 1]].
    // det(K − ω²M) = (2k − 2ω²)(k − ω²) − k² = 2ω⁴ − 4kω² + k² = 0: ω² = k(1 ± √½).
    let k = 8.0;
    let mass = DMatrix::from_row_slice(2, 2, &[2.0, 0.0, 0.0, 1.0]);
    let stiffness = DMatrix::from_row_slice(2, 2, &[2.0 * k, -k, -k, k]);
    let a = state_matrix(&mass, &DMatrix::zeros(2, 2), &stiffness).unwrap();
    let values = eigenvalues_of(a).unwrap();
    let expected = [
        (k * (1.0 - 0.5f64.sqrt())).sqrt(),
        (k * (1.0 + 0.5f64.sqrt())).sqrt(),
    ];
    assert_eq!(values.len(), 4);
    for (pair, omega) in values.chunks(2).zip(expected) {
        assert!(pair[0].real.abs() < 1e-12 * omega, "{pair:?}");
        assert!(
            (pair[0].imaginary - omega).abs() < 1e-12 * omega,
            "{pair:?}"
        );
        assert_eq!(pair[1].imaginary, -pair[0].imaginary);
    }
}

#[test]
fn a_massless_direction_is_a_typed_error() {
    let mass = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, 0.0]);
    let err = state_matrix(&mass, &DMatrix::zeros(2, 2), &DMatrix::identity(2, 2)).unwrap_err();
    assert_eq!(err, LinearError::SingularMass { dimension: 2 });
}

fn free_body() -> MultibodySystem {
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -9.81));
    builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            1.5,
            Matrix3::from_diagonal(&Vector3::new(0.1, 0.2, 0.3)),
            Isometry3::translation(0.0, 0.0, 1.0),
        ))
        .unwrap();
    builder.build().unwrap()
}

#[test]
fn a_free_body_under_gravity_has_twelve_zero_eigenvalues() {
    let mut system = free_body();
    let y = system.given_state().clone();
    let linear = linearize(&mut system, 0.0, &y, &LinearSettings::default()).unwrap();
    assert_eq!(linear.degrees_of_freedom, 6);
    assert_eq!(linear.eigenvalues.len(), 12);
    for e in &linear.eigenvalues {
        assert_eq!((e.real, e.imaginary), (0.0, 0.0), "{e:?}");
        assert_eq!(e.damping_ratio, None);
    }
}

#[test]
fn bad_operating_points_are_typed_errors() {
    let mut system = free_body();
    let settings = LinearSettings::default();
    let short = DVector::zeros(3);
    assert_eq!(
        linearize(&mut system, 0.0, &short, &settings).unwrap_err(),
        LinearError::WrongLength {
            given: 3,
            expected: 14
        }
    );
    let mut y = system.given_state().clone();
    y[2] = f64::NAN;
    assert!(matches!(
        linearize(&mut system, 0.0, &y, &settings).unwrap_err(),
        LinearError::NonFiniteState { index: 2, .. }
    ));
    let y = system.given_state().clone();
    assert!(matches!(
        linearize(&mut system, f64::INFINITY, &y, &settings).unwrap_err(),
        LinearError::NonFiniteState { .. }
    ));
    let mut y = system.given_state().clone();
    y.rows_mut(3, 4).fill(0.0);
    assert!(matches!(
        linearize(&mut system, 0.0, &y, &settings).unwrap_err(),
        LinearError::Evaluation(_)
    ));
}
