//! Two closed meshes, as given: their polyhedral intersection, one contact per region, by the
//! faceted engine's mesh–mesh method run on the meshes themselves. On meshes as given that
//! method is exact to round-off, so the exact engine takes it rather than a second copy:
//! nothing is tessellated (the triangles are the user's), the corner normals are the faces'
//! own (no point is lifted off a face), regions follow the pieces of each triangle the
//! intersection passes through (two regions on one large triangle stay two), each crossing
//! triangle's inside part is bounded by its own trace (the polyhedral intersection's volume,
//! centroid and area vector, for any triangulation of the same solids), and the points and
//! depth follow SPEC §4's ray rule through the centroid (`engine_facet::contact_region` gives
//! the method and its degenerate branches: a region whose centroid lies outside a body, not
//! convex, has its depth held to the convex bound `3V/|S|`; a mesh wholly inside the other
//! takes the ray rule through its centroid). Degenerate contacts (faces flush or touching,
//! vertices on faces, edges on edges) are those of `a` eroded by an infinitesimal amount
//! (`engine_facet::triangle_pair::intersect_perturbed`): touching faces bound no volume and
//! join no regions, and a flush face counts as `a`'s surface inside `b`, as the box–mesh pair
//! takes a flush face of its box.

use crate::kernel::PairContact;
use contact_core::geometry::TriangleMesh;
use contact_core::{
    Contact, FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3,
    PreparedPair, WorkCounters,
};
use std::cell::RefCell;
use std::sync::Arc;

/// Two closed meshes prepared once (their OBB trees and patch sums).
#[derive(Debug, Clone)]
pub(crate) struct MeshPair(Arc<dyn PreparedPair>);

impl PartialEq for MeshPair {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl MeshPair {
    /// Both meshes as they are; `None` unless both are closed.
    pub fn new(a: &Arc<TriangleMesh>, b: &Arc<TriangleMesh>) -> Option<Self> {
        if !(a.is_closed() && b.is_closed()) {
            return None;
        }
        // A mesh is taken as given: the faceting tolerance is not read for it.
        let engine = engine_facet::FacetEngine::new(FacetingTolerance::default());
        let pair = engine
            .prepare(
                &[GeometryInstance::new(Geometry::Mesh(a.clone()))],
                &[GeometryInstance::new(Geometry::Mesh(b.clone()))],
            )
            .ok()?;
        Some(Self(Arc::from(pair)))
    }

    /// The triangles and heap bytes the two prepared meshes hold.
    pub fn held(&self) -> (usize, usize) {
        let stats = self.0.stats();
        (stats.triangles, stats.bytes)
    }

    /// Every region's contact with `a` at `pose_a` and `b` at `pose_b` (world poses of the
    /// meshes' frames).
    pub fn contacts(
        &self,
        pose_a: &Isometry3,
        pose_b: &Isometry3,
        work: &mut WorkCounters,
        emit: &mut impl FnMut(PairContact),
    ) {
        thread_local! {
            static FOUND: RefCell<Vec<Contact>> = const { RefCell::new(Vec::new()) };
        }
        FOUND.with(|cell| {
            let mut fresh = Vec::new();
            let mut borrowed = cell.try_borrow_mut();
            let found = match borrowed.as_deref_mut() {
                Ok(v) => v,
                Err(_) => &mut fresh,
            };
            // The poses were checked finite by the caller; the faceted query fails on
            // nothing else.
            if self.0.query(pose_a, pose_b, found, work).is_err() {
                found.clear();
            }
            for c in found.iter() {
                emit(PairContact {
                    point_a: c.point_i_w,
                    point_b: c.point_j_w,
                    normal: c.normal_w,
                    depth: c.penetration,
                    area: c.area,
                });
            }
        });
    }
}
