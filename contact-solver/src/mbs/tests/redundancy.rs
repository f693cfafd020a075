//! Redundant constraint equations: removed and listed when consistent, refused naming the
//! joints when not. Oracles: a pendulum's closed-form angular acceleration, the slider-crank's
//! closed-form slider position, and counting (a duplicated REVOLUTE repeats all 5 equations).

use super::*;
use crate::kinematics::{degrees_of_freedom, solve_kinematic_state};
use std::f64::consts::FRAC_PI_2;

const G: f64 = 9.81;

/// A unit-mass, unit-inertia part with its CM at `cm` (unrotated).
fn part_at(builder: &mut MultibodyBuilder, name: &str, cm: Vector3<f64>) -> PartId {
    builder
        .add_part(PartSpec::at_rest(
            name,
            1.0,
            Matrix3::identity(),
            Isometry3::translation(cm.x, cm.y, cm.z),
        ))
        .unwrap()
}

/// A marker of `part` (CM at `cm`) at world point `p`, axes along the world's.
fn marker_at(
    builder: &mut MultibodyBuilder,
    part: PartId,
    cm: Vector3<f64>,
    p: Vector3<f64>,
) -> MarkerId {
    let local = p - cm;
    builder
        .add_marker(part, Isometry3::translation(local.x, local.y, local.z))
        .unwrap()
}

/// A pendulum (CM at (1, 0, 0), gravity −y) on `joints` REVOLUTEs about world z at the origin.
fn pendulum_on(joints: usize) -> (MultibodySystem, PartId) {
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, -G, 0.0));
    let cm = Vector3::new(1.0, 0.0, 0.0);
    let part = part_at(&mut builder, "PART/2", cm);
    for k in 1..=joints {
        let i = marker_at(&mut builder, part, cm, Vector3::zeros());
        let j = builder
            .add_marker(PartId::GROUND, Isometry3::identity())
            .unwrap();
        builder
            .add_constraint(format!("JOINT/{k}"), ConstraintKind::Revolute, i, j)
            .unwrap();
    }
    (builder.build().unwrap(), part)
}

#[test]
fn a_duplicated_joint_is_removed_and_listed_and_the_pendulum_swings_as_with_one() {
    let (system, part) = pendulum_on(2);
    let removed: Vec<_> = system.redundant_equations().collect();
    assert_eq!(removed.len(), 5, "{removed:#?}");
    assert_eq!(system.layout().constraint_rows(), 5);
    for (k, equation) in removed.iter().enumerate() {
        assert_eq!(equation.equation, k, "{equation}");
        assert_eq!(
            equation.depends_on,
            vec!["JOINT/1".to_string()],
            "{equation}"
        );
    }
    // Adams' pivoting may keep either copy; both name one joint as the other's duplicate.
    assert!(
        removed
            .iter()
            .all(|e| e.element == "JOINT/2" || e.element == "JOINT/1")
    );
    assert_eq!(removed[0].description, "translation along X");
    assert_eq!(removed[3].description, "rotation between Zi & Xj");
    // α = −m·g·L/(I_zz + m·L²) = −g/2 about z.
    let start = system.compute_initial_state(0.0).unwrap();
    let omega_dot = start.yp[system.layout().velocity_offset(part) + 5];
    assert!((omega_dot + G / 2.0).abs() < 1e-12, "{omega_dot}");
    let (single, _) = pendulum_on(1);
    assert_eq!(single.redundant_equations().count(), 0);
    let one = single.compute_initial_state(0.0).unwrap();
    assert!((one.yp.rows(0, 13).into_owned() - start.yp.rows(0, 13)).amax() < 1e-12);
}

