//! Mesh against mesh: intersecting triangle pairs → connected regions → one contact each, by the
//! SPEC §4 definition.
//!
//! ## Method (all in A's = I's mesh frame)
//! 1. **Crossings** (`crate::crossings`). The two OBB trees are descended together; leaf
//!    triangle pairs go to the exact triangle–triangle test ([`crate::triangle_pair`]), which
//!    returns each crossing segment oriented along `n_I × n_J`.
//! 2. **Regions.** Each triangle that crosses is a node, split into pieces where its segments
//!    bound more than one face inside the other solid ([`crate::triangle_pieces`]: two regions
//!    crossing one large triangle stay two); a crossing unites the two pieces it bounds
//!    (union-find). Then each surface is flooded from its crossing triangles into the triangles
//!    that lie wholly inside the other solid (a neighbour across an edge whose two corners are
//!    inside — behind every plane of the triangles it crosses — is inside; so is any
//!    non-crossing neighbour of an inside triangle). Flooding unites too, so the two loops of an
//!    annular contact (a torus pressed into a plane) make one region. A flood never leaves the
//!    other mesh's root box, so a gap in a loop cannot spread over a whole surface.
//! 3. **Per region.** The oriented loop gives the vector area `S = ½ Σ s₀ × s₁`: the normal is
//!    `−S/|S|` (from J into I) and the area is `|S|`, the patch's area projected on the contact
//!    plane. The intersection volume is bounded by I's surface inside J and J's surface inside
//!    I; the divergence theorem over those pieces (a crossing triangle's inside part bounded by
//!    its own trace, [`crate::piece_boundary`]; clipped by the planes of the triangles it
//!    crosses only where its trace does not form clean chains), as tetrahedra from the region's
//!    apex, gives its volume and centroid `g` (the loop's open lid cancels between the two
//!    sides): those of the polyhedral intersection of the two meshes. The apex is the loop's
//!    length-weighted centroid, one that follows the region, depends on no order of the search
//!    and moves continuously with the pose (where a plane clip stands in over a concave
//!    surface, the pieces do not quite close and the sums depend on it). The flood lists what it takes, and its cones are summed once the regions,
//!    and so their apexes, are known. The contact points are where the line through `g` along
//!    the normal meets each surface (I's along `−n`, J's along `+n`; the closest points to `g`
//!    when the loop is degenerate or the line meets nothing), lifted from the facet onto the
//!    curved PN triangle through the facet's corners and true corner normals
//!    ([`FacetMesh::lift_to_surface`]); the penetration is their distance. Every one of these
//!    is continuous in the pose, which dynamics needs. A region whose centroid lies outside one
//!    of the (closed) bodies is not convex — a thin crescent where a convex surface presses
//!    into a nearly conforming concave one, a body in a cavity — and the rays from the
//!    centroid cross a body's far side; the line through it still crosses the region beside
//!    the centroid, and the chord there (the first hits of the two surfaces on one side of `g`,
//!    whose middle lies in both bodies) gives the two points. Only where neither side has
//!    such a chord (a ring lying flat, its centroid in the hole) is the penetration held to
//!    the convex bound `3V/|S|` (no convex region of volume `V` and cross-section `|S|` is
//!    thicker), with J's point moved along the normal to match.
//! 4. **No crossings.** Closed meshes whose root boxes overlap are tested for containment (a
//!    ray-parity point-in-mesh test of three triangles' centroids, by majority). A body wholly inside the other is one
//!    contact: `g` is the inner body's centroid, the normal points from `g` to the closest point
//!    on the outer surface (see `containment`), the area is a quarter of the inner body's surface
//!    (Cauchy: its mean projected area).
//! 5. **Cavities.** A flipped solid is its mesh turned inside out
//!    ([`FacetMesh::build_inside_out`]): its facets face into the cavity, so the crossings,
//!    the inside tests against the other surface's planes, the loop and the sums above take
//!    the space outside it as they take a solid. Its inside is unbounded: the flood over the
//!    other surface has no leak guard, containment is tested whatever the boxes, a body clear
//!    of the cavity is wholly in its material, and where the cavity's surface lies inside the
//!    other body the intersection is that body less the cavity.
//!
//! ## Error bound
//! Every facet lies within `δ = L/FT` of the true surface (tessellation), so the faceted
//! intersection volume differs from the true one within a band of width `δ` around each
//! boundary; the penetration and contact points therefore carry an error of order `δ` (first
//! order in `1/FT`) from the closest-point search on the facets, reduced by the PN lift where
//! the facets approximate a smooth primitive, and the normal (from the loop's vector area, an average over the loop) an error
//! of order `δ/ℓ` with `ℓ` the loop's size. On the meshes as given, the volume, centroid and
//! area vector are the polyhedral intersection's to round-off (tested against convex clips of
//! a non-convex mesh built from convex pieces); a triangle whose trace is not clean falls back
//! to the plane clip, exact where the other surface is locally convex, an underestimate where
//! it is concave.

