//! The overlap of the unit disc with a convex region of the plane, in closed form: its
//! area, first moments, and the pieces of both boundaries that bound it.
//!
//! The unit disc is an ellipsoid's section seen through the affine map that makes the section
//! a circle (angle `θ` on the circle); the region is the other solid's section seen through
//! the same map: a convex polygon (a box) or an ellipse `k + K·(cos φ, sin φ)` (an ellipsoid
//! or a cylinder), `det K > 0`.
//!
//! - **Polygon**: the signed decomposition about the disc's centre. Each directed edge
//!   `p → q` spans the triangle `(0, p, q)`; its part inside the disc is a triangle where the
//!   edge is inside the circle and a circular sector where it is outside (the edge's
//!   crossings with the circle: a quadratic, solved without cancellation). The signed pieces
//!   add up to the overlap, arcs included (arc integrals are additive in the angle).
//! - **Ellipse**: the crossings are the roots of `f(θ) = |K⁻¹(u(θ) − k)|² − 1`, a
//!   trigonometric polynomial of degree 2: the half-angle substitution turns it into a real
//!   quartic, with the substitution's blind spot (`θ = θ_r + π`) put where `|f|` is largest
//!   among eight samples, so the leading coefficient is well away from zero. The quartic's
//!   roots come from Aberth's simultaneous iteration (the eigenvalues of its companion matrix
//!   by a Schur decomposition when it does not settle), the real ones polished by Newton on
//!   `f` itself.
//!   Arcs between consecutive crossings, of the circle and of the ellipse, are kept when their
//!   midpoints lie inside the other curve, and Green's theorem sums them. A root missed near
//!   a tangency (a complex pair closer than 1e-6 to the real axis is kept as real) loses a
//!   sliver whose area is of the order of the cube of the roots' separation; a spurious root
//!   only splits an arc in two with the same classification. No crossing: one curve is
//!   inside the other (tested at one point) or they are apart. `f ≡ 0` within round-off (the
//!   same circle): the disc.
//!
//! Green's theorem: area `½∮(x dy − y dx)`, moments `⅓∮x(x dy − y dx)` and `⅓∮y(x dy − y dx)`;
//! on arcs of ellipses these are trigonometric polynomials of degree 2, integrated exactly.

use crate::methods::disc_section::{Piece, cross, unit_disc_pieces};
use nalgebra::{Complex, Matrix2, Matrix4, Schur, Vector2};
use std::f64::consts::{FRAC_PI_4, PI, TAU};

/// [`DiscOverlap::shape`] of an ellipse overlap without crossings where the unit circle lies
/// inside the ellipse.
const CIRCLE_INSIDE: usize = 1;
/// [`DiscOverlap::shape`] of an ellipse overlap without crossings where the ellipse lies inside
/// the unit circle.
const ELLIPSE_INSIDE: usize = 3;

/// Most arcs of one kind an overlap keeps.
pub(crate) const MAX_ARCS: usize = 16;

/// Parameter intervals `(start, end)` of boundary arcs (signed: `end < start` runs
/// clockwise).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Arcs {
    spans: [(f64, f64); MAX_ARCS],
    len: usize,
}

impl Default for Arcs {
    fn default() -> Self {
        Self {
            spans: [(0.0, 0.0); MAX_ARCS],
            len: 0,
        }
    }
}

impl Arcs {
    /// Adds the arc from `start` to `end`.
    pub(crate) fn push(&mut self, start: f64, end: f64) {
        debug_assert!(self.len < MAX_ARCS, "too many arcs");
        if self.len < MAX_ARCS {
            self.spans[self.len] = (start, end);
            self.len += 1;
        }
    }

    /// The arcs kept.
    pub(crate) fn spans(&self) -> &[(f64, f64)] {
        &self.spans[..self.len]
    }
}

/// The overlap of the unit disc with a region, in the disc's coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct DiscOverlap {
    /// Area.
    pub area: f64,
    /// First moments `∫ w dA`.
    pub moment: Vector2<f64>,
    /// `Σ (u(θ₁) − u(θ₀))` over the circle's arcs inside the region (`u(θ) = (cos θ, sin θ)`).
    pub chord: Vector2<f64>,
    /// `Σ (θ₁ − θ₀)` over those arcs.
    pub angle: f64,
    /// The circle's arcs inside the region, in `θ`.
    pub arcs: Arcs,
    /// Polygon: the length of its edges inside the disc, measured after the map `map` given
    /// to [`disc_polygon`].
    pub other_length: f64,
    /// Ellipse: its arcs inside the disc, in `φ`.
    pub other_arcs: Arcs,
    /// The overlap's shape class: crossings of the two boundaries, plus 16 per polygon
    /// vertex inside the disc; an ellipse without crossings is 1 inside it, 3 holding it, 0
    /// apart. Where it changes with the slice, the moments have a kink.
    pub shape: usize,
}

