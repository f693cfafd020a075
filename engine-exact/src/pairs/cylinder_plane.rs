//! Cylinder against an unbounded plane: quadrature of closed-form slices, converged to
//! round-off.
//!
//! In the cylinder's frame (axis +z, bottom face at z = 0, top at `L`, radius `R`) the plane's
//! solid is `n·x ≤ h`; write `n = a·e + b·ẑ` with `e` the unit radial direction of `n`
//! (`a ≥ 0`). A line of the cylinder parallel to its axis at radial coordinate `u = e·x`
//! lies in the solid over the interval `z ∈ [z_lo(u), z_hi(u)] ∩ [0, L]` — `z ≤ (h − a u)/b`
//! for `b > 0`, `z ≥ (h − a u)/b` for `b < 0`, all or nothing for `b = 0` — a length `ℓ(u)`
//! that is piecewise linear in `u` with at most two kinks. So the volume and moments are
//! one-dimensional integrals over the disc's chords, `V = ∫ 2√(R² − u²)·ℓ(u) du`; with
//! `u = R sin φ` the integrand `2R² cos²φ·ℓ(R sin φ)` is a trigonometric polynomial on each
//! piece between kinks, which 12-node Gauss–Legendre integrates to round-off
//! ([`crate::quadrature`]). This stays exact when the axis is parallel to the plane (a wheel
//! on the ground, `b = 0`) or perpendicular to it (`a = 0`).
//!
//! - **an axis parallel to the plane within round-off** (`|b|·L` no larger than a few ulps of
//!   the lengths that went into `h`) is taken as parallel (`b = 0`). A line contact's
//!   centroid slides along the axis by about `b·L²/(8h)`, so at a grazing depth (`h` of
//!   1e-12 of the size) a tilt at round-off, 1e-16, would move it by 1e-4 of the size: noise
//!   amplified 10¹². The answer for `b = 0` is the exact answer for an orientation within
//!   round-off of the given one (backward stable), and it differs from the unsnapped answer
//!   by less than 1e-12 of the size once the depth exceeds 1e-4·L (ε·L²/h);
//! - contact iff the volume is positive; normal: the plane's outward normal;
//! - points (SPEC §4, taken along the normal through the centroid `g`: `ray_exit`):
//!   the foot of `g` on the plane, and where the line from `g` along `−n` leaves the cylinder
//!   (side or cap); δ is their distance;
//! - area (an estimate, exact for a wheel on its side or a cylinder standing upright): the
//!   plane's section inside the cylinder, `(1/|b|)·∫ chord` over the `u` where the plane
//!   meets the cylinder between its caps (its `b → 0` limit `chord(h/a)·L` once
//!   `|b| < 1e-9`); when the plane no longer cuts the cylinder (full immersion), the
//!   quarter of the cylinder's surface `π R (R + L)/2` (its mean projected area, as for
//!   the box pairs).

use super::solid_distance::Solid;
use crate::kernel::PairContact;
use crate::quadrature;
use crate::ray_exit::surface_point_along;
use contact_core::geometry::Cylinder;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use std::f64::consts::{FRAC_PI_2, PI};

