//! A 1 kg ball dropped 1 m on a plane with IMPACT: the full solver (exact engine, multibody
//! equations, BDF with contact prediction) against a separately integrated 1-DOF reference.

use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::{Analysis, ContactForce, SharedContact};
use contact::solver::mbs::{MultibodyBuilder, PartId, PartSpec};
use contact::solver::simulate::{DynamicsSettings, simulate};
use contact_core::geometry::Plane;
use contact_core::{ContactArgs, Geometry, GeometryEngine, GeometryInstance, NormalModel, Units};
use nalgebra::{Isometry3, Matrix3, Vector3};
use std::sync::Arc;

pub const RADIUS: f64 = 0.1;
const MASS: f64 = 1.0;
const G: f64 = 9.81;
const DROP: f64 = 1.0;

fn impact_args() -> ContactArgs {
    ContactArgs {
        impact: true,
        stiffness: Some(1e6),
        exponent: Some(1.5),
        damping: Some(50.0),
        dmax: Some(1e-4),
        ..ContactArgs::default()
    }
}

/// Apex heights of the ball's centre after each bounce, from the 1-DOF equation
/// `m z̈ = −m g + Fn(r − z, −ż)` integrated by classical RK4 at a fixed 1 µs step.
pub fn reference_apexes(bounces: usize) -> Vec<f64> {
    let (params, _) = impact_args().validate(&Units::MKS).unwrap();
    let NormalModel::Impact(law) = params.normal else {
        unreachable!()
    };
    let accel = |z: f64, v: f64| -G + law.force(RADIUS - z, -v).force / MASS;
    let (mut z, mut v) = (RADIUS + DROP, 0.0_f64);
    let dt = 1e-6;
    let mut apexes = Vec::new();
    let mut was_rising = false;
    while apexes.len() < bounces {
        let (k1z, k1v) = (v, accel(z, v));
        let (k2z, k2v) = (
            v + 0.5 * dt * k1v,
            accel(z + 0.5 * dt * k1z, v + 0.5 * dt * k1v),
        );
        let (k3z, k3v) = (
            v + 0.5 * dt * k2v,
            accel(z + 0.5 * dt * k2z, v + 0.5 * dt * k2v),
        );
        let (k4z, k4v) = (v + dt * k3v, accel(z + dt * k3z, v + dt * k3v));
        z += dt / 6.0 * (k1z + 2.0 * k2z + 2.0 * k3z + k4z);
        v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if was_rising && v <= 0.0 {
            apexes.push(z + v * v / (2.0 * G));
        }
        was_rising = v > 0.0 && z > RADIUS;
    }
    apexes
}

#[test]
fn rebound_heights_match_a_separately_integrated_reference() {
    let reference = reference_apexes(2);
    assert!(
        reference[0] < RADIUS + DROP && reference[0] > RADIUS + 0.5 * DROP,
        "{reference:?}"
    );

    let mut builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -G));
    let inertia = Matrix3::identity() * (0.4 * MASS * RADIUS * RADIUS);
    let start = Isometry3::translation(0.0, 0.0, RADIUS + DROP);
    let ball = builder
        .add_part(PartSpec::at_rest("PART/2", MASS, inertia, start))
        .unwrap();
    let engine = engine_exact::ExactEngine;
    let pair = engine
        .prepare(
            &[GeometryInstance::new(Geometry::sphere(RADIUS).unwrap())],
            &[GeometryInstance::new(Geometry::Plane(Plane::unbounded()))],
        )
        .unwrap();
    let (params, _) = impact_args().validate(&Units::MKS).unwrap();
    let contact = Arc::new(
        ContactForce::new(
            "CONTACT/1",
            ball,
            PartId::GROUND,
            pair,
            params,
            Analysis::Dynamics,
        )
        .unwrap(),
    );
    builder
        .add_force(Box::new(SharedContact(contact.clone())))
        .unwrap();
    let mut system = builder.build().unwrap();
    let settings = DynamicsSettings {
        start: 0.0,
        end: 1.6,
        output_step: 1e-3,
        integrator: IntegratorSettings {
            error: 1e-6,
            ..IntegratorSettings::default()
        },
    };
    let mut apexes = Vec::new();
    let mut was_rising = false;
    let summary = simulate(&mut system, &[contact], &settings, &mut |frame| {
        let s = frame.parts[ball.0];
        let (z, v) = (s.pose_w.translation.z, s.velocity_w.z);
        if was_rising && v <= 0.0 && frame.contacts[0].is_empty() {
            apexes.push(z + v * v / (2.0 * G));
        }
        was_rising = v > 0.0 && frame.contacts[0].is_empty();
        Ok(())
    })
    .unwrap();
    assert!(summary.rejected_for_contact_onset >= 1, "{summary:?}");
    assert!(apexes.len() >= 2, "apexes {apexes:?}, {summary:?}");
    for (k, (got, want)) in apexes.iter().zip(&reference).enumerate() {
        let rebound = (got - RADIUS, want - RADIUS);
        let relative = (rebound.0 - rebound.1).abs() / rebound.1;
        assert!(
            relative < 1e-3,
            "bounce {k}: rebound {} vs reference {} ({relative:e}); {summary:?}",
            rebound.0,
            rebound.1
        );
    }
}
