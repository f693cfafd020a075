//! Unit tests of the multibody equations, with shared fixtures.
//!
//! Oracles: central differences of the residual and of Φ (Jacobians), closed forms (free fall,
//! pendulum tension, torque-free rigid body), and a tiny fixed-step BDF2 driver written here
//! only to run dynamics before the product integrator exists (`driver`).

mod constraint_jacobians;
mod driver;
mod dynamics;
mod errors;
mod mechanisms;
mod newton_matrix;
mod redundancy;
mod springs;

use super::*;
use nalgebra::{DVector, Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};
use std::sync::Arc;

/// A small deterministic generator (xorshift) so fixtures need no dependency.
pub(super) struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed.max(1))
    }

    /// Uniform in [−1, 1).
    pub fn signed(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }

    pub fn vector(&mut self, scale: f64) -> Vector3<f64> {
        Vector3::new(self.signed(), self.signed(), self.signed()) * scale
    }

    pub fn rotation(&mut self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_scaled_axis(self.vector(2.0))
    }

    pub fn pose(&mut self, scale: f64) -> Isometry3<f64> {
        Isometry3::from_parts(Translation3::from(self.vector(scale)), self.rotation())
    }
}

/// A non-diagonal, positive definite inertia.
pub(super) fn inertia(rng: &mut Rng) -> Matrix3<f64> {
    let a = Matrix3::from_fn(|_, _| rng.signed());
    a * a.transpose() + Matrix3::identity() * 0.5
}

/// A random moving part.
pub(super) fn random_part(rng: &mut Rng, name: &str) -> PartSpec {
    PartSpec {
        name: name.to_owned(),
        mass: 1.0 + rng.signed().abs(),
        inertia_cm: inertia(rng),
        pose_w: rng.pose(1.0),
        velocity_w: rng.vector(1.0),
        angular_velocity_w: rng.vector(1.0),
    }
}

/// A smooth drive `f(t) = a sin(ωt) + b t` with exact derivatives.
pub(super) fn sine_drive(a: f64, omega: f64, b: f64) -> TimeFunction {
    Arc::new(move |t: f64| {
        (
            a * (omega * t).sin() + b * t,
            a * omega * (omega * t).cos() + b,
            -a * omega * omega * (omega * t).sin(),
        )
    })
}

/// Every joint and JPRIM kind between random markers of three random parts and the ground,
/// a translational and a rotational MOTION, and both springs: a system whose residual and
/// Newton matrix exercise every block. Positions are random, so constraints are violated.
pub(super) fn every_element_system(seed: u64, formulation: Formulation) -> MultibodySystem {
    let mut rng = Rng::new(seed);
    let mut builder = MultibodyBuilder::new(Vector3::new(0.1, -0.2, -9.81));
    builder.set_formulation(formulation);
    let parts: Vec<PartId> = (0..3)
        .map(|k| {
            builder
                .add_part(random_part(&mut rng, &format!("PART/{}", k + 2)))
                .unwrap()
        })
        .collect();
    let all = [PartId::GROUND, parts[0], parts[1], parts[2]];
    let mut ids = Vec::new();
    for (k, kind) in ConstraintKind::ALL.into_iter().enumerate() {
        let (a, b) = (all[1 + k % 3], all[(k + 2) % 4]);
        let (a, b) = if a == b { (a, PartId::GROUND) } else { (a, b) };
        let i = builder.add_marker(a, rng.pose(0.5)).unwrap();
        let j = builder.add_marker(b, rng.pose(0.5)).unwrap();
        ids.push((
            kind,
            builder
                .add_constraint(format!("JOINT/{k}"), kind, i, j)
                .unwrap(),
        ));
    }
    let find = |kind| {
        ids.iter()
            .find(|(k, _)| *k == kind)
            .map(|(_, id)| *id)
            .unwrap()
    };
    builder
        .add_motion(
            "MOTION/1",
            find(ConstraintKind::Translational),
            MotionDof::Translational,
            sine_drive(0.3, 2.0, 0.1),
        )
        .unwrap();
    builder
        .add_motion(
            "MOTION/2",
            find(ConstraintKind::Revolute),
            MotionDof::Rotational,
            sine_drive(0.5, 3.0, 7.0),
        )
        .unwrap();
    let params = SpringParams {
        stiffness: 50.0,
        damping: 3.0,
        free_length: 0.4,
        preload: 2.0,
    };
    builder
        .add_force(Box::new(
            TranslationalSpringDamper::new(
                "SPRING/1",
                parts[0],
                rng.vector(0.3),
                parts[1],
                rng.vector(0.3),
                params,
            )
            .unwrap(),
        ))
        .unwrap();
    builder
        .add_force(Box::new(
            RotationalSpringDamper::new(
                "SPRING/2",
                parts[2],
                rng.pose(0.3),
                parts[0],
                rng.pose(0.3),
                params,
            )
            .unwrap(),
        ))
        .unwrap();
    builder.build().unwrap()
}

/// A random state for `system`: builder positions with Euler parameters scaled off the unit
/// sphere by up to 1%, random multipliers (λ, μ and under SI2 η), and a random `y′`.
pub(super) fn random_state(system: &MultibodySystem, seed: u64) -> (DVector<f64>, DVector<f64>) {
    let mut rng = Rng::new(seed);
    let layout = system.layout();
    let mut y = system.initial_y.clone();
    for part in system.moving_parts() {
        let o = layout.position_offset(part) + 3;
        let scale = 1.0 + 0.01 * rng.signed();
        for i in 0..4 {
            y[o + i] *= scale;
        }
        y[layout.mu_offset(part)] = 0.1 * rng.signed();
    }
    for i in 0..layout.constraint_rows() {
        y[layout.lambda_offset() + i] = 10.0 * rng.signed();
        if layout.formulation() == Formulation::Si2 {
            y[layout.position_constraint_offset() + i] = 0.1 * rng.signed();
        }
    }
    let yp = DVector::from_fn(layout.size(), |_, _| rng.signed());
    (y, yp)
}
