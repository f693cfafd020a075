//! Box against a plane (bounded or not): exact convex clipping.
//!
//! The plane's solid is the prism `z ≤ 0` (`z ≥ 0` when flipped) over its `[XMIN, XMAX] ×
//! [YMIN, YMAX]` rectangle (infinite bounds drop their side). The box is clipped by the
//! prism's planes in the plane's frame ([`crate::polyhedron`]); from the intersection:
//! - contact iff its volume is positive;
//! - normal: the area-weighted outward normal of the prism's surface inside the box — the
//!   plane's normal for an unbounded plane, tilted when the box hangs over a bounded edge;
//!   when the box is wholly inside the prism that surface is empty, and the normal is the
//!   outward normal of the prism face nearest the centroid;
//! - points: where the line through the centroid along the normal leaves the prism (`+n`)
//!   and the box (`−n`); δ is their distance;
//! - area: the intersection's shadow on the plane normal to `n`.

use crate::kernel::PairContact;
use crate::polyhedron::ConvexPolyhedron;
use contact_core::geometry::{Cuboid, Plane};
use contact_core::{Isometry3, Point3, Vector3};

/// A bounding plane of a convex solid: `normal·x ≤ offset`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct HalfSpace {
    pub normal: Vector3,
    pub offset: f64,
}

/// Where the ray `origin + t·direction`, from inside the convex solid bounded by `planes`,
/// leaves it: the smallest `t ≥ 0` over the planes it heads towards (0 if none).
pub(crate) fn ray_exit(origin: &Point3, direction: &Vector3, planes: &[HalfSpace]) -> f64 {
    let mut best = f64::INFINITY;
    for h in planes {
        let rate = h.normal.dot(direction);
        if rate > 0.0 {
            best = best.min(((h.offset - h.normal.dot(&origin.coords)) / rate).max(0.0));
        }
    }
    if best.is_finite() { best } else { 0.0 }
}

/// The outward normal of the bounding plane nearest to the interior point `p`.
pub(crate) fn nearest_face_normal(p: &Point3, planes: &[HalfSpace]) -> Vector3 {
    let mut best = (f64::INFINITY, Vector3::z());
    for h in planes {
        let gap = h.offset - h.normal.dot(&p.coords);
        if gap < best.0 {
            best = (gap, h.normal);
        }
    }
    best.1
}

/// The planes of a box with centre `center` and unit axes `axes` (half extents `half`).
pub(crate) fn box_planes(center: &Point3, axes: &[Vector3; 3], half: &Vector3) -> [HalfSpace; 6] {
    let plane = |k: usize, s: f64| HalfSpace {
        normal: s * axes[k],
        offset: s * axes[k].dot(&center.coords) + half[k],
    };
    [
        plane(0, 1.0),
        plane(0, -1.0),
        plane(1, 1.0),
        plane(1, -1.0),
        plane(2, 1.0),
        plane(2, -1.0),
    ]
}

/// Contact of `cuboid` at `pose_box` with `plane` (flipped when `side < 0`) at `pose_plane`.
pub(crate) fn contact(
    cuboid: &Cuboid,
    pose_box: &Isometry3,
    plane: &Plane,
    side: f64,
    pose_plane: &Isometry3,
) -> Option<PairContact> {
    // Everything in the plane's frame P.
    let pose_pb = pose_plane.inv_mul(pose_box);
    let center = pose_pb * cuboid.center();
    let rotation = pose_pb.rotation.to_rotation_matrix();
    let unit_axes = [
        rotation.matrix().column(0).into_owned(),
        rotation.matrix().column(1).into_owned(),
        rotation.matrix().column(2).into_owned(),
    ];
    let half = cuboid.half_extents();
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
    let [x0, x1] = plane.x_range();
    let [y0, y1] = plane.y_range();
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
    for (bound, normal, finite) in [
        (x1, Vector3::x(), x1.is_finite()),
        (-x0, -Vector3::x(), x0.is_finite()),
        (y1, Vector3::y(), y1.is_finite()),
        (-y0, -Vector3::y(), y0.is_finite()),
    ] {
        if finite {
            prism[count] = HalfSpace {
                normal,
                offset: bound,
            };
            count += 1;
        }
    }
    let prism = &prism[..count];
    let mut poly = ConvexPolyhedron::cuboid(&center, &half_axes);
    for h in prism {
        poly.clip(&h.normal, h.offset);
    }
    let mass = poly.mass_properties();
    if mass.volume <= 0.0 {
        return None;
    }
    let c = mass.centroid;
    let s = mass.clipped_area_vector;
    let s_norm = s.norm();
    let normal = if s_norm > 0.0 {
        s / s_norm
    } else {
        nearest_face_normal(&c, prism)
    };
    let to_plane = ray_exit(&c, &normal, prism);
    let to_box = ray_exit(&c, &-normal, &box_planes(&center, &unit_axes, &half));
    let point_a = c - to_box * normal;
    let point_b = c + to_plane * normal;
    Some(PairContact {
        point_a: pose_plane * point_a,
        point_b: pose_plane * point_b,
        normal: pose_plane.rotation * normal,
        depth: to_plane + to_box,
        area: poly.projected_area(&normal),
    })
}
