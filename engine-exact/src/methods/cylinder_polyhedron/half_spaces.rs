//! A convex region given by half-spaces (a bounded plane's prism, open below) as the faces
//! the closed form takes: on each plane a square about the origin's foot, large enough
//! to hold everything the cylinder can reach, clipped by the other planes. Where a face is
//! cut only by the square it is larger than the true (unbounded) face, but only beyond the
//! cylinder's reach, where it meets nothing: the faces' pieces inside the cylinder, the caps'
//! sections and the side's arcs are those of the true region.

use super::{FACE_CORNERS, Face};
use crate::methods::section::Polygon;
use contact_core::{Vector2, Vector3};

/// The faces of `∩ {n·x ≤ d}` over `planes` (unit normals) within `reach` of the origin,
/// written to `out`; their count, or `None` when a face has more corners than it holds.
pub(crate) fn faces(planes: &[(Vector3, f64)], reach: f64, out: &mut [Face]) -> Option<usize> {
    let mut count = 0;
    for (k, &(n, d)) in planes.iter().enumerate() {
        // A right-handed basis of the plane (u × v = n), about the origin's foot.
        let helper = if n.x.abs() < 0.9 {
            Vector3::x()
        } else {
            Vector3::y()
        };
        let u = n.cross(&helper).normalize();
        let v = n.cross(&u);
        let foot = n * d;
        let half = 2.0 * (reach + d.abs());
        let mut polygon = Polygon::rectangle(Vector2::new(half, half));
        for (j, &(m, e)) in planes.iter().enumerate() {
            if j != k {
                // m·(foot + s u + t v) ≤ e.
                polygon.clip(&Vector2::new(m.dot(&u), m.dot(&v)), e - m.dot(&foot), 4);
            }
        }
        let corners = polygon.vertices();
        if corners.len() < 3 {
            continue;
        }
        if corners.len() > FACE_CORNERS || count == out.len() {
            return None;
        }
        let mut face = Face {
            normal: n,
            offset: d,
            corners: [foot; FACE_CORNERS],
            count: corners.len(),
        };
        for (c, p) in face.corners.iter_mut().zip(corners) {
            *c = foot + p.x * u + p.y * v;
        }
        out[count] = face;
        count += 1;
    }
    Some(count)
}
