//! Cylinder–torus and frustum–torus (cones included): the intersection's moments by slicing
//! across the torus' axis and integrating each slice in polar coordinates about it, one
//! contact per region.
//!
//! ## The method
//! In the torus' frame (axis `z`, centre at the origin, lengths divided by a power of two near
//! the pair's size) the plane `z = t` cuts the torus in the annulus `R − s ≤ ρ ≤ R + s`,
//! `s = √(ρ_t² − t²)`. Along each ray from the axis point the cylinder or frustum `b` is one
//! interval in closed form (the frustum pairs' quadratic and cap planes,
//! [`super::revolved_pair::slice`]), clipped to the annulus ([`mod@slice`]): the section's
//! area and first moments, and the torus' walls inside `b`, are integrals over `φ` of closed
//! forms, cut at closed-form events (rays tangent to `b`'s section, `b`'s rims through the
//! slice, each of the annulus' two circles crossing `b`'s lateral surface or a cap plane) and
//! integrated by the sine-mapped adaptive rule to 1e-13. The outer integral runs over the
//! tube's angle `ψ` (`t = ρ_t sin ψ`: `s = ρ_t cos ψ` keeps its digits at the tube's top and
//! bottom, and the slices' square-root ends there become smooth), to 1e-11, between the
//! region's lowest and highest slice, cut at `b`'s rims' extreme heights, the heights where a
//! coaxial `b`'s radius equals one of the annulus' radii (a circle passing onto its surface,
//! which no crossing marks), and the heights where the count of the circles' crossings with
//! `b`'s lateral surface or caps changes (the circles turning tangent to `b`, `b`'s rims
//! piercing the torus' surface: sampled and bisected by the ellipsoid pairs'
//! `shape_events`). Cuts closer than 1e-9 of the extent are merged, as in the frustum pairs.
//!
//! ## Regions
//! The torus is not convex: a rod across its hole meets the tube twice. Every meridian
//! half-plane cuts both solids in convex sets, so the regions are arcs of azimuth
//! ([`regions`], with the box–torus pair's search); each region is integrated inside its
//! wedge of azimuths (the `φ` integral simply runs over the wedge), one contact each. Each
//! region's lowest and highest slices are found by bisection on "the slice meets `b` inside
//! the wedge" from a seed slice: a point the gap's minimisation found inside both, else a cut
//! piece's midpoint or one of 33 samples. The box–torus pair's limit applies: a second region
//! narrower than the 128 azimuth samples that the golden refinement of sampled minima also
//! misses shares its neighbour's wedge (one contact for both); a region is never split.
//!
//! ## The normal and the areas
//! The area vector of the torus' surface inside `b` (outward of the torus), which
//! [`crate::methods::volume_contact`] turns into the normal: at `(ψ, φ)` the outer wall (radius
//! `R + s`) sweeps `(R + s)(s u + t e_z) dψ dφ` and the inner wall (`R − s`)
//! `(R − s)(−s u + t e_z) dψ dφ` (the tube's element `ρ_t(R + ρ_t cos ψ) dψ dφ` times its
//! normal `cos ψ u + sin ψ e_z`, the inner wall at `π − ψ`), each where its radius lies in
//! `b`'s interval along the ray; its unsigned area is `ρ_t(R ± s)` per unit of `ψ` and `φ`.
//! `b`'s surface inside the torus serves only to judge a vanishing area vector and to size an
//! enclosed region's area: `b`'s whole surface (closed form) when none of the torus' is
//! inside `b` (`b` inside the tube), `|S|` while that is not vanishing, none when the whole
//! torus is inside `b`, and otherwise (a symmetric crossing, as a coaxial rod filling the hole)
//! it is estimated as the torus' surface inside `b` (an area estimate, SPEC §4).
//!
//! ## Degenerate branches
//! - **Coaxial**: `b`'s sections are discs about the axis, its rims' heights are cuts, and
//!   the heights where `b`'s radius equals `R ± s` are cuts (closed form: a quadratic in `t`);
//!   a circle on `b`'s surface within 1e-12 counts as inside. A coaxial rod through the hole
//!   (or a sleeve around the ring) symmetric about the torus' mid-plane has a vanishing area
//!   vector: see below.
//! - **Perpendicular** axes and rods through the hole: as in the frustum pairs, rays along
//!   `b`'s axis have a vanishing leading coefficient and the caps bound the interval; a rod
//!   through the hole touching both sides gives two regions, two contacts.
//! - **Grazing**: the seed is the deepest point the gap's minimisation found (to 1e-9 of the
//!   tube's diameter); the extent is then bisected exactly on the slices. Touching is no
//!   contact, and a lens whose sections are round-off is no contact
//!   ([`crate::methods::volume_contact::unresolved_lens`]).
//! - **One inside the other**, **symmetric crossings** and **identical placements**: the
//!   area vector vanishes against the region's surface; with none of `b`'s surface inside the
//!   torus (the torus inside `b`) the normal is `b`'s outward normal at its face nearest the
//!   centroid, otherwise (`b` inside the tube, a symmetric crossing) the opposite of the
//!   torus' outward normal at its surface point nearest the centroid (for a centroid on the
//!   axis, the `+x` radial, as [`crate::methods::solid_distance`] documents); the area a quarter of
//!   the region's surface.

