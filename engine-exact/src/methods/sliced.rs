//! The slicing kernel of the cylinder–solid pairs: a cylinder `a` against a convex solid `b`
//! whose every section by the planes `x·n = t` is a convex polygon, `n` perpendicular to
//! `a`'s axis.
//!
//! ## The working frame
//! Coordinates `(t, u, v)`: origin at `a`'s centre, `t` along the slicing direction `n`, `v`
//! along `a`'s axis, `u` across both, lengths divided by a power of two near the pair's size.
//! The plane `t` cuts `a` in the rectangle `|u| ≤ w(t) = √(r² − t²)`, `|v| ≤ ℓ` (its half
//! length); `b` is a list of `Bound`s, each the half-plane `g·(u, v) ≤ d(t)` in every slice:
//! a plane of `b` (`g` its normal's in-plane part, `d` linear in `t`), or one side of a
//! cylinder whose axis lies in the slicing planes (`d = e·c ± w_b(t)`).
//!
//! ## The integrals
//! Per slice the clipped polygon ([`super::section`]) gives the area `A(t)`, its first moments
//! and the length `L_k(t)` of its edge on each half-plane `k`. Then `V = ∫A dt`, the centroid
//! from `∫(∫u, ∫v, tA) dt / V`, and the area vector of `a`'s surface inside `b`,
//! `S_a = Σ_k ∫ L_k (g_k − d_k'(t) n) dt` over `a`'s half-planes (`g_k` unit): the vector area
//! swept by a straight section line moving with `t`. For `a`'s caps `d' = 0`; for its side
//! `d' = w' = −t/w`, and `g ± (t/w) n` is the side's outward normal times `r/w`, the stretch
//! of its area over the slice's. The unsigned areas (`|g − d'n|`: `r/w` on a side, `1/|g|` on a
//! plane of unnormalised `g`) of both surfaces inside the other are integrated alongside.
//!
//! The integration variable is the angle `θ` of `t = r sin θ` (`r` being `a`'s radius): `a`'s
//! half width `w = r cos θ` and the distances `r ∓ t` to its ends are then free of
//! cancellation, and `a`'s side, whose element `L (t n ± w e)/w dt` is singular at the ends,
//! becomes `L (t n ± w e) dθ`. A second cylinder's width takes its factors `r_b ∓ (t − t_b)`
//! from those distances, so two cylinders whose sections end at the same `t` (identical or
//! aligned ones) agree there to the last bit.
//!
//! ## Where the integrand is not smooth
//! - square-root ends where a side's width `w` vanishes (`t = t₀ ± r` of each cylinder),
//! - kinks where a vertex of one section crosses an edge of the other (the `t` of each vertex
//!   of `b`, and the unknown `t` where a curved edge of one solid meets the other's surface),
//! - the two ends `t_min`, `t_max` of the intersection's extent along `n`.
//!
//! The ends are found first: one `t` inside is a piece's midpoint where the section is not
//! empty or, when none is (a sliver), the maximiser of the section's inscribed-circle margin
//! `μ(t)` — concave in `t` for two convex solids, found by golden-section search; `μ < 0`
//! everywhere means no overlap. From there bisection on "the section is not empty" (an
//! interval, by convexity) gives `t_min` and `t_max` to round-off (or within 1e-12 of the
//! bracket when the section is already non-empty there: the extent ends at a range end). Those, the square-root ends
//! and `b`'s vertices are the cuts of [`crate::quadrature::Adaptive`]: sine-mapped pieces,
//! halved where a kink between cuts remains, until the error estimate is within 1e-13
//! relative or 1e-14 of the whole (volume for the moments, surface for the areas), and
//! never below the round-off of a slice (1e-14 per unit of range, working units).

use super::section::{MAX_LABELS, Polygon};
use crate::quadrature;
use contact_core::{Vector2, Vector3, WorkCounters};

/// The adaptive rule: error estimates within 1e-13 relative, at most 24 halvings per piece (a kink
/// between cuts is then bracketed to 2⁻²⁴ of its piece).
const ADAPTIVE: quadrature::Adaptive = quadrature::Adaptive {
    tolerance: 1e-13,
    max_depth: 24,
    pair: crate::quadrature::Pair::Kronrod21,
};

/// Each piece may keep this fraction of the whole integral (volume or surface).
const FLOOR: f64 = 1e-14;

/// The floor per unit of the integration range, in working units: the round-off of one
/// slice's area and edge lengths, below which halving cannot improve an estimate (a sliver
/// of a grazing contact).
const ROUND_OFF: f64 = 1e-14;

