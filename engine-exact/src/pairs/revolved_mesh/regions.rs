//! The regions of a revolved solid against a mesh, labelled once per piece between cuts (see
//! the module doc of [`super`]).
//!
//! Nodes are each piece's chords (at its middle: the same chords, in the same order, at every
//! height of the piece), then per piece a *full outer* and a *full inner circle* (a circle
//! wholly inside the mesh's section). Within a piece: chords along a loop, the two ends of each
//! arc, and each hole (a section loop wholly inside the overlap, clockwise, or a full inner
//! circle) with the first boundary a ray along `+x` from its rightmost point meets. Across a
//! cut: a triangle's chords that overlap just below and just above it, and a full circle with
//! the parts touching the same circle in the pieces next to it (the solid's surface inside the
//! mesh runs on across the cut).

use super::section::Crossing;
use super::{Setup, Slice};
use crate::pairs::box_mesh::{UnionFind, closed_loops};
use crate::pairs::mesh_plane::PreparedMesh;
use contact_core::{Vector2, Vector3};

/// The regions' nodes and which pieces have a full outer and a full inner circle.
pub(super) struct Labels {
    /// Node of chord `c` of piece `p`'s slice: `offsets[p] + c`.
    pub offsets: Vec<usize>,
    /// The full outer circle of piece `p` is node `chords + p`, the inner `chords + P + p`.
    pub chords: usize,
    pub outer: Vec<bool>,
    pub inner: Vec<bool>,
}

impl Labels {
    pub fn outer_node(&self, p: usize) -> usize {
        self.chords + p
    }

    pub fn inner_node(&self, p: usize) -> usize {
        self.chords + self.outer.len() + p
    }

    /// How many nodes in all.
    pub fn nodes(&self) -> usize {
        self.chords + 2 * self.outer.len()
    }
}

/// The slice of piece `p` where it is labelled (its middle), or `None` for an empty piece.
pub(super) fn middle(setup: &Setup, p: usize) -> Option<f64> {
    let (lo, hi) = (setup.cuts[p], setup.cuts[p + 1]);
    (hi > lo).then_some(0.5 * (lo + hi))
}

/// Labels the regions; the forest holds [`Labels::nodes`] nodes.
pub(super) fn label(setup: &Setup, local: &[Vector3]) -> (Labels, UnionFind) {
    let pieces = setup.cuts.len() - 1;
    let mut slice = Slice::default();
    let (offsets, chords) = chord_offsets(setup, &mut slice);
    let mut labels = Labels {
        offsets,
        chords,
        outer: vec![false; pieces],
        inner: vec![false; pieces],
    };
    let mut forest = UnionFind::new(labels.nodes());
    // The nodes touching each circle, per piece: arcs' chords and the full circle.
    let mut on_outer: Vec<Vec<u32>> = vec![Vec::new(); pieces];
    let mut on_inner: Vec<Vec<u32>> = vec![Vec::new(); pieces];
    let neighbours = &setup.mesh.neighbours;
    for p in 0..pieces {
        let Some(t) = middle(setup, p) else { continue };
        let (ro, ri) = setup.profile.circles(t);
        setup.slice(p, t, &mut slice);
        let node = |c: usize| (labels.offsets[p] + c) as u32;
        join_along_loops(&slice, labels.offsets[p], neighbours, &mut forest);
        for (crossings, touching) in [
            (&slice.outer, &mut on_outer[p]),
            (&slice.inner, &mut on_inner[p]),
        ] {
            for (i, _, _) in super::arcs(crossings) {
                let next = &crossings[(i + 1) % crossings.len()];
                forest.union(node(crossings[i].chord), node(next.chord));
                touching.push(node(crossings[i].chord));
            }
        }
        let outer_node = labels.outer_node(p) as u32;
        let inner_node = labels.inner_node(p) as u32;
        if slice.outer.is_empty() && ro > 0.0 {
            labels.outer[p] = inside_section(setup.mesh, local, t, &Vector2::new(ro, 0.0));
            if labels.outer[p] {
                on_outer[p].push(outer_node);
            }
        }
        if slice.inner.is_empty() && ri > 0.0 {
            labels.inner[p] = inside_section(setup.mesh, local, t, &Vector2::new(ri, 0.0));
            if labels.inner[p] {
                on_inner[p].push(inner_node);
            }
        }
        let rays = Rays {
            slice: &slice,
            ro,
            ri,
            offset: labels.offsets[p],
            outer_full: labels.outer[p].then_some(outer_node),
            inner_full: labels.inner[p].then_some(inner_node),
        };
        // A full inner circle is a hole of the part around it.
        if let Some(n) = rays.inner_full {
            if let Some(hit) = rays.first_hit(&Vector2::new(ri, 0.0)) {
                forest.union(n, hit);
            }
        }
        join_holes(&rays, neighbours, &mut forest);
    }
    join_across_cuts(setup, &labels, &mut forest);
    join_full_circles(&labels, [&on_outer, &on_inner], &mut forest);
    (labels, forest)
}

