//! Which pieces of a cylinder–polyhedron intersection's boundary are joined, to tell whether
//! the intersection of a component that is not convex is one region (see [`super::mesh`]).
//!
//! The nodes are the component's triangles (a piece of each inside the cylinder) and the two
//! caps' rims when wholly inside the solid. Two triangles are joined when
//! - they share an edge that runs into the cylinder's interior (both pieces hold its part
//!   there; [`join_edges`]);
//! - a cap's region runs between their section chords (the rim arc from one's leaving crossing
//!   to the other's entering one: `section_cap`);
//! - the cylinder's side inside the solid runs between their rim arcs ([`join_across_side`]):
//!   between consecutive ends of the arcs the generators' intervals inside the solid are
//!   bounded below and above by fixed arcs, in fixed order; each interval joins its two.
//!
//! Every join is a path inside one region, so nodes found in one set are one region; a region
//! whose pieces are joined only otherwise (a cap's hole, say) reads as two sets, and the caller
//! slices instead: the test errs only towards the slower, general method.

use super::Bound;
use crate::methods::mesh_parts::{MAX_PART_TRIANGLES, MeshPart};
use contact_core::Vector3;
use std::f64::consts::TAU;

/// The node of the top cap's rim (wholly inside the solid); the bottom's is the next.
pub(crate) const TOP_RIM: usize = MAX_PART_TRIANGLES;

/// Nodes: the triangles and the two rims.
const NODES: usize = MAX_PART_TRIANGLES + 2;

/// A union–find over the nodes, with the nodes that have a piece.
#[derive(Debug, Clone)]
pub(crate) struct Links {
    parent: [u8; NODES],
    present: [bool; NODES],
}

impl Links {
    /// No node present, none joined.
    pub fn new() -> Self {
        Self {
            parent: std::array::from_fn(|k| k as u8),
            present: [false; NODES],
        }
    }

    /// Node `k` has a piece of the boundary.
    pub fn piece(&mut self, k: usize) {
        self.present[k] = true;
    }

    /// Nodes `a` and `b` lie on one region's boundary.
    pub fn join(&mut self, a: usize, b: usize) {
        let (a, b) = (self.root(a), self.root(b));
        self.parent[a.max(b)] = a.min(b) as u8;
    }

    fn root(&mut self, mut k: usize) -> usize {
        while self.parent[k] as usize != k {
            self.parent[k] = self.parent[self.parent[k] as usize];
            k = self.parent[k] as usize;
        }
        k
    }

    /// Whether the present nodes are one set (none present is one region too: the cylinder
    /// inside the solid).
    pub fn one(&mut self) -> bool {
        let mut first = None;
        for k in 0..NODES {
            if self.present[k] {
                let root = self.root(k);
                if *first.get_or_insert(root) != root {
                    return false;
                }
            }
        }
        true
    }
}

/// Joins the triangles of `part` (corners `corners` in the working frame: radius `r`, caps at
/// `±h`) across each edge that runs into the cylinder's interior.
pub(crate) fn join_edges(
    links: &mut Links,
    part: &MeshPart,
    corners: &[[Vector3; 3]],
    r: f64,
    h: f64,
) {
    for (k, tri) in corners.iter().enumerate() {
        for e in 0..3 {
            let n = part.neighbours[k][e] as usize;
            if n > k && runs_inside(&tri[e], &tri[(e + 1) % 3], r, h) {
                links.join(k, n);
            }
        }
    }
}

