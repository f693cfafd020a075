//! Ring tori: `n` tube sections around the axis, `k` vertices round each.

use super::circle::{segments_for_circle, unit_circle};
use super::{Counts, Tessellation};
use contact_core::geometry::Torus;
use contact_core::{Point3, Vector3};

fn sizes(t: &Torus, deviation: f64) -> (u64, u64) {
    (
        segments_for_circle(t.major_radius() + t.minor_radius(), 0.5 * deviation),
        segments_for_circle(t.minor_radius(), 0.5 * deviation),
    )
}

pub(super) fn counts(t: &Torus, deviation: f64) -> Counts {
    let (n, k) = sizes(t, deviation);
    Counts {
        segments: n,
        vertices: n.saturating_mul(k),
        triangles: n.saturating_mul(k).saturating_mul(2),
    }
}

/// A torus about +z of `G`: `n` sections around the axis, `k` vertices round the tube.
pub fn torus(t: &Torus, deviation: f64) -> Tessellation {
    let (n, k) = sizes(t, deviation);
    let (n, k) = (n as usize, k as usize);
    let (big, small) = (t.major_radius(), t.minor_radius());
    let around = unit_circle(n);
    let tube = unit_circle(k);
    let mut vertices = Vec::with_capacity(n * k);
    let mut normals = Vec::with_capacity(n * k);
    for &(ca, sa) in &around {
        for &(ct, st) in &tube {
            let normal = Vector3::new(ct * ca, ct * sa, st);
            normals.push(normal);
            vertices.push(Point3::new(big * ca, big * sa, 0.0) + small * normal);
        }
    }
    let at = |i: usize, j: usize| ((i % n) * k + j % k) as u32;
    let mut triangles = Vec::with_capacity(2 * n * k);
    for i in 0..n {
        for j in 0..k {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
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