pub(crate) fn on_circle(theta: f64) -> Vector2<f64> {
    Vector2::new(theta.cos(), theta.sin())
}

impl DiscOverlap {
    /// Adds the circle's arc from `t0` to `t1` (a sector about the centre for the area and
    /// moments, which is Green's integral along the arc).
    pub(crate) fn add_circle_arc(&mut self, t0: f64, t1: f64) {
        let (s0, c0) = t0.sin_cos();
        let (s1, c1) = t1.sin_cos();
        self.area += 0.5 * (t1 - t0);
        self.moment += Vector2::new(s1 - s0, c0 - c1) / 3.0;
        self.chord += Vector2::new(c1 - c0, s1 - s0);
        self.angle += t1 - t0;
        self.arcs.push(t0, t1);
    }

    /// Adds the ellipse's arc `k + K u(φ)`, `φ` from `f0` to `f1`: Green's integrals.
    pub(crate) fn add_ellipse_arc(&mut self, k: &Vector2<f64>, m: &Matrix2<f64>, f0: f64, f1: f64) {
        // p × p' = det K + a cos φ + b sin φ.
        let k1 = m.column(0).into_owned();
        let k2 = m.column(1).into_owned();
        let w = [m.determinant(), cross(k, &k2), -cross(k, &k1)];
        let x = [k.x, m[(0, 0)], m[(0, 1)]];
        let y = [k.y, m[(1, 0)], m[(1, 1)]];
        self.area += 0.5 * trig_product_integral(&w, &[1.0, 0.0, 0.0], f0, f1);
        self.moment += Vector2::new(
            trig_product_integral(&x, &w, f0, f1),
            trig_product_integral(&y, &w, f0, f1),
        ) / 3.0;
        self.other_arcs.push(f0, f1);
    }
}

/// `∫ (c₀ + c₁ cos φ + c₂ sin φ)(d₀ + d₁ cos φ + d₂ sin φ) dφ` from `f0` to `f1`.
pub(crate) fn trig_product_integral(c: &[f64; 3], d: &[f64; 3], f0: f64, f1: f64) -> f64 {
    let (s0, co0) = f0.sin_cos();
    let (s1, co1) = f1.sin_cos();
    let span = f1 - f0;
    let sin_diff = s1 - s0;
    let cos_diff = co1 - co0;
    // sin 2φ = 2 sin φ cos φ.
    let sin2_diff = 2.0 * (s1 * co1 - s0 * co0);
    let sin_sq_diff = (s1 - s0) * (s1 + s0);
    c[0] * d[0] * span + (c[0] * d[1] + c[1] * d[0]) * sin_diff
        - (c[0] * d[2] + c[2] * d[0]) * cos_diff
        + c[1] * d[1] * (0.5 * span + 0.25 * sin2_diff)
        + c[2] * d[2] * (0.5 * span - 0.25 * sin2_diff)
        + (c[1] * d[2] + c[2] * d[1]) * 0.5 * sin_sq_diff
}

/// The overlap of the unit disc with the convex polygon `vertices` (counter-clockwise).
/// Edge lengths inside the disc are measured after `map` (the map back to the slice plane).
pub(crate) fn disc_polygon(vertices: &[Vector2<f64>], map: &Matrix2<f64>) -> DiscOverlap {
    let mut out = DiscOverlap::default();
    unit_disc_pieces(vertices, 1.0, &mut |piece| match piece {
        Piece::Edge {
            crossings,
            starts_inside,
            ..
        } => out.shape += crossings + if starts_inside { 16 } else { 0 },
        Piece::Chord { a, e, .. } => {
            let twice = cross(&a, &e);
            out.area += 0.5 * twice;
            out.moment += (a + e) * (twice / 6.0);
            out.other_length += (map * (e - a)).norm();
        }
        Piece::Arc { start, sweep } => out.add_circle_arc(start, start + sweep),
    });
    out
}

/// `f(θ) = a₀ + a₁ cos θ + b₁ sin θ + a₂ cos 2θ + b₂ sin 2θ`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TrigQuadratic {
    a0: f64,
    a1: f64,
    b1: f64,
    a2: f64,
    b2: f64,
}

