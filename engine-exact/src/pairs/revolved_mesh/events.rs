//! The heights where the overlap of a slice's mesh section with the solid's section changes
//! its combinatorics, besides the mesh's vertex heights: where a circle of the section
//! touches a triangle's section line inside its segment, and where a mesh edge pierces the
//! solid's lateral surface.
//!
//! - **Tangency.** A triangle's plane `n·x = d` meets the slice `z = t` in the line at
//!   distance `|d − n_z t| / |n_xy|` from the axis. Against a frustum's circle `r₀ + k t` that
//!   is linear in `t`; against a torus' circles `R ± √(ρ² − t²)`, squaring gives a quadratic.
//!   A height counts when the touching point (the foot of the axis on the line) lies on the
//!   segment.
//! - **Piercing.** The edge `A + s D` against the cone `|p_xy| = r₀ + k z` is a quadratic in
//!   `s`; against the torus `(|p|² + R² − ρ²)² = 4R²|p_xy|²` a quartic
//!   ([`crate::pairs::box_revolved::events::roots_in`]).

use super::Profile;
use super::section::SlicedTriangle;
use crate::pairs::box_revolved::events::{cone_piercing, roots_in, torus_piercing};
use crate::pairs::mesh_plane::PreparedMesh;
use contact_core::Vector3;

/// Adds the tangency and piercing heights strictly inside the profile's range to `heights`.
pub(super) fn add_events(
    sliced: &[SlicedTriangle],
    local: &[Vector3],
    mesh: &PreparedMesh,
    profile: &Profile,
    heights: &mut Vec<f64>,
) {
    let (z0, z1) = profile.range();
    let mut push = |t: f64| {
        if t > z0 && t < z1 {
            heights.push(t);
        }
    };
    for tri in sliced {
        let vertices = mesh.triangles[tri.index as usize];
        let [a, b, c] = vertices.map(|i| local[i as usize]);
        let n = (b - a).cross(&(c - a));
        let g = n.xy().norm();
        let d0 = n.dot(&a);
        let (lo, hi) = tri.range();
        let mut touch = |t: f64| {
            if !(t > lo && t < hi) {
                return;
            }
            let foot = n.xy() * ((d0 - n.z * t) / (g * g));
            let (p, _, q, _) = tri.segment(t);
            let d = q - p;
            let along = (foot - p).dot(&d) / d.norm_squared();
            if (0.0..=1.0).contains(&along) {
                push(t);
            }
        };
        match *profile {
            Profile::Frustum { r0, slope: k, .. } => {
                for sign in [1.0, -1.0] {
                    // d0 − n_z t = sign·g·(r0 + k t).
                    let denominator = n.z + sign * g * k;
                    if denominator != 0.0 {
                        touch((d0 - sign * g * r0) / denominator);
                    }
                }
            }
            Profile::Torus { big, small } => {
                // With u = (d0 − n_z t)/g = α − β t and the distance σu (σ = ±1):
                // (σu − R)² + t² − ρ² = 0, a quadratic in t.
                let (alpha, beta) = (d0 / g, n.z / g);
                for sigma in [1.0, -1.0] {
                    let (a0, b0) = (sigma * alpha - big, -sigma * beta);
                    let coefficients = [
                        a0 * a0 - small * small,
                        2.0 * a0 * b0,
                        b0 * b0 + 1.0,
                        0.0,
                        0.0,
                    ];
                    let (roots, count) = roots_in(&coefficients, lo.max(-small), hi.min(small));
                    for &t in &roots[..count] {
                        if sigma * (alpha - beta * t) >= 0.0 {
                            touch(t);
                        }
                    }
                }
            }
        }
        // Each edge once: from the triangle whose index is below its neighbour's (a neighbour
        // that is not sliced lies flat, and its edges at its height are vertex heights).
        for e in 0..3 {
            let other = mesh.neighbours[tri.index as usize][e];
            if other < tri.index {
                continue;
            }
            let (pa, pb) = (
                local[vertices[e] as usize],
                local[vertices[(e + 1) % 3] as usize],
            );
            let d = pb - pa;
            let (roots, count) = roots_in(&piercing(profile, &pa, &d), 0.0, 1.0);
            for &s in &roots[..count] {
                push(pa.z + s * d.z);
            }
        }
    }
}

/// The polynomial in `s` (coefficients of `s^k`) whose roots are where the edge
/// `start + s·d` crosses the solid's lateral surface.
fn piercing(profile: &Profile, start: &Vector3, d: &Vector3) -> [f64; 5] {
    match *profile {
        Profile::Frustum { r0, slope, .. } => cone_piercing(r0, slope, start, d),
        // A sphere (no major radius): |start + s d|² = ρ², whose quartic would be a square.
        Profile::Torus { big: 0.0, small } => [
            start.norm_squared() - small * small,
            2.0 * start.dot(d),
            d.norm_squared(),
            0.0,
            0.0,
        ],
        Profile::Torus { big, small } => torus_piercing(big, small, start, d),
    }
}
