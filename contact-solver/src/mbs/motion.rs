//! MOTIONs: rheonomic constraints that drive a joint's free translation or rotation in time, or
//! one relative coordinate of a marker pair.
//!
//! A rotation about one of J's axes is measured as the angle of the I axis that follows it
//! cyclically (y_I about x_J, z_I about y_J, x_I about z_J): the body-fixed angle B1, B2 or B3
//! while the other two rotations are held (by a joint or other MOTIONs), as Adams uses them.

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

/// Which relative coordinate of marker I against marker J a marker-pair MOTION drives
/// (Adams `MOTION/…, I =, J =, X | Y | Z | B1 | B2 | B3`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MarkerMotionAxis {
    /// The displacement of the I origin along J's x axis, `x_J · (p_I − p_J) = f(t)`.
    X,
    /// Along J's y axis.
    Y,
    /// Along J's z axis.
    Z,
    /// The rotation of I about J's x axis, `atan2(y_I·z_J, y_I·y_J) = f(t)` modulo 2π.
    B1,
    /// The rotation of I about J's y axis, `atan2(z_I·x_J, z_I·z_J) = f(t)` modulo 2π.
    B2,
    /// The rotation of I about J's z axis, `atan2(x_I·y_J, x_I·x_J) = f(t)` modulo 2π.
    B3,
}

impl MarkerMotionAxis {
    /// The axis of Adams' index 0..=5 (X, Y, Z, B1, B2, B3).
    pub fn from_index(index: u8) -> Option<Self> {
        [Self::X, Self::Y, Self::Z, Self::B1, Self::B2, Self::B3]
            .get(usize::from(index))
            .copied()
    }
}
