//! The frustum–frustum pair by the divergence theorem: the intersection's volume and first
//! moments as fluxes through the two lateral surfaces alone, each a one-dimensional integral
//! over the azimuth of closed forms along the surface's straight generators.
//!
//! ## The fields
//! With `ŵ` a unit vector perpendicular to both axes (`â × b̂` normalized, exact to round-off
//! in `a`'s frame), `c` a reference point and `(ŵ, ê₁, ê₂)` orthonormal, the fields
//! `s ŵ`, `½ s² ŵ`, `p₁ s ŵ`, `p₂ s ŵ` (`s = (x − c)·ŵ`, `pᵢ = (x − c)·êᵢ`) have divergences
//! `1`, `s`, `p₁`, `p₂`, and all of them are parallel to every cap of both solids, so their
//! flux through the intersection's boundary is the flux through the parts of the two lateral
//! surfaces inside the other solid: the volume and the moments about `c` with no cap
//! integrated.
//!
//! ## A lateral surface inside the other solid
//! In the surface's own frame (axis `z`, radius `R(z) = r₀ + k z`), its generator at azimuth
//! `φ` is the line `(r₀u, 0) + z (k u, 1)`, `u = (cos φ, sin φ, 0)`; it meets the other
//! frustum in one interval in closed form ([`super::slice::interval_on_line`]: a quadratic
//! for the lateral quadric, two planes for the caps), clipped to `0 ≤ z ≤ L`. The surface
//! element is `R (u − k ẑ) dφ dz`, so every integrand is a polynomial in `z` of degree three
//! at most along the generator, integrated exactly by two Gauss points, and the integrals
//! over `φ` run on the adaptive sine-mapped rule between the closed-form events where the
//! interval's ends stop being smooth:
//! - the surface's rims crossing the other's lateral quadric (a quartic each) or its cap
//!   planes (a sinusoid): an end reaching `z = 0` or `z = L`;
//! - the other's rims piercing this lateral quadric (a quartic each): an end passing from the
//!   other's lateral surface to its cap;
//! - the generators tangent to the other's lateral quadric, where the interval opens or
//!   closes with a square-root end: the discriminant `β² − αγ` of the quadratic along the
//!   generator, of degree four in `(cos φ, sin φ)` as written but of degree two in truth (the
//!   discriminant does not change when the line's parameter is shifted, and from the apex —
//!   or, for a cylinder, along a fixed direction — it is a quadratic form in `(k u, 1)`),
//!   so its five Fourier coefficients come exactly from five samples and its zeros are a
//!   quartic's.
//!
//! Spurious roots (beyond a cap, on a cone's other nappe) only add cuts.

use super::quadric::{Quadric, circle_crossings, sinusoid_roots, trig_roots, wrap};
use super::slice::{Line, Pair, interval_on_line, rim_axes};
use crate::quadrature::{Adaptive, MAX_PIECES, Pair as KronrodPair};
use contact_core::{Matrix3, Vector3, WorkCounters};
use std::f64::consts::PI;

/// Components of the lateral integrals: the fluxes of `s ŵ`, `½ s² ŵ`, `p₁ s ŵ`, `p₂ s ŵ`
/// (the volume and the moments about `c` along `ŵ`, `ê₁`, `ê₂`), the surface's area vector
/// inside the other solid (3, outward) and its unsigned area.
pub(crate) const LATERAL: usize = 8;

/// The azimuthal rule: error estimates within 1e-13 relative, as the slices'.
const RULE: Adaptive = Adaptive {
    tolerance: 1e-13,
    max_depth: 20,
    pair: KronrodPair::Kronrod41,
};

/// The reference point and the frame of the fields, in the working frame of the surface's
/// solid.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Fields {
    /// The reference point `c`.
    pub centre: Vector3,
    /// `ŵ`, perpendicular to both axes.
    pub w: Vector3,
    /// `ê₁`.
    pub e1: Vector3,
    /// `ê₂`.
    pub e2: Vector3,
}

impl Fields {
    /// The same fields seen from the frame where `origin` is at zero and `(f1, f2, f3)` are
    /// the axes (orthonormal, right-handed).
    pub fn in_frame(&self, origin: &Vector3, axes: &[Vector3; 3]) -> Self {
        let turn = |v: &Vector3| Vector3::new(axes[0].dot(v), axes[1].dot(v), axes[2].dot(v));
        Self {
            centre: turn(&(self.centre - origin)),
            w: turn(&self.w),
            e1: turn(&self.e1),
            e2: turn(&self.e2),
        }
    }
}

