//! The frustum pair's moments by the divergence theorem over the two lateral surfaces
//! ([`super::lateral`]), with `a`'s caps from the polar slices; declined for grazing slivers.
//!
//! Where no cap can meet the intersection (`caps_clear`), one lateral surface is enough
//! ([`one_surface_sums`]): fields radial from `b`'s cone's apex, or along a cylinder's axis,
//! are tangent to that solid's lateral surface, so all their flux crosses the other's. Two
//! long solids crossing away from their ends are the case.

use super::add_caps;
use super::caps_clear::caps_clear;
use super::lateral;
use super::slice::{self, Pair, rim_axes};
use crate::methods::ellipsoid_sliced::COMPONENTS;
use crate::quadrature::Adaptive;
use contact_core::{Vector3, WorkCounters};

/// A region whose generators all have a discriminant below this fraction of its terms'
/// size, on both lateral surfaces, is a grazing sliver the divergence theorem does not
/// resolve: its interval lengths go as the root of that discriminant, whose digits the
/// cancellation took (measured on crossed cylinders sunk by δ: points within 2e-12 of the
/// polygon slicing at δ = 1e-6 of the radius, 2e-9 at 1e-7, none found below 1e-9), so it
/// is sliced.
const GRAZING: f64 = 1e-5;

/// The divergence theorem declines a grazing sliver ([`GRAZING`]): it is to be sliced.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Unresolved;

/// `|S_a|` below this fraction of the surfaces found is near vanishing: `b`'s caps inside `a`
/// are added to its surface there (elsewhere they only tighten a bound no test is near).
const NEAR_VANISHING: f64 = 1e-6;

/// The caps' polar integrals alongside the divergence theorem: as the slices' rule, on the
/// 41-node pair (their pieces are cut at every kink, see [`slice`]).
const CAP_RULE: Adaptive = Adaptive {
    pair: crate::quadrature::Pair::Kronrod41,
    ..slice::ADAPTIVE
};

/// How far (in thicknesses of the region: its volume over its lateral surfaces' area) the
/// fields' reference point may lie from the centroid before the fluxes are integrated again
/// about the centroid (each lost digit is a factor of ten of this distance).
const REFERENCE_REACH: f64 = 8.0;

