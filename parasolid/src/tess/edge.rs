//! Edges to polylines: sampled once per body, so the two faces of an edge share its points and
//! the mesh closes.
//!
//! Circles and ellipses are cut into equal-angle chords, `n = ⌈Δt / (2 acos(1 − δ/r))⌉` for the
//! larger radius r (a chord of angle θ deviates `r (1 − cos θ/2)`); B-spline and surface curves
//! are split at their knots and halved until each chord's midpoint and quarter points lie
//! within δ of the chord; intersection curves keep their stored points, with points added at
//! chord midpoints (projected back onto both surfaces) where a chord deviates more than δ.

use super::param::{uv, uv_near};
use crate::brep::Edge;
use crate::geom::{Curve, Surface};
use contact_core::Point3;
use std::f64::consts::TAU;

/// The most halvings of one span of a sampled curve.
const MAX_DEPTH: u32 = 14;

/// Distance from `p` to the segment `a`–`b`.
pub fn segment_distance(p: &Point3, a: &Point3, b: &Point3) -> f64 {
    let ab = b - a;
    let l2 = ab.norm_squared();
    let t = if l2 > 0.0 {
        ((p - a).dot(&ab) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * t)).norm()
}

/// The parameter range of a closed curve that is not a circle or ellipse (a closed
/// intersection curve or B-curve).
fn closed_period(c: &Curve) -> Option<(f64, f64)> {
    if c.is_periodic() {
        None
    } else {
        c.closed_range()
    }
}

/// The parameters at which an edge starts and ends, in the edge's direction.
fn end_parameters(edge: &Edge, vertices: &[Point3]) -> Option<(f64, f64)> {
    let c = &edge.curve;
    let sign = if edge.with_curve { 1.0 } else { -1.0 };
    match (edge.start, edge.end) {
        (Some(s), Some(e)) => {
            let t0 = c.closest(&vertices[s]);
            let mut t1 = c.closest(&vertices[e]);
            if c.is_periodic() {
                if s == e || (vertices[s] - vertices[e]).norm() == 0.0 {
                    t1 = t0 + sign * TAU;
                } else {
                    while sign * (t1 - t0) <= 0.0 {
                        t1 += sign * TAU;
                    }
                    while sign * (t1 - t0) > TAU {
                        t1 -= sign * TAU;
                    }
                    // Vertices of a tolerant edge may lie off its circle by more than they lie
                    // apart: an arc that would leave a gap under a thousandth of a radian is
                    // the short arc between near-coincident vertices, not a near-full circle.
                    if TAU - sign * (t1 - t0) < 1e-3 {
                        t1 -= sign * TAU;
                    }
                }
            }
            if let Some((lo, hi)) = closed_period(c) {
                // An edge across a closed curve's start runs on past its end.
                if sign * (t1 - t0) <= 0.0 {
                    t1 += sign * (hi - lo);
                }
            }
            Some((t0, t1))
        }
        (None, None) => {
            let (a, b) = c.range()?;
            Some(if edge.with_curve { (a, b) } else { (b, a) })
        }
        _ => None,
    }
}

