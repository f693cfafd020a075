//! A cylinder, a frustum (cone) or a ring torus against a closed triangle mesh (taken as
//! exact): the intersection's moments by slicing perpendicular to the solid's axis, one
//! contact per connected region. A cylinder against a mesh whose components are apart and
//! small takes each component in closed form instead ([`crate::methods::cylinder_polyhedron`]),
//! unless a face is within 1e-3 of parallel to its axis, a cap's section is not clear-cut, or
//! a component's pieces are not shown to be one region.
//!
//! ## The slices
//! In the solid's frame (axis `z`, lengths divided by a power of two near its size) the plane
//! `z = t` cuts the solid in the disc of radius `r(t) = r₀ + k t` (`0 ≤ t ≤ L`), or a torus
//! in the annulus `R − s ≤ |p| ≤ R + s`, `s = √(ρ² − t²)`, and the mesh in its section,
//! directed segments with the mesh on their left ([`section`]). Their overlap is bounded by
//! *chords* (the segments' parts inside the disc or annulus: the mesh surface inside the
//! solid) and *arcs* (the circles inside the section: the solid's surface inside the mesh;
//! the inner circle's run clockwise); each piece is summed about the axis in closed form, so
//! each part of the overlap gets its own area and first moments.
//!
//! - `V = ∫ area dt`, the centroid from `∫(∫p dA, t·area) dt / V`.
//! - The area vector of the solid's lateral surface inside the mesh, by the moving section:
//!   an arc sweeps `(ν − r′ e_z) r dφ dt` (the torus' inner circle, whose outward normal is
//!   `−ν`, `(−ν + r_i′ e_z) r_i dφ dt`); the caps add `∓e_z` times their overlap with the
//!   section at `t = 0, L` (the section's limit from inside). The mesh's surface inside closes
//!   the same region: `S_mesh = −S_solid`. A torus is integrated in the angle `θ` of
//!   `t = ρ sin θ`, as in [`super::box_revolved`].
//! - Unsigned areas: the lateral surface's `√(1 + k²) r A` per slice, a chord's length over
//!   its triangle's `|n_xy|/|n|` (the triangle's area per unit of height and length), and a
//!   triangle parallel to the slices by its overlap with the disc at its height.
//!
//! The quadrature ([`crate::quadrature::Adaptive`], the box–revolved pairs' tolerance) runs
//! between cuts where the overlap's combinatorics change: the mesh's vertex heights and the
//! [`events`] (a circle touching a triangle's section line inside the segment, a mesh edge
//! piercing the lateral surface). Between cuts the overlap is smooth or has a square-root
//! end.
//!
//! ## Regions
//! Labelled once per piece between cuts, at its middle, where the combinatorics hold for the
//! whole piece ([`regions`]): chords along a section loop, the two ends of each arc (walking a
//! circle counter-clockwise from a segment leaving its disc to the next crossing), holes
//! joined by a ray to the first boundary; across the cuts through the triangles crossing
//! them and the circles wholly inside the section. Each region is then integrated on its own
//! pieces.
//!
//! ## The contact (SPEC §4)
//! As [`super::box_revolved`]: normal `−S_solid/|S_solid|` (from the mesh into the solid), the
//! points where the line through the centroid along it leaves each body (the mesh's first
//! surface along the line, or its closest point when the line misses), area `|S|`. When `|S|`
//! vanishes: with no mesh surface inside the solid, the solid lies in the mesh and the normal
//! points from the centroid to the mesh's closest point; otherwise against the solid's outward
//! normal at its surface point nearest the centroid. Touching is no contact.

mod events;
mod region;
mod regions;
pub(crate) mod section;

pub(crate) use region::Region;
use region::area_scale;
pub(crate) use region::{fallback, on_mesh};

use super::mesh_plane::PreparedMesh;
use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::solid_distance::Solid;
use contact_core::{Isometry3, Vector2, Vector3, WorkCounters};
use section::{Crossing, SlicedTriangle, clip_to_disc};
use std::f64::consts::TAU;

/// Heights (working units) this close are one cut.
const MERGE: f64 = 1e-12;

/// The solid's sections, working units.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Profile {
    /// The disc of radius `r0 + slope·t` for `0 ≤ t ≤ len`.
    Frustum { r0: f64, slope: f64, len: f64 },
    /// The annulus `big ± √(small² − t²)` for `|t| ≤ small`.
    Torus { big: f64, small: f64 },
}

