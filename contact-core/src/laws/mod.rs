//! Force laws as pure functions of (penetration, rate, parameters), each with its partial
//! derivatives for the solver's Jacobian.
//!
//! Sign conventions (SPEC §5): δ ≥ 0 is the penetration and δ̇ its rate, positive while the
//! bodies approach. Normal forces are magnitudes ≥ 0 along the contact normal (J into I).
//! Friction follows Adams' signed μ(v), which already opposes the slip.

mod friction;
mod normal;
mod step;

pub use friction::{CoulombFriction, FrictionForce, FrictionTorque};
pub use normal::{AugmentedLagrangian, ImpactLaw, NormalForce, PoissonLaw};
pub use step::{Smooth, Step, step, step5};

#[cfg(test)]
mod tests;
