//! A body to a closed triangle mesh at a faceting tolerance.
//!
//! As for the faceted engine's primitives, a body of characteristic length `L` (its bounding-
//! box diagonal) at faceting tolerance FT is faceted so that chords deviate at most
//! `δ = L / FT` from the true edges and surfaces ([`FacetingTolerance::chord_deviation`]).
//! Edges are sampled once ([`edge`]); each face is triangulated in its parameter space between
//! its edges' points ([`face`]); the triangles of all faces then form one mesh, checked as
//! the faceted engine checks an STL mesh ([`TriangleMesh::new`]): closed, two-manifold,
//! consistently and outward oriented.

pub mod edge;
pub mod face;
pub mod param;
pub mod slivers;
#[cfg(test)]
mod solids_tests;

use crate::brep::{Body, Face};
use crate::error::{Error, ErrorKind};
use crate::part::Part;
use contact_core::geometry::TriangleMesh;
use contact_core::{FacetingTolerance, Point3};
use face::LoopPoint;

/// A body's tessellation before the closedness checks.
#[derive(Debug, Clone)]
pub struct Mesh {
    /// Vertices.
    pub vertices: Vec<Point3>,
    /// Triangles, oriented alike (outward once [`Mesh::signed_volume`] is positive).
    pub triangles: Vec<[u32; 3]>,
    /// The chord deviation used, δ = L / FT.
    pub deviation: f64,
}

impl Mesh {
    /// Enclosed signed volume (divergence theorem over the triangles).
    pub fn signed_volume(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.vertices[i as usize].coords);
                a.dot(&b.cross(&c)) / 6.0
            })
            .sum()
    }

    /// Centroid of the enclosed volume.
    pub fn centroid(&self) -> Point3 {
        let mut m = contact_core::Vector3::zeros();
        let mut v = 0.0;
        for t in &self.triangles {
            let [a, b, c] = t.map(|i| self.vertices[i as usize].coords);
            let dv = a.dot(&b.cross(&c)) / 6.0;
            v += dv;
            m += (a + b + c) * (dv / 4.0);
        }
        Point3::from(m / v)
    }
}

/// The bounding-box diagonal of a body: its vertices and coarse samples of every edge between
/// its ends (surfaces bulge past their edges by less than a chord deviation at any useful FT).
pub fn characteristic_length(body: &Body) -> f64 {
    let mut lo = Point3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY);
    let mut hi = -lo;
    let mut add = |p: &Point3| {
        lo = lo.inf(p);
        hi = hi.sup(p);
    };
    body.vertices.iter().for_each(&mut add);
    for e in &body.edges {
        if let Some(pts) = edge::sample(e, &body.vertices, f64::INFINITY) {
            pts.iter().for_each(&mut add);
        }
    }
    (hi - lo).norm()
}

/// Tessellates a body. A face whose triangulation fails between its edges' points (loops
/// whose chords cross where two of them nearly touch) has its edges sampled again four
/// times finer, and the body tessellated again, at most twelve times.
pub fn tessellate(part: &Part, body: &Body, tolerance: FacetingTolerance) -> Result<Mesh, Error> {
    tessellate_with_edges(part, body, tolerance, 1.0)
}

/// [`tessellate`] with every edge sampled at `edge_scale` times the chord deviation.
fn tessellate_with_edges(
    part: &Part,
    body: &Body,
    tolerance: FacetingTolerance,
    edge_scale: f64,
) -> Result<Mesh, Error> {
    let length = characteristic_length(body);
    if !(length.is_finite() && length > 0.0) {
        return Err(part.error(ErrorKind::Geometry {
            node: body.node.clone(),
            what: format!("the body's size is {length}"),
        }));
    }
    let delta = tolerance.chord_deviation(length);
    let mut edge_delta = vec![delta * edge_scale; body.edges.len()];
    let mut retries = 0;
    loop {
        match attempt(part, body, delta, &edge_delta) {
            Ok(mesh) => return Ok(mesh),
            Err((Some(f), _)) if retries < 12 => {
                for fin in body.faces[f].loops.iter().flatten() {
                    edge_delta[fin.edge] *= 0.25;
                }
                retries += 1;
            }
            Err((_, e)) => return Err(e),
        }
    }
}

/// A failed tessellation: the index of the face whose triangulation failed, if that is what
/// failed, and the error.
type Failure = (Option<usize>, Error);

/// One tessellation with each edge sampled at its own chord deviation; on failure, the
/// index of the face whose triangulation failed, if that is what failed. The body's vertices
/// come first, then each edge's inner points ([`edge_points`]), then each face's own points;
/// the triangles are oriented outward (reversed if the enclosed volume came out negative).
fn attempt(part: &Part, body: &Body, delta: f64, edge_delta: &[f64]) -> Result<Mesh, Failure> {
    let mut vertices = body.vertices.clone();
    let edge_ids = edge_points(part, body, edge_delta, &mut vertices)?;
    let mut triangles = Vec::new();
    for (index, f) in body.faces.iter().enumerate() {
        let loops = face_loops(part, f, &edge_ids, &vertices).map_err(|e| (None, e))?;
        let first_local = vertices.len() as u32;
        let ft = face::triangulate(&f.surface, &loops, delta, first_local).map_err(|e| {
            (
                e.refinable.then_some(index),
                part.error(ErrorKind::Geometry {
                    node: f.node.clone(),
                    what: format!("{} face: {}", surface_kind(&f.surface), e.what),
                }),
            )
        })?;
        vertices.extend(ft.points);
        triangles.extend(ft.triangles);
    }
    slivers::split_slivers(&vertices, &mut triangles);
    let mut mesh = Mesh {
        vertices,
        triangles,
        deviation: delta,
    };
    if mesh.signed_volume() < 0.0 {
        for t in &mut mesh.triangles {
            t.swap(1, 2);
        }
    }
    Ok(mesh)
}

