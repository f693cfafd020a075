//! SPHERICAL joint: the I and J origins coincide (3 equations, 3 rotations free).
//!
//! Equations in `primitives` terms, in row order.

use super::primitives::Primitive;

/// The equations of this constraint, in row order.
pub(super) fn primitives() -> Vec<Primitive> {
    vec![
        Primitive::Coincident(0),
        Primitive::Coincident(1),
        Primitive::Coincident(2),
    ]
}
