//! HOOKE joint: the origins coincide and x_I stays perpendicular to y_J (4 equations); the
//! cross-pin axes are x_I and y_J. (Adams' HOOKE convention, recalled from memory:
//! UNCONFIRMED in `reference/adams-reference.md` §7.12; Chrono calls it a universal joint.)
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
            axis_i: Axis::X,
            axis_j: Axis::Y,
        },
    ]
}
