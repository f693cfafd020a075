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

/// A region thinner than this fraction of the pair's size (volume over `|S|`) is checked for
/// being resolved at all ([`unresolved_lens`]).
pub(crate) const THIN: f64 = 1e-6;

/// Whether a thin region's moments are noise: every intersection of two convex solids (all
/// the pairs here) is convex, and a convex region's chord through its centroid along `n` is
/// at most `3V/|S|` (`V ≥ ⅓·A·ℓ` for the projected area `A = |S|` and the longest chord `ℓ`
/// along `n`), and the depth is that chord. A lens far thinner than the pair's size (overlaps
/// of 1e-8 of it and less between curved surfaces) has sections whose overlap areas are at
/// round-off, so its volume and centroid are noise, and the line through a centroid that lies
/// outside the lens crosses the surfaces far apart (seen: a depth of 5e-3 of the size for an
/// overlap of 4e-13). Such a region breaks the bound by orders of magnitude; it is touching
/// within round-off, and gives no contact. Only thin regions are checked, so a solid passing
/// through a thick plate (whose depth along the plate's normal can exceed the chord) is not.
pub(crate) fn unresolved_lens(volume: f64, s_norm: f64, depth: f64, length: f64) -> bool {
    let thickness = volume / s_norm;
    thickness <= THIN * length && depth > 3.0 * thickness * (1.0 + 1e-6) + 1e-13 * length
}

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
    contact_of_region(m, exit_a, exit_b, fallback_normal, true)
}

/// [`contact`] for a region that may not be convex (`convex` false: a torus' region), whose
/// depth along the normal may exceed the convex chord bound `3V/|S|` (a flat torus' region
/// has its centroid in the hole and takes its points as the closest ones), so the
/// [`unresolved_lens`] test, which rests on that bound, is not applied.
pub(crate) fn contact_of_region(
    m: &VolumeMoments,
    exit_a: impl Fn(&Point3, &Vector3) -> Point3,
    exit_b: impl Fn(&Point3, &Vector3) -> Point3,
    fallback_normal: impl FnOnce() -> Vector3,
    convex: bool,
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
    if convex && !enclosed && unresolved_lens(m.volume, s_norm, depth, m.length) {
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
