//! A top-down OBB tree over a triangle mesh, and the simultaneous descent of two trees.
//!
//! Nodes sit in one flat array in depth-first order (a node's first child follows it), each
//! holding its box axes, centre and half extents in the mesh frame, so a descent walks memory
//! forward. Build: fit a box to the node's triangles, split the triangles at the mean of their
//! centroids along the box's longest axis (at the median when that leaves a side empty),
//! recurse until at most [`LEAF_TRIANGLES`] remain. A small node whose facets face one way
//! (see [`COHERENT_NORMALS`], [`PATCH_FRAME_MAX_TRIANGLES`]) is a patch of surface: its box
//! takes the mean normal as its thin axis and the parent's axis most nearly in the patch's
//! plane as its first, with no eigen solve. Other nodes (the root, large nodes, a patch that
//! wraps round) take the principal axes of their vertex covariance, and keep the box in their
//! parent's axes instead when that one is smaller. A leaf's box is the smallest of those in
//! its triangles' own frames (edge, in-plane perpendicular, facet normal: flat and tight) and
//! its patch frame.

use crate::obb::{Obb, boxes_overlap_in_frame};
use contact_core::{Matrix3, Point3, Vector3, WorkCounters};

/// Triangles per leaf at most: four rather than two gives a third fewer box tests in a descent
/// and half the nodes, for more triangle pairs, which the contact search screens a leaf at a
/// time without branches (measurements: `docs/performance.md`).
pub const LEAF_TRIANGLES: usize = 4;

/// A node of at most [`PATCH_FRAME_MAX_TRIANGLES`] triangles is boxed in its mean-normal frame
/// when `|Σ aₖ nₖ| ≥ COHERENT_NORMALS · Σ aₖ` over its facets (areas `aₖ`, unit normals `nₖ`):
/// their normals agree to within some 45° on average.
pub const COHERENT_NORMALS: f64 = 0.7;

/// Nodes larger than this take principal axes even when their normals agree: a large coherent
/// patch is better served by its principal axes, whose longest one the split follows
/// (measurements: `docs/performance.md`).
pub const PATCH_FRAME_MAX_TRIANGLES: usize = 128;

/// One node: its box and either its right child (internal) or its triangle range (leaf).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Node {
    /// The box.
    pub obb: Obb,
    /// Internal: index of the right child (the left child is the next node). Leaf: the first
    /// entry in [`ObbTree::order`].
    pub index: u32,
    /// Triangles in a leaf; 0 for an internal node.
    pub count: u32,
    /// Radius of the box's bounding sphere (the half-diagonal), for a cheap first test.
    pub radius: f64,
}

/// The tree: nodes in depth-first order and the triangle order its leaves refer to.
#[derive(Debug, Clone, PartialEq)]
pub struct ObbTree {
    nodes: Vec<Node>,
    order: Vec<u32>,
}

