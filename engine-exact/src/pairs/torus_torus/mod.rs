//! Torus–torus: the intersection's moments by meridians of `a` (the half-planes about its
//! axis), each integrated in polar coordinates about its tube's centre ([`meridian`]); one
//! contact per region.
//!
//! ## The method
//! In `a`'s frame (axis `z`, centre at the origin, lengths divided by a power of two near the
//! pair's size) the meridian at azimuth `φ` cuts `a` in the tube's disc. Each circle about
//! the disc's centre meets `b` in arcs whose ends are the zeros of a trigonometric form of
//! degree two, and the moments over those arcs are closed forms ([`meridian`]); the integral
//! over the circles' radius is cut where the arcs change (a circle tangent to `b`'s section),
//! to 1e-13, and `a`'s wall inside `b` is the rim circle's arcs in closed form. The outer
//! integral over `φ` runs over each region's arc of azimuths, between its first and last
//! meridian (bisected on "the meridian meets `b`"), cut where the arcs of the meridian's rim
//! circle change (`a`'s wall: 2,048 azimuths sampled, each change bisected) and where `b` is
//! tangent to a meridian plane inside the tube (its section splits or joins:
//! [`TorusTorus::tangent_azimuths`]), to 1e-11. Pieces
//! closer than 1e-9 of the arc are merged.
//!
//! ## Regions
//! As for the other torus pairs ([`crate::pairs::revolved_torus::regions`]), the regions are
//! arcs of azimuth, from the meridian gap `g(φ) = min over the tube's disc of max(h_b,
//! h_tube)` ([`TorusTorus::gap`]; `h_b` the distance to `b`'s core circle less its tube
//! radius), negative exactly where the meridian meets both. `b`'s meridian sections are not
//! convex, so one arc may hold two regions that share azimuths (a ring around `a`'s tube
//! crossing it twice in one meridian): they are one contact, with summed moments. A region
//! is never split.
//!
//! ## The normal and the areas
//! `S`, the area vector of `a`'s surface inside `b`, gives the normal ([`volume_contact`]).
//! `b`'s surface inside `a` only judges a vanishing `S` and sizes an enclosed region's area:
//! `b`'s whole surface when none of `a`'s is inside `b` (`b` inside `a`'s tube), else `|S|`.
//! When `S` vanishes (one inside the other, or a symmetric crossing such as two coaxial rings
//! of different radii in one plane), the normal is `b`'s outward normal at its surface point
//! nearest the centroid when `a` lies inside `b`, else the opposite of `a`'s.
//!
//! ## Limits
//! The radii where a meridian's arcs change are found by sampling (64 circles, and 40
//! towards each end) and bisecting: two changes closer than the samples are a corner the
//! adaptive rule halves across (slower, not wrong), as is an outer cut the sampling misses.
//! A section no sampled circle meets is found from the gap's minimiser. Like every torus
//! pair, a region whose centroid lies in a ring's hole (two coaxial rings overlapping all
//! round) takes its points where the line along the normal leaves each body, or the closest
//! surface points when it misses one ([`crate::ray_exit`]).

pub(crate) mod meridian;
#[cfg(test)]
mod tests;

use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::ellipsoid_sliced::{COMPONENTS, pieces_within};
use crate::methods::sliced::last_inside;
use crate::methods::solid_distance::Solid;
use crate::pairs::box_revolved::azimuth::{SAMPLES, region_wedges_of};
use crate::pairs::revolved_pair::region_contact;
use crate::pairs::revolved_torus::slice::Wedge;
// The outer rule, merge and floor of the cylinder–torus pair, whose integrand has the same
// components.
use crate::pairs::revolved_torus::{MERGE, OUTER, outer_floor, settle_surfaces};
use crate::quadrature::MAX_PIECES;
use contact_core::geometry::Torus;
use contact_core::{Isometry3, WorkCounters};
use meridian::TorusTorus;
use std::cell::RefCell;
use std::f64::consts::PI;

/// Azimuths at which the rim circle's class is sampled over a region's arc.
const RIM_SAMPLES: usize = 2048;

/// Meridians sampled for a region when its seed's does not meet `b`.
const SAMPLED_MERIDIANS: usize = 33;