/// Samples every edge at its chord deviation in `edge_delta` ([`edge::sample`]) and appends
/// its inner points to `vertices`: each edge's points as mesh vertex ids, from start to end.
/// An edge's ends are its vertices' ids; a ring edge (no vertices) gets its first point as a
/// new vertex, which it also ends at.
fn edge_points(
    part: &Part,
    body: &Body,
    edge_delta: &[f64],
    vertices: &mut Vec<Point3>,
) -> Result<Vec<Vec<u32>>, Failure> {
    let mut edge_ids: Vec<Vec<u32>> = Vec::with_capacity(body.edges.len());
    for (e, &d) in body.edges.iter().zip(edge_delta) {
        let pts = edge::sample(e, &body.vertices, d).ok_or_else(|| {
            (
                None,
                part.error(ErrorKind::Geometry {
                    node: e.node.clone(),
                    what: "an edge with one vertex only, or a ring edge on an open curve".into(),
                }),
            )
        })?;
        let n = pts.len();
        let mut ids = Vec::with_capacity(n);
        let first = match e.start {
            Some(s) => s as u32,
            None => {
                vertices.push(pts[0]);
                vertices.len() as u32 - 1
            }
        };
        ids.push(first);
        for p in &pts[1..n - 1] {
            vertices.push(*p);
            ids.push(vertices.len() as u32 - 1);
        }
        ids.push(match e.end {
            Some(v) => v as u32,
            None => first,
        });
        edge_ids.push(ids);
    }
    Ok(edge_ids)
}

/// A face's loops as closed rings of loop points (first point not repeated at the end): each
/// loop's fins' edge points ([`edge_points`]' ids) in the fins' directions, joined end to
/// start. Rings of fewer than two points are left out; a face without any is an error, as is
/// a fin that does not start where the one before it ended.
fn face_loops(
    part: &Part,
    f: &Face,
    edge_ids: &[Vec<u32>],
    vertices: &[Point3],
) -> Result<Vec<Vec<LoopPoint>>, Error> {
    let geometry = |what: &str| {
        part.error(ErrorKind::Geometry {
            node: f.node.clone(),
            what: what.into(),
        })
    };
    let mut loops = Vec::with_capacity(f.loops.len());
    for l in &f.loops {
        let mut ring: Vec<LoopPoint> = Vec::new();
        for (k, fin) in l.iter().enumerate() {
            let ids = &edge_ids[fin.edge];
            let run: Vec<u32> = if fin.forward {
                ids.clone()
            } else {
                ids.iter().rev().copied().collect()
            };
            if k > 0 && ring.last().map(|p| p.id) != Some(run[0]) {
                return Err(geometry("a loop's fins do not meet end to start"));
            }
            let skip = usize::from(k > 0);
            ring.extend(run[skip..].iter().map(|&id| LoopPoint {
                id,
                p: vertices[id as usize],
            }));
        }
        if ring.len() > 1 && ring.first().map(|p| p.id) == ring.last().map(|p| p.id) {
            ring.pop();
        }
        if ring.len() >= 2 {
            loops.push(ring);
        }
    }
    if loops.is_empty() {
        return Err(geometry(
            "a face without a loop (a whole closed surface) is not tessellated",
        ));
    }
    Ok(loops)
}

/// The surface's kind, for messages.
pub fn surface_kind(s: &crate::geom::Surface) -> &'static str {
    use crate::geom::Surface as S;
    match s {
        S::Plane { .. } => "plane",
        S::Cone { tan, .. } if *tan == 0.0 => "cylinder",
        S::Cone { .. } => "cone",
        S::Sphere { .. } => "sphere",
        S::Torus { .. } => "torus",
        S::Nurbs(_) => "B-spline",
        S::Swept { .. } => "swept",
        S::Spun { .. } => "spun",
    }
}

/// Tessellates a body and checks it as the faceted engine checks a mesh file. A mesh that
/// fails the checks (faces that meet badly where coarse edge chords pass close to other
/// loops) is made again with every edge sampled four, then sixteen times finer.
pub fn body_mesh(
    part: &Part,
    body: &Body,
    tolerance: FacetingTolerance,
    name: &str,
) -> Result<TriangleMesh, Error> {
    let mut result = checked_mesh(part, body, tolerance, name, 1.0);
    for scale in [0.25, 0.0625] {
        if result.is_ok() {
            break;
        }
        result = checked_mesh(part, body, tolerance, name, scale);
    }
    result
}

fn checked_mesh(
    part: &Part,
    body: &Body,
    tolerance: FacetingTolerance,
    name: &str,
    edge_scale: f64,
) -> Result<TriangleMesh, Error> {
    let mesh = tessellate_with_edges(part, body, tolerance, edge_scale)?;
    // Drop vertices no triangle uses (edge points of faces that failed are errors already).
    let mut used = vec![u32::MAX; mesh.vertices.len()];
    let mut vertices = Vec::new();
    let triangles = mesh
        .triangles
        .iter()
        .map(|t| {
            t.map(|i| {
                let i = i as usize;
                if used[i] == u32::MAX {
                    used[i] = vertices.len() as u32;
                    vertices.push(mesh.vertices[i]);
                }
                used[i]
            })
        })
        .collect();
    TriangleMesh::new(vertices, triangles).map_err(|e| {
        part.error(ErrorKind::OpenMesh {
            body: name.to_string(),
            what: e.to_string(),
        })
    })
}
