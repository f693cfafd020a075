//! Dynamics against closed forms: free fall, pendulum tension and period, torque-free body.

use super::driver::integrate_bdf2;
use super::*;
use crate::dae::DaeSystem;
use crate::mbs::quaternion::parameters_of;
use std::f64::consts::{FRAC_PI_2, PI};

#[test]
fn residual_is_zero_on_the_exact_free_fall_with_spin() {
    // A body thrown with velocity u0 and spinning about its principal z axis: r(t) = r0 + u0 t
    // + ½ g t², e(t) = e0 ⊗ exp(ω′t/2), ω′ constant (no gyroscopic moment about a principal axis).
    let g = Vector3::new(0.0, 0.0, -9.81);
    let (r0, u0) = (Vector3::new(1.0, 2.0, 3.0), Vector3::new(0.5, -1.0, 4.0));
    let rotation0 = UnitQuaternion::from_euler_angles(0.3, -0.2, 1.1);
    let omega_body = Vector3::new(0.0, 0.0, 5.0);
    let mut builder = MultibodyBuilder::new(g);
    let part = builder
        .add_part(PartSpec {
            name: "PART/2".into(),
            mass: 2.5,
            inertia_cm: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
            pose_w: Isometry3::from_parts(Translation3::from(r0), rotation0),
            velocity_w: u0,
            angular_velocity_w: rotation0 * omega_body,
        })
        .unwrap();
    let mut system = builder.build().unwrap();
    let layout = *system.layout();
    let (qo, vo) = (layout.position_offset(part), layout.velocity_offset(part));
    for t in [0.0, 0.4, 1.3] {
        let rotation = rotation0 * UnitQuaternion::from_scaled_axis(omega_body * t);
        let e = parameters_of(&rotation);
        let mut y = DVector::zeros(layout.size());
        let mut yp = DVector::zeros(layout.size());
        y.fixed_rows_mut::<3>(qo)
            .copy_from(&(r0 + u0 * t + g * (0.5 * t * t)));
        y.fixed_rows_mut::<4>(qo + 3).copy_from(&e);
        y.fixed_rows_mut::<3>(vo).copy_from(&(u0 + g * t));
        y.fixed_rows_mut::<3>(vo + 3).copy_from(&omega_body);
        yp.fixed_rows_mut::<3>(qo).copy_from(&(u0 + g * t));
        // ė = ½ e ⊗ (0, ω′), written here as the quaternion product (not through G).
        let product = rotation.quaternion() * nalgebra::Quaternion::from_imag(omega_body);
        yp.fixed_rows_mut::<4>(qo + 3)
            .copy_from(&(parameters_of(&UnitQuaternion::new_unchecked(product)) * 0.5));
        yp.fixed_rows_mut::<3>(vo).copy_from(&g);
        let mut out = DVector::zeros(layout.size());
        system.residual(t, &y, &yp, &mut out).unwrap();
        assert!(
            out.amax() < 1e-13 * 25.0,
            "t = {t}: residual {}",
            out.transpose()
        );
    }
}

/// A compound pendulum: a part of mass `m`, inertia diag(`jc`) with its CM at distance
/// `length` from a REVOLUTE pivot at the world origin whose axis is world y, released at angle
/// `theta0` from the downward vertical with angular velocity `omega0` about world y.
fn pendulum(m: f64, jc: f64, length: f64, theta0: f64, omega0: f64) -> MultibodySystem {
    pendulum_builder(m, jc, length, theta0, omega0)
        .0
        .build()
        .unwrap()
}