/// Samples an edge from its start to its end with chord deviation at most `delta`. Ends are
/// the exact vertex positions; a ring edge starts and ends at the same point (repeated).
/// Intersection curves get points added where chords stray from both surfaces
/// (`refine_on_surfaces`), and points closer than δ/1000 to the one before or to the end
/// are dropped (`drop_close`).
pub fn sample(edge: &Edge, vertices: &[Point3], delta: f64) -> Option<Vec<Point3>> {
    let (t0, t1) = end_parameters(edge, vertices)?;
    let c = &edge.curve;
    let mut ts = match c {
        Curve::Line { .. } => vec![t0, t1],
        Curve::Ellipse { a, b, .. } => {
            let ring = edge.start.is_none() || edge.start == edge.end;
            ellipse_parameters(a.max(*b), ring, t0, t1, delta)
        }
        Curve::Polyline(p) => polyline_parameters(p.len(), t0, t1),
        _ => spline_parameters(c, t0, t1, delta),
    };
    if ts.len() < 2 {
        ts = vec![t0, t1];
    }
    let mut pts: Vec<Point3> = ts.iter().map(|&t| c.eval_wrapped(t)).collect();
    if let (Some(s), Some(e)) = (edge.start, edge.end) {
        pts[0] = vertices[s];
        let last = pts.len() - 1;
        pts[last] = vertices[e];
    } else {
        let last = pts.len() - 1;
        pts[last] = pts[0];
    }
    if let (Curve::Polyline(_), Some(surfaces), true) =
        (c, edge.surfaces.as_deref(), delta.is_finite())
    {
        pts = refine_on_surfaces(&pts, surfaces, delta);
    }
    Some(drop_close(&pts, delta))
}

/// Equal-angle parameters from `t0` to `t1` on a circle or ellipse of larger radius `r`:
/// `n = ⌈|t1 − t0| / θ⌉` steps with `θ = 2 acos(1 − δ/r)` (a third of a turn when δ ≥ r), at
/// least one, and at least three on a `ring` edge (one that closes on itself).
fn ellipse_parameters(r: f64, ring: bool, t0: f64, t1: f64, delta: f64) -> Vec<f64> {
    let step = if delta >= r {
        TAU / 3.0
    } else {
        2.0 * (1.0 - delta / r).acos()
    };
    let n = ((t1 - t0).abs() / step).ceil().max(1.0) as usize;
    let n = if ring { n.max(3) } else { n };
    (0..=n)
        .map(|i| t0 + (t1 - t0) * i as f64 / n as f64)
        .collect()
}

/// The parameters from `t0` to `t1` on a polyline of `len` stored points: the ends and every
/// stored point's parameter strictly between them (the integers, and their copies one
/// closed range on either side, for a run across a closed polyline's start), in order.
fn polyline_parameters(len: usize, t0: f64, t1: f64) -> Vec<f64> {
    let mut ts = vec![t0];
    let (lo, hi) = (t0.min(t1), t0.max(t1));
    let inner: Vec<f64> = (0..len)
        .map(|i| i as f64)
        .chain((1..len).map(|i| (i + len - 1) as f64))
        .chain((0..len - 1).map(|i| i as f64 - (len - 1) as f64))
        .filter(|&k| k > lo + 1e-9 && k < hi - 1e-9)
        .collect();
    let mut inner = inner;
    inner.sort_by(f64::total_cmp);
    inner.dedup();
    if t1 > t0 {
        ts.extend(inner);
    } else {
        ts.extend(inner.into_iter().rev());
    }
    ts.push(t1);
    ts
}

/// The parameters from `t0` to `t1` on a B-spline, surface or other curve: its knots between
/// the ends, each span cut in four, and each piece halved ([`refine`]) until its chord
/// deviates at most δ.
fn spline_parameters(c: &Curve, t0: f64, t1: f64, delta: f64) -> Vec<f64> {
    let mut breaks: Vec<f64> = match c {
        Curve::Nurbs(n) => n.breaks(),
        Curve::OnSurface { uv, .. } => uv.breaks(),
        Curve::Trimmed { basis, .. } => match basis.as_ref() {
            Curve::Nurbs(n) => n.breaks(),
            Curve::OnSurface { uv, .. } => uv.breaks(),
            _ => Vec::new(),
        },
        _ => Vec::new(),
    };
    let (lo, hi) = (t0.min(t1), t0.max(t1));
    breaks.retain(|&k| k > lo && k < hi);
    let mut ts = vec![lo];
    ts.extend(breaks);
    ts.push(hi);
    let coarse: Vec<f64> = ts
        .windows(2)
        .flat_map(|w| (0..4).map(move |i| w[0] + (w[1] - w[0]) * i as f64 / 4.0))
        .chain(std::iter::once(hi))
        .collect();
    let mut out = vec![coarse[0]];
    for w in coarse.windows(2) {
        refine(c, w[0], w[1], delta, 0, &mut out);
    }
    if t1 < t0 {
        out.reverse();
    }
    out
}

