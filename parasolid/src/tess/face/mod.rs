//! One face to triangles: its loops mapped into the surface's parameter space, cut open along a
//! seam where a periodic face has no seam edge, and the domain between them triangulated by a
//! constrained Delaunay triangulation with interior grid points where the surface curves.
//!
//! Loop points are the edges' shared samples, so neighbouring faces meet vertex for vertex.
//! The triangles are oriented as the face's loops run (a loop's own direction, not the surface
//! normal, decides), so the two faces of an edge, whose fins run opposite ways, give a
//! consistently oriented mesh.
//!
//! This module maps the loops and sorts them; `seam` cuts a face whose loops wind round it
//! open into one polygon, and `domain` triangulates the polygons.

mod domain;
mod seam;

use super::param::{Metric, metric, uv, uv_near};
use crate::geom::Surface;
use contact_core::{Point2, Point3};

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

/// A point in working parameter space (u along the wrap direction after a swap).
#[derive(Clone, Copy)]
struct Q {
    uv: Point2,
    id: u32,
}

/// What one face's triangulation works with: the surface, whether its parameters are swapped
/// (so that u is the direction the loops wind round), and the face's own new points.
struct Ctx<'a> {
    surface: &'a Surface,
    swap: bool,
    first_local: u32,
    points: Vec<Point3>,
}

impl Ctx<'_> {
    /// The surface point at working parameters `q` (swapped back to the surface's own order).
    fn eval(&self, q: &Point2) -> Point3 {
        if self.swap {
            self.surface.eval(q.y, q.x)
        } else {
            self.surface.eval(q.x, q.y)
        }
    }

    /// Adds the surface point at working parameters `q` as a face point; its mesh vertex id.
    fn new_point(&mut self, q: &Point2) -> u32 {
        self.points.push(self.eval(q));
        self.first_local + self.points.len() as u32 - 1
    }

    /// The metric of the working parameter box `(u0, u1, v0, v1)` at chord deviation `delta`,
    /// with scale and step in working order (swapped back when the parameters are swapped).
    fn metric(&self, (u0, u1, v0, v1): (f64, f64, f64, f64), delta: f64) -> Metric {
        if self.swap {
            let m = metric(self.surface, (v0, v1, u0, u1), delta);
            Metric {
                scale: (m.scale.1, m.scale.0),
                step: (m.step.1, m.step.0),
            }
        } else {
            metric(self.surface, (u0, u1, v0, v1), delta)
        }
    }
}

/// The parameter box `(u0, u1, v0, v1)` of the points (infinite and inverted without points).
fn uv_box<'q>(pts: impl Iterator<Item = &'q Q>) -> (f64, f64, f64, f64) {
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
    (u0, u1, v0, v1)
}

/// `x` moved by whole periods to within half a period of `prev` (`x` itself when the
/// direction is not periodic): `x − p·round((x − prev)/p)`.
fn unwrap(prev: f64, x: f64, period: Option<f64>) -> f64 {
    match period {
        Some(p) => x - p * ((x - prev) / p).round(),
        None => x,
    }
}

/// A loop that winds round the working u direction and the number of periods it winds.
type Winding = (Vec<Q>, i64);

/// A loop in parameter space, unwrapped continuously from its first point, and the number of
/// periods it winds round u and round v (0 in a direction that is not periodic).
struct Ring {
    points: Vec<Q>,
    wu: i64,
    wv: i64,
}

