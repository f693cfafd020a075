//! parry as one peer of the trade: its `contact` query on primitive pairs
//! ([`super::primitives`]) and its trimesh–trimesh contact manifolds on mesh pairs
//! ([`super::meshes`]), behind one [`GeometryEngine`] named `parry`, so the report puts parry's time and
//! errors beside ours on the same meshes and poses.
//!
//! On a mesh pair parry returns contact points per triangle pair, not per intersection region:
//! the peer reports one contact per geometry pair, parry's deepest point (its depth, its
//! normal, its two points) and no area. Its depth and normal errors against the reference are
//! therefore those of a deepest-point answer, and are reported as they are.

use super::{ParryEngine, ParryError, ParryPeer};
use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, PrepareError, PreparedPair,
    PreparedStats, QueryError, Side, Unsupported, WorkCounters,
};
use engine_facet::{FacetEngine, Shape};
use std::sync::Mutex;

/// parry on primitives and on mesh pairs.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ParryPeerEngine;

const PARRY: &str = "parry";

fn is_mesh(g: &Geometry) -> bool {
    matches!(g, Geometry::Mesh(_))
}

impl GeometryEngine for ParryPeerEngine {
    fn name(&self) -> &'static str {
        PARRY
    }

    fn supports(&self, i: &Geometry, j: &Geometry) -> Result<(), Unsupported> {
        if is_mesh(i) && is_mesh(j) {
            Ok(())
        } else {
            ParryEngine.supports(i, j)
        }
    }

    fn prepare(
        &self,
        i: &[GeometryInstance],
        j: &[GeometryInstance],
    ) -> Result<Box<dyn PreparedPair>, PrepareError> {
        let all_meshes = |l: &[GeometryInstance]| l.iter().all(|g| is_mesh(&g.geometry));
        if !(all_meshes(i) && all_meshes(j)) {
            return ParryEngine.prepare(i, j);
        }
        contact_core::check_lists(self, i, j)?;
        // parry gets our meshes as they are (a mesh keeps its facets at any tolerance).
        let facet = FacetEngine::new(contact_core::FacetingTolerance::DEFAULT);
        let mesh = |g: &GeometryInstance, side| -> Result<_, PrepareError> {
            match facet.prepare_geometry(g, side)?.shape {
                Shape::Mesh(m) => Ok(m),
                Shape::HalfSpace(_) | Shape::Planar(_) => unreachable!("only meshes reach here"),
            }
        };
        let mut pairs = Vec::new();
        let mut triangles = 0;
        for (gi, a) in i.iter().enumerate() {
            let ma = mesh(a, Side::I)?;
            for (gj, b) in j.iter().enumerate() {
                let mb = mesh(b, Side::J)?;
                triangles += ma.triangles.len() + mb.triangles.len();
                let refused = |e: ParryError| PrepareError::InvalidArgument {
                    label: b.label.clone(),
                    source: contact_core::InvalidArgument::with_text(
                        "mesh",
                        "refused by parry",
                        e.to_string(),
                    ),
                };
                let mut peer = ParryPeer::new(&ma, &mb).map_err(refused)?;
                // parry's only query error is an unsupported shape pair, which depends on the
                // shape types alone: one probe here proves every later query is answered.
                peer.deepest(&Isometry3::identity()).map_err(refused)?;
                pairs.push(MeshPair {
                    geometry_i: gi as u32,
                    geometry_j: gj as u32,
                    pose_i: a.pose_part_geometry,
                    pose_j: b.pose_part_geometry,
                    peer: Mutex::new(peer),
                });
            }
        }
        Ok(Box::new(PreparedParryMeshes { pairs, triangles }))
    }
}

/// One I mesh against one J mesh in parry's hands.
#[derive(Debug)]
struct MeshPair {
    geometry_i: u32,
    geometry_j: u32,
    pose_i: Isometry3,
    pose_j: Isometry3,
    /// parry's query needs its manifold buffers mutably; the lock is uncontended (the trade
    /// measures one thread) and costs tens of nanoseconds against parry's microseconds.
    peer: Mutex<ParryPeer>,
}