pub(crate) mod regions;
pub(crate) mod slice;

/// A torus region's surface areas from its sums `r` (see [`super::revolved_pair::sums`]'s
/// layout), given the whole surfaces of the torus (`whole_a`, its side `a`) and of `b`:
/// `b`'s surface inside the torus is all of it when none of the torus' is inside `b`, else
/// `|S_a|` stands for it; where `S_a` vanishes the torus' surface inside `b` is closed, all of
/// it (`b` then none) or a closed piece matched by as much of `b`'s.
pub(crate) fn settle_surfaces(r: &mut [f64; COMPONENTS], whole_a: f64, whole_b: f64) {
    let s_a = Vector3::new(r[4], r[5], r[6]).norm();
    let none_of_a = r[7] <= ENCLOSED * whole_b;
    r[8] = if none_of_a { whole_b } else { s_a };
    if !none_of_a && s_a <= ENCLOSED * (r[7] + r[8]) {
        if r[7] >= (1.0 - WHOLE) * whole_a {
            r[7] = whole_a;
            r[8] = 0.0;
        } else {
            r[8] = r[7];
        }
    }
}

#[cfg(test)]
mod tests;

use super::revolved_pair::{dimensions, quadric_of, region_contact, surface_of};
use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::ellipsoid_sliced::{COMPONENTS, add_shape_events_between, pieces_within};
use crate::methods::sliced::last_inside;
use crate::methods::solid_distance::Solid;
use crate::methods::volume_contact::ENCLOSED;
use crate::quadrature::{Adaptive, MAX_PIECES};
use contact_core::geometry::Torus;
use contact_core::{Isometry3, Vector3, WorkCounters};
use regions::Seed;
use slice::{TorusPair, Wedge};
use std::f64::consts::PI;

/// The outer rule over `ψ`, as the frustum pairs' over `t` (the torus–torus pair's over `φ`
/// too).
pub(crate) const OUTER: Adaptive = Adaptive {
    tolerance: 1e-11,
    max_depth: 14,
    pair: crate::quadrature::Pair::Kronrod21,
};

/// Cuts in `ψ` closer than this fraction of the region's extent are merged.
pub(crate) const MERGE: f64 = 1e-9;

/// A surface inside the other solid within this fraction of its whole is all of it.
pub(crate) const WHOLE: f64 = 1e-6;

/// Slices sampled for a region when no seed and no cut piece's midpoint meets it.
const SAMPLES: usize = 33;

/// The absolute error each outer piece may keep, as in the frustum pairs.
pub(crate) fn outer_floor(e: &[f64; COMPONENTS]) -> [f64; COMPONENTS] {
    let v = (e[0].abs() * 1e-12).max(1e-15);
    let surface = e[7].abs() + e[8].abs();
    let s = (surface * 1e-12).max(1e-15);
    let u = (surface * 1e-9).max(1e-15);
    [v, v, v, v, s, s, s, u, u]
}

