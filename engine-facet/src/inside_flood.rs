//! Step 2 of [`crate::contact_region`]: each surface is flooded from its crossing triangles into
//! the triangles that lie wholly inside the other solid, which are listed with their seed's
//! node (their cones are summed once the regions, and so their apexes, are known); floods that
//! meet unite their seeds' regions.
//!
//! The flood takes whole patches where it can ([`crate::patches`]): on reaching a triangle it
//! takes the largest subtree of the mesh's tree around it that is one connected patch, holds no
//! crossing triangle and no triangle taken already, and lies in the leak guard. Such a patch
//! lies wholly inside the other solid (it is connected, contains an inside triangle and meets
//! no triangle of the other surface), so the flood would have covered all of it: its cone sums
//! are added at once and the flood goes on from its rim. A query then pays per patch and per
//! rim edge, not per inside triangle (at 100k triangles a deep overlap has some 20k of them in
//! a few hundred patches).

use crate::contact_region::{RelativePose, corners_in_a, other_plane, union};
use crate::crossings::eroded_side;
use crate::facet_mesh::FacetMesh;
use crate::patches::PatchIndex;
use crate::scratch::{NodeMarks, RegionNode, Scratch};
use crate::triangle_pieces::NO_PIECE;
use contact_core::Vector3;

/// Marks which corners of the crossing triangles (the first `crossing_count` nodes) are
/// inside the other solid: behind every plane the triangle crosses. A corner on a plane
/// (within 1e-12 of the mesh's size) lies on the side the triangle tests put it
/// (`crate::crossings::eroded_side`: A eroded, so B's corner on A's plane is outside A).
fn mark_inside_corners(
    a: &FacetMesh,
    b: &FacetMesh,
    x: &RelativePose,
    s: &mut Scratch,
    crossing_count: usize,
) {
    for id in 0..crossing_count {
        let node = s.nodes[id];
        let mesh = if node.side == 0 { a } else { b };
        let c = corners_in_a(mesh, node.side, node.tri, x);
        let eps = 1e-12 * mesh.size;
        let mut bits = 0u8;
        for (k, v) in c.iter().enumerate() {
            let inside = (0..node.hit_count).all(|i| {
                let hit = s.hits[s.node_hits[(node.hit_start + i) as usize] as usize];
                let (n, p0) = other_plane(node.side, &hit);
                let d = n.dot(&(v - p0));
                if d.abs() > eps {
                    return d < 0.0;
                }
                node.side == 0 && eroded_side(a, node.tri, k, &n) < 0.0
            });
            bits |= u8::from(inside) << k;
        }
        s.nodes[id].inside_corners = bits;
    }
}

