//! Step 1 of [`crate::contact_region`]: the crossing segments of two meshes. The trees are
//! descended together ([`crate::obb_tree::descend_leaf_pairs`]); each pair of overlapping leaves
//! screens A's triangles' planes against B's leaf triangles at once, and the pairs left take the
//! exact triangle test ([`crate::triangle_pair::intersect_perturbed`]) with one on-plane band
//! for the whole query and A eroded by an infinitesimal amount ([`eroded_side`]).

use crate::contact_region::RelativePose;
use crate::facet_mesh::FacetMesh;
use crate::obb_tree::{LEAF_TRIANGLES, descend_leaf_pairs};
use crate::scratch::{Hit, Scratch};
use crate::triangle_pair::{PLANE_EPS, Sides, TrianglePair, intersect_perturbed};
use contact_core::{Vector3, WorkCounters};

/// Every crossing of a triangle of `a` with one of `b` (at `x` in A's frame), into `s.hits`.
pub(crate) fn find_crossings(
    a: &FacetMesh,
    b: &FacetMesh,
    x: &RelativePose,
    s: &mut Scratch,
    work: &mut WorkCounters,
) {
    let Scratch {
        stack,
        hits,
        box_cache,
        moved: recent,
        ..
    } = s;
    hits.clear();
    let mut tests = 0;
    // One on-plane band for every pair of the query (see `intersect_on_planes`): PLANE_EPS
    // times the longest edge of either mesh, so never narrower than any pair's own band in
    // `intersect` and, unlike one relative to the meshes' size, no wider than the triangles
    // call for when a small body meets a large one.
    let band = PLANE_EPS * a.longest_edge.max(b.longest_edge);
    let band_squared = band * band;
    recent.reset();
    descend_leaf_pairs(
        &a.tree,
        &b.tree,
        &x.rot,
        &x.t,
        stack,
        box_cache,
        work,
        |leaf_a, leaf_b| {
            // B's triangles of the leaf moved into A's frame once for all of A's, with their
            // planes, and kept for the next A leaves that meet this B leaf.
            let moved = recent.get(leaf_b, |tb| moved_triangle(b, tb, x));
            for &ta in leaf_a {
                let p = a.corners(ta);
                let n = (p[1] - p[0]).cross(&(p[2] - p[0]));
                // A B triangle strictly on one side of `p`'s plane, beyond the band, is
                // disjoint: the test's own first step, taken here for the whole leaf at once
                // and without branches (the outcome is a coin toss near the intersection
                // curve), so the rest is paid only by the pairs that need it.
                let band_n_squared = band_squared * n.norm_squared();
                let mut distances = [[0.0; 3]; LEAF_TRIANGLES];
                let mut keep = 0u32;
                for (k, (d, (q, _))) in distances.iter_mut().zip(moved).enumerate() {
                    *d = [
                        n.dot(&(q[0] - p[0])),
                        n.dot(&(q[1] - p[0])),
                        n.dot(&(q[2] - p[0])),
                    ];
                    let above = (d[0] > 0.0) & (d[1] > 0.0) & (d[2] > 0.0);
                    let below = (d[0] < 0.0) & (d[1] < 0.0) & (d[2] < 0.0);
                    let nearest = d[0].abs().min(d[1].abs()).min(d[2].abs());
                    let apart = (above | below) & (nearest * nearest > band_n_squared);
                    keep |= u32::from(!apart) << k;
                }
                keep &= (1 << leaf_b.len()) - 1;
                tests += leaf_b.len() as u64;
                while keep != 0 {
                    let k = keep.trailing_zeros() as usize;
                    keep &= keep - 1;
                    let (q, nq) = &moved[k];
                    let tb = leaf_b[k];
                    let sides = Sides {
                        p: |corner: usize| eroded_side(a, ta, corner, nq),
                        // B's vertex on A's plane lies outside A eroded.
                        q: 1.0,
                    };
                    if let (TrianglePair::Segment(s0, s1), ends) =
                        intersect_perturbed(&p, q, &n, nq, distances[k], band, sides)
                    {
                        hits.push(Hit {
                            ta,
                            tb,
                            s0,
                            s1,
                            plane_a: (a.face_normals[ta as usize], p[0]),
                            plane_b: (x.rot * b.face_normals[tb as usize], q[0]),
                            ends,
                        });
                    }
                }
            }
        },
    );
    work.primitive_tests += tests;
}

