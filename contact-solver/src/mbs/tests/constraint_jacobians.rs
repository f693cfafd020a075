//! Every constraint's Jacobian `Φ_q` against central differences of `Φ`.

use super::*;
use nalgebra::DMatrix;

/// `Φ(y)` through the system's own evaluation.
fn phi(system: &MultibodySystem, t: f64, y: &DVector<f64>) -> DVector<f64> {
    let states = system.part_states(y).unwrap();
    system.constraint_values(t, &states).unwrap()
}

/// Compares the Φ rows of the Newton matrix (q columns) with a central difference of Φ over
/// every q coordinate; returns the worst error relative to each row's largest entry.
fn worst_relative_error(system: &mut MultibodySystem, y: &DVector<f64>, t: f64) -> f64 {
    let layout = *system.layout();
    let (m, nq) = (layout.constraint_rows(), 7 * layout.parts());
    let mut matrix = DMatrix::zeros(layout.size(), layout.size());
    system
        .compute_newton_matrix(t, y, &DVector::zeros(layout.size()), 1.0, &mut matrix)
        .unwrap();
    let analytic = matrix
        .view((layout.lambda_offset(), 0), (m, nq))
        .into_owned();
    let mut worst: f64 = 0.0;
    for column in 0..nq {
        let h = 1e-6 * y[column].abs().max(1.0);
        let (mut plus, mut minus) = (y.clone(), y.clone());
        plus[column] += h;
        minus[column] -= h;
        let difference = (phi(system, t, &plus) - phi(system, t, &minus)) / (2.0 * h);
        for row in 0..m {
            let scale = analytic.row(row).amax().max(1e-12);
            worst = worst.max((analytic[(row, column)] - difference[row]).abs() / scale);
        }
    }
    worst
}

fn two_part_system(
    kind: ConstraintKind,
    to_ground: bool,
    motion: Option<MotionDof>,
    seed: u64,
) -> MultibodySystem {
    let mut rng = Rng::new(seed);
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let a = builder.add_part(random_part(&mut rng, "PART/2")).unwrap();
    let b = if to_ground {
        PartId::GROUND
    } else {
        builder.add_part(random_part(&mut rng, "PART/3")).unwrap()
    };
    let i = builder.add_marker(a, rng.pose(0.7)).unwrap();
    let j = builder.add_marker(b, rng.pose(0.7)).unwrap();
    let joint = builder.add_constraint("JOINT/1", kind, i, j).unwrap();
    if let Some(dof) = motion {
        builder
            .add_motion("MOTION/1", joint, dof, sine_drive(0.4, 1.5, 2.0))
            .unwrap();
    }
    builder.build().unwrap()
}

#[test]
fn every_joint_and_jprim_jacobian_matches_central_differences() {
    for kind in ConstraintKind::ALL {
        for (seed, to_ground) in [(11, false), (12, true), (13, false)] {
            let mut system = two_part_system(kind, to_ground, None, seed);
            let (y, _) = random_state(&system, seed + 100);
            let error = worst_relative_error(&mut system, &y, 0.3);
            assert!(
                error < 1e-6,
                "{kind:?} (seed {seed}, ground {to_ground}): relative error {error:e}"
            );
        }
    }
}

#[test]
fn motion_jacobians_match_central_differences() {
    let cases = [
        (ConstraintKind::Translational, MotionDof::Translational),
        (ConstraintKind::Cylindrical, MotionDof::Translational),
        (ConstraintKind::Revolute, MotionDof::Rotational),
        (ConstraintKind::Cylindrical, MotionDof::Rotational),
    ];
    for (kind, dof) in cases {
        let mut system = two_part_system(kind, false, Some(dof), 21);
        let (y, _) = random_state(&system, 121);
        let error = worst_relative_error(&mut system, &y, 1.7);
        assert!(error < 1e-6, "{kind:?} {dof:?}: relative error {error:e}");
    }
}

#[test]
fn motion_time_derivative_matches_a_difference_in_time() {
    // Φ_t of a driven row is −f′(t): compare with a central difference of Φ in t.
    let system = two_part_system(
        ConstraintKind::Revolute,
        true,
        Some(MotionDof::Rotational),
        31,
    );
    let (y, _) = random_state(&system, 131);
    let (t, h) = (0.8, 1e-5);
    let motion_row = system.layout().constraint_rows() - 1;
    let difference =
        (phi(&system, t + h, &y)[motion_row] - phi(&system, t - h, &y)[motion_row]) / (2.0 * h);
    let (analytic, _) = system.constraint_time_derivatives(t);
    assert!(
        (analytic[motion_row] - difference).abs() < 1e-8,
        "{} vs {difference}",
        analytic[motion_row]
    );
}

#[test]
fn equation_counts_match_the_degrees_of_freedom_removed() {
    use ConstraintKind::*;
    let expected = [
        (Fixed, 6),
        (Revolute, 5),
        (Translational, 5),
        (Cylindrical, 4),
        (Spherical, 3),
        (Planar, 3),
        (Universal, 4),
        (Hooke, 4),
        (InPlane, 1),
        (InLine, 2),
        (Orientation, 3),
        (ParallelAxes, 2),
        (Perpendicular, 1),
        (AtPoint, 3),
    ];
    for (kind, count) in expected {
        assert_eq!(kind.equations(), count, "{kind:?}");
    }
}

/// Two random parts (or a part and ground) joined by a distance constraint or a RACKPIN.
fn special_system(rackpin: bool, to_ground: bool, seed: u64) -> MultibodySystem {
    let mut rng = Rng::new(seed);
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let a = builder.add_part(random_part(&mut rng, "PART/2")).unwrap();
    let b = if to_ground {
        PartId::GROUND
    } else {
        builder.add_part(random_part(&mut rng, "PART/3")).unwrap()
    };
    let i = builder.add_marker(a, rng.pose(0.7)).unwrap();
    let j = builder.add_marker(b, rng.pose(0.7)).unwrap();
    if rackpin {
        builder.add_rackpin("JOINT/1", i, j, 0.3).unwrap();
    } else {
        builder.add_distance("GCON/1", i, j, 1.7).unwrap();
    }
    builder.build().unwrap()
}

#[test]
fn distance_and_rackpin_jacobians_match_central_differences() {
    for rackpin in [false, true] {
        for (seed, to_ground) in [(21, false), (22, true), (23, false)] {
            let mut system = special_system(rackpin, to_ground, seed);
            let (y, _) = random_state(&system, seed + 100);
            let error = worst_relative_error(&mut system, &y, 0.3);
            assert!(
                error < 1e-6,
                "rackpin {rackpin} (seed {seed}, ground {to_ground}): relative error {error:e}"
            );
        }
    }
}

#[test]
fn distance_and_rackpin_refuse_a_size_out_of_range() {
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let a = builder
        .add_part(random_part(&mut Rng::new(1), "PART/2"))
        .unwrap();
    let i = builder.add_marker(a, Isometry3::identity()).unwrap();
    let j = builder
        .add_marker(PartId::GROUND, Isometry3::identity())
        .unwrap();
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(builder.add_distance("GCON/1", i, j, bad).is_err());
        assert!(builder.add_rackpin("JOINT/1", i, j, bad).is_err());
    }
}
