//! Mesh against a half-space (a 3-D PLANE): exact triangle-against-plane clipping, no
//! tessellation of the plane.
//!
//! The triangles with a corner at or below the plane are found through the mesh's OBB tree
//! (a box wholly above the plane is skipped), grouped into regions by edge adjacency, and each
//! region gives one contact: the normal is the plane's (exact), the intersection volume's
//! centroid `g` comes from the divergence theorem over the clipped triangles as tetrahedra from
//! a point on the plane (the plane's lid then adds nothing), `point_j` is `g` projected on the
//! plane, `point_i` the point of the region's triangles straight below `g` along the plane's
//! normal (the closest point to `g` where that ray meets none), lifted onto the curved PN
//! triangle of that facet ([`FacetMesh::lift_to_surface`]), the penetration their distance.
//! The ray, not the closest point, keeps the depth and the force's line of action continuous
//! in the pose: around a vertex the closest point jumps from facet to facet. The area is the area
//! enclosed by the waterline loop (for a body wholly under the plane: its downward-facing area
//! projected on the plane).
//!
//! A convex mesh has one region below an unbounded plane, summed in one pass: over its flat
//! faces where it has few (`faces`: a box's six sides, a cylinder's caps and side strips),
//! else over its triangles (`convex`, the general path's sums to the bit).
//!
//! A bounded plane (finite XMIN…YMAX) stands for the prism under its rectangle: it ignores
//! triangles whose corners all lie beyond one of its edges, and a region reaching over an edge
//! is clipped by the prism's side faces too, its normal and centroid those of the clipped
//! intersection (`edge`).

use crate::contact_region::{
    LocalContact, add_polygon, clip_by_heights, label_regions, new_node, union,
};
use crate::facet_mesh::{FacetMesh, NO_NEIGHBOR};
use crate::plane_support::{
    Support, alone_contact, blended, ellipsoid_on_plane, sphere_on_plane, supports_by_region,
};
use crate::scratch::{PlaneNode, RegionSums, Scratch};
use contact_core::geometry::Plane;
use contact_core::{Isometry3, Matrix3, Vector3, WorkCounters};
use convex::convex_region;
use faces::faces_region;

mod convex;
mod edge;
mod faces;
#[cfg(test)]
pub(crate) mod tests;

/// A mesh of at most this many triangles is scanned whole against a plane rather than through
/// its OBB tree: the tree's box tests cost more than the few triangles they would skip.
const SCAN_WITHOUT_TREE: usize = 128;

/// The pose `X_AP` of plane P in mesh A's frame from the world poses `X_WA` and `X_WP`.
///
/// An unbounded plane's frame is first slid along the plane to the foot of A's origin, so the
/// translation is A's height above the plane, `R_AP · (0, 0, −h)`, computed from A's position in
/// P's frame: a mesh far along the plane from P's origin (1e85 away, 0.1 above it) keeps its
/// 0.1, which `X_WA⁻¹ · X_WP` loses to cancellation. A bounded plane keeps its frame (its
/// XMIN…YMAX are measured from it).
pub(crate) fn plane_pose_in_mesh_frame(
    pose_wa: &Isometry3,
    pose_wp: &Isometry3,
    plane: &Plane,
) -> Isometry3 {
    if !plane.is_unbounded() {
        return pose_wa.inv_mul(pose_wp);
    }
    let pose_pa = pose_wp.inv_mul(pose_wa);
    let rotation_ap = pose_pa.rotation.inverse();
    let height = pose_pa.translation.vector.z;
    Isometry3::from_parts(
        (rotation_ap * Vector3::new(0.0, 0.0, -height)).into(),
        rotation_ap,
    )
}

/// The plane's frame in A's frame: axes, origin, normal.
#[derive(Clone, Copy)]
struct PlaneFrame {
    rot: Matrix3,
    origin: Vector3,
    n: Vector3,
}

