//! Step 2 of [`crate::contact_region`]: each surface is flooded from its crossing triangles into
//! the triangles that lie wholly inside the other solid, whose cones (about the query's apex)
//! are summed into the seed's node; floods that meet unite their seeds' regions.

use crate::contact_region::{RelativePose, corners_in_a, other_plane, union};
use crate::facet_mesh::FacetMesh;
use crate::scratch::{RegionNode, Scratch};
use crate::surface_sums::SurfaceSums;
use contact_core::Vector3;

/// Floods each surface from its crossing triangles into the triangles inside the other solid,
/// summing them (in their own mesh frame) into the seed node's `inside` sums.
pub(crate) fn flood(a: &FacetMesh, b: &FacetMesh, x: &RelativePose, s: &mut Scratch) {
    let crossing_count = s.nodes.len();
    // Corners of crossing triangles: inside when strictly behind every crossed plane.
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
                n.dot(&(v - p0)) < -eps
            });
            bits |= u8::from(inside) << k;
        }
        s.nodes[id].inside_corners = bits;
    }
    // The other mesh's root box in each mesh's frame, as an axis-aligned box: the leak guard
    // (one per side, not per seed).
    let guards = [
        aabb(&x.box_in_a(b.tree.root())),
        aabb(&x.box_in_b(a.tree.root())),
    ];
    for id in 0..crossing_count as u32 {
        let node = s.nodes[id as usize];
        let both_inside = |k: usize| {
            node.inside_corners & (1 << k) != 0 && node.inside_corners & (1 << ((k + 1) % 3)) != 0
        };
        if !(both_inside(0) || both_inside(1) || both_inside(2)) {
            // No edge to flood across: most crossing triangles, so skip the set-up.
            continue;
        }
        let mesh = if node.side == 0 { a } else { b };
        // The seed's sums, side and apex stay local while it floods (its `inside` sums are
        // written only here, so the order of additions is unchanged).
        let Scratch {
            slots,
            nodes,
            queue,
            apex,
            ..
        } = s;
        let side = node.side as usize;
        let mut flood = Flood {
            mesh,
            guard: guards[side],
            apex: apex[side],
            seed: id,
            sums: nodes[id as usize].inside,
            slots: &mut slots[side],
            nodes,
            queue,
        };
        flood.queue.clear();
        for k in 0..3 {
            if both_inside(k) {
                flood.visit(mesh.neighbors[node.tri as usize][k]);
            }
        }
        while let Some(t) = flood.queue.pop() {
            let [n0, n1, n2] = mesh.neighbors[t as usize];
            flood.visit(n0);
            flood.visit(n1);
            flood.visit(n2);
        }
        let sums = flood.sums;
        s.nodes[id as usize].inside = sums;
    }
}

/// Flood mark: an inside triangle's slot holds its seed node with this bit set.
const INSIDE_BIT: u32 = 1 << 31;

/// The axis-aligned box `(min, max)` around an oriented box.
fn aabb(o: &crate::obb::Obb) -> (Vector3, Vector3) {
    let reach = o.axes.abs() * o.half_extents;
    (o.center - reach, o.center + reach)
}

/// One seed's flood over its mesh: the state [`visit`](Flood::visit) reads and writes.
struct Flood<'s> {
    mesh: &'s FacetMesh,
    /// The leak guard `(min, max)` in the mesh's frame.
    guard: (Vector3, Vector3),
    apex: Vector3,
    seed: u32,
    sums: SurfaceSums,
    slots: &'s mut crate::scratch::SlotMap,
    nodes: &'s mut Vec<RegionNode>,
    queue: &'s mut Vec<u32>,
}

impl Flood<'_> {
    /// Marks `tri` inside, adds its cone and queues it, unless it is marked already (then its
    /// owner joins the seed's region) or it leaves the guard box.
    #[inline(always)]
    fn visit(&mut self, tri: u32) {
        if tri == crate::facet_mesh::NO_NEIGHBOR {
            return;
        }
        if let Some(mark) = self.slots.get(tri) {
            let owner = mark & !INSIDE_BIT;
            if owner != self.seed {
                union(self.nodes, self.seed, owner);
            }
            return;
        }
        let [p, q, r] = self.mesh.corners(tri);
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
        self.slots.insert(tri, self.seed | INSIDE_BIT);
        self.sums.add_triangle(&p, &q, &r, &self.apex);
        self.queue.push(tri);
    }
}
