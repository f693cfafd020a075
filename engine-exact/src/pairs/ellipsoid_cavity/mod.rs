//! An ellipsoid (a sphere included) in a cavity shaped as a cylinder, a frustum or an
//! ellipsoid (a flipped solid, whose material is everything outside it). One contact per
//! connected region of the ellipsoid outside the cavity.
//!
//! ## The slices
//! In the cavity's frame (its `z` axis; lengths divided by a power of two near the pair's
//! size) the plane `z = t` cuts the ellipsoid in an ellipse, seen as the unit disc
//! ([`crate::methods::ellipsoid_sliced`]), and the cavity in an ellipse in the same
//! coordinates: a cylinder's or frustum's disc of radius `r(t)` between its ends at `0` and
//! `length`, an ellipsoid cavity's own section between `±c`. Between the ends the region's
//! section is the unit disc less that ellipse, one *lune* per component in closed form
//! ([`disc_less_ellipse`]); beyond them it is the whole section. Each lune is integrated as
//! the ellipsoid pairs integrate an overlap: area and moments for the volume and centroid;
//! the circle's arcs (the ellipsoid's surface in the material) for the area vector `S`; the
//! cavity's wall inside the ellipsoid (`√(1 + r′²)·r·Δφ` per slice on a cylinder or a
//! frustum, [`curved_area`] on an ellipsoid) and a cylinder's or frustum's end discs' overlap
//! with the section for the unsigned surface.
//!
//! ## Regions
//! The slicing range is cut at the ellipsoid's ends, the cavity's ends and the slices where
//! the section's crossings with the cavity's section change in number
//! ([`crate::methods::ellipsoid_sliced::shape_events`]) or its lunes jump ([`regions`]); between two cuts the lunes keep their number and their cyclic order
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
use crate::methods::ellipsoid_sliced::disc_less::{Lunes, disc_less_annulus, disc_less_ellipse};
use crate::methods::ellipsoid_sliced::disc_overlap::{DiscOverlap, disc_ellipse};
use crate::methods::ellipsoid_sliced::{
    ADAPTIVE, COMPONENTS, Integrals, Section, SlicedEllipsoid, curved_area, ellipsoid_in, floor,
    integrand, to_world,
};
use crate::methods::volume_contact::contact_of_region;
use contact_core::geometry::{Cylinder, Frustum, Torus};
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};
use nalgebra::{Matrix2, Vector2};
use regions::{Piece, Regions, connect_across_cuts, labels_for_integrals, pieces};
use walls::{cavity_points, toward_cavity};

mod regions;
mod walls;

/// A cavity an ellipsoid may sit in: the solid turned inside out, in its own frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Cavity {
    /// A cylinder on `z` from `0` to its length.
    Cylinder(Cylinder),
    /// A frustum (or cone) on `z`, its bottom radius at `0`.
    Frustum(Frustum),
    /// An ellipsoid about the origin with these semi-axes.
    Ellipsoid(Vector3),
    /// A ring torus about `z`.
    Torus(Torus),
}

/// `|S|` at or below this fraction of the region's surface counts as vanishing (the
/// quadratures hold `S` to about 1e-12 of the surface; a region whose `S` is that small is a
/// ring all round the cavity, or nearly).
const SYMMETRIC: f64 = 1e-9;

/// The cavity's profile: the disc of radius `r0 + slope·t`, `0 ≤ t ≤ length`.
#[derive(Debug, Clone, Copy)]
struct Profile {
    r0: f64,
    r1: f64,
    length: f64,
}

