//! A sphere against a closed triangle mesh (taken as exact): closed form through the mesh's
//! signed distance.
//!
//! - The closest point `q` of the mesh to the sphere's centre `c`: the nearest of every
//!   triangle's closest point (Ericson, *Real-Time Collision Detection*, §5.1.5), `O(n)`.
//!   Triangles whose ball lies beyond the nearest point so far are skipped (they cannot hold a
//!   nearer one).
//! - Inside or outside: when `q` lies inside its triangle's face, the side of that face (the
//!   segment from `q` to `c` runs along its normal and meets no other surface); on an edge, the
//!   side of the edge's pseudo-normal (the two faces' unit normals summed); at a corner, the
//!   generalized winding number `Σ Ω_t / 4π` of the closed mesh about `c` (solid angles by
//!   Van Oosterom & Strackee), 1 inside and 0 outside; `c` is inside when it exceeds ½ (it
//!   needs no corner pseudo-normal and its angle weights).
//! - Signed distance `s = ±|c − q|`, outward normal `n = (c − q)/|c − q|` outside and
//!   `(q − c)/|q − c|` inside (the face normal of the nearest triangle when `c` lies on it).
//! - Contact iff `s < r`: δ = `r − s`, points `c − r·n` and `q`, area `π(r² − s²)` outside,
//!   `π r²` inside: the closest-point answer, which the primitive solids keep only as a fast
//!   path where it is SPEC §4's ([`super::sphere_solid`]). Here it is used everywhere, so at
//!   a mesh's edges and corners (where the region is not symmetric about the normal through
//!   the centre) it departs from the centroid definition, and one contact per pair is
//!   returned.

use super::mesh_plane::PreparedMesh;
use crate::kernel::PairContact;
use contact_core::geometry::closest_point_on_triangle;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use std::f64::consts::PI;

/// The solid angle of triangle `a b c` seen from `p` (signed by orientation).
pub(crate) fn solid_angle(p: &Point3, a: &Point3, b: &Point3, c: &Point3) -> f64 {
    let (x, y, z) = (a - p, b - p, c - p);
    let (lx, ly, lz) = (x.norm(), y.norm(), z.norm());
    let numerator = x.dot(&y.cross(&z));
    let denominator = lx * ly * lz + x.dot(&y) * lz + y.dot(&z) * lx + z.dot(&x) * ly;
    2.0 * numerator.atan2(denominator)
}

/// Whether `centre` lies inside the mesh, read off the nearest triangle `t` and its nearest
/// point `q`: inside its face (every barycentric coordinate above 1e-9), by the side of the
/// face (the segment from `q` to the centre runs along the face normal and meets no other
/// surface); on one of its edges, by the side of the edge's pseudo-normal, the sum of the two
/// faces' unit normals (Bærentzen & Aanæs 2005: exact for the nearest point on an edge of a
/// closed, consistently oriented mesh). `None` at a corner or with the centre on the surface
/// (the winding number decides).
fn face_side(mesh: &PreparedMesh, t: usize, q: &Point3, centre: &Point3) -> Option<bool> {
    let [a, b, c] = mesh.triangles[t].map(|v| mesh.vertices[v as usize]);
    let n = (b - a).cross(&(c - a));
    let n2 = n.norm_squared();
    let weight = |u: &Point3, v: &Point3| (u - q).cross(&(v - q)).dot(&n) / n2;
    // The weight of each corner and the edge opposite it (edge k joins corners k and k + 1).
    let weights = [
        (weight(&b, &c), 1),
        (weight(&c, &a), 2),
        (weight(&a, &b), 0),
    ];
    let mut edges = weights
        .iter()
        .filter(|(w, _)| *w <= 1e-9)
        .map(|&(_, edge)| edge);
    let normal = match (edges.next(), edges.next()) {
        (None, _) => n,
        (Some(edge), None) => {
            let m = mesh.triangles[mesh.neighbours[t][edge] as usize];
            let [d, e, f] = m.map(|v| mesh.vertices[v as usize]);
            n / n2.sqrt() + (e - d).cross(&(f - d)).normalize()
        }
        (Some(_), Some(_)) => return None,
    };
    let height = (centre - q).dot(&normal);
    (height != 0.0).then_some(height < 0.0)
}

/// Contact of the sphere of `radius` at `pose_sphere` with `mesh` at `pose_mesh`.
pub(crate) fn contact(
    radius: f64,
    pose_sphere: &Isometry3,
    mesh: &PreparedMesh,
    pose_mesh: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let centre = pose_mesh.inverse_transform_point(&Point3::from(pose_sphere.translation.vector));
    let mut best = (f64::INFINITY, centre, 0usize);
    let mut tested = 0;
    for (t, (tri, (ball_centre, ball_radius))) in mesh.triangles.iter().zip(&mesh.balls).enumerate()
    {
        // A triangle whose ball lies beyond the nearest point so far cannot hold a nearer one.
        let lower = (centre - ball_centre).norm() - ball_radius * (1.0 + 1e-9);
        if lower > 0.0 && lower * lower > best.0 {
            continue;
        }
        tested += 1;
        let [a, b, c] = tri.map(|v| mesh.vertices[v as usize]);
        let q = closest_point_on_triangle(&centre, &a, &b, &c);
        let d = (centre - q).norm_squared();
        if d < best.0 {
            best = (d, q, t);
        }
    }
    work.primitive_tests += tested;
    let (d2, q, t) = best;
    let inside = match face_side(mesh, t, &q, &centre) {
        Some(inside) => inside,
        None => {
            let winding: f64 = mesh
                .triangles
                .iter()
                .map(|tri| {
                    let [a, b, c] = tri.map(|v| mesh.vertices[v as usize]);
                    solid_angle(&centre, &a, &b, &c)
                })
                .sum();
            winding > 2.0 * PI
        }
    };
    let distance = d2.sqrt();
    let n = if distance > 0.0 {
        let away = (centre - q) / distance;
        if inside { -away } else { away }
    } else {
        let [a, b, c] = mesh.triangles[t].map(|v| mesh.vertices[v as usize]);
        (b - a).cross(&(c - a)).normalize()
    };
    let s = if inside { -distance } else { distance };
    if s >= radius {
        return None;
    }
    let normal: Vector3 = pose_mesh.rotation * n;
    let c_w = pose_sphere.translation.vector;
    let area = if s >= 0.0 {
        PI * (radius - s) * (radius + s)
    } else {
        PI * radius * radius
    };
    Some(PairContact {
        point_a: Point3::from(c_w - radius * normal),
        point_b: pose_mesh * q,
        normal,
        depth: radius - s,
        area,
    })
}
