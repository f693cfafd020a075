//! Linearization (LINEAR/EIGENSOL) against closed-form eigenvalues: a damped oscillator on a
//! TRANSLATIONAL joint, a pendulum at its two equilibria, a double pendulum (with and without a
//! redundant constraint), and a ball resting on an IMPACT contact.

use crate::statics::lowered;
use contact::run::lower::lower;
use contact::solver::contact_force::Analysis;
use contact::solver::linear::{Eigenvalue, LinearSettings, linearize};
use contact::solver::mbs::{
    ConstraintKind, MarkerId, MultibodyBuilder, MultibodySystem, PartId, PartSpec, SpringParams,
    TranslationalSpringDamper,
};
use contact::solver::statics::{StaticsSettings, solve_statics};
use contact_core::FacetingTolerance;
use engine_facet::FacetEngine;
use nalgebra::{DVector, Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};
use std::f64::consts::{FRAC_PI_2, PI};

const G: f64 = 9.81;

/// `|a − b| / |b|`.
fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// The eigenvalues of `system` at its given state (assembled, velocities projected).
fn eigenvalues_at_rest(system: &mut MultibodySystem, settings: &LinearSettings) -> Vec<Eigenvalue> {
    let mut y = system.given_state().clone();
    system.assemble(0.0, &mut y).unwrap();
    system.project_velocities(0.0, &mut y).unwrap();
    linearize(system, 0.0, &y, settings).unwrap().eigenvalues
}

/// A block of mass `m` at `x` on a TRANSLATIONAL joint along world x, pulled towards the
/// origin by a spring-damper (k, c, free length 1) between its CM and the ground origin;
/// gravity along −z is carried by the joint.
fn oscillator(m: f64, k: f64, c: f64, x: f64) -> MultibodySystem {
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -G));
    let block = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            m,
            Matrix3::from_diagonal(&Vector3::new(0.01, 0.02, 0.03)),
            Isometry3::translation(x, 0.0, 0.0),
        ))
        .unwrap();
    let along_x = Isometry3::from_parts(
        Translation3::identity(),
        UnitQuaternion::from_scaled_axis(Vector3::new(0.0, FRAC_PI_2, 0.0)),
    );
    let i = builder.add_marker(block, along_x).unwrap();
    let j = builder.add_marker(PartId::GROUND, along_x).unwrap();
    builder
        .add_constraint("JOINT/1", ConstraintKind::Translational, i, j)
        .unwrap();
    let params = SpringParams {
        stiffness: k,
        damping: c,
        free_length: 1.0,
        preload: 0.0,
    };
    builder
        .add_force(Box::new(
            TranslationalSpringDamper::new(
                "SPRING/1",
                block,
                Vector3::zeros(),
                PartId::GROUND,
                Vector3::zeros(),
                params,
            )
            .unwrap(),
        ))
        .unwrap();
    builder.build().unwrap()
}

#[test]
fn a_damped_oscillator_on_a_translational_joint_has_the_closed_form_pair() {
    let (m, k, c): (f64, f64, f64) = (2.0, 800.0, 8.0);
    // s = −c/2m ± i·√(k/m − (c/2m)²); at the free length and stretched (the spring is linear,
    // so the operating point does not change the eigenvalues).
    let sigma = -c / (2.0 * m);
    let omega_d = (k / m - sigma * sigma).sqrt();
    let mut worst: f64 = 0.0;
    for x in [1.0, 1.1] {
        let values = eigenvalues_at_rest(&mut oscillator(m, k, c, x), &LinearSettings::default());
        assert_eq!(values.len(), 2, "{values:?}");
        let error = relative(values[0].real, sigma)
            .max(relative(values[0].imaginary, omega_d))
            .max(relative(values[1].imaginary, -omega_d))
            .max(relative(values[1].real, sigma));
        worst = worst.max(error);
        assert!(error < 1e-9, "x = {x}: {values:?} vs {sigma} ± {omega_d}i");
        let zeta = c / (2.0 * (k * m).sqrt());
        assert!(relative(values[0].damping_ratio.unwrap(), zeta) < 1e-9);
        let frequency = (k / m).sqrt() / (2.0 * PI);
        assert!(relative(values[0].frequency, frequency) < 1e-9);
    }
    println!("oscillator: worst relative error {worst:e}");
    // NODAMPIN: the undamped pair ±i√(k/m).
    let values = eigenvalues_at_rest(
        &mut oscillator(m, k, c, 1.0),
        &LinearSettings { damping: false },
    );
    let omega = (k / m).sqrt();
    assert!(values[0].real.abs() < 1e-9 * omega, "{values:?}");
    assert!(relative(values[0].imaginary, omega) < 1e-9, "{values:?}");
    assert_eq!(values[0].damping_ratio, Some(-values[0].real / omega));
}