impl Pair {
    /// The generator of `a` at azimuth `(c, s)` as a line seen by `b` (`m` is `b`'s
    /// quadratic form).
    fn generator(&self, m: &Matrix3, c: f64, s: f64) -> Line {
        let q = &self.b;
        let (r0, k) = (self.a.r0, self.a.slope);
        let v = Vector3::new(r0 * c, r0 * s, 0.0) - q.origin;
        let d = Vector3::new(k * c, k * s, 1.0);
        let height = q.axis.dot(&v);
        let across = v - q.axis * height;
        let (rho, radius) = (across.norm(), q.r0 + q.slope * height);
        let half_gradient = across - q.axis * (q.slope * radius);
        Line {
            height,
            rate: q.axis.dot(&d),
            quadratic: [
                d.dot(&(m * d)),
                d.dot(&half_gradient),
                (rho - radius) * (rho + radius),
            ],
            tol: 0.0,
        }
    }

    /// The integrand per unit of `φ` (see [`LATERAL`]).
    fn lateral_integrand(
        &self,
        (m, slant): (&Matrix3, f64),
        fields: &Fields,
        phi: f64,
    ) -> [f64; LATERAL] {
        let mut out = [0.0; LATERAL];
        let (s, c) = phi.sin_cos();
        let Some((enter, _, exit, _)) = interval_on_line(&self.b, &self.generator(m, c, s)) else {
            return out;
        };
        let (lo, hi) = (enter.max(0.0), exit.min(self.a.len));
        if hi <= lo {
            return out;
        }
        let (r0, k) = (self.a.r0, self.a.slope);
        let Fields { centre, w, e1, e2 } = fields;
        // ŵ·(u − k ẑ): the surface element's projection on ŵ per unit of R.
        let facing = w.x * c + w.y * s - k * w.z;
        let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        let offset = half / 3f64.sqrt();
        for z in [mid - offset, mid + offset] {
            let r = r0 + k * z;
            let d = Vector3::new(r * c, r * s, z) - centre;
            let (along, p1, p2) = (d.dot(w), d.dot(e1), d.dot(e2));
            let flux = half * r * facing * along;
            out[0] += flux;
            out[1] += 0.5 * along * flux;
            out[2] += p1 * flux;
            out[3] += p2 * flux;
            out[4] += half * r * c;
            out[5] += half * r * s;
            out[6] -= half * k * r;
            out[7] += half * slant * r;
        }
        out
    }

    /// `[α, β, γ]` of `b`'s quadratic `α z² + 2β z + γ` along `a`'s generator at `φ`.
    pub(crate) fn generator_quadratic(&self, m: &Matrix3, phi: f64) -> [f64; 3] {
        let (s, c) = phi.sin_cos();
        self.generator(m, c, s).quadratic
    }

    /// The discriminant of `b`'s quadratic along `a`'s generator at `φ` (positive where the
    /// generator's line crosses `b`'s lateral quadric).
    fn discriminant(&self, m: &Matrix3, phi: f64) -> f64 {
        let [alpha, beta, gamma] = self.generator_quadratic(m, phi);
        beta * beta - alpha * gamma
    }

    /// The discriminant as the trigonometric form of [`trig_roots`], from its five Fourier
    /// coefficients (it is of degree two, see the module docs).
    pub(crate) fn discriminant_form(&self, m: &Matrix3) -> [f64; 6] {
        let (mut a0, mut a1, mut b1, mut a2, mut b2) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for j in 0..5 {
            let phi = 2.0 * PI * j as f64 / 5.0;
            let d = self.discriminant(m, phi);
            a0 += d;
            a1 += d * phi.cos();
            b1 += d * phi.sin();
            a2 += d * (2.0 * phi).cos();
            b2 += d * (2.0 * phi).sin();
        }
        let f = 2.0 / 5.0;
        // a₂ cos 2φ + b₂ sin 2φ + a₁ cos φ + b₁ sin φ + a₀ as m₁₁C² + 2m₁₂CS + m₂₂S² + ….
        [
            f * a2,
            f * b2,
            -f * a2,
            0.5 * f * a1,
            0.5 * f * b1,
            a0 / 5.0,
        ]
    }

