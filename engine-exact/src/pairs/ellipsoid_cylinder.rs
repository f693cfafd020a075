//! Ellipsoid against cylinder, by slicing along the cylinder's axis.
//!
//! Slicing frame: the cylinder's frame (axis `z`, from `0` to its length). Every slice of the
//! cylinder is the same disc, overlapped with the ellipsoid's section in closed form
//! (`crate::methods::ellipsoid_sliced::disc_overlap`: an ellipse against a circle, the crossings a
//! quartic's roots). The slices are integrated between the lowest and highest `z` of the
//! ellipsoid's intersection with the infinite cylinder (duality over the pencil of the two
//! quadrics, `crate::methods::ellipsoid_sliced::extent`, which also proves them apart), clipped to
//! the caps. Where the sections become tangent inside that range the quadrature halves its
//! pieces down to the kink. The caps add their overlap with the ellipsoid's section to the
//! unsigned surface; the side's part inside the ellipsoid is `r·Δφ` per slice.
//!
//! The contact follows [`crate::methods::volume_contact`]. When the area vector vanishes: with the
//! ellipsoid inside the cylinder, the normal is the cylinder's outward normal at the surface
//! point nearest the centroid; with the cylinder inside the ellipsoid, against the
//! ellipsoid's level-surface normal at the centroid.

use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::ellipsoid_sliced::disc_solid::{self, DiscSlices};
use crate::methods::ellipsoid_sliced::extent::{Quadric, z_extent};
use crate::methods::ellipsoid_sliced::{SlicedEllipsoid, ellipsoid_in};
use crate::methods::solid_distance::Solid;
use contact_core::geometry::Cylinder;
use contact_core::{Isometry3, Vector3, WorkCounters};
use nalgebra::Matrix3;

/// Contact of the ellipsoid with `semi_axes` at `pose_a` with `cylinder` at `pose_b`.
pub(crate) fn contact(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    cylinder: &Cylinder,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let unit = unit_for(
        semi_axes
            .max()
            .max(cylinder.radius())
            .max(cylinder.length()),
    );
    let (c, l) = ellipsoid_in(pose_b, pose_a, semi_axes, unit);
    let radius = cylinder.radius() / unit;
    let length = cylinder.length() / unit;
    work.bounding_volume_tests += 1;
    let reach_z = l.row(2).norm();
    let reach_xy = (l.row(0).norm_squared() + l.row(1).norm_squared()).sqrt();
    if c.z - reach_z >= length || c.z + reach_z <= 0.0 || c.xy().norm() >= radius + reach_xy {
        return None;
    }
    let a = SlicedEllipsoid::new(c, &l)?;
    let ellipsoid = Quadric {
        center: c,
        q: a.inverse().transpose() * a.inverse(),
    };
    let tube = Quadric {
        center: Vector3::zeros(),
        q: Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.0)) / (radius * radius),
    };
    let (lo, hi) = z_extent(&ellipsoid, &tube)?;
    let (lo, hi) = (lo.max(0.0), hi.min(length));
    if lo >= hi {
        return None;
    }
    let slices = DiscSlices {
        radius: |_| radius,
        stretch: 1.0,
        length,
        extent: (lo, hi),
    };
    disc_solid::contact(
        &a,
        semi_axes,
        pose_a,
        &slices,
        &Solid::Cylinder(*cylinder),
        pose_b,
        unit,
        work,
    )
}
