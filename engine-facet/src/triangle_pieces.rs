//! A crossing triangle cut into the pieces its crossing segments bound, so that two regions
//! crossing one large triangle of the other surface stay two (step 2 of
//! [`crate::contact_region`]).
//!
//! The segments on a triangle `T` (its hits) are the trace of the other surface on `T`: they cut
//! `T` into faces lying alternately inside and outside the other solid. Each hit bounds exactly
//! one inside face (on its inside side: on `T` of A, against B's outward normal, `−(n_B −
//! (n_B·n_A) n_A)`; on `T` of B, `−(n_A − (n_A·n_B) n_B)`). A region of the intersection passes
//! through `T` along its inside faces, so the triangle's node is split by inside face: one
//! *piece* (a node of its own) per group of hits bounding the same inside face.
//!
//! ## Method
//! 1. **Chains.** A hit whose segment ends on an edge of its other triangle continues, across
//!    that edge, into the hit of the neighbouring triangle there: they are one chain of the
//!    trace. (Two triangles of the other surface that merely share an edge may both cross `T`
//!    in segments that never meet: the shared edge passes `T`'s plane outside `T`.) A
//!    triangle with one chain is one piece (nearly every triangle: this step reads only the
//!    segments' ends and the other triangles' neighbours).
//! 2. **Chains bounding one inside face.** For two chains `C_i`, `C_j`: their closest pair of
//!    points `q_i`, `q_j` and its midpoint `m`. No point of `C_i` or `C_j` is nearer to `m` than
//!    `|q_i − q_j|/2`, so the open segment `q_i q_j` crosses neither; if it crosses no other
//!    chain of `T` either, it lies in one face, and that face is inside when `m` lies on the
//!    inside side of both chains (judged, where the nearest point is a chain's corner, by the
//!    segment whose line lies farthest from `m`, as a point-in-polygon test by the nearest edge
//!    does). The chains are then one piece. Chains meeting within `1e-12` of the mesh's size
//!    are one curve (a trace through a corner of the other mesh, whose triangles share no
//!    edge). The test is sufficient, not necessary: an inside face so bent that the segment
//!    between its two chains' closest points leaves it is taken as two pieces.
//! 3. **Edges.** A flood across an edge of a split triangle belongs to the piece holding the
//!    edge's midpoint: the piece of the segment nearest to it (no other segment can cut the
//!    straight path to the nearest one). An edge the trace crosses (a segment ends on it)
//!    belongs to no piece: it runs in and out of the other solid, its corners may lie in two
//!    regions, and the curve's continuation into the neighbouring triangle
//!    ([`crate::contact_region`]) already joins the pieces that meet across it.
//!
//! The rest of the method runs on pieces as it does on triangles: each piece is clipped by the
//! planes of its own hits only, and a hit unites the pieces it bounds on either side.

use crate::contact_region::{RelativePose, corners_in_a};
use crate::facet_mesh::FacetMesh;
use crate::piece_boundary::side_of_nearest;
use crate::scratch::{Hit, RegionNode, Scratch};
use crate::triangle_pair::Feature;
use contact_core::Vector3;

/// No further piece of the triangle.
pub(crate) const NO_PIECE: u32 = u32::MAX;

/// Every edge of an unsplit triangle belongs to its one node.
pub(crate) const ALL_EDGES: u8 = 0b111;

/// Buffers for splitting one triangle.
#[derive(Debug, Default)]
pub(crate) struct PieceScratch {
    /// `(other triangle, local hit)` for the triangle being split, sorted.
    others: Vec<(u32, u32)>,
    /// Union-find parents: of the local hits (chains), then of the chains (pieces).
    parent: Vec<u32>,
    /// Each local hit's chain.
    chain_of: Vec<u32>,
    group: Vec<u32>,
    /// Each chain's group root, while the groups are formed.
    roots: Vec<u32>,
    /// Each chain's piece.
    piece_of_chain: Vec<u32>,
    /// Each piece's edges (bit `e`: edge `e`).
    edges: Vec<u8>,
    segments: Vec<Segment>,
    /// The triangle's hits in piece order.
    reordered: Vec<(u32, u32)>,
}

