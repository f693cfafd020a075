//! JPRIM INPLANE: the I origin stays in the J x-y plane (1 equation).
//!
//! Equations in `primitives` terms, in row order.

use super::primitives::{Axis, Primitive};

/// The equations of this constraint, in row order.
pub(super) fn primitives() -> Vec<Primitive> {
    vec![Primitive::InPlane {
        normal_j: Axis::Z,
        drive: None,
    }]
}
