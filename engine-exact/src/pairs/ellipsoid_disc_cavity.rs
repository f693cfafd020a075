//! An ellipsoid (a sphere included) in a cylinder- or frustum-shaped cavity: a flipped
//! cylinder or frustum, whose material is everything outside it. One contact per connected
//! region of the ellipsoid outside the cavity.
//!
//! ## The slices
//! In the cavity's frame (axis `z`, ends at `0` and `length`, lengths divided by a power of
//! two near the pair's size) the plane `z = t` cuts the ellipsoid in an ellipse, seen as the
//! unit disc ([`crate::methods::ellipsoid_sliced`]), and the cavity in the disc of radius
//! `r(t)`, an ellipse in the same coordinates. Between the ends the region's section is the
//! unit disc less that ellipse, one *lune* per component in closed form
//! ([`disc_less_ellipse`]); beyond them it is the whole section. Each lune is integrated as
//! the ellipsoid pairs integrate an overlap: area and moments for the volume and centroid;
//! the circle's arcs (the ellipsoid's surface in the material) for the area vector `S`; the
//! cavity's wall inside the ellipsoid, `√(1 + r′²)·r·Δφ` per slice, and its end discs'
//! overlap with the section for the unsigned surface.
//!
//! ## Regions
//! The slicing range is cut at the ellipsoid's ends, the cavity's ends and the slices where
//! the section's crossings with the cavity's circle change in number
//! ([`shape_events`]); between two cuts the lunes keep their number and their cyclic order
//! on the ellipsoid's circle, so each piece labels its lunes once, at its middle, and every
//! other slice maps its lunes onto those labels (the cyclic shift nearest in the arcs'
//! middles). Across a cut, a lune just below and one just above are one region when their
//! circle arcs overlap (where two lunes merge at a tangency, the merged arc overlaps both);
//! a section beyond an end is one piece of material, so every lune at an end joins it.
//!
//! ## The contact (SPEC §4)
//! Normal `−S/|S|` (the ellipsoid's surface in the material, outward: the force pushes it
//! back into the cavity). Points on the line through the centroid `g` along it: with `g` in
//! the material, where the line leaves the ellipsoid along `−n` and enters the cavity along
//! `+n`; with `g` in the cavity (a crescent pressed into the wall), the chord the line cuts
//! through the region beside `g` (on either side, the first crossings of the two surfaces,
//! the nearer chord whose middle lies in both bodies), as the faceted engine reads a region
//! whose centroid lies outside a body; failing both, the cavity's closest point. When `S`
//! vanishes (the ellipsoid wholly in the material, holding the whole cavity, or a ring all
//! round the wall: `|S|` within 1e-9 of the region's surface) the normal points from the
//! centroid to the cavity's closest surface point.

use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::ellipsoid_sliced::disc_less::{Lunes, MAX_LUNES, disc_less_ellipse};
use crate::methods::ellipsoid_sliced::disc_overlap::disc_ellipse;
use crate::methods::ellipsoid_sliced::{
    ADAPTIVE, COMPONENTS, Integrals, SlicedEllipsoid, ellipsoid_exit_w, ellipsoid_in, floor,
    integrand, shape_events, to_world,
};
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::methods::volume_contact::contact_of_region;
use crate::ray_exit::{frustum_line_interval, surface_point_along};
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use nalgebra::Matrix2;
use std::f64::consts::TAU;

/// Most cuts of the slicing range (the ellipsoid's two ends, the cavity's two, and the
/// shape changes between).
const MAX_CUTS: usize = 24;

/// Where, as a fraction of a piece, the lunes next to a cut are read for the regions'
/// connections across it.
const NEAR_CUT: f64 = 1e-6;

/// `|S|` at or below this fraction of the region's surface counts as vanishing (the
/// quadratures hold `S` to about 1e-12 of the surface; a region whose `S` is that small is a
/// ring all round the cavity, or nearly).
const SYMMETRIC: f64 = 1e-9;

/// Cuts closer than this fraction of the ellipsoid's height are one.
const MERGE: f64 = 1e-9;

/// The cavity's profile: the disc of radius `r0 + slope·t`, `0 ≤ t ≤ length`.
#[derive(Debug, Clone, Copy)]
struct Profile {
    r0: f64,
    r1: f64,
    length: f64,
}