use crate::facet_mesh::FacetMesh;
use crate::inside_flood::flood;
use crate::obb::boxes_overlap;
use crate::scratch::{Hit, RegionNode, RegionSums, Scratch};
use crate::triangle_pair::Feature;
use contact_core::{Isometry3, Matrix3, Point3, Vector3, WorkCounters};

/// One contact in A's mesh frame, before it is moved to the world.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalContact {
    /// Point on I's (A's) surface.
    pub point_i: Vector3,
    /// Point on J's (B's) surface.
    pub point_j: Vector3,
    /// Unit normal from J into I.
    pub normal: Vector3,
    /// Penetration ≥ 0.
    pub penetration: f64,
    /// Area estimate ≥ 0.
    pub area: f64,
}

/// The pose of B's mesh frame in A's, as a matrix and a vector.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RelativePose {
    pub rot: Matrix3,
    pub t: Vector3,
}

impl RelativePose {
    pub(crate) fn new(pose_ab: &Isometry3) -> Self {
        Self {
            rot: pose_ab.rotation.to_rotation_matrix().into_inner(),
            t: pose_ab.translation.vector,
        }
    }

    #[inline]
    pub(crate) fn apply(&self, v: &Vector3) -> Vector3 {
        self.rot * v + self.t
    }

    #[inline]
    pub(crate) fn inverse_apply(&self, v: &Vector3) -> Vector3 {
        self.rot.tr_mul(&(v - self.t))
    }

    /// A box of B's mesh frame expressed in A's.
    pub(crate) fn box_in_a(&self, o: &crate::obb::Obb) -> crate::obb::Obb {
        crate::obb::Obb {
            center: self.apply(&o.center),
            axes: self.rot * o.axes,
            half_extents: o.half_extents,
        }
    }

    /// A box of A's mesh frame expressed in B's.
    pub(crate) fn box_in_b(&self, o: &crate::obb::Obb) -> crate::obb::Obb {
        crate::obb::Obb {
            center: self.inverse_apply(&o.center),
            axes: self.rot.tr_mul(&o.axes),
            half_extents: o.half_extents,
        }
    }
}

/// All contacts between meshes A (I) and B (J), B at `pose_ab` in A's frame; appends to `out`.
pub(crate) fn mesh_mesh(
    a: &FacetMesh,
    b: &FacetMesh,
    pose_ab: &Isometry3,
    s: &mut Scratch,
    work: &mut WorkCounters,
    out: &mut Vec<LocalContact>,
) {
    let x = RelativePose::new(pose_ab);
    crate::crossings::find_crossings(a, b, &x, s, work);
    if s.hits.is_empty() {
        if let Some(c) = containment(a, b, &x) {
            out.push(c);
        }
        return;
    }
    build_nodes(a, b, &x, s);
    flood(a, b, &x, s);
    let region_count = label_regions(s);
    s.regions.clear();
    s.regions.resize(region_count, RegionSums::default());
    sum_loops(a, b, &x, s);
    crate::region_volumes::sum_volumes(a, b, &x, s);
    closest_points(a, b, &x, s);
    for r in &s.regions {
        out.push(finish_region(r));
    }
}

pub(crate) fn new_node(s: &mut Scratch, side: u8, tri: u32, crossing: bool) -> u32 {
    let id = s.nodes.len() as u32;
    s.nodes.push(RegionNode {
        side,
        tri,
        crossing,
        parent: id,
        region: 0,
        hit_start: 0,
        hit_count: 0,
        inside_corners: 0,
        edges: crate::triangle_pieces::ALL_EDGES,
        next_piece: crate::triangle_pieces::NO_PIECE,
        split: false,
    });
    s.slots[side as usize].insert(tri, id);
    id
}

