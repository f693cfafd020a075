//! Two spheres, and a sphere inside a spherical cavity (a flipped sphere): closed forms.
//!
//! With centres `c_a`, `c_b`, `D = |c_a − c_b|` and `u = (c_a − c_b)/D`:
//! - **Two solids:** contact iff `D < r_a + r_b`. The lens's centroid lies on the line of
//!   centres, so the surface points along the normal `u` are `c_a − r_a·u` and `c_b + r_b·u`,
//!   and δ = `r_a + r_b − D`. This holds through full containment (`D ≤ |r_a − r_b|`), where
//!   δ keeps growing as the spheres' centres approach. Area: the lens's circle
//!   `π(r_b² − x²)`, `x = (D² + r_b² − r_a²)/(2D)`; once a cap exceeds a hemisphere, the
//!   projected disc of that sphere (continuous).
//! - **Ball `a` in cavity `b`** (the material outside a sphere of radius `r_b`): contact iff
//!   `D + r_a > r_b`; the normal is `−u` (back towards the cavity's centre), the points are
//!   `c_a + r_a·u` and `c_b + r_b·u`, δ = `D + r_a − r_b`. Area: the circle where the two
//!   surfaces cross, or `π r_a²` once the ball's centre is past it.
//! - **Coincident centres** (`D = 0`): `u` is the +z axis of `b`'s geometry frame. Two solids
//!   then have δ = `r_a + r_b`; a ball in a cavity touches only when `r_a > r_b`.

use crate::kernel::PairContact;
use contact_core::{Isometry3, Vector3};
use std::f64::consts::PI;

/// The centres, their distance, the unit vector from `b`'s centre to `a`'s, and the
/// distance's reciprocal (0 for coincident centres). One division instead of four: on this
/// closed form the divider's latency is most of the time. Inlined: returned through memory,
/// the tuple's loads wait on the square root and the division behind its stores.
#[inline(always)]
fn centre_line(pose_a: &Isometry3, pose_b: &Isometry3) -> (Vector3, Vector3, f64, Vector3, f64) {
    let ca = pose_a.translation.vector;
    let cb = pose_b.translation.vector;
    let delta = ca - cb;
    let squared = delta.norm_squared();
    // `1/D = D/D²`: the square root and the division run side by side, not one after the
    // other (within an ulp of `1/D`).
    let distance = squared.sqrt();
    if distance > 0.0 {
        let inverse = distance * (1.0 / squared);
        (ca, cb, distance, delta * inverse, inverse)
    } else {
        (ca, cb, distance, pose_b.rotation * Vector3::z(), 0.0)
    }
}

/// Two solid spheres.
pub(crate) fn contact(
    radius_a: f64,
    pose_a: &Isometry3,
    radius_b: f64,
    pose_b: &Isometry3,
) -> Option<PairContact> {
    let (ca, cb, distance, u, inverse) = centre_line(pose_a, pose_b);
    let depth = radius_a + radius_b - distance;
    if depth <= 0.0 {
        return None;
    }
    let disc_radius_sq = if distance <= (radius_a - radius_b).abs() {
        radius_a.min(radius_b).powi(2)
    } else {
        // distance > |r_a − r_b| ≥ 0 here, so `inverse` is 1/distance.
        let x = (distance * distance + radius_b * radius_b - radius_a * radius_a) * (0.5 * inverse);
        if x < 0.0 {
            radius_b * radius_b
        } else if distance - x < 0.0 {
            radius_a * radius_a
        } else {
            (radius_b - x) * (radius_b + x)
        }
    };
    Some(PairContact {
        point_a: (ca - radius_a * u).into(),
        point_b: (cb + radius_b * u).into(),
        normal: u,
        depth,
        area: PI * disc_radius_sq,
    })
}

/// Solid ball `a` inside the spherical cavity `b` of radius `radius_b`.
pub(crate) fn contact_in_cavity(
    radius_a: f64,
    pose_a: &Isometry3,
    radius_b: f64,
    pose_b: &Isometry3,
) -> Option<PairContact> {
    let (ca, cb, distance, u, inverse) = centre_line(pose_a, pose_b);
    let depth = distance + radius_a - radius_b;
    if depth <= 0.0 {
        return None;
    }
    let disc_radius_sq = if distance > 0.0 {
        let x = (distance * distance + radius_b * radius_b - radius_a * radius_a) * (0.5 * inverse);
        if x > distance {
            ((radius_b - x) * (radius_b + x)).max(0.0)
        } else {
            radius_a * radius_a
        }
    } else {
        radius_a * radius_a
    };
    Some(PairContact {
        point_a: (ca + radius_a * u).into(),
        point_b: (cb + radius_b * u).into(),
        normal: -u,
        depth,
        area: PI * disc_radius_sq,
    })
}
