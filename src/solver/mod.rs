//! The solver: the DAE interface between integrator and equations, and the multibody equations.

pub mod dae;
pub mod mbs;
