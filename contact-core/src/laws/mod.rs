//! Force laws as pure functions of (penetration, rate, parameters), each with its partial
//! derivatives for the solver's Jacobian.
//!
//! Sign conventions (SPEC §5): δ ≥ 0 is the penetration and δ̇ its rate, positive while the
//! bodies approach. Normal forces are magnitudes ≥ 0 along the contact normal (J into I).
//! Friction follows Adams' signed μ(v), which already opposes the slip.
//!
//! User laws (NORMAL_ROUTINE, FRICTION_ROUTINE) are traits with a C ABI: [`UserNormalLaw`],
//! [`UserFrictionLaw`], [`UserContactAbi`].

mod friction;
mod normal;
mod slip_and_spin;
mod step;
mod user;

pub use friction::{CoulombFriction, CoulombParams, FrictionForce, FrictionTorque};
pub use normal::{
    AugmentedLagrangian, ImpactLaw, ImpactParams, NormalForce, PoissonLaw, PoissonParams,
};
pub use slip_and_spin::SlipAndSpin;
pub use step::{Smooth, Step, step, step5};
pub use user::{
    USER_ABI_VERSION, UserContact, UserContactAbi, UserFriction, UserFrictionLaw, UserLawError,
    UserNormalLaw, checked_friction, checked_normal_force,
};

#[cfg(test)]
mod tests;
