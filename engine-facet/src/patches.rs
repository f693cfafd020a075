//! Whole subtrees of a mesh's OBB tree as surface patches, so the inside flood of
//! [`crate::contact_region`] can take a patch lying wholly inside the other solid in one step
//! instead of triangle by triangle.
//!
//! The triangles are numbered in the tree's leaf order ([`crate::facet_mesh::FacetMesh::build`]),
//! so each node's triangles are one contiguous range. Per node this index keeps:
//! - its parent and its range of triangles;
//! - whether its triangles form one edge-connected patch (counted exactly, bottom-up: a node's
//!   components are its children's less the unions made across the edges between them). A
//!   patch that is connected and that no triangle of the other surface crosses lies wholly
//!   inside the other solid or wholly outside it, so one inside triangle places all of it;
//! - for nodes of at least [`MIN_PATCH`] triangles, the patch's cone sums as polynomials in the
//!   apex, about the node's box centre ([`PatchSums`]), so a query's cone sums over the patch
//!   cost one evaluation, not one per triangle; its rim, the neighbours outside it of its
//!   triangles, so a flood goes on from the patch without reading its inside (a patch of `k`
//!   triangles has some `3√k` of them); and its border, its triangles with a neighbour outside
//!   it, the only ones a flood can reach from outside, so only they are marked when it is taken.
//!
//! ## The cone sums as polynomials in the apex
//! For a triangle `(a, b, c)` with coordinates about a centre `m` and the apex `o`, `e = o − m`:
//! the tetrahedron's six-fold volume is `det(a, b, c) − e·N` (`N = (b − a)×(c − a)`, the same
//! about any centre) and its moment about `o` is that volume times `(a + b + c − 3e)/24`. Summed
//! over a patch they need `D = Σ det`, `Σ N`, `P = Σ det·s` and `Q = Σ s Nᵀ` (`s = a + b + c`):
//! volume `(D − e·ΣN)/6`, moment `(P − 3eD − Qe + 3(e·ΣN)e)/24`. Taken about the patch's own
//! centre, each term is of the patch's size, so the round-off stays relative to the patch and
//! its distance to the apex, as it does triangle by triangle.

use crate::obb_tree::ObbTree;
use crate::surface_sums::SurfaceSums;
use contact_core::{Matrix3, Point3, Vector3};

/// The fewest triangles a node must hold to keep precomputed sums and rim; smaller patches are
/// summed, and their rims found, triangle by triangle when taken (storing them would cost more
/// memory than it saves time).
pub const MIN_PATCH: u32 = 32;

/// No parent (the root) or no precomputed sums.
const NONE: u32 = u32::MAX;

/// A patch's cone sums as polynomials in the apex, about the node's box centre.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PatchSums {
    /// The centre `m` the coordinates are taken about.
    pub center: Vector3,
    /// `Σ det(a, b, c)`.
    pub det: f64,
    /// `Σ N`, twice the patch's vector area.
    pub normal: Vector3,
    /// `Σ det · s`.
    pub det_s: Vector3,
    /// `Σ s Nᵀ`.
    pub s_normal: Matrix3,
}

impl PatchSums {
    /// The sums of one triangle about `center`.
    fn triangle(a: &Vector3, b: &Vector3, c: &Vector3, center: &Vector3) -> Self {
        let (p, q, r) = (a - center, b - center, c - center);
        let det = p.dot(&q.cross(&r));
        let normal = (q - p).cross(&(r - p));
        let s = p + q + r;
        Self {
            center: *center,
            det,
            normal,
            det_s: det * s,
            s_normal: s * normal.transpose(),
        }
    }

    /// The same sums about another centre.
    fn about(&self, center: &Vector3) -> Self {
        let e = center - self.center;
        let en = e.dot(&self.normal);
        Self {
            center: *center,
            det: self.det - en,
            normal: self.normal,
            det_s: self.det_s - 3.0 * self.det * e - self.s_normal * e + 3.0 * en * e,
            s_normal: self.s_normal - 3.0 * e * self.normal.transpose(),
        }
    }