/// Most bounds of `b`.
pub(crate) const MAX_BOUNDS: usize = MAX_LABELS - 4;
/// Most cuts `b` adds (square-root ends and the intersection's vertices, see
/// [`super::slice_events`]); with the two ends they fill the adaptive rule's pieces.
pub(crate) const MAX_B_CUTS: usize = quadrature::MAX_PIECES - 1;

/// One bounding surface of `b`, as a half-plane in every slice (working frame `(t, u, v)`).
#[derive(Debug, Clone, Copy)]
pub(crate) enum Bound {
    /// The plane `normal·x ≤ offset`: in the slice, `(normal.y, normal.z)·(u, v) ≤ offset −
    /// normal.x·t`.
    Plane {
        /// Unit normal in `(t, u, v)`.
        normal: Vector3,
        /// Offset.
        offset: f64,
    },
    /// One side of a cylinder with its axis in the slicing planes:
    /// `sign·across·(u, v) ≤ sign·centre + √(radius² − (t − t0)²)`.
    Side {
        /// Unit in-plane direction across the cylinder's axis.
        across: Vector2,
        /// `across·c` for the cylinder's centre `c`.
        centre: f64,
        /// +1 or −1: which side.
        sign: f64,
        /// The `t` of the cylinder's axis.
        t0: f64,
        /// The cylinder's radius.
        radius: f64,
    },
}

/// Where a slice lies: `t`, and its distances `r_a − t` and `r_a + t` to `a`'s ends, kept
/// apart because near an end they are known better than `t` (see [`SlicedPair::integrand`]).
#[derive(Debug, Clone, Copy)]
struct Slice {
    t: f64,
    to_top: f64,
    to_bottom: f64,
}

impl Slice {
    /// The slice `t` of `a` with radius `radius`, its distances from `t`.
    fn at(t: f64, radius: f64) -> Self {
        Self {
            t,
            to_top: radius - t,
            to_bottom: radius + t,
        }
    }

    /// The slice `t = radius·sin θ`, the distances to the ends without cancellation.
    fn at_angle(theta: f64, radius: f64) -> Self {
        let (sin, cos) = theta.sin_cos();
        let squeezed = radius * cos * cos;
        let (to_top, to_bottom) = if sin >= 0.0 {
            (squeezed / (1.0 + sin), radius * (1.0 + sin))
        } else {
            (radius * (1.0 - sin), squeezed / (1.0 - sin))
        };
        Self {
            t: radius * sin,
            to_top,
            to_bottom,
        }
    }

    /// Half-width of a cylinder of radius `radius` with axis at `t0`, in this slice of a
    /// cylinder of radius `radius_a` about `t = 0`: `√((r − x)(r + x))`, `x = t − t0`, each
    /// factor from the distances to `a`'s ends (exact when the two cylinders' ends coincide).
    fn half_width(&self, radius: f64, t0: f64, radius_a: f64) -> f64 {
        let minus = self.to_top + ((radius - radius_a) + t0);
        let plus = self.to_bottom + ((radius - radius_a) - t0);
        (minus * plus).max(0.0).sqrt()
    }
}

/// Half-width `√(r² − x²)` of a disc at offset `x` (0 outside, NaN-free).
fn half_width(radius: f64, x: f64) -> f64 {
    ((radius - x) * (radius + x)).max(0.0).sqrt()
}

impl Bound {
    /// `(g, d)`: the half-plane `g·p ≤ d` in `slice` of `a` (radius `radius_a`).
    fn line(&self, slice: &Slice, radius_a: f64) -> (Vector2, f64) {
        let t = slice.t;
        match *self {
            Self::Plane { normal, offset } => {
                (Vector2::new(normal.y, normal.z), offset - normal.x * t)
            }
            Self::Side {
                across,
                centre,
                sign,
                t0,
                radius,
            } => (
                sign * across,
                sign * centre + slice.half_width(radius, t0, radius_a),
            ),
        }
    }

    /// `(vector, unsigned)` area of the surface per unit of edge length and of `t`.
    fn area_element(&self, slice: &Slice, radius_a: f64) -> (Vector3, f64) {
        let t = slice.t;
        match *self {
            Self::Plane { normal, .. } => {
                let g = normal.y.hypot(normal.z);
                if g > 0.0 {
                    (normal / g, 1.0 / g)
                } else {
                    (Vector3::zeros(), 0.0)
                }
            }
            Self::Side {
                across,
                sign,
                t0,
                radius,
                ..
            } => {
                let w = slice.half_width(radius, t0, radius_a);
                if w > 0.0 {
                    let g = sign * across;
                    (Vector3::new((t - t0) / w, g.x, g.y), radius / w)
                } else {
                    (Vector3::zeros(), 0.0)
                }
            }
        }
    }
}

