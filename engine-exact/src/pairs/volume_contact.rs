//! The shared end of the curved solid–solid pairs: from the intersection's moments to a
//! contact, by the SPEC §4 definition as the clipping pairs read it (see [`super::clipped`]).
//!
//! - **Normal** (from `b` into `a`): `−S/|S|`, `S` the area vector of `a`'s surface inside `b`
//!   (outward of `a`). When `|S|` vanishes against the surface inside (one body within the
//!   other, or two crossing symmetrically) the pair's own fallback direction is used.
//! - **Points**: where the line through the centroid `g` along the normal leaves each body
//!   (`a` along `−n`, `b` along `+n`); δ is their distance.
//! - **Area**: `|S|`, or a quarter of the intersection's surface when `S` vanishes (its mean
//!   projected area, Cauchy's formula).

use crate::kernel::PairContact;
use contact_core::{Point3, Vector3};

/// The moments of one intersection region, in the world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct VolumeMoments {
    /// Volume (> 0 for a contact).
    pub volume: f64,
    /// Centroid.
    pub centroid: Point3,
    /// Area vector of `a`'s surface inside `b`, outward of `a`: `∫ n_a dA`.
    pub area_vector_a: Vector3,
    /// Unsigned area of `a`'s surface inside `b` plus that of `b`'s inside `a` (the
    /// intersection's whole surface), for the vanishing test and the containment area.
    pub surface_area: f64,
    /// The pair's size (the working unit its quadrature ran in), for the round-off floor.
    pub length: f64,
}

/// A region whose whole surface is at most this times the pair's size squared is a
/// round-off sliver of quadratures that run to an absolute floor near 1e-15 of the size:
/// its area vector, hence its normal and the depth along it, is noise (seen: a depth of 0.1
/// of the size from an area of 1e-16 of its square), so it is no contact. A true contact
/// this small is shallower than about 1e-14 of the size for curved surfaces.
pub(crate) const ROUND_OFF_SURFACE: f64 = 1e-13;

/// `|S|` at or below this fraction of the intersection's surface counts as vanishing.
pub(crate) const ENCLOSED: f64 = 1e-12;

/// The contact of the region with moments `m`. `exit_a(g, d)` / `exit_b(g, d)` return the
/// point where the line from `g` along the unit `d` leaves `a` / `b` (the closest surface
/// point when `g` is outside); `fallback_normal()` gives the normal (from `b` into `a`) when
/// the area vector vanishes. `None` when the volume or the depth is not positive.
pub(crate) fn contact(
    m: &VolumeMoments,
    exit_a: impl Fn(&Point3, &Vector3) -> Point3,
    exit_b: impl Fn(&Point3, &Vector3) -> Point3,
    fallback_normal: impl FnOnce() -> Vector3,
) -> Option<PairContact> {
    if m.volume.is_nan() || m.volume <= 0.0 || !m.centroid.coords.iter().all(|c| c.is_finite()) {
        return None;
    }
    if m.surface_area.is_nan() || m.surface_area <= ROUND_OFF_SURFACE * m.length * m.length {
        return None;
    }
    let s_norm = m.area_vector_a.norm();
    // A NaN area vector counts as vanishing too.
    let enclosed = s_norm.is_nan() || s_norm <= ENCLOSED * m.surface_area;
    let (normal, area) = if enclosed {
        (fallback_normal(), 0.25 * m.surface_area)
    } else {
        (-m.area_vector_a / s_norm, s_norm)
    };
    let point_a = exit_a(&m.centroid, &-normal);
    let point_b = exit_b(&m.centroid, &normal);
    let depth = (point_b - point_a).norm();
    // A round-off sliver (a volume of a few ulps where the surfaces only touch) can leave no
    // depth along its normal: touching is not a contact.
    if depth.is_nan() || depth <= 0.0 {
        return None;
    }
    Some(PairContact {
        point_a,
        point_b,
        normal,
        depth,
        area,
    })
}
