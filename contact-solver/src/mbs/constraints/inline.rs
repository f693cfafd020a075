//! JPRIM INLINE: the I origin stays on the J z axis (2 equations).
//!
//! Equations in `primitives` terms, in row order.

use super::primitives::{Axis, Primitive};

/// The equations of this constraint, in row order.
pub(super) fn primitives() -> Vec<Primitive> {
    vec![
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
