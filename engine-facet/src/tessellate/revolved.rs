//! Cylinders and frusta: two rings of `n` vertices joined by quads, closed by fans at the caps.

use super::circle::{segments_for_circle, unit_circle};
use super::{Counts, Tessellation};
use contact_core::geometry::{Cylinder, Frustum};
use contact_core::{Point3, Vector3};

pub(super) fn counts(bottom: f64, top: f64, deviation: f64) -> Counts {
    let n = segments_for_circle(bottom.max(top), deviation);
    let rings = u64::from(bottom > 0.0) + u64::from(top > 0.0);
    Counts {
        segments: n,
        vertices: n.saturating_mul(rings).saturating_add(2),
        triangles: n.saturating_mul(2 * rings),
    }
}

/// A cylinder (bottom face at z = 0, axis +z): `n = n(r, δ)` segments, `4n` triangles.
pub fn cylinder(c: &Cylinder, deviation: f64) -> Tessellation {
    revolved(c.radius(), c.radius(), c.length(), deviation)
}

/// A frustum (bottom radius at z = 0, top at z = length); a zero radius becomes an apex vertex.
pub fn frustum(f: &Frustum, deviation: f64) -> Tessellation {
    revolved(f.bottom_radius(), f.top_radius(), f.length(), deviation)
}

fn revolved(r0: f64, r1: f64, length: f64, deviation: f64) -> Tessellation {
    let n = segments_for_circle(r0.max(r1), deviation) as usize;
    let ring = unit_circle(n);
    // The side's true normal: radial, tilted by the cone's slope (r0 − r1)/length.
    let slope = (r0 - r1) / length;
    let side_normal = |k: usize| Vector3::new(ring[k].0, ring[k].1, slope).normalize();
    let mut vertices = vec![Point3::origin(), Point3::new(0.0, 0.0, length)];
    let mut ring_start = [None, None];
    for (level, (r, z)) in [(r0, 0.0), (r1, length)].into_iter().enumerate() {
        if r > 0.0 {
            ring_start[level] = Some(vertices.len() as u32);
            vertices.extend(ring.iter().map(|&(c, s)| Point3::new(r * c, r * s, z)));
        }
    }
    let mut triangles = Vec::new();
    let mut corner_normals = Vec::new();
    let at = |start: u32, k: usize| start + (k % n) as u32;
    for k in 0..n {
        let (nk, nk1) = (side_normal(k), side_normal((k + 1) % n));
        match ring_start {
            [Some(b), Some(t)] => {
                triangles.push([at(b, k), at(b, k + 1), at(t, k + 1)]);
                corner_normals.push([nk, nk1, nk1]);
                triangles.push([at(b, k), at(t, k + 1), at(t, k)]);
                corner_normals.push([nk, nk1, nk]);
                triangles.push([0, at(b, k + 1), at(b, k)]);
                corner_normals.push([-Vector3::z(); 3]);
                triangles.push([1, at(t, k), at(t, k + 1)]);
                corner_normals.push([Vector3::z(); 3]);
            }
            [Some(b), None] => {
                triangles.push([at(b, k), at(b, k + 1), 1]);
                let apex = (0.5 * (nk + nk1)).normalize();
                corner_normals.push([nk, nk1, apex]);
                triangles.push([0, at(b, k + 1), at(b, k)]);
                corner_normals.push([-Vector3::z(); 3]);
            }
            [None, Some(t)] => {
                triangles.push([0, at(t, k + 1), at(t, k)]);
                let apex = (0.5 * (nk + nk1)).normalize();
                corner_normals.push([apex, nk1, nk]);
                triangles.push([1, at(t, k), at(t, k + 1)]);
                corner_normals.push([Vector3::z(); 3]);
            }
            // Frustum::new rejects two zero radii.
            [None, None] => {}
        }
    }
    Tessellation {
        vertices,
        triangles,
        corner_normals,
    }
}
