//! TRANSLATIONAL joint: a CYLINDRICAL joint whose rotation about z is also locked
//! (x_I ⊥ y_J; 5 equations); translation along z_J is free.
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
