//! The closed-form events of the frustum–frustum slicing: where a circle crosses a frustum's
//! lateral quadric or a cap plane, and the rays from a point tangent to a quadric's section.
//!
//! A frustum (a cylinder when the slope is 0) with bottom centre `o`, unit axis `w`, radius
//! `r₀ + k z` at height `z = w·(x − o)` has the lateral quadric
//! `Q(x) = |P(x − o)|² − (r₀ + k w·(x − o))²`, `P = I − w wᵀ` (negative inside). Along a
//! circle `c + r(cos ψ a₁ + sin ψ a₂)` it is a trigonometric polynomial of degree two in `ψ`,
//! whose zeros are a quartic's in `τ = tan(ψ/2)`: solved on the two half-turns
//! `|ψ| ≤ π/2` and `|ψ − π| ≤ π/2` (there `|τ| ≤ 1`, well conditioned) by
//! the box–revolved pair's `roots_in`, then polished by Newton's
//! method on the trigonometric form. Extra roots (on the quadric's extension beyond the caps,
//! or its other nappe) only add cuts, which cost time but not accuracy.

use crate::pairs::box_revolved::events::roots_in;
use contact_core::{Matrix3, Vector3};
use std::f64::consts::PI;

/// The lateral quadric of a frustum (or cylinder), in the working frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Quadric {
    /// Bottom centre.
    pub origin: Vector3,
    /// Unit axis.
    pub axis: Vector3,
    /// Radius at the bottom.
    pub r0: f64,
    /// Radius change per unit of height.
    pub slope: f64,
    /// Length.
    pub len: f64,
}

impl Quadric {
    /// Height `w·(x − o)` of `x` along the axis.
    pub fn height(&self, x: &Vector3) -> f64 {
        self.axis.dot(&(x - self.origin))
    }

    /// The part of `x − o` across the axis.
    pub fn across(&self, x: &Vector3) -> Vector3 {
        let d = x - self.origin;
        d - self.axis * self.axis.dot(&d)
    }

    /// The radius at the height of `x`.
    pub fn radius_at(&self, x: &Vector3) -> f64 {
        self.r0 + self.slope * self.height(x)
    }

    /// The extent along the working frame's `z` of the solid's two rims: their extreme
    /// heights `z₀ + w_z·h ∓ r·sqrt(w_x² + w_y²)` at `h = 0` and `h = len`.
    pub fn z_range(&self) -> (f64, f64) {
        let spread = self.axis.x.hypot(self.axis.y);
        let mut range = (f64::INFINITY, f64::NEG_INFINITY);
        for (h, r) in [(0.0, self.r0), (self.len, self.r0 + self.slope * self.len)] {
            let z = self.origin.z + self.axis.z * h;
            range = (range.0.min(z - r * spread), range.1.max(z + r * spread));
        }
        range
    }

    /// `Q(x)`, factored as `(|P(x − o)| − r)(|P(x − o)| + r)` so that points near the surface
    /// keep their digits.
    pub fn value(&self, x: &Vector3) -> f64 {
        let (rho, r) = (self.across(x).norm(), self.radius_at(x));
        (rho - r) * (rho + r)
    }

    /// A random frustum, cone or cylinder (radii in `[0, 1)`, length in `[0.2, 6)`, origin
    /// near the axis `z`, any axis): the clearance tests' solids.
    #[cfg(test)]
    pub fn random(rng: &mut crate::test_rng::Rng) -> Self {
        let (r0, r1, len) = (
            rng.uniform(0.0, 1.0),
            rng.uniform(0.0, 1.0),
            rng.uniform(0.2, 6.0),
        );
        Self {
            origin: Vector3::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), 0.0),
            axis: rng.unit(),
            r0,
            slope: (r1 - r0) / len,
            len,
        }
    }

    /// Whether `x` is in the solid (between the caps, within the radius at its height): the
    /// clearance tests' brute force.
    #[cfg(test)]
    pub fn holds(&self, x: &Vector3) -> bool {
        (0.0..=self.len).contains(&self.height(x)) && self.across(x).norm() <= self.radius_at(x)
    }

    /// `∇Q(x)/2 = P(x − o) − k r(x) w`.
    pub fn half_gradient(&self, x: &Vector3) -> Vector3 {
        self.across(x) - self.axis * (self.slope * self.radius_at(x))
    }

    /// The quadratic part of `Q`: `P − k² w wᵀ`.
    pub fn matrix(&self) -> Matrix3 {
        Matrix3::identity() - self.axis * self.axis.transpose() * (1.0 + self.slope * self.slope)
    }

    /// A convex function negative exactly inside the solid (bounded by the lateral surface and
    /// the caps), in lengths: `max(|P(x − o)| − r(x), −z, z − L)`, the radial term divided by
    /// `√(1 + k²)` so that each term is a distance to its plane or cone.
    pub fn inside(&self, x: &Vector3) -> f64 {
        let z = self.height(x);
        let radial = (self.across(x).norm() - (self.r0 + self.slope * z)) / self.slope.hypot(1.0);
        radial.max(-z).max(z - self.len)
    }
}

