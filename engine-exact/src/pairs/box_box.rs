//! Box against box: exact convex clipping.
//!
//! Box `a` is clipped by the six planes of box `b`, in `b`'s frame
//! ([`crate::polyhedron`]). From the intersection polyhedron:
//! - contact iff its volume is positive (touching faces, edges or corners are not contacts);
//! - normal (from `b` into `a`): the area-weighted outward normal of `b`'s surface inside `a`.
//!   Exchanging the boxes gives the area vector of `a`'s surface inside `b`, which is its exact
//!   negative (the intersection's closed surface sums to zero), so the pair is symmetric. When
//!   `a` lies wholly inside `b` that surface is empty and the normal is the outward normal of
//!   `b`'s face nearest the centroid (the way out);
//! - points: where the line through the centroid along the normal leaves `b` (`+n`) and `a`
//!   (`−n`); δ is their distance;
//! - area: the intersection's shadow on the plane normal to `n`.
//!
//! A separating-axis test on the six face axes rejects most separated pairs before clipping.

use super::box_plane::{box_planes, nearest_face_normal, ray_exit};
use crate::kernel::PairContact;
use crate::polyhedron::ConvexPolyhedron;
use contact_core::geometry::Cuboid;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};

/// Contact of box `a` at `pose_a` with box `b` at `pose_b`.
pub(crate) fn contact(
    a: &Cuboid,
    pose_a: &Isometry3,
    b: &Cuboid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    // Frame B: b's geometry frame moved to b's centre; b is then [-h, h]³.
    let frame_b = pose_b * nalgebra::Translation3::from(b.center().coords);
    let pose_rel = frame_b.inv_mul(pose_a);
    let center = pose_rel * a.center();
    let rotation = pose_rel.rotation.to_rotation_matrix();
    let m = rotation.matrix();
    let unit_axes = [
        m.column(0).into_owned(),
        m.column(1).into_owned(),
        m.column(2).into_owned(),
    ];
    let ha = a.half_extents();
    let hb = b.half_extents();
    let half_axes = [
        unit_axes[0] * ha.x,
        unit_axes[1] * ha.y,
        unit_axes[2] * ha.z,
    ];
    work.bounding_volume_tests += 1;
    // Separating axes: b's three axes, then a's three.
    let extent_a = half_axes[0].abs() + half_axes[1].abs() + half_axes[2].abs();
    if (0..3).any(|k| center[k].abs() >= hb[k] + extent_a[k]) {
        return None;
    }
    let abs_m = m.abs();
    if (0..3).any(|k| {
        let along = unit_axes[k].dot(&center.coords).abs();
        let extent_b = abs_m.column(k).dot(&hb);
        along >= ha[k] + extent_b
    }) {
        return None;
    }
    let mut poly = ConvexPolyhedron::cuboid(&center, &half_axes);
    let planes_b = box_planes(
        &Point3::origin(),
        &[Vector3::x(), Vector3::y(), Vector3::z()],
        &hb,
    );
    for h in &planes_b {
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
        nearest_face_normal(&c, &planes_b)
    };
    let to_b = ray_exit(&c, &normal, &planes_b);
    let to_a = ray_exit(&c, &-normal, &box_planes(&center, &unit_axes, &ha));
    Some(PairContact {
        point_a: frame_b * (c - to_a * normal),
        point_b: frame_b * (c + to_b * normal),
        normal: frame_b.rotation * normal,
        depth: to_a + to_b,
        area: poly.projected_area(&normal),
    })
}
