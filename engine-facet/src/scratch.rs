//! Per-thread scratch buffers, so queries allocate nothing once warm and one prepared pair can be
//! queried from many threads at once (each thread has its own buffers; results do not depend on
//! which thread ran).

use contact_core::Vector3;
use std::cell::RefCell;

/// A triangle → slot map cleared in O(1) by bumping a generation stamp (stamp and slot side
/// by side: one cache line per lookup).
#[derive(Debug, Default)]
pub(crate) struct SlotMap {
    entries: Vec<(u32, u32)>,
    generation: u32,
}

impl SlotMap {
    /// Empties the map and makes room for `n` triangles.
    pub(crate) fn reset(&mut self, n: usize) {
        if self.entries.len() < n {
            self.entries.resize(n, (0, 0));
        }
        self.generation = self.generation.wrapping_add(1);
        if self.generation == 0 {
            self.entries.fill((0, 0));
            self.generation = 1;
        }
    }

    #[inline]
    pub(crate) fn get(&self, t: u32) -> Option<u32> {
        let (stamp, slot) = self.entries[t as usize];
        (stamp == self.generation).then_some(slot)
    }

    #[inline]
    pub(crate) fn insert(&mut self, t: u32, slot: u32) {
        self.entries[t as usize] = (self.generation, slot);
    }
}

/// A set of tree nodes cleared in O(1) by bumping a generation stamp.
#[derive(Debug, Default)]
pub(crate) struct NodeMarks {
    stamps: Vec<u32>,
    generation: u32,
}

impl NodeMarks {
    /// Empties the set and makes room for `n` nodes.
    pub(crate) fn reset(&mut self, n: usize) {
        if self.stamps.len() < n {
            self.stamps.resize(n, 0);
        }
        self.generation = self.generation.wrapping_add(1);
        if self.generation == 0 {
            self.stamps.fill(0);
            self.generation = 1;
        }
    }

    #[inline]
    pub(crate) fn is_set(&self, node: u32) -> bool {
        self.stamps[node as usize] == self.generation
    }

    #[inline]
    pub(crate) fn set(&mut self, node: u32) {
        self.stamps[node as usize] = self.generation;
    }
}

/// One crossing of a triangle of A with one of B: the segment, in A's frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Hit {
    pub ta: u32,
    pub tb: u32,
    pub s0: Vector3,
    pub s1: Vector3,
    /// Unit normal and a point of A's triangle, in A's frame.
    pub plane_a: (Vector3, Vector3),
    /// Unit normal and a point of B's triangle, in A's frame.
    pub plane_b: (Vector3, Vector3),
    /// Where the segment's ends lie (`first`: on A's triangle).
    pub ends: [crate::triangle_pair::SegmentEnd; 2],
}

/// A triangle taking part in a contact: crossing the other surface, or inside the other solid.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RegionNode {
    /// 0 for mesh A, 1 for mesh B.
    pub side: u8,
    pub tri: u32,
    pub crossing: bool,
    /// Union-find parent.
    pub parent: u32,
    /// The region index, once labelled.
    pub region: u32,
    /// Range in `node_hits` of the hits on this triangle.
    pub hit_start: u32,
    pub hit_count: u32,
    /// Bit k set: corner k lies inside the other solid (crossing triangles only).
    pub inside_corners: u8,
    /// Bit k set: a flood across edge k belongs to this node (all three unless the triangle is
    /// split into pieces, see [`crate::triangle_pieces`]).
    pub edges: u8,
    /// The triangle's next piece, or [`crate::triangle_pieces::NO_PIECE`].
    pub next_piece: u32,
    /// The triangle is split into pieces (this node holds some of its hits).
    pub split: bool,
}

/// A triangle at or below the plane in a mesh–plane query: its corners (mesh frame) and their
/// heights above the plane, read once for the passes that follow.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlaneNode {
    pub tri: u32,
    /// Some corner lies above the plane.
    pub crossing: bool,
    pub corners: [Vector3; 3],
    pub heights: [f64; 3],
}

/// Running sums of one region.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct RegionSums {
    pub reference: Vector3,
    pub seen: bool,
    pub vector_area: Vector3,
    pub loop_length: f64,
    pub loop_moment: Vector3,
    pub loop_points: usize,
    pub loop_point_sum: Vector3,
    /// The region's cone apex (its loop's centroid) in A's frame, and in B's.
    pub apex: Vector3,
    pub apex_b: Vector3,
    pub volume: f64,
    pub volume_moment: Vector3,
    pub centroid: Vector3,
    pub best_i: (f64, Vector3, u32),
    pub best_j: (f64, Vector3, u32),
    pub fallback_normal: Vector3,
    pub down_area: f64,
    pub sums_a: crate::surface_sums::SurfaceSums,
    pub sums_b: crate::surface_sums::SurfaceSums,
    /// The line through the centroid measured the region deeper than a convex region of its
    /// volume and cross-section can be, the centroid lies outside a closed body, and the line
    /// crosses the region nowhere beside it: the penetration is held to the bound `3V/|S|`.
    pub held_to_bound: bool,
}

/// Everything a query reuses.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    pub stack: Vec<(u32, u32)>,
    pub hits: Vec<Hit>,
    pub slots: [SlotMap; 2],
    /// Per side, the tree nodes that are no free patch for the inside flood.
    pub blocked: [NodeMarks; 2],
    pub nodes: Vec<RegionNode>,
    pub node_hits: Vec<u32>,
    /// Per hit, the node (piece) it lies on in A and in B.
    pub hit_nodes: Vec<[u32; 2]>,
    /// Buffers for splitting crossing triangles into pieces.
    pub pieces: crate::triangle_pieces::PieceScratch,
    /// Buffers for a crossing triangle's inside part.
    pub boundary: crate::piece_boundary::BoundaryScratch,
    pub queue: Vec<u32>,
    /// Curved triangles whose smooth surface may reach below a plane (`crate::plane_support`).
    pub curved: Vec<u32>,
    /// Per node of a mesh–plane query, its triangle's corners and their heights above the
    /// plane.
    pub plane_nodes: Vec<PlaneNode>,
    /// Per vertex of a convex mesh, its height above a plane (`crate::flat_faces`).
    pub vertex_heights: Vec<f64>,
    /// The flat faces reaching below a plane, each with the range of `polygon` holding its
    /// part below the plane (empty for a face wholly below).
    pub touched: Vec<(u32, u32, u32)>,
    /// The inside flood's takings: `(seed node, triangle)`, or `(seed node, patch | PATCH_BIT)`
    /// for a whole patch (see [`crate::inside_flood`]).
    pub taken: Vec<(u32, u32)>,
    pub regions: Vec<RegionSums>,
    pub polygon: Vec<Vector3>,
    pub polygon_next: Vec<Vector3>,
    pub local: Vec<crate::contact_region::LocalContact>,
    pub box_cache: crate::obb_tree::BoxCache,
    /// B's leaves moved into A's frame lately (see [`crate::crossings`]).
    pub moved: crate::crossings::MovedLeaves,
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

/// Runs `f` with this thread's scratch buffers. Re-entrant calls (never made by this crate) get
/// fresh buffers instead of a panic.
pub(crate) fn with_scratch<R>(f: impl FnOnce(&mut Scratch) -> R) -> R {
    SCRATCH.with(|cell| match cell.try_borrow_mut() {
        Ok(mut s) => f(&mut s),
        Err(_) => f(&mut Scratch::default()),
    })
}
