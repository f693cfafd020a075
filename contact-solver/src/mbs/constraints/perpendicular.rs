//! JPRIM PERPENDICULAR: z_I stays perpendicular to z_J (1 equation).
//!
//! Equations in `primitives` terms, in row order.

use super::primitives::{Axis, Primitive};

/// The equations of this constraint, in row order.
pub(super) fn primitives() -> Vec<Primitive> {
    vec![Primitive::Perpendicular {
        axis_i: Axis::Z,
        axis_j: Axis::Z,
    }]
}
