//! Spring-damper force elements (Adams SPRINGDAMPER, translational and rotational).

mod rotational;
mod translational;

pub use rotational::RotationalSpringDamper;
pub use translational::TranslationalSpringDamper;

use super::error::MbsError;

/// Stiffness, damping, free length (or angle) and preload of a spring-damper.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpringParams {
    /// Stiffness `k ≥ 0` (force per length, or torque per radian).
    pub stiffness: f64,
    /// Damping `c ≥ 0` (force per velocity, or torque per angular velocity).
    pub damping: f64,
    /// The length (or angle, radians) at which the spring exerts only the preload; `≥ 0` for a
    /// translational spring, any finite value for a rotational one.
    pub free_length: f64,
    /// A constant force (or torque) added to the law; positive pushes the markers apart (turns
    /// I positively about z_J).
    pub preload: f64,
}

impl SpringParams {
    /// Checks every value is finite, `k ≥ 0`, `c ≥ 0`, and (when `length`) `free_length ≥ 0`.
    fn validate(&self, element: &str, length: bool) -> Result<(), MbsError> {
        let check = |argument: &'static str, value: f64, nonnegative: bool| {
            let ok = value.is_finite() && (!nonnegative || value >= 0.0);
            let allowed = if nonnegative {
                "finite and ≥ 0"
            } else {
                "finite"
            };
            if ok {
                Ok(())
            } else {
                Err(MbsError::invalid(element, argument, value, allowed))
            }
        };
        check("STIFFNESS", self.stiffness, true)?;
        check("DAMPING", self.damping, true)?;
        check("LENGTH", self.free_length, length)?;
        check("PRELOAD", self.preload, false)
    }
}
