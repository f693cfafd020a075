//! A point or a circle against an arc (Adams ARC): closed form.
//!
//! The arc is the circle of radius `R` about `b`'s origin from the +x axis through RANGLE,
//! counter-clockwise; its outward normal is radial (`u`, the unit vector from the centre), so
//! its material lies inside the circle — outside when the arc is flipped. For the point (or
//! the circle's centre) `p` at distance `D` and angle θ ∈ [0, 2π) from +x:
//! - θ within the arc: the closest point is `R·u` and the signed distance `s = ±(D − R)`;
//!   a **point** touches iff `s < 0` (δ = `−s`), a **circle** of radius `r` iff `s < r`
//!   (δ = `r − s`, its point `p − r·n`); the normal is the outward normal `n = ±u`.
//! - θ beyond the arc's ends: no contact, as beyond the end of an open curve (the arc has no
//!   material there).
//! - `p` at the centre (`D = 0`): every point of the arc is equally near; the arc's middle
//!   direction RANGLE/2 is used.
//! - Length (circle only): the chord `2√(r² − s²)` while the centre is outside the material,
//!   the diameter once inside; 0 for a point.

use super::InPlane;
use crate::kernel::PairContact;
use contact_core::{Point2, Vector2};
use std::f64::consts::TAU;

/// `(s, q, n)` for `p` against the arc, or `None` beyond its ends.
fn signed_distance(
    radius: f64,
    range: f64,
    side: f64,
    p: &Point2,
) -> Option<(f64, Point2, Vector2)> {
    let distance = p.coords.norm();
    let u = if distance > 0.0 {
        let theta = p.y.atan2(p.x).rem_euclid(TAU);
        if theta > range {
            return None;
        }
        p.coords / distance
    } else {
        let mid = 0.5 * range;
        Vector2::new(mid.cos(), mid.sin())
    };
    Some((
        side * (distance - radius),
        Point2::from(radius * u),
        side * u,
    ))
}

/// Point `a` against arc `b`.
pub(crate) fn point_arc(
    frame: &InPlane<'_>,
    radius: f64,
    range: f64,
    side: f64,
) -> Option<PairContact> {
    let p = frame.origin_a;
    let (s, q, n) = signed_distance(radius, range, side, &p)?;
    (s < 0.0).then(|| PairContact {
        point_a: frame.point_w(&p),
        point_b: frame.point_w(&q),
        normal: frame.vector_w(&n),
        depth: -s,
        area: 0.0,
    })
}

/// Circle `a` of radius `r` against arc `b`.
pub(crate) fn circle_arc(
    frame: &InPlane<'_>,
    r: f64,
    radius: f64,
    range: f64,
    side: f64,
) -> Option<PairContact> {
    let c = frame.origin_a;
    let (s, q, n) = signed_distance(radius, range, side, &c)?;
    if s >= r {
        return None;
    }
    let length = if s >= 0.0 {
        2.0 * ((r - s) * (r + s)).sqrt()
    } else {
        2.0 * r
    };
    Some(PairContact {
        point_a: frame.point_w(&(c - r * n)),
        point_b: frame.point_w(&q),
        normal: frame.vector_w(&n),
        depth: r - s,
        area: length,
    })
}
