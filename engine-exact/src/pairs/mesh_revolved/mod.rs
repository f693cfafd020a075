//! A cylinder or a frustum (cone) against a closed triangle mesh (taken as exact): the
//! intersection's moments by slicing perpendicular to the solid's axis, one contact per
//! connected region.
//!
//! ## The slices
//! In the solid's frame (axis `z`, lengths divided by a power of two near its size) the plane
//! `z = t` cuts the solid in the disc of radius `r(t) = r₀ + k t` (`0 ≤ t ≤ L`) and the mesh
//! in its section, directed segments with the mesh on their left ([`section`]). Their overlap
//! is bounded by *chords* (the segments' parts inside the disc: the mesh surface inside the
//! solid) and *arcs* (the circle inside the section: the solid's surface inside the mesh);
//! each piece is summed about the axis in closed form, so each part of the overlap gets its
//! own area and first moments.
//!
//! - `V = ∫ area dt`, the centroid from `∫(∫p dA, t·area) dt / V`.
//! - The area vector of the solid's lateral surface inside the mesh, by the moving section:
//!   an arc sweeps `(ν − k e_z) r dφ dt`; the caps add `∓e_z` times their overlap with the
//!   section at `t = 0, L` (the section's limit from inside). The mesh's surface inside closes
//!   the same region: `S_mesh = −S_solid`.
//! - Unsigned areas: the lateral surface's `√(1 + k²) r A` per slice, a chord's length over
//!   its triangle's `|n_xy|/|n|` (the triangle's area per unit of height and length), and a
//!   triangle parallel to the slices by its overlap with the disc at its height.
//!
//! The quadrature ([`crate::quadrature::Adaptive`], the box–revolved pairs' tolerance) runs
//! between cuts where the overlap's combinatorics change: the mesh's vertex heights, the
//! heights where the circle touches a triangle's section line inside the segment (linear in
//! `t`) and where a mesh edge pierces the lateral surface (a quadratic). Between cuts the
//! overlap is smooth or has a square-root end.
//!
//! ## Regions
//! Labelled once per piece between cuts, at its middle, where the combinatorics hold for the
//! whole piece. Nodes are the mesh triangles and one *full disc* per piece (the circle wholly
//! inside the section). A part of the overlap joins
//! - the triangles along a section loop inside the disc (consecutive chords meet on a mesh
//!   edge),
//! - the triangles at the two ends of each arc (walking the circle counter-clockwise from a
//!   segment leaving it to the next crossing),
//! - a hole's rim (a loop wholly inside the disc, running clockwise) and the first boundary
//!   a ray along `+x` from its rightmost vertex meets (a chord, or the arc it hits).
//!
//! Across the cuts, a triangle crossing a cut is in the parts on both sides, and a full disc
//! joins every part of the pieces next to it (nothing inside it can start or end at the cut
//! without a triangle that crosses it). Each region is then integrated on its own pieces.
//!
//! ## The contact (SPEC §4)
//! As [`super::box_revolved`]: normal `−S_solid/|S_solid|` (from the mesh into the solid), the
//! points where the line through the centroid along it leaves each body (the mesh's first
//! surface along the line, or its closest point when the line misses), area `|S|`. When `|S|`
//! vanishes: with no mesh surface inside the solid, the solid lies in the mesh and the normal
//! points from the centroid to the mesh's closest point; otherwise against the solid's outward
//! normal at its surface point nearest the centroid. Touching is no contact.

pub(crate) mod section;

use super::clipped::unit_for;
use super::disc_section::disc_section;
use super::ellipsoid_sliced::{ADAPTIVE, COMPONENTS, floor};
use super::mesh_box::UnionFind;
use super::mesh_plane::{PreparedMesh, closest_on_mesh, exit_along};
use super::solid_distance::{Solid, signed_distance};
use super::volume_contact::{self, ENCLOSED, VolumeMoments};
use crate::kernel::PairContact;
use crate::quadrature::MAX_PIECES;
use crate::ray_exit::surface_point_along_w;
use contact_core::{Isometry3, Point3, Vector2, Vector3, WorkCounters};
use section::{Crossing, SlicedTriangle, arc_moments, chord_moments, clip_to_disc};
use std::f64::consts::TAU;

