//! The solver: the integrator and the interface to the equations it integrates.
//!
//! - [`dae`]: [`DaeSystem`], the implicit DAE `F(t, y, y′) = 0` the multibody equations
//!   implement, with [`VariableKind`] and [`EvaluationError`].
//! - [`bdf`]: the GSTIFF-style variable-step, variable-order BDF integrator that solves it,
//!   step by step, with the hooks contact prediction needs.

pub mod bdf;
pub mod dae;

pub use dae::{DaeSystem, EvaluationError, VariableKind};