impl TorusPair {
    /// `b`'s extent along `z`: its rims' extreme heights.
    fn b_range(&self) -> (f64, f64) {
        self.b.z_range()
    }

    /// The tube angle of height `t`.
    fn angle(&self, t: f64) -> f64 {
        (t / self.small).clamp(-1.0, 1.0).asin()
    }

    /// The closed-form cuts in `ψ` inside `(lo, hi)`: `b`'s rims' extreme heights and the
    /// heights where `b`'s radius at the axis point equals `R ± s`.
    fn psi_cuts(&self, lo: f64, hi: f64, cuts: &mut [f64; MAX_PIECES + 1], n: &mut usize) {
        let q = &self.b;
        let spread = q.axis.x.hypot(q.axis.y);
        let mut push = |t: f64, cuts: &mut [f64; MAX_PIECES + 1]| {
            if t.abs() >= self.small {
                return;
            }
            let x = self.angle(t);
            if x > lo && x < hi && *n < cuts.len() {
                cuts[*n] = x;
                *n += 1;
            }
        };
        for h in [0.0, q.len] {
            let r = q.r0 + q.slope * h;
            let z = q.origin.z + q.axis.z * h;
            push(z - r * spread, cuts);
            push(z + r * spread, cuts);
        }
        // b's radius at (0, 0, t) is c₀ + c₁t; (c₀ − R + c₁t)² + t² = ρ_t².
        let (c0, c1) = (q.r0 - q.slope * q.axis.dot(&q.origin), q.slope * q.axis.z);
        let d = c0 - self.big;
        let (a, b, c) = (1.0 + c1 * c1, c1 * d, d * d - self.small * self.small);
        let disc = b * b - a * c;
        if disc >= 0.0 {
            let root = -(b + b.signum() * disc.sqrt());
            if root != 0.0 {
                push(root / a, cuts);
                push(c / root, cuts);
            } else {
                push(0.0, cuts);
            }
        }
    }

    /// The integrand per unit of `ψ`: `[V, ∫t, ∫x, ∫y, S (3), the torus' surface inside b,
    /// 0]`.
    fn integrand(&self, psi: f64, wedge: &Wedge, work: &mut WorkCounters) -> [f64; COMPONENTS] {
        let lv = self.level(psi);
        if lv.s <= 0.0 {
            return [0.0; COMPONENTS];
        }
        let p = self.slice(psi, wedge, work);
        let (s, t) = (lv.s, lv.t);
        let (wo, wi) = (lv.outer, lv.inner);
        let rim = wo * p[3] + wi * p[6];
        [
            s * p[0],
            s * t * p[0],
            s * p[1],
            s * p[2],
            s * (wo * p[4] - wi * p[7]),
            s * (wo * p[5] - wi * p[8]),
            t * rim,
            self.small * rim,
            0.0,
        ]
    }

    /// A slice of the region in `wedge` that meets `b` (from `seed`, else cut midpoints and
    /// samples), within `[lo, hi]`.
    fn inside_slice(
        &self,
        lo: f64,
        hi: f64,
        cuts: &[f64],
        wedge: &Wedge,
        seed: Option<Seed>,
    ) -> Option<f64> {
        seed.map(|s| self.angle(s.t))
            .filter(|&x| x > lo && x < hi && self.not_empty(x, wedge))
            .or_else(|| {
                cuts.windows(2)
                    .map(|w| 0.5 * (w[0] + w[1]))
                    .chain((0..SAMPLES).map(|k| lo + (hi - lo) * (k as f64 + 0.5) / SAMPLES as f64))
                    .find(|&x| self.not_empty(x, wedge))
            })
    }

