//! The domain between a face's parameter-space polygons triangulated: a constrained Delaunay
//! triangulation of the polygons' points with their edges as constraints, interior points on
//! a lattice where the surface curves, and the triangles inside by the even-odd rule.

use super::{Ctx, Q, uv_box};
use crate::tess::param::Metric;
use contact_core::Point2;
use spade::handles::FixedVertexHandle;
use spade::{ConstrainedDelaunayTriangulation, HasPosition, Point2 as SPoint, Triangulation};
use std::collections::{HashMap, VecDeque};

/// The most interior points one face may get.
const MAX_GRID_POINTS: usize = 400_000;

/// A triangulation vertex: its position in the scaled parameter space and mesh vertex id.
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

/// The triangles of the domain bounded by `polygons` (closed, in working parameters), as mesh
/// vertex ids. Parameters are scaled to lengths on the surface ([`Ctx::metric`] over the
/// polygons' box at chord deviation `delta`); interior points ([`grid`]) become face points.
/// The triangles run as the polygons' total signed area does (reversed when it is negative).
pub(super) fn triangles(
    ctx: &mut Ctx<'_>,
    polygons: &[Vec<Q>],
    delta: f64,
) -> Result<Vec<[u32; 3]>, String> {
    let bounds = uv_box(polygons.iter().flatten());
    let Metric { scale, step } = ctx.metric(bounds, delta);
    let mut t: ConstrainedDelaunayTriangulation<V> = ConstrainedDelaunayTriangulation::new();
    let (segments, signed_area) = boundary(&mut t, polygons, scale)?;
    grid(ctx, &mut t, &segments, bounds, scale, step)?;
    let depth = crossing_depths(&t);
    Ok(odd_triangles(&t, &depth, signed_area < 0.0))
}

/// Inserts the polygons' points, scaled by `scale` (coordinates snapped, [`snap`]; a point
/// met twice is one vertex), and their edges as constraints. Returns the edges as scaled
/// segments and twice the polygons' total signed area, Σ (xₐ y_b − x_b yₐ). Fails where a
/// constraint would cross one already there.
fn boundary(
    t: &mut ConstrainedDelaunayTriangulation<V>,
    polygons: &[Vec<Q>],
    scale: (f64, f64),
) -> Result<(Vec<(Point2, Point2)>, f64), String> {
    let to_s = |q: &Point2| SPoint::new(snap(q.x * scale.0), snap(q.y * scale.1));
    let mut at: HashMap<(u64, u64), FixedVertexHandle> = HashMap::new();
    let mut segments: Vec<(Point2, Point2)> = Vec::new();
    let mut signed_area = 0.0;
    for poly in polygons {
        let mut handles = Vec::with_capacity(poly.len());
        for q in poly {
            let s = to_s(&q.uv);
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
            let (sa, sb) = (to_s(&poly[k].uv), to_s(&poly[(k + 1) % poly.len()].uv));
            signed_area += sa.x * sb.y - sb.x * sa.y;
            segments.push((Point2::new(sa.x, sa.y), Point2::new(sb.x, sb.y)));
            let (ha, hb) = (handles[k], handles[(k + 1) % poly.len()]);
            if ha != hb && !t.exists_constraint(ha, hb) && t.try_add_constraint(ha, hb).is_empty() {
                return Err("the face's loops cross in its parameter space".into());
            }
        }
    }
    Ok((segments, signed_area))
}

/// Each inner face's depth: the fewest constraint edges crossed on a path to it from the
/// outer face (a breadth-first search from the faces on the hull, relaxed until no depth
/// falls). Inside the domain is an odd depth.
fn crossing_depths(t: &ConstrainedDelaunayTriangulation<V>) -> HashMap<usize, u32> {
    let mut depth: HashMap<usize, u32> = HashMap::with_capacity(t.num_inner_faces());
    let mut queue = VecDeque::new();
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
    depth
}

/// The inner faces of odd depth as triangles of mesh vertex ids, in the triangulation's face
/// order, reversed when `flip`; faces with a repeated id (a seam point and its copy) dropped.
fn odd_triangles(
    t: &ConstrainedDelaunayTriangulation<V>,
    depth: &HashMap<usize, u32>,
    flip: bool,
) -> Vec<[u32; 3]> {
    let faces: Vec<_> = t.inner_faces().map(|f| f.fix()).collect();
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
    out
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
    let rows = row_bands(segments, (y0, dy, ny), near);
    let mut added = 0usize;
    for (j, row) in rows.iter().enumerate() {
        let y = y0 + (j as f64 + 0.5) * dy;
        let xs = row_crossings(segments, row, y);
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

/// The segments near each lattice row: row `j` (at `y0 + (j + ½) dy`, `ny` rows) lists, in
/// order, the segments whose y range widened by `near` reaches the band of rows it spans.
fn row_bands(
    segments: &[(Point2, Point2)],
    (y0, dy, ny): (f64, f64, usize),
    near: f64,
) -> Vec<Vec<usize>> {
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
    rows
}

/// The x where the row's segments cross the line at `y`, sorted (a segment crosses when one
/// end lies at or below `y` and the other above).
fn row_crossings(segments: &[(Point2, Point2)], row: &[usize], y: f64) -> Vec<f64> {
    let mut xs: Vec<f64> = row
        .iter()
        .filter_map(|&k| {
            let (a, b) = segments[k];
            ((a.y <= y) != (b.y <= y)).then(|| a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x))
        })
        .collect();
    xs.sort_by(f64::total_cmp);
    xs
}

/// Coordinates below 1e-30 in size are zero (the triangulation refuses smaller ones).
fn snap(x: f64) -> f64 {
    if x.abs() < 1e-30 { 0.0 } else { x }
}

/// Distance from `p` to the segment `a`–`b`.
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