    fn add(&mut self, o: &Self) {
        self.det += o.det;
        self.normal += o.normal;
        self.det_s += o.det_s;
        self.s_normal += o.s_normal;
    }

    /// The cone sums about `apex` (same frame).
    pub fn cones(&self, apex: &Vector3) -> SurfaceSums {
        let e = apex - self.center;
        let en = e.dot(&self.normal);
        SurfaceSums {
            volume: (self.det - en) / 6.0,
            moment: (self.det_s - 3.0 * self.det * e - self.s_normal * e + 3.0 * en * e) / 24.0,
        }
    }
}

/// The patch index of one mesh (see the module doc).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PatchIndex {
    /// Per node: its parent, or `u32::MAX` for the root.
    pub parent: Vec<u32>,
    /// Per node: its triangles `first..end`.
    pub range: Vec<(u32, u32)>,
    /// Per node: its triangles form one edge-connected patch.
    pub connected: Vec<bool>,
    /// Per triangle: its leaf.
    pub leaf_of: Vec<u32>,
    /// Per node: the index of its sums in `sums`, or `u32::MAX` below [`MIN_PATCH`].
    pub sums_slot: Vec<u32>,
    /// The precomputed sums.
    pub sums: Vec<PatchSums>,
    /// Per precomputed slot `k`, its rim is `rim[rim_start[k]..rim_start[k + 1]]`.
    pub rim_start: Vec<u32>,
    /// The rims: each stored patch's triangles' neighbours outside it, in triangle and edge
    /// order (a neighbour across two edges appears twice).
    pub rim: Vec<u32>,
    /// Per precomputed slot `k`, its border is `border[border_start[k]..border_start[k + 1]]`.
    pub border_start: Vec<u32>,
    /// The borders: each stored patch's triangles with a neighbour outside it, in order.
    pub border: Vec<u32>,
}

/// How many edges join two sibling nodes' triangle ranges (`[first, end)` each), joined in
/// `union_find`; found from the smaller range's side.
fn join_children(
    union_find: &mut UnionFind,
    neighbors: &[[u32; 3]],
    left: (u32, u32),
    right: (u32, u32),
) -> u32 {
    let (small, large) = if left.1 - left.0 <= right.1 - right.0 {
        (left, right)
    } else {
        (right, left)
    };
    let mut joined = 0;
    for t in small.0..small.1 {
        for &m in &neighbors[t as usize] {
            if m >= large.0 && m < large.1 && union_find.union(t, m) {
                joined += 1;
            }
        }
    }
    joined
}

/// The patches stored whole (at least [`MIN_PATCH`] triangles): their slots, sums, rims and
/// borders, as [`PatchIndex`] keeps them.
struct Stored {
    sums_slot: Vec<u32>,
    sums: Vec<PatchSums>,
    rim_start: Vec<u32>,
    rim: Vec<u32>,
    border_start: Vec<u32>,
    border: Vec<u32>,
}

impl Stored {
    /// From each node's triangle range and sums, and the mesh's neighbours.
    fn of(range: &[(u32, u32)], all_sums: &[PatchSums], neighbors: &[[u32; 3]]) -> Self {
        let mut stored = Self {
            sums_slot: vec![NONE; range.len()],
            sums: Vec::new(),
            rim_start: vec![0],
            rim: Vec::new(),
            border_start: vec![0],
            border: Vec::new(),
        };
        for (i, &(first, end)) in range.iter().enumerate() {
            if end - first < MIN_PATCH {
                continue;
            }
            stored.sums_slot[i] = stored.sums.len() as u32;
            stored.sums.push(all_sums[i]);
            for t in first..end {
                let before = stored.rim.len();
                for &m in &neighbors[t as usize] {
                    if m < first || m >= end {
                        stored.rim.push(m);
                    }
                }
                if stored.rim.len() > before {
                    stored.border.push(t);
                }
            }
            stored.rim_start.push(stored.rim.len() as u32);
            stored.border_start.push(stored.border.len() as u32);
        }
        stored
    }
}