    /// The region's lowest and highest slice, bisected from `inside` towards `lo` and `hi`.
    fn extent(&self, lo: f64, hi: f64, inside: f64, wedge: &Wedge) -> (f64, f64) {
        let bisect =
            |inside: f64, outside: f64| last_inside(inside, outside, |x| self.not_empty(x, wedge));
        (bisect(inside, lo), bisect(inside, hi))
    }

    /// The integrals of the region in `wedge` (seeded by `seed`), `None` when it is empty.
    fn region(
        &self,
        wedge: &Wedge,
        seed: Option<Seed>,
        work: &mut WorkCounters,
    ) -> Option<[f64; COMPONENTS]> {
        let (b_lo, b_hi) = self.b_range();
        let (lo, hi) = (
            self.angle(b_lo.max(-self.small)),
            self.angle(b_hi.min(self.small)),
        );
        if lo.is_nan() || hi.is_nan() || lo >= hi {
            return None;
        }
        let mut cuts = [0.0; MAX_PIECES + 1];
        cuts[0] = lo;
        cuts[1] = hi;
        let mut n = 2;
        self.psi_cuts(lo, hi, &mut cuts, &mut n);
        add_shape_events_between(&mut cuts, &mut n, |psi| self.shape(psi));
        let start = self.inside_slice(lo, hi, &cuts[..n], wedge, seed)?;
        let (p_min, p_max) = self.extent(lo, hi, start, wedge);
        if p_min >= p_max {
            return None;
        }
        let (mut inner, m) = pieces_within(&cuts[..n], (p_min, p_max), MERGE);
        let mut slices = WorkCounters::default();
        let r = OUTER.integrate_pieces(
            &mut inner[..m],
            &mut |psi| self.integrand(psi, wedge, &mut slices),
            &outer_floor,
            work,
        );
        *work += slices;
        Some(r)
    }
}

/// The contacts of the cylinder or frustum `solid` (`a`, at `pose_a`) with `torus` (`b`, at
/// `pose_b`), one per region, normals from `b` into `a`.
pub(crate) fn contacts(
    solid: &Solid,
    pose_a: &Isometry3,
    torus: &Torus,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let Some(dims) = dimensions(solid) else {
        return;
    };
    let (big, small) = (torus.major_radius(), torus.minor_radius());
    let unit = unit_for(dims.0.max(dims.1).max(dims.2).max(big + small));
    // The torus' frame is the working frame: b is the cylinder or frustum.
    let pose_tb = pose_b.inv_mul(pose_a);
    let pair = TorusPair {
        big: big / unit,
        small: small / unit,
        b: quadric_of(
            dims,
            pose_tb.translation.vector / unit,
            pose_tb.rotation * Vector3::z(),
            unit,
        ),
    };
    // The bounding sphere about b's axis' midpoint against the tube: apart.
    work.bounding_volume_tests += 1;
    let q = &pair.b;
    let reach = q.r0.max(q.r0 + q.slope * q.len).hypot(0.5 * q.len);
    let centre = q.origin + q.axis * (0.5 * q.len);
    if (centre.xy().norm() - pair.big).hypot(centre.z) >= pair.small + reach {
        return;
    }
    let (wedges, count) = pair.regions();
    let torus_solid = Solid::Torus(*torus);
    let whole_torus = 4.0 * PI * PI * pair.big * pair.small;
    let whole_b = surface_of(&pair.b);
    for &(wedge, seed) in &wedges[..count] {
        let Some(mut r) = pair.region(&wedge, seed, work) else {
            continue;
        };
        let volume = r[0];
        if volume.is_nan() || volume <= 0.0 {
            continue;
        }
        // b's surface inside the torus (see the module docs).
        settle_surfaces(&mut r, whole_torus, whole_b);
        // A region of the torus need not be convex, even a thin one (a flat cap pressed on
        // the tube's top circle makes a curved strip whose centroid lies off it), so the
        // convex pairs' chord bound is not applied, as for the box–torus pair.
        let found = region_contact(&r, unit, (&torus_solid, pose_b), (solid, pose_a), false);
        if let Some(c) = found {
            // Computed with the torus first: back to the caller's order.
            emit(c.swapped());
        }
    }
}
