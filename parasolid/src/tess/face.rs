//! One face to triangles: its loops mapped into the surface's parameter space, cut open along a
//! seam where a periodic face has no seam edge, and the domain between them triangulated by a
//! constrained Delaunay triangulation with interior grid points where the surface curves.
//!
//! Loop points are the edges' shared samples, so neighbouring faces meet vertex for vertex.
//! The triangles are oriented as the face's loops run (a loop's own direction, not the surface
//! normal, decides), so the two faces of an edge, whose fins run opposite ways, give a
//! consistently oriented mesh.

use super::param::{Metric, metric, uv, uv_near};
use crate::geom::Surface;
use contact_core::{Point2, Point3};
use spade::handles::FixedVertexHandle;
use spade::{ConstrainedDelaunayTriangulation, HasPosition, Point2 as SPoint, Triangulation};
use std::collections::HashMap;

/// The most interior points one face may get.
const MAX_GRID_POINTS: usize = 400_000;

/// A loop point: its mesh vertex id and position.
#[derive(Debug, Clone, Copy)]
pub struct LoopPoint {
    /// Mesh vertex id.
    pub id: u32,
    /// Position.
    pub p: Point3,
}

/// A face's triangles: ids below the body's shared count are shared vertices, the others are
/// this face's own points (`first_local + k` is `points[k]`).
pub struct FaceTriangles {
    /// New points of this face (seam and interior points).
    pub points: Vec<Point3>,
    /// Triangles.
    pub triangles: Vec<[u32; 3]>,
}

#[derive(Clone, Copy)]
struct V {
    pos: SPoint<f64>,
    id: u32,
}

impl HasPosition for V {
    type Scalar = f64;
    fn position(&self) -> SPoint<f64> {
        self.pos
    }
}

/// A point in working parameter space (u along the wrap direction after a swap).
#[derive(Clone, Copy)]
struct Q {
    uv: Point2,
    id: u32,
}

struct Ctx<'a> {
    surface: &'a Surface,
    swap: bool,
    first_local: u32,
    points: Vec<Point3>,
}

impl Ctx<'_> {
    fn eval(&self, q: &Point2) -> Point3 {
        if self.swap {
            self.surface.eval(q.y, q.x)
        } else {
            self.surface.eval(q.x, q.y)
        }
    }

    fn new_point(&mut self, q: &Point2) -> u32 {
        self.points.push(self.eval(q));
        self.first_local + self.points.len() as u32 - 1
    }
}

fn unwrap(prev: f64, x: f64, period: Option<f64>) -> f64 {
    match period {
        Some(p) => x - p * ((x - prev) / p).round(),
        None => x,
    }
}

