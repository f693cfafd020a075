//! Box against a plane (bounded or not): exact convex clipping.
//!
//! An unbounded plane takes a shorter path with the same answer: the part of the box below
//! the plane in closed form from the corner heights ([`half_space`]); a bounded
//! plane's prism clips the box as a [`ConvexPolyhedron`].
//!
//! The plane's solid is the prism `z ≤ 0` (`z ≥ 0` when flipped) over its `[XMIN, XMAX] ×
//! [YMIN, YMAX]` rectangle (infinite bounds drop their side). The box is clipped by the
//! prism's planes in the plane's frame ([`crate::polyhedron`]); contact iff the intersection
//! has positive volume. Normal, points, depth and area follow [`crate::methods::clipped`]: for an
//! unbounded plane the normal is the plane's; over a bounded plane's edge it tilts towards
//! the side face inside the box; a box wholly under the plane takes the plane's normal. The
//! points lie on the line through the centroid along the normal.

mod half_space;
use crate::kernel::PairContact;
use crate::methods::clipped::{self, HalfSpace, box_planes, unit_for};
use crate::polyhedron::ConvexPolyhedron;
use contact_core::geometry::{Cuboid, Plane};
use contact_core::{Isometry3, Vector3};

/// Contact of `cuboid` at `pose_box` with `plane` (flipped when `side < 0`) at `pose_plane`.
// Inline, as is the unbounded path inside: each returned copy of the contact left between
// them is read back before its stores retire (a sixth of the query's time, measured).
#[inline]
pub(crate) fn contact(
    cuboid: &Cuboid,
    pose_box: &Isometry3,
    plane: &Plane,
    side: f64,
    pose_plane: &Isometry3,
) -> Option<PairContact> {
    if plane.is_unbounded() {
        return half_space::contact(cuboid, pose_box, side, pose_plane);
    }
    bounded(cuboid, pose_box, plane, side, pose_plane)
}

/// The bounded plane's prism clipping the box as a polyhedron, in the plane's frame. Out of
/// line, so the unbounded path stays small enough to inline.
#[inline(never)]
fn bounded(
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
    // Up to five planes: at most 11 faces; a box face gains one vertex per plane.
    let mut poly = ConvexPolyhedron::<11, 12>::cuboid(&center, &half_axes);
    clipped::contact(
        &mut poly,
        &planes_box,
        &prism[..count],
        &prism[..1],
        pose_plane,
        unit,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::UnitQuaternion;

    /// The unbounded plane's short path against the general clipping (a bounded plane far
    /// wider than the box), over tilts, depths up to full immersion and both sides.
    #[test]
    fn the_half_space_path_agrees_with_general_clipping() {
        let cuboid = Cuboid::centered(0.7, 0.4, 1.1).unwrap();
        let wide = Plane::bounded(-1e3, 1e3, -1e3, 1e3).unwrap();
        let plane_pose = Isometry3::new(Vector3::new(0.3, -0.2, 0.1), Vector3::new(0.1, 0.2, -0.3));
        let mut compared = 0;
        for k in 0..200 {
            let t = k as f64;
            let q = UnitQuaternion::from_euler_angles(0.37 * t, 0.91 * t, 0.13 * t);
            let z = -2.0 + 4.0 * ((0.618 * t) % 1.0);
            let pose_box = plane_pose * Isometry3::from_parts(Vector3::new(0.1, 0.2, z).into(), q);
            for side in [1.0, -1.0] {
                let short = contact(&cuboid, &pose_box, &Plane::unbounded(), side, &plane_pose);
                let general = contact(&cuboid, &pose_box, &wide, side, &plane_pose);
                match (short, general) {
                    (None, None) => {}
                    (Some(a), Some(b)) => {
                        compared += 1;
                        assert!((a.point_a - b.point_a).norm() < 1e-12, "{a:?} {b:?}");
                        assert!((a.point_b - b.point_b).norm() < 1e-12, "{a:?} {b:?}");
                        assert!((a.normal - b.normal).norm() < 1e-12, "{a:?} {b:?}");
                        assert!((a.depth - b.depth).abs() < 1e-12, "{a:?} {b:?}");
                        assert!((a.area - b.area).abs() < 1e-12, "{a:?} {b:?}");
                    }
                    other => panic!("{other:?}"),
                }
            }
        }
        assert!(compared > 150, "{compared}");
    }
}
