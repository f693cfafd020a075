//! A face whose loops wind round its periodic direction u (a cylinder's band, a cone or sphere
//! cap, a torus strip without a seam edge) cut open along a seam into one polygon of the
//! parameter plane, with its holes moved next to it.

use super::{Ctx, Q, Winding, uv_box};
use crate::geom::Surface;
use contact_core::Point2;

/// The polygons of a face whose loops `winding` wind round the period `p` of working u: the
/// seam polygon ([`seam_polygon`], its seam placed clear of the holes by [`seam_position`],
/// points on it every 0.05 p) and the holes, each shifted by whole periods so that its
/// smallest u lies in the period after the seam polygon's smallest u.
pub(super) fn cut_open(
    ctx: &mut Ctx<'_>,
    winding: &[Winding],
    holes: Vec<Vec<Q>>,
    p: f64,
) -> Result<Vec<Vec<Q>>, String> {
    let seam_step = 0.05 * p;
    let seam_u = seam_position(&holes, p);
    let mut polygons = vec![seam_polygon(ctx, winding, p, seam_step, seam_u)?];
    let left = polygons[0]
        .iter()
        .map(|q| q.uv.x)
        .fold(f64::INFINITY, f64::min);
    for mut h in holes {
        let lo = h.iter().map(|q| q.uv.x).fold(f64::INFINITY, f64::min);
        let shift = p * ((lo - left) / p).floor();
        for q in &mut h {
            q.uv.x -= shift;
        }
        polygons.push(h);
    }
    Ok(polygons)
}

/// The domain of a face whose loops wind round the periodic direction u, as one polygon:
/// the loop winding +1 from a seam point to its copy one period on, a seam line to the other
/// loop (or to the pole), that loop back one period, and the seam's copy back to the start.
/// The seam leaves the first loop at the point nearest the seam's u `seam_u` (the closest
/// pair of points of the two loops without holes, the loop's first point without either) and
/// has points every `seam_step` or less.
fn seam_polygon(
    ctx: &mut Ctx<'_>,
    winding: &[Winding],
    p: f64,
    seam_step: f64,
    seam_u: Option<f64>,
) -> Result<Vec<Q>, String> {
    let (a, wa) = &winding[0];
    if wa.abs() != 1 {
        return Err(format!("a loop winds {wa} times round the face"));
    }
    // Without holes, the seam joins the closest pair of points of the two loops: the segment
    // between an annulus' boundaries at their closest approach crosses neither.
    let closest = if seam_u.is_none() && winding.len() == 2 {
        Some(closest_pair(ctx, a, &winding[1].0, p))
    } else {
        None
    };
    let ia = match (seam_u, closest) {
        (_, Some((i, _))) => i,
        (Some(t), None) => nearest_u(a, t, p),
        (None, None) => 0,
    };
    let a_run = rotate(a, ia, *wa, p);
    let a_end = a_run[a_run.len() - 1].uv;
    let b_run = if winding.len() == 2 {
        let ib = closest.map(|(_, j)| j);
        second_run(&winding[1], *wa, a_end, seam_u, ib, p)?
    } else {
        pole_run(ctx, a, *wa, a_end, seam_u, p)?
    };
    let seam = seam_points(ctx, a_end, b_run[0].uv, seam_u, p, seam_step);
    let mut poly: Vec<Q> = a_run[..a_run.len() - 1].to_vec();
    poly.push(Q {
        uv: a_end,
        id: a_run[a_run.len() - 1].id,
    });
    poly.extend(seam.iter().map(|&(q, id)| Q { uv: q, id }));
    poly.extend(b_run[..b_run.len() - 1].iter().copied());
    let b_last = b_run[b_run.len() - 1];
    poly.push(b_last);
    let back = (b_run[0].uv.x - b_last.uv.x).round_to(p);
    poly.extend(seam.iter().rev().map(|&(q, id)| Q {
        uv: Point2::new(q.x - back, q.y),
        id,
    }));
    Ok(poly)
}

