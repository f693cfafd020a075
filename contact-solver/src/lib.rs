//! # contact-solver: the multibody solver of `contact`
//!
//! The integrator, the equations it integrates, and the interface between them. It knows
//! parts, joints, force elements and CONTACTs (through [`contact_core`]'s engine trait), not
//! datasets: the Adams layer (`contact-adams`) lowers a model onto it.
//!
//! - [`dae`] — [`DaeSystem`], the implicit DAE `F(t, y, y′) = 0` the multibody equations
//!   implement, with [`VariableKind`] and [`EvaluationError`].
//! - [`bdf`] — the GSTIFF-style variable-step, variable-order BDF integrator that solves it,
//!   step by step, with the hooks contact prediction needs.
//! - [`broad_phase`] — which force elements can act: far contacts are not evaluated.
//! - [`mbs`] — the multibody equations: parts, joints, JPRIMs, MOTIONs and force elements as an
//!   index-3 (or stabilized index-2) DAE.
//! - [`contact_force`] — a CONTACT as a force element: engine kinematics and force laws.
//! - [`contact_partials`] — a CONTACT's partials for the Newton matrix from one query.
//! - [`contact_multipliers`] — AUGMENTED_LAGRANGIAN_FORMULATION's multipliers and update.
//! - [`contact_plane`] — the check that keeps both parts of a 2-D contact in one plane.
//! - [`frame`] — output frames from a state; a state handed to the next analysis.
//! - [`kinematics`] — kinematic analysis of a model with zero degrees of freedom.
//! - [`linear`] — linearization about an operating point: reduced M, C, K and the eigenvalues.
//! - [`parallel`] — force elements evaluated on several threads with serial-identical bits.
//! - [`simulate`] — transient dynamics with contact prediction and output frames.
//! - [`statics`] — static equilibrium: Newton on the static residual, and the quasi-dynamic
//!   method.

#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod bdf;
pub mod broad_phase;
pub mod contact_force;
pub mod contact_multipliers;
pub mod contact_partials;
pub mod contact_plane;
pub mod dae;
pub mod frame;
pub mod kinematics;
pub mod linear;
pub mod mbs;
pub mod parallel;
pub mod simulate;
pub mod statics;

pub use dae::{DaeSystem, EvaluationError, NewtonStorage, VariableKind};