/// The radius `r₀ + k t` over `0 ≤ t ≤ L`, working units.
#[derive(Debug, Clone, Copy)]
struct Profile {
    r0: f64,
    slope: f64,
    len: f64,
}

impl Profile {
    fn radius(&self, t: f64) -> f64 {
        (self.r0 + self.slope * t).max(0.0)
    }
}

/// One slice's overlap pieces, with the root each is attributed to.
#[derive(Debug, Default)]
struct Slice {
    /// `(triangle index in the slice, chord start, chord end, whole segment inside)`.
    chords: Vec<(usize, Vector2, Vector2, bool)>,
    crossings: Vec<Crossing>,
    /// The segments: `(triangle, start, start edge, end, end edge)`.
    segments: Vec<(u32, Vector2, u8, Vector2, u8)>,
}

/// What is fixed for one query.
struct Setup<'a> {
    profile: Profile,
    sliced: Vec<SlicedTriangle>,
    /// Sorted heights between which the combinatorics hold.
    cuts: Vec<f64>,
    /// `active[p]`: the sliced triangles crossing piece `p`.
    active: Vec<Vec<u32>>,
    mesh: &'a PreparedMesh,
}

impl Setup<'_> {
    /// The slice at `t` of piece `p`.
    fn slice(&self, p: usize, t: f64, out: &mut Slice) {
        out.chords.clear();
        out.crossings.clear();
        out.segments.clear();
        let r = self.profile.radius(t);
        for &s in &self.active[p] {
            let tri = &self.sliced[s as usize];
            let (a, ae, b, be) = tri.segment(t);
            let k = out.segments.len();
            out.segments.push((tri.index, a, ae, b, be));
            if r <= 0.0 {
                continue;
            }
            let crossings = &mut out.crossings;
            if let Some((l0, l1)) = clip_to_disc(&a, &b, r, |x, leaves| {
                crossings.push(Crossing {
                    angle: x.y.atan2(x.x),
                    leaves,
                    segment: k,
                });
            }) {
                let d = b - a;
                out.chords
                    .push((k, a + l0 * d, a + l1 * d, l0 == 0.0 && l1 == 1.0));
            }
        }
        out.crossings.sort_by(|x, y| x.angle.total_cmp(&y.angle));
    }
}

/// Each arc inside the section: `(leaving crossing, start angle, sweep)`.
fn arcs(crossings: &[Crossing]) -> impl Iterator<Item = (usize, f64, f64)> + '_ {
    let n = crossings.len();
    (0..n).filter(|&i| crossings[i].leaves).map(move |i| {
        let next = &crossings[(i + 1) % n];
        let mut sweep = next.angle - crossings[i].angle;
        if sweep < 0.0 || (n == 1) {
            sweep += TAU;
        }
        (i, crossings[i].angle, sweep)
    })
}

