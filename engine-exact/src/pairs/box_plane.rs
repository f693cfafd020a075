//! Box against a plane (bounded or not): exact convex clipping.
//!
//! The plane's solid is the prism `z ≤ 0` (`z ≥ 0` when flipped) over its `[XMIN, XMAX] ×
//! [YMIN, YMAX]` rectangle (infinite bounds drop their side). The box is clipped by the
//! prism's planes in the plane's frame ([`crate::polyhedron`]); contact iff the intersection
//! has positive volume. Normal, points, depth and area follow [`super::clipped`]: for an
//! unbounded plane the normal is the plane's; over a bounded plane's edge it tilts towards
//! the side face inside the box; a box wholly under the plane takes the plane's normal. The
//! point on the plane is always the foot of the centroid on the plane itself.

use super::clipped::{self, HalfSpace, box_planes, unit_for};
use crate::kernel::PairContact;
use crate::polyhedron::ConvexPolyhedron;
use contact_core::geometry::{Cuboid, Plane};
use contact_core::{Isometry3, Vector3};

/// Contact of `cuboid` at `pose_box` with `plane` (flipped when `side < 0`) at `pose_plane`.
pub(crate) fn contact(
    cuboid: &Cuboid,
    pose_box: &Isometry3,
    plane: &Plane,
    side: f64,
    pose_plane: &Isometry3,
) -> Option<PairContact> {
    // Working frame: the plane's frame, lengths divided by `unit`.
    let unit = unit_for(cuboid.half_extents().norm());
    let pose_pb = pose_plane.inv_mul(pose_box);
    let center = (pose_pb * cuboid.center()) / unit;
    let rotation = pose_pb.rotation.to_rotation_matrix();
    let m = rotation.matrix();
    let unit_axes = [
        m.column(0).into_owned(),
        m.column(1).into_owned(),
        m.column(2).into_owned(),
    ];
    let half = cuboid.half_extents() / unit;
    let half_axes = [
        unit_axes[0] * half.x,
        unit_axes[1] * half.y,
        unit_axes[2] * half.z,
    ];
    // The box's extent along each axis of P: a cheap rejection before clipping.
    let extent = half_axes[0].abs() + half_axes[1].abs() + half_axes[2].abs();
    if side * center.z - extent.z >= 0.0 {
        return None;
    }
    let [x0, x1] = plane.x_range().map(|x| x / unit);
    let [y0, y1] = plane.y_range().map(|y| y / unit);
    if center.x + extent.x <= x0
        || center.x - extent.x >= x1
        || center.y + extent.y <= y0
        || center.y - extent.y >= y1
    {
        return None;
    }
    let mut prism = [HalfSpace {
        normal: Vector3::new(0.0, 0.0, side),
        offset: 0.0,
    }; 5];
    let mut count = 1;
    for (offset, normal) in [
        (x1, Vector3::x()),
        (-x0, -Vector3::x()),
        (y1, Vector3::y()),
        (-y0, -Vector3::y()),
    ] {
        if offset.is_finite() {
            prism[count] = HalfSpace { normal, offset };
            count += 1;
        }
    }
    let planes_box = box_planes(&center, &unit_axes, &half);
    if count == 1 {
        // One cutting plane: at most 7 faces of at most 6 vertices.
        let poly = ConvexPolyhedron::<7, 6>::cuboid(&center, &half_axes);
        clipped::contact(
            poly,
            &planes_box,
            &prism[..count],
            &prism[..1],
            pose_plane,
            unit,
        )
    } else {
        // Up to five planes: at most 11 faces; a box face gains one vertex per plane.
        let poly = ConvexPolyhedron::<11, 12>::cuboid(&center, &half_axes);
        clipped::contact(
            poly,
            &planes_box,
            &prism[..count],
            &prism[..1],
            pose_plane,
            unit,
        )
    }
}