/// The pendulum's builder and its joint, to add a MOTION.
fn pendulum_builder(
    m: f64,
    jc: f64,
    length: f64,
    theta0: f64,
    omega0: f64,
) -> (MultibodyBuilder, ConstraintId) {
    let g = Vector3::new(0.0, 0.0, -9.81);
    let mut builder = MultibodyBuilder::new(g);
    let cm = Vector3::new(length * theta0.sin(), 0.0, -length * theta0.cos());
    let spin = Vector3::new(0.0, omega0, 0.0);
    let bob = builder
        .add_part(PartSpec {
            name: "PART/2".into(),
            mass: m,
            inertia_cm: Matrix3::identity() * jc,
            pose_w: Isometry3::translation(cm.x, cm.y, cm.z),
            velocity_w: spin.cross(&cm),
            angular_velocity_w: spin,
        })
        .unwrap();
    // Marker z axes along world y: a rotation of −π/2 about x.
    let axis = UnitQuaternion::from_scaled_axis(Vector3::new(-FRAC_PI_2, 0.0, 0.0));
    let on_bob = builder
        .add_marker(bob, Isometry3::from_parts(Translation3::from(-cm), axis))
        .unwrap();
    let on_ground = builder
        .add_marker(
            PartId::GROUND,
            Isometry3::from_parts(Translation3::identity(), axis),
        )
        .unwrap();
    let joint = builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, on_bob, on_ground)
        .unwrap();
    (builder, joint)
}

#[test]
fn rotational_motion_multiplier_is_the_driving_torque() {
    // The pendulum driven by f(t) = 0.4 sin(3t) + 1.5t: assembly turns it to f(t0), velocity
    // projection spins it at f′(t0), and the MOTION's multiplier must supply
    // τ = (Jc + m L²) f″(t0) − ((c × m g)·z_J) about the joint axis z_J (world y); the reaction
    // of the MOTION row on the bob is −λ z_J, so λ = −τ.
    let (m, jc, length, theta0) = (1.5, 0.03, 0.6, 0.2);
    let (mut builder, joint) = pendulum_builder(m, jc, length, theta0, 0.0);
    let drive = sine_drive(0.4, 3.0, 1.5);
    builder
        .add_motion("MOTION/1", joint, MotionDof::Rotational, drive.clone())
        .unwrap();
    let system = builder.build().unwrap();
    let t0 = 0.9;
    let start = system.compute_initial_state(t0).unwrap();
    let (angle, rate, acceleration) = drive(t0);
    let c = start.y.fixed_rows::<3>(0).into_owned();
    let axis = Vector3::y();
    // x_J is world x and z_J world y; the bob starts unrotated (angle 0), so the MOTION turns
    // its CM about world y by f(t0).
    let c0 = Vector3::new(length * theta0.sin(), 0.0, -length * theta0.cos());
    let turned = UnitQuaternion::from_scaled_axis(axis * angle) * c0;
    assert!((c - turned).norm() < 1e-9, "{c} vs {turned}");
    let rotation = UnitQuaternion::new_normalize(nalgebra::Quaternion::new(
        start.y[3], start.y[4], start.y[5], start.y[6],
    ));
    let omega_w = rotation * start.y.fixed_rows::<3>(10).into_owned();
    assert!((omega_w - axis * rate).norm() < 1e-9, "{omega_w} vs {rate}");
    let gravity_moment = c.cross(&(Vector3::new(0.0, 0.0, -9.81) * m)).dot(&axis);
    let torque = (jc + m * length * length) * acceleration - gravity_moment;
    let lambda_motion = start.y[system.layout().lambda_offset() + 5];
    assert!(
        (lambda_motion + torque).abs() < 1e-7 * torque.abs().max(1.0),
        "λ = {lambda_motion}, τ = {torque}"
    );
}