/// Contact of `cylinder` at `pose_c` with the plane at `pose_plane` (flipped when `side < 0`).
pub(crate) fn contact(
    cylinder: &Cylinder,
    pose_c: &Isometry3,
    pose_plane: &Isometry3,
    side: f64,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let (r, len) = (cylinder.radius(), cylinder.length());
    let rotation = pose_c.rotation;
    let normal_w = side * (pose_plane.rotation * Vector3::z());
    let n = rotation.inverse_transform_vector(&normal_w);
    let h = n
        .dot(&rotation.inverse_transform_vector(
            &(pose_plane.translation.vector - pose_c.translation.vector),
        ));
    let a = n.xy().norm();
    let b = parallel_within_round_off(n.z, h, len, r, pose_c, pose_plane);
    // The cylinder's lowest point along n: reject before integrating.
    if (b * len).min(0.0) - a * r >= h {
        return None;
    }
    let e = if a > 0.0 {
        n.xy() / a
    } else {
        nalgebra::Vector2::x()
    };
    // The solid's z interval on the axial line at radial coordinate u.
    let interval = |u: f64| -> (f64, f64) {
        if b > 0.0 {
            (0.0, ((h - a * u) / b).min(len))
        } else if b < 0.0 {
            (((h - a * u) / b).max(0.0), len)
        } else if a * u <= h {
            (0.0, len)
        } else {
            (0.0, 0.0)
        }
    };
    // Kinks of ℓ(u), as angles φ = asin(u/R), sorted, with the ends ±π/2.
    let mut cuts = [-FRAC_PI_2, FRAC_PI_2, FRAC_PI_2, FRAC_PI_2];
    let mut count = 1;
    if a > 0.0 {
        let kinks = if b != 0.0 {
            [h / a, (h - b * len) / a]
        } else {
            [h / a, h / a]
        };
        for u in kinks {
            cuts[count] = (u / r).clamp(-1.0, 1.0).asin();
            count += 1;
        }
    }
    cuts[count] = FRAC_PI_2;
    count += 1;
    cuts[..count].sort_by(f64::total_cmp);
    let (mut volume, mut moment_u, mut moment_z, mut section) = (0.0, 0.0, 0.0, 0.0);
    for piece in cuts[..count].windows(2) {
        let (p0, p1) = (piece[0], piece[1]);
        if p1 <= p0 {
            continue;
        }
        // Does the plane cross the cylinder between its caps over this piece?
        let mid = r * (0.5 * (p0 + p1)).sin();
        let crosses = b != 0.0 && {
            let z = (h - a * mid) / b;
            (0.0..=len).contains(&z)
        };
        quadrature::for_each_node(p0, p1, |phi, w| {
            let (sin, cos) = phi.sin_cos();
            let u = r * sin;
            let weight = w * 2.0 * r * r * cos * cos;
            let (lo, hi) = interval(u);
            let length = (hi - lo).max(0.0);
            volume += weight * length;
            moment_u += weight * length * u;
            moment_z += weight * 0.5 * (hi + lo) * length;
            if crosses {
                section += weight;
            }
        });
        work.iterations += quadrature::NODES as u64;
    }
    if volume <= 0.0 {
        return None;
    }
    let u_bar = moment_u / volume;
    let centroid = Vector3::new(e.x * u_bar, e.y * u_bar, moment_z / volume);
    let to_plane = (h - n.dot(&centroid)).max(0.0);
    let on_cylinder = surface_point_along(&Solid::Cylinder(*cylinder), &centroid, &-n);
    let on_plane = centroid + to_plane * n;
    let area = if b.abs() < 1e-9 {
        let u = h / a;
        if u.abs() < r {
            2.0 * ((r - u) * (r + u)).sqrt() * len / a
        } else {
            0.0
        }
    } else {
        section / b.abs()
    };
    let area = if area > 0.0 {
        area
    } else {
        0.5 * PI * r * (r + len)
    };
    let center = pose_c.translation.vector;
    let world = |p: Vector3| Point3::from(center + rotation * p);
    Some(PairContact {
        point_a: world(on_cylinder),
        point_b: world(on_plane),
        normal: normal_w,
        depth: (on_plane - on_cylinder).norm(),
        area,
    })
}

/// `b` (the axis component of the plane normal in the cylinder's frame), or 0 when the tilt it
/// makes over the cylinder's length is within the round-off of the positions that went into
/// the plane height: the axis is then parallel to the plane as far as the input can tell.
fn parallel_within_round_off(
    b: f64,
    h: f64,
    len: f64,
    r: f64,
    pose_c: &Isometry3,
    pose_plane: &Isometry3,
) -> f64 {
    let magnitude =
        pose_c.translation.vector.norm() + pose_plane.translation.vector.norm() + h.abs() + len + r;
    if b.abs() * len <= 8.0 * f64::EPSILON * magnitude {
        0.0
    } else {
        b
    }
}
