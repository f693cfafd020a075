//! Ellipsoid against box, by slicing across the box's `z` axis.
//!
//! Slicing frame: the box's frame at its centre. Every slice of the box is the same rectangle,
//! overlapped with the ellipsoid's section in closed form
//! (`crate::methods::ellipsoid_sliced::disc_overlap`: a disc against a polygon after the map that
//! makes the section a circle). The quadrature is cut wherever the overlap's shape changes,
//! all in closed form, so each piece is smooth (or has a square-root end, which the
//! sine-mapped rule absorbs): the ends of the common `z` range, the heights where a section
//! is tangent to a side line of the rectangle (`α + βτ ± γ√(1 − τ²) = d`, a quadratic in
//! `τ`), and where the box's four `z` edges pierce the ellipsoid (a quadratic). Between
//! these cuts the overlap is empty throughout or nowhere. The box's `z` faces add their
//! overlap with the ellipsoid's section at `z = ±h_z` to the unsigned surface.
//!
//! The contact follows [`crate::methods::volume_contact`]. When the area vector vanishes: with the
//! ellipsoid inside the box, the normal is the outward normal of the box's face nearest the
//! centroid; with the box inside the ellipsoid, against the ellipsoid's level-surface normal
//! at the centroid (`crate::methods::ellipsoid_sliced::inward_of_ellipsoid`).

use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::ellipsoid_sliced::disc_overlap::disc_polygon;
use crate::methods::ellipsoid_sliced::{
    COMPONENTS, SlicedEllipsoid, ellipsoid_exit_w, ellipsoid_in, integrand, integrate,
    inward_of_ellipsoid, quadratic_roots, shape_events, to_world,
};
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::ray_exit::surface_point_along_w;
use contact_core::geometry::Cuboid;
use contact_core::{Isometry3, Vector3, WorkCounters};
use nalgebra::{Translation3, Vector2};

/// Contact of the ellipsoid with `semi_axes` at `pose_a` with `cuboid` at `pose_b`.
pub(crate) fn contact(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    cuboid: &Cuboid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let unit = unit_for(semi_axes.max().max(cuboid.half_extents().norm()));
    let frame = pose_b * Translation3::from(cuboid.center().coords);
    let (c, l) = ellipsoid_in(&frame, pose_a, semi_axes, unit);
    let half = cuboid.half_extents() / unit;
    work.bounding_volume_tests += 1;
    // Along each box axis the ellipsoid reaches |row_k(L)| from its centre.
    if (0..3).any(|k| c[k].abs() >= half[k] + l.row(k).norm()) {
        return None;
    }
    let a = SlicedEllipsoid::new(c, &l)?;
    let (a_lo, a_hi) = a.range();
    let (lo, hi) = (a_lo.max(-half.z), a_hi.min(half.z));
    if lo >= hi {
        return None;
    }
    let corners = [
        Vector2::new(-half.x, -half.y),
        Vector2::new(half.x, -half.y),
        Vector2::new(half.x, half.y),
        Vector2::new(-half.x, half.y),
    ];
    let (mut cuts, mut n) = side_and_edge_cuts(&a, &c, &half, &corners, (lo, hi));
    let overlap = |t: f64| {
        let sa = a.section(t)?;
        let inverse = sa.matrix.try_inverse()?;
        let w = corners.map(|v| inverse * (v - sa.center));
        Some((sa, disc_polygon(&w, &sa.matrix)))
    };
    shape_events(
        lo,
        hi,
        |t| overlap(t).map_or(0, |(_, o)| o.shape),
        &mut cuts,
        &mut n,
    );
    let mut f = |t: f64| -> [f64; COMPONENTS] {
        match overlap(t) {
            Some((sa, o)) if t >= lo && t <= hi => integrand(t, &sa, &o, o.other_length),
            _ => [0.0; COMPONENTS],
        }
    };
    let mut integrals = integrate(&mut cuts[..n], &mut f, work);
    for z in [-half.z, half.z] {
        if let Some((sa, o)) = overlap(z) {
            integrals.surface_b += sa.matrix.determinant() * o.area;
        }
    }
    let inside_box = integrals.surface_b == 0.0;
    let moments = to_world(&integrals, &frame, unit);
    let g = moments.centroid;
    crate::methods::volume_contact::contact(
        &moments,
        |g, d| ellipsoid_exit_w(semi_axes, pose_a, g, d),
        |g, d| surface_point_along_w(&Solid::Box(*cuboid), pose_b, g, d),
        || {
            if inside_box {
                let p = pose_b.inverse_transform_point(&g).coords;
                pose_b.rotation * signed_distance(&Solid::Box(*cuboid), &p).2
            } else {
                inward_of_ellipsoid(semi_axes, pose_a, &g, pose_b)
            }
        },
    )
}

/// The slice positions in `(lo, hi)` where the section of the ellipsoid `a` (centre `c`) meets
/// the box (half extents `half`, vertical edges through `corners`) in a new way: where it
/// touches the plane of each side, and where it passes each vertical edge; `lo` and `hi`
/// first, at most 33, and their number.
fn side_and_edge_cuts(
    a: &SlicedEllipsoid,
    c: &Vector3,
    half: &Vector3,
    corners: &[Vector2<f64>; 4],
    (lo, hi): (f64, f64),
) -> ([f64; 33], usize) {
    let mut cuts = [0.0; 33];
    cuts[0] = lo;
    cuts[1] = hi;
    let mut n = 2;
    let mut push = |t: f64, cuts: &mut [f64; 33]| {
        if t > lo && t < hi && n < cuts.len() {
            cuts[n] = t;
            n += 1;
        }
    };
    let sides = [
        (Vector2::x(), half.x),
        (-Vector2::x(), half.x),
        (Vector2::y(), half.y),
        (-Vector2::y(), half.y),
    ];
    for (normal, d) in sides {
        let (alpha, beta, gamma) = a.support_terms(&normal);
        let e = d - alpha;
        let (roots, count) = quadratic_roots(
            beta * beta + gamma * gamma,
            -2.0 * beta * e,
            e * e - gamma * gamma,
        );
        for &tau in &roots[..count] {
            if tau.abs() < 1.0 {
                push(a.t_of(tau), &mut cuts);
            }
        }
    }
    let inverse = a.inverse();
    let rate = inverse.column(2).into_owned();
    for corner in corners {
        let start = inverse * (Vector3::new(corner.x, corner.y, 0.0) - c);
        let (roots, count) = quadratic_roots(
            rate.norm_squared(),
            2.0 * start.dot(&rate),
            start.norm_squared() - 1.0,
        );
        for &t in &roots[..count] {
            push(t, &mut cuts);
        }
    }
    (cuts, n)
}