impl TrigQuadratic {
    pub(crate) fn value(&self, t: f64) -> f64 {
        let (s, c) = t.sin_cos();
        let (s2, c2) = (2.0 * s * c, (c - s) * (c + s));
        self.a0 + self.a1 * c + self.b1 * s + self.a2 * c2 + self.b2 * s2
    }

    fn slope(&self, t: f64) -> f64 {
        let (s, c) = t.sin_cos();
        let (s2, c2) = (2.0 * s * c, (c - s) * (c + s));
        -self.a1 * s + self.b1 * c - 2.0 * self.a2 * s2 + 2.0 * self.b2 * c2
    }

    /// The real roots in `[0, 2π)`, sorted (at most 4), and how many.
    fn roots(&self) -> ([f64; 4], usize) {
        let mut best = (0.0, -1.0);
        for j in 0..8 {
            let t = j as f64 * FRAC_PI_4;
            let v = self.value(t).abs();
            if v > best.1 {
                best = (t, v);
            }
        }
        // θ = θ_r + ψ with ψ = π at the largest sample.
        let shift = best.0 - PI;
        let (s, c) = shift.sin_cos();
        let (s2, c2) = (2.0 * s * c, (c - s) * (c + s));
        let a1 = self.a1 * c + self.b1 * s;
        let b1 = -self.a1 * s + self.b1 * c;
        let a2 = self.a2 * c2 + self.b2 * s2;
        let b2 = -self.a2 * s2 + self.b2 * c2;
        let a0 = self.a0;
        // x = tan(ψ/2), times (1 + x²)²: coefficients of x⁴ … x⁰.
        let lead = a0 - a1 + a2;
        let coeffs = [
            2.0 * b1 - 4.0 * b2,
            2.0 * a0 - 6.0 * a2,
            2.0 * b1 + 4.0 * b2,
            a0 + a1 + a2,
        ];
        let monic = coeffs.map(|ck| ck / lead);
        let mut roots = [0.0; 4];
        let mut n = 0;
        let eigenvalues = if monic.iter().all(|v| v.is_finite()) {
            quartic_roots_aberth(&monic).or_else(|| quartic_roots_schur(&monic))
        } else {
            None
        };
        match eigenvalues {
            Some(e) => {
                for z in e {
                    if z.im.abs() <= 1e-6 * (1.0 + z.re.abs()) {
                        roots[n] = self.polish(shift + 2.0 * z.re.atan());
                        n += 1;
                    }
                }
            }
            None => n = self.roots_by_sampling(&mut roots),
        }
        for r in &mut roots[..n] {
            *r = r.rem_euclid(TAU);
        }
        roots[..n].sort_by(f64::total_cmp);
        (roots, n)
    }

    /// Newton on `f`, each step kept only when it lowers `|f|`.
    fn polish(&self, mut t: f64) -> f64 {
        let mut value = self.value(t);
        for _ in 0..6 {
            let slope = self.slope(t);
            if slope == 0.0 || value == 0.0 {
                break;
            }
            let next = t - value / slope;
            let next_value = self.value(next);
            // A NaN step is refused too.
            if next_value.abs().partial_cmp(&value.abs()) != Some(std::cmp::Ordering::Less) {
                break;
            }
            t = next;
            value = next_value;
        }
        t
    }

    /// The fallback when the eigenvalues are not available: sign changes over 64 samples,
    /// bisected.
    fn roots_by_sampling(&self, roots: &mut [f64; 4]) -> usize {
        let mut n = 0;
        let step = TAU / 64.0;
        for j in 0..64 {
            let (mut lo, mut hi) = (j as f64 * step, (j + 1) as f64 * step);
            let (flo, fhi) = (self.value(lo), self.value(hi));
            if n == 4 || (flo < 0.0) == (fhi < 0.0) {
                continue;
            }
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if (self.value(mid) < 0.0) == (flo < 0.0) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            roots[n] = 0.5 * (lo + hi);
            n += 1;
        }
        n
    }
}

