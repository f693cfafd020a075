//! The shared end of the clipping pairs (box–plane, box–box): from the intersection
//! polyhedron to a contact.
//!
//! - **Normal** (from `b` into `a`): the area-weighted outward normal `S` of `b`'s surface
//!   inside `a` (the faces made by clipping). When that surface closes on itself
//!   (`|S| ≤ 1e-12·Σ|A|`, or no surface at all): if nothing was cut, `a` lies inside `b` and
//!   leaves through `b`'s face nearest the centroid (that face's outward normal); otherwise
//!   `b` lies inside `a` (or the two cross like a plus sign) and the normal is the opposite of
//!   `a`'s face nearest the centroid — the exchange of the first rule, so the pair stays
//!   symmetric.
//! - **Points**: where the line through the centroid along the normal leaves `b` (`+n`) and
//!   `a` (`−n`); δ is their distance.
//! - **Area**: the intersection's shadow on the plane normal to `n`.
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
    2f64.powi(length.log2().round() as i32)
}

/// Where the ray `origin + t·direction`, from inside the convex solid bounded by `planes`,
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

/// The outward normal of the bounding plane nearest to the interior point `p`.
fn nearest_face_normal(p: &Point3, planes: &[HalfSpace]) -> Vector3 {
    let mut best = (f64::INFINITY, Vector3::z());
    for h in planes {
        let gap = h.offset - h.normal.dot(&p.coords);
        if gap < best.0 {
            best = (gap, h.normal);
        }
    }
    best.1
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
pub(crate) fn contact<const F: usize, const V: usize>(
    mut poly: ConvexPolyhedron<F, V>,
    planes_a: &[HalfSpace],
    planes_b: &[HalfSpace],
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
    let normal = if s_norm > 1e-12 * mass.clipped_area {
        s / s_norm
    } else if !cut {
        nearest_face_normal(&c, planes_b)
    } else {
        -nearest_face_normal(&c, planes_a)
    };
    let to_b = ray_exit(&c, &normal, planes_b);
    let to_a = ray_exit(&c, &-normal, planes_a);
    let world = |p: Point3| frame * Point3::from(p.coords * unit);
    Some(PairContact {
        point_a: world(c - to_a * normal),
        point_b: world(c + to_b * normal),
        normal: frame.rotation * normal,
        depth: (to_a + to_b) * unit,
        area: poly.projected_area(&normal) * unit * unit,
    })
}