impl PatchIndex {
    /// Builds the index over a tree whose leaves hold their triangles in order
    /// ([`ObbTree::renumber_in_leaf_order`] done), with the mesh's neighbours.
    pub fn build(
        tree: &ObbTree,
        vertices: &[Point3],
        triangles: &[[u32; 3]],
        neighbors: &[[u32; 3]],
    ) -> Self {
        let nodes = tree.nodes();
        let n = nodes.len();
        let mut parent = vec![NONE; n];
        let mut range = vec![(0, 0); n];
        let mut leaf_of = vec![0; triangles.len()];
        let mut all_sums = vec![PatchSums::default(); n];
        // Edge-connected components per node, exact: one union-find over the triangles, joined
        // bottom-up across the edges inside each leaf and between each node's two children.
        let mut components = vec![0u32; n];
        let mut union_find = UnionFind::new(triangles.len());
        let corner = |t: u32, k: usize| vertices[triangles[t as usize][k] as usize].coords;
        // Children follow their parent in the array: backwards, every child comes first.
        for i in (0..n).rev() {
            let node = &nodes[i];
            let center = node.obb.center;
            if node.count > 0 {
                let (first, end) = (node.index, node.index + node.count);
                range[i] = (first, end);
                let mut sums = PatchSums {
                    center,
                    ..PatchSums::default()
                };
                for t in first..end {
                    leaf_of[t as usize] = i as u32;
                    sums.add(&PatchSums::triangle(
                        &corner(t, 0),
                        &corner(t, 1),
                        &corner(t, 2),
                        &center,
                    ));
                }
                all_sums[i] = sums;
                components[i] = (end - first) - join_across(&mut union_find, neighbors, first, end);
            } else {
                let (left, right) = (i + 1, node.index as usize);
                parent[left] = i as u32;
                parent[right] = i as u32;
                range[i] = (range[left].0, range[right].1);
                let mut sums = all_sums[left].about(&center);
                sums.add(&all_sums[right].about(&center));
                all_sums[i] = sums;
                let joined = join_children(&mut union_find, neighbors, range[left], range[right]);
                components[i] = components[left] + components[right] - joined;
            }
        }
        let connected = components.iter().map(|&c| c == 1).collect();
        let stored = Stored::of(&range, &all_sums, neighbors);
        Self {
            parent,
            range,
            connected,
            leaf_of,
            sums_slot: stored.sums_slot,
            sums: stored.sums,
            rim_start: stored.rim_start,
            rim: stored.rim,
            border_start: stored.border_start,
            border: stored.border,
        }
    }

    /// The node's cone sums about `apex`, precomputed or (below [`MIN_PATCH`]) summed from its
    /// triangles given by `corners`.
    #[inline]
    pub fn cones(
        &self,
        node: u32,
        apex: &Vector3,
        corners: impl Fn(u32) -> [Vector3; 3],
    ) -> SurfaceSums {
        let slot = self.sums_slot[node as usize];
        if slot != NONE {
            return self.sums[slot as usize].cones(apex);
        }
        let mut sums = SurfaceSums::default();
        let (first, end) = self.range[node as usize];
        for t in first..end {
            let [p, q, r] = corners(t);
            sums.add_triangle(&p, &q, &r, apex);
        }
        sums
    }

    /// Calls `f` with each neighbour outside the node of each of its triangles (in triangle and
    /// edge order), from the stored rim or, below [`MIN_PATCH`], from the triangles.
    #[inline]
    pub fn for_each_rim(&self, node: u32, neighbors: &[[u32; 3]], mut f: impl FnMut(u32)) {
        let slot = self.sums_slot[node as usize];
        if slot != NONE {
            let (start, end) = (
                self.rim_start[slot as usize] as usize,
                self.rim_start[slot as usize + 1] as usize,
            );
            for &m in &self.rim[start..end] {
                f(m);
            }
            return;
        }
        let (first, end) = self.range[node as usize];
        for t in first..end {
            for &m in &neighbors[t as usize] {
                if m < first || m >= end {
                    f(m);
                }
            }
        }
    }