/// The points without those closer than δ/1000 to the last one kept or to the end point,
/// which add nothing but slivers; the first and last points always stay.
fn drop_close(pts: &[Point3], delta: f64) -> Vec<Point3> {
    let last = pts[pts.len() - 1];
    let n = pts.len();
    let mut kept = vec![pts[0]];
    for (k, p) in pts.iter().enumerate().skip(1) {
        let keep = k == n - 1
            || ((p - kept[kept.len() - 1]).norm() > 1e-3 * delta
                && (p - last).norm() > 1e-3 * delta);
        if keep {
            kept.push(*p);
        }
    }
    kept
}

/// The point of both surfaces nearest `p`: alternating projections onto each (exact for
/// analytic surfaces), which converge to the intersection where the surfaces cross.
fn onto_both(p: &Point3, (s1, s2): &(Surface, Surface)) -> Point3 {
    let mut q = *p;
    let (mut h1, mut h2) = (None, None);
    for _ in 0..40 {
        let a = project(s1, &q, &mut h1);
        let b = project(s2, &a, &mut h2);
        let done = (b - q).norm() < 1e-12;
        q = b;
        if done {
            break;
        }
    }
    q
}

/// The foot of `p` on `s`, searched near `hint` (the last foot's parameters), which it sets.
fn project(s: &Surface, p: &Point3, hint: &mut Option<(f64, f64)>) -> Point3 {
    let (u, v) = match *hint {
        Some(h) => uv_near(s, p, h),
        None => uv(s, p),
    };
    *hint = Some((u, v));
    s.eval(u, v)
}

/// Stored intersection points with points added on both surfaces where a chord's midpoint
/// deviates from the curve by more than δ.
fn refine_on_surfaces(pts: &[Point3], surfaces: &(Surface, Surface), delta: f64) -> Vec<Point3> {
    fn split(
        a: Point3,
        b: Point3,
        s: &(Surface, Surface),
        delta: f64,
        depth: u32,
        out: &mut Vec<Point3>,
    ) {
        let m = onto_both(&nalgebra_mid(&a, &b), s);
        let dev = segment_distance(&m, &a, &b);
        // A midpoint that lands far from the chord is another branch: keep the chord.
        if dev > delta && dev < (b - a).norm() && depth < MAX_DEPTH {
            split(a, m, s, delta, depth + 1, out);
            split(m, b, s, delta, depth + 1, out);
        } else {
            out.push(b);
        }
    }
    let mut out = vec![pts[0]];
    for w in pts.windows(2) {
        split(w[0], w[1], surfaces, delta, 0, &mut out);
    }
    out
}

fn nalgebra_mid(a: &Point3, b: &Point3) -> Point3 {
    Point3::from((a.coords + b.coords) * 0.5)
}

/// Appends the parameters after `a` up to `b`, halving while a chord deviates more than δ.
fn refine(c: &Curve, a: f64, b: f64, delta: f64, depth: u32, out: &mut Vec<f64>) {
    let (pa, pb) = (c.eval_wrapped(a), c.eval_wrapped(b));
    let dev = [0.25, 0.5, 0.75]
        .iter()
        .map(|f| segment_distance(&c.eval_wrapped(a + (b - a) * f), &pa, &pb))
        .fold(0.0, f64::max);
    if dev > delta && depth < MAX_DEPTH {
        let m = 0.5 * (a + b);
        refine(c, a, m, delta, depth + 1, out);
        refine(c, m, b, delta, depth + 1, out);
    } else {
        out.push(b);
    }
}
