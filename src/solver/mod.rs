//! The solver: the integrator, the equations it integrates, and the interface between them.
//!
//! - [`dae`] — [`DaeSystem`], the implicit DAE `F(t, y, y′) = 0` the multibody equations
//!   implement, with [`VariableKind`] and [`EvaluationError`].
//! - [`bdf`] — the GSTIFF-style variable-step, variable-order BDF integrator that solves it,
//!   step by step, with the hooks contact prediction needs.
//! - [`mbs`] — the multibody equations: parts, joints, JPRIMs, MOTIONs and force elements as an
//!   index-3 (or stabilized index-2) DAE.

pub mod bdf;
pub mod dae;
pub mod mbs;

pub use dae::{DaeSystem, EvaluationError, VariableKind};
