//! A prepared CONTACT: the I and J lists' meshes and half-spaces, queried at poses.

use crate::contact_region::{LocalContact, mesh_mesh};
use crate::facet_mesh::FacetMesh;
use crate::planar::{self, Planar, PlanarContact};
use crate::plane_contact::{mesh_plane, plane_pose_in_mesh_frame};
use crate::scratch::{Scratch, with_scratch};
use crate::solid_on_face::implied_solid_on_face;
use contact_core::geometry::Plane;
use contact_core::{
    Contact, Isometry3, Point3, PreparedPair, PreparedStats, QueryError, WorkCounters, format_pose,
};
use std::sync::Arc;

/// What one geometry became.
#[derive(Debug, Clone)]
pub enum Shape {
    /// A closed (or accepted open) triangle mesh with its tree.
    Mesh(Arc<FacetMesh>),
    /// A half-space, kept exact.
    HalfSpace(Plane),
    /// A 2-D geometry (points and lines exact, the rest as polylines).
    Planar(Arc<Planar>),
}

/// One prepared entry of an I or J list.
#[derive(Debug, Clone)]
pub struct PreparedGeometry {
    /// The mesh or half-space, in the geometry frame `G`.
    pub shape: Shape,
    /// `X_PG`.
    pub pose_part_geometry: Isometry3,
    /// The label for messages.
    pub label: String,
}

/// The faceted engine's [`PreparedPair`].
#[derive(Debug, Clone)]
pub struct PreparedFacetPair {
    i: Vec<PreparedGeometry>,
    j: Vec<PreparedGeometry>,
    memo: PlaneMemo,
}

/// A mesh–plane entry's last contacts in the mesh's frame, with the entry and the plane's
/// pose in that frame they were found at. An unbounded plane's pose is taken slid to the foot
/// of the mesh ([`plane_pose_in_mesh_frame`]), so a mesh moved along the plane meets it at the
/// same pose to the bit — as a differenced Jacobian's tangent columns move it — and its
/// contacts are the last ones, moved with the mesh. A clone starts empty.
#[derive(Debug, Default)]
struct PlaneMemo(std::sync::Mutex<Option<(PlaneKey, Vec<LocalContact>)>>);

/// The entry (`I` index, `J` index) and the plane's pose in the mesh's frame, as bits.
type PlaneKey = ([usize; 2], [u64; 7]);

impl Clone for PlaneMemo {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl PlaneMemo {
    fn key(entry: [usize; 2], pose: &Isometry3) -> PlaneKey {
        let (t, q) = (pose.translation.vector, pose.rotation.quaternion().coords);
        (entry, [t.x, t.y, t.z, q.x, q.y, q.z, q.w].map(f64::to_bits))
    }

    /// The contacts at `key` into `local`: the remembered ones when the key is the last
    /// one, else `compute`'s, remembered.
    fn answer(
        &self,
        key: PlaneKey,
        local: &mut Vec<LocalContact>,
        compute: impl FnOnce(&mut Vec<LocalContact>),
    ) {
        if let Ok(last) = self.0.lock()
            && let Some((k, found)) = last.as_ref()
            && *k == key
        {
            local.extend_from_slice(found);
            return;
        }
        compute(local);
        if let Ok(mut last) = self.0.lock() {
            *last = Some((key, local.clone()));
        }
    }
}

impl PreparedFacetPair {
    /// Wraps prepared lists (see [`crate::FacetEngine`]).
    pub fn new(i: Vec<PreparedGeometry>, j: Vec<PreparedGeometry>) -> Self {
        Self {
            i,
            j,
            memo: PlaneMemo::default(),
        }
    }

    /// The prepared I list.
    pub fn i_list(&self) -> &[PreparedGeometry] {
        &self.i
    }

    /// The prepared J list.
    pub fn j_list(&self) -> &[PreparedGeometry] {
        &self.j
    }
}

fn to_world(pose: &Isometry3, c: &LocalContact, gi: usize, gj: usize) -> Contact {
    Contact {
        point_i_w: pose * Point3::from(c.point_i),
        point_j_w: pose * Point3::from(c.point_j),
        normal_w: pose.rotation * c.normal,
        penetration: c.penetration,
        area: c.area,
        geometry_i: gi as u32,
        geometry_j: gj as u32,
    }
}

/// One prepared geometry at its world pose, with its index in its list.
struct Placed<'a> {
    geometry: &'a PreparedGeometry,
    index: usize,
    pose_w: &'a Isometry3,
}

