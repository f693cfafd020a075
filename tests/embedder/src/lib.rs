//! # An embedder's first hour, compiled
//!
//! What a simulator that embeds `contact` writes first, against contact-core and the two engines
//! only (no solver, no Adams layer): pick an engine by name, prepare a pair of geometries once,
//! query it at the bodies' poses from its own threads, and turn each contact into a force with
//! the bodies' velocities. The workspace builds and tests this crate, so the path keeps
//! compiling and keeps its answers.
//!
//! ```
//! use contact_core::geometry::Plane;
//! use contact_core::laws::{ImpactLaw, ImpactParams};
//! use contact_core::{
//!     BodyMotion, FacetingTolerance, Geometry, GeometryInstance, GeometryLibrary, Isometry3,
//!     Vector3, WorkCounters,
//! };
//!
//! let engine = contact_embedder::engine("PARASOLID".parse()?, FacetingTolerance::DEFAULT);
//! let ball = GeometryInstance::new(Geometry::sphere(0.5)?);
//! let ground = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
//! let pair = engine.prepare(&[ball], &[ground])?;
//!
//! // The ball 0.01 deep, falling at 2 m/s; the ground at rest.
//! let falling = BodyMotion {
//!     pose_w: Isometry3::translation(0.0, 0.0, 0.49),
//!     velocity_w: Vector3::new(0.0, 0.0, -2.0),
//!     angular_velocity_w: Vector3::zeros(),
//! };
//! let ground = BodyMotion::at_rest(Isometry3::identity());
//! let mut contacts = Vec::new();
//! pair.query(&falling.pose_w, &ground.pose_w, &mut contacts, &mut WorkCounters::default())?;
//! let impact = ImpactLaw::from_params(ImpactParams {
//!     stiffness: 1e7,
//!     exponent: 1.5,
//!     damping: 1e3,
//!     max_penetration: 1e-3,
//! })?;
//! let load = contact_embedder::contact_load(&contacts[0], &falling, &ground, &impact, None);
//! assert_eq!(load.kinematics.penetration_rate, 2.0);
//! // Spring 1e7·0.01^1.5 plus full damping 1e3·2 (past DMAX), pushing the ball up.
//! let expected = 1e7 * 0.01_f64.powf(1.5) + 1e3 * 2.0;
//! assert!((load.force_w.z - expected).abs() < 1e-9 * expected);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

use contact_core::laws::{CoulombFriction, ImpactLaw};
use contact_core::{
    BodyMotion, Contact, ContactKinematics, FacetingTolerance, GeometryEngine, GeometryLibrary,
    Vector3,
};

/// The engine for `library` (from [`GeometryLibrary::parse`]: exact, faceted, or an Adams
/// name), the faceted one at the model-wide faceting `tolerance`. An embedder that depends on
/// both engines picks one here, once; everything after sees a `dyn GeometryEngine`.
pub fn engine(library: GeometryLibrary, tolerance: FacetingTolerance) -> Box<dyn GeometryEngine> {
    match library {
        GeometryLibrary::Exact => Box::new(engine_exact::ExactEngine),
        GeometryLibrary::Faceted => Box::new(engine_facet::FacetEngine::new(tolerance)),
    }
}

/// What one contact does to body I (body J gets the opposite force and torque).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLoad {
    /// The contact's rates, and the point `p` where the force acts (world frame).
    pub kinematics: ContactKinematics,
    /// The normal force magnitude `Fn ≥ 0`.
    pub normal_force: f64,
    /// The force on I at `p`: `Fn·n + F_t`, world frame.
    pub force_w: Vector3,
    /// The friction torque on I about the normal, `T·n`, world frame.
    pub torque_w: Vector3,
}

/// The IMPACT force and, with `friction`, the Coulomb friction force and torque of `contact`
/// between I moving as `body_i` and J moving as `body_j`, as the solver evaluates a CONTACT:
/// `Fn = impact(δ, δ̇)` and `(F_t, T) = friction.slip_and_spin(v_t, ω_n, Fn, A)` with δ̇,
/// v_t, ω_n from [`ContactKinematics::compute`].
pub fn contact_load(
    contact: &Contact,
    body_i: &BodyMotion,
    body_j: &BodyMotion,
    impact: &ImpactLaw,
    friction: Option<&CoulombFriction>,
) -> ContactLoad {
    let kinematics = ContactKinematics::compute(contact, body_i, body_j);
    let normal_force = impact
        .force(contact.penetration, kinematics.penetration_rate)
        .force;
    let (friction_force, torque) = match friction {
        Some(law) => {
            let both = law.slip_and_spin(
                &kinematics.slip_velocity_w,
                kinematics.spin,
                normal_force,
                contact.area,
            );
            (both.force.force, both.torque.torque)
        }
        None => (Vector3::zeros(), 0.0),
    };
    ContactLoad {
        kinematics,
        normal_force,
        force_w: contact.normal_w * normal_force + friction_force,
        torque_w: contact.normal_w * torque,
    }
}

#[cfg(test)]
mod tests;
