//! UNIVERSAL joint: the origins coincide and z_I stays perpendicular to z_J (4 equations);
//! the two free rotations are about z_I and z_J, the cross-pin axes. (Adams' UNIVERSAL
//! convention, recalled from memory: UNCONFIRMED in `reference/adams-reference.md` §7.12.)
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
            axis_j: Axis::Z,
        },
    ]
}