    /// The cuts in `φ ∈ [−π, π]` of `a`'s lateral surface inside `b`, sorted; how many.
    fn lateral_cuts(&self, m: &Matrix3) -> ([f64; MAX_PIECES + 1], usize) {
        let mut cuts = [0.0; MAX_PIECES + 1];
        cuts[0] = -PI;
        cuts[1] = PI;
        let mut n = 2;
        let mut push = |x: f64, cuts: &mut [f64; MAX_PIECES + 1]| {
            let x = wrap(x);
            if x.is_finite() && x > -PI && x < PI && n < cuts.len() {
                cuts[n] = x;
                n += 1;
            }
        };
        let (a, q) = (&self.a, &self.b);
        let b_rims = [(0.0, q.r0), (q.len, q.r0 + q.slope * q.len)];
        // a's rims against b's lateral quadric and cap planes.
        for (z, r) in [(0.0, a.r0), (a.len, a.r0 + a.slope * a.len)] {
            if r <= 0.0 {
                continue;
            }
            let centre = Vector3::new(0.0, 0.0, z);
            let (psi, k) = circle_crossings(q, &centre, &Vector3::x(), &Vector3::y(), r);
            for &x in &psi[..k] {
                push(x, &mut cuts);
            }
            for (h, _) in b_rims {
                let cap = q.origin + q.axis * h;
                let (psi, k) =
                    sinusoid_roots(r * q.axis.x, r * q.axis.y, -q.axis.dot(&(centre - cap)));
                for &x in &psi[..k] {
                    push(x, &mut cuts);
                }
            }
        }
        // b's rims piercing a's lateral quadric.
        let (e1, e2) = rim_axes(&q.axis);
        for (h, rim) in b_rims {
            if rim <= 0.0 {
                continue;
            }
            let centre = q.origin + q.axis * h;
            let (psi, k) = circle_crossings(a, &centre, &e1, &e2, rim);
            for &x in &psi[..k] {
                let point = centre + rim * (x.cos() * e1 + x.sin() * e2);
                if point.x != 0.0 || point.y != 0.0 {
                    push(point.y.atan2(point.x), &mut cuts);
                }
            }
        }
        // a's generators tangent to b's lateral quadric.
        let (psi, k) = trig_roots(&self.discriminant_form(m));
        for &x in &psi[..k] {
            push(x, &mut cuts);
        }
        cuts[..n].sort_by(f64::total_cmp);
        (cuts, n)
    }

    /// The integrals of [`LATERAL`] over `a`'s lateral surface inside `b`, the fields given in
    /// `a`'s frame.
    pub(crate) fn lateral(&self, fields: &Fields, work: &mut WorkCounters) -> [f64; LATERAL] {
        let m = self.b.matrix();
        // √(1 + k²): the surface element's length per unit of R dφ dz.
        let slant = self.a.slope.hypot(1.0);
        let (mut cuts, n) = self.lateral_cuts(&m);
        let floor = |e: &[f64; LATERAL]| {
            // Relative to the surface's own first estimates: a small region's integrals are
            // as small as it (no floor of the pair's size).
            let v = (e[0].abs() * 1e-14).max(f64::MIN_POSITIVE);
            let s = (e[7].abs() * 1e-14).max(f64::MIN_POSITIVE);
            [v, v, v, v, s, s, s, s]
        };
        RULE.integrate_pieces(
            &mut cuts[..n],
            &mut |phi| self.lateral_integrand((&m, slant), fields, phi),
            &floor,
            work,
        )
    }

    /// The same pair seen from `b`: `b` at the origin along `z`, `a` posed in `b`'s frame;
    /// with the origin and axes of that frame in `a`'s.
    pub(crate) fn swapped(&self) -> (Self, Vector3, [Vector3; 3]) {
        let q = &self.b;
        let (f1, f2) = rim_axes(&q.axis);
        let axes = [f1, f2, q.axis];
        let turn = |v: &Vector3| Vector3::new(f1.dot(v), f2.dot(v), q.axis.dot(v));
        let pair = Self {
            a: Quadric {
                origin: Vector3::zeros(),
                axis: Vector3::z(),
                ..*q
            },
            b: Quadric {
                origin: turn(&(-q.origin)),
                axis: turn(&Vector3::z()),
                ..self.a
            },
        };
        (pair, q.origin, axes)
    }
}

/// The midpoint of the closest points of the two axes' segments (`a`'s from the origin along
/// `z`), the fields' reference point: inside or near the intersection, so that the fluxes do
/// not cancel far above the volume.
pub(crate) fn reference_point(pair: &Pair) -> Vector3 {
    let (a, b) = (&pair.a, &pair.b);
    let (d1, d2) = (Vector3::z() * a.len, b.axis * b.len);
    let r = -b.origin;
    let (aa, ee, f) = (d1.dot(&d1), d2.dot(&d2), d2.dot(&r));
    let (c, bb) = (d1.dot(&r), d1.dot(&d2));
    let denom = aa * ee - bb * bb;
    let mut s = if denom > 0.0 {
        ((bb * f - c * ee) / denom).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let mut t = (bb * s + f) / ee;
    if t < 0.0 {
        t = 0.0;
        s = (-c / aa).clamp(0.0, 1.0);
    } else if t > 1.0 {
        t = 1.0;
        s = ((bb - c) / aa).clamp(0.0, 1.0);
    }
    0.5 * (d1 * s + b.origin + d2 * t)
}