/// A meridian found meeting both solids: its azimuth and gap (negative).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Seed {
    /// Azimuth about `a`'s axis.
    pub phi: f64,
    /// The meridian gap there.
    pub gap: f64,
}

impl TorusTorus {
    /// The outer integrand at `phi`: `[V, ∫z, ∫x, ∫y, S (3), a's surface inside b, 0]`.
    fn integrand(&self, phi: f64, work: &mut WorkCounters) -> [f64; COMPONENTS] {
        let p = self.integral(phi, work);
        let (s, c) = phi.sin_cos();
        [
            p[0],
            p[2],
            c * p[1],
            s * p[1],
            c * p[3],
            s * p[3],
            p[4],
            p[5],
            0.0,
        ]
    }

    /// The wedges holding one region each and the deepest seed in each; one wedge (the
    /// whole turn) when the sampling saw one region or none.
    pub(crate) fn regions(&self) -> (Vec<(Wedge, Option<Seed>)>, usize) {
        let seeds = RefCell::new(Vec::<Seed>::new());
        let g = |phi: f64| {
            let gap = self.gap(phi).0;
            if gap < 0.0 {
                seeds.borrow_mut().push(Seed { phi, gap });
            }
            gap
        };
        // g is (R + ρ)-Lipschitz in φ: only a positive minimum within a sampling step's
        // worth of zero can hide a dip.
        let step = std::f64::consts::TAU / SAMPLES as f64;
        let (cuts, count) = region_wedges_of(g, (self.big + self.small) * step);
        let seeds = seeds.into_inner();
        let deepest = |w: &Wedge| {
            seeds
                .iter()
                .filter(|s| w.contains(s.phi))
                .min_by(|a, b| a.gap.total_cmp(&b.gap))
                .copied()
        };
        if count == 0 {
            return (vec![(Wedge::WHOLE, deepest(&Wedge::WHOLE))], 1);
        }
        let out: Vec<_> = cuts[..count]
            .iter()
            .map(|&(start, end)| {
                let w = Wedge { start, end };
                (w, deepest(&w))
            })
            .collect();
        (out, count)
    }

    /// A meridian of the region in `wedge` that meets `b`: the seed's, else one of the
    /// samples'; `None` when none does.
    fn inside_meridian(&self, wedge: &Wedge, seed: Option<Seed>) -> Option<f64> {
        let (lo, hi) = (wedge.start, wedge.end);
        seed.map(|s| lo + (s.phi - lo).rem_euclid(std::f64::consts::TAU))
            .filter(|&phi| self.not_empty(phi))
            .or_else(|| {
                (0..SAMPLED_MERIDIANS)
                    .map(|k| lo + (hi - lo) * (k as f64 + 0.5) / SAMPLED_MERIDIANS as f64)
                    .find(|&phi| self.not_empty(phi))
            })
    }

    /// The region's first and last meridian, bisected from `inside` towards `lo` and `hi`
    /// (an end that still meets `b` is kept: the whole turn).
    fn extent(&self, lo: f64, hi: f64, inside: f64) -> (f64, f64) {
        let bisect =
            |inside: f64, outside: f64| last_inside(inside, outside, |x| self.not_empty(x));
        (bisect(inside, lo), bisect(inside, hi))
    }

    /// Adds to `cuts[..*n]` (up to its capacity) the azimuths in `(lo, hi)` where the rim
    /// circle's class changes: sampled at [`RIM_SAMPLES`] azimuths and geometrically towards
    /// both ends, each change bisected to round-off. The rim's class is one circle's zeros,
    /// cheap beside a meridian's integral, and an arc of the rim that splits and joins again
    /// within a few 1e-4 of a radian is common where the tubes cross at a shallow angle.
    fn rim_events(&self, lo: f64, hi: f64, cuts: &mut [f64; MAX_PIECES + 1], n: &mut usize) {
        let step = (hi - lo) / RIM_SAMPLES as f64;
        let near_lo = (1..=40).rev().map(|k| lo + 0.5 * step * 0.5f64.powi(k));
        let uniform = (0..RIM_SAMPLES).map(|k| lo + step * (k as f64 + 0.5));
        let near_hi = (1..=40).map(|k| hi - 0.5 * step * 0.5f64.powi(k));
        let mut last: Option<(f64, usize)> = None;
        for phi in near_lo.chain(uniform).chain(near_hi) {
            let class = self.rim_class(phi);
            if let Some((before, previous)) = last {
                if class != previous && *n < cuts.len() {
                    let (mut a, mut b) = (before, phi);
                    for _ in 0..60 {
                        let mid = 0.5 * (a + b);
                        if mid <= a || mid >= b {
                            break;
                        }
                        if self.rim_class(mid) == previous {
                            a = mid;
                        } else {
                            b = mid;
                        }
                    }
                    cuts[*n] = 0.5 * (a + b);
                    *n += 1;
                }
            }
            last = Some((phi, class));
        }
    }

