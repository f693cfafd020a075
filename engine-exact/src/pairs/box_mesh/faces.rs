//! The box's own surface inside the mesh: which region each part of it belongs to, and the
//! directed pieces that bound each face's caps.
//!
//! A region's boundary is the mesh surface inside the box (the clipped triangles) and the
//! *caps*, the parts of the box faces inside the mesh. A cap on a face is bounded by
//! - the cuts, where the mesh surface meets the face (a clipped triangle's edge along the
//!   face, run backwards: the closed boundary of a region runs each shared edge once each
//!   way), and
//! - the parts of the face's four box edges inside the mesh.
//!
//! **Box edges.** The mesh surface pierces a box edge where a clipped triangle has a vertex
//! on two box planes. Along the edge the piercings alternate between entering the mesh
//! (`n·d < 0` for the triangle's outward normal `n` and the edge direction `d`) and leaving
//! it; two in a row of one kind are one piercing found in both triangles of a shared mesh
//! edge, and count once. The parts inside join the regions of the piercings at their ends,
//! or the box corners they reach. A corner is inside when the nearest piercing along an edge
//! from it leaves the mesh; an edge without piercings passes its corners' state on; with no
//! piercing anywhere, one corner is tested with the winding number.
//!
//! **Holes.** Cuts that close on themselves inside a face, running clockwise as a cap
//! boundary, are the rim of a hole in a cap (a mesh tube through the face, a dent in it).
//! The hole is joined to the cap around it by a ray from its rightmost vertex along the face's
//! `+u`: the first boundary the ray meets bounds the same cap (the ray runs inside it), and a
//! hole's rightmost vertex has nothing of the hole further on. Each cut that does not close
//! already belongs to a region through the mesh surface (consecutive cuts lie in triangles
//! joined by an edge inside the box), and each cap touching the face's rim is joined through
//! its box edges.

use super::clip::{Clipped, Edge, plane};
use super::{NONE, UnionFind, closed_loops};
use contact_core::{Point3, Vector3};

/// The parts of the twelve box edges inside the mesh: `(edge, lo, hi, node)`.
pub(crate) type Intervals = Vec<(usize, f64, f64, u32)>;

/// Box edge `axis·4 + 2·[x_u > 0] + [x_v > 0]`, `u = axis + 1`, `v = axis + 2` (mod 3).
fn edge_id(axis: usize, u_positive: bool, v_positive: bool) -> usize {
    axis * 4 + 2 * usize::from(u_positive) + usize::from(v_positive)
}

/// The corner `[x > 0] + 2[y > 0] + 4[z > 0]` at the `hi` (or low) end of box edge `edge`.
fn edge_corner(edge: usize, hi: bool) -> usize {
    let axis = edge / 4;
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let mut bits = [false; 3];
    bits[axis] = hi;
    bits[u] = edge & 2 != 0;
    bits[v] = edge & 1 != 0;
    usize::from(bits[0]) + 2 * usize::from(bits[1]) + 4 * usize::from(bits[2])
}

/// The point at `t` along box edge `edge` of the box with half extents `half`.
pub(crate) fn edge_point(edge: usize, t: f64, half: &Vector3) -> Point3 {
    let axis = edge / 4;
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let mut p = Point3::origin();
    p[axis] = t;
    p[u] = if edge & 2 != 0 { half[u] } else { -half[u] };
    p[v] = if edge & 1 != 0 { half[v] } else { -half[v] };
    p
}

/// The box edge a vertex on the planes `on` (a bit set) lies on, if exactly two planes of
/// different axes.
fn edge_of(on: u8) -> Option<usize> {
    if on.count_ones() != 2 {
        return None;
    }
    let (j1, j2) = (
        on.trailing_zeros() as usize,
        7 - on.leading_zeros() as usize,
    );
    let ((a1, s1), (a2, s2)) = (plane(j1), plane(j2));
    if a1 == a2 {
        return None;
    }
    let axis = 3 - a1 - a2;
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let sign_on = |a: usize| if a == a1 { s1 } else { s2 };
    Some(edge_id(axis, sign_on(u) > 0.0, sign_on(v) > 0.0))
}