impl Profile {
    /// The profile of a cylinder, frustum or torus (in its own lengths) and its size; `None`
    /// for a box.
    pub(crate) fn of(solid: &Solid) -> Option<(Self, f64)> {
        match *solid {
            Solid::Cylinder(c) => Some((
                Self::Frustum {
                    r0: c.radius(),
                    slope: 0.0,
                    len: c.length(),
                },
                c.radius().max(c.length()),
            )),
            Solid::Frustum(f) => {
                let (r0, r1, len) = (f.bottom_radius(), f.top_radius(), f.length());
                Some((
                    Self::Frustum {
                        r0,
                        slope: (r1 - r0) / len,
                        len,
                    },
                    r0.max(r1).max(len),
                ))
            }
            Solid::Torus(t) => Some((
                Self::Torus {
                    big: t.major_radius(),
                    small: t.minor_radius(),
                },
                t.major_radius() + t.minor_radius(),
            )),
            Solid::Box(_) => None,
        }
    }

    /// The same profile in lengths divided by `unit` (the slope is a ratio and stays).
    pub(crate) fn scaled(self, unit: f64) -> Self {
        match self {
            Self::Frustum { r0, slope, len } => Self::Frustum {
                r0: r0 / unit,
                slope,
                len: len / unit,
            },
            Self::Torus { big, small } => Self::Torus {
                big: big / unit,
                small: small / unit,
            },
        }
    }

    /// The heights the solid spans.
    pub(crate) fn range(&self) -> (f64, f64) {
        match *self {
            Self::Frustum { len, .. } => (0.0, len),
            Self::Torus { small, .. } => (-small, small),
        }
    }

    /// The outer and inner radii at `t` (the inner is 0 for a frustum: no inner circle).
    pub(crate) fn circles(&self, t: f64) -> (f64, f64) {
        match *self {
            Self::Frustum { r0, slope, .. } => ((r0 + slope * t).max(0.0), 0.0),
            Self::Torus { big, small } => {
                let s = ((small - t) * (small + t)).max(0.0).sqrt();
                // A sphere is the torus of no major radius: no inner circle.
                (big + s, if s > 0.0 { (big - s).max(0.0) } else { 0.0 })
            }
        }
    }

    /// The largest radius.
    pub(crate) fn outer(&self) -> f64 {
        match *self {
            Self::Frustum { r0, slope, len } => r0.max(r0 + slope * len),
            Self::Torus { big, small } => big + small,
        }
    }
}

/// One slice's overlap pieces.
#[derive(Debug, Default)]
pub(crate) struct Slice {
    /// `(segment, chord start, chord end, whole segment inside the overlap)`.
    pub chords: Vec<(usize, Vector2, Vector2, bool)>,
    /// The segments' crossings with the outer circle, by angle.
    pub outer: Vec<Crossing>,
    /// With the inner circle (a torus'), by angle.
    pub inner: Vec<Crossing>,
    /// The segments: `(triangle, start, start edge, end, end edge)`.
    pub segments: Vec<(u32, Vector2, u8, Vector2, u8)>,
}

/// What is fixed for one query.
pub(crate) struct Setup<'a> {
    pub profile: Profile,
    sliced: Vec<SlicedTriangle>,
    /// Sorted heights between which the combinatorics hold.
    pub cuts: Vec<f64>,
    /// `active[p]`: the sliced triangles crossing piece `p`.
    active: Vec<Vec<u32>>,
    pub mesh: &'a PreparedMesh,
    /// For an ellipsoid sliced as the unit sphere: the cofactor `(bc, ac, ab)` of its
    /// semi-axes, which maps area vectors back (the solid's unsigned area element is
    /// `|cof ∘ ν| dA` on the sphere).
    cofactor: Option<Vector3>,
}

impl Setup<'_> {
    /// The slice at `t` of piece `p`.
    pub(crate) fn slice(&self, p: usize, t: f64, out: &mut Slice) {
        out.chords.clear();
        out.outer.clear();
        out.inner.clear();
        out.segments.clear();
        let (ro, ri) = self.profile.circles(t);
        for &s in &self.active[p] {
            let tri = &self.sliced[s as usize];
            let (a, ae, b, be) = tri.segment(t);
            let k = out.segments.len();
            out.segments.push((tri.index, a, ae, b, be));
            if ro <= 0.0 {
                continue;
            }
            let (outer_from, inner_from) = (out.outer.len(), out.inner.len());
            let Some((l0, l1)) = clip_to_disc(&a, &b, ro, recorder(&mut out.outer)) else {
                continue;
            };
            let d = b - a;
            // The part inside the inner disc is not in the annulus.
            let hole = if ri > 0.0 {
                clip_to_disc(&a, &b, ri, recorder(&mut out.inner))
            } else {
                None
            };
            let first = out.chords.len();
            match hole {
                Some((m0, m1)) => {
                    if m0 > l0 {
                        out.chords.push((k, a + l0 * d, a + m0 * d, false));
                    }
                    if l1 > m1 {
                        out.chords.push((k, a + m1 * d, a + l1 * d, false));
                    }
                }
                None => out
                    .chords
                    .push((k, a + l0 * d, a + l1 * d, l0 == 0.0 && l1 == 1.0)),
            }
            // A crossing into a disc ends the segment's chord before it, one out of a disc
            // starts the one after: the outer circle's into the first chord, out of the last;
            // the inner circle's the other way about.
            let last = out.chords.len().saturating_sub(1).max(first);
            for c in &mut out.outer[outer_from..] {
                c.chord = if c.leaves { last } else { first };
            }
            for c in &mut out.inner[inner_from..] {
                c.chord = if c.leaves { last } else { first };
            }
        }
        out.outer.sort_by(|x, y| x.angle.total_cmp(&y.angle));
        out.inner.sort_by(|x, y| x.angle.total_cmp(&y.angle));
    }
}

