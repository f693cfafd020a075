//! The one region of a convex mesh against an unbounded plane: the general path's sums in its
//! own order, without its bookkeeping of regions.

use super::{PlaneFrame, add_clipped, add_waterline, candidates, region_contact, volume_centroid};
use crate::contact_region::LocalContact;
use crate::facet_mesh::FacetMesh;
use crate::scratch::{PlaneNode, RegionSums, Scratch};
use contact_core::WorkCounters;

/// The one region of a convex mesh against an unbounded plane ([`FacetMesh::convex`]):
/// [`super::facets_plane`]'s sums in the same order, so the same bits, without the bookkeeping of
/// regions. `Some(None)` when no triangle reaches the plane; `None` when the region has no
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
        let c = a.corners(t);
        let h = [
            frame.height(&c[0]),
            frame.height(&c[1]),
            frame.height(&c[2]),
        ];
        if h[0].min(h[1]).min(h[2]) > 0.0 {
            continue;
        }
        let node = PlaneNode {
            tri: t,
            crossing: h[0] > 0.0 || h[1] > 0.0 || h[2] > 0.0,
            corners: c,
            heights: h,
        };
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
    Some(Some(region_contact(a, frame, in_region, &r)))
}
