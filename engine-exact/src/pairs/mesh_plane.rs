//! A closed triangle mesh (taken as exact) against an unbounded plane: exact clipping, one
//! contact per connected region below the plane.
//!
//! In the mesh's frame, with `d(v) = n·v − h` each vertex's height above the plane (the
//! plane's solid is `d ≤ 0`):
//! - **Regions.** A triangle with a vertex strictly below is *active*; two active triangles
//!   sharing an edge that dips below (`min(d_a, d_b) < 0`) belong to one region (union–find
//!   over the edge adjacency built at prepare time). A mesh resting on several feet gives one
//!   contact per foot.
//! - **Volume and centroid** of each region: the divergence theorem over its triangles'
//!   parts below the plane, with tetrahedra from a point *on* the plane (the foot of one of
//!   the region's vertices, so round-off is relative to the region's size), so the flat cap
//!   where the plane cuts the mesh contributes nothing and need not be built. The cap's area
//!   vector is minus the clipped triangles' (a closed surface sums to zero).
//! - **Normal:** the plane's. **Points** (SPEC §4, along the normal through the centroid):
//!   the foot of the centroid on the plane, and where the line from the centroid along `−n`
//!   first meets the mesh (every triangle is tried; the closest point of the whole mesh when
//!   the centroid lies outside it and the line misses); δ is their distance. **Area:** `|S|`, the area of the mesh surface below the plane
//!   projected on the plane (the cap's area).
//! - Touching (no vertex strictly below) is not a contact; a region of zero volume is skipped.
//!
//! Work is `O(vertices + triangles)` per query. The per-query arrays (heights, union–find,
//! per-region sums) live in a thread-local scratch that grows to the largest mesh seen and is
//! then reused: no allocation once warm.

use crate::kernel::PairContact;
use crate::methods::mesh_parts::{MeshPart, mesh_parts};
use contact_core::geometry::TriangleMesh;
use contact_core::geometry::{closest_point_on_triangle, line_triangle};
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use std::cell::RefCell;
use std::collections::HashMap;

/// A mesh with the triangle adjacency the region search needs.
#[derive(Debug, Clone, PartialEq)]
pub struct PreparedMesh {
    pub(crate) vertices: Vec<Point3>,
    pub(crate) triangles: Vec<[u32; 3]>,
    /// `neighbours[t][k]`: the triangle across edge `k` (vertices `k`, `k + 1`) of `t`.
    pub(crate) neighbours: Vec<[u32; 3]>,
    /// A ball holding every vertex (centre of the bounding box, in the mesh's frame), for the
    /// pairs that first check whether the mesh can reach the other body at all.
    pub(crate) centre: Point3,
    /// Its radius.
    pub(crate) radius: f64,
    /// Whether the triangles were turned inside out ([`Self::inverted`]): the solid is then
    /// the space outside the mesh (a cavity's walls), unbounded.
    pub(crate) inverted: bool,
    /// Per triangle, a ball around it (its centroid and the farthest corner's distance), so a
    /// line that passes it by is not intersected with it ([`exit_along`]).
    pub(crate) balls: Vec<(Point3, f64)>,
    /// Per triangle, its unit normal (zero for a degenerate one), so a line that crosses the
    /// triangle's plane outside its ball is not intersected with it ([`exit_along`]).
    pub(crate) normals: Vec<Vector3>,
    /// The components, when they are apart and small enough (see `mesh_parts`); empty
    /// otherwise and for a mesh turned inside out.
    pub(crate) parts: Vec<MeshPart>,
}

