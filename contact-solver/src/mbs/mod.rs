//! The multibody equations: rigid parts with joints, JPRIMs, MOTIONs and applied forces as an
//! index-3 (I3) or stabilized index-2 (SI2, [`Formulation`]) DAE for the integrator
//! ([`crate::dae::DaeSystem`]).
//!
//! Formulation (solver-notes §2.3): Cartesian coordinates per part — CM position `r`, Euler
//! parameters `e` (unit quaternion, with a normalization multiplier μ), CM velocity `u` and
//! body-frame angular velocity ω′ — and Lagrange multipliers λ for the constraints. The state
//! layout is [`StateLayout`]; the equations are on [`MultibodySystem`].
//!
//! - [`MultibodyBuilder`]: parts ([`PartSpec`]), markers, joints and JPRIMs
//!   ([`ConstraintKind`]), MOTIONs ([`MotionDof`], [`TimeFunction`]), force elements.
//! - `constraints/`: one file per joint type, each a list of four primitive equations with
//!   analytic Jacobians.
//! - [`ForceElement`]: what SFORCEs, springs and contacts implement; [`TranslationalSpringDamper`]
//!   and [`RotationalSpringDamper`] are two.
//! - [`MultibodySystem::compute_residual`] / [`MultibodySystem::compute_newton_matrix`]: the
//!   DAE and its Newton matrix, assembled by blocks.
//! - [`MultibodySystem::compute_initial_state`]: assembly, consistent velocities, initial
//!   accelerations and multipliers.
//! - [`MultibodySystem::redundant_equations`]: the equations the builder removed as redundant
//!   at the given configuration (`redundancy` module: column-pivoted QR of the constraint
//!   Jacobian); assembly refuses an inconsistent redundancy naming the elements.
//!
//! Sign convention: the constraint reaction on the parts is `−Φ_vᵀλ`
//! ([`MultibodySystem::constraint_reactions`]).
//!
//! ## Example: what an integrator sees
//! A block on a spring, sliding along world x on a TRANSLATIONAL joint. The consistent start
//! makes the residual vanish; one implicit-Euler Newton step uses the Newton matrix.
//! ```
//! use contact_solver::dae::DaeSystem;
//! use contact_solver::mbs::*;
//! use nalgebra::{DMatrix, DVector, Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};
//!
//! let mut builder = MultibodyBuilder::new(Vector3::new(0.0, 0.0, -9.81));
//! let pose = Isometry3::translation(1.1, 0.0, 0.0);
//! let block = builder.add_part(PartSpec::at_rest("PART/2", 2.0, Matrix3::identity() * 0.01, pose))?;
//! // Joint markers with z along world x (the sliding direction).
//! let along_x = Isometry3::from_parts(
//!     Translation3::identity(),
//!     UnitQuaternion::from_scaled_axis(Vector3::new(0.0, std::f64::consts::FRAC_PI_2, 0.0)),
//! );
//! let i = builder.add_marker(block, along_x)?;
//! let j = builder.add_marker(PartId::GROUND, along_x)?;
//! builder.add_constraint("JOINT/1", ConstraintKind::Translational, i, j)?;
//! let params = SpringParams { stiffness: 800.0, damping: 0.0, free_length: 1.0, preload: 0.0 };
//! builder.add_force(Box::new(TranslationalSpringDamper::new(
//!     "SPRING/1", block, Vector3::zeros(), PartId::GROUND, Vector3::zeros(), params,
//! )?))?;
//! let mut system = builder.build()?;
//!
//! let start = system.compute_initial_state(0.0)?;
//! let n = system.size(); // 14 per part + 5 joint rows
//! assert_eq!(n, 19);
//! let mut residual = DVector::zeros(n);
//! system.residual(0.0, &start.y, &start.yp, &mut residual)?;
//! assert!(residual.amax() < 1e-9);
//! // The spring pulls back with k·0.1 = 80 N: the initial acceleration is −40 m/s² along x.
//! let x_acceleration = start.yp[system.layout().velocity_offset(block)];
//! assert!((x_acceleration + 40.0).abs() < 1e-9);
//!
//! // One implicit-Euler step of h: y′ = (y − y₀)/h, Newton matrix ∂F/∂y + (1/h)·∂F/∂y′.
//! let h = 1e-3;
//! let (mut y, mut matrix) = (start.y.clone(), DMatrix::zeros(n, n));
//! for _ in 0..4 {
//!     let yp = (&y - &start.y) / h;
//!     system.residual(h, &y, &yp, &mut residual)?;
//!     system.newton_matrix(h, &y, &yp, 1.0 / h, &mut matrix)?;
//!     let step = matrix.clone().lu().solve(&(-&residual)).expect("nonsingular");
//!     y += step;
//! }
//! // The block moved back by about a·h² (implicit Euler: a·h²/(1 + ω²h²)).
//! let moved = y[0] - 1.1;
//! assert!((moved + 40.0 * h * h / (1.0 + 400.0 * h * h)).abs() < 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod builder;
mod constraints;
mod error;
mod force;
mod initial;
mod jacobian;
mod jacobian_constraints;
mod layout;
mod motion;
mod part;
pub(crate) mod quaternion;
mod redundancy;
mod residual;
mod springs;
mod system;

#[cfg(test)]
mod tests;

pub use builder::{ConstraintId, MultibodyBuilder};
pub use constraints::ConstraintKind;
pub use error::MbsError;
pub use force::{
    ForceElement, ForcePartials, Load, PartState, StateView, difference_partials,
    point_pair_partials,
};
pub use initial::InitialState;
pub use layout::{Formulation, StateLayout};
pub use motion::{MarkerMotionAxis, MotionDof, TimeFunction};
pub use part::{MarkerId, PartId, PartSpec};
pub use redundancy::{CONSISTENCY_TOLERANCE, RANK_TOLERANCE, RedundantEquation};
pub use springs::{RotationalSpringDamper, SpringParams, TranslationalSpringDamper};
pub use system::{MultibodySystem, SPARSE_FROM_SIZE};