impl Profile {
    /// The profile of a cylinder or frustum; `None` for a box or a torus.
    fn of(cavity: &Solid) -> Option<Self> {
        match *cavity {
            Solid::Cylinder(c) => Some(Self {
                r0: c.radius(),
                r1: c.radius(),
                length: c.length(),
            }),
            Solid::Frustum(f) => Some(Self {
                r0: f.bottom_radius(),
                r1: f.top_radius(),
                length: f.length(),
            }),
            Solid::Box(_) | Solid::Torus(_) => None,
        }
    }

    fn scaled(self, unit: f64) -> Self {
        Self {
            r0: self.r0 / unit,
            r1: self.r1 / unit,
            length: self.length / unit,
        }
    }

    /// `r(t)`, from the nearer end so both ends are exact.
    fn radius(&self, t: f64) -> f64 {
        let slope = (self.r1 - self.r0) / self.length;
        if t <= 0.5 * self.length {
            self.r0 + slope * t
        } else {
            self.r1 - slope * (self.length - t)
        }
    }

    /// The side's area per unit of arc and of height, `√(1 + r′²)`.
    fn stretch(&self) -> f64 {
        let slope = (self.r1 - self.r0) / self.length;
        (1.0 + slope * slope).sqrt()
    }
}

/// The ellipsoid's slices against the cavity's, in working units.
struct Slicing {
    a: SlicedEllipsoid,
    profile: Profile,
}

impl Slicing {
    /// The lunes of slice `t` with the slice's section, or `None` outside the ellipsoid.
    fn lunes(&self, t: f64) -> Option<(crate::methods::ellipsoid_sliced::Section, Lunes)> {
        let sa = self.a.section(t)?;
        if t < 0.0 || t > self.profile.length {
            return Some((sa, Lunes::whole_disc()));
        }
        let (center, hole) = self.hole(&sa, t)?;
        Some((sa, disc_less_ellipse(&center, &hole)))
    }

    /// The cavity's disc at `t` in the section's unit-disc coordinates.
    fn hole(
        &self,
        sa: &crate::methods::ellipsoid_sliced::Section,
        t: f64,
    ) -> Option<(nalgebra::Vector2<f64>, Matrix2<f64>)> {
        let inverse = sa.matrix.try_inverse()?;
        Some((
            inverse * -sa.center,
            inverse * self.profile.radius(t).max(0.0),
        ))
    }

    /// The crossing class of slice `t` (the cuts are where it changes).
    fn shape(&self, t: f64) -> usize {
        self.a
            .section(t)
            .and_then(|sa| self.hole(&sa, t))
            .map_or(0, |(c, m)| disc_ellipse(&c, &m).shape)
    }

    /// The unsigned rate of the cavity's wall inside the ellipsoid, for one lune.
    fn wall(
        &self,
        t: f64,
        lune: &crate::methods::ellipsoid_sliced::disc_overlap::DiscOverlap,
    ) -> f64 {
        let angle: f64 = lune
            .other_arcs
            .spans()
            .iter()
            .map(|(f0, f1)| (f1 - f0).abs())
            .sum();
        self.profile.stretch() * self.profile.radius(t).max(0.0) * angle
    }
}

/// The middle of a circle arc, in `[0, 2π)`.
fn arc_middle(lune: &crate::methods::ellipsoid_sliced::disc_overlap::DiscOverlap) -> f64 {
    lune.arcs
        .spans()
        .first()
        .map_or(0.0, |(t0, t1)| (0.5 * (t0 + t1)).rem_euclid(TAU))
}

/// The circle arc of a lune, `(start, end)` with `end ≥ start`.
fn arc_of(lune: &crate::methods::ellipsoid_sliced::disc_overlap::DiscOverlap) -> (f64, f64) {
    lune.arcs.spans().first().copied().unwrap_or((0.0, 0.0))
}

fn angular_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

/// Whether two circle arcs share more than a point.
fn arcs_overlap((a0, a1): (f64, f64), (b0, b1): (f64, f64)) -> bool {
    if a1 - a0 >= TAU || b1 - b0 >= TAU {
        return true;
    }
    let shift = (b0 - a0).rem_euclid(TAU);
    let (b0, b1) = (a0 + shift, a0 + shift + (b1 - b0));
    (b0 < a1) || (b1 > a0 + TAU)
}