fn find(nodes: &mut [RegionNode], mut i: u32) -> u32 {
    while nodes[i as usize].parent != i {
        let p = nodes[i as usize].parent;
        nodes[i as usize].parent = nodes[p as usize].parent;
        i = p;
    }
    i
}

pub(crate) fn union(nodes: &mut [RegionNode], i: u32, j: u32) {
    let (ri, rj) = (find(nodes, i), find(nodes, j));
    // The smaller index becomes the root: labels then follow first appearance, deterministically.
    if ri < rj {
        nodes[rj as usize].parent = ri;
    } else if rj < ri {
        nodes[ri as usize].parent = rj;
    }
}

/// One node per crossing triangle, hit lists per node (CSR), triangles split into the pieces
/// their hits bound ([`crate::triangle_pieces`]); then the pieces are united across each
/// crossing and where the intersection curve goes on into a neighbouring triangle.
fn build_nodes(a: &FacetMesh, b: &FacetMesh, x: &RelativePose, s: &mut Scratch) {
    s.nodes.clear();
    s.slots[0].reset(a.triangles.len());
    s.slots[1].reset(b.triangles.len());
    for h in 0..s.hits.len() {
        let Hit { ta, tb, .. } = s.hits[h];
        let na = match s.slots[0].get(ta) {
            Some(n) => n,
            None => new_node(s, 0, ta, true),
        };
        let nb = match s.slots[1].get(tb) {
            Some(n) => n,
            None => new_node(s, 1, tb, true),
        };
        s.nodes[na as usize].hit_count += 1;
        s.nodes[nb as usize].hit_count += 1;
    }
    let mut start = 0;
    for n in s.nodes.iter_mut() {
        n.hit_start = start;
        start += n.hit_count;
        n.hit_count = 0;
    }
    s.node_hits.clear();
    s.node_hits.resize(start as usize, 0);
    for (h, hit) in s.hits.iter().enumerate() {
        for (side, tri) in [(0, hit.ta), (1, hit.tb)] {
            if let Some(id) = s.slots[side].get(tri) {
                let n = &mut s.nodes[id as usize];
                s.node_hits[(n.hit_start + n.hit_count) as usize] = h as u32;
                n.hit_count += 1;
            }
        }
    }
    crate::triangle_pieces::split_crossing_triangles(a, b, x, s);
    s.hit_nodes.clear();
    s.hit_nodes.resize(s.hits.len(), [0; 2]);
    for (id, n) in s.nodes.iter().enumerate() {
        for &h in &s.node_hits[n.hit_start as usize..(n.hit_start + n.hit_count) as usize] {
            s.hit_nodes[h as usize][n.side as usize] = id as u32;
        }
    }
    for h in 0..s.hits.len() {
        let [na, nb] = s.hit_nodes[h];
        union(&mut s.nodes, na, nb);
    }
    // The intersection curve goes on across the edge (or corner) each segment ends on, into
    // the neighbouring triangle there: crossing triangles met that way are one region even
    // where no single triangle of the other mesh joins them (a corner grazing a face right on
    // the diagonal between its two triangles).
    for h in 0..s.hits.len() {
        let hit = s.hits[h];
        for end in hit.ends {
            let (side, tri, mesh) = if end.first {
                (0, hit.ta, a)
            } else {
                (1, hit.tb, b)
            };
            let across = match end.feature {
                Feature::Edge(k) => [k, k],
                // A corner: the edges on both sides of it.
                Feature::Corner(k) => [k, (k + 2) % 3],
            };
            let own = s.hit_nodes[h][side];
            for k in across {
                let next = mesh.neighbors[tri as usize][k as usize];
                if next == crate::facet_mesh::NO_NEIGHBOR {
                    continue;
                }
                if let Some(first) = s.slots[side].get(next) {
                    let other = continuing_piece(s, first, side as u8, &hit);
                    union(&mut s.nodes, own, other);
                }
            }
        }
    }
}

