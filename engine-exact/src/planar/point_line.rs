//! A point or a circle against a 2-D line (PLANE in a 2-D contact): closed forms.
//!
//! The line is `b`'s x axis over `[XMIN, XMAX]`; its material lies at `y ≤ 0`, or `y ≥ 0`
//! when flipped (`side = −1`), so the outward normal is `n = (0, side)`.
//! - **Point** at `(x, y)`, `d = side·y`: contact iff `d < 0` and `XMIN ≤ x ≤ XMAX`;
//!   δ = `−d`, the points are the point itself and its foot `(x, 0)`; length 0.
//! - **Circle** of radius `r` centred at height `d` (unbounded line only; a bounded one is
//!   [`super::circle_bounded_line`], which reduces to this where its range covers the disc's
//!   span): contact iff `d < r`; the segment's centroid lies on the normal through the
//!   centre, so δ = `r − d` with points `c − r·n` and `c − d·n`; length: the chord
//!   `2√(r² − d²)` while the centre is above the line, the diameter `2r` once below
//!   (continuous).

use super::InPlane;
use crate::kernel::PairContact;
use contact_core::geometry::Line;
use contact_core::{Point2, Vector2};

/// Point `a` against line `b`.
pub(crate) fn contact(frame: &InPlane<'_>, line: &Line, side: f64) -> Option<PairContact> {
    let p = frame.origin_a;
    let d = side * p.y;
    let [x0, x1] = line.x_range();
    if d >= 0.0 || p.x < x0 || p.x > x1 {
        return None;
    }
    let normal = Vector2::new(0.0, side);
    Some(PairContact {
        point_a: frame.point_w(&p),
        point_b: frame.point_w(&Point2::new(p.x, 0.0)),
        normal: frame.vector_w(&normal),
        depth: -d,
        area: 0.0,
    })
}

/// Circle `a` of `radius` against the unbounded line `b`.
pub(crate) fn circle_line(frame: &InPlane<'_>, radius: f64, side: f64) -> Option<PairContact> {
    let c = frame.origin_a;
    let d = side * c.y;
    if d >= radius {
        return None;
    }
    let normal = Vector2::new(0.0, side);
    let length = if d >= 0.0 {
        2.0 * ((radius - d) * (radius + d)).sqrt()
    } else {
        2.0 * radius
    };
    Some(PairContact {
        point_a: frame.point_w(&(c - radius * normal)),
        point_b: frame.point_w(&(c - d * normal)),
        normal: frame.vector_w(&normal),
        depth: radius - d,
        area: length,
    })
}
