//! Mechanisms with closed-form kinematics or dynamics: a Cardan joint's velocity ratio and a
//! spring-mass oscillator on a TRANSLATIONAL joint.

use super::driver::integrate_bdf2;
use super::*;
use std::f64::consts::{FRAC_PI_2, PI};

/// A marker at the part origin whose local `axis` points along `target` (world, parts unrotated).
fn marker_along(
    builder: &mut MultibodyBuilder,
    part: PartId,
    axis: Vector3<f64>,
    target: Vector3<f64>,
) -> MarkerId {
    let rotation = UnitQuaternion::rotation_between(&axis, &target).unwrap_or_else(|| {
        // Opposite vectors: half a turn about any perpendicular axis.
        UnitQuaternion::from_scaled_axis(
            axis.cross(&Vector3::x())
                .try_normalize(1e-9)
                .unwrap_or(Vector3::y())
                * PI,
        )
    });
    builder
        .add_marker(
            part,
            Isometry3::from_parts(Translation3::identity(), rotation),
        )
        .unwrap()
}

/// Output speed of a Cardan driveline: input shaft on a REVOLUTE about world x driven at
/// `rate`, output shaft at angle `beta` (axis d in the x-y plane) held by PARALLEL_AXES, the
/// two coupled by a `kind` joint (UNIVERSAL: pins z_I, z_J; HOOKE: pins x_I, y_J) whose input
/// pin points along `pin_in`. Returns the output's angular velocity about d.
fn cardan_output_rate(kind: ConstraintKind, beta: f64, pin_in: Vector3<f64>, rate: f64) -> f64 {
    let mut builder = MultibodyBuilder::new(Vector3::zeros());
    let inertia = Matrix3::from_diagonal(&Vector3::new(0.1, 0.2, 0.3));
    let input = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            1.0,
            inertia,
            Isometry3::identity(),
        ))
        .unwrap();
    let output = builder
        .add_part(PartSpec::at_rest(
            "PART/3",
            2.0,
            inertia,
            Isometry3::identity(),
        ))
        .unwrap();
    let d = Vector3::new(beta.cos(), beta.sin(), 0.0);
    let (x, z) = (Vector3::x(), Vector3::z());
    let (i, j) = (
        marker_along(&mut builder, input, z, x),
        marker_along(&mut builder, PartId::GROUND, z, x),
    );
    let shaft = builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, i, j)
        .unwrap();
    let (i, j) = (
        marker_along(&mut builder, output, z, d),
        marker_along(&mut builder, PartId::GROUND, z, d),
    );
    builder
        .add_constraint("JPRIM/1", ConstraintKind::ParallelAxes, i, j)
        .unwrap();
    // The output pin is perpendicular to the input pin and to the output shaft.
    let pin_out = d.cross(&pin_in).normalize();
    let (axis_i, axis_j) = match kind {
        ConstraintKind::Universal => (Vector3::z(), Vector3::z()),
        _ => (Vector3::x(), Vector3::y()),
    };
    let (i, j) = (
        marker_along(&mut builder, input, axis_i, pin_in),
        marker_along(&mut builder, output, axis_j, pin_out),
    );
    builder.add_constraint("JOINT/2", kind, i, j).unwrap();
    builder
        .add_motion(
            "MOTION/1",
            shaft,
            MotionDof::Rotational,
            Arc::new(move |t: f64| (rate * t, rate, 0.0)),
        )
        .unwrap();
    let system = builder.build().unwrap();
    let start = system.compute_initial_state(0.0).unwrap();
    assert_eq!(
        start.assembly_iterations, 0,
        "the driveline was built assembled"
    );
    let states = system.part_states(&start.y).unwrap();
    let omega_in = states[input.0].angular_velocity_w;
    assert!((omega_in - x * rate).norm() < 1e-12, "{omega_in}");
    let omega_out = states[output.0].angular_velocity_w;
    assert!(
        (omega_out - d * omega_out.dot(&d)).norm() < 1e-12,
        "the output turns about its shaft"
    );
    omega_out.dot(&d)
}

#[test]
fn cardan_joint_velocity_ratio_matches_the_textbook_formula() {
    // ω_out/ω_in = cos β / (1 − sin²β cos²θ), θ the input pin's angle from the plane of the
    // shafts: 1/cos β with the pin in the plane, cos β with the pin normal to it.
    for kind in [ConstraintKind::Universal, ConstraintKind::Hooke] {
        for beta in [0.3, 0.6] {
            let in_plane = cardan_output_rate(kind, beta, Vector3::y(), 2.0);
            assert!(
                (in_plane - 2.0 / beta.cos()).abs() < 1e-10,
                "{kind:?} β = {beta}: {in_plane}"
            );
            let normal = cardan_output_rate(kind, beta, Vector3::z(), 2.0);
            assert!(
                (normal - 2.0 * beta.cos()).abs() < 1e-10,
                "{kind:?} β = {beta}: {normal}"
            );
        }
    }
}

