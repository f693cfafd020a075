//! MOTIONs: rheonomic constraints that drive a joint's free translation or rotation in time.

use std::sync::Arc;

/// A MOTION's time function: `t ↦ (f(t), f′(t), f″(t))`, value and first two derivatives.
/// The derivatives must be the exact derivatives of the value (they set the consistent
/// initial velocities and accelerations). Non-finite output stops the evaluation with an
/// error naming the MOTION.
pub type TimeFunction = Arc<dyn Fn(f64) -> (f64, f64, f64) + Send + Sync>;

/// Which free coordinate of a joint a MOTION drives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MotionDof {
    /// The displacement of the I origin along z_J, `z_J · (p_I − p_J) = f(t)`. Allowed on
    /// TRANSLATIONAL and CYLINDRICAL joints.
    Translational,
    /// The rotation of x_I about z_J measured from x_J, `atan2(x_I·y_J, x_I·x_J) = f(t)`
    /// modulo 2π (so f may run through any number of turns). Allowed on REVOLUTE and
    /// CYLINDRICAL joints.
    Rotational,
}
