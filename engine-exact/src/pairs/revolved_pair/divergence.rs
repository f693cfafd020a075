//! The frustum pair's moments by the divergence theorem over the two lateral surfaces
//! ([`super::lateral`]), with `a`'s caps from the polar slices; declined for grazing slivers.

use super::add_caps;
use super::lateral;
use super::slice::{self, Pair};
use crate::pairs::ellipsoid_sliced::COMPONENTS;
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
    lo: f64,
    hi: f64,
    work: &mut WorkCounters,
) -> Result<Option<[f64; COMPONENTS]>, Unresolved> {
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