/// Cylinder `a` (radius and half length, working units, centred in the working frame) and
/// the solid `b` it is sliced against.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SlicedPair {
    /// `a`'s radius.
    pub radius_a: f64,
    /// `a`'s half length.
    pub half_length_a: f64,
    /// `b`'s bounds (the first `bound_count`).
    pub bounds: [Bound; MAX_BOUNDS],
    /// How many bounds `b` has.
    pub bound_count: usize,
    /// `b`'s extent along `t` (may be infinite).
    pub range_b: (f64, f64),
    /// The `t` where `b`'s section changes shape or has a square-root end (the first
    /// `cut_count`).
    pub cuts_b: [f64; MAX_B_CUTS],
    /// How many cuts `b` adds.
    pub cut_count: usize,
}

/// The moments of the intersection, in the working frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SlicedMoments {
    /// Volume.
    pub volume: f64,
    /// Centroid `(t, u, v)`.
    pub centroid: Vector3,
    /// `∫ n_a dA` over `a`'s surface inside `b`.
    pub area_vector_a: Vector3,
    /// Unsigned area of `a`'s surface inside `b`.
    pub area_a: f64,
    /// Unsigned area of `b`'s surface inside `a`.
    pub area_b: f64,
}

/// The four half-planes of `a`'s section, in the labels of [`Polygon::rectangle`].
fn bounds_a(radius: f64, half_length: f64) -> [Bound; 4] {
    let side = |sign| Bound::Side {
        across: Vector2::x(),
        centre: 0.0,
        sign,
        t0: 0.0,
        radius,
    };
    let cap = |sign: f64| Bound::Plane {
        normal: Vector3::new(0.0, 0.0, sign),
        offset: half_length,
    };
    [side(1.0), side(-1.0), cap(1.0), cap(-1.0)]
}

impl SlicedPair {
    fn bounds_b(&self) -> &[Bound] {
        &self.bounds[..self.bound_count.min(MAX_BOUNDS)]
    }

    /// The section at `t` (empty when `a` has no width there).
    fn section(&self, t: f64) -> Polygon {
        self.section_with_width(&Slice::at(t, self.radius_a), half_width(self.radius_a, t))
    }

    /// The section at `slice`, `a`'s half width there being `w`.
    fn section_with_width(&self, slice: &Slice, w: f64) -> Polygon {
        let mut polygon = Polygon::rectangle(Vector2::new(w, self.half_length_a));
        for (k, bound) in self.bounds_b().iter().enumerate() {
            let (g, d) = bound.line(slice, self.radius_a);
            polygon.clip(&g, d, (4 + k) as u8);
        }
        polygon
    }

    fn not_empty(&self, t: f64) -> bool {
        self.section(t).area() > 0.0
    }

    /// `[A, tA, ∫u, ∫v, S_a (3), area_a, area_b]` of slice `t = r sin θ`, times `dt/dθ =
    /// r cos θ`. In `θ` the half width `w = r cos θ` of `a` has no cancellation near `a`'s
    /// ends, and `a`'s side (whose area element per `dt` is `L(t n ± w e)/w`, singular there)
    /// becomes `L(t n ± w e)` per `dθ`: smooth.
    fn integrand(&self, theta: f64) -> [f64; 9] {
        let mut out = [0.0; 9];
        let slice = Slice::at_angle(theta, self.radius_a);
        let (t, w) = (slice.t, self.radius_a * theta.cos());
        if w <= 0.0 {
            return out;
        }
        let m = self.section_with_width(&slice, w).measures();
        if m.area <= 0.0 {
            return out;
        }
        let jacobian = w;
        out[0] = m.area * jacobian;
        out[1] = t * m.area * jacobian;
        out[2] = m.moment.x * jacobian;
        out[3] = m.moment.y * jacobian;
        // a's side (labels 0, 1: u = ±w) and caps (2, 3: v = ±ℓ).
        for (k, sign) in [(0, 1.0), (1, -1.0)] {
            let l = m.lengths[k];
            out[4] += l * t;
            out[5] += l * sign * w;
            out[7] += l * self.radius_a;
        }
        for (k, sign) in [(2, 1.0), (3, -1.0)] {
            let l = m.lengths[k] * jacobian;
            out[6] += l * sign;
            out[7] += l;
        }
        for (k, bound) in self.bounds_b().iter().enumerate() {
            if m.lengths[4 + k] > 0.0 {
                out[8] += m.lengths[4 + k] * bound.area_element(&slice, self.radius_a).1 * jacobian;
            }
        }
        out
    }