/// The coefficients `[m₁₁, m₁₂, m₂₂, g₁, g₂, h]` of `Q` along the circle `c + r(C a₁ + S a₂)`:
/// `m₁₁C² + 2m₁₂CS + m₂₂S² + 2(g₁C + g₂S) + h`.
fn circle_form(q: &Quadric, c: &Vector3, a1: &Vector3, a2: &Vector3, r: f64) -> [f64; 6] {
    let m = q.matrix();
    let g = q.half_gradient(c);
    [
        r * r * a1.dot(&(m * a1)),
        r * r * a1.dot(&(m * a2)),
        r * r * a2.dot(&(m * a2)),
        r * a1.dot(&g),
        r * a2.dot(&g),
        q.value(c),
    ]
}

/// The trigonometric form at `ψ` and its derivative.
fn trig(f: &[f64; 6], psi: f64) -> (f64, f64) {
    let (s, c) = psi.sin_cos();
    let value =
        f[0] * c * c + 2.0 * f[1] * c * s + f[2] * s * s + 2.0 * (f[3] * c + f[4] * s) + f[5];
    let slope =
        2.0 * (f[2] - f[0]) * c * s + 2.0 * f[1] * (c * c - s * s) + 2.0 * (f[4] * c - f[3] * s);
    (value, slope)
}

/// The angles `ψ ∈ (−π, π]` where the circle `c + r(cos ψ a₁ + sin ψ a₂)` crosses `q`'s
/// lateral quadric (at most four); how many. A circle lying on the quadric (every
/// coefficient at round-off of the circle's size) has none.
pub(crate) fn circle_crossings(
    q: &Quadric,
    c: &Vector3,
    a1: &Vector3,
    a2: &Vector3,
    r: f64,
) -> ([f64; 8], usize) {
    let f = circle_form(q, c, a1, a2, r);
    let scale = f.iter().map(|v| v.abs()).fold(0.0, f64::max);
    let size = (r + c.norm() + q.origin.norm() + q.r0 + q.len).powi(2);
    if scale.is_nan() || scale <= 1e-14 * size {
        return ([0.0; 8], 0);
    }
    trig_roots(&f)
}

/// The zeros `ψ ∈ (−π, π]` of the trigonometric form
/// `m₁₁C² + 2m₁₂CS + m₂₂S² + 2(g₁C + g₂S) + h` (`f = [m₁₁, m₁₂, m₂₂, g₁, g₂, h]`, `C = cos ψ`,
/// `S = sin ψ`; at most four); how many.
pub(crate) fn trig_roots(f: &[f64; 6]) -> ([f64; 8], usize) {
    let mut out = [0.0; 8];
    let mut n = 0;
    for (flip, offset) in [(1.0, 0.0), (-1.0, PI)] {
        // ψ = offset + 2 atan τ: cos and sin change sign with the half-turn, the
        // quadratic part does not.
        let (m11, m12, m22, g1, g2, h) = (f[0], f[1], f[2], flip * f[3], flip * f[4], f[5]);
        let poly = [
            m11 + 2.0 * g1 + h,
            4.0 * (m12 + g2),
            -2.0 * m11 + 4.0 * m22 + 2.0 * h,
            4.0 * (g2 - m12),
            m11 - 2.0 * g1 + h,
        ];
        let (roots, count) = roots_in(&poly, -1.0 - 1e-9, 1.0 + 1e-9);
        for &tau in &roots[..count] {
            let mut psi = offset + 2.0 * tau.atan();
            for _ in 0..3 {
                let (v, d) = trig(f, psi);
                if d == 0.0 || !(v / d).is_finite() || (v / d).abs() > 1e-3 {
                    break;
                }
                psi -= v / d;
            }
            if n < out.len() {
                out[n] = wrap(psi);
                n += 1;
            }
        }
    }
    (out, n)
}

