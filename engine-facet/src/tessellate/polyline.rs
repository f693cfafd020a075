//! 2-D shapes to polylines in the x-y plane of `G`, at the same chord-deviation rule.

use super::circle::segments_for_circle;
use contact_core::geometry::{Arc, Circle, Curve};
use contact_core::{Point2, Vector2};

/// A polyline in the x-y plane of `G`; `closed` joins the last point to the first.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline {
    /// The points, in order of travel (the outward normal is to the right).
    pub points: Vec<Point2>,
    /// The true outward unit normal of the shape at each point (`tangent × z`: to the right of
    /// travel; radial for circles and arcs), so contact normals can be interpolated along a
    /// chord instead of jumping from chord to chord.
    pub normals: Vec<Vector2>,
    /// True when the last point connects back to the first.
    pub closed: bool,
}

/// A circle as a closed polygon of `n(r, δ)` vertices on the circle, counter-clockwise (so the
/// outward normal, to the right of travel for curves, is outward only after reversing: circles
/// are solids, their polygon is counter-clockwise like a solid's boundary).
pub fn circle_polyline(c: &Circle, deviation: f64) -> Polyline {
    let n = segments_for_circle(c.radius(), deviation).min(1 << 24) as usize;
    let r = c.radius();
    let normals: Vec<Vector2> = (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            Vector2::new(t.cos(), t.sin())
        })
        .collect();
    Polyline {
        points: normals.iter().map(|u| Point2::from(r * u)).collect(),
        normals,
        closed: true,
    }
}

/// An arc as an open polyline from angle 0 to RANGLE with `⌈n(r, δ) · RANGLE/2π⌉` (≥ 1) chords.
pub fn arc_polyline(a: &Arc, deviation: f64) -> Polyline {
    let full = segments_for_circle(a.radius(), deviation).min(1 << 24) as f64;
    let chords = ((full * a.range_angle() / std::f64::consts::TAU).ceil() as usize).max(1);
    let r = a.radius();
    let normals: Vec<Vector2> = (0..=chords)
        .map(|k| {
            let t = a.range_angle() * k as f64 / chords as f64;
            Vector2::new(t.cos(), t.sin())
        })
        .collect();
    let closed = a.range_angle() >= std::f64::consts::TAU;
    let mut line = Polyline {
        points: normals.iter().map(|u| Point2::from(r * u)).collect(),
        normals,
        closed,
    };
    if closed {
        line.points.pop();
        line.normals.pop();
    }
    line
}

/// A B-spline curve as a polyline: each polynomial span between breakpoints is cut into chords
/// whose deviation is bounded by `|C''|max · h² / 8 ≤ deviation` (h the parameter step), with
/// `|C''|max` sampled at the span's ends and middle. An order-2 curve is its control polygon.
pub fn curve_polyline(c: &Curve, deviation: f64) -> Polyline {
    let breaks = c.breakpoints();
    let mut params = Vec::new();
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
            params.push(u0 + span * k as f64 / chords as f64);
        }
    }
    let closed = c.is_closed();
    if !closed {
        if let Some(&last) = breaks.last() {
            params.push(last);
        }
    }
    Polyline {
        points: params.iter().map(|&u| c.point(u)).collect(),
        normals: params.iter().map(|&u| curve_normal(c, u)).collect(),
        closed,
    }
}

/// The outward normal at `u`; at a cusp (zero derivative, from repeated control points) the
/// limit direction of the tangent there, along the second derivative.
fn curve_normal(c: &Curve, u: f64) -> Vector2 {
    c.normal(u).unwrap_or_else(|| {
        let t = c.second_derivative(u);
        Vector2::new(t.y, -t.x)
            .try_normalize(0.0)
            .unwrap_or_else(Vector2::y)
    })
}