#[test]
fn pendulum_initial_multiplier_is_the_analytic_joint_reaction() {
    let (m, jc, length, g) = (2.0, 0.05, 0.8, 9.81);
    for (theta0, omega0) in [(0.0, 0.0), (0.7, 0.0), (-1.2, 2.5)] {
        let system = pendulum(m, jc, length, theta0, omega0);
        let start = system.compute_initial_state(0.0).unwrap();
        // Oracle: rotation about the pivot, α = (c × m g)_y / (Jc + m L²); the CM acceleration
        // a = α × c + ω × (ω × c); the reaction on the bob R = m a − m g.
        let c = Vector3::new(length * theta0.sin(), 0.0, -length * theta0.cos());
        let gravity = Vector3::new(0.0, 0.0, -g);
        let alpha = Vector3::new(
            0.0,
            c.cross(&(gravity * m)).y / (jc + m * length * length),
            0.0,
        );
        let omega = Vector3::new(0.0, omega0, 0.0);
        let acceleration = alpha.cross(&c) + omega.cross(&omega.cross(&c));
        let reaction = acceleration * m - gravity * m;
        let lambda = start
            .y
            .rows(system.layout().lambda_offset(), 5)
            .into_owned();
        let from_lambda = -Vector3::new(lambda[0], lambda[1], lambda[2]);
        assert!(
            (from_lambda - reaction).norm() < 1e-9 * reaction.norm(),
            "θ0 = {theta0}: {from_lambda} vs {reaction}"
        );
        // No moment is needed to keep the axis: the rotational multipliers vanish.
        assert!(lambda[3].abs() < 1e-9 && lambda[4].abs() < 1e-9, "{lambda}");
        // Tension check in words: at the bottom at rest the joint carries exactly the weight.
        if theta0 == 0.0 {
            assert!((reaction.z - m * g).abs() < 1e-12);
        }
    }
}

#[test]
fn pendulum_period_energy_and_constraint_under_bdf2() {
    for formulation in [Formulation::I3, Formulation::Si2] {
        pendulum_period_energy_and_constraint(formulation);
    }
}

fn pendulum_period_energy_and_constraint(formulation: Formulation) {
    let (m, jc, length, g, theta0) = (1.0, 0.02, 0.5, 9.81, 0.1);
    let build = || {
        let (mut builder, _) = pendulum_builder(m, jc, length, theta0, 0.0);
        builder.set_formulation(formulation);
        builder.build().unwrap()
    };
    let (mut system, observer) = (build(), build());
    let start = system.compute_initial_state(0.0).unwrap();
    // Small-amplitude period with the first amplitude correction (1 + θ0²/16).
    let period = 2.0
        * PI
        * ((jc + m * length * length) / (m * g * length)).sqrt()
        * (1.0 + theta0 * theta0 / 16.0);
    let h = period / 400.0;
    let steps = (1.3 * period / h) as usize;
    let energy =
        |y: &DVector<f64>| observer.kinetic_energy(y) + observer.gravity_potential_energy(y);
    let e0 = energy(&start.y);
    let swing = m * g * length * (1.0 - theta0.cos());
    let (mut crossings, mut last_x) = (Vec::new(), start.y[0]);
    let (mut worst_energy, mut worst_phi, mut worst_velocity) = (0.0_f64, 0.0_f64, 0.0_f64);
    integrate_bdf2(&mut system, 0.0, &start, h, steps, |t, y| {
        let x = y[0]; // the CM's x: zero when the pendulum hangs straight down
        if last_x > 0.0 && x <= 0.0 {
            crossings.push(t - h * x / (x - last_x));
        }
        last_x = x;
        worst_energy = worst_energy.max((energy(y) - e0).abs() / swing);
        let states = observer.part_states(y).unwrap();
        worst_phi = worst_phi.max(observer.constraint_values(t, &states).unwrap().amax());
        let v = y.rows(7, 6).into_owned();
        worst_velocity = worst_velocity.max((observer.velocity_jacobian(&states) * v).amax());
    });
    assert_eq!(crossings.len(), 2, "{formulation:?}: {crossings:?}");
    let measured = crossings[1] - crossings[0];
    assert!(
        (measured - period).abs() < 5e-3 * period,
        "{formulation:?}: period {measured} vs {period}"
    );
    // BDF2 dissipates O((ωh)³) of the swing energy per step; 1% over 1.3 periods is far above
    // that and far below a sign error in any term.
    assert!(
        worst_energy < 1e-2,
        "{formulation:?}: energy drift {worst_energy} of the swing energy"
    );
    assert!(
        worst_phi < 1e-9 * length,
        "{formulation:?}: constraint residual {worst_phi}"
    );
    // SI2 enforces the velocity constraints too; I3 satisfies them only to the step's accuracy.
    if formulation == Formulation::Si2 {
        assert!(
            worst_velocity < 1e-9,
            "velocity constraint residual {worst_velocity}"
        );
    }
}

