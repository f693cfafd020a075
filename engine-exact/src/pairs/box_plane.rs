//! Box against a plane (bounded or not): exact convex clipping.
//!
//! An unbounded plane takes a shorter path with the same answer: the box's six faces clipped
//! by the one plane and summed from a point on the plane (see `half_space`); a bounded plane's
//! prism clips the box as a [`ConvexPolyhedron`].
//!
//! The plane's solid is the prism `z ≤ 0` (`z ≥ 0` when flipped) over its `[XMIN, XMAX] ×
//! [YMIN, YMAX]` rectangle (infinite bounds drop their side). The box is clipped by the
//! prism's planes in the plane's frame ([`crate::polyhedron`]); contact iff the intersection
//! has positive volume. Normal, points, depth and area follow [`super::clipped`]: for an
//! unbounded plane the normal is the plane's; over a bounded plane's edge it tilts towards
//! the side face inside the box; a box wholly under the plane takes the plane's normal. The
//! points lie on the line through the centroid along the normal.

use super::clipped::{self, HalfSpace, box_planes, unit_for};
use crate::kernel::PairContact;
use crate::polyhedron::ConvexPolyhedron;
use contact_core::geometry::{Cuboid, Plane};
use contact_core::{Isometry3, Point3, Vector3};

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
        half_space(&center, &half_axes, &planes_box, side, pose_plane, unit)
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

/// Corners `c + Σ ±A_k`, index bit `k` set for `+A_k`; faces as corner indices,
/// counter-clockwise seen from outside: +x, −x, +y, −y, +z, −z.
const FACES: [[usize; 4]; 6] = [
    [1, 3, 7, 5],
    [0, 4, 6, 2],
    [2, 6, 7, 3],
    [0, 1, 5, 4],
    [4, 5, 7, 6],
    [0, 2, 3, 1],
];

/// The box (centre `center`, half-axes `half_axes`, in the plane's frame and working units)
/// against the half-space `side·z ≤ 0`. By the divergence theorem with tetrahedra from a point
/// `o` on the plane (the deepest corner's foot), the flat cap contributes nothing to the volume and its moment, so only
/// the box's faces clipped by the plane are summed (no cap polygon is built); their area vector
/// `S` is minus the cap's, and `|S|` is the area. The rest follows [`clipped`]: normal the
/// plane's, points where the line through the centroid along the normal leaves the box and
/// meets the plane.
fn half_space(
    center: &Point3,
    half_axes: &[Vector3; 3],
    planes_box: &[HalfSpace; 6],
    side: f64,
    pose_plane: &Isometry3,
    unit: f64,
) -> Option<PairContact> {
    // Corners, and heights along the outward normal.
    let mut corners = [Vector3::zeros(); 8];
    let mut height = [0.0; 8];
    let mut deepest = 0;
    for (k, (corner, h)) in corners.iter_mut().zip(height.iter_mut()).enumerate() {
        let sign = |bit: usize| if k & (1 << bit) != 0 { 1.0 } else { -1.0 };
        *corner = center.coords
            + sign(0) * half_axes[0]
            + sign(1) * half_axes[1]
            + sign(2) * half_axes[2];
        *h = side * corner.z;
    }
    for k in 1..8 {
        if height[k] < height[deepest] {
            deepest = k;
        }
    }
    // The origin o of the tetrahedra: the deepest corner's foot on the plane, so a sliver's
    // sums keep their relative precision.
    let origin = Vector3::new(corners[deepest].x, corners[deepest].y, 0.0);
    for corner in &mut corners {
        *corner -= origin;
    }
    let (mut six_volume, mut moment, mut area_vector) = (0.0, Vector3::zeros(), Vector3::zeros());
    for face in &FACES {
        let mut poly = [Vector3::zeros(); 5];
        let mut len = 0;
        for k in 0..4 {
            let (i, j) = (face[k], face[(k + 1) % 4]);
            let (hp, hq) = (height[i], height[j]);
            if hp <= 0.0 {
                poly[len] = corners[i];
                len += 1;
            }
            if (hp < 0.0 && hq > 0.0) || (hp > 0.0 && hq < 0.0) {
                // From the lower index, so the two faces of an edge give the same bits.
                let (a, ha, b, hb) = if i < j {
                    (corners[i], hp, corners[j], hq)
                } else {
                    (corners[j], hq, corners[i], hp)
                };
                poly[len] = a + (b - a) * (ha / (ha - hb));
                len += 1;
            }
        }
        if len < 3 {
            continue;
        }
        let a = poly[0];
        for k in 1..len - 1 {
            let (b, c) = (poly[k], poly[k + 1]);
            let v6 = a.dot(&b.cross(&c));
            six_volume += v6;
            moment += v6 * (a + b + c);
            area_vector += 0.5 * (b - a).cross(&(c - a));
        }
    }
    if six_volume <= 0.0 {
        return None;
    }
    let g = Point3::from(origin + moment / (4.0 * six_volume));
    let normal = Vector3::new(0.0, 0.0, side);
    let point_a = g - clipped::ray_exit(&g, &-normal, planes_box) * normal;
    let point_b = Point3::new(g.x, g.y, 0.0);
    // Wholly below the plane (no corner above it) no face crosses it and the faces' area
    // vectors cancel: the area is a quarter of the box's surface, `2(xy + yz + zx)` in
    // half-axes. Otherwise it is the cap's, `|S|` (no square root per face for a total that
    // only this branch needs).
    let area = if height.iter().all(|&h| h <= 0.0) {
        let [x, y, z] = half_axes.each_ref().map(|a| a.norm());
        2.0 * (x * y + y * z + z * x)
    } else {
        area_vector.norm()
    };
    let world = |p: Point3| pose_plane * Point3::from(p.coords * unit);
    Some(PairContact {
        point_a: world(point_a),
        point_b: world(point_b),
        normal: pose_plane.rotation * normal,
        depth: (point_b - point_a).dot(&normal) * unit,
        area: area * unit * unit,
    })
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
