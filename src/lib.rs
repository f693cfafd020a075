//! # contact: compliant contact in rigid multibody simulation
//!
//! The application package of the workspace: it composes the geometry engines of
//! `engine-exact` and `engine-facet` (behind `contact_core::GeometryEngine`) with a multibody
//! solver. Modules:
//!
//! - [`solver`]: the DAE interface ([`solver::dae`]) and the multibody equations
//!   ([`solver::mbs`]): parts, joints, JPRIMs, MOTIONs and force elements as an index-3 DAE.
//!
//! ## Example: the initial tension of a pendulum
//! ```
//! use contact::solver::mbs::{ConstraintKind, MultibodyBuilder, PartSpec, PartId};
//! use nalgebra::{Isometry3, Matrix3, Vector3};
//!
//! // A 2 kg point-like bob hanging 1 m below a revolute joint on ground, at rest.
//! let mut builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -9.81));
//! let pose = Isometry3::translation(0.0, 0.0, -1.0);
//! let bob = builder.add_part(PartSpec::at_rest("bob", 2.0, Matrix3::identity() * 1e-3, pose))?;
//! let pivot_on_bob = builder.add_marker(bob, Isometry3::translation(0.0, 0.0, 1.0))?;
//! let pivot_on_ground = builder.add_marker(PartId::GROUND, Isometry3::identity())?;
//! builder.add_constraint("JOINT/1", ConstraintKind::Revolute, pivot_on_bob, pivot_on_ground)?;
//! let system = builder.build()?;
//! let start = system.compute_initial_state(0.0)?;
//! // The joint holds the bob's weight. The reaction on the bob is −Φ_rᵀλ, and Φ_r = I for the
//! // joint's point rows, so λ_z is minus the 19.62 N the joint pulls up with.
//! let lambda_z = start.y[system.layout().lambda_offset() + 2];
//! assert!((lambda_z + 2.0 * 9.81).abs() < 1e-9);
//! # Ok::<(), contact::solver::mbs::MbsError>(())
//! ```
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod solver;
