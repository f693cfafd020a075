//! A general ellipsoid against a bounded PLANE: the unbounded plane's closed form
//! (`crate::pairs::ellipsoid_plane`) with the centre on the free side and no edge within reach,
//! otherwise the ellipsoid–box slicing on the plane's prism cut to a box about the ellipsoid
//! (`crate::methods::bounded_plane`).

use crate::kernel::PairContact;
use crate::methods::bounded_plane::{local_box, well_inside};
use crate::pairs::{ellipsoid_box, ellipsoid_plane};
use contact_core::geometry::Plane;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};

/// The contact of the ellipsoid of `semi_axes` (`a`, at `pose_a`) with the bounded `plane`
/// (`b`, at `pose_b`, flipped when `side < 0`).
pub(crate) fn contact(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    plane: &Plane,
    side: f64,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let centre = Point3::from(pose_a.translation.vector);
    let reach = semi_axes.max();
    // With its centre on the plane's free side (beyond, the half-space's area estimate is the
    // central section, the prism's the section itself).
    let free_side = pose_b.inverse_transform_point(&centre).z * side > 0.0;
    if free_side && well_inside(plane, pose_b, &centre, reach) {
        return ellipsoid_plane::contact(semi_axes, pose_a, pose_b, side);
    }
    let (cuboid, pose_box) = local_box(plane, side, pose_b, &centre, reach)?;
    ellipsoid_box::contact(semi_axes, pose_a, &cuboid, &pose_box, work)
}