/// The pair's sums by the divergence theorem ([`lateral`]): the volume and moments from the two
/// lateral surfaces' fluxes (`w` the unit perpendicular to both axes), `a`'s area vector
/// from its lateral surface and caps, and (the last component) `b`'s surface inside `a`;
/// `None` when no volume is found (apart, touching).
pub(super) fn divergence_sums(
    pair: &Pair,
    w: &Vector3,
    (lo, hi): (f64, f64),
    surfaces: Surfaces,
    work: &mut WorkCounters,
) -> Result<Option<[f64; COMPONENTS]>, Unresolved> {
    if surfaces == Surfaces::OneWherePossible {
        if let Some(r) = one_surface_sums(pair, work) {
            return Ok(r);
        }
    }
    let (swapped, origin, axes) = pair.swapped();
    let mut fields = lateral::Fields {
        centre: lateral::reference_point(pair),
        w: *w,
        e1: Vector3::z(),
        e2: w.cross(&Vector3::z()),
    };
    let (mut lateral_a, mut lateral_b) = (
        pair.lateral(&fields),
        swapped.lateral(&fields.in_frame(&origin, &axes)),
    );
    if lateral_a.conditioning.max(lateral_b.conditioning) < GRAZING {
        return Err(Unresolved);
    }
    let mut recentred = false;
    let (on_a, on_b, volume, moment) = loop {
        let (on_a, on_b) = (lateral_a.integrate(work), lateral_b.integrate(work));
        let volume = on_a[0] + on_b[0];
        if volume.is_nan() || volume <= 0.0 {
            return Ok(None);
        }
        let offset = fields.w * (on_a[1] + on_b[1])
            + fields.e1 * (on_a[2] + on_b[2])
            + fields.e2 * (on_a[3] + on_b[3]);
        let moment = fields.centre * volume + offset;
        // Each flux is integrated to a relative tolerance of its own size, about the
        // reference point's distance from the region times its surface: far more than the
        // volume (its thickness times the surface) for a small or thin region far from the
        // axes' closest points. Then once more about the centroid just found.
        let thickness = volume / (on_a[7] + on_b[7]);
        if recentred || offset.norm() / volume <= REFERENCE_REACH * thickness {
            break (on_a, on_b, volume, moment);
        }
        fields.centre = moment / volume;
        lateral_a.set_fields(&fields);
        lateral_b.set_fields(&fields.in_frame(&origin, &axes));
        recentred = true;
    };
    let mut r = [
        volume, moment.z, moment.x, moment.y, on_a[4], on_a[5], on_a[6], on_a[7], 0.0,
    ];
    // No absolute floor: a small region's caps are as small as it, and its normal is theirs.
    // Nor is `b`'s slab widened for a cap flush with `b`'s (axes apart, no cap is): the
    // widening's sliver, 1e-12 of the unit across a chord, is 1e-9 of a small region's area.
    add_caps(pair, (lo, hi), (&CAP_RULE, 0.0, false), &mut r, work);
    // b's surface inside a: its lateral part, integrated alongside; its caps only where the
    // area vector is near vanishing (containment, symmetric crossings), where the whole
    // surface judges it and sizes the area.
    r[8] = on_b[7];
    if Vector3::new(r[4], r[5], r[6]).norm() <= NEAR_VANISHING * (r[7] + r[8]) {
        let mut caps_b = [0.0; COMPONENTS];
        add_caps(
            &swapped,
            swapped.b_range(),
            (&CAP_RULE, 0.0, false),
            &mut caps_b,
            work,
        );
        r[8] += caps_b[7];
    }
    Ok(Some(r))
}

/// Which lateral surfaces [`divergence_sums`] integrates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Surfaces {
    /// One where [`one_surface_sums`] applies, else both.
    OneWherePossible,
    /// Both always (the one-surface sums' check).
    #[cfg_attr(not(test), allow(dead_code))]
    Both,
}