impl PlaneFrame {
    fn new(pose_a_plane: &Isometry3) -> Self {
        let rot = pose_a_plane.rotation.to_rotation_matrix().into_inner();
        Self {
            rot,
            origin: pose_a_plane.translation.vector,
            n: rot.column(2).into_owned(),
        }
    }

    /// The height of `v` above the plane, along its normal.
    fn height(&self, v: &Vector3) -> f64 {
        self.n.dot(&(v - self.origin))
    }

    /// Triangle `t` with corners `c` as a node of the plane passes, and its lowest corner's
    /// height (the triangle reaches the plane where it is ≤ 0).
    fn node(&self, t: u32, c: [Vector3; 3]) -> (PlaneNode, f64) {
        let h = [self.height(&c[0]), self.height(&c[1]), self.height(&c[2])];
        let node = PlaneNode {
            tri: t,
            crossing: h[0] > 0.0 || h[1] > 0.0 || h[2] > 0.0,
            corners: c,
            heights: h,
        };
        (node, h[0].min(h[1]).min(h[2]))
    }
}

/// All contacts of mesh A (taken as I) with the half-space whose frame is at `pose_a_plane`
/// (`X_AP`, from [`plane_pose_in_mesh_frame`]) in A's frame; appends them in A's frame to `out`.
pub(crate) fn mesh_plane(
    a: &FacetMesh,
    plane: &Plane,
    pose_a_plane: &Isometry3,
    s: &mut Scratch,
    work: &mut WorkCounters,
    out: &mut Vec<LocalContact>,
) {
    let frame = PlaneFrame::new(pose_a_plane);
    let n = frame.n;
    let height = |v: &Vector3| frame.height(v);
    if plane.is_unbounded()
        && let Some(found) = sphere_on_plane(a, &n, &height)
    {
        out.extend(found);
        return;
    }
    if plane.is_unbounded()
        && let Some((centre, semi)) = a.implied_ellipsoid
    {
        let Some(cap) = ellipsoid_on_plane(&centre.coords, &semi, &n, &height) else {
            return;
        };
        if cap.weight < 1.0 {
            // Deeper: blended with the facets' one region (none while they stay above).
            let start = out.len();
            facets_plane(a, plane, &frame, s, work, out);
            match out.len() - start {
                0 => out.push(alone_contact(&cap, &n)),
                1 => out[start] = blended(&out[start], &cap, &n),
                _ => {}
            }
        } else {
            out.push(alone_contact(&cap, &n));
        }
        return;
    }
    facets_plane(a, plane, &frame, s, work, out);
}