/// The piece of a neighbouring triangle (its first node `first`) that the curve of `hit` goes
/// on into: the one holding a hit with the same triangle of the other surface, else the one
/// holding the segment nearest to `hit`'s.
fn continuing_piece(s: &Scratch, first: u32, side: u8, hit: &Hit) -> u32 {
    let mut piece = first;
    if s.nodes[first as usize].next_piece == crate::triangle_pieces::NO_PIECE {
        return first;
    }
    let other = |h: &Hit| if side == 0 { h.tb } else { h.ta };
    let mut nearest = (f64::INFINITY, first);
    while piece != crate::triangle_pieces::NO_PIECE {
        let n = &s.nodes[piece as usize];
        for &h in &s.node_hits[n.hit_start as usize..(n.hit_start + n.hit_count) as usize] {
            let next = &s.hits[h as usize];
            if other(next) == other(hit) {
                return piece;
            }
            let gap = [next.s0, next.s1]
                .iter()
                .flat_map(|p| [(p - hit.s0).norm(), (p - hit.s1).norm()])
                .fold(f64::INFINITY, f64::min);
            if gap < nearest.0 {
                nearest = (gap, piece);
            }
        }
        piece = n.next_piece;
    }
    nearest.1
}

/// A triangle's corners in A's frame.
#[inline]
pub(crate) fn corners_in_a(m: &FacetMesh, side: u8, tri: u32, x: &RelativePose) -> [Vector3; 3] {
    let c = m.corners(tri);
    if side == 0 {
        c
    } else {
        [x.apply(&c[0]), x.apply(&c[1]), x.apply(&c[2])]
    }
}

/// The plane (unit normal, point) in A's frame of the triangle on the other side of hit `h`.
#[inline]
pub(crate) fn other_plane(side: u8, hit: &Hit) -> (Vector3, Vector3) {
    if side == 0 { hit.plane_b } else { hit.plane_a }
}

/// Sets each node's `region` to the index of its set, numbered in order of first appearance;
/// returns the number of regions. A set's root is its smallest index (see [`union`]).
pub(crate) fn label_regions(s: &mut Scratch) -> usize {
    let n = s.nodes.len();
    for i in 0..n {
        let r = find(&mut s.nodes, i as u32);
        s.nodes[i].parent = r;
    }
    let mut count = 0u32;
    for i in 0..n {
        let root = s.nodes[i].parent as usize;
        if root == i {
            s.nodes[i].region = count;
            count += 1;
        } else {
            s.nodes[i].region = s.nodes[root].region;
        }
    }
    count as usize
}

fn sum_loops(a: &FacetMesh, b: &FacetMesh, x: &RelativePose, s: &mut Scratch) {
    for h in 0..s.hits.len() {
        let hit = s.hits[h];
        let r = s.nodes[s.hit_nodes[h][0] as usize].region as usize;
        let sums = &mut s.regions[r];
        if !sums.seen {
            sums.seen = true;
            sums.reference = hit.s0;
            // J's outward facet normal: the fallback direction of the force on I.
            sums.fallback_normal =
                x.rot * b.face_normals[hit.tb as usize] - a.face_normals[hit.ta as usize];
        }
        let (p0, p1) = (hit.s0 - sums.reference, hit.s1 - sums.reference);
        sums.vector_area += 0.5 * p0.cross(&p1);
        let len = (hit.s1 - hit.s0).norm();
        sums.loop_length += len;
        sums.loop_moment += len * 0.5 * (hit.s0 + hit.s1);
        sums.loop_points += 2;
        sums.loop_point_sum += hit.s0 + hit.s1;
    }
    for r in s.regions.iter_mut() {
        r.apex = if r.loop_length > 0.0 {
            r.loop_moment / r.loop_length
        } else {
            r.loop_point_sum / r.loop_points.max(1) as f64
        };
    }
}

pub(crate) fn add_polygon(sums: &mut RegionSums, poly: &[Vector3]) {
    let o = sums.apex;
    for k in 1..poly.len().saturating_sub(1) {
        let (p, q, r) = (poly[0] - o, poly[k] - o, poly[k + 1] - o);
        let v = p.dot(&q.cross(&r)) / 6.0;
        sums.volume += v;
        // × 0.25 is ÷ 4 to the bit, without three divisions.
        sums.volume_moment += v * (p + q + r) * 0.25;
    }
}

