//! JPRIM PARALLEL_AXES: z_I stays parallel to z_J (2 equations).
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
    ]
}