/// Each piece's first chord node (`offsets[p]`), labelling each non-empty piece at its
/// middle (in `slice`), and the chords in all.
fn chord_offsets(setup: &Setup, slice: &mut Slice) -> (Vec<usize>, usize) {
    let pieces = setup.cuts.len() - 1;
    let mut offsets = Vec::with_capacity(pieces);
    let mut chords = 0;
    for p in 0..pieces {
        offsets.push(chords);
        if let Some(t) = middle(setup, p) {
            setup.slice(p, t, slice);
            chords += slice.chords.len();
        }
    }
    (offsets, chords)
}

/// Joins the chords of one piece's `slice` (its chord nodes from `offset`) along their loops:
/// across a mesh edge, the neighbour's segment ends where this one starts (its last chord) and
/// starts where this one ends (its first).
fn join_along_loops(slice: &Slice, offset: usize, neighbours: &[[u32; 3]], forest: &mut UnionFind) {
    let node = |c: usize| (offset + c) as u32;
    // Chords joined along their loops: across a mesh edge, the neighbour's segment ends
    // where this one starts (its last chord) and starts where this one ends (its first).
    let mut by_triangle = std::collections::HashMap::with_capacity(slice.segments.len());
    for (k, seg) in slice.segments.iter().enumerate() {
        by_triangle.insert(seg.0, k);
    }
    let (first, last) = chord_ends(slice);
    for (c, &(k, a, e, _)) in slice.chords.iter().enumerate() {
        let (tri, start, start_edge, end, end_edge) = slice.segments[k];
        let across = |edge: u8| by_triangle.get(&neighbours[tri as usize][edge as usize]);
        if a == start {
            if let Some(&j) = across(start_edge) {
                if let Some(l) = last[j] {
                    forest.union(node(c), node(l));
                }
            }
        }
        if e == end {
            if let Some(&j) = across(end_edge) {
                if let Some(f) = first[j] {
                    forest.union(node(c), node(f));
                }
            }
        }
    }
}

/// Joins each full outer (inner) circle with the nodes touching the outer (inner) circle in
/// the pieces next to it (`on[0]` per piece for the outer, `on[1]` for the inner): the solid's
/// surface inside the mesh runs on across the cut.
fn join_full_circles(labels: &Labels, on: [&Vec<Vec<u32>>; 2], forest: &mut UnionFind) {
    let pieces = labels.outer.len();
    let [on_outer, on_inner] = on;
    for (full, on, node) in [
        (
            &labels.outer,
            on_outer,
            Labels::outer_node as fn(&Labels, usize) -> usize,
        ),
        (&labels.inner, on_inner, Labels::inner_node),
    ] {
        for p in (0..pieces).filter(|&p| full[p]) {
            for q in [p.wrapping_sub(1), p + 1] {
                for &n in on.get(q).into_iter().flatten() {
                    forest.union(node(labels, p) as u32, n);
                }
            }
        }
    }
}

/// Each segment's first and last chord in the slice.
fn chord_ends(slice: &Slice) -> (Vec<Option<usize>>, Vec<Option<usize>>) {
    let mut first = vec![None; slice.segments.len()];
    let mut last = vec![None; slice.segments.len()];
    for (c, &(k, ..)) in slice.chords.iter().enumerate() {
        first[k].get_or_insert(c);
        last[k] = Some(c);
    }
    (first, last)
}

