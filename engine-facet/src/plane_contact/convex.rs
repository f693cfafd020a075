//! The one region of a convex mesh against an unbounded plane: the general path's sums in its
//! own order, without its bookkeeping of regions.

use super::{
    PlaneFrame, add_clipped, add_waterline, candidates, contact_below, region_contact,
    volume_centroid,
};
use crate::contact_region::LocalContact;
use crate::facet_mesh::FacetMesh;
use crate::scratch::{PlaneNode, RegionSums, Scratch};
use contact_core::{Vector3, WorkCounters};

/// The one region of a convex mesh against an unbounded plane ([`FacetMesh::convex`]):
/// [`super::facets_plane`]'s sums in the same order, so the same bits, without the bookkeeping of
/// regions; I's point below the centroid is found as a convex solid's exit ([`exit_below`]). `Some(None)` when no triangle reaches the plane; `None` when the region has no
/// waterline (it only touches the plane, or the whole body is under it), which the general
/// path answers.
pub(super) fn convex_region(
    a: &FacetMesh,
    frame: &PlaneFrame,
    s: &mut Scratch,
    work: &mut WorkCounters,
) -> Option<Option<LocalContact>> {
    let n = frame.n;
    let mut below = std::mem::take(&mut s.queue);
    let mut counted = WorkCounters::default();
    candidates(a, frame, 0.0, &mut below, &mut counted);
    let mut r = RegionSums::default();
    s.plane_nodes.clear();
    for &t in &below {
        counted.primitive_tests += 1;
        let (node, lowest) = frame.node(t, a.corners(t));
        if lowest > 0.0 {
            continue;
        }
        if node.crossing {
            add_waterline(a, &n, &node, &mut r);
        }
        s.plane_nodes.push(node);
    }
    s.queue = below;
    if s.plane_nodes.is_empty() {
        *work += counted;
        return Some(None);
    }
    if r.loop_length <= 0.0 {
        return None;
    }
    *work += counted;
    let on_loop = r.loop_moment / r.loop_length;
    r.apex = on_loop - n * frame.height(&on_loop);
    for node in &s.plane_nodes {
        add_clipped(&n, node, &mut r);
    }
    r.centroid = volume_centroid(&r);
    let in_region = s.plane_nodes.iter().map(|node| node.tri);
    Some(Some(
        match exit_below(a, frame, &s.plane_nodes, &r.centroid) {
            Some(below) => contact_below(a, frame, &r, below),
            None => region_contact(a, frame, in_region, &r),
        },
    ))
}

/// Where the line from `g` along −n leaves the convex mesh, among the triangles below the
/// plane (the exit lies below `g`, so on one of them): the nearest of their planes that face
/// along the line, `s = min n_f·(c − g)/(n_f·(−n))` over `n_f·(−n) > 0`. From a point inside
/// a convex solid that is the exit, with no test of the triangle's edges. On a flat facet that
/// is all the point needs (a fan of coplanar facets, as a cylinder's cap, ties everywhere and
/// any of them gives the point); a curved facet is lifted onto its patch from where it holds
/// the point, so there the ray test ([`FacetMesh::first_ray_hit_among`]) picks among the
/// facets whose planes tie, within `1e-9` of the size. `None` when no plane faces along the
/// line or `g` lies outside one of them (a region without volume), left to the ray test.
fn exit_below(
    a: &FacetMesh,
    frame: &PlaneFrame,
    nodes: &[PlaneNode],
    g: &Vector3,
) -> Option<(u32, Vector3)> {
    let down = -frame.n;
    let along = |node: &PlaneNode| {
        let normal = a.face_normals[node.tri as usize];
        let facing = normal.dot(&down);
        (facing > 0.0).then(|| normal.dot(&(node.corners[0] - g)) / facing)
    };
    let mut best: Option<(f64, u32)> = None;
    for node in nodes {
        if let Some(s) = along(node)
            && best.is_none_or(|(b, _)| s < b)
        {
            best = Some((s, node.tri));
        }
    }
    let (s, tri) = best?;
    if s < 0.0 {
        return None;
    }
    let exit = (tri, g + down * s);
    if !a.is_curved(tri) {
        return Some(exit);
    }
    let tie = 1e-9 * a.size;
    let tied = nodes
        .iter()
        .filter(|node| along(node).is_some_and(|t| t - s <= tie))
        .map(|node| node.tri);
    Some(a.first_ray_hit_among(tied, g, &down).unwrap_or(exit))
}
