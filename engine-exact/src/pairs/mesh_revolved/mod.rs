//! A cylinder, a frustum (cone) or a ring torus against a closed triangle mesh (taken as
//! exact): the intersection's moments by slicing perpendicular to the solid's axis, one
//! contact per connected region.
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
mod regions;
pub(crate) mod section;

use super::clipped::unit_for;
use super::disc_section::disc_section;
use super::ellipsoid_sliced::{ADAPTIVE, COMPONENTS, floor};
use super::mesh_plane::{PreparedMesh, closest_on_mesh, exit_along};
use super::solid_distance::{Solid, signed_distance};
use super::volume_contact::{self, ENCLOSED, VolumeMoments};
use crate::kernel::PairContact;
use crate::quadrature::MAX_PIECES;
use crate::ray_exit::surface_point_along_w;
use contact_core::{Isometry3, Point3, Vector2, Vector3, WorkCounters};
use section::{Crossing, SlicedTriangle, arc_moments, chord_moments, clip_to_disc};
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
                (big + s, if s > 0.0 { big - s } else { 0.0 })
            }
        }
    }

    /// The largest radius.
    fn outer(&self) -> f64 {
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
    let (profile, size) = match *solid {
        Solid::Cylinder(c) => (
            Profile::Frustum {
                r0: c.radius(),
                slope: 0.0,
                len: c.length(),
            },
            c.radius().max(c.length()),
        ),
        Solid::Frustum(f) => {
            let (r0, r1, len) = (f.bottom_radius(), f.top_radius(), f.length());
            (
                Profile::Frustum {
                    r0,
                    slope: (r1 - r0) / len,
                    len,
                },
                r0.max(r1).max(len),
            )
        }
        Solid::Torus(t) => (
            Profile::Torus {
                big: t.major_radius(),
                small: t.minor_radius(),
            },
            t.major_radius() + t.minor_radius(),
        ),
        Solid::Box(_) => return,
    };
    let unit = unit_for(size);
    let profile = match profile {
        Profile::Frustum { r0, slope, len } => Profile::Frustum {
            r0: r0 / unit,
            slope,
            len: len / unit,
        },
        Profile::Torus { big, small } => Profile::Torus {
            big: big / unit,
            small: small / unit,
        },
    };
    let (z0, z1) = profile.range();
    let outer = profile.outer();
    let relative = pose_a.inv_mul(pose_b);
    let reach = (relative * mesh.centre).coords / unit;
    let radius = mesh.radius / unit;
    if reach.z + radius <= z0 || reach.z - radius >= z1 || reach.xy().norm() - radius >= outer {
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
            Some(s) => sliced.push(s),
            None => flat.push((t as u32, v)),
        }
    }
    events::add_events(&sliced, &local, mesh, &profile, &mut heights);
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
    let pieces = cuts.len() - 1;
    let active: Vec<Vec<u32>> = cuts
        .windows(2)
        .map(|w| {
            (0..sliced.len() as u32)
                .filter(|&s| {
                    let (lo, hi) = sliced[s as usize].range();
                    lo <= w[0] + MERGE && hi >= w[1] - MERGE
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
    let (labels, mut forest) = regions::label(&setup, &local);
    let roots: Vec<u32> = (0..labels.nodes() as u32).map(|n| forest.find(n)).collect();
    // The regions, in the order of their smallest node, and the triangles each touches (for
    // the faces parallel to the slices).
    let mut found: Vec<u32> = Vec::new();
    let mut touched: Vec<(u32, u32)> = Vec::new();
    let mut scratch = Slice::default();
    for p in 0..pieces {
        let Some(t) = regions::middle(&setup, p) else {
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
    let region = Region {
        setup: &setup,
        roots: &roots,
        labels: &labels,
        flat: &flat,
        touched: &touched,
    };
    for root in found {
        if let Some(c) = region.contact(root, solid, pose_a, pose_b, unit, work) {
            emit(c);
        }
    }
}

/// What a region's integration reads.
struct Region<'a> {
    setup: &'a Setup<'a>,
    roots: &'a [u32],
    labels: &'a regions::Labels,
    flat: &'a [(u32, [Vector3; 3])],
    /// `(triangle, root)` for every chord, sorted.
    touched: &'a [(u32, u32)],
}

impl Region<'_> {
    /// The integrand for region `root` at `x` (the height `t` for a frustum, the angle `θ` of
    /// `t = ρ sin θ` for a torus): `[area, t·area, ∫x, ∫y, S_solid (3), solid's surface inside
    /// the mesh, mesh's surface inside the solid]` per unit of `x`.
    fn integrand(&self, root: u32, x: f64, slice: &mut Slice) -> [f64; COMPONENTS] {
        let setup = self.setup;
        let mut out = [0.0; COMPONENTS];
        // t, dt/dx, and per circle the factor of `r·sweep` in S_z and in the unsigned area.
        let (t, jacobian, (sz_outer, sz_inner), unsigned) = match setup.profile {
            Profile::Frustum { slope, .. } => (x, 1.0, (-slope, 0.0), (1.0 + slope * slope).sqrt()),
            Profile::Torus { small, .. } => {
                let (sin, cos) = x.sin_cos();
                let (t, s) = (small * sin, small * cos);
                if s.is_nan() || s <= 0.0 {
                    return out;
                }
                (t, s, (t, t), small)
            }
        };
        let labels = self.labels;
        let pieces = labels.outer.len();
        let p = setup
            .cuts
            .partition_point(|&c| c <= t)
            .saturating_sub(1)
            .min(pieces.saturating_sub(1));
        let (ro, ri) = setup.profile.circles(t);
        if ro <= 0.0 {
            return out;
        }
        setup.slice(p, t, slice);
        let node = |c: usize| labels.offsets[p] + c;
        let mut mesh_area = 0.0;
        let mut add = |m: [f64; 3], sign: f64| {
            out[0] += sign * m[0];
            out[2] += sign * m[1];
            out[3] += sign * m[2];
        };
        for (c, &(k, a, e, _)) in slice.chords.iter().enumerate() {
            if self.roots.get(node(c)) != Some(&root) {
                continue;
            }
            add(chord_moments(&a, &e), 1.0);
            let slope = setup.sliced[setup.active[p][k] as usize].slope;
            mesh_area += (e - a).norm() / slope;
        }
        // Per circle: radius, orientation (+1 outer, −1 inner), S_z factor, crossings, full.
        let mut lateral = [0.0; 4];
        let circles = [
            (
                ro,
                1.0,
                sz_outer,
                &slice.outer,
                labels.outer[p],
                labels.outer_node(p),
            ),
            (
                ri,
                -1.0,
                sz_inner,
                &slice.inner,
                labels.inner[p],
                labels.inner_node(p),
            ),
        ];
        for (r, sign, sz, crossings, full, full_node) in circles {
            if r <= 0.0 {
                continue;
            }
            let mut swept = |start: f64, sweep: f64| {
                let (m, normal) = arc_moments(r, start, sweep);
                add(m, sign);
                lateral[0] += sign * r * normal.x;
                lateral[1] += sign * r * normal.y;
                lateral[2] += sz * r * sweep;
                lateral[3] += unsigned * r * sweep;
            };
            if crossings.is_empty() {
                if full && self.roots[full_node] == root {
                    swept(0.0, TAU);
                }
            } else {
                for (i, start, sweep) in arcs(crossings) {
                    if self.roots.get(node(crossings[i].chord)) == Some(&root) {
                        swept(start, sweep);
                    }
                }
            }
        }
        // Per dx: the sections' terms times dt/dx; the swept S_z and unsigned terms already
        // are (a torus' `(t/s)·r·sweep` and `(ρ/s)·r·sweep` per dt are `t·r·sweep` and
        // `ρ·r·sweep` per dθ, smooth where `s` vanishes).
        out[0] *= jacobian;
        out[2] *= jacobian;
        out[3] *= jacobian;
        out[1] = t * out[0];
        out[4] = lateral[0] * jacobian;
        out[5] = lateral[1] * jacobian;
        out[6] = lateral[2];
        out[7] = lateral[3];
        out[8] = mesh_area * jacobian;
        out
    }

    /// Region `root`'s contact.
    fn contact(
        &self,
        root: u32,
        solid: &Solid,
        pose_a: &Isometry3,
        pose_b: &Isometry3,
        unit: f64,
        work: &mut WorkCounters,
    ) -> Option<PairContact> {
        let setup = self.setup;
        let mut slice = Slice::default();
        let torus = matches!(setup.profile, Profile::Torus { .. });
        let small = match setup.profile {
            Profile::Torus { small, .. } => small,
            Profile::Frustum { .. } => 1.0,
        };
        let mapped: Vec<f64> = if torus {
            setup
                .cuts
                .iter()
                .map(|c| (c / small).clamp(-1.0, 1.0).asin())
                .collect()
        } else {
            setup.cuts.clone()
        };
        let mut f = |x: f64| self.integrand(root, x, &mut slice);
        let mut r = [0.0; COMPONENTS];
        let n = mapped.len();
        let mut start = 0;
        while start + 1 < n {
            let end = (start + MAX_PIECES).min(n - 1);
            let mut cuts = mapped[start..=end].to_vec();
            let part = ADAPTIVE.integrate_pieces(&mut cuts, &mut f, &floor, work);
            for k in 0..COMPONENTS {
                r[k] += part[k];
            }
            start = end;
        }
        let mut slice = Slice::default();
        // A frustum's caps: the section's limit from inside at t = 0 and t = L.
        if let Profile::Frustum { len, .. } = setup.profile {
            for (t, sign) in [(0.0, -1.0), (len, 1.0)] {
                let c = self.integrand(root, t, &mut slice);
                r[6] += sign * c[0];
                r[7] += c[0];
            }
        }
        // Mesh faces parallel to the slices, by their overlap with the section at their height.
        let (z0, z1) = setup.profile.range();
        for (tri, v) in self.flat {
            let joined = setup.mesh.neighbours[*tri as usize]
                .iter()
                .any(|&n| self.touched.binary_search(&(n, root)).is_ok());
            let h = v[0].z;
            if !joined || h < z0 || h > z1 {
                continue;
            }
            let mut polygon = [v[0].xy(), v[1].xy(), v[2].xy()];
            if (polygon[1] - polygon[0]).perp(&(polygon[2] - polygon[0])) < 0.0 {
                polygon.swap(1, 2);
            }
            let (ro, ri) = setup.profile.circles(h);
            r[8] +=
                disc_section(ro, &polygon, &[0; 3]).area - disc_section(ri, &polygon, &[0; 3]).area;
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
            pose_b
                * exit_along(mesh, &from, &direction)
                    .unwrap_or_else(|| closest_on_mesh(mesh, &from))
        };
        volume_contact::contact_of_region(
            &moments,
            |g, d| surface_point_along_w(solid, pose_a, g, d),
            on_mesh,
            fallback,
            false,
        )
    }
}