/// A crossing recorder into `list` (the chord is set once the segment's chords are known).
fn recorder(list: &mut Vec<Crossing>) -> impl FnMut(Vector2, bool) + '_ {
    move |x, leaves| {
        list.push(Crossing {
            angle: x.y.atan2(x.x),
            leaves,
            chord: 0,
        })
    }
}

/// Each arc of a circle inside the section: `(leaving crossing, start angle, sweep)`.
pub(crate) fn arcs(crossings: &[Crossing]) -> impl Iterator<Item = (usize, f64, f64)> + '_ {
    let n = crossings.len();
    (0..n).filter(|&i| crossings[i].leaves).map(move |i| {
        let next = &crossings[(i + 1) % n];
        let mut sweep = next.angle - crossings[i].angle;
        if sweep < 0.0 || n == 1 {
            sweep += TAU;
        }
        (i, crossings[i].angle, sweep)
    })
}

/// The contacts of `solid` (a cylinder, frustum or torus, `a`, at `pose_a`) with `mesh`
/// (`b`, at `pose_b`), one per region, normals from `b` into `a`. A box gives none.
pub(crate) fn contacts(
    solid: &Solid,
    pose_a: &Isometry3,
    mesh: &PreparedMesh,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    // A cylinder against a mesh's parts: each in closed form where it can.
    if let Solid::Cylinder(c) = solid {
        if crate::methods::cylinder_polyhedron::mesh::mesh_contacts(
            c, pose_a, mesh, pose_b, work, emit,
        ) {
            return;
        }
    }
    let Some((profile, size)) = Profile::of(solid) else {
        return;
    };
    let unit = unit_for(size);
    let profile = profile.scaled(unit);
    let relative = pose_a.inv_mul(pose_b);
    let (z0, z1) = profile.range();
    let outer = profile.outer();
    let reach = (relative * mesh.centre).coords / unit;
    let radius = mesh.radius / unit;
    // The mesh's ball must reach the solid (a cavity's solid reaches everywhere).
    if !mesh.inverted
        && (reach.z + radius <= z0 || reach.z - radius >= z1 || reach.xy().norm() - radius >= outer)
    {
        return;
    }
    let local: Vec<Vector3> = mesh
        .vertices
        .iter()
        .map(|v| (relative * v).coords / unit)
        .collect();
    sliced_regions(
        profile,
        &local,
        mesh,
        None,
        work,
        &mut |region, root, work| {
            if let Some(c) = region.contact(root, solid, pose_a, pose_b, unit, work) {
                emit(c);
            }
        },
    );
}

/// Slices `mesh` (its vertices `local` in the solid's frame, working units) against the
/// solid of `profile`, labels the regions and hands each to `per_region` with its root.
pub(crate) fn sliced_regions(
    profile: Profile,
    local: &[Vector3],
    mesh: &PreparedMesh,
    cofactor: Option<Vector3>,
    work: &mut WorkCounters,
    per_region: &mut dyn FnMut(&Region, u32, &mut WorkCounters),
) {
    let (sliced, flat, mut heights) = reaching_triangles(&profile, local, mesh, cofactor, work);
    events::add_events(&sliced, local, mesh, &profile, &mut heights);
    let cuts = merged_cuts(heights, profile.range().1);
    let pieces = cuts.len() - 1;
    let active = active_triangles(&cuts, &sliced);
    let setup = Setup {
        profile,
        sliced,
        cuts,
        active,
        mesh,
        cofactor,
    };
    let (labels, mut forest) = regions::label(&setup, local);
    let roots: Vec<u32> = (0..labels.nodes() as u32).map(|n| forest.find(n)).collect();
    let (found, touched) = found_regions(&setup, &labels, &roots, pieces);
    let region = Region {
        setup: &setup,
        roots: &roots,
        labels: &labels,
        flat: &flat,
        touched: &touched,
    };
    for root in found {
        per_region(&region, root, work);
    }
}

