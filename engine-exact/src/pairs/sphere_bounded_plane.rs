//! A sphere against a bounded PLANE: the unbounded plane's closed form
//! (`crate::pairs::sphere_plane`) with the centre on the free side and no edge within reach,
//! otherwise the sphere–box pair (`crate::pairs::sphere_solid`) on the plane's prism cut to a
//! box about the sphere (`crate::methods::bounded_plane`).

use crate::kernel::PairContact;
use crate::methods::bounded_plane::{local_box, well_inside};
use crate::methods::solid_distance::Solid;
use crate::pairs::{sphere_plane, sphere_solid};
use contact_core::geometry::Plane;
use contact_core::{Isometry3, Point3, WorkCounters};

/// The contact of the sphere of `radius` (`a`, at `pose_a`) with the bounded `plane` (`b`, at
/// `pose_b`, flipped when `side < 0`).
pub(crate) fn contact(
    radius: f64,
    pose_a: &Isometry3,
    plane: &Plane,
    side: f64,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let centre = Point3::from(pose_a.translation.vector);
    // As the ellipsoid: the half-space's answer with the centre on the free side.
    let free_side = pose_b.inverse_transform_point(&centre).z * side > 0.0;
    if free_side && well_inside(plane, pose_b, &centre, radius) {
        return sphere_plane::contact(radius, pose_a, pose_b, side);
    }
    let (cuboid, pose_box) = local_box(plane, side, pose_b, &centre, radius)?;
    sphere_solid::contact(radius, pose_a, &Solid::Box(cuboid), &pose_box, work)
}