impl ObbTree {
    /// Builds the tree over `triangles` (vertex indices into `vertices`).
    pub fn build(vertices: &[Point3], triangles: &[[u32; 3]]) -> Self {
        let centroids: Vec<Vector3> = triangles
            .iter()
            .map(|t| {
                (vertices[t[0] as usize].coords
                    + vertices[t[1] as usize].coords
                    + vertices[t[2] as usize].coords)
                    / 3.0
            })
            .collect();
        // Area-weighted facet normals (the edge cross products), summed per node for its frame.
        let area_normals: Vec<Vector3> = triangles
            .iter()
            .map(|t| {
                let [p, q, r] = t.map(|v| vertices[v as usize]);
                (q - p).cross(&(r - p))
            })
            .collect();
        let mut order: Vec<u32> = (0..triangles.len() as u32).collect();
        let mut nodes = Vec::with_capacity(2 * triangles.len() / LEAF_TRIANGLES + 1);
        // Explicit stack of (node slot, range start, range end, parent's axes) to build
        // depth-first.
        let mut pending = vec![(usize::MAX, 0usize, order.len(), None::<Matrix3>)];
        while let Some((parent, start, end, parent_axes)) = pending.pop() {
            let slot = nodes.len();
            if parent != usize::MAX {
                let p: &mut Node = &mut nodes[parent];
                p.index = slot as u32;
            }
            let range = &mut order[start..end];
            let points = range
                .iter()
                .flat_map(|&t| triangles[t as usize].iter().map(|&v| vertices[v as usize]));
            let obb = if range.len() <= LEAF_TRIANGLES {
                leaf_box(
                    vertices,
                    triangles,
                    &area_normals,
                    range,
                    parent_axes.as_ref(),
                )
            } else {
                let patch = parent_axes.filter(|_| range.len() <= PATCH_FRAME_MAX_TRIANGLES);
                match patch.and_then(|axes| patch_frame(&area_normals, range, &axes)) {
                    Some(axes) => Obb::fit_with_axes(points.clone(), axes),
                    None => Obb::fit(points.clone()),
                }
            };
            if range.len() <= LEAF_TRIANGLES {
                nodes.push(Node {
                    obb,
                    index: start as u32,
                    count: range.len() as u32,
                    radius: obb.half_extents.norm(),
                });
                continue;
            }
            let axis_index = obb.half_extents.imax();
            let axis = obb.axes.column(axis_index).into_owned();
            // The split follows the node's own frame, but the box kept is the smaller of its
            // own and its parent's axes' (see `smaller_box`).
            let obb = match parent_axes {
                Some(axes) => smaller_box(obb, Obb::fit_with_axes(points, axes)),
                None => obb,
            };
            let key = |t: &u32| centroids[*t as usize].dot(&axis);
            let mean = range.iter().map(key).sum::<f64>() / range.len() as f64;
            let mut split = partition(range, |t| key(t) < mean);
            if split == 0 || split == range.len() {
                split = range.len() / 2;
                range.select_nth_unstable_by(split, |x, y| key(x).total_cmp(&key(y)));
            }
            nodes.push(Node {
                obb,
                index: 0,
                count: 0,
                radius: obb.half_extents.norm(),
            });
            // Right pushed first so the left child is built next, right after its parent.
            pending.push((slot, start + split, end, Some(obb.axes)));
            pending.push((usize::MAX, start, start + split, Some(obb.axes)));
        }
        Self { nodes, order }
    }

    /// The nodes, root first.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// Triangle indices in leaf order.
    pub fn order(&self) -> &[u32] {
        &self.order
    }

    /// The root box.
    pub fn root(&self) -> &Obb {
        &self.nodes[0].obb
    }

    /// Triangles of a leaf node.
    pub fn leaf_triangles(&self, node: &Node) -> &[u32] {
        &self.order[node.index as usize..(node.index + node.count) as usize]
    }

    /// Renumbers the triangles in leaf order: returns the old index of each new one (the old
    /// [`order`](Self::order)) and leaves `order` the identity, so every subtree's triangles
    /// are one contiguous range and a leaf's neighbours in the tree are near it in memory.
    /// The caller must reorder its per-triangle data by the returned permutation.
    pub fn renumber_in_leaf_order(&mut self) -> Vec<u32> {
        let identity = (0..self.order.len() as u32).collect();
        std::mem::replace(&mut self.order, identity)
    }

    /// Heap bytes held.
    pub fn heap_bytes(&self) -> usize {
        self.nodes.capacity() * std::mem::size_of::<Node>() + self.order.capacity() * 4
    }

    /// Calls `leaf` with each triangle in the subtree of node `node`, in leaf order.
    pub fn visit_subtree(&self, node: u32, mut leaf: impl FnMut(u32)) {
        let mut stack = vec![node as usize];
        while let Some(i) = stack.pop() {
            let n = &self.nodes[i];
            if n.count > 0 {
                self.leaf_triangles(n).iter().for_each(|&t| leaf(t));
            } else {
                stack.push(n.index as usize);
                stack.push(i + 1);
            }
        }
    }

    /// Visits every node whose box passes `keep` (given the box; a failing node's subtree is
    /// skipped) and calls `leaf` with each triangle of a kept leaf.
    pub fn visit(&self, mut keep: impl FnMut(&Obb) -> bool, mut leaf: impl FnMut(u32)) {
        let mut i = 0;
        let mut stack: Vec<usize> = Vec::new();
        loop {
            let node = &self.nodes[i];
            if keep(&node.obb) {
                if node.count > 0 {
                    for &t in self.leaf_triangles(node) {
                        leaf(t);
                    }
                } else {
                    stack.push(node.index as usize);
                    i += 1;
                    continue;
                }
            }
            match stack.pop() {
                Some(next) => i = next,
                None => return,
            }
        }
    }
}