    /// Calls `f` with each of the node's triangles that has a neighbour outside it, from the
    /// stored border or, below [`MIN_PATCH`], from the triangles.
    #[inline]
    pub fn for_each_border(&self, node: u32, neighbors: &[[u32; 3]], mut f: impl FnMut(u32)) {
        let slot = self.sums_slot[node as usize];
        if slot != NONE {
            let (start, end) = (
                self.border_start[slot as usize] as usize,
                self.border_start[slot as usize + 1] as usize,
            );
            for &t in &self.border[start..end] {
                f(t);
            }
            return;
        }
        let (first, end) = self.range[node as usize];
        for t in first..end {
            if neighbors[t as usize].iter().any(|&m| m < first || m >= end) {
                f(t);
            }
        }
    }

    /// The parent of `node`, `None` at the root.
    #[inline]
    pub fn parent_of(&self, node: u32) -> Option<u32> {
        let p = self.parent[node as usize];
        (p != NONE).then_some(p)
    }

    /// Heap bytes held.
    pub fn heap_bytes(&self) -> usize {
        self.parent.capacity() * 4
            + self.range.capacity() * 8
            + self.connected.capacity()
            + self.leaf_of.capacity() * 4
            + self.sums_slot.capacity() * 4
            + self.sums.capacity() * std::mem::size_of::<PatchSums>()
            + (self.rim_start.capacity() + self.rim.capacity()) * 4
            + (self.border_start.capacity() + self.border.capacity()) * 4
    }
}

/// The unions made across the edges between triangles of `first..end` (a leaf's own edges).
fn join_across(uf: &mut UnionFind, neighbors: &[[u32; 3]], first: u32, end: u32) -> u32 {
    let mut joined = 0;
    for t in first..end {
        for &m in &neighbors[t as usize] {
            if m >= first && m < t && uf.union(t, m) {
                joined += 1;
            }
        }
    }
    joined
}

/// Union-find over triangles, with path halving.
struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    fn new(n: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
        }
    }

    fn find(&mut self, mut i: u32) -> u32 {
        while self.parent[i as usize] != i {
            let p = self.parent[i as usize];
            self.parent[i as usize] = self.parent[p as usize];
            i = p;
        }
        i
    }

    /// Joins the sets of `i` and `j`; true when they were apart.
    fn union(&mut self, i: u32, j: u32) -> bool {
        let (ri, rj) = (self.find(i), self.find(j));
        if ri == rj {
            return false;
        }
        self.parent[ri.max(rj) as usize] = ri.min(rj);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The polynomial sums, shifted between centres and evaluated at an apex, against the
    /// cones summed triangle by triangle about that apex.
    #[test]
    fn shifted_patch_sums_give_the_cones_about_any_apex() {
        let v = |x: f64, y: f64, z: f64| Vector3::new(x, y, z);
        let tris = [
            [v(0.1, 0.2, 0.3), v(1.3, -0.2, 0.5), v(0.4, 1.1, -0.7)],
            [v(-0.5, 0.9, 0.2), v(0.6, 0.4, 1.2), v(-1.1, -0.3, 0.8)],
            [v(2.0, 0.1, -0.4), v(0.3, -1.5, 0.2), v(1.0, 0.6, 1.9)],
        ];
        let (m1, m2) = (v(0.7, -0.4, 0.2), v(-3.0, 2.0, 5.0));
        let mut about_m1 = PatchSums {
            center: m1,
            ..PatchSums::default()
        };
        for t in &tris {
            about_m1.add(&PatchSums::triangle(&t[0], &t[1], &t[2], &m1));
        }
        let shifted = about_m1.about(&m2);
        for apex in [v(0.0, 0.0, 0.0), v(4.0, -1.0, 2.5), v(0.3, 0.3, 0.3)] {
            let mut direct = SurfaceSums::default();
            for t in &tris {
                direct.add_triangle(&t[0], &t[1], &t[2], &apex);
            }
            for sums in [about_m1, shifted] {
                let got = sums.cones(&apex);
                assert!(
                    (got.volume - direct.volume).abs() < 1e-13,
                    "{got:?} {direct:?}"
                );
                assert!(
                    (got.moment - direct.moment).norm() < 1e-13,
                    "{got:?} {direct:?}"
                );
            }
        }
    }
}