/// Maps each lune of `here` to one of the `reference` middles: the cyclic shift nearest in
/// the arcs' middles when the counts agree; else one to one, each reference middle taking the
/// nearest lune left (a lune vanishing at a cut, read within round-off of it, is left out).
fn labels(reference: &[f64], here: &Lunes) -> [Option<usize>; MAX_LUNES] {
    let mut out = [None; MAX_LUNES];
    let parts = here.parts();
    let k = reference.len();
    if k == 0 {
        return out;
    }
    if parts.len() == k {
        let cost = |shift: usize| -> f64 {
            (0..k)
                .map(|j| {
                    angular_distance(reference[j], arc_middle(&parts[(j + shift) % k])).powi(2)
                })
                .sum()
        };
        let best = (0..k)
            .min_by(|&x, &y| cost(x).total_cmp(&cost(y)))
            .unwrap_or(0);
        for j in 0..k {
            out[(j + best) % k] = Some(j);
        }
        return out;
    }
    for (j, &m) in reference.iter().enumerate() {
        let nearest = (0..parts.len())
            .filter(|&i| out[i].is_none())
            .min_by(|&x, &y| {
                angular_distance(arc_middle(&parts[x]), m)
                    .total_cmp(&angular_distance(arc_middle(&parts[y]), m))
            });
        if let Some(i) = nearest {
            out[i] = Some(j);
        }
    }
    out
}

/// Union–find over the pieces' lunes.
struct Regions {
    parent: Vec<usize>,
}

impl Regions {
    fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    fn join(&mut self, x: usize, y: usize) {
        let (rx, ry) = (self.find(x), self.find(y));
        if rx != ry {
            self.parent[rx.max(ry)] = rx.min(ry);
        }
    }
}

/// One piece of the slicing range: its ends and the middles of its lunes' arcs at its middle.
struct Piece {
    lo: f64,
    hi: f64,
    middles: Vec<f64>,
    /// The index of its first lune among all pieces' lunes.
    first: usize,
}

/// Hands `emit` one contact per region of the ellipsoid with `semi_axes` at `pose_a` outside
/// the cylinder- or frustum-shaped cavity `cavity` at `pose_b`.
pub(crate) fn contacts(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    cavity: &Solid,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut impl FnMut(PairContact),
) {
    let Some(profile) = Profile::of(cavity) else {
        return;
    };
    let unit = unit_for(
        semi_axes
            .max()
            .max(profile.r0)
            .max(profile.r1)
            .max(profile.length),
    );
    let profile = profile.scaled(unit);
    let (c, l) = ellipsoid_in(pose_b, pose_a, semi_axes, unit);
    work.bounding_volume_tests += 1;
    let reach_z = l.row(2).norm();
    let reach_xy = (l.row(0).norm_squared() + l.row(1).norm_squared()).sqrt();
    // Wholly inside the cylinder of the cavity's smaller end radius: no material touched.
    if c.z - reach_z > 0.0
        && c.z + reach_z < profile.length
        && c.xy().norm() + reach_xy < profile.r0.min(profile.r1)
    {
        return;
    }
    let Some(a) = SlicedEllipsoid::new(c, &l) else {
        return;
    };
    let slicing = Slicing { a, profile };
    let pieces = pieces(&slicing);
    let mut regions = Regions {
        parent: (0..pieces.last().map_or(0, |p| p.first + p.middles.len())).collect(),
    };
    connect_across_cuts(&slicing, &pieces, &mut regions);
    let sums = integrate_regions(&slicing, &pieces, &mut regions, work);
    for (_, r) in sums {
        if r[0] <= 0.0 {
            continue;
        }
        let integrals = Integrals {
            volume: r[0],
            centroid: Vector3::new(r[2], r[3], r[1]) / r[0],
            area_vector_a: Vector3::new(r[4], r[5], r[6]),
            surface_a: r[7],
            surface_b: r[8],
        };
        let mut moments = to_world(&integrals, pose_b, unit);
        // A ring all round the wall (a ball a hair larger than the bore) has `S` at the
        // quadrature's round-off, whose direction is noise: taken as vanishing.
        if moments.area_vector_a.norm() <= SYMMETRIC * moments.surface_area {
            moments.area_vector_a = Vector3::zeros();
        }
        let points =
            |g: &Point3, n: &Vector3| cavity_points(semi_axes, pose_a, cavity, pose_b, g, n);
        let contact = contact_of_region(
            &moments,
            |g, d| points(g, &-d).0,
            |g, d| points(g, d).1,
            || toward_cavity(cavity, pose_b, &moments.centroid),
            false,
        );
        if let Some(contact) = contact {
            emit(contact);
        }
    }
}

