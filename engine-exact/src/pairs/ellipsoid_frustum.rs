//! Ellipsoid against frustum (or cone), by slicing across the frustum's axis.
//!
//! Slicing frame: the frustum's frame (axis `z`, bottom cap at `0`, top cap at its length
//! `L`). The slice `z = t` cuts the frustum in the disc of radius `r(t) = r₀ + k t`,
//! `k = (r₁ − r₀)/L`, overlapped with the ellipsoid's elliptic section in closed form
//! (`crate::methods::ellipsoid_sliced::disc_overlap`: an ellipse against a circle, the crossings a
//! quartic's roots), as in [`super::ellipsoid_cylinder`] with a radius that changes with `t`.
//!
//! ## The extent
//! The slices are integrated between the lowest and highest `t` of the intersection. With
//! `g(t)` the distance from the axis to the ellipsoid's section at `t`
//! (`crate::methods::ellipsoid_sliced::distance`), the section meets the frustum's disc iff
//! `f(t) = g(t) − r(t) < 0`. `g` is convex on the ellipsoid's range (the distance to a convex
//! set, minimised over the slice: a partial minimum of a jointly convex function) and `r` is
//! linear, so `f` is convex: its minimum over the ellipsoid's range clipped to `[0, L]`
//! (golden section) is non-negative when the solids are apart or only touch, and otherwise the
//! ends are the zeros of `f` on either side of it, bisected to round-off (or the range's ends
//! where `f` is already negative there). Where the sections become tangent inside the range
//! the overlap has a kink: [`crate::methods::ellipsoid_sliced::shape_events`] finds it by the change of the crossings' count.
//!
//! ## The integrals
//! Volume, centroid and the area vector of the ellipsoid's surface inside the frustum as in
//! [`crate::methods::ellipsoid_sliced`]. The unsigned area of the frustum's surface inside the
//! ellipsoid: the lateral surface's `√(1 + k²)·r(t)·Δφ` per slice (`Δφ` the circle's angle
//! inside the ellipsoid's section: the side's element is `√(1 + k²)·r dφ dt`), plus each cap's
//! overlap with the ellipsoid's section at its height. A cone's apex (`r = 0` at a cap) is a
//! disc of no radius: an empty overlap, a smooth end of the integrand.
//!
//! ## The contact
//! By [`crate::methods::volume_contact`]. When the area vector vanishes: with the ellipsoid inside the
//! frustum (none of the frustum's surface inside the ellipsoid), the normal is the frustum's
//! outward normal at the surface point nearest the centroid; with the frustum inside the
//! ellipsoid, against the ellipsoid's level-surface normal at the centroid; the area a quarter
//! of the intersection's surface. Touching (the minimum of `f` not below zero) is no contact.

use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::ellipsoid_sliced::disc_solid::{self, DiscSlices};
use crate::methods::ellipsoid_sliced::distance::ellipse_distance;
use crate::methods::ellipsoid_sliced::{SlicedEllipsoid, ellipsoid_in};
use crate::methods::sliced::golden_maximum;
use crate::methods::solid_distance::Solid;
use contact_core::geometry::Frustum;
use contact_core::{Isometry3, Vector2, Vector3, WorkCounters};

/// Bisection steps for each end of the extent (a `t` range of about 1 halved to round-off).
const BISECTIONS: usize = 64;

/// The `t` range `(lo, hi)` where the ellipsoid `a`'s section meets the disc of radius
/// `radius(t)` about the axis, inside `[from, to]`; `None` when they are apart or only touch.
/// `radius` must be linear (or concave) in `t`, so that `dist(axis, section) − radius` is
/// convex (see the module doc).
pub(crate) fn disc_extent(
    a: &SlicedEllipsoid,
    radius: impl Fn(f64) -> f64,
    from: f64,
    to: f64,
) -> Option<(f64, f64)> {
    let (e_lo, e_hi) = a.range();
    let (from, to) = (from.max(e_lo), to.min(e_hi));
    if from.is_nan() || to.is_nan() || from >= to {
        return None;
    }
    let f = |t: f64| {
        let t = t.clamp(from, to);
        let gap = match a.section(t) {
            Some(s) => ellipse_distance(&Vector2::zeros(), &s.center, &s.matrix),
            None => a.center_at(t).norm(),
        };
        gap - radius(t)
    };
    let deepest = golden_maximum(from, to, |t| -f(t));
    let ends = [from, to];
    let (best, value) = std::iter::once(deepest)
        .chain(ends)
        .map(|t| (t, f(t)))
        .fold((deepest, f64::INFINITY), |acc, (t, v)| {
            if v < acc.1 { (t, v) } else { acc }
        });
    if value.is_nan() || value >= 0.0 {
        return None;
    }
    // From the deepest slice to each end: the last slice where the section still meets.
    let bisect = |mut inside: f64, mut outside: f64| {
        if f(outside) < 0.0 {
            return outside;
        }
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (inside + outside);
            if mid == inside || mid == outside {
                break;
            }
            if f(mid) < 0.0 {
                inside = mid;
            } else {
                outside = mid;
            }
        }
        0.5 * (inside + outside)
    };
    let (lo, hi) = (bisect(best, from), bisect(best, to));
    (lo < hi).then_some((lo, hi))
}

/// Contact of the ellipsoid with `semi_axes` at `pose_a` with `frustum` at `pose_b`.
pub(crate) fn contact(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    frustum: &Frustum,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let unit = unit_for(
        semi_axes
            .max()
            .max(frustum.bottom_radius())
            .max(frustum.top_radius())
            .max(frustum.length()),
    );
    let (c, l) = ellipsoid_in(pose_b, pose_a, semi_axes, unit);
    let (r0, r1) = (frustum.bottom_radius() / unit, frustum.top_radius() / unit);
    let length = frustum.length() / unit;
    let slope = (r1 - r0) / length;
    // r(t) from the nearer cap, so both ends are exact.
    let radius = |t: f64| {
        if t <= 0.5 * length {
            r0 + slope * t
        } else {
            r1 - slope * (length - t)
        }
    };
    work.bounding_volume_tests += 1;
    let reach_z = l.row(2).norm();
    let reach_xy = (l.row(0).norm_squared() + l.row(1).norm_squared()).sqrt();
    if c.z - reach_z >= length || c.z + reach_z <= 0.0 || c.xy().norm() >= r0.max(r1) + reach_xy {
        return None;
    }
    let a = SlicedEllipsoid::new(c, &l)?;
    let (lo, hi) = disc_extent(&a, radius, 0.0, length)?;
    let slices = DiscSlices {
        radius,
        stretch: (1.0 + slope * slope).sqrt(),
        length,
        extent: (lo, hi),
    };
    disc_solid::contact(
        &a,
        semi_axes,
        pose_a,
        &slices,
        &Solid::Frustum(*frustum),
        pose_b,
        unit,
        work,
    )
}