#[test]
fn torque_free_body_conserves_angular_momentum_and_energy_in_the_residual() {
    // With no forces, the residual's dynamic rows give J ω̇′ = −ω′ × Jω′. Then the world angular
    // momentum H = A J ω′ and the energy T = ½ ω′ᵀJω′ must be stationary:
    // dH/dt = A (ω′ × Jω′ + J ω̇′) = 0 and dT/dt = ω′ᵀ J ω̇′ = 0.
    let mut rng = Rng::new(5);
    for _ in 0..5 {
        let mut builder = MultibodyBuilder::new(Vector3::zeros());
        let part = builder.add_part(random_part(&mut rng, "PART/2")).unwrap();
        let mut system = builder.build().unwrap();
        let layout = *system.layout();
        let start = system.compute_initial_state(0.0).unwrap();
        let vo = layout.velocity_offset(part);
        let mut yp = start.yp.clone();
        yp.fixed_rows_mut::<3>(vo + 3).fill(0.0);
        let mut out = DVector::zeros(layout.size());
        system.residual(0.0, &start.y, &yp, &mut out).unwrap();
        let inertia = system.parts[0].inertia;
        let omega = start.y.fixed_rows::<3>(vo + 3).into_owned();
        let omega_dot = -inertia.try_inverse().unwrap() * out.fixed_rows::<3>(vo + 3);
        let h_dot = omega.cross(&(inertia * omega)) + inertia * omega_dot;
        let scale = (inertia * omega).norm() * omega.norm();
        assert!(h_dot.norm() < 1e-13 * scale, "dH/dt = {h_dot}");
        assert!(omega.dot(&(inertia * omega_dot)).abs() < 1e-13 * scale * omega.norm());
        // The same accelerations come out of the initial-condition solve.
        assert!(
            (start.yp.fixed_rows::<3>(vo + 3) - omega_dot).norm()
                < 1e-12 * omega_dot.norm().max(1e-300)
        );
    }
}

#[test]
fn initial_state_is_consistent_for_a_driven_mechanism() {
    for formulation in [Formulation::I3, Formulation::Si2] {
        driven_mechanism_is_consistent(formulation);
    }
}