impl PreparedMesh {
    /// Builds the adjacency; `None` unless every edge has exactly one neighbour across it
    /// (a closed 2-manifold, which `TriangleMesh::new` guarantees).
    pub fn new(mesh: &TriangleMesh) -> Option<Self> {
        let triangles = mesh.triangles().to_vec();
        let mut by_edge: HashMap<(u32, u32), u32> = HashMap::with_capacity(3 * triangles.len());
        for (t, tri) in triangles.iter().enumerate() {
            for k in 0..3 {
                by_edge.insert((tri[k], tri[(k + 1) % 3]), u32::try_from(t).ok()?);
            }
        }
        let mut neighbours = Vec::with_capacity(triangles.len());
        for tri in &triangles {
            let mut n = [0u32; 3];
            for k in 0..3 {
                n[k] = *by_edge.get(&(tri[(k + 1) % 3], tri[k]))?;
            }
            neighbours.push(n);
        }
        let (lo, hi) = mesh.bounding_box();
        let centre = nalgebra::center(&lo, &hi);
        let radius = mesh
            .vertices()
            .iter()
            .map(|v| (v - centre).norm())
            .fold(0.0, f64::max);
        let vertices = mesh.vertices().to_vec();
        let balls = triangles
            .iter()
            .map(|tri| {
                let [a, b, c] = tri.map(|v| vertices[v as usize]);
                let g = Point3::from((a.coords + b.coords + c.coords) / 3.0);
                let r = (a - g).norm().max((b - g).norm()).max((c - g).norm());
                (g, r)
            })
            .collect();
        let normals = triangles
            .iter()
            .map(|tri| {
                let [a, b, c] = tri.map(|v| vertices[v as usize]);
                (b - a)
                    .cross(&(c - a))
                    .try_normalize(0.0)
                    .unwrap_or_default()
            })
            .collect();
        let parts = mesh_parts(&vertices, &triangles, &neighbours);
        Some(Self {
            vertices,
            triangles,
            neighbours,
            centre,
            radius,
            inverted: false,
            balls,
            normals,
            parts,
        })
    }

    /// The heap bytes it holds (for the prepared pair's statistics).
    pub fn heap_bytes(&self) -> usize {
        let parts: usize = self
            .parts
            .iter()
            .map(|p| p.triangles.capacity() * 4 + p.neighbours.capacity() * 3)
            .sum();
        self.vertices.capacity() * std::mem::size_of::<Point3>()
            + (self.triangles.capacity() + self.neighbours.capacity()) * 12
            + self.balls.capacity() * std::mem::size_of::<(Point3, f64)>()
            + self.normals.capacity() * std::mem::size_of::<Vector3>()
            + self.parts.capacity() * std::mem::size_of::<crate::methods::mesh_parts::MeshPart>()
            + parts
    }

    /// The same mesh turned inside out (every triangle reversed): its solid is the space
    /// outside the mesh, as a flipped (cavity) geometry reads it.
    pub fn inverted(&self) -> Self {
        let triangles: Vec<[u32; 3]> = self.triangles.iter().map(|t| [t[0], t[2], t[1]]).collect();
        // Edge k of [a, c, b] is edge 2 − k of [a, b, c] reversed (k = 0: a→c is c→a, edge 2;
        // k = 1: c→b, edge 1; k = 2: b→a, edge 0), with the same neighbour across it.
        let neighbours = self.neighbours.iter().map(|n| [n[2], n[1], n[0]]).collect();
        let mut out = Self {
            vertices: self.vertices.clone(),
            triangles,
            neighbours,
            centre: self.centre,
            radius: self.radius,
            inverted: !self.inverted,
            balls: self.balls.clone(),
            normals: self.normals.iter().map(|n| -n).collect(),
            parts: Vec::new(),
        };
        if !out.inverted {
            out.parts = mesh_parts(&out.vertices, &out.triangles, &out.neighbours);
        }
        out
    }
}

#[derive(Debug, Clone, Copy, Default)]
struct RegionSums {
    /// The region's own point on the plane the tetrahedra start from (set by its first
    /// triangle), so the sums cancel on the region's scale, not the mesh's.
    anchor: Option<Point3>,
    six_volume: f64,
    moment: Vector3,
    /// The area vector of the region's surface below the plane (`S`).
    area: Vector3,
}

