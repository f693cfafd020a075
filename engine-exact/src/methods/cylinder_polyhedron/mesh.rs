//! A cylinder against a closed mesh of small components apart from one another (see
//! `mesh_parts`): each component met is one polyhedron of the closed form, the points and
//! the containment normal as the mesh's sliced regions take them (`revolved_mesh`).
//!
//! A convex component meets the cylinder in one convex region: one contact. One that is not
//! convex takes its caps from its section ([`super::Caps::Section`]) and may meet the
//! cylinder in several regions. Each region's boundary holds a piece of the component's
//! surface (the cylinder is convex, so no region has a cavity; a boundary of the cylinder's
//! surface alone is all of it, inside the solid, with no face pieces at all). So when the
//! pieces are shown to be joined (across edges into the cylinder, the caps and the side:
//! [`super::links`]) the intersection is one region, one contact; otherwise the mesh is
//! sliced, which labels its regions.

use super::links::{Links, join_edges};
use super::{Caps, FACE_CORNERS, Face, moments, moments_of};
use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::mesh_parts::{MAX_PART_TRIANGLES, MeshPart};
use crate::methods::sliced::SlicedMoments;
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::methods::volume_contact::{self, ENCLOSED, VolumeMoments};
use crate::pairs::mesh_plane::PreparedMesh;
use crate::pairs::revolved_mesh::{fallback, on_mesh};
use crate::ray_exit::surface_point_along_w;
use contact_core::geometry::Cylinder;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};

/// Flat pieces: every triangle of a part and the two caps.
const FLATS: usize = MAX_PART_TRIANGLES + 2;
/// Rim arcs: a few per triangle at most (a triangle's piece is bounded by three edges).
const ARCS: usize = 4 * MAX_PART_TRIANGLES;

/// The contacts of `cylinder` at `pose_a` with the parts of `mesh` at `pose_b`, handed to
/// `emit`; false (and nothing emitted) when the mesh has no parts or one needs the slicing (a
/// face within 1e-3 of parallel to the axis, a cap's section not clear-cut, a component met
/// in pieces not shown to be one region), which the caller then runs.
pub(crate) fn mesh_contacts(
    cylinder: &Cylinder,
    pose_a: &Isometry3,
    mesh: &PreparedMesh,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) -> bool {
    if mesh.inverted || mesh.parts.is_empty() {
        return false;
    }
    let (r, half) = (cylinder.radius(), 0.5 * cylinder.length());
    let unit = unit_for(r.max(half));
    let relative = pose_a.inv_mul(pose_b);
    let mut found: [Option<SlicedMoments>; 8] = [None; 8];
    let mut found_count = 0;
    let mut faces = [Face {
        normal: Vector3::zeros(),
        offset: 0.0,
        corners: [Vector3::zeros(); FACE_CORNERS],
        count: 3,
    }; MAX_PART_TRIANGLES];
    let mut corners = [[Vector3::zeros(); 3]; MAX_PART_TRIANGLES];
    for part in &mesh.parts {
        let moments = part_moments(
            part,
            mesh,
            &relative,
            (r, half, unit),
            (&mut faces, &mut corners),
            work,
        );
        match moments {
            None => return false,
            Some(None) => {}
            Some(Some(m)) if found_count < found.len() => {
                found[found_count] = Some(m);
                found_count += 1;
            }
            // More regions than kept: the slicing takes them all.
            Some(Some(_)) => return false,
        }
    }
    for m in found.iter().flatten() {
        if let Some(c) = region_contact(m, cylinder, pose_a, mesh, pose_b, unit) {
            emit(c);
        }
    }
    true
}

/// The moments of the cylinder (radius `r`, half-length `half`) against one `part` of `mesh`
/// (`relative` maps the mesh's frame into the cylinder's; working lengths over `unit`), its
/// faces and triangles built in the buffers given: `Some(None)` when they do not meet,
/// `None` when the part needs the slicing (see [`mesh_contacts`]).
fn part_moments(
    part: &MeshPart,
    mesh: &PreparedMesh,
    relative: &Isometry3,
    (r, half, unit): (f64, f64, f64),
    (faces, corners): (
        &mut [Face; MAX_PART_TRIANGLES],
        &mut [[Vector3; 3]; MAX_PART_TRIANGLES],
    ),
    work: &mut WorkCounters,
) -> Option<Option<SlicedMoments>> {
    let rotation = relative.rotation;
    let centre_a = Vector3::new(0.0, 0.0, half);
    let c = (relative * part.centre).coords - centre_a;
    work.bounding_volume_tests += 1;
    if c.z.abs() - part.radius >= half || c.xy().norm() - part.radius >= r {
        return Some(None);
    }
    let count = part.triangles.len();
    for ((face, tri), &t) in faces
        .iter_mut()
        .zip(corners.iter_mut())
        .zip(&part.triangles)
    {
        *tri = mesh.triangles[t as usize]
            .map(|v| ((relative * mesh.vertices[v as usize]).coords - centre_a) / unit);
        let normal = rotation * mesh.normals[t as usize];
        *face = Face {
            normal,
            offset: normal.dot(&tri[0]),
            corners: std::array::from_fn(|c| tri[c.min(2)]),
            count: 3,
        };
    }
    work.primitive_tests += count as u64;
    let (r_w, h_w) = (r / unit, half / unit);
    if part.convex {
        moments::<FLATS, ARCS>(r_w, h_w, &faces[..count])
    } else {
        let mut links = Links::new();
        join_edges(&mut links, part, &corners[..count], r_w, h_w);
        let m = moments_of::<FLATS, ARCS>(
            r_w,
            h_w,
            &faces[..count],
            Caps::Section(&corners[..count]),
            Some(&mut links),
        );
        if let Some(Some(_)) = m {
            if !links.one() {
                return None;
            }
        }
        m
    }
}

/// The contact of one region from its moments `m` (working frame: the cylinder's, origin at
/// its centre, lengths over `unit`), normals from the mesh into the cylinder.
fn region_contact(
    m: &SlicedMoments,
    cylinder: &Cylinder,
    pose_a: &Isometry3,
    mesh: &PreparedMesh,
    pose_b: &Isometry3,
    unit: f64,
) -> Option<PairContact> {
    let centre_a = Vector3::new(0.0, 0.0, 0.5 * cylinder.length());
    let solid = Solid::Cylinder(*cylinder);
    let centroid = pose_a * Point3::from(centre_a + m.centroid * unit);
    let moments = VolumeMoments {
        volume: m.volume * unit * unit * unit,
        centroid,
        area_vector_a: pose_a.rotation * m.area_vector_a * (unit * unit),
        surface_area: (m.area_a + m.area_b) * unit * unit,
        length: unit,
    };
    let solid_inside = m.area_b <= ENCLOSED * (m.area_a + m.area_b);
    let against_solid = || {
        let p = pose_a.inverse_transform_point(&centroid).coords;
        -(pose_a.rotation * signed_distance(&solid, &p).2)
    };
    volume_contact::contact_of_region(
        &moments,
        |g, d| surface_point_along_w(&solid, pose_a, g, d),
        |g, d| on_mesh(mesh, pose_b, g, d),
        || fallback(solid_inside, mesh, pose_b, &centroid, against_solid),
        false,
    )
}
