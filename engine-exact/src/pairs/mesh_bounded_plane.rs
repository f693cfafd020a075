//! A closed mesh (taken as exact) against a bounded PLANE: the unbounded plane's clipping
//! where no edge of the plane is within the mesh's reach, otherwise the box–mesh intersection
//! on the plane's prism cut to a box about the mesh (`crate::methods::bounded_plane`); one
//! contact per region.

use crate::kernel::PairContact;
use crate::pairs::mesh_plane::PreparedMesh;
use contact_core::geometry::Plane;
use contact_core::{Isometry3, WorkCounters};

/// The contacts of `mesh` (at `pose_mesh`) with the bounded `plane` (at `pose_plane`,
/// flipped when `side < 0`): the unbounded plane's clipping when every edge is out of the
/// mesh's reach ([`crate::methods::bounded_plane::well_inside`]), otherwise [`prism_contacts`].
pub(crate) fn contacts(
    mesh: &PreparedMesh,
    pose_mesh: &Isometry3,
    plane: &Plane,
    side: f64,
    pose_plane: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let centre = pose_mesh * mesh.centre;
    if crate::methods::bounded_plane::well_inside(plane, pose_plane, &centre, mesh.radius) {
        crate::pairs::mesh_plane::contacts(mesh, pose_mesh, pose_plane, side, work, emit);
        return;
    }
    prism_contacts(mesh, pose_mesh, plane, side, pose_plane, work, emit);
}

/// Contacts of `mesh` at `pose_mesh` (`a`) with the bounded `plane` (flipped when `side <
/// 0`) at `pose_plane` (`b`): the mesh against the box standing for the plane about the mesh's
/// ball.
pub(crate) fn prism_contacts(
    mesh: &PreparedMesh,
    pose_mesh: &Isometry3,
    plane: &Plane,
    side: f64,
    pose_plane: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let centre = pose_mesh * mesh.centre;
    let Some((cuboid, pose_box)) =
        crate::methods::bounded_plane::local_box(plane, side, pose_plane, &centre, mesh.radius)
    else {
        return;
    };
    crate::pairs::box_mesh::contacts(&cuboid, &pose_box, mesh, pose_mesh, work, &mut |c| {
        emit(c.swapped())
    });
}