/// Joins the chords of one triangle on the two sides of each cut that overlap along its
/// segment just below and just above the cut (a triangle's part inside the solid runs on
/// across a cut; a torus may cut one triangle into two parts, which then stay apart, and a
/// part that ends at the cut does not join the one that starts there).
fn join_across_cuts(setup: &Setup, labels: &Labels, forest: &mut UnionFind) {
    let pieces = setup.cuts.len() - 1;
    let (mut below, mut above) = (Slice::default(), Slice::default());
    let mut middle_slice = Slice::default();
    for p in 0..pieces.saturating_sub(1) {
        let (Some(_), Some(_)) = (middle(setup, p), middle(setup, p + 1)) else {
            continue;
        };
        let cut = setup.cuts[p + 1];
        // Just off the cut: far enough that round-off keeps each side's combinatorics.
        let off = |width: f64| {
            (1e-9 * width)
                .max(1e-15 * cut.abs().max(1.0))
                .min(0.5 * width)
        };
        let t_below = cut - off(cut - setup.cuts[p]);
        let t_above = cut + off(setup.cuts[p + 2] - cut);
        setup.slice(p, t_below, &mut below);
        setup.slice(p + 1, t_above, &mut above);
        // The nodes are the chords at each piece's middle; a slice just off a cut whose
        // height is a few ulps from its event may hold one more or one fewer (a chord of
        // round-off length), so the chords are matched to the middle's by their triangle and
        // their order along it, not by their index.
        let node_below = middle_nodes(setup, labels, p, &below, &mut middle_slice);
        let node_above = middle_nodes(setup, labels, p + 1, &above, &mut middle_slice);
        let along = |slice: &Slice, c: usize| {
            let (k, a, e, _) = slice.chords[c];
            let (_, p0, _, p1, _) = slice.segments[k];
            let d = p1 - p0;
            let dd = d.norm_squared().max(f64::MIN_POSITIVE);
            ((a - p0).dot(&d) / dd, (e - p0).dot(&d) / dd)
        };
        for (ca, node_a) in node_below.iter().enumerate() {
            let tri = below.segments[below.chords[ca].0].0;
            let (a0, a1) = along(&below, ca);
            for (cb, node_b) in node_above.iter().enumerate() {
                if above.segments[above.chords[cb].0].0 != tri {
                    continue;
                }
                let (b0, b1) = along(&above, cb);
                // Overlapping along most of the shorter one: a chord that vanishes at the cut
                // (a circle passing the segment's end) overlaps the chord that replaces it only
                // by its own vanishing length.
                let shared = a1.min(b1) - a0.max(b0);
                if shared > 1e-4 * (a1 - a0).max(b1 - b0) {
                    if let (Some(na), Some(nb)) = (node_a, node_b) {
                        forest.union(*na, *nb);
                    }
                }
            }
        }
    }
}

/// The node of each chord of `slice` (a slice of piece `p`): the chord of the piece's middle
/// on the same triangle with the same rank along it, `None` when the middle has no such chord.
fn middle_nodes(
    setup: &Setup,
    labels: &Labels,
    p: usize,
    slice: &Slice,
    scratch: &mut Slice,
) -> Vec<Option<u32>> {
    let Some(t) = middle(setup, p) else {
        return vec![None; slice.chords.len()];
    };
    setup.slice(p, t, scratch);
    let ranked = |s: &Slice| {
        let mut seen: std::collections::HashMap<u32, usize> = std::collections::HashMap::new();
        s.chords
            .iter()
            .map(|&(k, ..)| {
                let tri = s.segments[k].0;
                let rank = seen.entry(tri).or_insert(0);
                *rank += 1;
                (tri, *rank)
            })
            .collect::<Vec<_>>()
    };
    let at_middle = ranked(scratch);
    ranked(slice)
        .iter()
        .map(|key| {
            at_middle
                .iter()
                .position(|m| m == key)
                .map(|c| (labels.offsets[p] + c) as u32)
        })
        .collect()
}

/// Whether the point `x` of the slice `z = t` lies inside the mesh's solid: the parity of the
/// mesh's section segments crossing the ray from `x` along `+x` (every triangle crossing
/// `t`), the other way about for a mesh turned inside out (a cavity).
fn inside_section(mesh: &PreparedMesh, local: &[Vector3], t: f64, x: &Vector2) -> bool {
    let mut inside = mesh.inverted;
    for tri in &mesh.triangles {
        let v = tri.map(|i| local[i as usize]);
        let Some(s) = super::section::SlicedTriangle::new(0, v) else {
            continue;
        };
        let (lo, hi) = s.range();
        if !(lo < t && t < hi) {
            continue;
        }
        let (p, _, q, _) = s.segment(t);
        if (p.y > x.y) != (q.y > x.y) {
            let at = p.x + (x.y - p.y) / (q.y - p.y) * (q.x - p.x);
            if at > x.x {
                inside = !inside;
            }
        }
    }
    inside
}