/// Sutherland–Hodgman: keeps the part of `poly` with `n·(v − p0) ≤ 0`, into `out`
/// ([`clip_by_heights`] with the heights formed once per corner).
pub(crate) fn clip(poly: &[Vector3], out: &mut Vec<Vector3>, n: &Vector3, p0: &Vector3) {
    out.clear();
    clip_by_heights(
        poly.len(),
        |k| (poly[k], n.dot(&(poly[k] - p0))),
        |p| out.push(p),
        |_| {},
    );
}

/// Sutherland–Hodgman on the polygon of `count` corners `corner(k) = (point, height)`: pushes
/// the corners at or below the plane (height ≤ 0) and the points where an edge passes
/// strictly through it, `u + (v − u)·h_u/(h_u − h_v)`, in order; calls `crossing` with the
/// point of every edge whose ends lie on either side of `h ≤ 0` (the polygon's waterline ends,
/// a corner on the plane included). `corner` is called once per corner, in order; the wrap
/// to the first corner is the last step rather than an index taken modulo the count.
pub(crate) fn clip_by_heights(
    count: usize,
    corner: impl Fn(usize) -> (Vector3, f64),
    mut push: impl FnMut(Vector3),
    mut crossing: impl FnMut(Vector3),
) {
    if count == 0 {
        return;
    }
    let first = corner(0);
    let (mut u, mut du) = first;
    for k in 1..=count {
        let (v, dv) = if k < count { corner(k) } else { first };
        if du <= 0.0 {
            push(u);
        }
        let strict = (du < 0.0 && dv > 0.0) || (du > 0.0 && dv < 0.0);
        if strict || (du <= 0.0) != (dv <= 0.0) {
            let at = u + (v - u) * (du / (du - dv));
            if strict {
                push(at);
            }
            if (du <= 0.0) != (dv <= 0.0) {
                crossing(at);
            }
        }
        (u, du) = (v, dv);
    }
}

/// Each region's contact points: where the line through its centroid `g` along the loop normal
/// meets the two surfaces (I's along `−n`, J's along `+n`), lifted onto the curved surfaces the
/// facets approximate. The line's hits move continuously with the pose; the closest points to
/// `g` (used where the loop is degenerate or the line meets nothing) jump between facets where
/// two are equally near, and a force that jumps defeats the solver's Newton corrector.
fn closest_points(a: &FacetMesh, b: &FacetMesh, x: &RelativePose, s: &mut Scratch) {
    let Scratch { regions, stack, .. } = s;
    for r in regions.iter_mut() {
        let g = r.centroid;
        let gb = x.inverse_apply(&g);
        let along = loop_normal(r).map(|n| {
            (
                a.first_ray_hit(&g, &(-n)),
                b.first_ray_hit(&gb, &x.rot.tr_mul(&n)),
            )
        });
        let (ti, pi) = match along {
            Some((Some(hit), _)) => hit,
            _ => a.closest_point(&g, stack),
        };
        let (tj, pj) = match along {
            Some((_, Some(hit))) => hit,
            _ => b.closest_point(&gb, stack),
        };
        r.best_i = (0.0, a.lift_to_surface(ti, &pi), ti);
        r.best_j = (0.0, x.apply(&b.lift_to_surface(tj, &pj)), tj);
        // Only a region measured deeper than the convex bound pays for the inside tests (open
        // meshes have no inside: their regions keep the line's measure).
        let area = r.vector_area.norm();
        let bound = 3.0 * r.volume.max(0.0) / area;
        let outside = area > 0.0
            && bound.is_finite()
            && (r.best_j.1 - r.best_i.1).norm() > bound
            && a.closed
            && b.closed
            && !(a.contains(&Point3::from(g)) && b.contains(&Point3::from(gb)));
        r.held_to_bound = false;
        let Some(n) = loop_normal(r).filter(|_| outside) else {
            continue;
        };
        match chord_beside(a, b, x, &g, &n) {
            Some((i, j)) => {
                r.best_i = (0.0, a.lift_to_surface(i.0, &i.1), i.0);
                r.best_j = (0.0, x.apply(&b.lift_to_surface(j.0, &j.1)), j.0);
            }
            None => r.held_to_bound = true,
        }
    }
}