/// The facets' contacts of mesh A with the plane (a tessellated sphere's blended with the
/// sphere's support points); as [`mesh_plane`]: the triangles at or below the plane become
/// nodes joined into regions by edge adjacency, each region's waterline loop and clipped
/// volume are summed, and each region gives one contact.
fn facets_plane(
    a: &FacetMesh,
    plane: &Plane,
    frame: &PlaneFrame,
    s: &mut Scratch,
    work: &mut WorkCounters,
    out: &mut Vec<LocalContact>,
) {
    if a.convex && plane.is_unbounded() && a.implied_sphere.is_none() {
        let found = match &a.flat_faces {
            Some(faces) => faces_region(a, faces, frame, s, work),
            None => convex_region(a, frame, s, work),
        };
        if let Some(found) = found {
            out.extend(found);
            return;
        }
    }
    let n = frame.n;
    let height = |v: &Vector3| frame.height(v);
    // How far the sphere a tessellated sphere's facets stand for reaches beyond them: the PN
    // patches' reach, doubled (the sphere's sag over a facet and the patch's differ by the
    // patch's error, far below either). Other meshes keep their facets' contact.
    let beyond_facets = if a.implied_sphere.is_some() {
        2.0 * a.pn_reach
    } else {
        0.0
    };
    let curved = nodes_below(a, plane, frame, beyond_facets, s, work);
    let count = regions_by_flood(a, s);
    s.regions.clear();
    s.regions.resize(count, RegionSums::default());
    // The smooth surface's support points (`plane_support`): a region they answer whole
    // needs no facet sums.
    let mut by_region = vec![None; count];
    let mut alone = Vec::new();
    if !curved.is_empty() {
        let region_tris: Vec<(u32, u32)> = s.nodes.iter().map(|n| (n.tri, n.region)).collect();
        supports_by_region(
            a,
            &n,
            &height,
            &curved,
            &region_tris,
            &mut by_region,
            &mut alone,
        );
    }
    s.curved = curved;
    // Regions reaching over a bounded plane's edge are answered on the prism under it.
    let prism = (!plane.is_unbounded()).then(|| edge::Prism::new(plane, frame));
    let mut over_edge = vec![false; count];
    if let Some(prism) = &prism {
        for node in &s.nodes {
            if !over_edge[node.region as usize] {
                over_edge[node.region as usize] = prism.reaches_over_an_edge(&a.corners(node.tri));
            }
        }
    }
    let smooth_only: Vec<bool> = by_region
        .iter()
        .zip(&over_edge)
        .map(|(b, &over)| over || b.is_some_and(|s: Support| s.weight >= 1.0))
        .collect();
    sum_waterlines(a, frame, &smooth_only, s);
    sum_volumes(a, frame, &smooth_only, s);
    for (index, r) in s.regions.iter().enumerate() {
        let in_region = s
            .nodes
            .iter()
            .filter(|node| node.region as usize == index)
            .map(|node| node.tri);
        if let (Some(prism), true) = (&prism, over_edge[index]) {
            out.extend(edge::edge_region_contact(a, prism, in_region));
            continue;
        }
        let support = by_region[index];
        if let Some(support) = support.filter(|_| smooth_only[index]) {
            out.push(alone_contact(&support, &n));
            continue;
        }
        let facets = region_contact(a, frame, in_region, r);
        out.push(match support {
            Some(support) => blended(&facets, &support, &n),
            None => facets,
        });
    }
    out.extend(alone.iter().map(|s| alone_contact(s, &n)));
}

/// The triangles that may reach `beyond_facets` below the plane, into `below`: all of a small
/// mesh, else those of the OBB tree's leaves that reach it.
fn candidates(
    a: &FacetMesh,
    frame: &PlaneFrame,
    beyond_facets: f64,
    below: &mut Vec<u32>,
    work: &mut WorkCounters,
) {
    below.clear();
    if a.triangles.len() <= SCAN_WITHOUT_TREE {
        below.extend(0..a.triangles.len() as u32);
        return;
    }
    let n = frame.n;
    let mut box_tests = 0;
    a.tree.visit(
        |obb| {
            box_tests += 1;
            let reach: f64 = (0..3)
                .map(|i| obb.half_extents[i] * n.dot(&obb.axes.column(i)).abs())
                .sum();
            frame.height(&obb.center) - reach <= beyond_facets
        },
        |t| below.push(t),
    );
    work.bounding_volume_tests += box_tests;
}