/// The ring from `ring[start]` round to its copy `w` periods on (unwrapped continuously),
/// `n + 1` points, the last set exactly to the first's u plus `w·p`.
fn rotate(ring: &[Q], start: usize, w: i64, p: f64) -> Vec<Q> {
    let n = ring.len();
    let mut out = Vec::with_capacity(n + 1);
    let mut prev = ring[start].uv.x;
    for k in 0..=n {
        let q = ring[(start + k) % n];
        let x = super::unwrap(prev, q.uv.x, Some(p));
        prev = x;
        out.push(Q {
            uv: Point2::new(x, q.uv.y),
            id: q.id,
        });
    }
    let target = out[0].uv.x + w as f64 * p;
    let last = out.len() - 1;
    out[last].uv.x = target;
    out
}

/// The distance in u from `x` to the nearest copy of `target`, `|x − t − p·round((x − t)/p)|`.
fn off(x: f64, target: f64, p: f64) -> f64 {
    (x - target - p * ((x - target) / p).round()).abs()
}

/// The index of the ring's point whose u is nearest a copy of `target` (0 for an empty ring).
fn nearest_u(ring: &[Q], target: f64, p: f64) -> usize {
    (0..ring.len())
        .min_by(|&i, &j| off(ring[i].uv.x, target, p).total_cmp(&off(ring[j].uv.x, target, p)))
        .unwrap_or(0)
}

/// The indices of the closest pair of points of loops `a` and `b`, in lengths on the surface
/// ([`seam_scale`]) with u distances taken to the nearest copy; the first such pair.
fn closest_pair(ctx: &Ctx<'_>, a: &[Q], b: &[Q], p: f64) -> (usize, usize) {
    let (su, sv) = seam_scale(ctx, a.iter().chain(b.iter()));
    let mut best = (f64::INFINITY, 0, 0);
    for (i, qa) in a.iter().enumerate() {
        for (j, qb) in b.iter().enumerate() {
            let du = off(qa.uv.x, qb.uv.x, p) * su;
            let dv = (qa.uv.y - qb.uv.y) * sv;
            let d = du * du + dv * dv;
            if d < best.0 {
                best = (d, i, j);
            }
        }
    }
    (best.1, best.2)
}

/// The second winding loop `(b, wb)` as the seam polygon's other side: from its point `ib`
/// (else the one nearest the seam's u, else nearest `a_end`'s u) round one period, shifted by
/// whole periods to start within half a period of `a_end`. The loops must wind opposite ways.
fn second_run(
    (b, wb): &Winding,
    wa: i64,
    a_end: Point2,
    seam_u: Option<f64>,
    ib: Option<usize>,
    p: f64,
) -> Result<Vec<Q>, String> {
    if *wb != -wa {
        return Err("two loops wind round the face the same way".into());
    }
    // The point of b closest to a's, or nearest the seam's u.
    let target = seam_u.unwrap_or(a_end.x);
    let ib = ib.unwrap_or_else(|| nearest_u(b, target, p));
    let mut run = rotate(b, ib, *wb, p);
    let shift = p * ((run[0].uv.x - a_end.x) / p).round();
    for q in &mut run {
        q.uv.x -= shift;
    }
    Ok(run)
}

/// The seam polygon's other side where one loop `a` winds round the face: the pole the
/// surface closes to, as a new face point, at the seam's u (else `a_end`'s) and one period
/// back, against the loop's winding `wa`.
fn pole_run(
    ctx: &mut Ctx<'_>,
    a: &[Q],
    wa: i64,
    a_end: Point2,
    seam_u: Option<f64>,
    p: f64,
) -> Result<Vec<Q>, String> {
    let pole_v =
        pole(ctx.surface, ctx.swap, a).ok_or("one loop winds round a face that has no pole")?;
    let pole_u = match seam_u {
        Some(t) => t - p * ((t - a_end.x) / p).round(),
        None => a_end.x,
    };
    let pole = Point2::new(pole_u, pole_v);
    let pole_id = ctx.new_point(&pole);
    Ok(vec![
        Q {
            uv: pole,
            id: pole_id,
        },
        Q {
            uv: Point2::new(a_end.x - wa.signum() as f64 * p, pole_v),
            id: pole_id,
        },
    ])
}