#[test]
fn an_overdamped_oscillator_has_two_real_roots() {
    let (m, k, c): (f64, f64, f64) = (2.0, 800.0, 200.0);
    let sigma = -c / (2.0 * m);
    let root = (sigma * sigma - k / m).sqrt();
    let values = eigenvalues_at_rest(&mut oscillator(m, k, c, 1.0), &LinearSettings::default());
    assert_eq!(values.len(), 2);
    // Sorted by |s|: the slow root first.
    let (slow, fast) = (sigma + root, sigma - root);
    assert_eq!((values[0].imaginary, values[1].imaginary), (0.0, 0.0));
    let error = relative(values[0].real, slow).max(relative(values[1].real, fast));
    println!("overdamped oscillator: worst relative error {error:e}");
    assert!(error < 1e-9, "{values:?} vs {slow}, {fast}");
    assert_eq!(values[0].damping_ratio, Some(1.0));
}

/// A marker at `position` (part frame) whose z axis is world y (parts unrotated).
fn pin_marker(builder: &mut MultibodyBuilder, part: PartId, position: Vector3<f64>) -> MarkerId {
    let z_along_y = UnitQuaternion::from_scaled_axis(Vector3::new(-FRAC_PI_2, 0.0, 0.0));
    builder
        .add_marker(
            part,
            Isometry3::from_parts(Translation3::from(position), z_along_y),
        )
        .unwrap()
}

/// A link of mass `m` with its CM a distance `d` from a REVOLUTE pin about world y at the
/// origin, hanging below it (`up = false`) or standing above it, inertia `i_cm` about y.
fn pendulum(m: f64, d: f64, i_cm: f64, up: bool) -> MultibodySystem {
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -G));
    let z = if up { d } else { -d };
    let link = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            m,
            Matrix3::from_diagonal(&Vector3::new(0.3, i_cm, 0.2)),
            Isometry3::translation(0.0, 0.0, z),
        ))
        .unwrap();
    let i = pin_marker(&mut builder, link, Vector3::new(0.0, 0.0, -z));
    let j = pin_marker(&mut builder, PartId::GROUND, Vector3::zeros());
    builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, i, j)
        .unwrap();
    builder.build().unwrap()
}

#[test]
fn a_pendulum_oscillates_at_the_bottom_and_is_unstable_at_the_top() {
    let (m, d, i_cm) = (3.0, 0.4, 0.05);
    let omega = (m * G * d / (i_cm + m * d * d)).sqrt();
    let settings = LinearSettings::default();
    let bottom = eigenvalues_at_rest(&mut pendulum(m, d, i_cm, false), &settings);
    assert_eq!(bottom.len(), 2, "{bottom:?}");
    let bottom_error = relative(bottom[0].imaginary, omega).max(bottom[0].real.abs() / omega);
    assert!(bottom_error < 1e-9, "{bottom:?} vs ±{omega}i");
    assert_eq!(bottom[1].imaginary, -bottom[0].imaginary);
    let top = eigenvalues_at_rest(&mut pendulum(m, d, i_cm, true), &settings);
    assert_eq!(top.len(), 2, "{top:?}");
    let top_error = relative(top[0].real, -omega)
        .max(relative(top[1].real, omega))
        .max(top[0].imaginary.abs() / omega);
    assert!(top_error < 1e-9, "{top:?} vs ±{omega}");
    assert_eq!(top[1].damping_ratio, Some(-1.0));
    println!("pendulum: worst relative error bottom {bottom_error:e}, top {top_error:e}");
}

