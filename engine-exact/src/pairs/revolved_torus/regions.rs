//! The separate regions of a cylinder or frustum against a ring torus, by azimuth, and a
//! point inside each.
//!
//! A meridian half-plane `H_φ` cuts the convex `b` in a convex set and the torus in the
//! tube's disc, so, as for the box and the ellipsoid (see
//! [`crate::pairs::box_revolved::azimuth`]), the regions are the arcs of azimuth where those
//! meet, found by [`region_wedges_of`] from a gap `g(φ)` negative exactly there. Here
//! `g(φ) = min over the tube's disc of max(h_b, h_tube)`, `h_b` the convex distance-like
//! function of [`Quadric::inside`] (negative inside `b`) and `h_tube` the distance to the
//! tube's centre less its radius: a convex function over a disc, minimised by nested golden
//! sections (height outside, radius inside; a partial minimum of a convex function is
//! convex). `h_b` is defined and continuous everywhere, so `g` falls toward `b`'s azimuths
//! even where `H_φ` misses `b`, and a narrow dip lies in a basin the sampling sees. Each
//! evaluation with `g < 0` yields a point strictly inside both solids; the deepest one in a
//! region's wedge seeds that region's slices.

use super::slice::{TorusPair, Wedge};
use crate::methods::sliced::golden_search;
use crate::pairs::box_revolved::azimuth::{SAMPLES, region_wedges_of};
use contact_core::Vector3;
use std::cell::RefCell;

/// Golden-section steps per level of the gap's fine minimisation: the brackets shrink to
/// 1e-9 of the tube's diameter, so `g` is within about that of its minimum (both terms are
/// 1-Lipschitz), the grazing depths the pair resolves.
const FINE: usize = 44;

/// Steps of the first, coarse minimisation (brackets 5e-4 of the diameter): its value is an
/// upper bound of `g` (a value of the margin at a point), within [`BAND`] of it; only a value
/// inside the band is minimised again with [`FINE`] steps.
const COARSE: usize = 16;

/// Eight times the coarse brackets' widths, in tube radii.
const BAND: f64 = 8.0 * 2.0 * 2.0 * 4.6e-4;

/// A point found inside both solids: its azimuth, the gap there (negative), its height.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Seed {
    /// Azimuth about the torus' axis.
    pub phi: f64,
    /// `g(φ)` (negative: the depth of the point inside both, in the weaker sense).
    pub gap: f64,
    /// Height of the point.
    pub t: f64,
}

/// Recorded seeds: every negative evaluation of the gap, the deepest kept when full.
const RECORDED: usize = 2 * SAMPLES;

impl TorusPair {
    /// `g(φ)` and the height of its minimiser: coarse, and fine near zero.
    pub(crate) fn gap(&self, phi: f64) -> (f64, f64) {
        let coarse = self.gap_in(phi, COARSE);
        if coarse.0.abs() > BAND * self.small {
            return coarse;
        }
        let fine = self.gap_in(phi, FINE);
        if fine.0 <= coarse.0 { fine } else { coarse }
    }

    /// The margin's minimum over the tube's disc at `phi` by `steps` golden sections per
    /// level, and the height where it was found.
    fn gap_in(&self, phi: f64, steps: usize) -> (f64, f64) {
        let (sin, cos) = phi.sin_cos();
        let (big, small) = (self.big, self.small);
        let margin = |rho: f64, t: f64| {
            let x = Vector3::new(rho * cos, rho * sin, t);
            let d = rho - big;
            self.b.inside(&x).max((d * d + t * t).sqrt() - small)
        };
        let across =
            |t: f64| golden_search(big - small, big + small, steps, |rho| -margin(rho, t)).1;
        let (t, best) = golden_search(-small, small, steps, across);
        (-best, t)
    }

    /// The wedges holding one region each (none: the whole turn is one region or none) and
    /// the deepest seed found in each (`None` where no evaluation found the solids meeting).
    pub(crate) fn regions(&self) -> ([(Wedge, Option<Seed>); SAMPLES / 2], usize) {
        let seeds = RefCell::new(([None::<Seed>; RECORDED], 0usize));
        let g = |phi: f64| {
            let (gap, t) = self.gap(phi);
            if gap < 0.0 {
                let mut s = seeds.borrow_mut();
                let (list, n) = &mut *s;
                let seed = Seed { phi, gap, t };
                if *n < RECORDED {
                    list[*n] = Some(seed);
                    *n += 1;
                } else if let Some(worst) = list.iter_mut().max_by(|a, b| {
                    a.map_or(0.0, |s| s.gap)
                        .total_cmp(&b.map_or(0.0, |s| s.gap))
                }) {
                    if worst.is_none_or(|w| w.gap > gap) {
                        *worst = Some(seed);
                    }
                }
            }
            gap
        };
        // g is (R + ρ_t)-Lipschitz in φ (the disc's points move by at most R + ρ_t per
        // radian): only a positive minimum within a sampling step's worth of zero can hide a
        // dip below it between samples.
        let step = std::f64::consts::TAU / SAMPLES as f64;
        let (cuts, count) = region_wedges_of(g, (self.big + self.small) * step);
        let (list, n) = seeds.into_inner();
        let deepest = |w: &Wedge| {
            list[..n]
                .iter()
                .flatten()
                .filter(|s| w.contains(s.phi))
                .min_by(|a, b| a.gap.total_cmp(&b.gap))
                .copied()
        };
        let mut out = [(Wedge::WHOLE, None); SAMPLES / 2];
        if count == 0 {
            out[0] = (Wedge::WHOLE, deepest(&Wedge::WHOLE));
            return (out, 1);
        }
        for (o, &(start, end)) in out.iter_mut().zip(&cuts[..count]) {
            let w = Wedge { start, end };
            *o = (w, deepest(&w));
        }
        (out, count)
    }
}