/// Splits every crossing triangle whose hits bound more than one inside face (see the module
/// docs). Nodes are the crossing triangles' nodes, their hit lists filled; new pieces are
/// appended to `s.nodes`, linked from the triangle's first node by `next_piece`, and the slots
/// keep the first node.
pub(crate) fn split_crossing_triangles(
    a: &FacetMesh,
    b: &FacetMesh,
    x: &RelativePose,
    s: &mut Scratch,
) {
    let count = s.nodes.len();
    for id in 0..count {
        if s.nodes[id].hit_count >= 2 {
            split(a, b, x, s, id as u32);
        }
    }
}

/// The triangle `own` of the other surface that hit `h` crosses, seen from `side`.
#[inline]
fn other_triangle(side: u8, hit: &Hit) -> u32 {
    if side == 0 { hit.tb } else { hit.ta }
}

fn find(parent: &mut [u32], mut i: u32) -> u32 {
    while parent[i as usize] != i {
        let p = parent[parent[i as usize] as usize];
        parent[i as usize] = p;
        i = p;
    }
    i
}

fn unite(parent: &mut [u32], i: u32, j: u32) {
    let (ri, rj) = (find(parent, i), find(parent, j));
    if ri != rj {
        parent[ri.max(rj) as usize] = ri.min(rj);
    }
}

fn split(a: &FacetMesh, b: &FacetMesh, x: &RelativePose, s: &mut Scratch, id: u32) {
    let node = s.nodes[id as usize];
    let (own_mesh, other_mesh) = if node.side == 0 { (a, b) } else { (b, a) };
    let range = node.hit_start as usize..(node.hit_start + node.hit_count) as usize;
    let Scratch {
        hits,
        node_hits,
        pieces: w,
        nodes,
        ..
    } = &mut *s;
    let local: &[u32] = &node_hits[range.clone()];
    if local.len() <= SMALL && one_chain(node.side, local, hits, other_mesh) {
        return;
    }
    let chains = w.label_chains(node.side, local, hits, other_mesh);
    if chains == 1 {
        return;
    }
    w.segments.clear();
    w.segments.extend(
        local
            .iter()
            .map(|&h| Segment::of(node.side, &hits[h as usize])),
    );
    let pieces = w.group_chains(chains, 1e-12 * own_mesh.size);
    if pieces == 1 {
        return;
    }
    let corners = corners_in_a(own_mesh, node.side, node.tri, x);
    let crossed = crossed_edges(node.side, local, hits, &corners, 1e-12 * own_mesh.size);
    w.assign_edges(&corners, pieces, crossed);
    // The hits in piece order; the first piece keeps the node, the others get nodes of their
    // own, linked in order.
    w.reordered.clear();
    w.reordered.extend(
        local
            .iter()
            .enumerate()
            .map(|(i, &h)| (w.piece_of_chain[w.chain_of[i] as usize], h)),
    );
    w.reordered.sort_by_key(|e| e.0);
    for (slot, &(_, h)) in node_hits[range].iter_mut().zip(&w.reordered) {
        *slot = h;
    }
    w.make_pieces(nodes, id, pieces);
}

impl PieceScratch {
    /// Step 1: each local hit's chain in `chain_of`; returns the number of chains.
    fn label_chains(
        &mut self,
        side: u8,
        local: &[u32],
        hits: &[Hit],
        other_mesh: &FacetMesh,
    ) -> u32 {
        let k = local.len();
        self.others.clear();
        self.others.extend(
            local
                .iter()
                .enumerate()
                .map(|(i, &h)| (other_triangle(side, &hits[h as usize]), i as u32)),
        );
        self.others.sort_unstable();
        self.parent.clear();
        self.parent.extend(0..k as u32);
        for (i, &h) in local.iter().enumerate() {
            for nb in continuations(side, &hits[h as usize], other_mesh) {
                if let Ok(m) = self.others.binary_search_by_key(&nb, |e| e.0) {
                    unite(&mut self.parent, i as u32, self.others[m].1);
                }
            }
        }
        self.chain_of.clear();
        let mut chains = 0u32;
        for i in 0..k as u32 {
            let root = find(&mut self.parent, i);
            let c = if root == i {
                chains += 1;
                chains - 1
            } else {
                self.chain_of[root as usize]
            };
            self.chain_of.push(c);
        }
        chains
    }