#[derive(Debug, Default)]
struct Scratch {
    height: Vec<f64>,
    parent: Vec<u32>,
    sums: Vec<RegionSums>,
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

fn find(parent: &mut [u32], mut t: u32) -> u32 {
    while parent[t as usize] != t {
        let up = parent[parent[t as usize] as usize];
        parent[t as usize] = up;
        t = up;
    }
    t
}

/// Contacts of `mesh` at `pose_mesh` with the plane at `pose_plane` (flipped when
/// `side < 0`), one per region, handed to `emit` in the order of each region's first triangle.
pub(crate) fn contacts(
    mesh: &PreparedMesh,
    pose_mesh: &Isometry3,
    pose_plane: &Isometry3,
    side: f64,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let normal_w = side * (pose_plane.rotation * Vector3::z());
    let n = pose_mesh.rotation.inverse_transform_vector(&normal_w);
    let h = n.dot(
        &pose_mesh
            .inverse_transform_point(&Point3::from(pose_plane.translation.vector))
            .coords,
    );
    SCRATCH.with(|cell| {
        let mut guard = cell.borrow_mut();
        let scratch = &mut *guard;
        scratch.height.clear();
        scratch
            .height
            .extend(mesh.vertices.iter().map(|v| n.dot(&v.coords) - h));
        if scratch.height.iter().all(|&d| d >= 0.0) {
            return;
        }
        let count = mesh.triangles.len();
        scratch.parent.clear();
        scratch.parent.extend(0..count as u32);
        scratch.sums.clear();
        scratch.sums.resize(count, RegionSums::default());
        join_regions(mesh, &scratch.height, &mut scratch.parent);
        sum_regions(mesh, &n, scratch, work);
        // One contact per region, in the order of its first triangle (its root).
        for root in 0..count {
            if scratch.parent[root] as usize != root || scratch.sums[root].six_volume <= 0.0 {
                continue;
            }
            let sums = scratch.sums[root];
            let Some(o) = sums.anchor else { continue };
            let centroid = o + sums.moment / (4.0 * sums.six_volume);
            let to_plane = (h - n.dot(&centroid.coords)).max(0.0);
            let on_plane = centroid + to_plane * n;
            let on_mesh = exit_along(mesh, &centroid, &-n)
                .unwrap_or_else(|| closest_on_mesh(mesh, &centroid));
            emit(PairContact {
                point_a: pose_mesh * on_mesh,
                point_b: pose_mesh * on_plane,
                normal: normal_w,
                depth: (on_plane - on_mesh).norm(),
                area: sums.area.norm(),
            });
        }
    });
}

/// True when a corner of the triangle `tri` lies below the plane (`height` per vertex).
fn dips_below(height: &[f64], tri: &[u32; 3]) -> bool {
    tri.iter().any(|&v| height[v as usize] < 0.0)
}

/// The regions: the triangles that dip below the plane (`height` per vertex) joined in
/// `parent` (a union–find, each root its region's first triangle) across the edges that dip
/// below it.
fn join_regions(mesh: &PreparedMesh, height: &[f64], parent: &mut [u32]) {
    // Regions: union across edges that dip below the plane.
    for (t, tri) in mesh.triangles.iter().enumerate() {
        if !dips_below(height, tri) {
            continue;
        }
        for k in 0..3 {
            let (a, b) = (tri[k] as usize, tri[(k + 1) % 3] as usize);
            if height[a].min(height[b]) < 0.0 {
                let (ra, rb) = (find(parent, t as u32), find(parent, mesh.neighbours[t][k]));
                if ra != rb {
                    parent[ra.max(rb) as usize] = ra.min(rb);
                }
            }
        }
    }
}

/// Each region's sums at its root in `scratch`: over each triangle's part below the plane
/// (outward normal `n` in the mesh's frame), the tetrahedra from the region's anchor on the
/// plane.
fn sum_regions(mesh: &PreparedMesh, n: &Vector3, scratch: &mut Scratch, work: &mut WorkCounters) {
    let height = &scratch.height;
    // Sums over each triangle's part below the plane, tetrahedra from the region's anchor
    // on the plane.
    for (t, tri) in mesh.triangles.iter().enumerate() {
        if !dips_below(height, tri) {
            continue;
        }
        work.primitive_tests += 1;
        let mut poly = [Point3::origin(); 4];
        let mut len = 0;
        for k in 0..3 {
            let (i, j) = (tri[k] as usize, tri[(k + 1) % 3] as usize);
            let (p, q) = (mesh.vertices[i], mesh.vertices[j]);
            let (dp, dq) = (height[i], height[j]);
            if dp <= 0.0 {
                poly[len] = p;
                len += 1;
            }
            if (dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0) {
                poly[len] = p + (q - p) * (dp / (dp - dq));
                len += 1;
            }
        }
        let root = find(&mut scratch.parent, t as u32) as usize;
        let sums = &mut scratch.sums[root];
        let o = *sums.anchor.get_or_insert_with(|| {
            // The foot of a vertex below the plane.
            let v = tri
                .iter()
                .copied()
                .find(|&v| height[v as usize] < 0.0)
                .unwrap_or(tri[0]);
            mesh.vertices[v as usize] - height[v as usize] * n
        });
        let a = poly[0] - o;
        for k in 1..len.saturating_sub(1) {
            let (b, c) = (poly[k] - o, poly[k + 1] - o);
            let v6 = a.dot(&b.cross(&c));
            sums.six_volume += v6;
            sums.moment += v6 * (a + b + c);
            let piece = 0.5 * (poly[k] - poly[0]).cross(&(poly[k + 1] - poly[0]));
            sums.area += piece;
        }
    }
}

/// Where the line from `p` along the unit `direction` first meets the mesh's surface (every
/// triangle, [`line_triangle`] with the barycentric bounds widened by 1e-12, so a line through
/// a shared edge or corner meets one of its triangles despite round-off), or `None`. A
/// triangle whose ball (grown by 1e-9, more than the widening moves a hit) the line passes by,
/// lies behind `p` or beyond the nearest hit so far, or whose plane the line crosses outside
/// the ball, is not intersected: it could give no nearer hit, so the answer is the same.
/// (The last test spares the walls a line runs along: against the ball alone the line from a
/// foot's centroid down through its sole is intersected with every wall of the foot.)
pub(crate) fn exit_along(mesh: &PreparedMesh, p: &Point3, direction: &Vector3) -> Option<Point3> {
    let mut best = f64::INFINITY;
    for ((tri, (centre, radius)), normal) in
        mesh.triangles.iter().zip(&mesh.balls).zip(&mesh.normals)
    {
        let e = centre - p;
        let along = e.dot(direction);
        let reach = radius * (1.0 + 1e-9);
        let square = e.norm_squared();
        // The square of the distance from the centre to the line, against the ball's, with
        // room for the round-off of `|e|² − along²`.
        let passes_by = square - along * along > reach * reach + 1e-15 * square;
        if passes_by | (along + reach < 0.0) | (along - reach > best) {
            continue;
        }
        // Where the line crosses the triangle's plane (through its centroid), against the
        // ball, with room for that crossing's round-off, ε·|e|/|n·d| (1e-6·|e|/|n·d| here).
        // A line parallel to the plane and off it crosses at infinity (missed, as
        // `line_triangle` finds); one in the plane gives NaN and is tried.
        let denominator = normal.dot(direction);
        let t = normal.dot(&e) / denominator;
        let room = 1e-12 * square / (denominator * denominator);
        let off = t * direction - e;
        let misses = off.norm_squared() > reach * reach + room;
        // Or it crosses behind `p`, or beyond the nearest hit so far, by more than that room.
        let behind = (t < 0.0) & (t * t > room);
        let beyond = (t > best) & ((t - best) * (t - best) > room);
        if misses | behind | beyond {
            continue;
        }
        let [a, b, c] = tri.map(|v| mesh.vertices[v as usize].coords);
        if let Some(t) = line_triangle(&p.coords, direction, &a, &b, &c, 1e-12) {
            if t >= 0.0 && t < best {
                best = t;
            }
        }
    }
    best.is_finite().then(|| p + best * direction)
}

/// The point of the whole mesh surface closest to `p` (every triangle: the region's own
/// surface is not always the nearest; those whose ball lies beyond the best so far are
/// skipped, as they cannot win). Distances within 1e-12 relative count as tied and the first
/// triangle wins, so a symmetric pose gives the same point in any frame.
pub(crate) fn closest_on_mesh(mesh: &PreparedMesh, p: &Point3) -> Point3 {
    let mut best = (f64::INFINITY, *p);
    for (tri, (centre, radius)) in mesh.triangles.iter().zip(&mesh.balls) {
        // No point of a triangle whose ball lies farther than the best so far can win.
        if (centre - p).norm() - radius * (1.0 + 1e-9) > best.0 {
            continue;
        }
        let [a, b, c] = tri.map(|v| mesh.vertices[v as usize]);
        let q = closest_point_on_triangle(p, &a, &b, &c);
        let d = (q - p).norm();
        if d < best.0 - 1e-12 * best.0.min(f64::MAX) {
            best = (d, q);
        }
    }
    best.1
}