#[test]
fn block_on_a_translational_joint_oscillates_on_its_spring() {
    // A block sliding along world x on a TRANSLATIONAL joint, pulled by a spring to a ground
    // point on the x axis, gravity along −z carried by the joint. Oracle: x(t) = x0 cos(√(k/m) t)
    // about the spring's free position, and the joint carries exactly the weight.
    let (m, k, x0) = (2.0, 800.0, 0.05);
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -9.81));
    let block = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            m,
            Matrix3::identity() * 0.01,
            Isometry3::translation(1.0 + x0, 0.0, 0.0),
        ))
        .unwrap();
    let along_x = UnitQuaternion::from_scaled_axis(Vector3::new(0.0, FRAC_PI_2, 0.0)); // z → x
    let i = builder
        .add_marker(
            block,
            Isometry3::from_parts(Translation3::identity(), along_x),
        )
        .unwrap();
    let j = builder
        .add_marker(
            PartId::GROUND,
            Isometry3::from_parts(Translation3::identity(), along_x),
        )
        .unwrap();
    builder
        .add_constraint("JOINT/1", ConstraintKind::Translational, i, j)
        .unwrap();
    let params = SpringParams {
        stiffness: k,
        damping: 0.0,
        free_length: 1.0,
        preload: 0.0,
    };
    let spring = TranslationalSpringDamper::new(
        "SPRING/1",
        block,
        Vector3::zeros(),
        PartId::GROUND,
        Vector3::zeros(),
        params,
    )
    .unwrap();
    builder.add_force(Box::new(spring)).unwrap();
    let mut system = builder.build().unwrap();
    let start = system.compute_initial_state(0.0).unwrap();
    let layout = *system.layout();
    let reactions = system.constraint_reactions(&start.y).unwrap();
    assert!(
        (reactions[0].force_w - Vector3::new(0.0, 0.0, m * 9.81)).norm() < 1e-9,
        "{:?}",
        reactions[0]
    );
    assert!(
        (start.yp[layout.velocity_offset(block)] + k * x0 / m).abs() < 1e-9,
        "initial acceleration −k x0/m"
    );
    let omega = (k / m).sqrt();
    let h = 2.0 * PI / omega / 200.0;
    let mut worst: f64 = 0.0;
    integrate_bdf2(&mut system, 0.0, &start, h, 250, |t, y| {
        // BDF2 lags the phase by about (ωh)³/12 … 2(ωh)³/9 rad per step: under 8e-3 rad (0.8%
        // of x0) after 250 steps, while a 5% error in k or m would be off by ~0.2 rad.
        worst = worst.max((y[0] - 1.0 - x0 * (omega * t).cos()).abs());
    });
    assert!(
        worst < 0.02 * x0,
        "largest deviation from x0 cos ωt: {worst}"
    );
}

#[test]
fn a_far_off_start_assembles_onto_the_joint() {
    // A bob whose revolute marker sits 1 above its CM, placed 3 away from the pivot and turned
    // by ~2 rad: backtracked Gauss–Newton must close the joint. Oracle: afterwards the marker
    // is at the pivot (CM 1 from it) and the z axes agree.
    let mut rng = Rng::new(17);
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -9.81));
    let pose = Isometry3::from_parts(Translation3::new(2.0, -1.5, 1.8), rng.rotation());
    let bob = builder
        .add_part(PartSpec::at_rest("PART/2", 1.0, Matrix3::identity(), pose))
        .unwrap();
    let i = builder
        .add_marker(bob, Isometry3::translation(0.0, 0.0, 1.0))
        .unwrap();
    let j = builder
        .add_marker(PartId::GROUND, Isometry3::identity())
        .unwrap();
    builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, i, j)
        .unwrap();
    let system = builder.build().unwrap();
    let start = system.compute_initial_state(0.0).unwrap();
    assert!(start.assembly_iterations > 1);
    let pose = system.part_states(&start.y).unwrap()[bob.0].pose_w;
    assert!((pose * nalgebra::Point3::new(0.0, 0.0, 1.0)).coords.norm() < 1e-9);
    let z_i = pose.rotation * Vector3::z();
    assert!(z_i.cross(&Vector3::z()).norm() < 1e-9, "{z_i}");
}