/// A leaf's box: of the frames of its triangles (each its first edge, the in-plane
/// perpendicular and its normal: flat boxes) and, when its facets face one way, its patch frame
/// (see [`patch_frame`]), the one giving the box of least surface area (measurements:
/// `docs/performance.md`).
fn leaf_box(
    vertices: &[Point3],
    triangles: &[[u32; 3]],
    area_normals: &[Vector3],
    range: &[u32],
    parent_axes: Option<&Matrix3>,
) -> Obb {
    let points = || {
        range
            .iter()
            .flat_map(|&t| triangles[t as usize].iter().map(|&v| vertices[v as usize]))
    };
    let triangle_frame = |t: u32| {
        let [p, q, _] = triangles[t as usize].map(|v| vertices[v as usize]);
        let e = (q - p).try_normalize(0.0)?;
        let n = area_normals[t as usize].try_normalize(0.0)?;
        Some(Matrix3::from_columns(&[e, n.cross(&e), n]))
    };
    // The first triangle's frame, or for a degenerate one any frame: every leaf gets a box.
    let first = triangle_frame(range[0]).unwrap_or_else(|| {
        let [p, q, _] = triangles[range[0] as usize].map(|v| vertices[v as usize]);
        let e = (q - p).try_normalize(0.0).unwrap_or_else(Vector3::x);
        let n = e
            .cross(&Vector3::y())
            .try_normalize(0.0)
            .unwrap_or_else(Vector3::z);
        Matrix3::from_columns(&[e, n.cross(&e), n])
    });
    let others = range[1..].iter().filter_map(|&t| triangle_frame(t));
    let patch = parent_axes
        .filter(|_| range.len() > 1)
        .and_then(|axes| patch_frame(area_normals, range, axes));
    others
        .chain(patch)
        .fold(Obb::fit_with_axes(points(), first), |best, axes| {
            smaller_box(best, Obb::fit_with_axes(points(), axes))
        })
}

/// Of two boxes around the same points, the one of least surface area (the first on a tie).
/// An internal node's box is the smaller of its own frame's and its parent's axes'.
fn smaller_box(first: Obb, second: Obb) -> Obb {
    let surface = |o: &Obb| {
        let h = o.half_extents;
        h.x * h.y + h.y * h.z + h.z * h.x
    };
    if surface(&second) < surface(&first) {
        second
    } else {
        first
    }
}

/// The frame of a patch whose facets face one way (see [`COHERENT_NORMALS`]): the mean normal
/// as the third axis, the parent's axis with the largest part in the patch's plane, made
/// perpendicular to it, as the first. `None` when the normals do not agree (or the facets have
/// no area).
fn patch_frame(area_normals: &[Vector3], range: &[u32], parent_axes: &Matrix3) -> Option<Matrix3> {
    let (sum, total) = range.iter().fold((Vector3::zeros(), 0.0), |(s, a), &t| {
        let n = area_normals[t as usize];
        (s + n, a + n.norm())
    });
    let length = sum.norm();
    if !(total > 0.0 && length >= COHERENT_NORMALS * total) {
        return None;
    }
    let n = sum / length;
    let in_plane = |c: usize| {
        let axis = parent_axes.column(c);
        axis - n * n.dot(&axis)
    };
    let first = (0..3)
        .map(in_plane)
        .max_by(|u, v| u.norm_squared().total_cmp(&v.norm_squared()))?
        .try_normalize(0.0)?;
    Some(Matrix3::from_columns(&[first, n.cross(&first), n]))
}

/// Moves the elements satisfying `left` to the front; returns how many there are.
fn partition(items: &mut [u32], left: impl Fn(&u32) -> bool) -> usize {
    let mut k = 0;
    for i in 0..items.len() {
        if left(&items[i]) {
            items.swap(i, k);
            k += 1;
        }
    }
    k
}

/// B's node boxes moved into A's frame, computed at most once per node per query (a node of B
/// meets several nodes of A during a descent). One entry per node holds the stamp, centre and
/// axes side by side, so a lookup touches one place in memory rather than three arrays.
#[derive(Debug, Default)]
pub struct BoxCache {
    entries: Vec<CachedBox>,
    generation: u32,
}

/// One node's box in A's frame, valid for the generation in its stamp.
#[derive(Debug, Clone, Copy)]
struct CachedBox {
    /// `2g − 1`: the centre is moved for generation `g`; `2g`: the axes too.
    stamp: u32,
    center: Vector3,
    axes: Matrix3,
}