/// Two links hanging from a REVOLUTE about world y: link 1 (mass m1, CM a1 below the pivot,
/// inertia i1 about its CM) and link 2 pinned to it at l1 below the pivot (m2, CM a2 below
/// that pin, i2). With `redundant`, a PARALLEL_AXES JPRIM repeats what the first REVOLUTE
/// already imposes on link 1.
fn double_pendulum(links: [[f64; 3]; 2], l1: f64, redundant: bool) -> MultibodySystem {
    let [[m1, a1, i1], [m2, a2, i2]] = links;
    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -G));
    let inertia = |i: f64| Matrix3::from_diagonal(&Vector3::new(0.7 * i + 0.01, i, 0.5 * i));
    let link1 = builder
        .add_part(PartSpec::at_rest(
            "PART/2",
            m1,
            inertia(i1),
            Isometry3::translation(0.0, 0.0, -a1),
        ))
        .unwrap();
    let link2 = builder
        .add_part(PartSpec::at_rest(
            "PART/3",
            m2,
            inertia(i2),
            Isometry3::translation(0.0, 0.0, -l1 - a2),
        ))
        .unwrap();
    let (i, j) = (
        pin_marker(&mut builder, link1, Vector3::new(0.0, 0.0, a1)),
        pin_marker(&mut builder, PartId::GROUND, Vector3::zeros()),
    );
    builder
        .add_constraint("JOINT/1", ConstraintKind::Revolute, i, j)
        .unwrap();
    let (i, j) = (
        pin_marker(&mut builder, link2, Vector3::new(0.0, 0.0, a2)),
        pin_marker(&mut builder, link1, Vector3::new(0.0, 0.0, a1 - l1)),
    );
    builder
        .add_constraint("JOINT/2", ConstraintKind::Revolute, i, j)
        .unwrap();
    if redundant {
        let (i, j) = (
            pin_marker(&mut builder, link1, Vector3::new(0.1, 0.0, 0.0)),
            pin_marker(&mut builder, PartId::GROUND, Vector3::new(0.2, 0.0, 0.0)),
        );
        builder
            .add_constraint("JPRIM/3", ConstraintKind::ParallelAxes, i, j)
            .unwrap();
    }
    builder.build().unwrap()
}

#[test]
fn a_double_pendulum_has_the_frequencies_of_its_two_by_two_eigenproblem() {
    let links = [[2.0, 0.3, 0.04], [1.0, 0.25, 0.02]];
    let l1 = 0.6;
    let [[m1, a1, i1], [m2, a2, i2]] = links;
    // Angles θ1, θ2 from the vertical: M = [[i1 + m1a1² + m2l1², m2l1a2], [m2l1a2, i2 + m2a2²]],
    // K = diag((m1a1 + m2l1)g, m2a2g); det(K − ω²M) = 0 is a quadratic in ω².
    let (m11, m12, m22) = (
        i1 + m1 * a1 * a1 + m2 * l1 * l1,
        m2 * l1 * a2,
        i2 + m2 * a2 * a2,
    );
    let (k11, k22) = ((m1 * a1 + m2 * l1) * G, m2 * a2 * G);
    let (qa, qb, qc) = (m11 * m22 - m12 * m12, -(k11 * m22 + k22 * m11), k11 * k22);
    let disc = (qb * qb - 4.0 * qa * qc).sqrt();
    let expected = [
        ((-qb - disc) / (2.0 * qa)).sqrt(),
        ((-qb + disc) / (2.0 * qa)).sqrt(),
    ];
    for redundant in [false, true] {
        let mut system = double_pendulum(links, l1, redundant);
        let values = eigenvalues_at_rest(&mut system, &LinearSettings::default());
        assert_eq!(values.len(), 4, "redundant = {redundant}: {values:?}");
        let mut worst: f64 = 0.0;
        for (pair, omega) in values.chunks(2).zip(expected) {
            worst = worst
                .max(relative(pair[0].imaginary, omega))
                .max(pair[0].real.abs() / omega);
            assert_eq!(pair[1].imaginary, -pair[0].imaginary);
        }
        println!("double pendulum (redundant = {redundant}): worst relative error {worst:e}");
        assert!(
            worst < 1e-9,
            "redundant = {redundant}: {values:?} vs {expected:?}"
        );
    }
}