/// Where the unit circle meets the ellipse `center + matrix·u(φ)` (`det matrix > 0`).
pub(crate) enum CircleCrossings {
    /// The matrix is singular: no ellipse.
    Degenerate,
    /// The ellipse is the unit circle within round-off.
    Same,
    /// No crossing, the circle inside the ellipse.
    CircleInside,
    /// No crossing, the ellipse inside the circle.
    EllipseInside,
    /// No crossing, the two apart.
    Apart,
    /// Crossings at the circle's angles `theta[..n]` (ascending in `[0, 2π)`).
    At {
        /// The angles.
        theta: [f64; 4],
        /// How many.
        n: usize,
        /// `f(θ) = |K⁻¹(u(θ) − k)|² − 1`, negative where the circle runs inside the ellipse.
        inside: TrigQuadratic,
        /// `K⁻¹`, for the ellipse's parameter `φ` of a crossing.
        inverse: Matrix2<f64>,
    },
}

impl CircleCrossings {
    /// The crossings of the unit circle with the ellipse `center + matrix·u(φ)`.
    pub(crate) fn of(center: &Vector2<f64>, matrix: &Matrix2<f64>) -> Self {
        let Some(inverse) = matrix.try_inverse() else {
            return Self::Degenerate;
        };
        let g = inverse.transpose() * inverse;
        let gk = g * center;
        let f = TrigQuadratic {
            a0: 0.5 * (g[(0, 0)] + g[(1, 1)]) + center.dot(&gk) - 1.0,
            a1: -2.0 * gk.x,
            b1: -2.0 * gk.y,
            a2: 0.5 * (g[(0, 0)] - g[(1, 1)]),
            b2: g[(0, 1)],
        };
        let size = 0.5 * (g[(0, 0)] + g[(1, 1)]) + center.dot(&gk) + 1.0;
        let largest = f.a0.abs() + f.a1.abs() + f.b1.abs() + f.a2.abs() + f.b2.abs();
        if largest <= 1e-14 * size {
            return Self::Same;
        }
        let (theta, n) = f.roots();
        if n > 0 {
            return Self::At {
                theta,
                n,
                inside: f,
                inverse,
            };
        }
        // Without crossings one point tells which curve holds the other (two concentric
        // circles swap it with no tangency between).
        if f.value(0.0) < 0.0 {
            Self::CircleInside
        } else if (center + matrix.column(0)).norm_squared() < 1.0 {
            Self::EllipseInside
        } else {
            Self::Apart
        }
    }
}

/// The ellipse's parameter `φ ∈ [0, 2π)` of the circle's point at angle `theta`.
pub(crate) fn ellipse_parameter(inverse: &Matrix2<f64>, center: &Vector2<f64>, theta: f64) -> f64 {
    let w = inverse * (on_circle(theta) - center);
    w.y.atan2(w.x).rem_euclid(TAU)
}

/// The overlap of the unit disc with the ellipse `center + matrix·u(φ)` (`det matrix > 0`).
pub(crate) fn disc_ellipse(center: &Vector2<f64>, matrix: &Matrix2<f64>) -> DiscOverlap {
    let mut out = DiscOverlap::default();
    let (roots, n, f, inverse) = match CircleCrossings::of(center, matrix) {
        CircleCrossings::Degenerate | CircleCrossings::Apart => return out,
        CircleCrossings::Same => {
            out.add_circle_arc(0.0, TAU);
            return out;
        }
        CircleCrossings::CircleInside => {
            out.add_circle_arc(0.0, TAU);
            out.shape = CIRCLE_INSIDE;
            return out;
        }
        CircleCrossings::EllipseInside => {
            out.add_ellipse_arc(center, matrix, 0.0, TAU);
            out.shape = ELLIPSE_INSIDE;
            return out;
        }
        CircleCrossings::At {
            theta,
            n,
            inside,
            inverse,
        } => (theta, n, inside, inverse),
    };
    out.shape = n;
    let mut params = [0.0; 4];
    for k in 0..n {
        let t0 = roots[k];
        let t1 = if k + 1 < n {
            roots[k + 1]
        } else {
            roots[0] + TAU
        };
        if t1 > t0 && f.value(0.5 * (t0 + t1)) < 0.0 {
            out.add_circle_arc(t0, t1);
        }
        params[k] = ellipse_parameter(&inverse, center, t0);
    }
    params[..n].sort_by(f64::total_cmp);
    for k in 0..n {
        let f0 = params[k];
        let f1 = if k + 1 < n {
            params[k + 1]
        } else {
            params[0] + TAU
        };
        let mid = 0.5 * (f0 + f1);
        if f1 > f0 && (center + matrix * on_circle(mid)).norm_squared() < 1.0 {
            out.add_ellipse_arc(center, matrix, f0, f1);
        }
    }
    out
}