/// A node per triangle at or below the plane (within a bounded plane's XMIN…YMAX), with its
/// corners' heights; returns the curved triangles within `beyond_facets` of it (whose smooth
/// surface may reach below it).
fn nodes_below(
    a: &FacetMesh,
    plane: &Plane,
    frame: &PlaneFrame,
    beyond_facets: f64,
    s: &mut Scratch,
    work: &mut WorkCounters,
) -> Vec<u32> {
    let PlaneFrame { rot, origin, .. } = *frame;
    let [x0, x1] = plane.x_range();
    let [y0, y1] = plane.y_range();
    let bounded = !plane.is_unbounded();
    let (ex, ey) = (rot.column(0).into_owned(), rot.column(1).into_owned());
    let beyond = |c: &[Vector3; 3]| {
        let xs = c.map(|v| ex.dot(&(v - origin)));
        let ys = c.map(|v| ey.dot(&(v - origin)));
        xs.iter().all(|&u| u < x0)
            || xs.iter().all(|&u| u > x1)
            || ys.iter().all(|&u| u < y0)
            || ys.iter().all(|&u| u > y1)
    };
    s.nodes.clear();
    s.plane_nodes.clear();
    s.slots[0].reset(a.triangles.len());
    let mut below: Vec<u32> = std::mem::take(&mut s.queue);
    candidates(a, frame, beyond_facets, &mut below, work);
    let mut curved = std::mem::take(&mut s.curved);
    curved.clear();
    for &t in &below {
        work.primitive_tests += 1;
        let c = a.corners(t);
        if bounded && beyond(&c) {
            continue;
        }
        let (node, lowest) = frame.node(t, c);
        if lowest <= 0.0 {
            new_node(s, 0, t, node.crossing);
            s.plane_nodes.push(node);
        }
        if a.implied_sphere.is_some() && lowest <= beyond_facets && a.is_curved(t) {
            curved.push(t);
        }
    }
    s.queue = below;
    curved
}

/// Labels the nodes' regions by edge adjacency and returns their count: a flood from each
/// unlabelled node in turn, so regions are numbered by their first node, as
/// [`label_regions`] numbers them (a set's root is its smallest index). A flood that reaches a
/// node of an earlier region has met a link its neighbour does not return (an edge shared by
/// more than two triangles): the nodes are then joined by union–find, which takes every link
/// both ways.
fn regions_by_flood(a: &FacetMesh, s: &mut Scratch) -> usize {
    const UNLABELLED: u32 = u32::MAX;
    for node in &mut s.nodes {
        node.region = UNLABELLED;
    }
    let mut stack = std::mem::take(&mut s.queue);
    let mut count = 0u32;
    let mut one_sided = false;
    'starts: for start in 0..s.nodes.len() {
        if s.nodes[start].region != UNLABELLED {
            continue;
        }
        s.nodes[start].region = count;
        stack.clear();
        stack.push(start as u32);
        while let Some(id) = stack.pop() {
            let tri = s.nodes[id as usize].tri;
            for &nb in &a.neighbors[tri as usize] {
                let Some(other) = (nb != NO_NEIGHBOR).then(|| s.slots[0].get(nb)).flatten() else {
                    continue;
                };
                let node = &mut s.nodes[other as usize];
                if node.region == UNLABELLED {
                    node.region = count;
                    stack.push(other);
                } else if node.region != count {
                    one_sided = true;
                    break 'starts;
                }
            }
        }
        count += 1;
    }
    s.queue = stack;
    if !one_sided {
        return count as usize;
    }
    for id in 0..s.nodes.len() {
        s.nodes[id].parent = id as u32;
    }
    for id in 0..s.nodes.len() {
        let tri = s.nodes[id].tri;
        for &nb in &a.neighbors[tri as usize] {
            if let Some(other) = (nb != NO_NEIGHBOR).then(|| s.slots[0].get(nb)).flatten() {
                union(&mut s.nodes, id as u32, other);
            }
        }
    }
    label_regions(s)
}

/// Each region's waterline loop (its vector area, length and length moment), the segments
/// oriented along `n_tri × n_plane` as mesh–mesh segments are; regions the smooth surface
/// answers whole are skipped.
fn sum_waterlines(a: &FacetMesh, frame: &PlaneFrame, smooth_only: &[bool], s: &mut Scratch) {
    for (node, pn) in s.nodes.iter().zip(&s.plane_nodes) {
        if pn.crossing && !smooth_only[node.region as usize] {
            add_waterline(a, &frame.n, pn, &mut s.regions[node.region as usize]);
        }
    }
}