/// Whether the segment `p → q` has a part of positive length strictly inside the cylinder of
/// radius `r` between `z = ±h`.
fn runs_inside(p: &Vector3, q: &Vector3, r: f64, h: f64) -> bool {
    let d = q - p;
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    if d.z == 0.0 {
        if p.z.abs() >= h {
            return false;
        }
    } else {
        let (a, b) = ((-h - p.z) / d.z, (h - p.z) / d.z);
        lo = lo.max(a.min(b));
        hi = hi.min(a.max(b));
    }
    // |p + λ d|² < r² in the plane: a λ² + 2 b λ + c < 0.
    let (a, b, c) = (
        d.xy().norm_squared(),
        p.xy().dot(&d.xy()),
        p.xy().norm_squared() - r * r,
    );
    if a == 0.0 {
        return c < 0.0 && hi > lo;
    }
    let disc = b * b - a * c;
    if disc.is_nan() || disc <= 0.0 {
        return false;
    }
    let root = disc.sqrt();
    lo = lo.max((-b - root) / a);
    hi = hi.min((-b + root) / a);
    hi > lo
}

/// Most arc ends the side's test takes (more: no joins across the side).
const MAX_ENDS: usize = 128;

/// Joins the owners of the rim arcs `bounds` that bound one interval of a generator inside the
/// solid, between each two consecutive arc ends (see the module doc).
pub(crate) fn join_across_side(links: &mut Links, bounds: &[Bound]) {
    if 2 * bounds.len() > MAX_ENDS {
        return;
    }
    let mut ends = [0.0f64; MAX_ENDS];
    let mut count = 0;
    for b in bounds {
        for angle in [b.arc.start, b.arc.start + 2.0 * b.arc.half_angle] {
            ends[count] = angle.rem_euclid(TAU);
            count += 1;
        }
    }
    let ends = &mut ends[..count];
    ends.sort_unstable_by(f64::total_cmp);
    let mut active = [(0.0f64, 0.0f64, 0usize); MAX_ENDS];
    for k in 0..count {
        let next = if k + 1 < count {
            ends[k + 1]
        } else {
            ends[0] + TAU
        };
        if next - ends[k] <= 1e-12 {
            continue;
        }
        let phi = 0.5 * (ends[k] + next);
        let (sin, cos) = phi.sin_cos();
        let mut n = 0;
        for b in bounds {
            if (phi - b.arc.start).rem_euclid(TAU) < 2.0 * b.arc.half_angle {
                active[n] = (
                    b.z[0] + b.z[1] * cos + b.z[2] * sin,
                    b.sign,
                    b.owner as usize,
                );
                n += 1;
            }
        }
        let active = &mut active[..n];
        active.sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
        // Lower and upper bounds alternate along a generator; where round-off blurs the
        // order, this piece joins nothing.
        let alternate = n % 2 == 0
            && active
                .chunks(2)
                .all(|pair| pair[0].1 < 0.0 && pair[1].1 > 0.0 && pair[0].0 < pair[1].0);
        if alternate {
            for pair in active.chunks(2) {
                links.join(pair[0].2, pair[1].2);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn present_nodes_joined_are_one() {
        let mut links = Links::new();
        assert!(links.one());
        links.piece(3);
        links.piece(7);
        assert!(!links.one());
        links.join(9, 7);
        links.join(3, 9);
        assert!(links.one());
        links.piece(TOP_RIM);
        assert!(!links.one());
    }

    #[test]
    fn an_edge_runs_inside_when_part_of_it_is_interior() {
        let (r, h) = (1.0, 1.0);
        let inside =
            |p: [f64; 3], q: [f64; 3]| runs_inside(&Vector3::from(p), &Vector3::from(q), r, h);
        assert!(inside([-2.0, 0.0, 0.0], [2.0, 0.0, 0.0]));
        assert!(inside([0.0, 0.0, -3.0], [0.0, 0.0, 3.0]));
        // Tangent to the side, on a cap's plane, and beside the cylinder: no.
        assert!(!inside([-2.0, 1.0, 0.0], [2.0, 1.0, 0.0]));
        assert!(!inside([-2.0, 0.0, 1.0], [2.0, 0.0, 1.0]));
        assert!(!inside([2.0, 0.0, -3.0], [2.0, 0.0, 3.0]));
        // Ending short of it.
        assert!(!inside([-3.0, 0.0, 0.0], [-1.5, 0.0, 0.0]));
    }
}
