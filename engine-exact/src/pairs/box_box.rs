//! Box against box: exact convex clipping.
//!
//! Box `a` is clipped by the six planes of box `b`, in `b`'s frame
//! ([`crate::polyhedron`]); contact iff the intersection has positive volume (touching faces,
//! edges or corners are not contacts). Normal, points, depth and area follow
//! [`crate::methods::clipped`]: the area-weighted normal of `b`'s surface inside `a`; exchanging the
//! boxes gives `a`'s surface inside `b`, its exact negative in exact arithmetic (the
//! intersection's closed surface sums to zero), so the pair is symmetric.
//!
//! A separating-axis test on the six face axes rejects most separated pairs before clipping.

use crate::kernel::PairContact;
use crate::methods::clipped::{self, box_planes, unit_for};
use crate::polyhedron::{ConvexPolyhedron, MAX_FACE_VERTICES, MAX_FACES};
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
    // Working frame: b's geometry frame moved to b's centre (b is then [-h, h]³), lengths
    // divided by `unit`.
    let unit = unit_for(a.half_extents().norm().max(b.half_extents().norm()));
    let frame_b = pose_b * nalgebra::Translation3::from(b.center().coords);
    let pose_rel = frame_b.inv_mul(pose_a);
    let center = (pose_rel * a.center()) / unit;
    let rotation = pose_rel.rotation.to_rotation_matrix();
    let m = rotation.matrix();
    let unit_axes = [
        m.column(0).into_owned(),
        m.column(1).into_owned(),
        m.column(2).into_owned(),
    ];
    let ha = a.half_extents() / unit;
    let hb = b.half_extents() / unit;
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
        along >= ha[k] + abs_m.column(k).dot(&hb)
    }) {
        return None;
    }
    let mut poly = ConvexPolyhedron::<MAX_FACES, MAX_FACE_VERTICES>::cuboid(&center, &half_axes);
    let planes_a = box_planes(&center, &unit_axes, &ha);
    let planes_b = box_planes(
        &Point3::origin(),
        &[Vector3::x(), Vector3::y(), Vector3::z()],
        &hb,
    );
    clipped::contact(&mut poly, &planes_a, &planes_b, &planes_b, &frame_b, unit)
}
