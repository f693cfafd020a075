//! A cylinder against a closed mesh whose components are all convex solids (see
//! `convex_parts`): each component met is one convex polyhedron of the closed form, one
//! contact each, the points and the containment normal as the mesh's sliced regions take
//! them (`mesh_revolved`).

use super::{FACE_CORNERS, Face, moments};
use crate::kernel::PairContact;
use crate::pairs::clipped::unit_for;
use crate::pairs::convex_parts::MAX_PART_TRIANGLES;
use crate::pairs::mesh_plane::PreparedMesh;
use crate::pairs::mesh_revolved::{fallback, on_mesh};
use crate::pairs::sliced::SlicedMoments;
use crate::pairs::solid_distance::{Solid, signed_distance};
use crate::pairs::volume_contact::{self, ENCLOSED, VolumeMoments};
use crate::ray_exit::surface_point_along_w;
use contact_core::geometry::Cylinder;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};

/// Flat pieces: every triangle of a part and the two caps.
const FLATS: usize = MAX_PART_TRIANGLES + 2;
/// Rim arcs: a few per triangle at most (a triangle's piece is bounded by three edges).
const ARCS: usize = 4 * MAX_PART_TRIANGLES;

/// The contacts of `cylinder` at `pose_a` with the convex parts of `mesh` at `pose_b`, handed
/// to `emit`; false (and nothing emitted) when the mesh has no convex parts or one needs the
/// slicing (a face within 1e-3 of parallel to the axis), which the caller then runs.
pub(crate) fn mesh_contacts(
    cylinder: &Cylinder,
    pose_a: &Isometry3,
    mesh: &PreparedMesh,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) -> bool {
    if mesh.inverted || mesh.convex_parts.is_empty() {
        return false;
    }
    let (r, half) = (cylinder.radius(), 0.5 * cylinder.length());
    let unit = unit_for(r.max(half));
    let relative = pose_a.inv_mul(pose_b);
    let rotation = relative.rotation;
    let centre_a = Vector3::new(0.0, 0.0, half);
    let mut found: [Option<SlicedMoments>; 8] = [None; 8];
    let mut found_count = 0;
    let mut faces = [Face {
        normal: Vector3::zeros(),
        offset: 0.0,
        corners: [Vector3::zeros(); FACE_CORNERS],
        count: 3,
    }; MAX_PART_TRIANGLES];
    for part in &mesh.convex_parts {
        let c = (relative * part.centre).coords - centre_a;
        work.bounding_volume_tests += 1;
        if c.z.abs() - part.radius >= half || c.xy().norm() - part.radius >= r {
            continue;
        }
        for (face, &t) in faces.iter_mut().zip(&part.triangles) {
            let corner = |k: usize| {
                let v = mesh.vertices[mesh.triangles[t as usize][k] as usize];
                ((relative * v).coords - centre_a) / unit
            };
            let normal = rotation * mesh.normals[t as usize];
            let v0 = corner(0);
            *face = Face {
                normal,
                offset: normal.dot(&v0),
                corners: std::array::from_fn(|c| if c < 3 { corner(c) } else { v0 }),
                count: 3,
            };
        }
        work.primitive_tests += part.triangles.len() as u64;
        match moments::<FLATS, ARCS>(r / unit, half / unit, &faces[..part.triangles.len()]) {
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
    let solid = Solid::Cylinder(*cylinder);
    for m in found.iter().flatten() {
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
        let contact = volume_contact::contact_of_region(
            &moments,
            |g, d| surface_point_along_w(&solid, pose_a, g, d),
            |g, d| on_mesh(mesh, pose_b, g, d),
            || fallback(solid_inside, mesh, pose_b, &centroid, against_solid),
            false,
        );
        if let Some(c) = contact {
            emit(c);
        }
    }
    true
}