/// Triangulates a face. `loops` are closed rings (first point not repeated at the end).
pub fn triangulate(
    surface: &Surface,
    loops: &[Vec<LoopPoint>],
    delta: f64,
    first_local: u32,
) -> Result<FaceTriangles, String> {
    let (pu, pv) = surface.periods();
    // Parameters, unwrapped along each loop, and each loop's winding.
    let mut rings: Vec<(Vec<Q>, i64, i64)> = Vec::new();
    for l in loops {
        let mut ring: Vec<Q> = Vec::with_capacity(l.len());
        // The previous point's parameters as found (before unwrapping), to search near.
        let mut raw: Option<(f64, f64)> = None;
        for (k, lp) in l.iter().enumerate() {
            let (mut u, mut v) = match raw {
                Some(h) => uv_near(surface, &lp.p, h),
                None => uv(surface, &lp.p),
            };
            raw = Some((u, v));
            if k > 0 {
                let last = ring[k - 1].uv;
                u = unwrap(last.x, u, pu);
                v = unwrap(last.y, v, pv);
            }
            ring.push(Q {
                uv: Point2::new(u, v),
                id: lp.id,
            });
        }
        let (first, last) = (ring[0].uv, ring[ring.len() - 1].uv);
        let close_u = unwrap(last.x, first.x, pu);
        let close_v = unwrap(last.y, first.y, pv);
        let wu = pu.map_or(0, |p| ((close_u - first.x) / p).round() as i64);
        let wv = pv.map_or(0, |p| ((close_v - first.y) / p).round() as i64);
        rings.push((ring, wu, wv));
    }
    let winds_u = rings.iter().any(|r| r.1 != 0);
    let winds_v = rings.iter().any(|r| r.2 != 0);
    if winds_u && winds_v {
        return Err("loops wind round both periodic directions".into());
    }
    let swap = winds_v;
    let period = if swap { pv } else { pu };
    let mut ctx = Ctx {
        surface,
        swap,
        first_local,
        points: Vec::new(),
    };
    let mut winding = Vec::new();
    let mut holes = Vec::new();
    for (mut ring, wu, wv) in rings {
        if swap {
            for q in &mut ring {
                q.uv = Point2::new(q.uv.y, q.uv.x);
            }
        }
        let w = if swap { wv } else { wu };
        if w != 0 {
            winding.push((ring, w))
        } else {
            holes.push(ring)
        }
    }
    let mut polygons: Vec<Vec<Q>> = Vec::new();
    match winding.len() {
        0 => polygons = holes,
        1 | 2 => {
            let p = period.ok_or("a loop winds round a direction that is not periodic")?;
            let seam_step = 0.05 * p;
            let seam_u = seam_position(&holes, p);
            polygons.push(seam_polygon(&mut ctx, &winding, p, seam_step, seam_u)?);
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
        }
        n => return Err(format!("{n} loops wind round the face")),
    }
    // Shift non-winding loops of a periodic face next to the first.
    if winding.is_empty() {
        for (k, per) in [
            (0usize, if swap { pv } else { pu }),
            (1, if swap { pu } else { pv }),
        ] {
            let Some(p) = per else { continue };
            let coord = |q: &Q| if k == 0 { q.uv.x } else { q.uv.y };
            let mean0 = polygons[0].iter().map(coord).sum::<f64>() / polygons[0].len() as f64;
            for poly in polygons.iter_mut().skip(1) {
                let mean = poly.iter().map(coord).sum::<f64>() / poly.len() as f64;
                let shift = p * ((mean - mean0) / p).round();
                for q in poly.iter_mut() {
                    if k == 0 {
                        q.uv.x -= shift
                    } else {
                        q.uv.y -= shift
                    }
                }
            }
        }
    }
    cdt(&mut ctx, &polygons, delta).map(|triangles| FaceTriangles {
        points: ctx.points,
        triangles,
    })
}

