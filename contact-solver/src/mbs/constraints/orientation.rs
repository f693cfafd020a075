//! JPRIM ORIENTATION: the I axes stay aligned with the J axes (3 equations); translation
//! is free.
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
        Primitive::Perpendicular {
            axis_i: Axis::X,
            axis_j: Axis::Y,
        },
    ]
}
