//! Where each marker is: the marker table the lowered model and its expressions share.
//!
//! The solver's parts live at their centre of mass (CM) frames, the dataset's markers and
//! geometry on part frames; [`MarkerTable`] holds every marker as `(solver part, X_CM,M)`.

use contact_core::{Isometry3, Vector3};
use contact_solver::mbs::{PartId, PartState};
use std::collections::BTreeMap;

/// A marker on a solver part: the part and the marker's pose in the part's CM frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlacedMarker {
    /// The solver part (ground included).
    pub part: PartId,
    /// `X_CM,M`.
    pub pose_cm_marker: Isometry3,
}

/// Every marker of the model, by Adams id.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MarkerTable {
    /// Markers by id.
    pub markers: BTreeMap<u32, PlacedMarker>,
}

impl MarkerTable {
    /// The world pose of marker `id` given every part's state (`None` for an unknown id).
    pub fn pose_w(&self, id: u32, parts: &[PartState]) -> Option<Isometry3> {
        let m = self.markers.get(&id)?;
        Some(parts.get(m.part.0)?.pose_w * m.pose_cm_marker)
    }

    /// The world velocity of marker `id`'s origin and its part's angular velocity.
    pub fn velocity_w(&self, id: u32, parts: &[PartState]) -> Option<(Vector3, Vector3)> {
        let m = self.markers.get(&id)?;
        let s = parts.get(m.part.0)?;
        let p = (s.pose_w * m.pose_cm_marker).translation.vector;
        Some((s.point_velocity_w(&p), s.angular_velocity_w))
    }
}