/// Triangulates a face. `loops` are closed rings (first point not repeated at the end).
pub fn triangulate(
    surface: &Surface,
    loops: &[Vec<LoopPoint>],
    delta: f64,
    first_local: u32,
) -> Result<FaceTriangles, FaceFailure> {
    let (pu, pv) = surface.periods();
    let rings: Vec<Ring> = loops.iter().map(|l| ring(surface, l, (pu, pv))).collect();
    off_surface(surface, loops, &rings, delta)?;
    let winds_u = rings.iter().any(|r| r.wu != 0);
    let winds_v = rings.iter().any(|r| r.wv != 0);
    if winds_u && winds_v {
        return Err("loops wind round both periodic directions".into());
    }
    let swap = winds_v;
    let periods = if swap { (pv, pu) } else { (pu, pv) };
    let mut ctx = Ctx {
        surface,
        swap,
        first_local,
        points: Vec::new(),
    };
    let (winding, holes) = sort_rings(rings, swap);
    let polygons = match winding.len() {
        0 => {
            let mut polygons = holes;
            align_loops(&mut polygons, periods);
            polygons
        }
        1 | 2 => {
            let p = periods
                .0
                .ok_or("a loop winds round a direction that is not periodic")?;
            seam::cut_open(&mut ctx, &winding, holes, p)?
        }
        n => return Err(format!("{n} loops wind round the face").into()),
    };
    let triangles = domain::triangles(&mut ctx, &polygons, delta)?;
    Ok(FaceTriangles {
        points: ctx.points,
        triangles,
    })
}

/// Loop points farther than this many chord deviations from the face's surface mean that the
/// face's edges do not lie on it (valid edges lie within their tolerance, far below the chord
/// deviation at any usable faceting tolerance).
pub const OFF_SURFACE: f64 = 10.0;

/// An error, not to be mended by refining the edges, when a loop point lies farther than
/// [`OFF_SURFACE`] chord deviations from the surface at the parameters found for it.
fn off_surface(
    surface: &Surface,
    loops: &[Vec<LoopPoint>],
    rings: &[Ring],
    delta: f64,
) -> Result<(), FaceFailure> {
    let worst = loops
        .iter()
        .zip(rings)
        .flat_map(|(l, r)| l.iter().zip(&r.points))
        .map(|(lp, q)| (surface.eval(q.uv.x, q.uv.y) - lp.p).norm())
        .fold(0.0, f64::max);
    if worst > OFF_SURFACE * delta || worst.is_nan() {
        return Err(FaceFailure {
            what: format!(
                "an edge point lies {worst:e} from the face's surface, more than {OFF_SURFACE} chord deviations ({delta:e}): its edges do not lie on it"
            ),
            refinable: false,
        });
    }
    Ok(())
}

/// Why a face was not triangulated, and whether sampling its edges finer may mend it (loops
/// that come near each other) or not (edges off the surface).
#[derive(Debug, Clone, PartialEq)]
pub struct FaceFailure {
    /// What went wrong.
    pub what: String,
    /// Whether finer edges may mend it.
    pub refinable: bool,
}

impl From<String> for FaceFailure {
    fn from(what: String) -> Self {
        Self {
            what,
            refinable: true,
        }
    }
}

impl From<&str> for FaceFailure {
    fn from(what: &str) -> Self {
        what.to_string().into()
    }
}

/// A loop's parameters, each point's found near the one before it (the first's without a
/// hint) and unwrapped onto it, and the loop's windings: the whole periods between its last
/// point's continuation to the first and the first, `round((close − first)/p)`.
fn ring(surface: &Surface, l: &[LoopPoint], (pu, pv): (Option<f64>, Option<f64>)) -> Ring {
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
    Ring {
        points: ring,
        wu,
        wv,
    }
}

/// The rings in working parameters (u and v exchanged when `swap`), split into those that
/// wind round the working u direction, with their winding, and those that do not (holes).
fn sort_rings(rings: Vec<Ring>, swap: bool) -> (Vec<Winding>, Vec<Vec<Q>>) {
    let mut winding = Vec::new();
    let mut holes = Vec::new();
    for Ring {
        points: mut ring,
        wu,
        wv,
    } in rings
    {
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
    (winding, holes)
}

/// Shifts the loops after the first by whole periods, in each periodic working direction
/// (`periods` in working order), so that their mean coordinate lies within half a period of
/// the first loop's: loops of a periodic face that none winds round, side by side.
fn align_loops(polygons: &mut [Vec<Q>], periods: (Option<f64>, Option<f64>)) {
    for (k, per) in [(0usize, periods.0), (1, periods.1)] {
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