/// The contacts of I's geometry `a` against J's geometry `b` (`placed`), appended to
/// `contacts` in world frame; `parts` are the two parts' world poses (for messages). A 2-D
/// pair whose parts left their plane is an error.
fn pair_contacts(
    [a, b]: [Placed<'_>; 2],
    parts: [&Isometry3; 2],
    memo: &PlaneMemo,
    s: &mut Scratch,
    work: &mut WorkCounters,
    local: &mut Vec<LocalContact>,
    contacts: &mut Vec<Contact>,
) -> Result<(), QueryError> {
    let (gi, gj) = (a.index, b.index);
    let (pose_wa, pose_wb) = (a.pose_w, b.pose_w);
    match (&a.geometry.shape, &b.geometry.shape) {
        (Shape::Mesh(ma), Shape::Mesh(mb)) => {
            let pose_ab = pose_wa.inv_mul(pose_wb);
            if implied_solid_on_face(mb, ma, &pose_ab.inverse(), s, work, local) {
                contacts.extend(local.iter().map(|c| to_world(pose_wb, c, gj, gi).swapped()));
            } else {
                if !implied_solid_on_face(ma, mb, &pose_ab, s, work, local) {
                    mesh_mesh(ma, mb, &pose_ab, s, work, local);
                }
                contacts.extend(local.iter().map(|c| to_world(pose_wa, c, gi, gj)));
            }
        }
        (Shape::Mesh(ma), Shape::HalfSpace(p)) => {
            let pose_ab = plane_pose_in_mesh_frame(pose_wa, pose_wb, p);
            let key = PlaneMemo::key([gi, gj], &pose_ab);
            memo.answer(key, local, |local| {
                mesh_plane(ma, p, &pose_ab, s, work, local);
            });
            contacts.extend(local.iter().map(|c| to_world(pose_wa, c, gi, gj)));
        }
        (Shape::HalfSpace(p), Shape::Mesh(mb)) => {
            let pose_ba = plane_pose_in_mesh_frame(pose_wb, pose_wa, p);
            let key = PlaneMemo::key([gi, gj], &pose_ba);
            memo.answer(key, local, |local| {
                mesh_plane(mb, p, &pose_ba, s, work, local);
            });
            contacts.extend(local.iter().map(|c| to_world(pose_wb, c, gj, gi).swapped()));
        }
        (Shape::Planar(pa), Shape::Planar(pb)) => {
            let length = match (pa.length, pb.length) {
                (Some(x), Some(y)) => x.max(y),
                (x, y) => x.or(y).unwrap_or(1.0),
            };
            planar::contacts(
                &pa.shape,
                pose_wa,
                &pb.shape,
                pose_wb,
                length,
                work,
                &mut |c| contacts.push(planar_to_contact(&c, gi, gj)),
            )
            .map_err(|e| QueryError::OutOfPlane {
                i: pa.kind,
                j: pb.kind,
                label_i: a.geometry.label.clone(),
                label_j: b.geometry.label.clone(),
                angle_rad: e.angle_rad,
                offset: e.offset,
                pose_i: format_pose(parts[0]),
                pose_j: format_pose(parts[1]),
            })?;
        }
        // `supports` rejects PLANE against PLANE and 2-D against 3-D before prepare builds
        // anything.
        (Shape::HalfSpace(_), Shape::HalfSpace(_))
        | (Shape::Planar(_), Shape::Mesh(_) | Shape::HalfSpace(_))
        | (Shape::Mesh(_) | Shape::HalfSpace(_), Shape::Planar(_)) => {}
    }
    Ok(())
}

fn planar_to_contact(c: &PlanarContact, gi: usize, gj: usize) -> Contact {
    Contact {
        point_i_w: c.point_i,
        point_j_w: c.point_j,
        normal_w: c.normal,
        penetration: c.depth,
        area: c.length,
        geometry_i: gi as u32,
        geometry_j: gj as u32,
    }
}

impl PreparedPair for PreparedFacetPair {
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
        let result = with_scratch(|s| {
            let mut local = std::mem::take(&mut s.local);
            let mut result = Ok(());
            'pairs: for (gi, a) in self.i.iter().enumerate() {
                let pose_wa = pose_world_i * a.pose_part_geometry;
                for (gj, b) in self.j.iter().enumerate() {
                    work.geometry_pairs += 1;
                    let pose_wb = pose_world_j * b.pose_part_geometry;
                    local.clear();
                    let placed = [
                        Placed {
                            geometry: a,
                            index: gi,
                            pose_w: &pose_wa,
                        },
                        Placed {
                            geometry: b,
                            index: gj,
                            pose_w: &pose_wb,
                        },
                    ];
                    let parts = [pose_world_i, pose_world_j];
                    result =
                        pair_contacts(placed, parts, &self.memo, s, work, &mut local, contacts);
                    if result.is_err() {
                        break 'pairs;
                    }
                }
            }
            s.local = local;
            result
        });
        result?;
        work.contacts += contacts.len() as u64;
        Ok(())
    }

    fn stats(&self) -> PreparedStats {
        let mut stats = PreparedStats::default();
        for g in self.i.iter().chain(&self.j) {
            stats.geometries += 1;
            match &g.shape {
                Shape::Mesh(m) => {
                    stats.triangles += m.triangles.len();
                    stats.bytes += m.heap_bytes();
                }
                Shape::Planar(p) => {
                    if let planar::PlanarShape::Disc { polygon: b, .. }
                    | planar::PlanarShape::Boundary(b) = &p.shape
                    {
                        stats.bytes += b.heap_bytes();
                    }
                }
                Shape::HalfSpace(_) => {}
            }
        }
        stats
    }
}