/// Finds the box edges' parts inside the mesh and joins each to its regions. Nodes are the
/// polygons `0..P` and the corners `P..P + 8`. `inside_corner(k)` decides a corner when no
/// edge is pierced at all.
pub(crate) fn box_edges(
    polygons: &[Clipped],
    normals: &[Vector3],
    half: &Vector3,
    forest: &mut UnionFind,
    inside_corner: impl FnOnce(usize) -> bool,
    intervals: &mut Intervals,
) {
    let corner_node = |c: usize| (polygons.len() + c) as u32;
    // Piercings per edge: (t, enters, node).
    let mut piercings: [Vec<(f64, bool, u32)>; 12] = Default::default();
    for (i, poly) in polygons.iter().enumerate() {
        for k in 0..poly.len {
            let Some(edge) = edge_of(poly.on[k]) else {
                continue;
            };
            let rate = normals[i][edge / 4];
            if rate != 0.0 {
                piercings[edge].push((poly.points[k][edge / 4], rate < 0.0, i as u32));
            }
        }
    }
    let mut corner_inside: [Option<bool>; 8] = [None; 8];
    for (edge, list) in piercings.iter_mut().enumerate() {
        list.sort_by(|a, b| a.0.total_cmp(&b.0));
        // One piercing seen from both triangles of a mesh edge: keep one, join both.
        let mut kept: Vec<(f64, bool, u32)> = Vec::with_capacity(list.len());
        for &p in list.iter() {
            match kept.last() {
                Some(last) if last.1 == p.1 => forest.union(last.2, p.2),
                _ => kept.push(p),
            }
        }
        *list = kept;
        if let (Some(first), Some(last)) = (list.first(), list.last()) {
            corner_inside[edge_corner(edge, false)].get_or_insert(!first.1);
            corner_inside[edge_corner(edge, true)].get_or_insert(last.1);
        }
    }
    // Edges without piercings pass their corners' state on.
    if corner_inside.iter().all(Option::is_none) {
        let state = inside_corner(0);
        corner_inside = [Some(state); 8];
    }
    for _ in 0..8 {
        for (edge, list) in piercings.iter().enumerate() {
            if list.is_empty() {
                let (lo, hi) = (edge_corner(edge, false), edge_corner(edge, true));
                if let Some(s) = corner_inside[lo].or(corner_inside[hi]) {
                    corner_inside[lo].get_or_insert(s);
                    corner_inside[hi].get_or_insert(s);
                }
            }
        }
    }
    for (edge, list) in piercings.iter().enumerate() {
        let h = half[edge / 4];
        let (lo, hi) = (edge_corner(edge, false), edge_corner(edge, true));
        let mut add = |forest: &mut UnionFind, a: (f64, u32), b: (f64, u32)| {
            forest.union(a.1, b.1);
            if b.0 > a.0 {
                intervals.push((edge, a.0, b.0, a.1));
            }
        };
        let Some(first) = list.first() else {
            if corner_inside[lo] == Some(true) {
                add(forest, (-h, corner_node(lo)), (h, corner_node(hi)));
            }
            continue;
        };
        if !first.1 {
            add(forest, (-h, corner_node(lo)), (first.0, first.2));
        }
        for w in list.windows(2) {
            if w[0].1 {
                add(forest, (w[0].0, w[0].2), (w[1].0, w[1].2));
            }
        }
        let last = list[list.len() - 1];
        if last.1 {
            add(forest, (last.0, last.2), (h, corner_node(hi)));
        }
    }
}

/// The cuts of face `f`: `(polygon, edge index)` for each polygon with an edge along it.
pub(crate) fn cuts(polygons: &[Clipped], f: usize) -> Vec<(u32, usize)> {
    let mut out = Vec::new();
    for (i, poly) in polygons.iter().enumerate() {
        if let Some(e) = (0..poly.len).find(|&e| poly.edges[e] == Edge::Cut(f as u8)) {
            out.push((i as u32, e));
        }
    }
    out
}

