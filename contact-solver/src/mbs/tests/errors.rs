//! Bad input gives typed errors naming the argument, value and range.

use super::*;

#[test]
fn nonpositive_mass_is_rejected_with_its_value() {
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let spec = PartSpec::at_rest("PART/2", -1.0, Matrix3::identity(), Isometry3::identity());
    let error = builder.add_part(spec).unwrap_err();
    assert!(matches!(
        error,
        MbsError::InvalidArgument {
            argument: "MASS",
            ..
        }
    ));
    assert_eq!(
        error.to_string(),
        "PART/2: MASS = -1.0 is out of range: must be finite and > 0"
    );
}

#[test]
fn indefinite_inertia_is_rejected() {
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -0.5));
    let error = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            1.0,
            inertia,
            Isometry3::identity(),
        ))
        .unwrap_err();
    assert!(error.to_string().contains("positive definite"), "{error}");
}

#[test]
fn constraint_between_markers_of_one_part_is_rejected() {
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let part = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            1.0,
            Matrix3::identity(),
            Isometry3::identity(),
        ))
        .unwrap();
    let i = builder.add_marker(part, Isometry3::identity()).unwrap();
    let j = builder
        .add_marker(part, Isometry3::translation(1.0, 0.0, 0.0))
        .unwrap();
    let error = builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, i, j)
        .unwrap_err();
    assert_eq!(
        error,
        MbsError::SamePart {
            element: "JOINT/1".into(),
            part: 1
        }
    );
}

#[test]
fn unknown_marker_and_part_are_named() {
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let error = builder
        .add_marker(PartId(3), Isometry3::identity())
        .unwrap_err();
    assert!(matches!(
        error,
        MbsError::UnknownPart { id: 3, last: 0, .. }
    ));
    let g = builder
        .add_marker(PartId::GROUND, Isometry3::identity())
        .unwrap();
    let error = builder
        .add_constraint("JOINT/7", ConstraintKind::Fixed, g, MarkerId(9))
        .unwrap_err();
    assert_eq!(
        error,
        MbsError::UnknownMarker {
            element: "JOINT/7".into(),
            id: 9,
            count: 1
        }
    );
}

#[test]
fn rotational_motion_on_a_translational_joint_is_rejected() {
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let part = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            1.0,
            Matrix3::identity(),
            Isometry3::identity(),
        ))
        .unwrap();
    let i = builder.add_marker(part, Isometry3::identity()).unwrap();
    let j = builder
        .add_marker(PartId::GROUND, Isometry3::identity())
        .unwrap();
    let joint = builder
        .add_constraint("JOINT/1", ConstraintKind::Translational, i, j)
        .unwrap();
    let error = builder
        .add_motion(
            "MOTION/1",
            joint,
            MotionDof::Rotational,
            sine_drive(1.0, 1.0, 0.0),
        )
        .unwrap_err();
    assert_eq!(
        error.to_string(),
        "MOTION/1: a rotational motion needs a REVOLUTE or CYLINDRICAL joint, but JOINT/1 is TRANSLATIONAL"
    );
}

#[test]
fn negative_spring_stiffness_is_rejected() {
    let params = SpringParams {
        stiffness: -5.0,
        damping: 0.0,
        free_length: 1.0,
        preload: 0.0,
    };
    let error = TranslationalSpringDamper::new(
        "SPRING/1",
        PartId(1),
        Vector3::zeros(),
        PartId::GROUND,
        Vector3::zeros(),
        params,
    )
    .unwrap_err();
    assert_eq!(
        error.to_string(),
        "SPRING/1: STIFFNESS = -5.0 is out of range: must be finite and ≥ 0"
    );
}

#[test]
fn non_finite_motion_stops_evaluation_naming_the_motion() {
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let part = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            1.0,
            Matrix3::identity(),
            Isometry3::identity(),
        ))
        .unwrap();
    let i = builder.add_marker(part, Isometry3::identity()).unwrap();
    let j = builder
        .add_marker(PartId::GROUND, Isometry3::identity())
        .unwrap();
    let joint = builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, i, j)
        .unwrap();
    builder
        .add_motion(
            "MOTION/4",
            joint,
            MotionDof::Rotational,
            Arc::new(|t: f64| ((-t).sqrt(), 0.0, 0.0)),
        )
        .unwrap();
    let mut system = builder.build().unwrap();
    let y = system.initial_y.clone();
    let mut out = DVector::zeros(y.len());
    let error = crate::dae::DaeSystem::residual(&mut system, 1.0, &y, &y, &mut out).unwrap_err();
    assert_eq!(error.element, "MOTION/4");
}

