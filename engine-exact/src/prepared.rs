//! A CONTACT prepared for the exact engine: one kernel per (I geometry, J geometry) pair.

use crate::dispatch::select;
use crate::kernel::{Kernel, PairContact, PairError};
use contact_core::{
    Contact, GeometryInstance, GeometryKind, Isometry3, PrepareError, PreparedPair, PreparedStats,
    QueryError, WorkCounters, format_pose,
};

/// One (I geometry, J geometry) pair: its kernel runs on `first` and `second`, which are
/// (I, J), or (J, I) when `swap` is set.
#[derive(Debug, Clone)]
struct Entry {
    kernel: Kernel,
    swap: bool,
    geometry_i: u32,
    geometry_j: u32,
    /// `X_PG` of the kernel's first geometry (I's part frame, or J's when swapped); `None`
    /// for the identity, which saves a pose product per query.
    pose_part_first: Option<Isometry3>,
    /// `X_PG` of the kernel's second geometry, `None` for the identity.
    pose_part_second: Option<Isometry3>,
    /// The pair's length scale: the larger characteristic length of the two geometries, or 1
    /// model unit when neither has one (a point against an unbounded line).
    length: f64,
    kind_i: GeometryKind,
    kind_j: GeometryKind,
    label_i: String,
    label_j: String,
}

/// The prepared form of one CONTACT for [`crate::ExactEngine`]. Queries allocate nothing
/// beyond growing the caller's contact buffer.
#[derive(Debug, Clone)]
pub struct PreparedExact {
    entries: Vec<Entry>,
    geometries: usize,
}

impl PreparedExact {
    /// Selects a kernel for every (I, J) pair; the lists are assumed checked by
    /// [`contact_core::check_lists`].
    pub fn new(i: &[GeometryInstance], j: &[GeometryInstance]) -> Result<Self, PrepareError> {
        let mut entries = Vec::with_capacity(i.len() * j.len());
        for (index_i, gi) in i.iter().enumerate() {
            for (index_j, gj) in j.iter().enumerate() {
                let selected = select(&gi.geometry, gi.flip_normal, &gj.geometry, gj.flip_normal)?;
                let (first, second) = if selected.swap { (gj, gi) } else { (gi, gj) };
                let length = match (
                    gi.geometry.characteristic_length(),
                    gj.geometry.characteristic_length(),
                ) {
                    (Some(a), Some(b)) => a.max(b),
                    (Some(a), None) | (None, Some(a)) => a,
                    (None, None) => 1.0,
                };
                entries.push(Entry {
                    kernel: selected.kernel,
                    swap: selected.swap,
                    geometry_i: index_u32(index_i),
                    geometry_j: index_u32(index_j),
                    pose_part_first: non_identity(&first.pose_part_geometry),
                    pose_part_second: non_identity(&second.pose_part_geometry),
                    length,
                    kind_i: gi.geometry.kind(),
                    kind_j: gj.geometry.kind(),
                    label_i: gi.label.clone(),
                    label_j: gj.label.clone(),
                });
            }
        }
        Ok(Self {
            entries,
            geometries: i.len() + j.len(),
        })
    }
}

fn non_identity(pose: &Isometry3) -> Option<Isometry3> {
    (*pose != Isometry3::identity()).then_some(*pose)
}

/// SPEC §3 caps a list at 32,767 geometries, so an index always fits.
fn index_u32(index: usize) -> u32 {
    u32::try_from(index).unwrap_or(u32::MAX)
}

impl PreparedPair for PreparedExact {
    fn query(
        &self,
        pose_world_i: &Isometry3,
        pose_world_j: &Isometry3,
        contacts: &mut Vec<Contact>,
        work: &mut WorkCounters,
    ) -> Result<(), QueryError> {
        contacts.clear();
        QueryError::check_poses(pose_world_i, pose_world_j)?;
        work.queries += 1;
        let mut work_contacts = 0;
        for e in &self.entries {
            work.geometry_pairs += 1;
            let (pose_first, pose_second) = if e.swap {
                (pose_world_j, pose_world_i)
            } else {
                (pose_world_i, pose_world_j)
            };
            // `X_WG = X_WP · X_PG`, or `X_WP` itself when `X_PG` is the identity: no product
            // and no copy. The copy matters on the closed forms: a kernel reading a pose just
            // stored as a copy waits on store-to-load forwarding.
            let composed_a = e.pose_part_first.map(|p| pose_first * p);
            let composed_b = e.pose_part_second.map(|p| pose_second * p);
            let pose_a = composed_a.as_ref().unwrap_or(pose_first);
            let pose_b = composed_b.as_ref().unwrap_or(pose_second);
            // The contact is built in place, swapped by choosing its fields: a swapped copy
            // of the kernel's answer first would be read back before its stores retire.
            let swap = e.swap;
            let mut emit = |c: PairContact| {
                work_contacts += 1;
                let (point_i_w, point_j_w, normal_w) = if swap {
                    (c.point_b, c.point_a, -c.normal)
                } else {
                    (c.point_a, c.point_b, c.normal)
                };
                contacts.push(Contact {
                    point_i_w,
                    point_j_w,
                    normal_w,
                    penetration: c.depth,
                    area: c.area,
                    geometry_i: e.geometry_i,
                    geometry_j: e.geometry_j,
                });
            };
            e.kernel
                .evaluate(pose_a, pose_b, e.length, work, &mut emit)
                .map_err(|err| match err {
                    PairError::OutOfPlane { angle_rad, offset } => QueryError::OutOfPlane {
                        i: e.kind_i,
                        j: e.kind_j,
                        label_i: e.label_i.clone(),
                        label_j: e.label_j.clone(),
                        angle_rad,
                        offset,
                        pose_i: format_pose(pose_world_i),
                        pose_j: format_pose(pose_world_j),
                    },
                })?;
        }
        work.contacts += work_contacts;
        Ok(())
    }

    fn stats(&self) -> PreparedStats {
        let mut stats = PreparedStats {
            geometries: self.geometries,
            triangles: 0,
            bytes: self.entries.capacity() * std::mem::size_of::<Entry>(),
        };
        // Each entry prepares its own meshes, so each is counted.
        for (triangles, bytes) in self.entries.iter().filter_map(|e| e.kernel.held_meshes()) {
            stats.triangles += triangles;
            stats.bytes += bytes;
        }
        stats
    }
}