#[derive(Debug)]
struct PreparedParryMeshes {
    pairs: Vec<MeshPair>,
    triangles: usize,
}

impl PreparedPair for PreparedParryMeshes {
    fn query(
        &self,
        pose_world_i: &Isometry3,
        pose_world_j: &Isometry3,
        contacts: &mut Vec<Contact>,
        work: &mut WorkCounters,
    ) -> Result<(), QueryError> {
        QueryError::check_poses(pose_world_i, pose_world_j)?;
        contacts.clear();
        work.queries += 1;
        for pair in &self.pairs {
            work.geometry_pairs += 1;
            let (world_a, world_b) = (pose_world_i * pair.pose_i, pose_world_j * pair.pose_j);
            let pose_ab = world_a.inverse() * world_b;
            let deepest = match pair.peer.lock() {
                Ok(mut peer) => peer.deepest(&pose_ab),
                Err(poisoned) => poisoned.into_inner().deepest(&pose_ab),
            };
            // Never an error after the probe in `prepare` (see there).
            let Some(d) = deepest.ok().flatten() else {
                continue;
            };
            contacts.push(Contact {
                point_i_w: world_a * d.point_a,
                point_j_w: world_a * d.point_b,
                normal_w: -(world_a * d.normal_a),
                penetration: d.depth,
                area: 0.0,
                geometry_i: pair.geometry_i,
                geometry_j: pair.geometry_j,
            });
            work.contacts += 1;
        }
        Ok(())
    }

    fn stats(&self) -> PreparedStats {
        PreparedStats {
            geometries: 2 * self.pairs.len(),
            triangles: self.triangles,
            bytes: self.pairs.capacity() * std::mem::size_of::<MeshPair>(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::Vector3;
    use contact_core::geometry::{Ellipsoid, TriangleMesh};
    use std::sync::Arc;

    fn mesh_sphere(r: f64) -> GeometryInstance {
        let t = engine_facet::tessellate::ellipsoid(&Ellipsoid::sphere(r).unwrap(), 1e-3 * r);
        let mesh = TriangleMesh::new(t.vertices, t.triangles).unwrap();
        GeometryInstance::new(Geometry::Mesh(Arc::new(mesh)))
    }

    #[test]
    fn parry_meshes_answer_two_overlapping_spheres_with_their_deepest_point() {
        let pair = ParryPeerEngine
            .prepare(&[mesh_sphere(1.0)], &[mesh_sphere(0.7)])
            .unwrap();
        // I above J along a tilted axis, overlapping by 0.1 (the true spheres').
        let axis = Vector3::new(0.3, -0.2, 1.0).normalize();
        let i = Isometry3::from_parts((axis * 1.6).into(), Default::default());
        let mut out = Vec::new();
        pair.query(
            &i,
            &Isometry3::identity(),
            &mut out,
            &mut WorkCounters::default(),
        )
        .unwrap();
        assert_eq!(out.len(), 1, "{out:?}");
        let c = out[0];
        // parry's deepest point is that of one triangle pair seen as two thin shells, not the
        // region's: its depth is positive and at most the spheres' overlap, its points lie on
        // the two surfaces, and they are δ apart along the normal (J into I).
        assert!(c.penetration > 0.0 && c.penetration <= 0.1 + 1e-9, "{c:?}");
        let centre_i = axis * 1.6;
        assert!(
            ((c.point_i_w.coords - centre_i).norm() - 1.0).abs() < 2e-3,
            "{c:?}"
        );
        assert!((c.point_j_w.coords.norm() - 0.7).abs() < 2e-3, "{c:?}");
        let gap = c.point_j_w - c.point_i_w;
        assert!((gap - c.normal_w * c.penetration).norm() < 1e-9, "{c:?}");
        // Separated: nothing.
        let apart = Isometry3::from_parts((axis * 1.8).into(), Default::default());
        pair.query(
            &apart,
            &Isometry3::identity(),
            &mut out,
            &mut WorkCounters::default(),
        )
        .unwrap();
        assert!(out.is_empty(), "{out:?}");
    }
}