/// `ψ` in `(−π, π]`.
pub(crate) fn wrap(psi: f64) -> f64 {
    let mut x = psi;
    while x > PI {
        x -= 2.0 * PI;
    }
    while x <= -PI {
        x += 2.0 * PI;
    }
    x
}

/// The angles where `a cos ψ + b sin ψ = c` (none, or two, or one when tangent).
pub(crate) fn sinusoid_roots(a: f64, b: f64, c: f64) -> ([f64; 2], usize) {
    let amplitude = a.hypot(b);
    if amplitude.is_nan() || amplitude == 0.0 || c.abs() > amplitude {
        return ([0.0; 2], 0);
    }
    let base = b.atan2(a);
    let spread = (c / amplitude).clamp(-1.0, 1.0).acos();
    ([wrap(base + spread), wrap(base - spread)], 2)
}

/// The directions `φ` (of `u = (cos φ, sin φ, 0)`) of the rays from `p` tangent to the section
/// of `q`'s lateral quadric by the plane through `p` normal to `z`: where the quadratic
/// `Q(p + ρu)` has a double root, `(β·u)² − Q(p)·uᵀMu = 0` with `β = ∇Q(p)/2` — a quadratic
/// form in `u`, four directions at most (two lines through `p`).
pub(crate) fn tangent_directions(q: &Quadric, p: &Vector3) -> ([f64; 4], usize) {
    let m = q.matrix();
    let beta = q.half_gradient(p);
    let c = q.value(p);
    let n11 = beta.x * beta.x - c * m[(0, 0)];
    let n12 = beta.x * beta.y - c * m[(0, 1)];
    let n22 = beta.y * beta.y - c * m[(1, 1)];
    // n11 C² + 2 n12 C S + n22 S² = ½(n11 + n22) + ½(n11 − n22) cos 2φ + n12 sin 2φ.
    let (roots, count) = sinusoid_roots(0.5 * (n11 - n22), n12, -0.5 * (n11 + n22));
    let mut out = [0.0; 4];
    for k in 0..count {
        out[2 * k] = wrap(0.5 * roots[k]);
        out[2 * k + 1] = wrap(0.5 * roots[k] + PI);
    }
    (out, 2 * count)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cone() -> Quadric {
        Quadric {
            origin: Vector3::new(0.3, -0.2, 0.1),
            axis: Vector3::new(0.2, 0.5, 0.8).normalize(),
            r0: 0.7,
            slope: -0.3,
            len: 1.5,
        }
    }

    #[test]
    fn circle_crossings_lie_on_the_quadric_and_are_all_found() {
        let q = cone();
        let (c, a1, a2, r) = (Vector3::new(0.1, 0.2, 0.6), Vector3::x(), Vector3::y(), 0.8);
        let (psi, n) = circle_crossings(&q, &c, &a1, &a2, r);
        let at = |p: f64| c + r * (p.cos() * a1 + p.sin() * a2);
        for &p in &psi[..n] {
            assert!(q.value(&at(p)).abs() < 1e-14, "{}", q.value(&at(p)));
        }
        // Every sign change of a fine sampling is near a found root.
        let samples = 20000;
        let mut changes = 0;
        for k in 0..samples {
            let (p0, p1) = (
                -PI + 2.0 * PI * k as f64 / samples as f64,
                -PI + 2.0 * PI * (k + 1) as f64 / samples as f64,
            );
            if (q.value(&at(p0)) > 0.0) != (q.value(&at(p1)) > 0.0) {
                changes += 1;
                assert!(psi[..n].iter().any(|&x| (wrap(x - p0)).abs() < 1e-3));
            }
        }
        assert!(changes >= 2 && changes <= n, "{changes} {n}");
    }

    #[test]
    fn tangent_rays_touch_the_section() {
        let q = cone();
        let p = Vector3::new(1.9, 0.4, 0.5);
        let (phi, n) = tangent_directions(&q, &p);
        assert_eq!(n, 4);
        for &f in &phi[..n] {
            let u = Vector3::new(f.cos(), f.sin(), 0.0);
            let (a, b, c) = (
                u.dot(&(q.matrix() * u)),
                q.half_gradient(&p).dot(&u),
                q.value(&p),
            );
            assert!((b * b - a * c).abs() < 1e-13, "{}", b * b - a * c);
        }
    }
}