/// The contacts of `solid` (a cylinder or frustum, `a`, at `pose_a`) with `mesh` (`b`, at
/// `pose_b`), one per region, normals from `b` into `a`. Other solids give none.
pub(crate) fn contacts(
    solid: &Solid,
    pose_a: &Isometry3,
    mesh: &PreparedMesh,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let (r0, r1, len) = match *solid {
        Solid::Cylinder(c) => (c.radius(), c.radius(), c.length()),
        Solid::Frustum(f) => (f.bottom_radius(), f.top_radius(), f.length()),
        Solid::Box(_) | Solid::Torus(_) => return,
    };
    let unit = unit_for(r0.max(r1).max(len));
    let profile = Profile {
        r0: r0 / unit,
        slope: (r1 - r0) / len,
        len: len / unit,
    };
    let relative = pose_a.inv_mul(pose_b);
    let reach = (relative * mesh.centre).coords / unit;
    let radius = mesh.radius / unit;
    let outer = (r0.max(r1)) / unit;
    if reach.z + radius <= 0.0
        || reach.z - radius >= profile.len
        || reach.xy().norm() - radius >= outer
    {
        return;
    }
    let local: Vec<Vector3> = mesh
        .vertices
        .iter()
        .map(|v| (relative * v).coords / unit)
        .collect();
    // The triangles that can reach the solid's bounding box.
    let mut sliced = Vec::new();
    let mut flat = Vec::new();
    let mut heights = vec![0.0, profile.len];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let v = tri.map(|i| local[i as usize]);
        let (lo, hi) = bounds(&v);
        if hi.z < 0.0
            || lo.z > profile.len
            || lo.x > outer
            || hi.x < -outer
            || lo.y > outer
            || hi.y < -outer
        {
            continue;
        }
        work.primitive_tests += 1;
        for p in &v {
            if p.z > 0.0 && p.z < profile.len {
                heights.push(p.z);
            }
        }
        match SlicedTriangle::new(t as u32, v) {
            Some(s) => sliced.push(s),
            None => flat.push((t as u32, v)),
        }
    }
    add_events(&sliced, &local, mesh, &profile, &mut heights);
    heights.sort_by(f64::total_cmp);
    heights.dedup();
    let cuts = heights;
    let pieces = cuts.len() - 1;
    let active: Vec<Vec<u32>> = cuts
        .windows(2)
        .map(|w| {
            (0..sliced.len() as u32)
                .filter(|&s| {
                    let (lo, hi) = sliced[s as usize].range();
                    lo <= w[0] && hi >= w[1]
                })
                .collect()
        })
        .collect();
    let setup = Setup {
        profile,
        sliced,
        cuts,
        active,
        mesh,
    };
    let count = mesh.triangles.len();
    let mut forest = UnionFind::new(count + pieces);
    let full = label_regions(&setup, &local, &mut forest);
    let roots: Vec<u32> = (0..(count + pieces) as u32)
        .map(|n| forest.find(n))
        .collect();
    // The regions, in the order of their smallest node.
    let mut regions: Vec<u32> = Vec::new();
    let mut scratch = Slice::default();
    for p in 0..pieces {
        let w = (setup.cuts[p], setup.cuts[p + 1]);
        if w.1 <= w.0 {
            continue;
        }
        setup.slice(p, 0.5 * (w.0 + w.1), &mut scratch);
        for &(k, ..) in &scratch.chords {
            regions.push(roots[scratch.segments[k].0 as usize]);
        }
        if full[p] {
            regions.push(roots[count + p]);
        }
    }
    regions.sort_unstable();
    regions.dedup();
    for region in regions {
        let found = region_contact(
            &setup, &roots, &full, &flat, region, solid, pose_a, pose_b, unit, work,
        );
        if let Some(c) = found {
            emit(c);
        }
    }
}

fn bounds(v: &[Vector3; 3]) -> (Vector3, Vector3) {
    (v[0].inf(&v[1]).inf(&v[2]), v[0].sup(&v[1]).sup(&v[2]))
}

/// The heights where the circle touches a triangle's section line within its segment, and
/// where a mesh edge pierces the lateral surface.
fn add_events(
    sliced: &[SlicedTriangle],
    local: &[Vector3],
    mesh: &PreparedMesh,
    profile: &Profile,
    heights: &mut Vec<f64>,
) {
    let Profile { r0, slope: k, len } = *profile;
    let mut push = |t: f64| {
        if t > 0.0 && t < len {
            heights.push(t);
        }
    };
    for tri in sliced {
        let [a, b, c] = mesh.triangles[tri.index as usize].map(|i| local[i as usize]);
        let n = (b - a).cross(&(c - a));
        let g = n.xy().norm();
        let d0 = n.dot(&a);
        let (lo, hi) = tri.range();
        for sign in [1.0, -1.0] {
            // d0 − n_z t = sign·g·(r0 + k t).
            let denominator = n.z + sign * g * k;
            if denominator == 0.0 {
                continue;
            }
            let t = (d0 - sign * g * r0) / denominator;
            if !(t > lo && t < hi) {
                continue;
            }
            let foot = n.xy() * ((d0 - n.z * t) / (g * g));
            let (p, _, q, _) = tri.segment(t);
            let d = q - p;
            let along = (foot - p).dot(&d) / d.norm_squared();
            if (0.0..=1.0).contains(&along) {
                push(t);
            }
        }
        // Each edge once: from the triangle whose index is below its neighbour's, or whose
        // neighbour is not sliced (the edge is seen from here only).
        let vertices = mesh.triangles[tri.index as usize];
        for e in 0..3 {
            let other = mesh.neighbours[tri.index as usize][e];
            if other < tri.index {
                continue;
            }
            let (pa, pb) = (
                local[vertices[e] as usize],
                local[vertices[(e + 1) % 3] as usize],
            );
            let d = pb - pa;
            let base = r0 + k * pa.z;
            let qa = d.xy().norm_squared() - k * k * d.z * d.z;
            let qb = 2.0 * (pa.xy().dot(&d.xy()) - k * d.z * base);
            let qc = pa.xy().norm_squared() - base * base;
            for s in quadratic_roots(qa, qb, qc) {
                if s > 0.0 && s < 1.0 {
                    push(pa.z + s * d.z);
                }
            }
        }
    }
}