#[test]
fn a_planar_slider_crank_runs_with_its_redundant_equation_removed() {
    // Crank r on a REVOLUTE at the origin driven at ω, rod l on a REVOLUTE at the crank tip,
    // rod end on an INLINE JPRIM along world x: 12 − 13 equations for 0 freedoms, one redundant.
    let (r, l, theta0, omega) = (1.0, 3.0, 0.4_f64, 2.0);
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, -G, 0.0));
    let tip = Vector3::new(r * theta0.cos(), r * theta0.sin(), 0.0);
    let end = Vector3::new(tip.x + (l * l - tip.y * tip.y).sqrt(), 0.0, 0.0);
    let (crank_cm, rod_cm) = (tip / 2.0, (tip + end) / 2.0);
    let crank = part_at(&mut builder, "PART/2", crank_cm);
    let rod = part_at(&mut builder, "PART/3", rod_cm);
    let pivot_i = marker_at(&mut builder, crank, crank_cm, Vector3::zeros());
    let pivot_j = builder
        .add_marker(PartId::GROUND, Isometry3::identity())
        .unwrap();
    let pivot = builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, pivot_i, pivot_j)
        .unwrap();
    let tip_i = marker_at(&mut builder, rod, rod_cm, tip);
    let tip_j = marker_at(&mut builder, crank, crank_cm, tip);
    builder
        .add_constraint("JOINT/2", ConstraintKind::Revolute, tip_i, tip_j)
        .unwrap();
    let end_i = marker_at(&mut builder, rod, rod_cm, end);
    let along_x = builder
        .add_marker(
            PartId::GROUND,
            Isometry3::from_parts(
                Translation3::identity(),
                UnitQuaternion::from_scaled_axis(Vector3::new(0.0, FRAC_PI_2, 0.0)),
            ),
        )
        .unwrap();
    builder
        .add_constraint("JPRIM/1", ConstraintKind::InLine, end_i, along_x)
        .unwrap();
    let drive: TimeFunction = Arc::new(move |t| (omega * t, omega, 0.0));
    builder
        .add_motion("MOTION/1", pivot, MotionDof::Rotational, drive)
        .unwrap();
    let system = builder.build().unwrap();
    let removed: Vec<_> = system.redundant_equations().collect();
    assert_eq!(removed.len(), 1, "{removed:#?}");
    system.compute_initial_state(0.0).unwrap();
    let mut y = system.given_state().clone();
    for step in 1..=20 {
        let t = 0.05 * f64::from(step);
        let state = solve_kinematic_state(&system, t, &y).unwrap();
        y = state.y;
        assert_eq!(degrees_of_freedom(&system, &y).unwrap(), 0);
        let rod_pose = system.part_states(&y).unwrap()[rod.0].pose_w;
        let x_end = rod_pose * nalgebra::Point3::from(end - rod_cm);
        let theta = theta0 + omega * t;
        let exact = r * theta.cos() + (l * l - (r * theta.sin()).powi(2)).sqrt();
        assert!(
            (x_end.x - exact).abs() < 1e-9,
            "t = {t}: {} vs {exact}",
            x_end.x
        );
        assert!(x_end.y.abs() < 1e-9 && x_end.z.abs() < 1e-9, "{x_end}");
    }
}

#[test]
fn inconsistent_redundancy_is_an_error_naming_the_joints() {
    // Two REVOLUTEs about z on one part, 1 apart on the part and 1.5 apart on the ground: the
    // second joint's y equation repeats the first's gradient but cannot hold with it.
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, -G, 0.0));
    let cm = Vector3::new(1.0, 0.0, 0.0);
    let part = part_at(&mut builder, "PART/2", cm);
    let near = marker_at(&mut builder, part, cm, Vector3::zeros());
    let far = marker_at(&mut builder, part, cm, Vector3::new(0.0, 1.0, 0.0));
    let ground_near = builder
        .add_marker(PartId::GROUND, Isometry3::identity())
        .unwrap();
    let ground_far = builder
        .add_marker(PartId::GROUND, Isometry3::translation(0.0, 1.5, 0.0))
        .unwrap();
    builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, near, ground_near)
        .unwrap();
    builder
        .add_constraint("JOINT/7", ConstraintKind::Revolute, far, ground_far)
        .unwrap();
    let system = builder.build().unwrap();
    assert!(system.redundant_equations().count() >= 1);
    let error = system.compute_initial_state(0.0).unwrap_err();
    let MbsError::InconsistentRedundancy { elements, .. } = &error else {
        panic!("{error}")
    };
    assert_eq!(elements, &["JOINT/1".to_string(), "JOINT/7".to_string()]);
    let message = error.to_string();
    assert!(message.contains("JOINT/1, JOINT/7"), "{message}");
    assert!(message.contains("translation along Y"), "{message}");
}