/// Joins each hole of face `f`'s caps to the cap around it (see the module doc).
/// `next_polygon(i, k)` is the polygon across triangle edge `k` of polygon `i` (or
/// [`NONE`]); `cut_index[i]` is polygon `i`'s position in `cuts` (or [`NONE`]).
#[allow(clippy::too_many_arguments)]
pub(crate) fn join_holes(
    polygons: &[Clipped],
    f: usize,
    cuts: &[(u32, usize)],
    cut_index: &[u32],
    next_polygon: impl Fn(u32, u8) -> u32,
    half: &Vector3,
    intervals: &Intervals,
    forest: &mut UnionFind,
) {
    let (axis, sign) = plane(f);
    let normal = sign * unit(axis);
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let segment = |c: &(u32, usize)| {
        let poly = &polygons[c.0 as usize];
        (poly.points[c.1], poly.points[(c.1 + 1) % poly.len])
    };
    // Follow each cut forward through the neighbours until it closes or leaves the face.
    let next = |at: usize| {
        let (i, e) = cuts[at];
        let poly = &polygons[i as usize];
        let Edge::Triangle(k) = poly.edges[(e + 1) % poly.len] else {
            return None;
        };
        let j = next_polygon(i, k);
        (j != NONE && cut_index[j as usize] != NONE).then(|| cut_index[j as usize] as usize)
    };
    closed_loops(cuts.len(), next, |walk| {
        // In the polygons' order a hole's rim runs counter-clockwise about the outward normal.
        let origin = segment(&cuts[walk[0]]).0;
        let area: f64 = walk
            .iter()
            .map(|&s| {
                let (p, q) = segment(&cuts[s]);
                (p - origin).cross(&(q - origin)).dot(&normal)
            })
            .sum();
        if area <= 0.0 {
            return;
        }
        let right = walk
            .iter()
            .map(|&s| segment(&cuts[s]).0)
            .max_by(|a, b| a[u].total_cmp(&b[u]))
            .unwrap_or(origin);
        let hole_node = cuts[walk[0]].0;
        // The first boundary along +u from the rightmost vertex.
        let tolerance = 1e-12 * half.norm();
        let mut best = (half[u] - right[u], NONE);
        for c in cuts {
            let (p, q) = segment(c);
            let (lo, hi) = if p[v] <= q[v] { (p, q) } else { (q, p) };
            if !(lo[v] <= right[v] && right[v] < hi[v]) {
                continue;
            }
            let s = (right[v] - lo[v]) / (hi[v] - lo[v]);
            let along = lo[u] + s * (hi[u] - lo[u]) - right[u];
            if along > tolerance && along < best.0 {
                best = (along, c.0);
            }
        }
        let hit = if best.1 != NONE {
            best.1
        } else {
            // The face's rim at u = +h: the box edge along v there.
            // Box edge along v: its own u' = v + 1 = axis and v' = v + 2 = u (mod 3).
            let edge = edge_id(v, sign > 0.0, true);
            match intervals
                .iter()
                .find(|&&(e, lo, hi, _)| e == edge && lo <= right[v] && right[v] <= hi)
            {
                Some(&(_, _, _, node)) => node,
                None => return,
            }
        };
        forest.union(hole_node, hit);
    });
}

/// The directed pieces bounding face `f`'s caps, each with its node: the cuts run backwards
/// and the box edges' parts inside the mesh, counter-clockwise about the face's normal.
pub(crate) fn cap_pieces(
    polygons: &[Clipped],
    f: usize,
    cuts: &[(u32, usize)],
    half: &Vector3,
    intervals: &Intervals,
    mut piece: impl FnMut(u32, Point3, Point3),
) {
    for &(i, e) in cuts {
        let poly = &polygons[i as usize];
        piece(i, poly.points[(e + 1) % poly.len], poly.points[e]);
    }
    let (axis, sign) = plane(f);
    let normal = sign * unit(axis);
    let centre = Point3::from(normal * half[axis]);
    for &(edge, lo, hi, node) in intervals {
        let a = edge / 4;
        if a == axis {
            continue;
        }
        let mid = edge_point(edge, 0.0, half);
        if (mid[axis] > 0.0) != (sign > 0.0) {
            continue;
        }
        let (p, q) = (edge_point(edge, lo, half), edge_point(edge, hi, half));
        let forward = normal.cross(&unit(a)).dot(&(centre - mid)) > 0.0;
        if forward {
            piece(node, p, q);
        } else {
            piece(node, q, p);
        }
    }
}

fn unit(axis: usize) -> Vector3 {
    let mut e = Vector3::zeros();
    e[axis] = 1.0;
    e
}