/// The seam's inner points from `s0` to `s1`, new face points with their working parameters:
/// with a seam u, through the gap between the holes (`s0`, two points at u* a quarter and
/// three quarters of the way in v, `s1`), each straight piece cut into steps of at most
/// `seam_step`.
fn seam_points(
    ctx: &mut Ctx<'_>,
    s0: Point2,
    s1: Point2,
    seam_u: Option<f64>,
    p: f64,
    seam_step: f64,
) -> Vec<(Point2, u32)> {
    let mut path = vec![s0];
    if let Some(t) = seam_u {
        let t = t - p * ((t - s0.x) / p).round();
        path.push(Point2::new(t, s0.y + 0.25 * (s1.y - s0.y)));
        path.push(Point2::new(t, s0.y + 0.75 * (s1.y - s0.y)));
    }
    path.push(s1);
    let mut seam: Vec<(Point2, u32)> = Vec::new();
    for (k, w) in path.windows(2).enumerate() {
        let m = (((w[1] - w[0]).norm() / seam_step).ceil() as usize).max(1);
        if k > 0 {
            seam.push((w[0], ctx.new_point(&w[0])));
        }
        for i in 1..m {
            let q = w[0] + (w[1] - w[0]) * (i as f64 / m as f64);
            seam.push((q, ctx.new_point(&q)));
        }
    }
    seam
}

/// Lengths per unit u and v of the surface over the points' parameter box.
fn seam_scale<'q>(ctx: &Ctx<'_>, pts: impl Iterator<Item = &'q Q>) -> (f64, f64) {
    ctx.metric(uv_box(pts), f64::INFINITY).scale
}

/// Where a seam should cut a periodic face so that no hole straddles it: the middle of the
/// widest gap between the holes' u ranges (`None` without holes).
fn seam_position(holes: &[Vec<Q>], p: f64) -> Option<f64> {
    if holes.is_empty() {
        return None;
    }
    let mut spans: Vec<(f64, f64)> = holes
        .iter()
        .map(|h| {
            let lo = h.iter().map(|q| q.uv.x).fold(f64::INFINITY, f64::min);
            let hi = h.iter().map(|q| q.uv.x).fold(f64::NEG_INFINITY, f64::max);
            let start = lo.rem_euclid(p);
            (start, start + (hi - lo))
        })
        .collect();
    spans.sort_by(|a, b| a.0.total_cmp(&b.0));
    // Merge, then the widest gap (including the one wrapping past the period).
    let mut merged: Vec<(f64, f64)> = Vec::new();
    for s in spans {
        match merged.last_mut() {
            Some(m) if s.0 <= m.1 => m.1 = m.1.max(s.1),
            _ => merged.push(s),
        }
    }
    let mut best = (f64::NEG_INFINITY, 0.0);
    for k in 0..merged.len() {
        let end = merged[k].1;
        let next = if k + 1 < merged.len() {
            merged[k + 1].0
        } else {
            merged[0].0 + p
        };
        if next - end > best.0 {
            best = (next - end, 0.5 * (end + next));
        }
    }
    Some(best.1)
}

/// Rounding to a whole multiple.
trait RoundTo {
    /// The multiple of `p` nearest `self`, `p·round(self/p)`.
    fn round_to(self, p: f64) -> f64;
}

impl RoundTo for f64 {
    fn round_to(self, p: f64) -> f64 {
        p * (self / p).round()
    }
}

/// The v of the pole a loop's face closes to (sphere poles, a cone's apex).
fn pole(s: &Surface, swap: bool, ring: &[Q]) -> Option<f64> {
    if swap {
        return None;
    }
    let mean_v = ring.iter().map(|q| q.uv.y).sum::<f64>() / ring.len() as f64;
    match s {
        Surface::Sphere { .. } => Some(std::f64::consts::FRAC_PI_2.copysign(mean_v)),
        Surface::Cone { r, tan, .. } if *tan != 0.0 => Some(-r / tan),
        _ => None,
    }
}