/// The pieces between the cuts, each with its lunes' labels.
fn pieces(slicing: &Slicing) -> Vec<Piece> {
    let (e_lo, e_hi) = slicing.a.range();
    let length = slicing.profile.length;
    let mut cuts = [0.0; MAX_CUTS];
    cuts[..2].copy_from_slice(&[e_lo, e_hi]);
    let mut n = 2;
    for end in [0.0, length] {
        if end > e_lo && end < e_hi {
            cuts[n] = end;
            n += 1;
        }
    }
    let (lo, hi) = (e_lo.max(0.0), e_hi.min(length));
    if lo < hi {
        shape_events(lo, hi, |t| slicing.shape(t), &mut cuts, &mut n);
    }
    let mut cuts = cuts[..n].to_vec();
    cuts.sort_by(f64::total_cmp);
    // Changes the shape samples cannot see: a lune vanishing and another appearing within
    // one sample's spacing (the class the same on both sides).
    let mut hidden = Vec::new();
    for w in cuts.windows(2) {
        if w[0] >= lo && w[1] <= hi && w[1] > w[0] {
            hidden_events(slicing, w[0], w[1], &mut hidden);
        }
    }
    cuts.extend(hidden);
    cuts.sort_by(f64::total_cmp);
    // Cuts within round-off of each other are one change (a tangency bisected from both
    // sides): a piece between them would hold no slice of its own.
    let merge = MERGE * (e_hi - e_lo);
    let mut kept: Vec<f64> = Vec::with_capacity(cuts.len());
    for &c in &cuts {
        let is_end = c == e_lo || c == e_hi || c == 0.0 || c == length;
        match kept.last_mut() {
            Some(last) if c - *last <= merge => {
                if is_end {
                    *last = c;
                }
            }
            _ => kept.push(c),
        }
    }
    let cuts = kept;
    let mut out: Vec<Piece> = Vec::new();
    let mut first = 0;
    for w in cuts.windows(2) {
        let mid = 0.5 * (w[0] + w[1]);
        let middles: Vec<f64> = slicing
            .lunes(mid)
            .map(|(_, l)| l.parts().iter().map(arc_middle).collect())
            .unwrap_or_default();
        let count = middles.len();
        out.push(Piece {
            lo: w[0],
            hi: w[1],
            middles,
            first,
        });
        first += count;
    }
    out
}

/// Samples across a piece between shape changes in [`hidden_events`].
const CONTINUITY_SAMPLES: usize = 32;

/// Bisections of a discontinuity between two samples (down to 2⁻⁵⁰ of their spacing).
const CONTINUITY_DEPTH: usize = 50;

/// Whether the lunes at `t0` and `t1` are the same lunes moved: as many, and each (in the
/// cyclic order nearest in their middles) overlapping its match.
fn continuous(slicing: &Slicing, t0: f64, t1: f64) -> bool {
    let (Some((_, a)), Some((_, b))) = (slicing.lunes(t0), slicing.lunes(t1)) else {
        return true;
    };
    if a.parts().len() != b.parts().len() {
        return false;
    }
    let middles: Vec<f64> = a.parts().iter().map(arc_middle).collect();
    let label = labels(&middles, &b);
    b.parts()
        .iter()
        .zip(label)
        .all(|(p, j)| j.is_some_and(|j| arcs_overlap(arc_of(&a.parts()[j]), arc_of(p))))
}

