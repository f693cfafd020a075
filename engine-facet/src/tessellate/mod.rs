//! Tessellation: every native primitive to a closed, watertight, outward-oriented triangle mesh
//! (and 2-D circles, arcs and curves to polylines) at a faceting tolerance FT.
//!
//! ## The tolerance → segments mapping (SPEC §7)
//! A geometry with characteristic length `L` (its bounding-box diagonal,
//! [`Geometry::characteristic_length`]) is faceted so that no point of a facet lies farther than
//! `δ = L / FT` from the true surface. A circle of radius `r` cut into `n` equal chords deviates
//! by `r·(1 − cos(π/n))`, so the smallest `n` meeting a deviation `d` is
//!
//! ```text
//! n(r, d) = max(3, ⌈π / acos(1 − d/r)⌉)      (n = 3 when d ≥ r)
//! ```
//!
//! Per primitive ([`counts`] gives the numbers without building anything):
//!
//! | primitive | segments | vertices | triangles |
//! |---|---|---|---|
//! | ellipsoid, semi-axes `a ≥ b ≥ c` | `n = n(a, δ/2)` around, `m = max(2, ⌈n/2⌉)` bands | `n(m−1) + 2` | `2n(m−1)` |
//! | cylinder radius `r` | `n = n(r, δ)` | `2n + 2` | `4n` |
//! | frustum, radii `r₀, r₁` | `n = n(max(r₀, r₁), δ)` | `2n + 2` (`n` less for a zero radius) | `4n` (`2n` less for a zero radius) |
//! | box | — | 8 | 12 |
//! | torus `R, r` | `n = n(R + r, δ/2)` around, `k = n(r, δ/2)` round the tube | `nk` | `2nk` |
//!
//! Curved quads split into two triangles deviate up to twice their edge chords, so the ellipsoid
//! and torus use `δ/2` per direction; for an ellipsoid the deviation is bounded through the
//! largest semi-axis (the mesh is the linear image of a unit UV sphere). Vertices lie on the true
//! surface, so convex primitives are inscribed: faceted volumes are slightly smaller.
//! The counts change in steps (they are integers) and never fall as FT rises; above
//! [`MAX_TRIANGLES`] triangles for one geometry `prepare` fails with
//! [`PrepareError::TooManyTriangles`](contact_core::PrepareError::TooManyTriangles).
//! Planes (half-spaces) are not tessellated: triangle against half-space is exact.

mod circle;
mod cuboid;
mod ellipsoid;
mod polyline;
mod revolved;
mod torus;

pub use circle::segments_for_circle;
pub use cuboid::cuboid;
pub use ellipsoid::ellipsoid;
pub use polyline::{Polyline, arc_polyline, circle_polyline, curve_polyline};
pub use revolved::{cylinder, frustum};
pub use torus::torus;

use contact_core::geometry::Geometry;
use contact_core::{FacetingTolerance, Point3, Vector3};

/// The most triangles one geometry may be faceted into (16 million: about 1.5 GB of mesh and tree).
pub const MAX_TRIANGLES: u64 = 16_000_000;

/// A tessellated surface: vertices, counter-clockwise triangles seen from outside, and the exact
/// surface normal at each triangle corner (equal to the facet normal on flat faces), all in `G`.
#[derive(Debug, Clone, PartialEq)]
pub struct Tessellation {
    /// Vertices on the true surface.
    pub vertices: Vec<Point3>,
    /// Triangles as vertex indices.
    pub triangles: Vec<[u32; 3]>,
    /// The true outward unit normal at each corner of each triangle.
    pub corner_normals: Vec<[Vector3; 3]>,
}

/// Segment, vertex and triangle counts a tessellation would produce.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Counts {
    /// Segments of the main circle (0 for a box).
    pub segments: u64,
    /// Vertices.
    pub vertices: u64,
    /// Triangles.
    pub triangles: u64,
}

/// The counts the tessellation of `geometry` at `tolerance` would have, without building it.
/// `None` for geometry that is not tessellated into triangles (planes, meshes, 2-D shapes).
pub fn counts(geometry: &Geometry, tolerance: FacetingTolerance) -> Option<Counts> {
    let deviation = tolerance.chord_deviation(geometry.characteristic_length()?);
    match geometry {
        Geometry::Ellipsoid(e) => Some(ellipsoid::counts(e, deviation)),
        Geometry::Cylinder(c) => Some(revolved::counts(c.radius(), c.radius(), deviation)),
        Geometry::Frustum(f) => Some(revolved::counts(
            f.bottom_radius(),
            f.top_radius(),
            deviation,
        )),
        Geometry::Cuboid(_) => Some(Counts {
            segments: 0,
            vertices: 8,
            triangles: 12,
        }),
        Geometry::Torus(t) => Some(torus::counts(t, deviation)),
        Geometry::Plane(_)
        | Geometry::Mesh(_)
        | Geometry::Point
        | Geometry::Line(_)
        | Geometry::Circle(_)
        | Geometry::Arc(_)
        | Geometry::Curve(_) => None,
    }
}

/// Tessellates a 3-D primitive at `tolerance`; `None` for geometry that is not a primitive solid
/// (planes, meshes, 2-D shapes). Call [`counts`] first to check the size.
pub fn tessellate(geometry: &Geometry, tolerance: FacetingTolerance) -> Option<Tessellation> {
    let deviation = tolerance.chord_deviation(geometry.characteristic_length()?);
    match geometry {
        Geometry::Ellipsoid(e) => Some(ellipsoid(e, deviation)),
        Geometry::Cylinder(c) => Some(cylinder(c, deviation)),
        Geometry::Frustum(f) => Some(frustum(f, deviation)),
        Geometry::Cuboid(b) => Some(cuboid(b)),
        Geometry::Torus(t) => Some(torus(t, deviation)),
        Geometry::Plane(_)
        | Geometry::Mesh(_)
        | Geometry::Point
        | Geometry::Line(_)
        | Geometry::Circle(_)
        | Geometry::Arc(_)
        | Geometry::Curve(_) => None,
    }
}

/// Flat-face corner normals for triangles without curved-surface information (STL meshes).
pub fn flat_corner_normals(vertices: &[Point3], triangles: &[[u32; 3]]) -> Vec<[Vector3; 3]> {
    triangles
        .iter()
        .map(|&[a, b, c]| {
            let (a, b, c) = (
                vertices[a as usize],
                vertices[b as usize],
                vertices[c as usize],
            );
            let n = (b - a).cross(&(c - a));
            let n = n.try_normalize(0.0).unwrap_or_else(Vector3::z);
            [n; 3]
        })
        .collect()
}
