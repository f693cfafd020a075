//! Ellipsoid against an unbounded plane: closed form through the affine map to a sphere.
//!
//! In the ellipsoid's frame, with semi-axes `s` (`S = diag(s)`), plane normal `n` and the
//! solid `n·x ≤ h`: the map `x = S·y` sends the ellipsoid to the unit ball and the plane to
//! `m·y ≤ σ` with `m = S n/|S n|`, `σ = h/|S n|`. Affine maps keep centroids, so the
//! intersection's centroid is `S` applied to the unit-ball cap's centroid
//! `y_c = −m·3(2 − t)²/(4(3 − t))`, with cap height `t = 1 + σ`:
//! - contact iff `σ > −1`; `σ ≥ 1` is full immersion (`t = 2`, the centroid is the centre);
//! - normal: the plane's outward normal `n`;
//! - `point_j` is the foot of the centroid on the plane; `point_i` is where the ray from the
//!   centroid along `−n` leaves the ellipsoid (a quadratic, solved without cancellation);
//! - δ = the distance between them;
//! - area (an estimate, exact for a sphere): the plane section `π·abc·(1 − σ²)/|S n|` while
//!   the centre is above the plane, the central section `π·abc/|S n|` once it is below.

use crate::kernel::PairContact;
use contact_core::{Isometry3, Vector3};
use std::f64::consts::PI;

/// Contact of the ellipsoid with `semi_axes` at `pose_e` with the plane at `pose_plane`.
pub(crate) fn contact(
    semi_axes: &Vector3,
    pose_e: &Isometry3,
    pose_plane: &Isometry3,
    side: f64,
) -> Option<PairContact> {
    let rotation = pose_e.rotation;
    let center = pose_e.translation.vector;
    let normal_w = side * (pose_plane.rotation * Vector3::z());
    let n = rotation.inverse_transform_vector(&normal_w);
    let h = n.dot(&rotation.inverse_transform_vector(&(pose_plane.translation.vector - center)));
    let sn = semi_axes.component_mul(&n);
    let k = sn.norm();
    let sigma = h / k;
    if sigma <= -1.0 {
        return None;
    }
    let t = (1.0 + sigma).min(2.0);
    let g = 3.0 * (2.0 - t) * (2.0 - t) / (4.0 * (3.0 - t));
    let centroid = semi_axes.component_mul(&(-g / k * sn));
    let to_plane = h - n.dot(&centroid);
    let tau = crate::ray_exit::ellipsoid_exit(semi_axes, &centroid, &-n).unwrap_or(0.0);
    let point_a = centroid - tau * n;
    let point_b = centroid + to_plane * n;
    let abc = semi_axes.x * semi_axes.y * semi_axes.z;
    let s = sigma.min(0.0);
    Some(PairContact {
        point_a: (center + rotation * point_a).into(),
        point_b: (center + rotation * point_b).into(),
        normal: normal_w,
        depth: to_plane + tau,
        area: PI * abc * (1.0 - s) * (1.0 + s) / k,
    })
}
