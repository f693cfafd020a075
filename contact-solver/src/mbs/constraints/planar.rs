//! PLANAR joint: the I origin stays in the J x-y plane and z_I stays parallel to z_J
//! (3 equations); in-plane translation and rotation about z are free.
//!
//! Equations in `primitives` terms, in row order.

use super::primitives::{Axis, Primitive};

/// The equations of this constraint, in row order.
pub(super) fn primitives() -> Vec<Primitive> {
    vec![
        Primitive::InPlane {
            normal_j: Axis::Z,
            drive: None,
        },
        Primitive::Perpendicular {
            axis_i: Axis::Z,
            axis_j: Axis::X,
        },
        Primitive::Perpendicular {
            axis_i: Axis::Z,
            axis_j: Axis::Y,
        },
    ]
}
