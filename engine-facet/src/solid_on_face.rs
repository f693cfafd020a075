//! A tessellated sphere or ellipsoid against one flat face of another mesh (a ball on a
//! faceted box or an STL floor): the contact is the implied solid's with the face's plane.
//!
//! Mesh A stands for a sphere or an ellipsoid ([`FacetMesh::implied_sphere`],
//! [`FacetMesh::implied_ellipsoid`]); write `E` for that solid. When every triangle of mesh B
//! that reaches into `E` is flat (its corner normals are its facet normal) and lies in one
//! plane, `E ∩ B` near the contact is `E` cut by that plane: B is closed, so if the section of
//! `E` by the plane crossed the boundary of the coplanar triangles, `E` would hold a point of a
//! boundary edge and so reach a triangle off the plane. The contact is then
//! [`mesh_plane`]'s against the unbounded plane, which answers for the solid A stands for
//! ([`crate::plane_support`]) rather than for its inscribed facets: the facets' ray rule steps
//! as the support point crosses A's edges and makes a bouncing ball's restitution depend on
//! where it lands. Wherever `E` reaches a second plane of B (an edge or a corner of a box), or a
//! curved triangle, the facets answer as before; the two answers differ there by at most A's
//! chord deviation.
//!
//! "Reaches" is exact: a triangle reaches into `E` when its closest point to the centre, in
//! the affine frame where `E` is the unit ball, lies within distance 1. The candidates are the
//! leaves of B's OBB tree whose box meets `E`'s bounding sphere.

use crate::contact_region::LocalContact;
use crate::facet_mesh::FacetMesh;
use crate::plane_contact::mesh_plane;
use crate::scratch::Scratch;
use contact_core::geometry::{Plane, closest_point_on_triangle};
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use std::cell::Cell;

/// Coplanarity tolerance: facet normals equal to 1e-9 (unit vectors), offsets to 1e-9 of B's size.
const COPLANAR: f64 = 1e-9;

/// The solid mesh A stands for, as `(centre, semi-axes)` in A's frame (a sphere's three
/// semi-axes equal), if any.
fn implied_solid(a: &FacetMesh) -> Option<(Point3, Vector3)> {
    a.implied_sphere
        .map(|(c, r)| (c, Vector3::repeat(r)))
        .or(a.implied_ellipsoid)
}

/// The contact of mesh A with mesh B (B's frame at `pose_ab` in A's) when A stands for a
/// sphere or an ellipsoid, some triangle of B reaches into it, and every one that does is flat
/// and in one plane; appends it to `out` in A's frame and returns `true`. Returns `false`,
/// appending nothing, when the facets must answer (nothing reaching included: the bodies are
/// apart or one holds the other, which the facets' containment test tells).
pub(crate) fn implied_solid_on_face(
    a: &FacetMesh,
    b: &FacetMesh,
    pose_ab: &Isometry3,
    s: &mut Scratch,
    work: &mut WorkCounters,
    out: &mut Vec<LocalContact>,
) -> bool {
    let Some((centre_a, semi)) = implied_solid(a) else {
        return false;
    };
    if !b.closed {
        return false;
    }
    // E in B's frame: centre, the rotation taking B's vectors to A's, and the bounding radius.
    let pose_ba = pose_ab.inverse();
    let centre = pose_ba * centre_a;
    let to_a = pose_ab.rotation;
    let bound = semi.max();
    let to_unit_ball = |p: &Point3| (to_a * (p - centre)).component_div(&semi);
    // The plane `n·x = offset` of the first triangle reaching E; cleared (`coplanar` false)
    // by a curved triangle or one off that plane.
    let face: Cell<Option<(Vector3, f64)>> = Cell::new(None);
    let coplanar = Cell::new(true);
    b.tree.visit(
        |obb| coplanar.get() && obb_reaches(obb, &centre.coords, bound),
        |t| {
            let [p, q, r] = b.triangles[t as usize].map(|v| b.vertices[v as usize]);
            let [p1, q1, r1] = [p, q, r].map(|x| Point3::from(to_unit_ball(&x)));
            let closest = closest_point_on_triangle(&Point3::origin(), &p1, &q1, &r1);
            if !coplanar.get() || closest.coords.norm() >= 1.0 {
                return;
            }
            let n = b.face_normals[t as usize];
            let flat = b.corner_normals[t as usize]
                .iter()
                .all(|c| (c - n).norm() <= COPLANAR);
            let on_face = match face.get() {
                None => {
                    face.set(Some((n, n.dot(&p.coords))));
                    true
                }
                Some((n0, o0)) => {
                    (n - n0).norm() <= COPLANAR
                        && [p, q, r]
                            .iter()
                            .all(|x| (n0.dot(&x.coords) - o0).abs() <= COPLANAR * b.size)
                }
            };
            coplanar.set(flat && on_face);
        },
    );
    if !coplanar.get() {
        return false;
    }
    let Some((n_b, offset)) = face.get() else {
        // Nothing reaches E: apart, or one body wholly inside the other (the facets' test).
        return false;
    };
    let pose_a_plane = pose_ab * face_frame(&n_b, offset);
    mesh_plane(a, &Plane::unbounded(), &pose_a_plane, s, work, out);
    true
}

/// Whether the box `obb` comes within `radius` of `centre`.
fn obb_reaches(obb: &crate::obb::Obb, centre: &Vector3, radius: f64) -> bool {
    let local = obb.axes.transpose() * (centre - obb.center);
    let outside = (local.abs() - obb.half_extents).map(|x| x.max(0.0));
    outside.norm() <= radius
}

/// A frame whose z axis is the unit normal `n` and whose origin lies on the plane `n·x = offset`.
fn face_frame(n: &Vector3, offset: f64) -> Isometry3 {
    let rotation = contact_core::nalgebra::UnitQuaternion::rotation_between(&Vector3::z(), n)
        .unwrap_or_else(|| {
            contact_core::nalgebra::UnitQuaternion::from_axis_angle(
                &Vector3::x_axis(),
                std::f64::consts::PI,
            )
        });
    Isometry3::from_parts((n * offset).into(), rotation)
}