/// A slice's boundaries as a ray along `+x` meets them.
struct Rays<'a> {
    slice: &'a Slice,
    ro: f64,
    ri: f64,
    /// The piece's first chord node.
    offset: usize,
    outer_full: Option<u32>,
    inner_full: Option<u32>,
}

impl Rays<'_> {
    /// The node of the first boundary the ray from `from` (inside the overlap) along `+x`
    /// meets: a chord's triangle, or the owner of the arc (or full circle) it reaches.
    fn first_hit(&self, from: &Vector2) -> Option<u32> {
        let tolerance = 1e-12 * self.ro.max(1.0);
        let slice = self.slice;
        let mut best = (f64::INFINITY, None);
        for (c, &(_, a, e, _)) in slice.chords.iter().enumerate() {
            let (lo, hi) = if a.y <= e.y { (a, e) } else { (e, a) };
            if !(lo.y <= from.y && from.y < hi.y) {
                continue;
            }
            let x = lo.x + (from.y - lo.y) / (hi.y - lo.y) * (hi.x - lo.x) - from.x;
            if x > tolerance && x < best.0 {
                best = (x, Some((self.offset + c) as u32));
            }
        }
        // The outer circle ahead; the inner circle if the ray runs into it from its left.
        let outer_x = (self.ro * self.ro - from.y * from.y).max(0.0).sqrt();
        let mut circle = (outer_x - from.x, true, outer_x);
        if self.ri > 0.0 && from.y.abs() < self.ri {
            let inner_x = -(self.ri * self.ri - from.y * from.y).sqrt();
            if inner_x - from.x > tolerance && inner_x - from.x < circle.0 {
                circle = (inner_x - from.x, false, inner_x);
            }
        }
        if best.0 <= circle.0 {
            return best.1;
        }
        let (crossings, full) = if circle.1 {
            (&slice.outer, self.outer_full)
        } else {
            (&slice.inner, self.inner_full)
        };
        let angle = from.y.atan2(circle.2);
        owner(crossings, angle)
            .map(|c| (self.offset + c) as u32)
            .or(full)
    }
}

/// The chord owning the arc that holds `angle`: the one at the crossing starting it, if it
/// leaves.
fn owner(crossings: &[Crossing], angle: f64) -> Option<usize> {
    if crossings.is_empty() {
        return None;
    }
    let i = crossings.partition_point(|x| x.angle <= angle);
    let start = &crossings[(i + crossings.len() - 1) % crossings.len()];
    start.leaves.then_some(start.chord)
}

/// Joins each hole (a section loop wholly inside the overlap, clockwise) to the part
/// around it.
fn join_holes(rays: &Rays, neighbours: &[[u32; 3]], forest: &mut UnionFind) {
    let slice = rays.slice;
    let whole: Vec<usize> = (0..slice.chords.len())
        .filter(|&c| slice.chords[c].3)
        .collect();
    let find = |tri: u32| {
        whole
            .iter()
            .position(|&c| slice.segments[slice.chords[c].0].0 == tri)
    };
    let next = |at: usize| {
        let (tri, _, _, _, end_edge) = slice.segments[slice.chords[whole[at]].0];
        find(neighbours[tri as usize][end_edge as usize])
    };
    closed_loops(whole.len(), next, |walk| {
        let area: f64 = walk
            .iter()
            .map(|&w| {
                let (_, a, e, _) = slice.chords[whole[w]];
                a.x * e.y - a.y * e.x
            })
            .sum();
        if area >= 0.0 {
            return;
        }
        let right = walk
            .iter()
            .map(|&w| slice.chords[whole[w]].1)
            .max_by(|a, b| a.x.total_cmp(&b.x))
            .unwrap_or_default();
        let hole = (rays.offset + whole[walk[0]]) as u32;
        if let Some(node) = rays.first_hit(&right) {
            forest.union(hole, node);
        }
    });
}