/// A triangle parallel to the slices: its index in the mesh and its vertices.
type FlatTriangle = (u32, [Vector3; 3]);

/// The triangles of `mesh` (vertices `local`) that can reach the bounding box of the solid of
/// `profile`: those that cross the slices (their area scaled by `cofactor`, see
/// [`area_scale`]), those parallel to them (`flat`), and the heights where the section may
/// change (the range's ends and the vertices within it).
fn reaching_triangles(
    profile: &Profile,
    local: &[Vector3],
    mesh: &PreparedMesh,
    cofactor: Option<Vector3>,
    work: &mut WorkCounters,
) -> (Vec<SlicedTriangle>, Vec<FlatTriangle>, Vec<f64>) {
    let (z0, z1) = profile.range();
    let outer = profile.outer();
    // The triangles that can reach the solid's bounding box.
    let mut sliced = Vec::new();
    let mut flat = Vec::new();
    let mut heights = vec![z0, z1];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let v = tri.map(|i| local[i as usize]);
        let (lo, hi) = (v[0].inf(&v[1]).inf(&v[2]), v[0].sup(&v[1]).sup(&v[2]));
        if hi.z < z0 || lo.z > z1 || lo.x > outer || hi.x < -outer || lo.y > outer || hi.y < -outer
        {
            continue;
        }
        work.primitive_tests += 1;
        for p in &v {
            if p.z > z0 && p.z < z1 {
                heights.push(p.z);
            }
        }
        match SlicedTriangle::new(t as u32, v) {
            Some(mut s) => {
                s.scale = area_scale(&v, cofactor);
                sliced.push(s)
            }
            None => flat.push((t as u32, v)),
        }
    }
    (sliced, flat, heights)
}

/// The cuts from the event `heights`, sorted, those closer than [`MERGE`] merged, the last
/// set to the solid's top `z1`.
fn merged_cuts(mut heights: Vec<f64>, z1: f64) -> Vec<f64> {
    // Heights closer than `MERGE` are one cut: vertices on one plane of the mesh reach the
    // solid's frame a few ulps apart, and a piece between them would be labelled at a middle
    // whose combinatorics are those of neither side.
    heights.sort_by(f64::total_cmp);
    let mut cuts: Vec<f64> = Vec::with_capacity(heights.len());
    for h in heights {
        match cuts.last() {
            Some(&last) if h - last <= MERGE => {}
            _ => cuts.push(h),
        }
    }
    if let Some(last) = cuts.last_mut() {
        *last = z1;
    }
    cuts
}

/// Per piece between `cuts`, the `sliced` triangles spanning it (to [`MERGE`]).
fn active_triangles(cuts: &[f64], sliced: &[SlicedTriangle]) -> Vec<Vec<u32>> {
    cuts.windows(2)
        .map(|w| {
            (0..sliced.len() as u32)
                .filter(|&s| {
                    let (lo, hi) = sliced[s as usize].range();
                    lo <= w[0] + MERGE && hi >= w[1] - MERGE
                })
                .collect()
        })
        .collect()
}

/// The regions' roots (`roots` per node of `labels`), in the order of their smallest node,
/// and the (triangle, root) pairs of the triangles each touches (for the faces parallel to
/// the slices), both sorted and without repeats.
fn found_regions(
    setup: &Setup,
    labels: &regions::Labels,
    roots: &[u32],
    pieces: usize,
) -> (Vec<u32>, Vec<(u32, u32)>) {
    // The regions, in the order of their smallest node, and the triangles each touches (for
    // the faces parallel to the slices).
    let mut found: Vec<u32> = Vec::new();
    let mut touched: Vec<(u32, u32)> = Vec::new();
    let mut scratch = Slice::default();
    for p in 0..pieces {
        let Some(t) = regions::middle(setup, p) else {
            continue;
        };
        setup.slice(p, t, &mut scratch);
        for (c, &(k, ..)) in scratch.chords.iter().enumerate() {
            let root = roots[labels.offsets[p] + c];
            found.push(root);
            touched.push((scratch.segments[k].0, root));
        }
        if labels.outer[p] {
            found.push(roots[labels.outer_node(p)]);
        }
        if labels.inner[p] {
            found.push(roots[labels.inner_node(p)]);
        }
    }
    touched.sort_unstable();
    touched.dedup();
    found.sort_unstable();
    found.dedup();
    (found, touched)
}
