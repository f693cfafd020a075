//! The shared tail of the ellipsoid pairs whose other solid is sliced into discs about its axis
//! (a cylinder, a frustum): each section's overlap with the disc in closed form, integrated
//! between the extent's ends with the shape changes as cuts, the caps' overlaps added to the
//! disc solid's surface, and the contact from the moments.

use super::disc_overlap::disc_ellipse;
use super::{
    COMPONENTS, SlicedEllipsoid, ellipsoid_exit_w, integrand, integrate, inward_of_ellipsoid,
    shape_events, to_world,
};
use crate::kernel::PairContact;
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::ray_exit::surface_point_along_w;
use contact_core::{Isometry3, Vector3, WorkCounters};
use nalgebra::Matrix2;

/// The slices of the solid, in its frame (axis `z`, caps at `0` and `length`, working units).
pub(crate) struct DiscSlices<R: Fn(f64) -> f64> {
    /// The disc's radius at height `t`.
    pub radius: R,
    /// The side's area per unit of slice arc and of height, `√(1 + r′²)`.
    pub stretch: f64,
    /// The solid's length.
    pub length: f64,
    /// The intersection's extent along the axis, within `[0, length]`.
    pub extent: (f64, f64),
}

/// Contact of the ellipsoid `a` (sliced in the solid's frame; its semi-axes and pose given too)
/// with the disc-sliced `solid` at `pose_b`; `unit` the working unit. When the area vector
/// vanishes: with the ellipsoid inside the solid, the normal is the solid's outward normal at
/// the surface point nearest the centroid; with the solid inside the ellipsoid, against the
/// ellipsoid's level-surface normal at the centroid.
#[expect(
    clippy::too_many_arguments,
    reason = "the pair's two bodies, each with its shape and pose, and the working unit"
)]
pub(crate) fn contact<R: Fn(f64) -> f64>(
    a: &SlicedEllipsoid,
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    slices: &DiscSlices<R>,
    solid: &Solid,
    pose_b: &Isometry3,
    unit: f64,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let radius = &slices.radius;
    let overlap = |t: f64| {
        let sa = a.section(t)?;
        let inverse = sa.matrix.try_inverse()?;
        let disc: Matrix2<f64> = inverse * radius(t).max(0.0);
        Some((sa, disc_ellipse(&(inverse * -sa.center), &disc)))
    };
    let mut f = |t: f64| -> [f64; COMPONENTS] {
        match overlap(t) {
            Some((sa, o)) => {
                let side: f64 = o.other_arcs.spans().iter().map(|(f0, f1)| f1 - f0).sum();
                integrand(t, &sa, &o, slices.stretch * radius(t) * side)
            }
            None => [0.0; COMPONENTS],
        }
    };
    let (lo, hi) = slices.extent;
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
    for z in [0.0, slices.length] {
        if let Some((sa, o)) = overlap(z) {
            integrals.surface_b += sa.matrix.determinant() * o.area;
        }
    }
    let inside_solid = integrals.surface_b == 0.0;
    let moments = to_world(&integrals, pose_b, unit);
    let g = moments.centroid;
    crate::methods::volume_contact::contact(
        &moments,
        |g, d| ellipsoid_exit_w(semi_axes, pose_a, g, d),
        |g, d| surface_point_along_w(solid, pose_b, g, d),
        || {
            if inside_solid {
                let p = pose_b.inverse_transform_point(&g).coords;
                pose_b.rotation * signed_distance(solid, &p).2
            } else {
                inward_of_ellipsoid(semi_axes, pose_a, &g, pose_b)
            }
        },
    )
}