/// Adds to `cuts` the changes inside `(lo, hi)` that keep the crossing class on both sides:
/// consecutive samples whose lunes are not [`continuous`] are bisected until a slice of
/// another class appears between them (then its two class changes are bisected to
/// round-off, as [`shape_events`] does) or the interval is at round-off (a cut there).
fn hidden_events(slicing: &Slicing, lo: f64, hi: f64, cuts: &mut Vec<f64>) {
    let at = |k: usize| lo + (hi - lo) * k as f64 / CONTINUITY_SAMPLES as f64;
    for k in 0..CONTINUITY_SAMPLES {
        let (a, b) = (at(k), at(k + 1));
        if !continuous(slicing, a, b) {
            locate_jump(slicing, a, b, CONTINUITY_DEPTH, cuts);
        }
    }
}

/// Finds the change between `a` and `b` whose lunes are not continuous (see
/// [`hidden_events`]).
fn locate_jump(slicing: &Slicing, a: f64, b: f64, depth: usize, cuts: &mut Vec<f64>) {
    let mid = 0.5 * (a + b);
    if depth == 0 || mid <= a || mid >= b {
        cuts.push(mid);
        return;
    }
    let class = slicing.shape(a);
    if slicing.shape(mid) != class || slicing.shape(b) != class {
        let mut found = [0.0; 4];
        let mut n = 0;
        shape_events(a, b, |t| slicing.shape(t), &mut found, &mut n);
        cuts.extend_from_slice(&found[..n]);
        return;
    }
    for (x, y) in [(a, mid), (mid, b)] {
        if !continuous(slicing, x, y) {
            locate_jump(slicing, x, y, depth - 1, cuts);
        }
    }
}

/// Joins the lunes on both sides of every cut whose circle arcs overlap.
fn connect_across_cuts(slicing: &Slicing, pieces: &[Piece], regions: &mut Regions) {
    let near = |piece: &Piece, at_hi: bool| {
        let t = if at_hi {
            piece.hi - NEAR_CUT * (piece.hi - piece.lo)
        } else {
            piece.lo + NEAR_CUT * (piece.hi - piece.lo)
        };
        slicing.lunes(t).map(|(_, l)| {
            let label = labels(&piece.middles, &l);
            let arcs: Vec<((f64, f64), usize)> = l
                .parts()
                .iter()
                .zip(label)
                .filter_map(|(p, j)| j.map(|j| (arc_of(p), piece.first + j)))
                .collect();
            arcs
        })
    };
    for w in pieces.windows(2) {
        let (below, above) = (&w[0], &w[1]);
        if below.middles.is_empty() || above.middles.is_empty() || below.hi != above.lo {
            continue;
        }
        let (Some(down), Some(up)) = (near(below, true), near(above, false)) else {
            continue;
        };
        for &(arc_d, id_d) in &down {
            for &(arc_u, id_u) in &up {
                if arcs_overlap(arc_d, arc_u) {
                    regions.join(id_d, id_u);
                }
            }
        }
    }
}

/// Each region's integrals (`COMPONENTS` sums, slicing frame), in the order of their first
/// lune; the cavity's end discs inside the ellipsoid are added to the region beyond them.
fn integrate_regions(
    slicing: &Slicing,
    pieces: &[Piece],
    regions: &mut Regions,
    work: &mut WorkCounters,
) -> Vec<(usize, [f64; COMPONENTS])> {
    let mut sums: Vec<(usize, [f64; COMPONENTS])> = Vec::new();
    let mut add = |root: usize, values: &[f64; COMPONENTS]| {
        let slot = match sums.iter().position(|(r, _)| *r == root) {
            Some(k) => k,
            None => {
                sums.push((root, [0.0; COMPONENTS]));
                sums.len() - 1
            }
        };
        for (s, v) in sums[slot].1.iter_mut().zip(values) {
            *s += v;
        }
    };
    let length = slicing.profile.length;
    for piece in pieces {
        for j in 0..piece.middles.len() {
            let mut f = |t: f64| -> [f64; COMPONENTS] {
                let mut total = [0.0; COMPONENTS];
                let Some((sa, lunes)) = slicing.lunes(t) else {
                    return total;
                };
                let label = labels(&piece.middles, &lunes);
                for (p, &k) in lunes.parts().iter().zip(&label) {
                    if k == Some(j) {
                        let row = integrand(t, &sa, p, slicing.wall(t, p));
                        for (s, v) in total.iter_mut().zip(row) {
                            *s += v;
                        }
                    }
                }
                total
            };
            let mut ends = [piece.lo, piece.hi];
            let r = ADAPTIVE.integrate_pieces(&mut ends, &mut f, &floor, work);
            let root = regions.find(piece.first + j);
            add(root, &r);
        }
        // The cavity's end disc at this piece's far side, inside the ellipsoid, closes the
        // region beyond the end.
        let end = if piece.hi == 0.0 {
            Some(0.0)
        } else if piece.lo == length {
            Some(length)
        } else {
            None
        };
        if let (Some(z), false) = (end, piece.middles.is_empty()) {
            if let Some(sa) = slicing.a.section(z) {
                if let Some((c, m)) = slicing.hole(&sa, z) {
                    let mut cap = [0.0; COMPONENTS];
                    cap[8] = sa.matrix.determinant() * disc_ellipse(&c, &m).area;
                    add(regions.find(piece.first), &cap);
                }
            }
        }
    }
    sums
}

