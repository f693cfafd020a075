//! A frustum (cone) or ring torus against a bounded PLANE: the unbounded plane's closed form
//! where no edge of the plane is within the solid's reach, otherwise the box–frustum/torus
//! slicing on the plane's prism cut to a box about the solid (`crate::methods::bounded_plane`);
//! one contact per region.

use crate::kernel::PairContact;
use crate::methods::solid_distance::Solid;
use contact_core::geometry::Plane;
use contact_core::{Isometry3, Point3, WorkCounters};

/// The contacts of the frustum or torus `solid` (`a`, at `pose_a`) with the bounded `plane`
/// (`b`, at `pose_b`, flipped when `side < 0`): the unbounded plane's closed form when every
/// edge is out of the solid's reach ([`crate::methods::bounded_plane::well_inside`]), otherwise
/// [`prism_contacts`].
pub(crate) fn contacts(
    solid: &Solid,
    pose_a: &Isometry3,
    plane: &Plane,
    side: f64,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let Some((centre, reach)) = ball(solid, pose_a) else {
        return;
    };
    if crate::methods::bounded_plane::well_inside(plane, pose_b, &centre, reach) {
        if let Some(c) = crate::pairs::revolved_plane::contact(solid, pose_a, pose_b, side, work) {
            emit(c);
        }
        return;
    }
    prism_contacts(solid, pose_a, plane, side, pose_b, work, emit);
}

/// The same by the box pair on the plane's prism cut to a box about the solid
/// ([`crate::methods::bounded_plane`]), swapped, wherever the edges are.
pub(crate) fn prism_contacts(
    solid: &Solid,
    pose_a: &Isometry3,
    plane: &Plane,
    side: f64,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let Some((centre_w, reach)) = ball(solid, pose_a) else {
        return;
    };
    let Some((cuboid, pose_box)) =
        crate::methods::bounded_plane::local_box(plane, side, pose_b, &centre_w, reach)
    else {
        return;
    };
    crate::pairs::box_revolved::contacts(&cuboid, &pose_box, solid, pose_a, work, &mut |c| {
        emit(c.swapped())
    });
}

/// A ball holding the frustum or torus `solid` at `pose`: its world centre (the middle of the
/// axis; the torus' centre) and radius; `None` for a box or a cylinder.
fn ball(solid: &Solid, pose: &Isometry3) -> Option<(Point3, f64)> {
    let (centre, reach) = match *solid {
        Solid::Frustum(f) => (
            Point3::new(0.0, 0.0, 0.5 * f.length()),
            f.bottom_radius()
                .max(f.top_radius())
                .hypot(0.5 * f.length()),
        ),
        Solid::Torus(t) => (Point3::origin(), t.major_radius() + t.minor_radius()),
        Solid::Box(_) | Solid::Cylinder(_) => return None,
    };
    Some((pose * centre, reach))
}
