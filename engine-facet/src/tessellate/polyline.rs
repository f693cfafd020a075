//! 2-D shapes to polylines in the x-y plane of `G`, at the same chord-deviation rule.

use super::circle::segments_for_circle;
use contact_core::Point2;
use contact_core::geometry::{Arc, Circle, Curve};

/// A polyline in the x-y plane of `G`; `closed` joins the last point to the first.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline {
    /// The points, in order of travel (the outward normal is to the right).
    pub points: Vec<Point2>,
    /// True when the last point connects back to the first.
    pub closed: bool,
}

/// A circle as a closed polygon of `n(r, δ)` vertices on the circle, counter-clockwise (so the
/// outward normal, to the right of travel for curves, is outward only after reversing: circles
/// are solids, their polygon is counter-clockwise like a solid's boundary).
pub fn circle_polyline(c: &Circle, deviation: f64) -> Polyline {
    let n = segments_for_circle(c.radius(), deviation).min(1 << 24) as usize;
    let r = c.radius();
    let points = (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            Point2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    Polyline {
        points,
        closed: true,
    }
}

/// An arc as an open polyline from angle 0 to RANGLE with `⌈n(r, δ) · RANGLE/2π⌉` (≥ 1) chords.
pub fn arc_polyline(a: &Arc, deviation: f64) -> Polyline {
    let full = segments_for_circle(a.radius(), deviation).min(1 << 24) as f64;
    let chords = ((full * a.range_angle() / std::f64::consts::TAU).ceil() as usize).max(1);
    let r = a.radius();
    let points = (0..=chords)
        .map(|k| {
            let t = a.range_angle() * k as f64 / chords as f64;
            Point2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    let closed = a.range_angle() >= std::f64::consts::TAU;
    let mut line = Polyline { points, closed };
    if closed {
        line.points.pop();
    }
    line
}

/// A B-spline curve as a polyline: each polynomial span between breakpoints is cut into chords
/// whose deviation is bounded by `|C''|max · h² / 8 ≤ deviation` (h the parameter step), with
/// `|C''|max` sampled at the span's ends and middle. An order-2 curve is its control polygon.
pub fn curve_polyline(c: &Curve, deviation: f64) -> Polyline {
    let breaks = c.breakpoints();
    let mut points = Vec::new();
    for w in breaks.windows(2) {
        let (u0, u1) = (w[0], w[1]);
        let second = [u0, 0.5 * (u0 + u1), u1]
            .iter()
            .map(|&u| c.second_derivative(u).norm())
            .fold(0.0, f64::max);
        let span = u1 - u0;
        let chords = if second > 0.0 && deviation > 0.0 {
            (span * (second / (8.0 * deviation)).sqrt())
                .ceil()
                .clamp(1.0, 1e6) as usize
        } else {
            1
        };
        for k in 0..chords {
            points.push(c.point(u0 + span * k as f64 / chords as f64));
        }
    }
    let closed = c.is_closed();
    if !closed {
        if let Some(&last) = breaks.last() {
            points.push(c.point(last));
        }
    }
    Polyline { points, closed }
}
