//! FIXED joint: the origins coincide and the axes stay aligned (6 equations).
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
        Primitive::Perpendicular {
            axis_i: Axis::X,
            axis_j: Axis::Y,
        },
    ]
}