impl BoxCache {
    fn reset(&mut self, n: usize) {
        if self.entries.len() < n {
            self.entries.resize(
                n,
                CachedBox {
                    stamp: 0,
                    center: Vector3::zeros(),
                    axes: Matrix3::zeros(),
                },
            );
        }
        // Stamps use 2g − 1 and 2g, so generations stay below 2³¹.
        self.generation += 1;
        if self.generation >= 1 << 31 {
            for e in &mut self.entries {
                e.stamp = 0;
            }
            self.generation = 1;
        }
    }
}

/// Descends two trees at once and calls `on_pair` with every pair of triangles (indices into
/// the meshes) whose leaf boxes overlap. `rot_ab`, `t_ab`: the pose of B's mesh frame in A's
/// (`X_AB`). The larger box of a pair is split first. Counts box tests in `work`.
#[expect(
    clippy::too_many_arguments,
    reason = "scratch buffers are passed in to avoid allocation"
)]
pub fn descend_pair(
    a: &ObbTree,
    b: &ObbTree,
    rot_ab: &Matrix3,
    t_ab: &Vector3,
    stack: &mut Vec<(u32, u32)>,
    cache: &mut BoxCache,
    work: &mut WorkCounters,
    mut on_pair: impl FnMut(u32, u32),
) {
    descend_leaf_pairs(a, b, rot_ab, t_ab, stack, cache, work, |la, lb| {
        for &ta in la {
            for &tb in lb {
                on_pair(ta, tb);
            }
        }
    });
}

/// [`descend_pair`] by leaves: calls `on_leaves` with the triangles of each pair of leaves whose
/// boxes overlap, in the same order, so a caller can share work between a leaf's pairs (moving
/// B's triangles into A's frame once, A's plane once).
#[expect(
    clippy::too_many_arguments,
    reason = "scratch buffers are passed in to avoid allocation"
)]
pub fn descend_leaf_pairs(
    a: &ObbTree,
    b: &ObbTree,
    rot_ab: &Matrix3,
    t_ab: &Vector3,
    stack: &mut Vec<(u32, u32)>,
    cache: &mut BoxCache,
    work: &mut WorkCounters,
    mut on_leaves: impl FnMut(&[u32], &[u32]),
) {
    stack.clear();
    stack.push((0, 0));
    cache.reset(b.nodes.len());
    // Stamp 2g − 1: centre moved into A's frame; 2g: axes too.
    let (centre_done, axes_done) = (cache.generation * 2 - 1, cache.generation * 2);
    let mut tests = 0;
    while let Some((ia, ib)) = stack.pop() {
        let (na, nb) = (&a.nodes[ia as usize], &b.nodes[ib as usize]);
        tests += 1;
        let e = &mut cache.entries[ib as usize];
        if (e.stamp != centre_done) & (e.stamp != axes_done) {
            e.stamp = centre_done;
            e.center = rot_ab * nb.obb.center + t_ab;
        }
        // Bounding spheres first: one distance, and most far pairs end here.
        let reach = na.radius + nb.radius;
        if (e.center - na.obb.center).norm_squared() > reach * reach {
            continue;
        }
        if e.stamp != axes_done {
            e.stamp = axes_done;
            e.axes = rot_ab * nb.obb.axes;
        }
        if !boxes_overlap_in_frame(
            &na.obb.axes,
            &na.obb.center,
            &na.obb.half_extents,
            &e.axes,
            &e.center,
            &nb.obb.half_extents,
        ) {
            continue;
        }
        if na.count > 0 && nb.count > 0 {
            on_leaves(a.leaf_triangles(na), b.leaf_triangles(nb));
        } else {
            push_children(a, b, ia, ib, stack);
        }
    }
    work.bounding_volume_tests += tests;
}