/// The side of B's plane (normal `nq`, any length) on which A's corner `corner` of triangle
/// `ta`, lying on that plane, is taken: A is eroded by an infinitesimal amount, each vertex
/// moved inwards along its pseudo-normal `m`, so the corner lies on the side of `−m·n_q`
/// (inside B where A's surface runs along B's the same way, a flush face; outside where the
/// two face each other, touching). Where `m ⟂ n_q` it is moved along [`NUDGE`] instead. A
/// side depends only on the vertex and the plane, so every pair classifies it alike; touching
/// faces come apart and bound no volume, and a flush face belongs to A's surface inside B.
#[inline]
pub(crate) fn eroded_side(a: &FacetMesh, ta: u32, corner: usize, nq: &Vector3) -> f64 {
    let v = a.triangles[ta as usize][corner];
    let side = -a.vertex_normals[v as usize].dot(nq);
    if side != 0.0 { side } else { nq.dot(&NUDGE) }
}

/// The direction, in A's frame, A is nudged by an infinitesimal amount for the triangle tests
/// where erosion leaves a vertex on a plane ([`eroded_side`]): generic, so that no face
/// normal of a mesh built on axes or simple angles is perpendicular to it.
pub(crate) const NUDGE: Vector3 = Vector3::new(
    0.318_290_114_925_167_3,
    0.577_215_664_901_532_9,
    0.754_877_666_246_692_8,
);

/// Slots of the direct-mapped store of B leaves moved into A's frame (one query's; 6 KB). A B
/// leaf meets two or three A leaves, mostly close together in the descent; the contacts do
/// not depend on the slot count (measurements: `docs/performance.md`).
const MOVED_SLOTS: usize = 16;

/// A leaf's triangles moved into A's frame, each with its plane's normal.
type MovedLeaf = [([Vector3; 3], Vector3); LEAF_TRIANGLES];

/// The direct-mapped store of B leaves moved into A's frame, keyed by a leaf's first triangle.
/// It lives in the scratch buffers, so a query clears only its keys (a separated query would
/// otherwise pay for filling 6 KB).
#[derive(Debug, Default)]
pub(crate) struct MovedLeaves {
    keys: [u32; MOVED_SLOTS],
    leaves: Vec<MovedLeaf>,
}

impl MovedLeaves {
    /// Forgets every leaf (a new query, a new pose).
    fn reset(&mut self) {
        self.keys = [u32::MAX; MOVED_SLOTS];
        if self.leaves.len() < MOVED_SLOTS {
            self.leaves.resize(
                MOVED_SLOTS,
                [([Vector3::zeros(); 3], Vector3::zeros()); LEAF_TRIANGLES],
            );
        }
    }

    /// The leaf's triangles moved by `move_triangle`, moved now unless stored already. Entries
    /// past the leaf's length hold another leaf's triangles: callers read only `leaf.len()`.
    #[inline]
    fn get(
        &mut self,
        leaf: &[u32],
        move_triangle: impl Fn(u32) -> ([Vector3; 3], Vector3),
    ) -> &MovedLeaf {
        let key = leaf[0];
        let slot = key as usize % MOVED_SLOTS;
        if self.keys[slot] != key {
            self.keys[slot] = key;
            for (m, &t) in self.leaves[slot].iter_mut().zip(leaf) {
                *m = move_triangle(t);
            }
        }
        &self.leaves[slot]
    }
}

/// B's triangle `tb` moved into A's frame, with its plane's normal `(q₁ − q₀) × (q₂ − q₀)`.
#[inline]
fn moved_triangle(b: &FacetMesh, tb: u32, x: &RelativePose) -> ([Vector3; 3], Vector3) {
    let [q0, q1, q2] = b.corners(tb);
    let q = [x.apply(&q0), x.apply(&q1), x.apply(&q2)];
    (q, (q[1] - q[0]).cross(&(q[2] - q[0])))
}