/// The centroid `g` of a region that is not convex lies outside one of the bodies (a
/// crescent where a convex surface presses into a nearly conforming concave one, or a body in
/// a cavity), and the rays from it along `∓n` cross the far side of that body. The line
/// through `g` still crosses the region itself beside `g`: on one side of it, the first hits
/// of the two surfaces bound a chord whose middle lies in both bodies. That chord's ends, I's
/// point `(triangle, point)` in A's frame and J's in B's, are SPEC §4's contact points; `None`
/// when neither side has such a chord (a ring lying flat, whose centroid is in its hole).
#[allow(clippy::type_complexity)]
fn chord_beside(
    a: &FacetMesh,
    b: &FacetMesh,
    x: &RelativePose,
    g: &Vector3,
    n: &Vector3,
) -> Option<((u32, Vector3), (u32, Vector3))> {
    let gb = x.inverse_apply(g);
    let mut best: Option<(f64, (u32, Vector3), (u32, Vector3))> = None;
    for side in [-1.0, 1.0] {
        let dir = n * side;
        let (Some(hit_a), Some(hit_b)) = (
            a.first_ray_hit(g, &dir),
            b.first_ray_hit(&gb, &x.rot.tr_mul(&dir)),
        ) else {
            continue;
        };
        let (pa, pb) = (hit_a.1, x.apply(&hit_b.1));
        // J's point lies beyond I's along n; the chord's middle in both bodies.
        let middle = 0.5 * (pa + pb);
        if (pb - pa).dot(n) <= 0.0
            || !a.contains(&Point3::from(middle))
            || !b.contains(&Point3::from(x.inverse_apply(&middle)))
        {
            continue;
        }
        let near = (pa - g).norm().min((pb - g).norm());
        if best.as_ref().is_none_or(|(d, _, _)| near < *d) {
            best = Some((near, hit_a, hit_b));
        }
    }
    best.map(|(_, i, j)| (i, j))
}

/// The region's normal from J into I, `−S/|S|` with `S` the loop's vector area, or `None` when
/// the loop encloses (almost) no area.
pub(crate) fn loop_normal(r: &RegionSums) -> Option<Vector3> {
    let area = r.vector_area.norm();
    let scale = r.loop_length.max(f64::MIN_POSITIVE);
    (area > 1e-12 * scale * scale).then(|| -r.vector_area / area)
}

fn finish_region(r: &RegionSums) -> LocalContact {
    let (pi, pj) = (r.best_i.1, r.best_j.1);
    let area = r.vector_area.norm();
    let normal = if let Some(n) = loop_normal(r) {
        n
    } else if let Some(n) = (pj - pi).try_normalize(1e-300) {
        n
    } else {
        r.fallback_normal
            .try_normalize(0.0)
            .unwrap_or_else(Vector3::z)
    };
    // A region whose centroid lies outside one of the bodies and whose line crosses it nowhere
    // beside the centroid (see `chord_beside`). A convex region of volume V whose
    // cross-section normal to n has area A is no thicker along n than 3V/A (the cone over
    // its section is the thinnest such body): the penetration of such a region is held to
    // that, the point on J moved along the normal with it.
    if r.held_to_bound {
        // The clipped volume can come out below zero where J is concave (see the error bound
        // in the module docs): no depth then, never a negative one.
        let bound = 3.0 * r.volume.max(0.0) / area;
        return LocalContact {
            point_i: pi,
            point_j: pi + normal * bound,
            normal,
            penetration: bound,
            area,
        };
    }
    LocalContact {
        point_i: pi,
        point_j: pj,
        normal,
        penetration: (pj - pi).norm(),
        area,
    }
}