/// The four complex roots of `x⁴ + c₀x³ + c₁x² + c₂x + c₃` by Aberth's simultaneous
/// iteration (cubic convergence for simple roots), from four points on a circle of the roots'
/// radius bound, to 1e-13 relative or until the steps stall below 1e-7 (a double root; the
/// real roots are polished on `f` afterwards); `None` when it has not settled within 60
/// steps, for [`quartic_roots_schur`] to answer.
fn quartic_roots_aberth(c: &[f64; 4]) -> Option<[Complex<f64>; 4]> {
    let p = |z: Complex<f64>| (((z + c[0]) * z + c[1]) * z + c[2]) * z + c[3];
    let dp = |z: Complex<f64>| ((z * 4.0 + 3.0 * c[0]) * z + 2.0 * c[1]) * z + c[2];
    // Every root lies within 2·max |c_k|^(1/(4−k)) (Fujiwara); start just inside, turned off
    // the axes so that no start is real or conjugate to another.
    let bound = 2.0
        * c.iter()
            .enumerate()
            .map(|(k, ck)| ck.abs().powf(1.0 / (k + 1) as f64))
            .fold(0.0, f64::max);
    let radius = if bound > 0.0 { 0.5 * bound } else { 1.0 };
    let mut z = [Complex::new(0.0, 0.0); 4];
    for (k, zk) in z.iter_mut().enumerate() {
        *zk = Complex::from_polar(radius, 0.4 + k as f64 * std::f64::consts::FRAC_PI_2);
    }
    let mut previous = f64::INFINITY;
    for _ in 0..60 {
        let mut largest_step = 0.0f64;
        for k in 0..4 {
            let (value, slope) = (p(z[k]), dp(z[k]));
            if value == Complex::new(0.0, 0.0) {
                continue;
            }
            let ratio = value / slope;
            let mut repulsion = Complex::new(0.0, 0.0);
            for (j, zj) in z.iter().enumerate() {
                if j != k {
                    repulsion += (z[k] - zj).inv();
                }
            }
            let step = ratio / (Complex::new(1.0, 0.0) - ratio * repulsion);
            if !step.re.is_finite() || !step.im.is_finite() {
                return None;
            }
            z[k] -= step;
            // Squared, to spare the roots: compared with squared thresholds below.
            let size = 1.0 + z[k].re.abs() + z[k].im.abs();
            largest_step = largest_step.max(step.norm_sqr() / (size * size));
        }
        // Settled, or stalled at round-off: a double root is only known to about √ε, where
        // the steps stop shrinking (they halve while it converges, linearly).
        if largest_step <= 1e-28 || (largest_step <= 1e-16 && largest_step > 0.49 * previous) {
            return Some(z);
        }
        previous = largest_step;
    }
    None
}