/// Crossing triangle `pn`'s segment of the waterline into `r`: its vector area (from the
/// region's first point), length and length moment, oriented along `n_tri × n`.
fn add_waterline(a: &FacetMesh, n: &Vector3, pn: &PlaneNode, r: &mut RegionSums) {
    let (c, h) = (&pn.corners, &pn.heights);
    let mut pts = [Vector3::zeros(); 2];
    let mut k = 0;
    for i in 0..3 {
        let j = if i == 2 { 0 } else { i + 1 };
        if (h[i] <= 0.0) != (h[j] <= 0.0) && k < 2 {
            pts[k] = c[i] + (c[j] - c[i]) * (h[i] / (h[i] - h[j]));
            k += 1;
        }
    }
    if k < 2 {
        return;
    }
    add_loop_segment(r, pts, &a.face_normals[pn.tri as usize].cross(n));
}

/// A waterline segment into `r`: its vector area (from the region's first point), length and
/// length moment, oriented along `dir` (`n_facet × n`, as mesh–mesh segments are).
fn add_loop_segment(r: &mut RegionSums, mut pts: [Vector3; 2], dir: &Vector3) {
    if (pts[1] - pts[0]).dot(dir) < 0.0 {
        pts.swap(0, 1);
    }
    if !r.seen {
        r.seen = true;
        r.reference = pts[0];
    }
    r.vector_area += 0.5 * (pts[0] - r.reference).cross(&(pts[1] - r.reference));
    let len = (pts[1] - pts[0]).norm();
    r.loop_length += len;
    r.loop_moment += len * 0.5 * (pts[0] + pts[1]);
}

/// Each region's apex (its waterline's centroid on the plane), clipped volume, volume centroid
/// and, for a region without a waterline, downward area; regions the smooth surface answers
/// whole are skipped.
fn sum_volumes(a: &FacetMesh, frame: &PlaneFrame, smooth_only: &[bool], s: &mut Scratch) {
    let n = frame.n;
    let height = |v: &Vector3| frame.height(v);
    let Scratch {
        nodes,
        plane_nodes,
        regions,
        ..
    } = s;
    // A region whose waterline has no length only touches the plane (at a vertex or an edge
    // exactly on it): its point is its lowest corner, with no depth. Without crossing
    // triangles the whole (closed) body is under the plane: its cones sum to its volume from
    // any apex, and its own centroid keeps them small however deep it lies (an apex on the
    // plane, 1e66 away, overflows them).
    let mut touching: Vec<Option<(f64, Vector3)>> = vec![None; regions.len()];
    for (node, pn) in nodes
        .iter()
        .zip(plane_nodes.iter())
        .filter(|(node, _)| node.crossing && regions[node.region as usize].loop_length <= 0.0)
    {
        let slot = &mut touching[node.region as usize];
        for (&v, &h) in pn.corners.iter().zip(&pn.heights) {
            if slot.is_none_or(|(lowest, _)| h < lowest) {
                *slot = Some((h, v));
            }
        }
    }
    for (r, touching) in regions.iter_mut().zip(&touching) {
        r.apex = match touching {
            _ if r.loop_length > 0.0 => {
                let on_loop = r.loop_moment / r.loop_length;
                on_loop - n * height(&on_loop)
            }
            Some((_, lowest)) => lowest - n * height(lowest),
            None => a.centroid.coords,
        };
    }
    for (node, pn) in nodes
        .iter()
        .zip(plane_nodes.iter())
        .filter(|(node, _)| !smooth_only[node.region as usize])
    {
        add_clipped(&n, pn, &mut regions[node.region as usize]);
    }
    for r in regions.iter_mut() {
        r.centroid = volume_centroid(r);
    }
}

/// The part of `pn` at or below the plane into `r`: its cone from the region's apex and, for a
/// region without a waterline, its downward area.
fn add_clipped(n: &Vector3, pn: &PlaneNode, r: &mut RegionSums) {
    let mut clipped = [Vector3::zeros(); 4];
    let polygon = if pn.crossing {
        let mut count = 0;
        clip_by_heights(
            3,
            |k| (pn.corners[k], pn.heights[k]),
            |p| {
                clipped[count] = p;
                count += 1;
            },
            |_| {},
        );
        &clipped[..count]
    } else {
        &pn.corners[..]
    };
    add_polygon(r, polygon);
    if r.loop_length > 0.0 {
        // The waterline's area is the region's (`region_contact`).
        return;
    }
    let mut vector_area = Vector3::zeros();
    for k in 1..polygon.len().saturating_sub(1) {
        vector_area += 0.5 * (polygon[k] - polygon[0]).cross(&(polygon[k + 1] - polygon[0]));
    }
    r.down_area += (-vector_area.dot(n)).max(0.0);
}