/// Floods each surface from its crossing triangles into the triangles inside the other solid,
/// listing each triangle or whole patch taken with its seed node in `s.taken`.
pub(crate) fn flood(a: &FacetMesh, b: &FacetMesh, x: &RelativePose, s: &mut Scratch) {
    s.taken.clear();
    let crossing_count = s.nodes.len();
    mark_inside_corners(a, b, x, s, crossing_count);
    // Subtrees holding a crossing triangle are not patches of one side of the other surface.
    for side in 0..2 {
        let mesh = if side == 0 { a } else { b };
        s.blocked[side].reset(mesh.tree.nodes().len());
    }
    for node in &s.nodes[..crossing_count] {
        let mesh = if node.side == 0 { a } else { b };
        let leaf = mesh.patches.leaf_of[node.tri as usize];
        block_up(&mesh.patches, &mut s.blocked[node.side as usize], leaf);
    }
    // The other mesh's root box in each mesh's frame, as an axis-aligned box: the leak guard
    // (one per side, not per seed). The inside of an inside-out mesh is unbounded: no guard.
    let everywhere = (
        Vector3::repeat(f64::NEG_INFINITY),
        Vector3::repeat(f64::INFINITY),
    );
    let guard = |other: &FacetMesh, within: crate::obb::Obb| {
        if other.inside_out {
            everywhere
        } else {
            aabb(&within)
        }
    };
    let guards = [
        guard(b, x.box_in_a(b.tree.root())),
        guard(a, x.box_in_b(a.tree.root())),
    ];
    for id in 0..crossing_count as u32 {
        let node = s.nodes[id as usize];
        // Edge k, both its corners inside, and (in a triangle split into pieces) this piece's.
        let both_inside = |k: usize| {
            node.edges & (1 << k) != 0
                && node.inside_corners & (1 << k) != 0
                && node.inside_corners & (1 << ((k + 1) % 3)) != 0
        };
        if !(both_inside(0) || both_inside(1) || both_inside(2)) {
            // No edge to flood across: most crossing triangles, so skip the set-up.
            continue;
        }
        let mesh = if node.side == 0 { a } else { b };
        let Scratch {
            slots,
            blocked,
            nodes,
            queue,
            taken,
            ..
        } = s;
        let side = node.side as usize;
        let mut flood = Flood {
            mesh,
            guard: guards[side],
            seed: id,
            taken,
            slots: &mut slots[side],
            blocked: &mut blocked[side],
            nodes,
            queue,
        };
        flood.queue.clear();
        for k in 0..3 {
            if both_inside(k) {
                flood.visit(mesh.neighbors[node.tri as usize][k]);
            }
        }
        while let Some(item) = flood.queue.pop() {
            if item & PATCH_BIT == 0 {
                let [n0, n1, n2] = mesh.neighbors[item as usize];
                flood.visit(n0);
                flood.visit(n1);
                flood.visit(n2);
            } else {
                // A patch taken whole: go on across its rim.
                let patch = item & !PATCH_BIT;
                mesh.patches
                    .for_each_rim(patch, &mesh.neighbors, |m| flood.visit(m));
            }
        }
    }
}

/// Flood mark: an inside triangle's slot holds its seed node with this bit set.
const INSIDE_BIT: u32 = 1 << 31;

/// Queue and `taken` entry: a patch (tree node) rather than a triangle.
pub(crate) const PATCH_BIT: u32 = 1 << 31;

/// Blocks `node` and its ancestors as patches (up to the first one blocked already): they hold
/// a crossing triangle or a triangle taken already.
fn block_up(patches: &PatchIndex, blocked: &mut NodeMarks, mut node: u32) {
    loop {
        if blocked.is_set(node) {
            return;
        }
        blocked.set(node);
        match patches.parent_of(node) {
            Some(p) => node = p,
            None => return,
        }
    }
}

/// The axis-aligned box `(min, max)` around an oriented box.
fn aabb(o: &crate::obb::Obb) -> (Vector3, Vector3) {
    let reach = o.axes.abs() * o.half_extents;
    (o.center - reach, o.center + reach)
}

/// Whether the box `inner` lies in the box `outer`.
fn aabb_within(inner: &(Vector3, Vector3), outer: &(Vector3, Vector3)) -> bool {
    inner.0.x >= outer.0.x
        && inner.0.y >= outer.0.y
        && inner.0.z >= outer.0.z
        && inner.1.x <= outer.1.x
        && inner.1.y <= outer.1.y
        && inner.1.z <= outer.1.z
}

/// One seed's flood over its mesh: the state [`visit`](Flood::visit) reads and writes.
struct Flood<'s> {
    mesh: &'s FacetMesh,
    /// The leak guard `(min, max)` in the mesh's frame.
    guard: (Vector3, Vector3),
    seed: u32,
    /// What the floods took: `(seed node, triangle)`, or a patch with [`PATCH_BIT`].
    taken: &'s mut Vec<(u32, u32)>,
    slots: &'s mut crate::scratch::SlotMap,
    /// Tree nodes that are not patches this query (see [`block_up`]).
    blocked: &'s mut NodeMarks,
    nodes: &'s mut Vec<RegionNode>,
    /// Triangles, and patches (with [`PATCH_BIT`]), whose neighbours are still to be visited.
    queue: &'s mut Vec<u32>,
}

