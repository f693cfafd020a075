//! Points and circles against circles: closed forms on the line of centres.
//!
//! `b`'s centre is the origin of its plane; with `a`'s centre (or the point) at distance `D`
//! and `u` the unit vector from `b`'s centre to `a`'s (`b`'s x axis when `D = 0`):
//! - **Point in a solid circle:** contact iff `D < r`; normal `u` (out of the circle),
//!   δ = `r − D`, points: the point and `r·u`; length 0.
//! - **Point in a hole** (a flipped circle: material outside radius `r`): contact iff
//!   `D > r`; normal `−u`, δ = `D − r`, points: the point and `r·u`.
//! - **Two solid circles:** contact iff `D < r_a + r_b`; the lens's centroid lies on the line
//!   of centres, so the points are `c_a − r_a·u` and `r_b·u`, δ = `r_a + r_b − D` (also in full
//!   containment); length: the common chord, or a diameter once a segment exceeds a half disc.
//! - **Circle `a` in hole `b`:** contact iff `D + r_a > r_b`; normal `−u`, points
//!   `c_a + r_a·u` and `r_b·u`, δ = `D + r_a − r_b`; length: the chord where the circles
//!   cross, or `2 r_a` once `a`'s centre is past it.

use super::InPlane;
use crate::kernel::PairContact;
use contact_core::{Point2, Vector2};

fn centre_line(frame: &InPlane<'_>) -> (Point2, f64, Vector2) {
    let c = frame.origin_a;
    let distance = c.coords.norm();
    let u = if distance > 0.0 {
        c.coords / distance
    } else {
        Vector2::x()
    };
    (c, distance, u)
}

/// Point `a` against the solid circle (or, with `hole`, the circular hole) `b`.
pub(crate) fn point_circle(frame: &InPlane<'_>, radius: f64, hole: bool) -> Option<PairContact> {
    let (p, distance, u) = centre_line(frame);
    let (depth, normal) = if hole {
        (distance - radius, -u)
    } else {
        (radius - distance, u)
    };
    if depth <= 0.0 {
        return None;
    }
    Some(PairContact {
        point_a: frame.point_w(&p),
        point_b: frame.point_w(&Point2::from(radius * u)),
        normal: frame.vector_w(&normal),
        depth,
        area: 0.0,
    })
}

/// Two solid circles.
pub(crate) fn circle_circle(
    frame: &InPlane<'_>,
    radius_a: f64,
    radius_b: f64,
) -> Option<PairContact> {
    let (c, distance, u) = centre_line(frame);
    let depth = radius_a + radius_b - distance;
    if depth <= 0.0 {
        return None;
    }
    let half_chord = if distance <= (radius_a - radius_b).abs() {
        radius_a.min(radius_b)
    } else {
        let x =
            (distance * distance + radius_b * radius_b - radius_a * radius_a) / (2.0 * distance);
        if x < 0.0 {
            radius_b
        } else if distance - x < 0.0 {
            radius_a
        } else {
            ((radius_b - x) * (radius_b + x)).sqrt()
        }
    };
    Some(PairContact {
        point_a: frame.point_w(&(c - radius_a * u)),
        point_b: frame.point_w(&Point2::from(radius_b * u)),
        normal: frame.vector_w(&u),
        depth,
        area: 2.0 * half_chord,
    })
}

/// Solid circle `a` inside the circular hole `b`.
pub(crate) fn circle_in_hole(
    frame: &InPlane<'_>,
    radius_a: f64,
    radius_b: f64,
) -> Option<PairContact> {
    let (c, distance, u) = centre_line(frame);
    let depth = distance + radius_a - radius_b;
    if depth <= 0.0 {
        return None;
    }
    let half_chord = if distance > 0.0 {
        let x =
            (distance * distance + radius_b * radius_b - radius_a * radius_a) / (2.0 * distance);
        if x > distance {
            ((radius_b - x) * (radius_b + x)).max(0.0).sqrt()
        } else {
            radius_a
        }
    } else {
        radius_a
    };
    Some(PairContact {
        point_a: frame.point_w(&(c + radius_a * u)),
        point_b: frame.point_w(&Point2::from(radius_b * u)),
        normal: frame.vector_w(&-u),
        depth,
        area: 2.0 * half_chord,
    })
}
