//! A geometry placed on a part: what one entry of a CONTACT's IGEOM or JGEOM list means.

use crate::{Geometry, InvalidArgument, Isometry3};
use std::sync::Arc;

/// One geometry of a CONTACT's I or J list, placed on its part.
///
/// `pose_part_geometry` is `X_PG`: the geometry frame `G` measured in the part frame `P`
/// (Drake's monogram notation, see the crate docs). `flip_normal` is IFLIP_NORMAL/JFLIP_NORMAL
/// for a single geometry, or membership in IFLIP_GEOMETRY/JFLIP_GEOMETRY for a list: it reverses
/// the outward normal of a 2-D curve, arc or circle (the material side) and of a 3-D solid (the
/// solid then means the space outside it, as a ball inside a spherical cup).
#[derive(Debug, Clone, PartialEq)]
pub struct GeometryInstance {
    /// The shape (shared: one GRAPHICS may serve several contacts).
    pub geometry: Arc<Geometry>,
    /// `X_PG`, the geometry frame in the part frame.
    pub pose_part_geometry: Isometry3,
    /// Reverse the outward normal.
    pub flip_normal: bool,
    /// The faceting tolerance for this geometry (Adams `GRAPHICS/…, FACETING_TOLERANCE`), or
    /// `None` to use the engine's.
    pub faceting_tolerance: Option<crate::FacetingTolerance>,
    /// A label for messages (the Adams GRAPHICS id, or any name).
    pub label: String,
}

impl GeometryInstance {
    /// A geometry at the part frame's origin, not flipped, with the engine's tolerance.
    pub fn new(geometry: Geometry) -> Self {
        Self {
            geometry: Arc::new(geometry),
            pose_part_geometry: Isometry3::identity(),
            flip_normal: false,
            faceting_tolerance: None,
            label: String::new(),
        }
    }

    /// Places the geometry at `pose_part_geometry` (`X_PG`).
    #[must_use]
    pub fn at(mut self, pose_part_geometry: Isometry3) -> Self {
        self.pose_part_geometry = pose_part_geometry;
        self
    }

    /// Sets the label used in messages.
    #[must_use]
    pub fn labeled(mut self, label: impl Into<String>) -> Self {
        self.label = label.into();
        self
    }

    /// Reverses the outward normal.
    #[must_use]
    pub fn flipped(mut self) -> Self {
        self.flip_normal = !self.flip_normal;
        self
    }

    /// Sets this geometry's own faceting tolerance.
    pub fn with_faceting_tolerance(mut self, tolerance: f64) -> Result<Self, InvalidArgument> {
        self.faceting_tolerance = Some(crate::FacetingTolerance::new(tolerance)?);
        Ok(self)
    }
}
