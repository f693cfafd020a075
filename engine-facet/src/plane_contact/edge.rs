//! A region over a bounded plane's edge: SPEC §4 on the solid a bounded PLANE stands for.
//!
//! A bounded plane is the prism `P = {x0 ≤ x ≤ x1, y0 ≤ y ≤ y1, h ≤ 0}` under its rectangle
//! (`h` the height along its normal `n`). Where a region of mesh A reaches over an edge of
//! the rectangle, the intersection `A ∩ P` is closed by P's side faces as well as its top, so
//! its area vector tilts off `n` and its centroid moves in from the edge. Each triangle is
//! clipped by all five faces of P, and from the clipped polygons of A's surface alone:
//! - the area vector `S = Σ ½ (b − a) × (c − a)` and the normal `−S/|S|` (from J into I);
//! - the volume `V` and first moment `∫ q dV` (`q = p − o`, `o` the plane's origin), by the
//!   divergence theorem with fields that vanish on P's faces other than A's: `F = h·n`
//!   (`div F = 1`) and `F = (q − n h)·h + n h²/2` (`div F = q`). On the top `h = 0` and on
//!   the sides `n·n_side = 0`, so only A's clipped polygons add:
//!   `V = Σ ∫ h (n·n_A) dA`, `∫ q dV = Σ ∫ (q h − n h²/2)(n·n_A) dA`, integrands of degree
//!   one and two in position, integrated exactly by the triangles' edge-midpoint rule.
//!
//! The contact points follow the ray rule: the line through the centroid `g` along the
//! normal leaves A at the first facet it meets (lifted onto the PN patch, as elsewhere), and
//! leaves P through whichever face it reaches first. As for a region inside the rectangle,
//! the depth is held to the convex bound `3V/|S|` where the facets' own depth passes it.
//! Inside the rectangle this is the same contact [`super::region_contact`] gives.

use super::PlaneFrame;
use crate::contact_region::{LocalContact, clip};
use crate::facet_mesh::FacetMesh;
use contact_core::Vector3;
use contact_core::geometry::Plane;

/// The prism under a bounded plane's rectangle, in A's frame.
pub(super) struct Prism {
    origin: Vector3,
    /// The plane's x and y axes and normal.
    axes: [Vector3; 3],
    x: [f64; 2],
    y: [f64; 2],
}

impl Prism {
    pub(super) fn new(plane: &Plane, frame: &PlaneFrame) -> Self {
        Self {
            origin: frame.origin,
            axes: [
                frame.rot.column(0).into_owned(),
                frame.rot.column(1).into_owned(),
                frame.n,
            ],
            x: plane.x_range(),
            y: plane.y_range(),
        }
    }

    /// True when a corner of `c` lies beyond the rectangle's x or y range.
    pub(super) fn reaches_over_an_edge(&self, c: &[Vector3; 3]) -> bool {
        c.iter().any(|v| {
            let q = v - self.origin;
            let (u, w) = (self.axes[0].dot(&q), self.axes[1].dot(&q));
            u < self.x[0] || u > self.x[1] || w < self.y[0] || w > self.y[1]
        })
    }

    /// The five faces as `(outward unit normal, offset)`: inside where `normal·q ≤ offset`
    /// (an infinite offset: no face on that side).
    fn faces(&self) -> [(Vector3, f64); 5] {
        let [ex, ey, n] = self.axes;
        [
            (n, 0.0),
            (ex, self.x[1]),
            (-ex, -self.x[0]),
            (ey, self.y[1]),
            (-ey, -self.y[0]),
        ]
    }

    /// How far along `dir` (unit) the line from `q` (inside) leaves the prism: the nearest
    /// face ahead; `None` when no face is ahead.
    fn exit(&self, q: &Vector3, dir: &Vector3) -> Option<f64> {
        self.faces()
            .iter()
            .filter_map(|(normal, offset)| {
                let rate = normal.dot(dir);
                (rate > 0.0 && offset.is_finite()).then(|| (offset - normal.dot(q)) / rate)
            })
            .reduce(f64::min)
    }
}

/// The sums of one region over the prism.
#[derive(Default)]
struct Sums {
    vector_area: Vector3,
    volume: f64,
    /// `∫ q dV`.
    moment: Vector3,
}

impl Sums {
    /// A triangle `t` of A's clipped surface (relative to the origin).
    fn add_triangle(&mut self, n: &Vector3, t: [Vector3; 3]) {
        let area = 0.5 * (t[1] - t[0]).cross(&(t[2] - t[0]));
        let weight = n.dot(&area);
        self.vector_area += area;
        let h = |q: &Vector3| n.dot(q);
        let centre = (t[0] + t[1] + t[2]) / 3.0;
        self.volume += weight * h(&centre);
        let field = |q: Vector3| q * h(&q) - n * (0.5 * h(&q) * h(&q));
        let mids = [
            0.5 * (t[0] + t[1]),
            0.5 * (t[1] + t[2]),
            0.5 * (t[2] + t[0]),
        ];
        self.moment += weight * (field(mids[0]) + field(mids[1]) + field(mids[2])) / 3.0;
    }
}

/// The contact of the region of `triangles` of mesh A over the prism (see the module docs);
/// `None` when the clipped region has no volume or no area (it only touches P).
pub(super) fn edge_region_contact(
    a: &FacetMesh,
    prism: &Prism,
    triangles: impl Iterator<Item = u32> + Clone,
) -> Option<LocalContact> {
    let n = prism.axes[2];
    let mut sums = Sums::default();
    let (mut poly, mut next) = (Vec::with_capacity(8), Vec::with_capacity(8));
    for t in triangles.clone() {
        poly.clear();
        poly.extend(a.corners(t).iter().map(|c| c - prism.origin));
        for (normal, offset) in prism.faces().iter().filter(|(_, o)| o.is_finite()) {
            clip(&poly, &mut next, normal, &(normal * *offset));
            std::mem::swap(&mut poly, &mut next);
            if poly.len() < 3 {
                break;
            }
        }
        for k in 1..poly.len().saturating_sub(1) {
            sums.add_triangle(&n, [poly[0], poly[k], poly[k + 1]]);
        }
    }
    let section = sums.vector_area.norm();
    if !(sums.volume > 0.0 && section > 0.0) {
        return None;
    }
    let normal = -sums.vector_area / section;
    let g = sums.moment / sums.volume;
    let g_a = g + prism.origin;
    let (tri, on_facet) = a
        .first_ray_hit_among(triangles.clone(), &g_a, &(-normal))
        .unwrap_or_else(|| super::closest_in_region(a, triangles, &g_a));
    let point_j = g_a + normal * prism.exit(&g, &normal).unwrap_or(0.0);
    let point_i = if tri == u32::MAX {
        on_facet
    } else {
        a.lift_to_surface(tri, &on_facet)
    };
    let bound = 3.0 * sums.volume / section;
    let facets_depth = (point_j - on_facet).norm();
    if a.closed && bound.is_finite() && facets_depth > bound * (1.0 + 1e-9) {
        return Some(LocalContact {
            point_i: point_j - normal * bound,
            point_j,
            normal,
            penetration: bound,
            area: section,
        });
    }
    Some(LocalContact {
        point_i,
        point_j,
        normal,
        penetration: (point_j - point_i).norm(),
        area: section,
    })
}
