//! The slicing's outer integral (see the module docs, "The slicing"): the cuts in `t`
//! (`b`'s extent, its rims' piercings, the heights where the slices change shape), the
//! intersection's extent in `t` (with the golden-section search for slivers) and the
//! integrand per unit of `t`, integrated by the outer adaptive rule into [`Sums`].

use super::quadric::{self, circle_crossings};
use super::slice::{self, Pair, rim_axes};
use super::{Sums, add_caps};
use crate::methods::ellipsoid_sliced::{COMPONENTS, add_shape_events_between, pieces_within};
use crate::methods::sliced::{golden_search, last_inside};
use crate::quadrature::Adaptive;
use crate::quadrature::MAX_PIECES;
use contact_core::{Vector3, WorkCounters};

/// The outer rule over `t`: looser than the slices' own 1e-13, whose round-off and
/// acceptance noise (a slice's subdivision changes with `t`) it must not chase; at most 16
/// halvings per piece.
const OUTER: Adaptive = Adaptive {
    tolerance: 1e-11,
    max_depth: 14,
    pair: crate::quadrature::Pair::Kronrod21,
};

/// The absolute error each outer piece may keep: 1e-12 of the whole volume (for the volume
/// and moments) and of the whole surface (for the area vector), 1e-9 of the surface for the
/// unsigned areas (only compared against the area vector, and their slices are resolved to
/// 1e-10: a floor below that would chase the slices' own error).
fn outer_floor(e: &[f64; COMPONENTS]) -> [f64; COMPONENTS] {
    let v = (e[0].abs() * 1e-12).max(1e-15);
    let surface = e[7].abs() + e[8].abs();
    let s = (surface * 1e-12).max(1e-15);
    let u = (surface * 1e-9).max(1e-15);
    [v, v, v, v, s, s, s, u, u]
}

/// Cuts in `t` closer than this fraction of the intersection's extent are merged.
const MERGE: f64 = 1e-9;

/// Slices sampled for the intersection when no cut piece's midpoint meets it.
const SAMPLES: usize = 33;

/// Golden-section steps per level of the sliver search (each shrinks by 0.618).
const GOLDEN_STEPS: usize = 48;

impl Pair {
    /// `b`'s extent along `z`: its rims' extreme heights.
    pub(super) fn b_range(&self) -> (f64, f64) {
        self.b.z_range()
    }

    /// The cuts in `t` inside `(lo, hi)` besides the ends: `b`'s rims' extreme heights and
    /// their piercings of `a`'s lateral surface.
    fn t_cuts(&self, lo: f64, hi: f64, cuts: &mut [f64; MAX_PIECES + 1], n: &mut usize) {
        let q = &self.b;
        let spread = q.axis.x.hypot(q.axis.y);
        let (e1, e2) = rim_axes(&q.axis);
        let mut push = |x: f64, cuts: &mut [f64; MAX_PIECES + 1]| {
            if x > lo && x < hi && *n < cuts.len() {
                cuts[*n] = x;
                *n += 1;
            }
        };
        // Where a's radius equals b's radius at the axis point's height along b: for a
        // coaxial b, where a's circle passes onto b's surface (no crossings mark it: the
        // circle lies on the surface there, and its inside-b indicator jumps).
        let rate = self.a.slope - q.slope * q.axis.z;
        if rate != 0.0 {
            push(
                (q.r0 - q.slope * q.axis.dot(&q.origin) - self.a.r0) / rate,
                cuts,
            );
        }
        for (h, r) in [(0.0, q.r0), (q.len, q.r0 + q.slope * q.len)] {
            let centre = q.origin + q.axis * h;
            push(centre.z - r * spread, cuts);
            push(centre.z + r * spread, cuts);
            if r > 0.0 {
                let (psi, k) = circle_crossings(&self.a, &centre, &e1, &e2, r);
                for &x in &psi[..k] {
                    push((centre + r * (x.cos() * e1 + x.sin() * e2)).z, cuts);
                }
            }
        }
    }

