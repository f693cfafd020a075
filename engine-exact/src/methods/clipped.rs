//! The shared end of the clipping pairs (box–plane, box–box): from the intersection
//! polyhedron to a contact, by the SPEC §4 definition (the faceted engine's too).
//!
//! - **Normal** (from `b` into `a`): `S/|S|` with `S` the area vector of `b`'s surface inside
//!   `a` (the faces made by clipping) — the same as `−S_a/|S_a|` for `a`'s surface inside `b`,
//!   since the intersection's closed surface sums to zero, and the rate of change of the
//!   overlap volume when `a` is translated. When that surface closes on itself
//!   (`|S| ≤ 1e-12·Σ|A|`, or no surface at all): if nothing was cut, `a` lies inside `b` and
//!   the normal points from the centroid towards the closest point of `b`'s surface (the
//!   outward normal of the nearest face of that surface; for a plane, the plane's normal);
//!   otherwise `b` lies inside `a` (or the
//!   two cross like a plus sign) and the normal is the opposite of `a`'s face nearest the
//!   centroid — the exchange of the first rule, so the pair stays symmetric.
//! - **Points** (SPEC §4, taken along the normal through the centroid `g` of the
//!   intersection, `ray_exit`): where the line from `g` along `+n` leaves `b`'s
//!   surface and along `−n` leaves `a`; δ is their distance. `g` lies inside both convex
//!   solids, so each exit is the nearest bounding plane the line heads towards. (The plain
//!   closest points to `g` jump between faces where two are equally near, so the force and its
//!   line of action would jump; along the normal they move continuously with the poses.)
//! - **Area**: `|S|`, the contact patch projected on the plane normal to `n`; when `S`
//!   vanishes (containment), a quarter of the intersection's surface (its mean projected
//!   area, Cauchy's formula).
//!
//! The polyhedron is built in coordinates divided by a power of two near the pair's size, so
//! products of three lengths neither overflow nor underflow for sizes within about 1e±100, and
//! scaling a scene by a power of two scales the answer bit for bit.

use crate::kernel::PairContact;
use crate::polyhedron::ConvexPolyhedron;
use contact_core::{Isometry3, Point3, Vector3};

/// A bounding plane of a convex solid: `normal·x ≤ offset`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct HalfSpace {
    pub normal: Vector3,
    pub offset: f64,
}

/// The power of two nearest `length` (> 0, finite), the unit the clipping works in.
pub(crate) fn unit_for(length: f64) -> f64 {
    // From the bits: 2^e·m with m ∈ [1, 2) rounds to 2^(e+1) from m ≥ √2 on.
    let bits = length.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i64;
    if exponent == 0 || exponent >= 0x7fe {
        // Subnormal or at the top of the range: the slow path.
        return 2f64.powi(length.log2().round() as i32);
    }
    let mantissa = f64::from_bits((bits & ((1 << 52) - 1)) | (1023 << 52));
    let rounded = exponent + i64::from(mantissa >= std::f64::consts::SQRT_2);
    f64::from_bits((rounded as u64) << 52)
}

/// The bounding plane nearest to the interior point `p`: `(gap, outward normal)`, the gap
/// clamped at 0 (round-off can put `p` a hair outside). The foot on that plane, `p +
/// gap·normal`, is the point of the solid's surface closest to `p`. Planes whose gaps differ
/// by less than [`TIE`] (working units) count as tied and the first in `planes` wins, so a
/// symmetric pose gives the same face whatever the round-off of the frame it is seen in.
pub(crate) fn nearest_face(p: &Point3, planes: &[HalfSpace]) -> (f64, Vector3) {
    let mut best = (f64::INFINITY, Vector3::z());
    for h in planes {
        let gap = h.offset - h.normal.dot(&p.coords);
        if gap < best.0 - TIE {
            best = (gap, h.normal);
        }
    }
    (best.0.max(0.0), best.1)
}

/// Gaps closer than this (in working units, where the pair's size is about 1) are a tie.
pub(crate) const TIE: f64 = 1e-12;

/// Where the line `origin + t·direction`, from inside the convex solid bounded by `planes`,
/// leaves it: the smallest `t ≥ 0` over the planes it heads towards (0 if none).
pub(crate) fn ray_exit(origin: &Point3, direction: &Vector3, planes: &[HalfSpace]) -> f64 {
    let mut best = f64::INFINITY;
    for h in planes {
        let rate = h.normal.dot(direction);
        if rate > 0.0 {
            best = best.min(((h.offset - h.normal.dot(&origin.coords)) / rate).max(0.0));
        }
    }
    if best.is_finite() { best } else { 0.0 }
}

/// The planes of a box with centre `center`, unit axes `axes` and half extents `half`.
pub(crate) fn box_planes(center: &Point3, axes: &[Vector3; 3], half: &Vector3) -> [HalfSpace; 6] {
    let plane = |k: usize, s: f64| HalfSpace {
        normal: s * axes[k],
        offset: s * axes[k].dot(&center.coords) + half[k],
    };
    [
        plane(0, 1.0),
        plane(0, -1.0),
        plane(1, 1.0),
        plane(1, -1.0),
        plane(2, 1.0),
        plane(2, -1.0),
    ]
}

/// Clips `poly` (solid `a`, in the working frame) by `planes_b` and turns the intersection
/// into a contact in the world: `frame` maps working coordinates times `unit` to the world.
/// `surface_b` are the planes whose union is `b`'s surface (all of `planes_b` for a solid, the
/// plane alone for a plane's prism).
pub(crate) fn contact<const F: usize, const V: usize>(
    poly: &mut ConvexPolyhedron<F, V>,
    planes_a: &[HalfSpace],
    planes_b: &[HalfSpace],
    surface_b: &[HalfSpace],
    frame: &Isometry3,
    unit: f64,
) -> Option<PairContact> {
    let mut cut = false;
    for h in planes_b {
        cut |= poly.clip(&h.normal, h.offset);
    }
    let mass = poly.mass_properties();
    if mass.volume <= 0.0 {
        return None;
    }
    let c = mass.centroid;
    let s = mass.clipped_area_vector;
    let s_norm = s.norm();
    let (_, face_a) = nearest_face(&c, planes_a);
    let (_, face_b) = nearest_face(&c, surface_b);
    let enclosed = s_norm <= 1e-12 * mass.clipped_area;
    let normal = if !enclosed {
        s / s_norm
    } else if !cut {
        face_b
    } else {
        -face_a
    };
    let area = if enclosed {
        0.25 * poly.surface_area()
    } else {
        s_norm
    };
    let to_a = ray_exit(&c, &-normal, planes_a);
    let to_b = ray_exit(&c, &normal, planes_b);
    let world = |p: Point3| frame * Point3::from(p.coords * unit);
    Some(PairContact {
        point_a: world(c - to_a * normal),
        point_b: world(c + to_b * normal),
        normal: frame.rotation * normal,
        depth: (to_a + to_b) * unit,
        area: area * unit * unit,
    })
}
