//! 2-D pairs, computed in the plane of the second (canonical) geometry `b`.
//!
//! Both geometries lie in the x-y planes of their frames. Each query first checks the two
//! planes coincide — the angle between their normals (either orientation: a marker whose z
//! axis is reversed still spans the same plane) at most [`PLANE_ANGLE_TOLERANCE`] rad, and
//! `a`'s origin within `PLANE_OFFSET_TOLERANCE · L` of `b`'s plane, `L` the pair's length
//! scale — and otherwise reports [`QueryError::OutOfPlane`](contact_core::QueryError).
//! Results are mapped back to the world with `b`'s pose (normals have no z component in `b`).
//!
//! The 2-D "area" of a contact is a length: the intersection region's extent across the
//! normal.

pub(crate) mod arc;
pub(crate) mod boundary;
pub(crate) mod circle_bounded_line;
pub(crate) mod circles;
pub(crate) mod closest;
pub(crate) mod crossings;
pub(crate) mod curve_eval;
pub(crate) mod overlap;
pub(crate) mod point_curve;
pub(crate) mod point_line;

use crate::kernel::PairError;
use contact_core::{Isometry3, Point2, Point3, Vector2, Vector3};

use contact_core::geometry::plane_departure;
pub use contact_core::geometry::{PLANE_ANGLE_TOLERANCE, PLANE_OFFSET_TOLERANCE};

/// The first geometry's origin expressed in the second geometry's plane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct InPlane<'a> {
    /// `a`'s origin in `b`'s frame (x, y).
    pub origin_a: Point2,
    /// `X_WGb`.
    pub pose_b: &'a Isometry3,
}

impl<'a> InPlane<'a> {
    /// Checks `a` and `b` share a plane and expresses `a`'s origin in `b`'s frame.
    pub fn new(pose_a: &Isometry3, pose_b: &'a Isometry3, length: f64) -> Result<Self, PairError> {
        let relative = pose_b.inv_mul(pose_a);
        if let Some((angle_rad, offset)) = plane_departure(&relative, length) {
            return Err(PairError::OutOfPlane { angle_rad, offset });
        }
        let t = relative.translation.vector;
        Ok(Self {
            origin_a: Point2::new(t.x, t.y),
            pose_b,
        })
    }

    /// A point of `b`'s plane, in the world.
    pub fn point_w(&self, p: &Point2) -> Point3 {
        self.pose_b * Point3::new(p.x, p.y, 0.0)
    }

    /// A direction of `b`'s plane, in the world.
    pub fn vector_w(&self, v: &Vector2) -> Vector3 {
        self.pose_b.rotation * Vector3::new(v.x, v.y, 0.0)
    }
}
