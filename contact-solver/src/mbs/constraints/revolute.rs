//! REVOLUTE joint: the origins coincide and z_I stays parallel to z_J (5 equations); the one
//! free rotation is about the common z axis.
//!
//! Equations in `primitives` terms, in row order.

use super::primitives::{Axis, Primitive};

/// The equations of this constraint, in row order.
pub(super) fn primitives() -> Vec<Primitive> {
    vec![
        Primitive::Coincident(0),
        Primitive::Coincident(1),
        Primitive::Coincident(2),
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
