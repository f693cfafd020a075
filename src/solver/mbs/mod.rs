//! The multibody equations: rigid parts with joints, JPRIMs, MOTIONs and applied forces as an
//! index-3 (I3) or stabilized index-2 (SI2, [`Formulation`]) DAE for the integrator
//! ([`crate::solver::dae::DaeSystem`]).
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
//!
//! Sign convention: the constraint reaction on the parts is `−Φ_vᵀλ`
//! ([`MultibodySystem::constraint_reactions`]).

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
mod quaternion;
mod residual;
mod springs;
mod system;

#[cfg(test)]
mod tests;

pub use builder::{ConstraintId, MultibodyBuilder};
pub use constraints::ConstraintKind;
pub use error::MbsError;
pub use force::{
    ForceElement, Load, PartState, StateView, difference_partials, point_pair_partials,
};
pub use initial::InitialState;
pub use layout::{Formulation, StateLayout};
pub use motion::{MotionDof, TimeFunction};
pub use part::{MarkerId, PartId, PartSpec};
pub use springs::{RotationalSpringDamper, SpringParams, TranslationalSpringDamper};
pub use system::MultibodySystem;