/// No crossings: one body may lie wholly inside the other (both closed, root boxes overlapping).
///
/// I inside J: `g` is I's centroid (the intersection's), `p_j` the closest point to it on J
/// (where the line through `g` along `n` first meets J), the normal `(p_j − g)` normalised
/// (the way out), `p_i` where the line through `g` leaves I along `−n` (SPEC §4's ray rule;
/// I's vertex deepest along `−n` when the line misses I, a centroid outside a non-convex
/// body), penetration `(p_j − p_i)·n`. J inside I mirrors this. The normal comes from the
/// closest point on the outer mesh's facets, so it is accurate to about one facet angle of the
/// outer mesh (the crossing path's loop normal is far better); the penetration to `O(δ)`.
pub(crate) fn containment(a: &FacetMesh, b: &FacetMesh, x: &RelativePose) -> Option<LocalContact> {
    if !(a.closed && b.closed) {
        return None;
    }
    let (ra, rb) = (a.tree.root(), b.tree.root());
    let r = ra.axes.tr_mul(&(x.rot * rb.axes));
    let t = ra.axes.tr_mul(&(x.apply(&rb.center) - ra.center));
    // Apart, unless one is inside out: a body clear of a cavity is wholly in its material.
    let overlap = boxes_overlap(&ra.half_extents, &rb.half_extents, &r, &t);
    if !(a.inside_out || b.inside_out || overlap) {
        return None;
    }
    if inside_by_majority(a, |v| b.contains(&Point3::from(x.inverse_apply(v)))) {
        let g = if a.inside_out {
            // A cavity whose surface lies in solid B: the intersection is B less the cavity.
            shell_centroid(
                &x.apply(&b.centroid.coords),
                b.volume,
                &a.centroid.coords,
                a.volume,
            )
        } else {
            a.centroid.coords
        };
        let gb = x.inverse_apply(&g);
        let pj = x.apply(&b.closest_point(&gb, &mut Vec::new()).1);
        let n = (pj - g).try_normalize(0.0).unwrap_or_else(Vector3::z);
        let pi = a.first_ray_hit(&g, &(-n)).map_or_else(
            || support(a.vertices.iter().map(|v| v.coords), &(-n)),
            |h| h.1,
        );
        return Some(LocalContact {
            point_i: pi,
            point_j: pj,
            normal: n,
            penetration: (pj - pi).dot(&n).max(0.0),
            area: 0.25 * a.area,
        });
    }
    if inside_by_majority(b, |v| a.contains(&Point3::from(x.apply(v)))) {
        let g = if b.inside_out {
            shell_centroid(
                &a.centroid.coords,
                a.volume,
                &x.apply(&b.centroid.coords),
                b.volume,
            )
        } else {
            x.apply(&b.centroid.coords)
        };
        let pi = a.closest_point(&g, &mut Vec::new()).1;
        let n = (g - pi).try_normalize(0.0).unwrap_or_else(Vector3::z);
        let pj = b
            .first_ray_hit(&x.inverse_apply(&g), &x.rot.tr_mul(&n))
            .map_or_else(
                || support(b.vertices.iter().map(|v| x.apply(&v.coords)), &n),
                |h| x.apply(&h.1),
            );
        return Some(LocalContact {
            point_i: pi,
            point_j: pj,
            normal: n,
            penetration: (pj - pi).dot(&n).max(0.0),
            area: 0.25 * b.area,
        });
    }
    None
}

/// The centroid of a solid (centroid `solid`, volume `v > 0`) less a cavity inside it
/// (centroid `cavity`, volume `w < 0`, as an inside-out mesh keeps it): `(v·s + w·c)/(v + w)`;
/// the solid's own centroid when nothing is left.
fn shell_centroid(solid: &Vector3, v: f64, cavity: &Vector3, w: f64) -> Vector3 {
    let left = v + w;
    if left > 0.0 {
        (solid * v + cavity * w) / left
    } else {
        *solid
    }
}

/// Whether `mesh` lies inside the other solid, with no crossing between them: judged by the
/// centroids of three of its triangles (first, middle, last), two of which must be inside. A
/// point on the other surface counts there as outside or inside as the triangle tests'
/// perturbation puts it, which the ray test cannot know; a triangle's centroid lies on the
/// other surface only where the two faces are flush or touch, while a vertex does wherever a
/// corner or an edge rests on the other body (two boxes touching along an edge share two
/// vertices' worth of surface and no volume). The vote keeps one flush face from deciding.
fn inside_by_majority(mesh: &FacetMesh, inside: impl Fn(&Vector3) -> bool) -> bool {
    let n = mesh.triangles.len();
    if n == 0 {
        return false;
    }
    let votes = [0, n / 2, n - 1]
        .iter()
        .filter(|&&t| {
            let [p, q, r] = mesh.corners(t as u32);
            inside(&((p + q + r) / 3.0))
        })
        .count();
    votes >= 2
}

fn support(points: impl Iterator<Item = Vector3>, dir: &Vector3) -> Vector3 {
    points
        .max_by(|u, v| u.dot(dir).total_cmp(&v.dot(dir)))
        .unwrap_or_else(Vector3::zeros)
}