/// The resting ball of `crate::statics` (radius 0.1, mass 1, IMPACT k = 1e6, e = 1.5,
/// c = 50, DMAX = 1e-4), its CM at height `z`.
fn ball(z: f64) -> String {
    format!(
        "ball on a plane\n\
         UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
         PART/1, GROUND\nMARKER/10, PART = 1\n\
         PART/2, MASS = 1, CM = 20, IP = 0.004, 0.004, 0.004\nMARKER/20, PART = 2, QP = 0.01, -0.02, {z}\n\
         GRAPHICS/1, ELLIPSOID, CM = 20, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2\n\
         GRAPHICS/2, PLANE, RM = 10\n\
         CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT, STIFFNESS = 1E6, EXPONENT = 1.5, DAMPING = 50, DMAX = 1E-4\n\
         ACCGRAV/ KGRAV = -9.81\nEND\n"
    )
}

#[test]
fn a_resting_ball_adds_the_contact_stiffness_and_a_lifted_one_adds_nothing() {
    let (m, k, e, c) = (1.0, 1e6, 1.5, 50.0);
    let mut model = lowered("linear_ball.adm", &ball(0.099));
    let y = model.system.given_state().clone();
    let settings = StaticsSettings {
        error: 1e-12,
        imbalance: 1e-10,
        ..StaticsSettings::default()
    };
    let found = solve_statics(&mut model.system, 0.0, &y, &settings).unwrap();
    let linear = linearize(&mut model.system, 0.0, &found.y, &LinearSettings::default()).unwrap();
    assert_eq!(linear.degrees_of_freedom, 6);
    let values = &linear.eigenvalues;
    assert_eq!(values.len(), 12);
    // k·δ^e = m·g; the normal stiffness dFn/dδ = k·e·δ^(e−1); δ > DMAX, so the damping is c.
    let delta = (m * G / k).powf(1.0 / e);
    let stiffness = k * e * delta.powf(e - 1.0);
    let omega = (stiffness / m).sqrt();
    let vertical = &values[10..];
    // The contact's partials are forward differences with step h = √ε·max(|r|, L) (lifting
    // the ball by h): at worst the stiffness is the secant (f(δ) − f(δ − h))/h of
    // f = k·δ^e, off by about ½(e − 1)h/δ, and the frequency by √(secant/f′) − 1.
    let r = found.y.fixed_rows::<3>(0).norm();
    let h = f64::EPSILON.sqrt() * r.max(model.system.length_scale());
    let secant = k * (delta.powf(e) - (delta - h).powf(e)) / h;
    let bound = 1.01 * (1.0 - (secant / stiffness).sqrt()) + 1e-12;
    let frequency_error = relative(vertical[0].magnitude(), omega);
    // The real part −c/2m does not depend on the stiffness; the damping force is linear in δ̇.
    let real_error = relative(vertical[0].real, -c / (2.0 * m));
    println!(
        "resting ball: frequency error {frequency_error:e} (bound {bound:e}), real part error {real_error:e}"
    );
    assert!(frequency_error < bound, "{vertical:?} vs |s| = {omega}");
    assert!(real_error < 1e-9, "{vertical:?} vs σ = {}", -c / (2.0 * m));
    assert_eq!(vertical[1].imaginary, -vertical[0].imaginary);
    // Sliding and turning on the plane meet no stiffness and no damping (no friction).
    let free = values[..10]
        .iter()
        .map(|s| s.magnitude())
        .fold(0.0, f64::max);
    println!("resting ball: largest free-mode |s| {free:e} (vertical {omega})");
    assert!(free < 1e-6 * omega, "{values:?}");

    let mut lifted = lowered("linear_ball_lifted.adm", &ball(0.3));
    let y = lifted.system.given_state().clone();
    let linear = linearize(&mut lifted.system, 0.0, &y, &LinearSettings::default()).unwrap();
    assert_eq!(linear.eigenvalues.len(), 12);
    for s in &linear.eigenvalues {
        assert_eq!((s.real, s.imaginary), (0.0, 0.0), "{s:?}");
    }
}