impl Flood<'_> {
    /// Marks `tri` inside, lists it and queues it, unless it is marked already (then its
    /// owner joins the seed's region) or it leaves the guard box; takes the largest free patch
    /// around it whole when there is one.
    #[inline(always)]
    fn visit(&mut self, tri: u32) {
        if tri == crate::facet_mesh::NO_NEIGHBOR {
            return;
        }
        if let Some(mark) = self.slots.get(tri) {
            let owner = mark & !INSIDE_BIT;
            if mark & INSIDE_BIT == 0 && self.nodes[owner as usize].next_piece != NO_PIECE {
                self.join_pieces_facing(tri, owner);
            } else if owner != self.seed {
                union(self.nodes, self.seed, owner);
            }
            return;
        }
        let p = self.mesh.vertices[self.mesh.triangles[tri as usize][0] as usize].coords;
        let guard = &self.guard;
        // Leak guard: an inside triangle lies in the other mesh's root box.
        if p.x < guard.0.x
            || p.y < guard.0.y
            || p.z < guard.0.z
            || p.x > guard.1.x
            || p.y > guard.1.y
            || p.z > guard.1.z
        {
            return;
        }
        let patches = &self.mesh.patches;
        let leaf = patches.leaf_of[tri as usize];
        match self.free_patch(leaf) {
            Some(patch) => {
                // Only the border can be reached again: every other triangle of the patch has
                // its three neighbours in it, and none of them is ever visited one by one.
                let slots = &mut *self.slots;
                let mark = self.seed | INSIDE_BIT;
                patches.for_each_border(patch, &self.mesh.neighbors, |t| slots.insert(t, mark));
                self.taken.push((self.seed, patch | PATCH_BIT));
                block_up(patches, self.blocked, patch);
                self.queue.push(patch | PATCH_BIT);
            }
            None => {
                self.slots.insert(tri, self.seed | INSIDE_BIT);
                self.taken.push((self.seed, tri));
                block_up(patches, self.blocked, leaf);
                self.queue.push(tri);
            }
        }
    }

    /// A crossing triangle split into pieces, reached by the flood: the seed joins the pieces
    /// whose edges face what the seed has taken (or the seed's own triangle).
    fn join_pieces_facing(&mut self, tri: u32, first: u32) {
        let seed_tri = self.nodes[self.seed as usize].tri;
        let mut piece = first;
        while piece != NO_PIECE {
            let edges = self.nodes[piece as usize].edges;
            let facing = (0..3).any(|k| {
                let nb = self.mesh.neighbors[tri as usize][k];
                edges & (1 << k) != 0
                    && nb != crate::facet_mesh::NO_NEIGHBOR
                    && (nb == seed_tri || self.slots.get(nb) == Some(self.seed | INSIDE_BIT))
            });
            if facing && piece != self.seed {
                union(self.nodes, self.seed, piece);
            }
            piece = self.nodes[piece as usize].next_piece;
        }
    }

    /// The highest node on the path up from `leaf` that is a free patch: not blocked (then
    /// neither is any node below it), one connected patch, its box in the guard. The path is
    /// read from the small per-node arrays only; the boxes (a cache miss each) are read from
    /// the top candidate down until one lies in the guard, mostly the first.
    fn free_patch(&self, leaf: u32) -> Option<u32> {
        let patches = &self.mesh.patches;
        let nodes = self.mesh.tree.nodes();
        let mut path = [0u32; 64];
        let mut len = 0;
        let mut node = leaf;
        loop {
            if self.blocked.is_set(node) {
                break;
            }
            if patches.connected[node as usize] && len < path.len() {
                path[len] = node;
                len += 1;
            }
            match patches.parent_of(node) {
                Some(p) => node = p,
                None => break,
            }
        }
        path[..len]
            .iter()
            .rev()
            .copied()
            .find(|&n| aabb_within(&aabb(&nodes[n as usize].obb), &self.guard))
    }
}