    /// The integrals of the region in `wedge` (seeded by `seed`), `None` when it is empty.
    pub(crate) fn region(
        &self,
        wedge: &Wedge,
        seed: Option<Seed>,
        work: &mut WorkCounters,
    ) -> Option<[f64; COMPONENTS]> {
        let start = self.inside_meridian(wedge, seed)?;
        let (lo, hi) = if *wedge == Wedge::WHOLE {
            (start - PI, start + PI)
        } else {
            (wedge.start, wedge.end)
        };
        let (p_min, p_max) = self.extent(lo, hi, start);
        if p_min >= p_max {
            return None;
        }
        let mut cuts = [0.0; MAX_PIECES + 1];
        cuts[0] = p_min;
        cuts[1] = p_max;
        let mut n = 2;
        self.rim_events(p_min, p_max, &mut cuts, &mut n);
        for phi in self.tangent_azimuths() {
            let lifted = p_min + (phi - p_min).rem_euclid(std::f64::consts::TAU);
            if lifted < p_max && n < cuts.len() {
                cuts[n] = lifted;
                n += 1;
            }
        }
        cuts[..n].sort_by(f64::total_cmp);
        let (mut inner, m) = pieces_within(&cuts[..n], (p_min, p_max), MERGE);
        let mut meridians = WorkCounters::default();
        let r = OUTER.integrate_pieces(
            &mut inner[..m],
            &mut |phi| self.integrand(phi, &mut meridians),
            &outer_floor,
            work,
        );
        *work += meridians;
        Some(r)
    }
}

/// The contacts of torus `a` (at `pose_a`) with torus `b` (at `pose_b`), one per region,
/// normals from `b` into `a`.
pub(crate) fn contacts(
    a: &Torus,
    pose_a: &Isometry3,
    b: &Torus,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let size = (a.major_radius() + a.minor_radius()).max(b.major_radius() + b.minor_radius());
    let unit = unit_for(size);
    let pose_ab = pose_a.inv_mul(pose_b);
    let pair = TorusTorus {
        big: a.major_radius() / unit,
        small: a.minor_radius() / unit,
        b_big: b.major_radius() / unit,
        b_small: b.minor_radius() / unit,
        origin: pose_ab.translation.vector / unit,
        to_b: pose_ab.rotation.to_rotation_matrix().matrix().transpose(),
    };
    // Bounding spheres: apart.
    work.bounding_volume_tests += 1;
    if pair.origin.norm() >= pair.big + pair.small + pair.b_big + pair.b_small {
        return;
    }
    let (wedges, _) = pair.regions();
    let (solid_a, solid_b) = (Solid::Torus(*a), Solid::Torus(*b));
    let whole_a = 4.0 * PI * PI * pair.big * pair.small;
    let whole_b = 4.0 * PI * PI * pair.b_big * pair.b_small;
    for &(wedge, seed) in &wedges {
        let Some(mut r) = pair.region(&wedge, seed, work) else {
            continue;
        };
        let volume = r[0];
        if volume.is_nan() || volume <= 0.0 {
            continue;
        }
        settle_surfaces(&mut r, whole_a, whole_b);
        // A torus' region need not be convex (see the cylinder–torus pair).
        let found = region_contact(&r, unit, (&solid_a, pose_a), (&solid_b, pose_b), false);
        if let Some(c) = found {
            emit(c);
        }
    }
}
