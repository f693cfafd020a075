//! CYLINDRICAL joint: z_I stays parallel to z_J and the I origin stays on the J z axis
//! (4 equations); translation along and rotation about the common axis are free.
//!
//! Equations in `primitives` terms, in row order.

use super::primitives::{Axis, Primitive};

/// The equations of this constraint, in row order.
pub(super) fn primitives() -> Vec<Primitive> {
    vec![
        Primitive::Perpendicular {
            axis_i: Axis::Z,
            axis_j: Axis::X,
        },
        Primitive::Perpendicular {
            axis_i: Axis::Z,
            axis_j: Axis::Y,
        },
        Primitive::InPlane {
            normal_j: Axis::X,
            drive: None,
        },
        Primitive::InPlane {
            normal_j: Axis::Y,
            drive: None,
        },
    ]
}