/// The sums from one lateral surface alone, where no cap can meet the intersection
/// ([`caps_clear`]): for `b` a frustum,
/// the fields radial from its apex over `a`'s surface ([`radial_sums`]); else (or where
/// those decline), for a cylinder among them, the fields of [`lateral`] taken along its axis
/// over the other's surface. Either family is tangent to the one solid's lateral surface, so
/// their flux through the intersection's boundary all crosses the other's. That surface's
/// area vector is then minus the first's (the boundary is closed), and its unsigned area the
/// surface inside the other solid on its side; the first's surface inside the other is left
/// at the area vector's length (a lower bound, as the slicing takes it: it only sizes the
/// vanishing tests). `None` where this does not apply, or declines: a cap in reach, two
/// frusta whose apexes are out of reach, a grazing sliver, or an area vector near vanishing
/// (a symmetric crossing, whose area the whole surface sizes): both surfaces are integrated
/// there. `Some(None)`: no volume.
pub(super) fn one_surface_sums(
    pair: &Pair,
    work: &mut WorkCounters,
) -> Option<Option<[f64; COMPONENTS]>> {
    if !caps_clear(pair) {
        return None;
    }
    if pair.b.slope != 0.0 {
        let apex = pair.b.origin - pair.b.axis * (pair.b.r0 / pair.b.slope);
        if let Some(r) = radial_sums(pair, &apex, work) {
            return Some(r);
        }
    }
    // The surface integrated is b's when a is the cylinder (the fields along a's axis, z).
    let of_b = if pair.b.slope == 0.0 {
        false
    } else if pair.a.slope == 0.0 {
        true
    } else {
        return None;
    };
    let (swapped, origin, axes) = pair.swapped();
    let axis = if of_b { Vector3::z() } else { pair.b.axis };
    let (e1, e2) = rim_axes(&axis);
    let mut fields = lateral::Fields {
        centre: lateral::reference_point(pair),
        w: axis,
        e1,
        e2,
    };
    let seen = |fields: &lateral::Fields| {
        if of_b {
            fields.in_frame(&origin, &axes)
        } else {
            *fields
        }
    };
    let mut surface = if of_b {
        swapped.lateral(&seen(&fields))
    } else {
        pair.lateral(&seen(&fields))
    };
    if surface.conditioning < GRAZING {
        return None;
    }
    let mut recentred = false;
    loop {
        let on = surface.integrate(work);
        let volume = on[0];
        if volume.is_nan() || volume <= 0.0 {
            return Some(None);
        }
        let offset = fields.w * on[1] + fields.e1 * on[2] + fields.e2 * on[3];
        let moment = fields.centre * volume + offset;
        // As in `divergence_sums`, the region's surface about twice the one integrated.
        let thickness = volume / (2.0 * on[7]);
        if recentred || offset.norm() / volume <= REFERENCE_REACH * thickness {
            let own = Vector3::new(on[4], on[5], on[6]);
            let s_a = if of_b {
                -(axes[0] * own.x + axes[1] * own.y + axes[2] * own.z)
            } else {
                own
            };
            let projected = s_a.norm();
            if projected.is_nan() || projected <= NEAR_VANISHING * on[7] {
                return None;
            }
            let (inside_b, inside_a) = if of_b {
                (projected, on[7])
            } else {
                (on[7], projected)
            };
            return Some(Some([
                volume, moment.z, moment.x, moment.y, s_a.x, s_a.y, s_a.z, inside_b, inside_a,
            ]));
        }
        fields.centre = moment / volume;
        surface.set_fields(&seen(&fields));
        recentred = true;
    }
}

/// How far (in thicknesses of the region) a cone's apex may lie from the centroid for the
/// fields radial from it ([`radial_sums`]): their fluxes cancel over the region as that
/// distance over its thickness, and cannot be taken about another point (only fields
/// through the apex are tangent to the cone); past this the other ways are taken.
const RADIAL_REACH: f64 = 1e3;

/// [`one_surface_sums`] for `b` a frustum (a cone's part) whose `apex` is given (in `a`'s
/// frame): the fields radial from the apex are tangent to `b`'s lateral surface, so all
/// their flux crosses `a`'s. `None` where it declines (a grazing sliver, an apex beyond
/// [`RADIAL_REACH`], an area vector near vanishing); `Some(None)`: no volume.
fn radial_sums(
    pair: &Pair,
    apex: &Vector3,
    work: &mut WorkCounters,
) -> Option<Option<[f64; COMPONENTS]>> {
    // Lengths here are in units of the pair's size, and a thickness is at most that: an apex
    // more than the reach from the axes' closest points (the region is near them) is about
    // as far from the centroid in thicknesses, declined before integrating anything (a
    // frustum all but a cylinder, whose apex is far off).
    if (apex - lateral::reference_point(pair)).norm() > RADIAL_REACH {
        return None;
    }
    let mut surface = pair.lateral_radial(apex);
    if surface.conditioning < GRAZING {
        return None;
    }
    let on = surface.integrate(work);
    let volume = on[0];
    if volume.is_nan() || volume <= 0.0 {
        return Some(None);
    }
    let moment = apex * volume + Vector3::new(on[1], on[2], on[3]);
    let thickness = volume / (2.0 * on[7]);
    if (moment / volume - apex).norm() > RADIAL_REACH * thickness {
        return None;
    }
    let s_a = Vector3::new(on[4], on[5], on[6]);
    let projected = s_a.norm();
    if projected.is_nan() || projected <= NEAR_VANISHING * on[7] {
        return None;
    }
    Some(Some([
        volume, moment.z, moment.x, moment.y, s_a.x, s_a.y, s_a.z, on[7], projected,
    ]))
}