/// The clipped volume's centroid from the cones' sums (the apex for a region without volume).
fn volume_centroid(r: &RegionSums) -> Vector3 {
    if r.volume > 0.0 {
        r.apex + r.volume_moment / r.volume
    } else {
        r.apex
    }
}

/// The contact of the region of triangles `in_region` from its sums: `point_j` the centroid on
/// the plane, `point_i` I's surface straight below the centroid along −n (continuous in the
/// pose, where the closest point to it jumps between the facets around a vertex), the area the
/// waterline's (else the downward area of a body wholly under the plane).
fn region_contact(
    a: &FacetMesh,
    frame: &PlaneFrame,
    in_region: impl Iterator<Item = u32> + Clone,
    r: &RegionSums,
) -> LocalContact {
    let g = r.centroid;
    let below = a
        .first_ray_hit_among(in_region.clone(), &g, &(-frame.n))
        .unwrap_or_else(|| closest_in_region(a, in_region, &g));
    contact_below(a, frame, r, below)
}

/// [`region_contact`] with I's facet point straight below the centroid found: `below` is its
/// triangle and the point on the flat facet (`u32::MAX` and any point for none).
fn contact_below(
    a: &FacetMesh,
    frame: &PlaneFrame,
    r: &RegionSums,
    (tri, on_facet): (u32, Vector3),
) -> LocalContact {
    let n = frame.n;
    let g = r.centroid;
    let point_j = g - n * frame.height(&g);
    let point_i = if tri == u32::MAX {
        on_facet
    } else {
        a.lift_to_surface(tri, &on_facet)
    };
    let section = if r.loop_length > 0.0 {
        r.vector_area.norm()
    } else {
        r.down_area
    };
    // A region cut by the plane is no thicker along n than 3V/|S| if it is convex (the cone
    // over its section is the thinnest such body), and the line through the centroid of one
    // that is not — a ring of a torus lying flat, whose centroid is in the hole — meets I far
    // from it (0.88 for a ring 2 mm deep). As in mesh–mesh contact, the depth is held to that
    // bound, here where the facets' own depth (before the lift onto the curved surface, which
    // the facets' volume does not see) passes it: never for a convex region, and continuously
    // in the pose; the points are then put on the line through the centroid.
    let bound = 3.0 * r.volume.max(0.0) / section;
    let facets_depth = (point_j - on_facet).norm();
    if a.closed && r.loop_length > 0.0 && bound.is_finite() && facets_depth > bound * (1.0 + 1e-9) {
        return LocalContact {
            point_i: point_j - n * bound,
            point_j,
            normal: n,
            penetration: bound,
            area: section,
        };
    }
    LocalContact {
        point_i,
        point_j,
        normal: n,
        penetration: (point_j - point_i).norm(),
        area: section,
    }
}

/// The point of triangles `in_region` closest to `g`, with its triangle (`u32::MAX` and `g`
/// itself for a region without triangles): where the ray from `g` meets none of them.
fn closest_in_region(
    a: &FacetMesh,
    in_region: impl Iterator<Item = u32>,
    g: &Vector3,
) -> (u32, Vector3) {
    let mut best = (f64::INFINITY, u32::MAX, *g);
    for tri in in_region {
        let p = a.closest_on_triangle(tri, g);
        let d = (p - g).norm_squared();
        if d < best.0 {
            best = (d, tri, p);
        }
    }
    (best.1, best.2)
}
