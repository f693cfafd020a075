//! The solver's contact force against contact-core's pieces an embedder uses: the engine's
//! contact, [`ContactKinematics`] and the force laws give the same bits as
//! [`ContactForce::reports`] and the loads of [`ContactForce::evaluate`](ForceElement::evaluate).

use super::*;
use crate::mbs::PartState;
use contact_core::geometry::Plane;
use contact_core::{
    BodyMotion, ContactArgs, FrictionSwitch, Geometry, GeometryEngine, GeometryInstance, Isometry3,
    Units,
};

/// IMPACT (k 1e6, e 1.5, c 50, DMAX 1e-3) with Coulomb friction (μs 0.3, μd 0.2, vs 0.1, vd 1).
fn args() -> ContactArgs {
    ContactArgs {
        impact: true,
        stiffness: Some(1e6),
        exponent: Some(1.5),
        damping: Some(50.0),
        dmax: Some(1e-3),
        coulomb_friction: Some(FrictionSwitch::On),
        mu_static: Some(0.3),
        mu_dynamic: Some(0.2),
        stiction_transition_velocity: Some(0.1),
        friction_transition_velocity: Some(1.0),
        ..ContactArgs::default()
    }
}

fn geometry() -> (GeometryInstance, GeometryInstance) {
    (
        GeometryInstance::new(Geometry::sphere(0.1).unwrap()),
        GeometryInstance::new(Geometry::Plane(Plane::unbounded())),
    )
}

/// A ball about 1e-4 deep in a tilted plate (inside the damping ramp); both parts move and
/// turn.
fn ball_in_moving_plate() -> (PartState, PartState) {
    let ball = PartState {
        pose_w: Isometry3::new(
            nalgebra::Vector3::new(0.01, -0.02, 0.0996),
            nalgebra::Vector3::new(0.2, -0.1, 0.3),
        ),
        velocity_w: nalgebra::Vector3::new(0.3, -0.2, -0.4),
        angular_velocity_w: nalgebra::Vector3::new(1.0, 2.0, 3.0),
    };
    let plate = PartState {
        pose_w: Isometry3::new(
            nalgebra::Vector3::new(0.0, 0.0, 0.0),
            nalgebra::Vector3::new(0.02, -0.01, 0.0),
        ),
        velocity_w: nalgebra::Vector3::new(0.1, 0.0, 0.05),
        angular_velocity_w: nalgebra::Vector3::new(0.0, -0.3, 0.5),
    };
    (ball, plate)
}

#[test]
fn the_solver_force_is_the_kinematics_helper_and_the_laws() {
    let (ball, ground) = geometry();
    let engine = engine_exact::ExactEngine;
    let (params, _) = args().validate(&Units::MKS).unwrap();
    let element = ContactForce::new(
        "CONTACT/1",
        PartId(1),
        PartId(2),
        engine
            .prepare(std::slice::from_ref(&ball), std::slice::from_ref(&ground))
            .unwrap(),
        params.clone(),
        Analysis::Dynamics,
    )
    .unwrap();
    let (ball_state, plate_state) = ball_in_moving_plate();
    let states = [PartState::GROUND, ball_state, plate_state];
    let view = StateView::new(&states);
    let reports = element.reports(0.0, &view).unwrap();
    assert_eq!(reports.len(), 1, "{reports:?}");

    // The embedder's path: query, kinematics, laws.
    let pair = engine.prepare(&[ball], &[ground]).unwrap();
    let mut contacts = Vec::new();
    pair.query(
        &ball_state.pose_w,
        &plate_state.pose_w,
        &mut contacts,
        &mut WorkCounters::default(),
    )
    .unwrap();
    let motion = |s: &PartState| BodyMotion {
        pose_w: s.pose_w,
        velocity_w: s.velocity_w,
        angular_velocity_w: s.angular_velocity_w,
    };
    let (NormalModel::Impact(impact), FrictionModel::On(coulomb)) =
        (&params.normal, &params.friction)
    else {
        unreachable!("IMPACT with friction on")
    };
    let bits = |v: &Vector3| v.map(f64::to_bits);
    for (report, contact) in reports.iter().zip(&contacts) {
        assert_eq!(report.contact, *contact);
        let k = ContactKinematics::compute(contact, &motion(&ball_state), &motion(&plate_state));
        // The rates are not trivial: approaching, slipping and spinning.
        assert!(k.penetration_rate > 0.0 && k.slip_velocity_w.norm() > 0.1 && k.spin != 0.0);
        let normal = impact.force(contact.penetration, k.penetration_rate).force;
        let both = coulomb.slip_and_spin(&k.slip_velocity_w, k.spin, normal, contact.area);
        let (friction, torque) = (both.force.force, both.torque.torque);
        assert!(normal > 0.0 && torque != 0.0);
        assert_eq!(
            report.penetration_rate.to_bits(),
            k.penetration_rate.to_bits()
        );
        assert_eq!(report.normal_force.to_bits(), normal.to_bits());
        assert_eq!(bits(&report.friction_force_w), bits(&friction));
        assert_eq!(report.friction_torque.to_bits(), torque.to_bits());

        // The loads: the force at the midpoint, moved to each part's CM, plus the torque,
        // summed from zero as the element sums its contacts.
        let zero = Vector3::zeros();
        let force = contact.normal_w * normal + friction;
        let mut loads = [Load::default(); 2];
        element.evaluate(0.0, &view, &mut loads).unwrap();
        let on_i = Load::at_point(
            force,
            &k.point_w.coords,
            &ball_state.pose_w.translation.vector,
        );
        let on_j = Load::at_point(
            -force,
            &k.point_w.coords,
            &plate_state.pose_w.translation.vector,
        );
        assert_eq!(bits(&loads[0].force_w), bits(&(zero + on_i.force_w)));
        assert_eq!(
            bits(&loads[0].torque_w),
            bits(&(zero + (on_i.torque_w + contact.normal_w * torque)))
        );
        assert_eq!(bits(&loads[1].force_w), bits(&(zero + on_j.force_w)));
        assert_eq!(
            bits(&loads[1].torque_w),
            bits(&(zero + (on_j.torque_w - contact.normal_w * torque)))
        );
    }
}
