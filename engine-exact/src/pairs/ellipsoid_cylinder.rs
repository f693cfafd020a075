//! Ellipsoid against cylinder, by slicing along the cylinder's axis.
//!
//! Slicing frame: the cylinder's frame (axis `z`, from `0` to its length). Every slice of the
//! cylinder is the same disc, overlapped with the ellipsoid's section in closed form
//! (`super::ellipsoid_sliced::disc_overlap`: an ellipse against a circle, the crossings a
//! quartic's roots). The slices are integrated between the lowest and highest `z` of the
//! ellipsoid's intersection with the infinite cylinder (duality over the pencil of the two
//! quadrics, `super::ellipsoid_sliced::extent`, which also proves them apart), clipped to
//! the caps. Where the sections become tangent inside that range the quadrature halves its
//! pieces down to the kink. The caps add their overlap with the ellipsoid's section to the
//! unsigned surface; the side's part inside the ellipsoid is `r·Δφ` per slice.
//!
//! The contact follows [`super::volume_contact`]. When the area vector vanishes: with the
//! ellipsoid inside the cylinder, the normal is the cylinder's outward normal at the surface
//! point nearest the centroid; with the cylinder inside the ellipsoid, against the
//! ellipsoid's level-surface normal at the centroid.

use super::clipped::unit_for;
use super::ellipsoid_sliced::disc_overlap::disc_ellipse;
use super::ellipsoid_sliced::extent::{Quadric, z_extent};
use super::ellipsoid_sliced::{
    COMPONENTS, SlicedEllipsoid, ellipsoid_exit_w, ellipsoid_in, integrand, integrate,
    inward_of_ellipsoid, shape_events, to_world,
};
use super::solid_distance::{Solid, signed_distance};
use crate::kernel::PairContact;
use crate::ray_exit::surface_point_along_w;
use contact_core::geometry::Cylinder;
use contact_core::{Isometry3, Vector3, WorkCounters};
use nalgebra::{Matrix2, Matrix3};

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
    let overlap = |t: f64| {
        let sa = a.section(t)?;
        let inverse = sa.matrix.try_inverse()?;
        let disc: Matrix2<f64> = inverse * radius;
        Some((sa, disc_ellipse(&(inverse * -sa.center), &disc)))
    };
    let mut f = |t: f64| -> [f64; COMPONENTS] {
        match overlap(t) {
            Some((sa, o)) => {
                let side: f64 = o.other_arcs.spans().iter().map(|(f0, f1)| f1 - f0).sum();
                integrand(t, &sa, &o, radius * side)
            }
            None => [0.0; COMPONENTS],
        }
    };
    let mut cuts = [0.0; 24];
    cuts[..2].copy_from_slice(&[lo, hi]);
    let mut n = 2;
    shape_events(
        lo,
        hi,
        |t| overlap(t).map_or(0, |(_, o)| o.shape),
        &mut cuts,
        &mut n,
    );
    let mut integrals = integrate(&mut cuts[..n], &mut f, work);
    for z in [0.0, length] {
        if let Some((sa, o)) = overlap(z) {
            integrals.surface_b += sa.matrix.determinant() * o.area;
        }
    }
    let inside_cylinder = integrals.surface_b == 0.0;
    let moments = to_world(&integrals, pose_b, unit);
    let g = moments.centroid;
    super::volume_contact::contact(
        &moments,
        |g, d| ellipsoid_exit_w(semi_axes, pose_a, g, d),
        |g, d| surface_point_along_w(&Solid::Cylinder(*cylinder), pose_b, g, d),
        || {
            if inside_cylinder {
                let p = pose_b.inverse_transform_point(&g).coords;
                pose_b.rotation * signed_distance(&Solid::Cylinder(*cylinder), &p).2
            } else {
                inward_of_ellipsoid(semi_axes, pose_a, &g, pose_b)
            }
        },
    )
}