    /// Step 2: chains bounding one inside face are one piece (`piece_of_chain`); returns the
    /// number of pieces.
    fn group_chains(&mut self, chains: u32, touch: f64) -> u32 {
        let normal = self.segments[0].own_normal;
        self.group.clear();
        self.group.extend(0..chains);
        for ci in 0..chains {
            for cj in ci + 1..chains {
                if find(&mut self.group, ci) == find(&mut self.group, cj) {
                    continue;
                }
                // Chains already found to be one curve with `ci` or `cj` block nothing
                // between them.
                self.roots.clear();
                for c in 0..chains {
                    let root = find(&mut self.group, c);
                    self.roots.push(root);
                }
                let (ri, rj) = (self.roots[ci as usize], self.roots[cj as usize]);
                let roots = &self.roots;
                let apart = |k: u32| roots[k as usize] != ri && roots[k as usize] != rj;
                if one_face(
                    &self.segments,
                    &self.chain_of,
                    ci,
                    cj,
                    apart,
                    &normal,
                    touch,
                ) {
                    unite(&mut self.group, ci, cj);
                }
            }
        }
        self.piece_of_chain.clear();
        self.piece_of_chain.resize(chains as usize, NO_PIECE);
        let mut pieces = 0u32;
        for c in 0..chains {
            let root = find(&mut self.group, c);
            if self.piece_of_chain[root as usize] == NO_PIECE {
                self.piece_of_chain[root as usize] = pieces;
                pieces += 1;
            }
            self.piece_of_chain[c as usize] = self.piece_of_chain[root as usize];
        }
        pieces
    }

    /// Step 3: each edge of the triangle (`corners`) the trace does not cross to the piece of
    /// the segment nearest its midpoint, in `edges`; the edges in `crossed` to none.
    fn assign_edges(&mut self, corners: &[Vector3; 3], pieces: u32, crossed: u8) {
        self.edges.clear();
        self.edges.resize(pieces as usize, 0);
        for e in 0..3 {
            if crossed & (1 << e) != 0 {
                continue;
            }
            let mid = 0.5 * (corners[e] + corners[(e + 1) % 3]);
            let nearest = self
                .segments
                .iter()
                .enumerate()
                .map(|(i, s)| (s.distance_to(&mid), i))
                .min_by(|u, v| u.0.total_cmp(&v.0))
                .map_or(0, |(_, i)| i);
            let p = self.piece_of_chain[self.chain_of[nearest] as usize] as usize;
            self.edges[p] |= 1 << e;
        }
    }

    /// The pieces as nodes: node `id` keeps the first, new nodes the others, each holding its
    /// run of the reordered hits, its edges, and the link to the next.
    fn make_pieces(&self, nodes: &mut Vec<RegionNode>, id: u32, pieces: u32) {
        let node = nodes[id as usize];
        let mut start = node.hit_start;
        let mut previous = id;
        for p in 0..pieces {
            let count = self.reordered.iter().filter(|e| e.0 == p).count() as u32;
            let piece_id = if p == 0 {
                id
            } else {
                let new_id = nodes.len() as u32;
                nodes.push(RegionNode {
                    parent: new_id,
                    ..node
                });
                nodes[previous as usize].next_piece = new_id;
                new_id
            };
            let piece = &mut nodes[piece_id as usize];
            piece.hit_start = start;
            piece.hit_count = count;
            piece.edges = self.edges[p as usize];
            piece.split = true;
            piece.next_piece = NO_PIECE;
            start += count;
            previous = piece_id;
        }
    }
}