/// The real roots of `a s² + b s + c` (none when there are none, one for a linear equation).
fn quadratic_roots(a: f64, b: f64, c: f64) -> impl Iterator<Item = f64> {
    let mut roots = [f64::NAN; 2];
    if a == 0.0 {
        if b != 0.0 {
            roots[0] = -c / b;
        }
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc >= 0.0 {
            let q = -0.5 * (b + b.signum() * disc.sqrt());
            if q != 0.0 {
                roots = [q / a, c / q];
            } else {
                roots[0] = 0.0;
            }
        }
    }
    roots.into_iter().filter(|r| r.is_finite())
}

/// Labels the regions (see the module doc); returns which pieces have a full disc.
fn label_regions(setup: &Setup, local: &[Vector3], forest: &mut UnionFind) -> Vec<bool> {
    let count = setup.mesh.triangles.len();
    let pieces = setup.cuts.len() - 1;
    let mut full = vec![false; pieces];
    let mut present: Vec<Vec<u32>> = vec![Vec::new(); pieces];
    let mut slice = Slice::default();
    let neighbours = &setup.mesh.neighbours;
    for p in 0..pieces {
        let (lo, hi) = (setup.cuts[p], setup.cuts[p + 1]);
        if hi <= lo {
            continue;
        }
        let t = 0.5 * (lo + hi);
        let r = setup.profile.radius(t);
        setup.slice(p, t, &mut slice);
        // Chords joined along their loops.
        for &(k, a, e, _) in &slice.chords {
            let (tri, start, start_edge, end, end_edge) = slice.segments[k];
            if a == start {
                forest.union(tri, neighbours[tri as usize][start_edge as usize]);
            }
            if e == end {
                forest.union(tri, neighbours[tri as usize][end_edge as usize]);
            }
            present[p].push(tri);
        }
        // The arcs' two ends.
        for (i, _, _) in arcs(&slice.crossings) {
            let next = &slice.crossings[(i + 1) % slice.crossings.len()];
            let here = slice.segments[slice.crossings[i].segment].0;
            forest.union(here, slice.segments[next.segment].0);
        }
        if slice.crossings.is_empty() && r > 0.0 {
            full[p] = inside_section(setup.mesh, local, t, &Vector2::new(r, 0.0));
            if full[p] {
                present[p].push((count + p) as u32);
            }
        }
        join_holes(&slice, r, neighbours, full[p], (count + p) as u32, forest);
    }
    for (p, _) in full.iter().enumerate().filter(|(_, f)| **f) {
        for q in [p.wrapping_sub(1), p + 1] {
            if let Some(nodes) = present.get(q) {
                for &n in nodes {
                    forest.union((count + p) as u32, n);
                }
            }
        }
    }
    full
}