#[test]
fn the_multipliers_of_the_operating_point_are_solved_for_not_read() {
    // The pendulum's stiffness is all geometric (∂(Φ_vᵀλ)/∂q): garbage multipliers in y must
    // not change it.
    let (m, d, i_cm) = (3.0, 0.4, 0.05);
    let mut system = pendulum(m, d, i_cm, false);
    let mut y = system.given_state().clone();
    let lambda = system.layout().lambda_offset();
    let rows = system.layout().constraint_rows();
    y.rows_mut(lambda, rows)
        .copy_from(&DVector::from_element(rows, 1e3));
    let values = linearize(&mut system, 0.0, &y, &LinearSettings::default())
        .unwrap()
        .eigenvalues;
    let omega = (m * G * d / (i_cm + m * d * d)).sqrt();
    assert!(relative(values[0].imaginary, omega) < 1e-9, "{values:?}");
}

#[test]
fn the_faceted_ball_has_the_exact_balls_modes() {
    let (m, k, e, c) = (1.0, 1e6, 1.5, 50.0);
    let loaded = crate::inline("linear_ball_facet.adm", &ball(0.099));
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
    let engine = FacetEngine::new(FacetingTolerance::new(300.0028).unwrap());
    let mut model = lower(&loaded.model, &engine, Analysis::Quasistatic, &no_meshes).unwrap();
    let y = model.system.given_state().clone();
    let settings = StaticsSettings {
        error: 1e-12,
        imbalance: 1e-10,
        ..StaticsSettings::default()
    };
    let found = solve_statics(&mut model.system, 0.0, &y, &settings).unwrap();
    let values = linearize(&mut model.system, 0.0, &found.y, &LinearSettings::default())
        .unwrap()
        .eigenvalues;
    assert_eq!(values.len(), 12);
    // The ground PLANE is exact in both engines and the faceted depth changes one for one
    // with a vertical lift, as the exact depth does: the vertical pair is the exact engine's,
    // within the same difference bound.
    let delta = (m * G / k).powf(1.0 / e);
    let stiffness = k * e * delta.powf(e - 1.0);
    let omega = (stiffness / m).sqrt();
    let r = found.y.fixed_rows::<3>(0).norm();
    let h = f64::EPSILON.sqrt() * r.max(model.system.length_scale());
    let secant = k * (delta.powf(e) - (delta - h).powf(e)) / h;
    let bound = 1.01 * (1.0 - (secant / stiffness).sqrt()) + 1e-12;
    let vertical = &values[10..];
    let error = relative(vertical[0].magnitude(), omega);
    println!("faceted ball: vertical frequency error {error:e} (bound {bound:e})");
    assert!(error < bound, "{values:?}");
    assert!(
        relative(vertical[0].real, -c / (2.0 * m)) < 1e-9,
        "{values:?}"
    );
    // Sliding, spinning and tilting stay free, as for the exact ball: the facets' contact
    // with the plane lies on the line from the sphere's centre along the normal (the smooth
    // surface's support point, engine-facet's plane_support), so tilting the ball moves no
    // force off its centre. A polyhedron resting on a vertex would rock instead.
    let largest_free = values[..10]
        .iter()
        .map(|s| s.magnitude())
        .fold(0.0, f64::max);
    println!("faceted ball: largest free-mode |s| {largest_free:e} (vertical {omega})");
    assert!(largest_free < 1e-6 * omega, "{values:?}");
}