    /// The largest `μ` with a disc of radius `μ` (in the slice, measured by each half-plane's
    /// `|g|`) inside the section at `t`; concave in `t`. Brute force over the vertices of the
    /// 3-variable linear program (at most 10 half-planes: 120 triples).
    fn margin(&self, t: f64) -> f64 {
        let mut lines = [(Vector2::zeros(), 0.0, 0.0); MAX_LABELS];
        let mut count = 0;
        for bound in bounds_a(self.radius_a, self.half_length_a)
            .iter()
            .chain(self.bounds_b())
        {
            let (g, d) = bound.line(&Slice::at(t, self.radius_a), self.radius_a);
            lines[count] = (g, g.norm(), d);
            count += 1;
        }
        let lines = &lines[..count];
        let mut best = f64::NEG_INFINITY;
        for i in 0..count {
            for j in i + 1..count {
                for k in j + 1..count {
                    let (a, b, c) = (lines[i], lines[j], lines[k]);
                    let m = nalgebra::Matrix3::new(
                        a.0.x, a.0.y, a.1, b.0.x, b.0.y, b.1, c.0.x, c.0.y, c.1,
                    );
                    let Some(inverse) = m.try_inverse() else {
                        continue;
                    };
                    let x = inverse * Vector3::new(a.2, b.2, c.2);
                    if !x.iter().all(|v| v.is_finite()) || x.z <= best {
                        continue;
                    }
                    let p = x.xy();
                    let feasible = lines
                        .iter()
                        .all(|l| l.0.dot(&p) + l.1 * x.z <= l.2 + 1e-12 * (1.0 + l.2.abs()));
                    if feasible {
                        best = x.z;
                    }
                }
            }
        }
        best
    }

    /// The cuts of `[lo, hi]`: its ends and `b`'s cuts inside it, sorted, those closer than
    /// round-off of the range dropped; the cuts and their number.
    fn sorted_cuts(&self, lo: f64, hi: f64) -> ([f64; quadrature::MAX_PIECES + 1], usize) {
        let mut cuts = [0.0; quadrature::MAX_PIECES + 1];
        cuts[0] = lo;
        cuts[1] = hi;
        let mut count = 2;
        for &c in &self.cuts_b[..self.cut_count.min(MAX_B_CUTS)] {
            if c > lo && c < hi {
                cuts[count] = c;
                count += 1;
            }
        }
        cuts[..count].sort_by(f64::total_cmp);
        // Cuts closer than round-off of the range make empty pieces: drop them.
        let mut unique = 1;
        for k in 1..count {
            if cuts[k] > cuts[unique - 1] + 1e-14 * (hi - lo) {
                cuts[unique] = cuts[k];
                unique += 1;
            }
        }
        (cuts, unique)
    }

    /// The intersection's extent `(t_min, t_max)` within `[lo, hi]`, found from a `t` inside
    /// it (the middle of a piece between `cuts`, else the largest margin); `None` when there
    /// is none.
    fn extent(&self, lo: f64, hi: f64, cuts: &[f64]) -> Option<(f64, f64)> {
        // One t inside the intersection's extent.
        let inside = cuts
            .windows(2)
            .map(|p| 0.5 * (p[0] + p[1]))
            .find(|&t| self.not_empty(t))
            .or_else(|| {
                let t = golden_maximum(lo, hi, |t| self.margin(t));
                (self.margin(t) >= 0.0 && self.not_empty(t)).then_some(t)
            })?;
        let t_min = if self.not_empty(lo) {
            lo
        } else {
            bisect(lo, inside, |t| self.not_empty(t))
        };
        let t_max = if self.not_empty(hi) {
            hi
        } else {
            bisect(hi, inside, |t| self.not_empty(t))
        };
        Some((t_min, t_max))
    }