/// Whether the point `x` of the slice `z = t` lies inside the mesh: the parity of the mesh's
/// section segments crossing the ray from `x` along `+x` (every triangle crossing `t`).
fn inside_section(mesh: &PreparedMesh, local: &[Vector3], t: f64, x: &Vector2) -> bool {
    let mut inside = false;
    for tri in &mesh.triangles {
        let v = tri.map(|i| local[i as usize]);
        let Some(s) = SlicedTriangle::new(0, v) else {
            continue;
        };
        let (lo, hi) = s.range();
        if !(lo < t && t < hi) {
            continue;
        }
        let (p, _, q, _) = s.segment(t);
        if (p.y > x.y) != (q.y > x.y) {
            let at = p.x + (x.y - p.y) / (q.y - p.y) * (q.x - p.x);
            if at > x.x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Joins each hole (a section loop wholly inside the disc, clockwise) to the part around it.
fn join_holes(
    slice: &Slice,
    r: f64,
    neighbours: &[[u32; 3]],
    full: bool,
    full_node: u32,
    forest: &mut UnionFind,
) {
    // The chords that are whole segments, by triangle.
    let whole: Vec<usize> = (0..slice.chords.len())
        .filter(|&c| slice.chords[c].3)
        .collect();
    let find = |tri: u32| {
        whole
            .iter()
            .position(|&c| slice.segments[slice.chords[c].0].0 == tri)
    };
    let mut visited = vec![false; whole.len()];
    let mut walk = Vec::new();
    for start in 0..whole.len() {
        if visited[start] {
            continue;
        }
        walk.clear();
        let mut at = start;
        let closed = loop {
            visited[at] = true;
            walk.push(at);
            let (tri, _, _, _, end_edge) = slice.segments[slice.chords[whole[at]].0];
            let Some(next) = find(neighbours[tri as usize][end_edge as usize]) else {
                break false;
            };
            if next == start {
                break true;
            }
            if visited[next] {
                break false;
            }
            at = next;
        };
        if !closed {
            continue;
        }
        let area: f64 = walk
            .iter()
            .map(|&w| {
                let (_, a, e, _) = slice.chords[whole[w]];
                a.x * e.y - a.y * e.x
            })
            .sum();
        if area >= 0.0 {
            continue;
        }
        let right = walk
            .iter()
            .map(|&w| slice.chords[whole[w]].1)
            .max_by(|a, b| a.x.total_cmp(&b.x))
            .unwrap_or_default();
        let hole = slice.segments[slice.chords[whole[walk[0]]].0].0;
        let tolerance = 1e-12 * r.max(1.0);
        let mut best = ((r * r - right.y * right.y).max(0.0).sqrt() - right.x, None);
        for &(k, a, e, _) in &slice.chords {
            let (lo, hi) = if a.y <= e.y { (a, e) } else { (e, a) };
            if !(lo.y <= right.y && right.y < hi.y) {
                continue;
            }
            let x = lo.x + (right.y - lo.y) / (hi.y - lo.y) * (hi.x - lo.x) - right.x;
            if x > tolerance && x < best.0 {
                best = (x, Some(slice.segments[k].0));
            }
        }
        let hit = match best.1 {
            Some(tri) => Some(tri),
            None => {
                // The circle: the arc holding the hit's angle belongs to the crossing that
                // starts it.
                let angle = right.y.atan2(right.x + best.0);
                let c = &slice.crossings;
                if c.is_empty() {
                    full.then_some(full_node)
                } else {
                    let i = c.partition_point(|x| x.angle <= angle);
                    let owner = &c[(i + c.len() - 1) % c.len()];
                    owner.leaves.then(|| slice.segments[owner.segment].0)
                }
            }
        };
        if let Some(node) = hit {
            forest.union(hole, node);
        }
    }
}

/// The integrand at `t` for `region`: `[area, t·area, ∫x, ∫y, S_solid (3), solid's surface
/// inside the mesh, mesh's surface inside the solid]` per unit of `t`.
#[allow(clippy::too_many_arguments)]
fn integrand(
    setup: &Setup,
    roots: &[u32],
    full: &[bool],
    region: u32,
    t: f64,
    slice: &mut Slice,
) -> [f64; COMPONENTS] {
    let mut out = [0.0; COMPONENTS];
    let p = setup
        .cuts
        .partition_point(|&c| c <= t)
        .saturating_sub(1)
        .min(full.len().saturating_sub(1));
    let r = setup.profile.radius(t);
    if r <= 0.0 {
        return out;
    }
    setup.slice(p, t, slice);
    let count = setup.mesh.triangles.len();
    let mut add = |m: [f64; 3]| {
        out[0] += m[0];
        out[2] += m[1];
        out[3] += m[2];
    };
    let mut mesh_area = 0.0;
    for &(k, a, e, _) in &slice.chords {
        let tri = slice.segments[k].0;
        if roots[tri as usize] != region {
            continue;
        }
        add(chord_moments(&a, &e));
        let slope = setup.sliced[setup.active[p][k] as usize].slope;
        mesh_area += (e - a).norm() / slope;
    }
    let k = setup.profile.slope;
    let swept = |start: f64, sweep: f64, add: &mut dyn FnMut([f64; 3]), out6: &mut [f64; 4]| {
        let (m, normal) = arc_moments(r, start, sweep);
        add(m);
        out6[0] += r * normal.x;
        out6[1] += r * normal.y;
        out6[2] -= k * r * sweep;
        out6[3] += (1.0 + k * k).sqrt() * r * sweep;
    };
    let mut lateral = [0.0; 4];
    if slice.crossings.is_empty() {
        if full[p] && roots[count + p] == region {
            swept(0.0, TAU, &mut add, &mut lateral);
        }
    } else {
        for (i, start, sweep) in arcs(&slice.crossings) {
            let tri = slice.segments[slice.crossings[i].segment].0;
            if roots[tri as usize] == region {
                swept(start, sweep, &mut add, &mut lateral);
            }
        }
    }
    out[1] = t * out[0];
    out[4] = lateral[0];
    out[5] = lateral[1];
    out[6] = lateral[2];
    out[7] = lateral[3];
    out[8] = mesh_area;
    out
}

/// One region's contact.
#[allow(clippy::too_many_arguments)]
fn region_contact(
    setup: &Setup,
    roots: &[u32],
    full: &[bool],
    flat: &[(u32, [Vector3; 3])],
    region: u32,
    solid: &Solid,
    pose_a: &Isometry3,
    pose_b: &Isometry3,
    unit: f64,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let mut slice = Slice::default();
    let mut f = |t: f64| integrand(setup, roots, full, region, t, &mut slice);
    let mut r = [0.0; COMPONENTS];
    let n = setup.cuts.len();
    let mut start = 0;
    while start + 1 < n {
        let end = (start + MAX_PIECES).min(n - 1);
        let mut cuts = setup.cuts[start..=end].to_vec();
        let part = ADAPTIVE.integrate_pieces(&mut cuts, &mut f, &floor, work);
        for k in 0..COMPONENTS {
            r[k] += part[k];
        }
        start = end;
    }
    // The caps: the section's limit from inside at t = 0 and t = L.
    for (t, sign) in [(0.0, -1.0), (setup.profile.len, 1.0)] {
        let c = integrand(setup, roots, full, region, t, &mut slice);
        r[6] += sign * c[0];
        r[7] += c[0];
    }
    // Mesh faces parallel to the slices, by their overlap with the disc at their height.
    for (tri, v) in flat {
        let joined = setup.mesh.neighbours[*tri as usize]
            .iter()
            .any(|&n| roots[n as usize] == region);
        let h = v[0].z;
        if !joined || h < 0.0 || h > setup.profile.len {
            continue;
        }
        let mut polygon = [v[0].xy(), v[1].xy(), v[2].xy()];
        let twice = (polygon[1] - polygon[0]).perp(&(polygon[2] - polygon[0]));
        if twice < 0.0 {
            polygon.swap(1, 2);
        }
        r[8] += disc_section(setup.profile.radius(h), &polygon, &[0; 3]).area;
    }
    let volume = r[0];
    if volume.is_nan() || volume <= 0.0 {
        return None;
    }
    let centroid = pose_a * Point3::from(Vector3::new(r[2], r[3], r[1]) / volume * unit);
    let s_solid = pose_a.rotation * Vector3::new(r[4], r[5], r[6]) * (unit * unit);
    let (solid_area, mesh_area) = (r[7], r[8]);
    let moments = VolumeMoments {
        volume: volume * unit * unit * unit,
        centroid,
        area_vector_a: s_solid,
        surface_area: (solid_area + mesh_area) * unit * unit,
        length: unit,
    };
    let mesh = setup.mesh;
    let solid_inside = mesh_area <= ENCLOSED * (solid_area + mesh_area);
    let fallback = || {
        if solid_inside {
            let c = pose_b.inverse_transform_point(&centroid);
            let q = closest_on_mesh(mesh, &c);
            let away = pose_b.rotation * (q - c);
            if away.norm() > 0.0 {
                away.normalize()
            } else {
                Vector3::z()
            }
        } else {
            let p = pose_a.inverse_transform_point(&centroid).coords;
            -(pose_a.rotation * signed_distance(solid, &p).2)
        }
    };
    let on_mesh = |g: &Point3, d: &Vector3| {
        let from = pose_b.inverse_transform_point(g);
        let direction = pose_b.inverse_transform_vector(d);
        pose_b * exit_along(mesh, &from, &direction).unwrap_or_else(|| closest_on_mesh(mesh, &from))
    };
    volume_contact::contact_of_region(
        &moments,
        |g, d| surface_point_along_w(solid, pose_a, g, d),
        on_mesh,
        fallback,
        false,
    )
}