/// The domain of a face whose loops wind round the periodic direction u, as one polygon:
/// the loop winding +1 from a seam point to its copy one period on, a seam line to the other
/// loop (or to the pole), that loop back one period, and the seam's copy back to the start.
fn seam_polygon(
    ctx: &mut Ctx<'_>,
    winding: &[(Vec<Q>, i64)],
    p: f64,
    seam_step: f64,
    seam_u: Option<f64>,
) -> Result<Vec<Q>, String> {
    let (a, wa) = &winding[0];
    if wa.abs() != 1 {
        return Err(format!("a loop winds {wa} times round the face"));
    }
    let rotate = |ring: &[Q], start: usize, w: i64| -> Vec<Q> {
        // From ring[start] round to its copy one period on (unwrapped continuously).
        let n = ring.len();
        let mut out = Vec::with_capacity(n + 1);
        let mut prev = ring[start].uv.x;
        for k in 0..=n {
            let q = ring[(start + k) % n];
            let x = unwrap(prev, q.uv.x, Some(p));
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
    };
    let off = |x: f64, target: f64| (x - target - p * ((x - target) / p).round()).abs();
    // Without holes, the seam joins the closest pair of points of the two loops: the segment
    // between an annulus' boundaries at their closest approach crosses neither.
    let closest = if seam_u.is_none() && winding.len() == 2 {
        let b = &winding[1].0;
        let (su, sv) = seam_scale(ctx, a.iter().chain(b.iter()));
        let mut best = (f64::INFINITY, 0, 0);
        for (i, qa) in a.iter().enumerate() {
            for (j, qb) in b.iter().enumerate() {
                let du = off(qa.uv.x, qb.uv.x) * su;
                let dv = (qa.uv.y - qb.uv.y) * sv;
                let d = du * du + dv * dv;
                if d < best.0 {
                    best = (d, i, j);
                }
            }
        }
        Some((best.1, best.2))
    } else {
        None
    };
    let ia = match (seam_u, closest) {
        (_, Some((i, _))) => i,
        (Some(t), None) => (0..a.len())
            .min_by(|&i, &j| off(a[i].uv.x, t).total_cmp(&off(a[j].uv.x, t)))
            .unwrap_or(0),
        (None, None) => 0,
    };
    let a_run = rotate(a, ia, *wa);
    let a_end = a_run[a_run.len() - 1].uv;
    let mut poly: Vec<Q> = a_run[..a_run.len() - 1].to_vec();
    let b_run: Vec<Q> = if winding.len() == 2 {
        let (b, wb) = &winding[1];
        if *wb != -wa {
            return Err("two loops wind round the face the same way".into());
        }
        // The point of b closest to a's, or nearest the seam's u.
        let target = seam_u.unwrap_or(a_end.x);
        let ib = match closest {
            Some((_, j)) => j,
            None => (0..b.len())
                .min_by(|&i, &j| off(b[i].uv.x, target).total_cmp(&off(b[j].uv.x, target)))
                .unwrap_or(0),
        };
        let mut run = rotate(b, ib, *wb);
        let shift = p * ((run[0].uv.x - a_end.x) / p).round();
        for q in &mut run {
            q.uv.x -= shift;
        }
        run
    } else {
        // One loop: the other side is a pole, where the surface closes to a point.
        let pole_v =
            pole(ctx.surface, ctx.swap, a).ok_or("one loop winds round a face that has no pole")?;
        let pole_u = match seam_u {
            Some(t) => t - p * ((t - a_end.x) / p).round(),
            None => a_end.x,
        };
        let pole = Point2::new(pole_u, pole_v);
        let pole_id = ctx.new_point(&pole);
        vec![
            Q {
                uv: pole,
                id: pole_id,
            },
            Q {
                uv: Point2::new(a_end.x - wa.signum() as f64 * p, pole_v),
                id: pole_id,
            },
        ]
    };
    // Seam from a's end to b's start; its copy (one period back) from b's end to a's start.
    let (s0, s1) = (a_end, b_run[0].uv);
    // Through the gap between the holes: a's seam point, two points at u*, b's seam point.
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

/// Lengths per unit u and v of the surface over the points' parameter box.
fn seam_scale<'q>(ctx: &Ctx<'_>, pts: impl Iterator<Item = &'q Q>) -> (f64, f64) {
    let (mut u0, mut u1, mut v0, mut v1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for q in pts {
        u0 = u0.min(q.uv.x);
        u1 = u1.max(q.uv.x);
        v0 = v0.min(q.uv.y);
        v1 = v1.max(q.uv.y);
    }
    if ctx.swap {
        let m = metric(ctx.surface, (v0, v1, u0, u1), f64::INFINITY);
        (m.scale.1, m.scale.0)
    } else {
        metric(ctx.surface, (u0, u1, v0, v1), f64::INFINITY).scale
    }
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

trait RoundTo {
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

fn cdt(ctx: &mut Ctx<'_>, polygons: &[Vec<Q>], delta: f64) -> Result<Vec<[u32; 3]>, String> {
    let all = polygons.iter().flatten();
    let (mut u0, mut u1, mut v0, mut v1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for q in all {
        u0 = u0.min(q.uv.x);
        u1 = u1.max(q.uv.x);
        v0 = v0.min(q.uv.y);
        v1 = v1.max(q.uv.y);
    }
    let Metric { scale, step } = if ctx.swap {
        let m = metric(ctx.surface, (v0, v1, u0, u1), delta);
        Metric {
            scale: (m.scale.1, m.scale.0),
            step: (m.step.1, m.step.0),
        }
    } else {
        metric(ctx.surface, (u0, u1, v0, v1), delta)
    };
    let to_s = |q: &Point2| SPoint::new(q.x * scale.0, q.y * scale.1);
    let mut t: ConstrainedDelaunayTriangulation<V> = ConstrainedDelaunayTriangulation::new();
    let mut at: HashMap<(u64, u64), FixedVertexHandle> = HashMap::new();
    let mut segments: Vec<(Point2, Point2)> = Vec::new();
    let mut signed_area = 0.0;
    for poly in polygons {
        let mut handles = Vec::with_capacity(poly.len());
        for q in poly {
            let s = to_s(&q.uv);
            let s = SPoint::new(snap(s.x), snap(s.y));
            let key = (s.x.to_bits(), s.y.to_bits());
            let h = match at.get(&key) {
                Some(&h) => h,
                None => {
                    let h = t
                        .insert(V { pos: s, id: q.id })
                        .map_err(|e| format!("{e:?}"))?;
                    at.insert(key, h);
                    h
                }
            };
            handles.push(h);
        }
        for k in 0..poly.len() {
            let (a, b) = (poly[k].uv, poly[(k + 1) % poly.len()].uv);
            let (sa, sb) = (to_s(&a), to_s(&b));
            let (sa, sb) = (
                SPoint::new(snap(sa.x), snap(sa.y)),
                SPoint::new(snap(sb.x), snap(sb.y)),
            );
            signed_area += sa.x * sb.y - sb.x * sa.y;
            segments.push((Point2::new(sa.x, sa.y), Point2::new(sb.x, sb.y)));
            let (ha, hb) = (handles[k], handles[(k + 1) % poly.len()]);
            if ha != hb && !t.exists_constraint(ha, hb) && t.try_add_constraint(ha, hb).is_empty() {
                return Err("the face's loops cross in its parameter space".into());
            }
        }
    }
    grid(ctx, &mut t, &segments, (u0, u1, v0, v1), scale, step)?;
    // Inside: an odd number of boundary crossings from the outside.
    let faces: Vec<_> = t.inner_faces().map(|f| f.fix()).collect();
    let mut depth: HashMap<usize, u32> = HashMap::with_capacity(faces.len());
    let mut queue = std::collections::VecDeque::new();
    for f in t.inner_faces() {
        for e in f.adjacent_edges() {
            if e.rev().face().is_outer() {
                let d = u32::from(t.is_constraint_edge(e.as_undirected().fix()));
                let entry = depth.entry(f.fix().index()).or_insert(d);
                if d < *entry {
                    *entry = d;
                }
                queue.push_back(f.fix());
            }
        }
    }
    while let Some(fh) = queue.pop_front() {
        let f = t.face(fh);
        let d = depth[&fh.index()];
        for e in f.adjacent_edges() {
            let Some(g) = e.rev().face().as_inner() else {
                continue;
            };
            let dg = d + u32::from(t.is_constraint_edge(e.as_undirected().fix()));
            let known = depth.get(&g.fix().index()).copied();
            if known.is_none_or(|k| dg < k) {
                depth.insert(g.fix().index(), dg);
                queue.push_back(g.fix());
            }
        }
    }
    let flip = signed_area < 0.0;
    let mut out = Vec::new();
    for fh in faces {
        if depth.get(&fh.index()).is_some_and(|d| d % 2 == 1) {
            let [a, b, c] = t.face(fh).vertices().map(|v| v.data().id);
            if a == b || b == c || a == c {
                continue;
            }
            out.push(if flip { [a, c, b] } else { [a, b, c] });
        }
    }
    Ok(out)
}

/// Interior points on a lattice in the scaled parameter space, inside the domain (even-odd
/// rule along each lattice row) and not closer than a quarter step to its boundary.
fn grid(
    ctx: &mut Ctx<'_>,
    t: &mut ConstrainedDelaunayTriangulation<V>,
    segments: &[(Point2, Point2)],
    (u0, u1, v0, v1): (f64, f64, f64, f64),
    scale: (f64, f64),
    step: (Option<f64>, Option<f64>),
) -> Result<(), String> {
    let (su, sv) = match step {
        (None, None) => return Ok(()),
        (Some(a), None) => (a * scale.0, 3.0 * a * scale.0),
        (None, Some(b)) => (3.0 * b * scale.1, b * scale.1),
        (Some(a), Some(b)) => (a * scale.0, b * scale.1),
    };
    let (x0, x1, y0, y1) = (u0 * scale.0, u1 * scale.0, v0 * scale.1, v1 * scale.1);
    let nx = ((x1 - x0) / su).ceil() as usize;
    let ny = ((y1 - y0) / sv).ceil() as usize;
    if nx < 2 && ny < 2 {
        return Ok(());
    }
    if nx.saturating_mul(ny) > 4 * MAX_GRID_POINTS {
        return Err(format!("{nx} × {ny} interior points are too many"));
    }
    let (dx, dy) = ((x1 - x0) / nx.max(1) as f64, (y1 - y0) / ny.max(1) as f64);
    let near = 0.25 * dx.min(dy);
    // Segments by lattice row band (expanded by `near`).
    let mut rows: Vec<Vec<usize>> = vec![Vec::new(); ny];
    for (k, (a, b)) in segments.iter().enumerate() {
        let lo = ((a.y.min(b.y) - near - y0) / dy - 0.5).floor().max(0.0) as usize;
        let hi = ((a.y.max(b.y) + near - y0) / dy - 0.5).ceil().max(0.0) as usize;
        for row in rows
            .iter_mut()
            .take(hi.min(ny.saturating_sub(1)) + 1)
            .skip(lo)
        {
            row.push(k);
        }
    }
    let mut added = 0usize;
    for (j, row) in rows.iter().enumerate() {
        let y = y0 + (j as f64 + 0.5) * dy;
        let mut xs: Vec<f64> = row
            .iter()
            .filter_map(|&k| {
                let (a, b) = segments[k];
                ((a.y <= y) != (b.y <= y)).then(|| a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x))
            })
            .collect();
        xs.sort_by(f64::total_cmp);
        for i in 0..nx {
            let x = x0 + (i as f64 + 0.5) * dx;
            if xs.partition_point(|&c| c < x) % 2 == 0 {
                continue;
            }
            let p = Point2::new(x, y);
            if row
                .iter()
                .any(|&k| seg_dist(&p, &segments[k].0, &segments[k].1) < near)
            {
                continue;
            }
            let q = Point2::new(x / scale.0, y / scale.1);
            let id = ctx.new_point(&q);
            t.insert(V {
                pos: SPoint::new(x, y),
                id,
            })
            .map_err(|e| format!("{e:?}"))?;
            added += 1;
            if added > MAX_GRID_POINTS {
                return Err("too many interior points".into());
            }
        }
    }
    Ok(())
}

/// Coordinates below 1e-30 in size are zero (the triangulation refuses smaller ones).
fn snap(x: f64) -> f64 {
    if x.abs() < 1e-30 { 0.0 } else { x }
}

fn seg_dist(p: &Point2, a: &Point2, b: &Point2) -> f64 {
    let ab = b - a;
    let l2 = ab.norm_squared();
    let s = if l2 > 0.0 {
        ((p - a).dot(&ab) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * s)).norm()
}