    /// The moments of the intersection, or `None` when it has no volume.
    pub fn integrate(&self, work: &mut WorkCounters) -> Option<SlicedMoments> {
        let lo = (-self.radius_a).max(self.range_b.0);
        let hi = self.radius_a.min(self.range_b.1);
        if lo.is_nan() || hi.is_nan() || lo >= hi {
            return None;
        }
        let (cuts, count) = self.sorted_cuts(lo, hi);
        let (t_min, t_max) = self.extent(lo, hi, &cuts[..count])?;
        // Keep the cuts strictly inside [t_min, t_max].
        let mut kept = [0.0; quadrature::MAX_PIECES + 1];
        kept[0] = t_min;
        kept[1] = t_max;
        let mut kept_count = 2;
        for &c in &cuts[..count] {
            if c > t_min && c < t_max {
                kept[kept_count] = c;
                kept_count += 1;
            }
        }
        // To the angle θ of t = r sin θ (see `integrand`).
        let to_angle = |t: f64| (t / self.radius_a).clamp(-1.0, 1.0).asin();
        for c in &mut kept[..kept_count] {
            *c = to_angle(*c);
        }
        let mut f = |theta: f64| self.integrand(theta);
        // Round-off of a slice's measures is about 1e-15 of the (near 1) working sizes
        // whatever the intersection's size: the floors never go below that over the range.
        let span = (kept[..kept_count]
            .iter()
            .copied()
            .fold(f64::NEG_INFINITY, f64::max)
            - kept[..kept_count]
                .iter()
                .copied()
                .fold(f64::INFINITY, f64::min))
        .max(0.0);
        let round_off = ROUND_OFF * span;
        let floor = |estimate: &[f64; 9]| {
            let volume = (FLOOR * estimate[0].abs()).max(round_off);
            let surface = (FLOOR * (estimate[7].abs() + estimate[8].abs())).max(round_off);
            // b's unsigned area only decides containment: it may keep more.
            [
                volume,
                volume,
                volume,
                volume,
                surface,
                surface,
                surface,
                surface,
                1e4 * surface,
            ]
        };
        let s = ADAPTIVE.integrate_pieces(&mut kept[..kept_count], &mut f, &floor, work);
        if s[0].is_nan() || s[0] <= 0.0 {
            return None;
        }
        Some(SlicedMoments {
            volume: s[0],
            centroid: Vector3::new(s[1], s[2], s[3]) / s[0],
            area_vector_a: Vector3::new(s[4], s[5], s[6]),
            area_a: s[7],
            area_b: s[8],
        })
    }
}

/// The last point found where `not_empty` holds, bisecting from `inside` (where it holds)
/// towards `outside` to round-off: a region's first or last slice. When `outside` itself
/// holds, the region runs to it and it is returned.
pub(crate) fn last_inside(
    mut inside: f64,
    mut outside: f64,
    not_empty: impl Fn(f64) -> bool,
) -> f64 {
    if not_empty(outside) {
        return outside;
    }
    for _ in 0..200 {
        let mid = 0.5 * (inside + outside);
        if mid == inside || mid == outside {
            break;
        }
        if not_empty(mid) {
            inside = mid;
        } else {
            outside = mid;
        }
    }
    inside
}

/// The boundary between `outside` (where `inside_at` is false) and `inside` (where it is
/// true), by bisection to round-off; the last `t` found outside. The boundary is often
/// `outside` itself (the intersection ends where one solid does, a range end the caller
/// starts from): one look 1e-12 of the bracket inside it settles that without the search,
/// the sliver it leaves holding no volume to speak of (the sections vanish at the end).
fn bisect(mut outside: f64, mut inside: f64, inside_at: impl Fn(f64) -> bool) -> f64 {
    let near = outside + (inside - outside) * 1e-12;
    if near != outside && inside_at(near) {
        return outside;
    }
    for _ in 0..80 {
        let mid = 0.5 * (outside + inside);
        if mid == outside || mid == inside {
            break;
        }
        if inside_at(mid) {
            inside = mid;
        } else {
            outside = mid;
        }
    }
    outside
}

/// The maximiser of the unimodal `f` on `[lo, hi]`, by golden-section search to round-off.
pub(crate) fn golden_maximum(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> f64 {
    golden_search(lo, hi, 90, f).0
}

/// The maximum of the unimodal `f` on `[lo, hi]` by golden sections, at most `steps` of them
/// (fewer once the bracket is at round-off): `(x, f(x))`.
pub(crate) fn golden_search(
    mut lo: f64,
    mut hi: f64,
    steps: usize,
    f: impl Fn(f64) -> f64,
) -> (f64, f64) {
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = hi - ratio * (hi - lo);
    let mut x2 = lo + ratio * (hi - lo);
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..steps {
        if f1 < f2 {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + ratio * (hi - lo);
            f2 = f(x2);
        } else {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - ratio * (hi - lo);
            f1 = f(x1);
        }
        if hi - lo <= f64::EPSILON * (lo.abs().max(hi.abs())) {
            break;
        }
    }
    if f1 >= f2 { (x1, f1) } else { (x2, f2) }
}
