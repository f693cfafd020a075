//! Ellipsoids (and spheres) as UV spheres scaled by the semi-axes.

use super::circle::{segments_for_circle, unit_circle};
use super::{Counts, Tessellation};
use contact_core::geometry::Ellipsoid;
use contact_core::{Point3, Vector3};
use std::f64::consts::PI;

fn sizes(e: &Ellipsoid, deviation: f64) -> (u64, u64) {
    let a = e.semi_axes().max();
    let n = segments_for_circle(a, 0.5 * deviation);
    let m = n.div_ceil(2).max(2);
    (n, m)
}

pub(super) fn counts(e: &Ellipsoid, deviation: f64) -> Counts {
    let (n, m) = sizes(e, deviation);
    Counts {
        segments: n,
        vertices: n.saturating_mul(m - 1).saturating_add(2),
        triangles: n.saturating_mul(m - 1).saturating_mul(2),
    }
}

/// A UV ellipsoid: `n` meridians, `m` latitude bands (poles on ±z), every vertex on the surface;
/// `n`, `m` from the module's table. Corner normals are the ellipsoid's true normals.
pub fn ellipsoid(e: &Ellipsoid, deviation: f64) -> Tessellation {
    let (n, m) = sizes(e, deviation);
    let (n, m) = (n as usize, m as usize);
    let s = e.semi_axes();
    let ring = unit_circle(n);
    let mut unit = Vec::with_capacity(n * (m - 1) + 2);
    unit.push(Vector3::new(0.0, 0.0, -1.0));
    for band in 1..m {
        let polar = PI * band as f64 / m as f64;
        let (z, rho) = (-polar.cos(), polar.sin());
        for &(c, sn) in &ring {
            unit.push(Vector3::new(rho * c, rho * sn, z));
        }
    }
    unit.push(Vector3::new(0.0, 0.0, 1.0));
    let vertices: Vec<Point3> = unit
        .iter()
        .map(|u| Point3::from(u.component_mul(&s)))
        .collect();
    // The normal of x²/a² + … = 1 at a point is the gradient (x/a², y/b², z/c²).
    let inv2 = Vector3::new(1.0 / (s.x * s.x), 1.0 / (s.y * s.y), 1.0 / (s.z * s.z));
    let normals: Vec<Vector3> = vertices
        .iter()
        .map(|p| p.coords.component_mul(&inv2).normalize())
        .collect();
    let top = (n * (m - 1) + 1) as u32;
    let at = |band: usize, k: usize| (1 + (band - 1) * n + k % n) as u32;
    let mut triangles = Vec::with_capacity(2 * n * (m - 1));
    for k in 0..n {
        triangles.push([0, at(1, k + 1), at(1, k)]);
    }
    for band in 1..m - 1 {
        for k in 0..n {
            let (a, b) = (at(band, k), at(band, k + 1));
            let (c, d) = (at(band + 1, k + 1), at(band + 1, k));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    for k in 0..n {
        triangles.push([top, at(m - 1, k), at(m - 1, k + 1)]);
    }
    let corner_normals = triangles
        .iter()
        .map(|t| t.map(|v| normals[v as usize]))
        .collect();
    Tessellation {
        vertices,
        triangles,
        corner_normals,
    }
}