/// The edges of the triangle on `side` (corners `corners`) that its hits `local` end on (bit
/// `k`: edge `k`): the trace crosses them. An end counts by its feature (a corner for both its
/// edges) and by its place, within `touch` of the edge: where an edge of this triangle crosses
/// an edge of the other surface, the two cuts' ends coincide and the feature names either.
fn crossed_edges(side: u8, local: &[u32], hits: &[Hit], corners: &[Vector3; 3], touch: f64) -> u8 {
    let mut crossed = 0u8;
    for &h in local {
        let hit = &hits[h as usize];
        for end in hit.ends {
            if end.first == (side == 0) {
                crossed |= match end.feature {
                    Feature::Edge(k) => 1 << k,
                    Feature::Corner(k) => (1 << k) | (1 << ((k + 2) % 3)),
                };
            }
        }
        for p in [hit.s0, hit.s1] {
            for k in 0..3 {
                let (a, b) = (corners[k], corners[(k + 1) % 3]);
                let d = b - a;
                let t = ((p - a).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
                if (a + d * t - p).norm() <= touch {
                    crossed |= 1 << k;
                }
            }
        }
    }
    crossed
}

/// Triangles with this many hits or fewer are first checked for one chain directly.
const SMALL: usize = 8;

/// The triangles of the other surface the trace of `hit` goes on into from its own other
/// triangle: the neighbours across the edges of that triangle its segment ends on (a corner
/// counts for both its edges). Two triangles of the other surface that only share an edge
/// meet the triangle being split in segments that continue into each other only where the
/// segment ends on that edge; elsewhere the shared edge crosses the plane outside it.
fn continuations(side: u8, hit: &Hit, other_mesh: &FacetMesh) -> impl Iterator<Item = u32> {
    let u = other_triangle(side, hit) as usize;
    let neighbors = other_mesh.neighbors[u];
    hit.ends.into_iter().flat_map(move |end| {
        let edges = if end.first == (side == 0) {
            // An end on the triangle's own boundary: the trace goes on in the triangle's
            // neighbour, not along this triangle.
            [None, None]
        } else {
            match end.feature {
                Feature::Edge(k) => [Some(k), None],
                Feature::Corner(k) => [Some(k), Some((k + 2) % 3)],
            }
        };
        edges
            .into_iter()
            .flatten()
            .map(move |k| neighbors[k as usize])
            .filter(|&nb| nb != crate::facet_mesh::NO_NEIGHBOR)
    })
}

/// Whether the hits (at most [`SMALL`]) form one chain: grown from the first hit through the
/// [`continuations`] of its segment's ends.
fn one_chain(side: u8, local: &[u32], hits: &[Hit], other_mesh: &FacetMesh) -> bool {
    let mut others = [0u32; SMALL];
    for (o, &h) in others.iter_mut().zip(local) {
        *o = other_triangle(side, &hits[h as usize]);
    }
    let others = &others[..local.len()];
    let all = (1u32 << others.len()) - 1;
    let mut reached = 1u32;
    let mut frontier = 1u32;
    while frontier != 0 {
        let i = frontier.trailing_zeros() as usize;
        frontier &= frontier - 1;
        for nb in continuations(side, &hits[local[i] as usize], other_mesh) {
            for (j, u) in others.iter().enumerate() {
                if reached & (1 << j) == 0 && *u == nb {
                    reached |= 1 << j;
                    frontier |= 1 << j;
                }
            }
        }
    }
    reached == all
}

/// A hit's segment on the triangle being split, with the triangle's normal and the direction,
/// in its plane, into the other solid.
#[derive(Debug, Clone, Copy)]
struct Segment {
    p: Vector3,
    q: Vector3,
    own_normal: Vector3,
    inward: Vector3,
}

impl Segment {
    fn of(side: u8, hit: &Hit) -> Self {
        let (own, other) = if side == 0 {
            (hit.plane_a.0, hit.plane_b.0)
        } else {
            (hit.plane_b.0, hit.plane_a.0)
        };
        Self {
            p: hit.s0,
            q: hit.s1,
            own_normal: own,
            inward: -(other - other.dot(&own) * own),
        }
    }

    /// The closest point to `m` and its distance.
    fn closest(&self, m: &Vector3) -> (Vector3, f64) {
        let d = self.q - self.p;
        let len2 = d.norm_squared();
        let t = if len2 > 0.0 {
            ((m - self.p).dot(&d) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let c = self.p + d * t;
        (c, (m - c).norm())
    }

    /// The segment's ends and its inward direction, as [`side_of_nearest`] takes them.
    fn with_inward(&self) -> (Vector3, Vector3, Vector3) {
        (self.p, self.q, self.inward)
    }

    fn distance_to(&self, m: &Vector3) -> f64 {
        self.closest(m).1
    }
}

/// The closest points of two segments (clamped parameters, as in Ericson's *Real-Time
/// Collision Detection* §5.1.9).
fn closest_pair(s: &Segment, t: &Segment) -> (Vector3, Vector3) {
    let (d1, d2, r) = (s.q - s.p, t.q - t.p, s.p - t.p);
    let (a, e, f) = (d1.norm_squared(), d2.norm_squared(), d2.dot(&r));
    let (mut u, mut v);
    if a <= f64::MIN_POSITIVE && e <= f64::MIN_POSITIVE {
        return (s.p, t.p);
    }
    if a <= f64::MIN_POSITIVE {
        u = 0.0;
        v = (f / e).clamp(0.0, 1.0);
    } else {
        let c = d1.dot(&r);
        if e <= f64::MIN_POSITIVE {
            v = 0.0;
            u = (-c / a).clamp(0.0, 1.0);
        } else {
            let b = d1.dot(&d2);
            let denom = a * e - b * b;
            u = if denom > 0.0 {
                ((b * f - c * e) / denom).clamp(0.0, 1.0)
            } else {
                0.0
            };
            v = (b * u + f) / e;
            if v < 0.0 {
                v = 0.0;
                u = (-c / a).clamp(0.0, 1.0);
            } else if v > 1.0 {
                v = 1.0;
                u = ((b - c) / a).clamp(0.0, 1.0);
            }
        }
    }
    (s.p + d1 * u, t.p + d2 * v)
}

/// Whether chains `ci` and `cj` bound one inside face (module docs, step 2); only the chains
/// `apart` from both (not one curve with either) can block the way between them.
fn one_face(
    segments: &[Segment],
    chain_of: &[u32],
    ci: u32,
    cj: u32,
    apart: impl Fn(u32) -> bool,
    normal: &Vector3,
    touch: f64,
) -> bool {
    let of = |c: u32| {
        segments
            .iter()
            .zip(chain_of)
            .filter(move |(_, k)| **k == c)
            .map(|(s, _)| s)
    };
    let mut best = (f64::INFINITY, Vector3::zeros(), Vector3::zeros());
    for s in of(ci) {
        for t in of(cj) {
            let (p, q) = closest_pair(s, t);
            let d = (p - q).norm();
            if d < best.0 {
                best = (d, p, q);
            }
        }
    }
    let (gap, qi, qj) = best;
    if gap <= touch {
        return true;
    }
    // A segment no longer than `touch` (an infinitesimal trace where the other surface's
    // vertex touches this triangle's plane) separates nothing.
    let blocked = segments
        .iter()
        .zip(chain_of)
        .filter(|(s, k)| apart(**k) && (s.q - s.p).norm() > touch)
        .any(|(s, _)| crosses(&qi, &qj, s, normal));
    if blocked {
        return false;
    }
    let m = 0.5 * (qi + qj);
    side_of_nearest(of(ci).map(Segment::with_inward), &m) > 0.0
        && side_of_nearest(of(cj).map(Segment::with_inward), &m) > 0.0
}

/// Whether segment `s` meets the segment `p q` in the triangle's plane (normal `n`); touching
/// counts as meeting. A point of one on the other's line counts only within the other's
/// extent (a segment of zero length, a trace's tip at a vertex of the other surface, lies on
/// every line through it).
fn crosses(p: &Vector3, q: &Vector3, s: &Segment, n: &Vector3) -> bool {
    let orient = |a: &Vector3, b: &Vector3, c: &Vector3| n.dot(&(b - a).cross(&(c - a)));
    let (o1, o2) = (orient(p, q, &s.p), orient(p, q, &s.q));
    let (o3, o4) = (orient(&s.p, &s.q, p), orient(&s.p, &s.q, q));
    if o1 * o2 < 0.0 && o3 * o4 < 0.0 {
        return true;
    }
    // Touching: an end of one on the other (collinear with it, within its extent).
    let within = |a: &Vector3, b: &Vector3, c: &Vector3| {
        (0..3).all(|k| a[k].min(b[k]) <= c[k] && c[k] <= a[k].max(b[k]))
    };
    (o1 == 0.0 && within(p, q, &s.p))
        || (o2 == 0.0 && within(p, q, &s.q))
        || (o3 == 0.0 && within(&s.p, &s.q, p))
        || (o4 == 0.0 && within(&s.p, &s.q, q))
}
