//! A sphere against a closed triangle mesh (taken as exact): closed form through the mesh's
//! signed distance.
//!
//! - The closest point `q` of the mesh to the sphere's centre `c`: the nearest of every
//!   triangle's closest point (Ericson, *Real-Time Collision Detection*, §5.1.5), `O(n)`.
//! - Inside or outside: the generalized winding number `Σ Ω_t / 4π` of the closed mesh about
//!   `c` (solid angles by Van Oosterom & Strackee), 1 inside and 0 outside; `c` is inside
//!   when it exceeds ½. It needs no choice of feature normal at edges and vertices.
//! - Signed distance `s = ±|c − q|`, outward normal `n = (c − q)/|c − q|` outside and
//!   `(q − c)/|q − c|` inside (the face normal of the nearest triangle when `c` lies on it).
//! - Contact iff `s < r`: δ = `r − s`, points `c − r·n` and `q`, area `π(r² − s²)` outside,
//!   `π r²` inside — as for the primitive solids ([`super::sphere_solid`]), whose remarks on
//!   edges, corners and a single contact per pair apply here too.

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
    let mut winding = 0.0;
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let [a, b, c] = tri.map(|v| mesh.vertices[v as usize]);
        let q = closest_point_on_triangle(&centre, &a, &b, &c);
        let d = (centre - q).norm_squared();
        if d < best.0 {
            best = (d, q, t);
        }
        winding += solid_angle(&centre, &a, &b, &c);
    }
    work.primitive_tests += mesh.triangles.len() as u64;
    let (d2, q, t) = best;
    let inside = winding > 2.0 * PI;
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
