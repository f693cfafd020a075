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
//! **The hand-over is continuous.** Let `d` be the least unit-ball distance from `E`'s centre
//! to a triangle of B that is not on the face (off its plane, or curved), and
//! `β = min(ℓ/a_min, ½)` a band of about one facet of A (`ℓ` A's longest edge, `a_min` the
//! least semi-axis). With `x = (d − 1)/β`, the plane answer has weight
//! `w = 3x² − 2x³` on `[0, 1]` (1 beyond the band, 0 as `E` reaches the other triangle) and the
//! facets' contact `1 − w`: depths and areas mix linearly, points by each answer's share of the
//! depth, the normal is the normalised weighted sum. Facets that miss the shallow contact count
//! as depth 0, so the contact fades in as their answer does. Inside the band both answers hold
//! (the section is still inside the face), and they differ by at most the chord deviation, so
//! the mix is too; a pair whose answers have different numbers of regions there is left to the
//! facets.
//!
//! "Reaches" is exact: a triangle reaches into `E` when its closest point to the centre, in
//! the affine frame where `E` is the unit ball, lies within distance 1. The candidates are the
//! leaves of B's OBB tree whose box meets `E`'s bounding sphere.

use crate::contact_region::{LocalContact, mesh_mesh};
use crate::facet_mesh::FacetMesh;
use crate::plane_contact::mesh_plane;
use crate::scratch::Scratch;
use contact_core::geometry::{Plane, closest_point_on_triangle};
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use std::cell::{Cell, RefCell};

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
    let band = (a.longest_edge / semi.min()).min(0.5);
    let reach = triangles_reaching(b, pose_ab.inverse() * centre_a, pose_ab, &semi, band);
    if !reach.coplanar {
        return false;
    }
    let Some(plane) = reach.plane else {
        // Nothing reaches E: apart, or one body wholly inside the other (the facets' test).
        return false;
    };
    // The plane answer's weight: 1 unless a triangle off the face is within the band.
    let weight = reach
        .near
        .iter()
        .filter(|&&(t, _)| !(flat(b, t) && on_plane(b, t, plane)))
        .map(|&(_, distance)| {
            let x = ((distance - 1.0) / band).clamp(0.0, 1.0);
            x * x * (3.0 - 2.0 * x)
        })
        .fold(1.0, f64::min);
    if weight <= 0.0 {
        return false;
    }
    let pose_a_plane = pose_ab * face_frame(&plane.0, plane.1);
    if weight >= 1.0 {
        mesh_plane(a, &Plane::unbounded(), &pose_a_plane, s, work, out);
        return true;
    }
    let (mut on_plane_answer, mut facets) = (Vec::new(), Vec::new());
    mesh_plane(
        a,
        &Plane::unbounded(),
        &pose_a_plane,
        s,
        work,
        &mut on_plane_answer,
    );
    mesh_mesh(a, b, pose_ab, s, work, &mut facets);
    match (on_plane_answer.as_slice(), facets.as_slice()) {
        ([], []) => true,
        ([plane_contact], []) => {
            out.push(mixed(plane_contact, None, weight));
            true
        }
        ([plane_contact], [facet_contact]) => {
            out.push(mixed(plane_contact, Some(facet_contact), weight));
            true
        }
        // Regions that do not pair up: the facets answer (see the module docs).
        _ => false,
    }
}

/// What of B reaches the implied solid E (centre `centre` in B's frame, semi-axes `semi` in
/// A's axes, B's vectors turned into A's by `pose_ab`'s rotation).
struct Reach {
    /// The plane `n·x = offset` of the first triangle reaching E.
    plane: Option<(Vector3, f64)>,
    /// Whether every triangle reaching E is flat and in that plane.
    coplanar: bool,
    /// Triangles within the band outside E: (triangle, unit-ball distance).
    near: Vec<(u32, f64)>,
}

/// B's triangles that reach into E or lie within `band` (in unit-ball distance) outside it;
/// the search stops once one reaching E is curved or off the first one's plane.
fn triangles_reaching(
    b: &FacetMesh,
    centre: Point3,
    pose_ab: &Isometry3,
    semi: &Vector3,
    band: f64,
) -> Reach {
    let to_a = pose_ab.rotation;
    let bound = semi.max();
    let to_unit_ball = |p: &Point3| (to_a * (p - centre)).component_div(semi);
    let face: Cell<Option<(Vector3, f64)>> = Cell::new(None);
    let coplanar = Cell::new(true);
    let near = RefCell::new(Vec::new());
    b.tree.visit(
        |obb| coplanar.get() && obb_reaches(obb, &centre.coords, bound * (1.0 + band)),
        |t| {
            let [p, q, r] = b.triangles[t as usize].map(|v| b.vertices[v as usize]);
            let [p1, q1, r1] = [p, q, r].map(|x| Point3::from(to_unit_ball(&x)));
            let distance = closest_point_on_triangle(&Point3::origin(), &p1, &q1, &r1)
                .coords
                .norm();
            if !coplanar.get() || distance >= 1.0 + band {
                return;
            }
            if distance >= 1.0 {
                near.borrow_mut().push((t, distance));
                return;
            }
            let n = b.face_normals[t as usize];
            let on_face = match face.get() {
                None => {
                    face.set(Some((n, n.dot(&p.coords))));
                    true
                }
                Some(plane) => on_plane(b, t, plane),
            };
            coplanar.set(flat(b, t) && on_face);
        },
    );
    Reach {
        plane: face.get(),
        coplanar: coplanar.get(),
        near: near.into_inner(),
    }
}

/// Whether triangle `t` of `b` is flat: its corner normals are its facet normal.
fn flat(b: &FacetMesh, t: u32) -> bool {
    let n = b.face_normals[t as usize];
    b.corner_normals[t as usize]
        .iter()
        .all(|c| (c - n).norm() <= COPLANAR)
}

/// Whether triangle `t` of `b` lies in the plane `n0·x = o0` (its normal along `n0`).
fn on_plane(b: &FacetMesh, t: u32, (n0, o0): (Vector3, f64)) -> bool {
    let n = b.face_normals[t as usize];
    (n - n0).norm() <= COPLANAR
        && b.triangles[t as usize]
            .iter()
            .all(|&v| (n0.dot(&b.vertices[v as usize].coords) - o0).abs() <= COPLANAR * b.size)
}

/// The plane answer with weight `w` mixed with the facets' (`None`: no contact, depth 0):
/// depths and areas linearly, points by each answer's share of the depth, the normal as the
/// normalised weighted sum.
fn mixed(plane: &LocalContact, facets: Option<&LocalContact>, w: f64) -> LocalContact {
    let Some(facets) = facets else {
        return LocalContact {
            penetration: w * plane.penetration,
            area: w * plane.area,
            point_j: plane.point_i + (plane.point_j - plane.point_i) * w,
            ..*plane
        };
    };
    let (wp, wf) = (w * plane.penetration, (1.0 - w) * facets.penetration);
    let depth = wp + wf;
    let normal = (plane.normal * w + facets.normal * (1.0 - w))
        .try_normalize(0.0)
        .unwrap_or(plane.normal);
    let (point_i, point_j) = if depth > 0.0 {
        (
            (plane.point_i * wp + facets.point_i * wf) / depth,
            (plane.point_j * wp + facets.point_j * wf) / depth,
        )
    } else {
        (plane.point_i, plane.point_j)
    };
    LocalContact {
        point_i,
        point_j,
        normal,
        penetration: depth,
        area: w * plane.area + (1.0 - w) * facets.area,
    }
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