/// The node pairs to test after the overlapping pair `(ia, ib)`, of which at least one node is
/// internal, pushed onto `stack` in the order [`descend_leaf_pairs`] pops them: the larger
/// box split (a leaf is never split), and where both children would be split again at once,
/// the four grandchild pairs directly.
#[inline]
fn push_children(a: &ObbTree, b: &ObbTree, ia: u32, ib: u32, stack: &mut Vec<(u32, u32)>) {
    let (na, nb) = (&a.nodes[ia as usize], &b.nodes[ib as usize]);
    match (na.count > 0, nb.count > 0) {
        (true, true) => {}
        (false, true) => {
            // As below: two internal children would each be split again against the leaf.
            let (a1, a2) = (ia + 1, na.index);
            let (n1, n2) = (&a.nodes[a1 as usize], &a.nodes[a2 as usize]);
            if n1.count == 0 && n2.count == 0 {
                stack.extend_from_slice(&[
                    (n2.index, ib),
                    (a2 + 1, ib),
                    (n1.index, ib),
                    (a1 + 1, ib),
                ]);
            } else {
                stack.push((a2, ib));
                stack.push((a1, ib));
            }
        }
        (true, false) => {
            let (b1, b2) = (ib + 1, nb.index);
            let (n1, n2) = (&b.nodes[b1 as usize], &b.nodes[b2 as usize]);
            if n1.count == 0 && n2.count == 0 {
                stack.extend_from_slice(&[
                    (ia, n2.index),
                    (ia, b2 + 1),
                    (ia, n1.index),
                    (ia, b1 + 1),
                ]);
            } else {
                stack.push((ia, b2));
                stack.push((ia, b1));
            }
        }
        (false, false) => {
            let (sa, sb) = (na.obb.size(), nb.obb.size());
            // Left child `+ 1`, right child `index`; pushed right first so the left pops
            // first.
            let (a1, a2, b1, b2) = (ia + 1, na.index, ib + 1, nb.index);
            // When the node split here has two children that the rule would each pair
            // with the other node's children next, the four grandchild pairs are pushed at
            // once, in the order the two steps would pop them: near the leaves most pairs
            // pass, and skipping the middle test of such a pair saves more than the pairs
            // it would have pruned cost.
            let splits_b_next = |c: u32| {
                let n = &a.nodes[c as usize];
                n.count > 0 || n.obb.size() < sb
            };
            let splits_a_next = |c: u32| {
                let n = &b.nodes[c as usize];
                n.count > 0 || sa >= n.obb.size()
            };
            if sa >= sb {
                if splits_b_next(a1) && splits_b_next(a2) {
                    stack.extend_from_slice(&[(a2, b2), (a2, b1), (a1, b2), (a1, b1)]);
                } else {
                    stack.push((a2, ib));
                    stack.push((a1, ib));
                }
            } else if splits_a_next(b1) && splits_a_next(b2) {
                stack.extend_from_slice(&[(a2, b2), (a1, b2), (a2, b1), (a1, b1)]);
            } else {
                stack.push((ia, b2));
                stack.push((ia, b1));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A gently curved strip gets a right-handed orthonormal frame with its mean normal third;
    /// the closed surface of a tetrahedron (normals summing to zero) gets none.
    #[test]
    fn patch_frames_follow_the_mean_normal_and_refuse_closed_patches() {
        let v = Vector3::new;
        let strip = [
            v(0.0, 0.0, 0.0),
            v(1.0, 0.0, 0.1),
            v(0.0, 1.0, 0.0),
            v(1.0, 1.0, 0.1),
            v(2.0, 0.0, 0.4),
            v(2.0, 1.0, 0.4),
        ];
        let area_normals = |points: &[Vector3], faces: &[[usize; 3]]| -> Vec<Vector3> {
            faces
                .iter()
                .map(|t| (points[t[1]] - points[t[0]]).cross(&(points[t[2]] - points[t[0]])))
                .collect()
        };
        let normals = area_normals(&strip, &[[0, 1, 2], [1, 3, 2], [1, 4, 3], [4, 5, 3]]);
        let parent = nalgebra::Rotation3::from_euler_angles(0.3, -0.2, 0.9).into_inner();
        let axes = patch_frame(&normals, &[0, 1, 2, 3], &parent).unwrap();
        assert!((axes.transpose() * axes - Matrix3::identity()).norm() < 1e-14);
        assert!((axes.determinant() - 1.0).abs() < 1e-14);
        let mean = normals.iter().sum::<Vector3>().normalize();
        assert!((axes.column(2) - mean).norm() < 1e-14);

        let tetra = [
            v(0.0, 0.0, 0.0),
            v(1.0, 0.0, 0.0),
            v(0.0, 1.0, 0.0),
            v(0.0, 0.0, 1.0),
        ];
        let closed = area_normals(&tetra, &[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]);
        assert!(patch_frame(&closed, &[0, 1, 2, 3], &parent).is_none());
    }
}