    /// How many times `a`'s circle at `t` crosses `b`'s surface (its lateral surface between
    /// the caps, and its cap discs): the slices' shape, which changes where the circle becomes
    /// tangent to the surface (the critical heights of the two surfaces' intersection curve),
    /// the events the closed forms do not give.
    fn crossing_count(&self, t: f64) -> usize {
        let r = self.radius_a(t);
        if r <= 0.0 {
            return 0;
        }
        let q = &self.b;
        let p = Vector3::new(0.0, 0.0, t);
        let at = |psi: f64| p + r * Vector3::new(psi.cos(), psi.sin(), 0.0);
        let (psi, k) = circle_crossings(q, &p, &Vector3::x(), &Vector3::y(), r);
        let mut count = psi[..k]
            .iter()
            .filter(|&&x| {
                let z = q.height(&at(x));
                (0.0..=q.len).contains(&z)
            })
            .count();
        for (h, rim) in [(0.0, q.r0), (q.len, q.r0 + q.slope * q.len)] {
            let centre = q.origin + q.axis * h;
            let (psi, k) =
                quadric::sinusoid_roots(r * q.axis.x, r * q.axis.y, -q.axis.dot(&(p - centre)));
            count += psi[..k]
                .iter()
                .filter(|&&x| q.across(&at(x)).norm() <= rim)
                .count();
        }
        count
    }

    /// The largest margin `min(−h_a, −h_b)` over the slab `lo ≤ z ≤ hi` and its height, by
    /// nested golden sections (the margin is concave, so each partial maximum is too).
    fn deepest(&self, lo: f64, hi: f64) -> (f64, f64) {
        let reach = self.a.r0.max(self.a.r0 + self.a.slope * self.a.len);
        let margin = |x: f64, y: f64, z: f64| {
            let p = Vector3::new(x, y, z);
            -(self.a.inside(&p).max(self.b.inside(&p)))
        };
        golden_search(lo, hi, GOLDEN_STEPS, |z| {
            golden_search(-reach, reach, GOLDEN_STEPS, |x| {
                golden_search(-reach, reach, GOLDEN_STEPS, |y| margin(x, y, z)).1
            })
            .1
        })
    }

    /// The intersection's lowest and highest slice inside `[lo, hi]`, or `None` when it has
    /// none (touching, apart).
    fn extent(&self, lo: f64, hi: f64, cuts: &[f64]) -> Option<(f64, f64)> {
        let inside = cuts
            .windows(2)
            .map(|w| 0.5 * (w[0] + w[1]))
            .chain((0..SAMPLES).map(|k| lo + (hi - lo) * (k as f64 + 0.5) / SAMPLES as f64))
            .find(|&t| self.not_empty(t))
            .or_else(|| {
                let (t, depth) = self.deepest(lo, hi);
                (depth > 0.0 && self.not_empty(t)).then_some(t)
            })?;
        let bisect =
            |inside: f64, outside: f64| last_inside(inside, outside, |x| self.not_empty(x));
        Some((bisect(inside, lo), bisect(inside, hi)))
    }

    /// The integrand in `t`: `[area, t·area, ∫x, ∫y, S_a (3), a's surface inside b, b's inside
    /// a]` per unit of `t`.
    fn integrand(&self, t: f64, work: &mut WorkCounters) -> [f64; COMPONENTS] {
        let r = self.radius_a(t);
        let s = self.slice(t, false, work);
        let k = self.a.slope;
        [
            s[0],
            t * s[0],
            s[1],
            s[2],
            r * s[4],
            r * s[5],
            -k * r * s[3],
            k.hypot(1.0) * r * s[3],
            0.0,
        ]
    }
}

/// [`sums`](super::sums) by slicing across `a`'s axis.
pub(super) fn sliced_sums(
    pair: Pair,
    unit: f64,
    (lo, hi): (f64, f64),
    work: &mut WorkCounters,
) -> Option<Sums> {
    let mut cuts = [0.0; MAX_PIECES + 1];
    cuts[0] = lo;
    cuts[1] = hi;
    let mut n = 2;
    pair.t_cuts(lo, hi, &mut cuts, &mut n);
    // The crossing count between each pair of closed-form cuts.
    add_shape_events_between(&mut cuts, &mut n, |t| pair.crossing_count(t));
    let (t_min, t_max) = pair.extent(lo, hi, &cuts[..n])?;
    if t_min >= t_max {
        return None;
    }
    // The cuts inside the extent, with its ends.
    let (mut inner, m) = pieces_within(&cuts[..n], (t_min, t_max), MERGE);
    // The slices' own counts, apart from the outer rule's (both borrow a counter).
    let mut slices = WorkCounters::default();
    let mut r = OUTER.integrate_pieces(
        &mut inner[..m],
        &mut |t| pair.integrand(t, &mut slices),
        &outer_floor,
        work,
    );
    *work += slices;
    add_caps(
        &pair,
        (lo, hi),
        (&slice::ADAPTIVE, slice::SLICE_FLOOR, true),
        &mut r,
        work,
    );
    Some(Sums {
        pair,
        r,
        unit,
        surface_b: false,
    })
}