impl Profile {
    /// The profile of a cylinder (`r0 = r1`) or a frustum, in lengths divided by `unit`.
    fn new(r0: f64, r1: f64, length: f64, unit: f64) -> Self {
        Self {
            r0: r0 / unit,
            r1: r1 / unit,
            length: length / unit,
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

/// The cavity's sections, in working units.
enum Sections {
    /// A cylinder's or frustum's discs about the axis.
    Disc(Profile),
    /// An ellipsoid's ellipses.
    Ellipsoid(SlicedEllipsoid),
    /// A torus' annuli `big ± √(small² − t²)`.
    Torus { big: f64, small: f64 },
}

/// The ellipsoid's slices against the cavity's, in working units.
pub(super) struct Slicing {
    a: SlicedEllipsoid,
    cavity: Sections,
}

impl Slicing {
    /// The `t` range of the cavity's sections; beyond it the material is whole.
    fn cavity_range(&self) -> (f64, f64) {
        match &self.cavity {
            Sections::Disc(p) => (0.0, p.length),
            Sections::Ellipsoid(e) => e.range(),
            Sections::Torus { small, .. } => (-small, *small),
        }
    }

    /// The lunes of slice `t` with the slice's section, or `None` outside the ellipsoid.
    fn lunes(&self, t: f64) -> Option<(Section, Lunes)> {
        let sa = self.a.section(t)?;
        let (lo, hi) = self.cavity_range();
        if t <= lo || t >= hi {
            return Some((sa, Lunes::whole_disc()));
        }
        let Some((center, hole)) = self.hole(&sa, t) else {
            return Some((sa, Lunes::whole_disc()));
        };
        if let Some((inner_center, inner)) = self.inner_hole(&sa, t) {
            return Some((
                sa,
                disc_less_annulus((&inner_center, &inner), (&center, &hole)),
            ));
        }
        Some((sa, disc_less_ellipse(&center, &hole)))
    }

    /// The cavity's section at `t` in the ellipsoid section's unit-disc coordinates (a
    /// torus' outer circle).
    fn hole(&self, sa: &Section, t: f64) -> Option<(Vector2<f64>, Matrix2<f64>)> {
        let inverse = sa.matrix.try_inverse()?;
        match &self.cavity {
            Sections::Disc(p) => Some((inverse * -sa.center, inverse * p.radius(t).max(0.0))),
            Sections::Ellipsoid(e) => {
                let sb = e.section(t)?;
                Some((inverse * (sb.center - sa.center), inverse * sb.matrix))
            }
            Sections::Torus { big, small } => {
                let s = ((small - t) * (small + t)).max(0.0).sqrt();
                Some((inverse * -sa.center, inverse * (big + s)))
            }
        }
    }

    /// A torus' inner circle at `t` in the same coordinates (`None` for the other cavities).
    fn inner_hole(&self, sa: &Section, t: f64) -> Option<(Vector2<f64>, Matrix2<f64>)> {
        let Sections::Torus { big, small } = self.cavity else {
            return None;
        };
        let inverse = sa.matrix.try_inverse()?;
        let s = ((small - t) * (small + t)).max(0.0).sqrt();
        Some((inverse * -sa.center, inverse * (big - s).max(0.0)))
    }

    /// The crossing class of slice `t` (the cuts are where it changes): of the outer curve,
    /// and of a torus' inner circle by eights.
    fn shape(&self, t: f64) -> usize {
        let Some(sa) = self.a.section(t) else {
            return 0;
        };
        let outer = self
            .hole(&sa, t)
            .map_or(0, |(c, m)| disc_ellipse(&c, &m).shape);
        let inner = self
            .inner_hole(&sa, t)
            .map_or(0, |(c, m)| disc_ellipse(&c, &m).shape);
        outer + 8 * inner
    }

    /// The unsigned rate of the cavity's wall inside the ellipsoid, for one part whose
    /// `other_arcs` lie on the cavity's curve `curve` (see [`Lunes::curves`]).
    fn wall(&self, t: f64, lune: &DiscOverlap, curve: u8) -> f64 {
        let (lo, hi) = self.cavity_range();
        if t <= lo || t >= hi {
            return 0.0;
        }
        let mut spans = [(0.0, 0.0); crate::methods::ellipsoid_sliced::disc_overlap::MAX_ARCS];
        let count = lune.other_arcs.spans().len();
        for (s, &(f0, f1)) in spans.iter_mut().zip(lune.other_arcs.spans()) {
            *s = (f0.min(f1), f0.max(f1));
        }
        let angle: f64 = spans[..count].iter().map(|(f0, f1)| f1 - f0).sum();
        match &self.cavity {
            Sections::Disc(p) => p.stretch() * p.radius(t).max(0.0) * angle,
            Sections::Ellipsoid(e) => e
                .section(t)
                .map_or(0.0, |sb| curved_area(&sb, &spans[..count])),
            Sections::Torus { big, small } => {
                // The tube's area per unit of arc and height: ρ/s on both circles.
                let s = ((small - t) * (small + t)).max(0.0).sqrt();
                let radius = if curve == 1 { big - s } else { big + s };
                small / s * radius.max(0.0) * angle
            }
        }
    }
}

/// Hands `emit` one contact per region of the ellipsoid with `semi_axes` at `pose_a` outside
/// `cavity` at `pose_b`.
pub(crate) fn contacts(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    cavity: &Cavity,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut impl FnMut(PairContact),
) {
    let size = match cavity {
        Cavity::Cylinder(c) => c.radius().max(c.length()),
        Cavity::Frustum(f) => f.bottom_radius().max(f.top_radius()).max(f.length()),
        Cavity::Ellipsoid(semi) => semi.max(),
        Cavity::Torus(t) => t.major_radius() + t.minor_radius(),
    };
    let unit = unit_for(semi_axes.max().max(size));
    let (c, l) = ellipsoid_in(pose_b, pose_a, semi_axes, unit);
    work.bounding_volume_tests += 1;
    let Some(slicing) = slicing(cavity, c, &l, unit) else {
        return;
    };
    let pieces = pieces(&slicing);
    let mut regions = Regions::new(pieces.last().map_or(0, |p| p.first + p.middles.len()));
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

/// The slicing of the ellipsoid `{c + L u : |u| ≤ 1}` (cavity frame, working units) against
/// the cavity, or `None` when the ellipsoid lies clear inside it (a sufficient test: inside
/// the cylinder of a cylinder's or frustum's smaller end radius, or inside an ellipsoid's
/// inscribed ball about its centre; a torus is always sliced) or is degenerate.
fn slicing(cavity: &Cavity, c: Vector3, l: &nalgebra::Matrix3<f64>, unit: f64) -> Option<Slicing> {
    let reach = Vector3::from_fn(|k, _| l.row(k).norm());
    let sections = match *cavity {
        Cavity::Cylinder(cyl) => {
            Sections::Disc(Profile::new(cyl.radius(), cyl.radius(), cyl.length(), unit))
        }
        Cavity::Frustum(f) => Sections::Disc(Profile::new(
            f.bottom_radius(),
            f.top_radius(),
            f.length(),
            unit,
        )),
        Cavity::Ellipsoid(semi) => {
            let semi = semi / unit;
            if c.norm() + reach.norm() < semi.min() {
                return None;
            }
            Sections::Ellipsoid(SlicedEllipsoid::new(
                Vector3::zeros(),
                &nalgebra::Matrix3::from_diagonal(&semi),
            )?)
        }
        Cavity::Torus(t) => Sections::Torus {
            big: t.major_radius() / unit,
            small: t.minor_radius() / unit,
        },
    };
    if let Sections::Disc(p) = &sections
        && c.z - reach.z > 0.0
        && c.z + reach.z < p.length
        && c.xy().norm() + reach.xy().norm() < p.r0.min(p.r1)
    {
        return None;
    }
    Some(Slicing {
        a: SlicedEllipsoid::new(c, l)?,
        cavity: sections,
    })
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
    let (c_lo, c_hi) = slicing.cavity_range();
    for piece in pieces {
        for j in 0..piece.middles.len() {
            let mut f = |t: f64| -> [f64; COMPONENTS] {
                let mut total = [0.0; COMPONENTS];
                let Some((sa, lunes)) = slicing.lunes(t) else {
                    return total;
                };
                let label = labels_for_integrals(&piece.middles, &lunes);
                let parts = lunes.parts().iter().zip(lunes.curves()).zip(&label);
                for ((p, &curve), &k) in parts {
                    if k == Some(j) {
                        let row = integrand(t, &sa, p, slicing.wall(t, p, curve));
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
        // A cylinder's or frustum's end disc at this piece's far side, inside the ellipsoid,
        // closes the region beyond the end.
        let end = if piece.hi == c_lo {
            Some(c_lo)
        } else if piece.lo == c_hi {
            Some(c_hi)
        } else {
            None
        };
        if let (Some(z), false, Sections::Disc(_)) =
            (end, piece.middles.is_empty(), &slicing.cavity)
            && let Some(sa) = slicing.a.section(z)
            && let Some((c, m)) = slicing.hole(&sa, z)
        {
            let mut cap = [0.0; COMPONENTS];
            cap[8] = sa.matrix.determinant() * disc_ellipse(&c, &m).area;
            add(regions.find(piece.first), &cap);
        }
    }
    sums
}