fn driven_mechanism_is_consistent(formulation: Formulation) {
    // A crank on a REVOLUTE driven by a rotational MOTION, a slider on a TRANSLATIONAL driven by
    // a translational MOTION, and a free link hung from the crank by a SPHERICAL joint, all
    // placed slightly off their joints. Oracle: the residual at (y0, y0′) vanishes, the
    // velocity constraints hold, and the driven coordinates follow f, f′, f″.
    let mut rng = Rng::new(9);
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, -9.81, 0.0));
    builder.set_formulation(formulation);
    let specs = [
        random_part(&mut rng, "PART/2"),
        random_part(&mut rng, "PART/3"),
        random_part(&mut rng, "PART/4"),
    ];
    let crank = builder.add_part(specs[0].clone()).unwrap();
    let slider = builder.add_part(specs[1].clone()).unwrap();
    let link = builder.add_part(specs[2].clone()).unwrap();
    // Each J marker is placed at its I marker's world pose moved by ~0.02 (length and radian),
    // so the joints start nearly closed with z_I close to +z_J (a REVOLUTE also closes with
    // z_I = −z_J, which would reverse the MOTION's sign).
    let part_poses = [
        Isometry3::identity(),
        specs[0].pose_w,
        specs[1].pose_w,
        specs[2].pose_w,
    ];
    let pair = |b: &mut MultibodyBuilder, rng: &mut Rng, part_i: PartId, part_j: PartId| {
        let pose_i = rng.pose(0.3);
        let nudge = Isometry3::from_parts(
            Translation3::from(rng.vector(0.02)),
            UnitQuaternion::from_scaled_axis(rng.vector(0.02)),
        );
        let pose_j = part_poses[part_j.0].inverse() * part_poses[part_i.0] * pose_i * nudge;
        (
            b.add_marker(part_i, pose_i).unwrap(),
            b.add_marker(part_j, pose_j).unwrap(),
        )
    };
    let (c1, g1) = pair(&mut builder, &mut rng, crank, PartId::GROUND);
    let revolute = builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, c1, g1)
        .unwrap();
    let (s1, g2) = pair(&mut builder, &mut rng, slider, PartId::GROUND);
    let translational = builder
        .add_constraint("JOINT/2", ConstraintKind::Translational, s1, g2)
        .unwrap();
    let (l1, c2) = pair(&mut builder, &mut rng, link, crank);
    builder
        .add_constraint("JOINT/3", ConstraintKind::Spherical, l1, c2)
        .unwrap();
    let spin = sine_drive(0.5, 2.0, 3.0);
    let stroke = sine_drive(0.2, 5.0, -0.4);
    builder
        .add_motion("MOTION/1", revolute, MotionDof::Rotational, spin.clone())
        .unwrap();
    builder
        .add_motion(
            "MOTION/2",
            translational,
            MotionDof::Translational,
            stroke.clone(),
        )
        .unwrap();
    let mut system = builder.build().unwrap();
    let t0 = 0.7;
    let start = system.compute_initial_state(t0).unwrap();
    assert!(
        start.assembly_iterations > 0,
        "the parts were placed off their joints"
    );
    let layout = *system.layout();
    let mut out = DVector::zeros(layout.size());
    system.residual(t0, &start.y, &start.yp, &mut out).unwrap();
    assert!(out.amax() < 1e-8, "residual {}", out.transpose());
    let states = system.part_states(&start.y).unwrap();
    let v = start.y.rows(layout.velocity_offset(crank), 18).into_owned();
    let (phi_t, _) = system.constraint_time_derivatives(t0);
    assert!((system.velocity_jacobian(&states) * v + phi_t).amax() < 1e-10);
    // The crank turns about its joint's z axis at f′ with angular acceleration f″ (world).
    let joint_axis =
        states[crank.0].pose_w.rotation * system.constraints[0].marker_i.rotation * Vector3::z();
    let vo = layout.velocity_offset(crank);
    let rotation = states[crank.0].pose_w.rotation;
    let omega_w = rotation * start.y.fixed_rows::<3>(vo + 3).into_owned();
    let alpha_w = rotation * start.yp.fixed_rows::<3>(vo + 3).into_owned();
    let (_, rate, acceleration) = spin(t0);
    assert!(
        (omega_w - joint_axis * rate).norm() < 1e-9,
        "{omega_w} vs {rate}"
    );
    assert!(
        (alpha_w - joint_axis * acceleration).norm() < 1e-6,
        "{alpha_w} vs {acceleration}"
    );
    // The slider's velocity and acceleration along its joint axis are f′ and f″ of the stroke.
    let slider_axis = system.constraints[1].marker_j.rotation * Vector3::z();
    let so = layout.velocity_offset(slider);
    let (_, rate, acceleration) = stroke(t0);
    assert!((start.y.fixed_rows::<3>(so).dot(&slider_axis) - rate).abs() < 1e-9);
    assert!((start.yp.fixed_rows::<3>(so).dot(&slider_axis) - acceleration).abs() < 1e-6);
}
