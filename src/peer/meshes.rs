//! parry's trimesh–trimesh contact manifolds on the faceted engine's meshes and poses, so `contact query --peer parry` and the benches can time the
//! library people use today beside ours. parry returns per-triangle contact points (no regions,
//! no volume-based depths): `contact query` compares its timing and point count, and the trade
//! report its deepest point ([`ParryPeer::deepest`]) as a depth and normal.

use contact_core::{Isometry3, Point3, Vector3};
use engine_facet::facet_mesh::FacetMesh;
use parry3d_f64::query::{
    ContactManifold, ContactManifoldsWorkspace, DefaultQueryDispatcher, PersistentQueryDispatcher,
};
use parry3d_f64::shape::TriMesh;
use thiserror::Error;

/// parry refused a mesh or a query.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("parry: {message}")]
pub struct ParryError {
    /// parry's message.
    pub message: String,
}

/// parry's deepest penetrating point between two meshes, in the first mesh's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParryDeepest {
    /// The point on A.
    pub point_a: Point3,
    /// The point on B.
    pub point_b: Point3,
    /// The unit normal out of A towards B.
    pub normal_a: Vector3,
    /// The penetration depth (> 0).
    pub depth: f64,
}

/// A mesh as parry's `TriMesh` (with its BVH), plus reusable manifold buffers.
pub struct ParryPeer {
    a: TriMesh,
    b: TriMesh,
    manifolds: Vec<ContactManifold<(), ()>>,
    workspace: Option<ContactManifoldsWorkspace>,
}

impl std::fmt::Debug for ParryPeer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ParryPeer")
            .field("triangles_a", &self.a.num_triangles())
            .field("triangles_b", &self.b.num_triangles())
            .finish()
    }
}

fn trimesh(m: &FacetMesh) -> Result<TriMesh, ParryError> {
    TriMesh::new(m.vertices.clone(), m.triangles.clone()).map_err(|e| ParryError {
        message: format!("{e:?}"),
    })
}

impl ParryPeer {
    /// Builds parry's meshes (and their trees) from two prepared meshes.
    pub fn new(a: &FacetMesh, b: &FacetMesh) -> Result<Self, ParryError> {
        Ok(Self {
            a: trimesh(a)?,
            b: trimesh(b)?,
            manifolds: Vec::new(),
            workspace: None,
        })
    }

    /// parry's deepest contact point over all its manifolds between A and B (B at `pose_ab` in
    /// A's frame), everything in A's frame: `None` when parry finds no penetrating point. The
    /// normal is parry's, pointing out of A towards B.
    pub fn deepest(&mut self, pose_ab: &Isometry3) -> Result<Option<ParryDeepest>, ParryError> {
        self.contact_points(pose_ab)?;
        let mut best: Option<ParryDeepest> = None;
        for m in &self.manifolds {
            let (part_a, part_b) = (
                m.subshape_pos1.unwrap_or_else(Isometry3::identity),
                m.subshape_pos2.unwrap_or_else(Isometry3::identity),
            );
            for p in &m.points {
                let depth = -p.dist;
                if depth > 0.0 && best.is_none_or(|b| depth > b.depth) {
                    best = Some(ParryDeepest {
                        point_a: part_a * p.local_p1,
                        point_b: pose_ab * (part_b * p.local_p2),
                        normal_a: part_a * m.local_n1,
                        depth,
                    });
                }
            }
        }
        Ok(best)
    }

    /// All contact points parry finds between A and B (B at `pose_ab` in A's frame) with zero
    /// prediction distance; returns the number of points over all manifolds. The workspace is
    /// reset first so every call does the full work (no temporal coherence), as ours does.
    pub fn contact_points(&mut self, pose_ab: &Isometry3) -> Result<usize, ParryError> {
        self.workspace = None;
        self.manifolds.clear();
        DefaultQueryDispatcher
            .contact_manifolds(
                pose_ab,
                &self.a,
                &self.b,
                0.0,
                &mut self.manifolds,
                &mut self.workspace,
            )
            .map_err(|e| ParryError {
                message: format!("{e:?}"),
            })?;
        Ok(self.manifolds.iter().map(|m| m.points.len()).sum())
    }
}