/// The same roots as the eigenvalues of the companion matrix (a general Schur
/// decomposition: several times the cost, but indifferent to multiple roots).
fn quartic_roots_schur(c: &[f64; 4]) -> Option<[Complex<f64>; 4]> {
    let mut companion = Matrix4::zeros();
    for (k, ck) in c.iter().enumerate() {
        companion[(0, k)] = -ck;
    }
    for k in 1..4 {
        companion[(k, k - 1)] = 1.0;
    }
    Schur::try_new(companion, f64::EPSILON, 400).map(|schur| {
        // A double real root's 2×2 block can come back with a NaN imaginary part (its
        // discriminant rounded below zero): it is real.
        let e = schur
            .complex_eigenvalues()
            .map(|z| Complex::new(z.re, if z.im.is_nan() { 0.0 } else { z.im }));
        [e[0], e[1], e[2], e[3]]
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Aberth's roots are the companion matrix's eigenvalues: on 20,000 seeded quartics
    /// (random coefficients, and double roots and close pairs by construction), the same roots
    /// within 1e-7 of their size (1e-6 for a double root, known to √ε either way), and the
    /// iteration falls back to Schur rarely.
    #[test]
    fn aberth_roots_agree_with_the_companion_eigenvalues() {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut uniform = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let mut fallbacks = 0;
        for case in 0..20_000 {
            let c = match case % 3 {
                0 => [
                    uniform() * 4.0,
                    uniform() * 4.0,
                    uniform() * 4.0,
                    uniform() * 4.0,
                ],
                // (x − r)²(x² + px + q): a double real root.
                1 => {
                    let (r, p, q) = (uniform() * 2.0, uniform() * 2.0, uniform() * 2.0);
                    [
                        p - 2.0 * r,
                        q - 2.0 * r * p + r * r,
                        r * r * p - 2.0 * r * q,
                        r * r * q,
                    ]
                }
                // (x − r)(x − r − δ)(x² + px + q): a close real pair.
                _ => {
                    let (r, p, q) = (uniform() * 2.0, uniform() * 2.0, uniform() * 2.0);
                    let d = 1e-4 * (1.0 + uniform());
                    let (s1, s2) = (2.0 * r + d, r * (r + d));
                    [p - s1, q - s1 * p + s2, s2 * p - s1 * q, s2 * q]
                }
            };
            let Some(schur) = quartic_roots_schur(&c) else {
                continue;
            };
            let Some(aberth) = quartic_roots_aberth(&c) else {
                fallbacks += 1;
                continue;
            };
            let double = case % 3 == 1;
            for z in schur {
                let nearest = aberth
                    .iter()
                    .map(|w| (w - z).norm())
                    .fold(f64::INFINITY, f64::min);
                // A double root is known to √ε by either method.
                let allowed = if double { 1e-6 } else { 1e-7 } * (1.0 + z.norm());
                assert!(nearest <= allowed, "{case}: {c:?}\n{schur:?}\n{aberth:?}");
            }
        }
        assert!(fallbacks < 200, "{fallbacks} fallbacks");
    }

    /// Area and centroid of the overlap by a fine grid over the disc (an independent count).
    fn grid(inside: impl Fn(&Vector2<f64>) -> bool) -> (f64, Vector2<f64>) {
        let n = 1000;
        let h = 2.0 / n as f64;
        let (mut area, mut m) = (0.0, Vector2::zeros());
        for i in 0..n {
            for j in 0..n {
                let p = Vector2::new(-1.0 + (i as f64 + 0.5) * h, -1.0 + (j as f64 + 0.5) * h);
                if p.norm_squared() < 1.0 && inside(&p) {
                    area += h * h;
                    m += p * h * h;
                }
            }
        }
        (area, m)
    }

    #[test]
    fn disc_and_ellipse_overlap_matches_a_grid_count() {
        let k = Vector2::new(0.7, -0.3);
        let m = Matrix2::new(0.8, 0.3, -0.2, 0.5);
        let o = disc_ellipse(&k, &m);
        let inv = m.try_inverse().unwrap();
        let (area, moment) = grid(|p| (inv * (p - k)).norm_squared() < 1.0);
        assert!((o.area - area).abs() < 2e-3, "{} vs {area}", o.area);
        assert!(
            (o.moment - moment).norm() < 2e-3,
            "{:?} vs {moment:?}",
            o.moment
        );
    }

    #[test]
    fn disc_and_square_overlap_matches_a_grid_count() {
        let v = [
            Vector2::new(-0.2, -1.5),
            Vector2::new(1.5, -1.5),
            Vector2::new(1.5, 0.4),
            Vector2::new(-0.2, 0.4),
        ];
        let o = disc_polygon(&v, &Matrix2::identity());
        let (area, moment) = grid(|p| p.x > -0.2 && p.y < 0.4);
        assert!((o.area - area).abs() < 2e-3, "{} vs {area}", o.area);
        assert!((o.moment - moment).norm() < 2e-3);
        // Inside edges: x = −0.2 from y = −√0.96 to 0.4, and y = 0.4 from x = −0.2 to √0.84.
        let expected = (0.4 + 0.96f64.sqrt()) + (0.84f64.sqrt() + 0.2);
        assert!((o.other_length - expected).abs() < 1e-14);
    }

    #[test]
    fn two_circles_give_the_lens_in_closed_form() {
        // Unit circle and the circle of radius 1 at (1, 0): lens area 2π/3 − √3/2.
        let o = disc_ellipse(&Vector2::new(1.0, 0.0), &Matrix2::identity());
        let exact = 2.0 * PI / 3.0 - 3f64.sqrt() / 2.0;
        assert!((o.area - exact).abs() < 1e-14, "{}", o.area);
        assert!((o.moment.x / o.area - 0.5).abs() < 1e-14);
        assert!(o.moment.y.abs() < 1e-14);
        // Contained and apart.
        let inner = disc_ellipse(&Vector2::new(0.1, 0.0), &(0.5 * Matrix2::identity()));
        assert!((inner.area - 0.25 * PI).abs() < 1e-15);
        let apart = disc_ellipse(&Vector2::new(3.0, 0.0), &Matrix2::identity());
        assert_eq!(apart.area, 0.0);
        let same = disc_ellipse(&Vector2::zeros(), &Matrix2::identity());
        assert!((same.area - PI).abs() < 1e-15);
    }
}
