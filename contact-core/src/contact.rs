//! What an engine returns: one [`Contact`] per intersection region (SPEC §4).

use crate::{Point3, Vector3};

/// The kinematics of one contact region between a geometry of the I list and one of the J list,
/// all in the world frame `W`.
///
/// - `normal_w` is a unit vector pointing from J into I: the direction the normal force pushes I.
/// - `penetration` δ ≥ 0 is the distance between the two surfaces' points nearest the centroid
///   of the intersection volume (area in 2-D) along the normal — where the line through the
///   centroid along `normal_w` leaves each body; for a sphere on a plane it is `r − d`.
/// - `point_i_w` lies on I's surface, `point_j_w` on J's; `point_i_w − point_j_w ≈ −δ·normal_w`
///   (I's surface point is the deepest into J).
/// - `area` estimates the contact patch (for the friction torque radius `R = sqrt(A/π)`); for a
///   2-D contact it is the length of the contact segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Point on I's surface, in `W`.
    pub point_i_w: Point3,
    /// Point on J's surface, in `W`.
    pub point_j_w: Point3,
    /// Unit normal from J into I, in `W`.
    pub normal_w: Vector3,
    /// Penetration depth δ ≥ 0.
    pub penetration: f64,
    /// Contact area estimate ≥ 0 (length in 2-D).
    pub area: f64,
    /// Index of the geometry in the I list.
    pub geometry_i: u32,
    /// Index of the geometry in the J list.
    pub geometry_j: u32,
}

impl Contact {
    /// The same contact seen with I and J exchanged: points and indices swap, the normal flips.
    #[must_use]
    pub fn swapped(&self) -> Self {
        Self {
            point_i_w: self.point_j_w,
            point_j_w: self.point_i_w,
            normal_w: -self.normal_w,
            penetration: self.penetration,
            area: self.area,
            geometry_i: self.geometry_j,
            geometry_j: self.geometry_i,
        }
    }

    /// The force application point: midway between the two surface points.
    pub fn midpoint_w(&self) -> Point3 {
        nalgebra::center(&self.point_i_w, &self.point_j_w)
    }

    /// True when every number is finite and the normal is unit to 1e-9.
    pub fn is_well_formed(&self) -> bool {
        self.point_i_w
            .iter()
            .chain(self.point_j_w.iter())
            .all(|c| c.is_finite())
            && self.penetration.is_finite()
            && self.penetration >= 0.0
            && self.area.is_finite()
            && self.area >= 0.0
            && (self.normal_w.norm() - 1.0).abs() < 1e-9
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn swapping_twice_is_the_identity_and_flips_the_normal_once() {
        let c = Contact {
            point_i_w: Point3::new(0.0, 0.0, -0.1),
            point_j_w: Point3::new(0.0, 0.0, 0.0),
            normal_w: Vector3::z(),
            penetration: 0.1,
            area: 0.5,
            geometry_i: 2,
            geometry_j: 7,
        };
        let s = c.swapped();
        assert_eq!(s.normal_w, -Vector3::z());
        assert_eq!((s.geometry_i, s.geometry_j), (7, 2));
        assert_eq!(s.point_i_w, c.point_j_w);
        assert_eq!(s.swapped(), c);
        assert!(c.is_well_formed());
        assert_eq!(c.midpoint_w(), Point3::new(0.0, 0.0, -0.05));
    }
}
