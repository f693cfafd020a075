//! A point or a circle against a curve (Adams CURVE, B-spline order 2–4): iterative, to
//! `1e-13` of the curve's size.
//!
//! The curve's outward normal is `tangent × z = (t_y, −t_x)/|t|` (SPEC §2), reversed when the
//! curve is flipped; its material lies on the other side. With `C(u*)` the point of the curve
//! closest to the point (or to the circle's centre) `p` ([`PlanarCurve::closest`]) and
//! `s = (p − C(u*))·n(u*)` the signed distance:
//! - **Point:** contact iff `s < 0`; δ = `−s`, normal `n(u*)`, points `p` and `C(u*)`;
//!   length 0.
//! - **Circle** of radius `r`: contact iff `s < r`; δ = `r − s`, normal `n(u*)`, points
//!   `p − r·n` and `C(u*)`; length: the chord `2√(r² − s²)` while the centre is outside the
//!   material, the diameter once inside. This is the roller-follower answer: exact where the
//!   curve is straight or circular around the contact; on a curve of curvature κ it departs
//!   from the area-centroid definition of SPEC §4 by O(κ·δ²).
//! - **Ends of an open curve:** when the closest point is an end and `p` lies beyond it
//!   (along the tangent by more than `1e-9` of the curve's size), there is no contact.
//! - **Cusps** (zero derivative, from repeated control points): the tangent is taken along
//!   the second derivative, the limit direction of the curve there.
//! - One contact per pair: the deepest, at the global closest point; a circle touching a
//!   curve in two separate places (a V-groove) reports the nearer one only.

use super::InPlane;
use super::curve_eval::PlanarCurve;
use crate::kernel::PairContact;
use contact_core::{Point2, Vector2, WorkCounters};

/// The signed distance of `p` from the curve, with the closest point and the normal; `None`
/// when `p` lies beyond an open end.
fn signed_distance(
    curve: &PlanarCurve,
    side: f64,
    p: &Point2,
    work: &mut WorkCounters,
) -> Option<(f64, Point2, Vector2)> {
    let closest = curve.closest(p, &mut work.iterations);
    let mut t = closest.tangent;
    if t.norm() == 0.0 {
        t = curve.second_derivative(closest.u);
    }
    let t_norm = t.norm();
    if t_norm == 0.0 {
        return None;
    }
    let t = t / t_norm;
    let offset = p - closest.point;
    if closest.at_end && offset.dot(&t).abs() > 1e-9 * curve.length() {
        return None;
    }
    let n = side * Vector2::new(t.y, -t.x);
    Some((offset.dot(&n), closest.point, n))
}

/// Point `a` against curve `b`.
pub(crate) fn point_curve(
    frame: &InPlane<'_>,
    curve: &PlanarCurve,
    side: f64,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let p = frame.origin_a;
    let (s, on_curve, n) = signed_distance(curve, side, &p, work)?;
    if s >= 0.0 {
        return None;
    }
    Some(PairContact {
        point_a: frame.point_w(&p),
        point_b: frame.point_w(&on_curve),
        normal: frame.vector_w(&n),
        depth: -s,
        area: 0.0,
    })
}

/// Circle `a` of `radius` against curve `b`.
pub(crate) fn circle_curve(
    frame: &InPlane<'_>,
    radius: f64,
    curve: &PlanarCurve,
    side: f64,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let c = frame.origin_a;
    let (s, on_curve, n) = signed_distance(curve, side, &c, work)?;
    if s >= radius {
        return None;
    }
    let length = if s >= 0.0 {
        2.0 * ((radius - s) * (radius + s)).sqrt()
    } else {
        2.0 * radius
    };
    Some(PairContact {
        point_a: frame.point_w(&(c - radius * n)),
        point_b: frame.point_w(&on_curve),
        normal: frame.vector_w(&n),
        depth: radius - s,
        area: length,
    })
}