/// The two contact points of SPEC §4 on the line through `g` along the normal `n` (world
/// frame): the ellipsoid's and the cavity's (see the module doc).
fn cavity_points(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    cavity: &Solid,
    pose_b: &Isometry3,
    g: &Point3,
    n: &Vector3,
) -> (Point3, Point3) {
    let gb = pose_b.inverse_transform_point(g).coords;
    let nb = pose_b.inverse_transform_vector(n);
    let (distance, closest, _) = signed_distance(cavity, &gb);
    let closest_w = pose_b * Point3::from(closest);
    let default_a = ellipsoid_exit_w(semi_axes, pose_a, g, &-n);
    let interval = |dir: &Vector3| line_interval(cavity, &gb, dir);
    if distance >= 0.0 {
        // In the material: the line enters the cavity along +n.
        let entry = interval(&nb)
            .filter(|&(_, s1)| s1 > 0.0)
            .map(|(s0, _)| s0.max(0.0));
        return match entry {
            Some(s) => (default_a, g + s * n),
            None => (default_a, closest_w),
        };
    }
    // In the cavity: the nearer chord beside g whose middle lies in both bodies.
    let mut best: Option<(f64, Point3, Point3)> = None;
    for side in [-1.0, 1.0] {
        let dir = n * side;
        let pa = ellipsoid_exit_w(semi_axes, pose_a, g, &dir);
        let pb = pose_b * Point3::from(surface_point_along(cavity, &gb, &(nb * side)));
        let middle = Point3::from(0.5 * (pa.coords + pb.coords));
        let middle_b = pose_b.inverse_transform_point(&middle).coords;
        let in_a = {
            let p = pose_a.inverse_transform_point(&middle).coords;
            p.component_div(semi_axes).norm_squared() < 1.0
        };
        if (pb - pa).dot(n) <= 0.0 || !in_a || signed_distance(cavity, &middle_b).0 <= 0.0 {
            continue;
        }
        let near = (pa - g).norm().min((pb - g).norm());
        if best.as_ref().is_none_or(|(d, _, _)| near < *d) {
            best = Some((near, pa, pb));
        }
    }
    match best {
        Some((_, pa, pb)) => (pa, pb),
        None => (default_a, closest_w),
    }
}

/// The line `o + s d` inside the (unflipped) cylinder or frustum, in its frame.
fn line_interval(cavity: &Solid, o: &Vector3, d: &Vector3) -> Option<(f64, f64)> {
    let profile = Profile::of(cavity)?;
    frustum_line_interval(profile.r0, profile.r1, profile.length, o, d)
}

/// From the centroid to the cavity's closest surface point (world frame), or the cavity's
/// `−z` when the centroid is on its surface.
fn toward_cavity(cavity: &Solid, pose_b: &Isometry3, g: &Point3) -> Vector3 {
    let gb = pose_b.inverse_transform_point(g).coords;
    let (_, closest, _) = signed_distance(cavity, &gb);
    let away = pose_b.rotation * (closest - gb);
    away.try_normalize(0.0)
        .unwrap_or_else(|| -(pose_b.rotation * Vector3::z()))
}