/// A part at the origin with markers at its CM and 1 along x.
fn part_with_two_markers(builder: &mut MultibodyBuilder) -> (MarkerId, MarkerId) {
    let part = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            1.0,
            Matrix3::identity(),
            Isometry3::identity(),
        ))
        .unwrap();
    let near = builder.add_marker(part, Isometry3::identity()).unwrap();
    let far = builder
        .add_marker(part, Isometry3::translation(1.0, 0.0, 0.0))
        .unwrap();
    (near, far)
}

#[test]
fn joints_that_cannot_close_are_refused_naming_both() {
    // The part's markers are 1 apart, the ground's 5 apart: two SPHERICAL joints cannot both
    // close. Along the line of the markers the second joint's equation repeats the first's
    // gradient (a rotation does not move either point along it), so it is the redundant one
    // that cannot hold: 4 units off, over L = 5.
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let (near, far) = part_with_two_markers(&mut builder);
    let ground_near = builder
        .add_marker(PartId::GROUND, Isometry3::identity())
        .unwrap();
    let ground_far = builder
        .add_marker(PartId::GROUND, Isometry3::translation(5.0, 0.0, 0.0))
        .unwrap();
    builder
        .add_constraint("JOINT/1", ConstraintKind::Spherical, near, ground_near)
        .unwrap();
    builder
        .add_constraint("JOINT/2", ConstraintKind::Spherical, far, ground_far)
        .unwrap();
    let system = builder.build().unwrap();
    let error = system.compute_initial_state(0.0).unwrap_err();
    let MbsError::InconsistentRedundancy {
        elements,
        equations,
    } = &error
    else {
        panic!("{error}")
    };
    assert_eq!(elements, &["JOINT/1".to_string(), "JOINT/2".to_string()]);
    assert_eq!(equations.len(), 1, "{error}");
    assert!(equations[0].contains("translation along X"), "{error}");
    assert!(equations[0].contains("value -8.000e-1"), "{error}");
}

#[test]
fn unnormalized_orientation_is_renormalized_and_zero_is_rejected() {
    let quaternion =
        |w, i, j, k| UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(w, i, j, k));
    let pose = |q| Isometry3::from_parts(Translation3::identity(), q);
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let spec = PartSpec::at_rest(
        "PART/2",
        1.0,
        Matrix3::identity(),
        pose(quaternion(2.0, 0.0, 0.0, 0.0)),
    );
    let part = builder.add_part(spec).unwrap();
    let system = builder.build().unwrap();
    let e = system.parameters(&system.initial_y, part);
    assert_eq!(e, nalgebra::Vector4::new(1.0, 0.0, 0.0, 0.0));
    let zero = PartSpec::at_rest(
        "PART/3",
        1.0,
        Matrix3::identity(),
        pose(quaternion(0.0, 0.0, 0.0, 0.0)),
    );
    let error = MultibodyBuilder::new(Vector3::zeros())
        .add_part(zero)
        .unwrap_err();
    assert_eq!(
        error.to_string(),
        "PART/3: ORIENTATION (quaternion norm) = 0.0 is out of range: must be finite and > 0"
    );
}

#[test]
fn a_system_with_only_ground_is_an_error_in_every_analysis_not_a_panic() {
    let builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -9.81));
    let mut system = builder.build().unwrap();
    assert_eq!(
        system.compute_initial_state(0.0).unwrap_err(),
        MbsError::NoMovingPart
    );
    let settings = crate::simulate::DynamicsSettings {
        start: 0.0,
        end: 1.0,
        output_step: 0.1,
        integrator: crate::bdf::IntegratorSettings::default(),
    };
    let error =
        crate::simulate::simulate(&mut system, &[], &settings, &mut |_| Ok(())).unwrap_err();
    assert!(
        matches!(
            error,
            crate::simulate::SimulationError::Initial(MbsError::NoMovingPart)
        ),
        "{error}"
    );
    let y = system.initial_y.clone();
    let statics = crate::statics::solve_statics(
        &mut system,
        0.0,
        &y,
        &crate::statics::StaticsSettings::default(),
    );
    assert!(statics.is_err());
}
