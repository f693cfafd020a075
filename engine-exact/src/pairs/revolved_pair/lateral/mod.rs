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
//! The fields radial from a point `p`, `(x − p)/3` and `(x − p)(x − p)ᵢ/4` (divergences `1`
//! and `(x − p)ᵢ`), are tangent to every lateral surface whose generators meet at `p`: a
//! cone's, from its apex. Where no cap meets the intersection they give its volume and
//! moments from the other surface alone ([`Pair::lateral_radial`]).
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

use super::quadric::Quadric;
use super::slice::{Line, Pair, interval_on_line, rim_axes};
use crate::quadrature::{self, Adaptive, MAX_PIECES, MAX_RULE_NODES, Pair as KronrodPair};
use crate::sin_cos::sin_cos;
#[cfg(test)]
use contact_core::Matrix3;
use contact_core::{Vector3, WorkCounters};

mod events;

/// Components of the lateral integrals: the fluxes of `s ŵ`, `½ s² ŵ`, `p₁ s ŵ`, `p₂ s ŵ`
/// (the volume and the moments about `c` along `ŵ`, `ê₁`, `ê₂`), the surface's area vector
/// inside the other solid (3, outward) and its unsigned area.
pub(crate) const LATERAL: usize = 8;

/// The azimuthal rule: error estimates within 1e-13 relative, as the slices'.
const RULE: Adaptive = Adaptive {
    tolerance: 1e-13,
    max_depth: 14,
    pair: KronrodPair::Kronrod41,
};

/// One lateral surface inside the other solid: its integrand, its events, and how well its
/// generators meet the other solid.
pub(crate) struct Lateral<'p> {
    /// The integrand.
    integrand: Integrand<'p>,
    /// The events, sorted, `−π` and `π` included.
    cuts: [f64; MAX_PIECES + 1],
    /// How many.
    n: usize,
    /// The largest `(β² − αγ)/(β² + |αγ|)` among the generators at the middles of the pieces
    /// that meet the other solid: near 0 when every one of them is within round-off of
    /// tangent to its quadric (a grazing sliver, whose interval lengths `∝ √(β² − αγ)` have
    /// lost their digits), 1 when one crosses it squarely (or meets only its caps).
    pub conditioning: f64,
}

impl Lateral<'_> {
    /// The same surface with the fields taken about another point (the events and the
    /// generators do not depend on it).
    pub(crate) fn set_fields(&mut self, fields: &Fields) {
        self.integrand.set_fields(fields);
    }

    /// The integrals of [`LATERAL`].
    pub(crate) fn integrate(&mut self, work: &mut WorkCounters) -> [f64; LATERAL] {
        let floor = |e: &[f64; LATERAL]| {
            // Relative to the surface's own first estimates: a small region's integrals are
            // as small as it (no floor of the pair's size). A moment may vanish by symmetry
            // (about a reference point on a plane of symmetry): its floor, 1e-12 of the
            // volume times the working unit, holds the centroid to 1e-12 of the pair's size,
            // where the volume's would ask a vanishing integral for 1e-14.
            let v = (e[0].abs() * 1e-14).max(f64::MIN_POSITIVE);
            let m = (e[0].abs() * 1e-12).max(f64::MIN_POSITIVE);
            let s = (e[7].abs() * 1e-14).max(f64::MIN_POSITIVE);
            [v, m, m, m, s, s, s, s]
        };
        RULE.integrate_pieces(&mut self.cuts[..self.n], &mut &self.integrand, &floor, work)
    }
}

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

/// `b`'s view of `a`'s generators as trigonometric polynomials in the azimuth: each
/// quantity of the line ([`Line`]) as `[1, C, S, C², CS, S²]`-coefficients (`C = cos φ`,
/// `S = sin φ`), expanded once from `b`'s quadric in `a`'s frame.
#[derive(Debug, Clone, Copy)]
struct Generators {
    /// `w·(o − o_b)`: constant, `C`, `S`.
    height: [f64; 3],
    /// `w·d`.
    rate: [f64; 3],
    /// `dᵀMd`.
    alpha: [f64; 6],
    /// `dᵀ(M(o − o_b) − k_b r_b w)`.
    beta: [f64; 6],
    /// `Q_b(o)`.
    gamma: [f64; 6],
}

impl Generators {
    /// The generators of `a` (origin `o = r₀u`, direction `d = k u + ẑ`) against `b`'s
    /// quadric `Q(x) = (x − o_b)ᵀM(x − o_b) − 2k_b r_b w·(x − o_b) − r_b²`.
    fn new(pair: &Pair) -> Self {
        let (r0, k) = (pair.a.r0, pair.a.slope);
        let q = &pair.b;
        let (b, ob) = (q.axis, q.origin);
        let m = q.matrix();
        let m_ob = m * ob;
        let g0 = -m_ob - b * (q.slope * q.r0);
        let (m00, m01, m11, m20, m21, m22) = (
            m[(0, 0)],
            m[(0, 1)],
            m[(1, 1)],
            m[(2, 0)],
            m[(2, 1)],
            m[(2, 2)],
        );
        let ko = 2.0 * q.slope * q.r0;
        Self {
            height: [-b.dot(&ob), r0 * b.x, r0 * b.y],
            rate: [b.z, k * b.x, k * b.y],
            alpha: [
                m22,
                2.0 * k * m20,
                2.0 * k * m21,
                k * k * m00,
                2.0 * k * k * m01,
                k * k * m11,
            ],
            beta: [
                g0.z,
                k * g0.x + r0 * m20,
                k * g0.y + r0 * m21,
                k * r0 * m00,
                2.0 * k * r0 * m01,
                k * r0 * m11,
            ],
            gamma: [
                ob.dot(&m_ob) + ko * b.dot(&ob) - q.r0 * q.r0,
                -2.0 * r0 * m_ob.x - ko * r0 * b.x,
                -2.0 * r0 * m_ob.y - ko * r0 * b.y,
                r0 * r0 * m00,
                2.0 * r0 * r0 * m01,
                r0 * r0 * m11,
            ],
        }
    }

    /// The generator at azimuth `(c, s)`.
    fn line(&self, c: f64, s: f64) -> Line {
        let t = [1.0, c, s, c * c, c * s, s * s];
        let dot = |f: &[f64; 6]| f.iter().zip(&t).map(|(a, b)| a * b).sum::<f64>();
        let lin = |f: &[f64; 3]| f[0] + f[1] * c + f[2] * s;
        Line {
            height: lin(&self.height),
            rate: lin(&self.rate),
            quadratic: [dot(&self.alpha), dot(&self.beta), dot(&self.gamma)],
            tol: 0.0,
        }
    }
}

/// What every azimuth of one lateral integral shares: the generators, `a`'s shape and the
/// fields' frame.
struct Integrand<'p> {
    /// The pair.
    pair: &'p Pair,
    /// `a`'s generators seen by `b`.
    generators: Generators,
    /// `√(1 + k²)`: the surface element's length per unit of `R dφ dz`.
    slant: f64,
    /// `ŵ`, `ê₁`, `ê₂`.
    axes: [Vector3; 3],
    /// `c·ŵ`, `c·ê₁`, `c·ê₂`.
    offsets: [f64; 3],
    /// The apex `p` of the fields radial from it ([`Pair::lateral_radial`]), in place of the
    /// fields along `ŵ`.
    radial: Option<Vector3>,
}

impl Integrand<'_> {
    fn new<'p>(pair: &'p Pair, fields: &Fields) -> Integrand<'p> {
        let mut integrand = Integrand {
            pair,
            generators: Generators::new(pair),
            slant: pair.a.slope.hypot(1.0),
            axes: [Vector3::zeros(); 3],
            offsets: [0.0; 3],
            radial: None,
        };
        integrand.set_fields(fields);
        integrand
    }

    /// Takes the fields' frame and reference point.
    fn set_fields(&mut self, fields: &Fields) {
        self.axes = [fields.w, fields.e1, fields.e2];
        self.offsets = self.axes.map(|e| e.dot(&fields.centre));
    }

    /// The integrand per unit of `φ` (see [`LATERAL`]).
    fn at(&self, phi: f64) -> [f64; LATERAL] {
        let (s, c) = sin_cos(phi);
        self.on_generator(c, s, self.inside(c, s))
    }

    /// The part `(lo, hi)` of the generator at azimuth `(c, s)` inside `b` (`hi ≤ lo` when
    /// none is).
    fn inside(&self, c: f64, s: f64) -> (f64, f64) {
        match interval_on_line(&self.pair.b, &self.generators.line(c, s)) {
            Some((enter, _, exit, _)) => (enter.max(0.0), exit.min(self.pair.a.len)),
            None => (0.0, 0.0),
        }
    }

    /// The integrand on the generator at azimuth `(c, s)` over its part `(lo, hi)` inside `b`:
    /// along the generator a point at height `z` is `(R u, z)`, so each field's coordinate is
    /// `R (e·u) + z e_z − c·e`.
    fn on_generator(&self, c: f64, s: f64, (lo, hi): (f64, f64)) -> [f64; LATERAL] {
        let mut out = [0.0; LATERAL];
        if hi <= lo {
            return out;
        }
        let (r0, k) = (self.pair.a.r0, self.pair.a.slope);
        let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        let offset = half * FRAC_1_SQRT_3;
        let points = [mid - offset, mid + offset];
        if let Some(p) = &self.radial {
            // (x − p)·(u − k ẑ) = R − k z − p·(u − k ẑ) = r₀ − p·u + k p_z along the whole
            // generator: the radial fields' flux per unit of R dz is that over 3, and times
            // (x − p)ᵢ/4 for the moments.
            let height = r0 - (p.x * c + p.y * s) + k * p.z;
            for z in points {
                let r = r0 + k * z;
                let flux = half * r * height;
                out[0] += flux / 3.0;
                out[1] += 0.25 * (r * c - p.x) * flux;
                out[2] += 0.25 * (r * s - p.y) * flux;
                out[3] += 0.25 * (z - p.z) * flux;
            }
        } else {
            self.along_fields(c, s, (half, points), &mut out);
        }
        // ∫R dz, exact for the linear radius.
        let area = half * points.iter().map(|z| r0 + k * z).sum::<f64>();
        out[4] = area * c;
        out[5] = area * s;
        out[6] = -k * area;
        out[7] = self.slant * area;
        out
    }

    /// The fluxes of the fields along `ŵ` on the generator at azimuth `(c, s)`, over the part
    /// of half-width `half` with Gauss points `points`, into `out[..4]`.
    fn along_fields(
        &self,
        c: f64,
        s: f64,
        (half, points): (f64, [f64; 2]),
        out: &mut [f64; LATERAL],
    ) {
        let (r0, k) = (self.pair.a.r0, self.pair.a.slope);
        let [w, e1, e2] = &self.axes;
        let [cw, c1, c2] = self.offsets;
        let (uw, u1, u2) = (w.x * c + w.y * s, e1.x * c + e1.y * s, e2.x * c + e2.y * s);
        // ŵ·(u − k ẑ): the surface element's projection on ŵ per unit of R.
        let facing = uw - k * w.z;
        for z in points {
            let r = r0 + k * z;
            let along = r * uw + z * w.z - cw;
            let flux = half * r * facing * along;
            out[0] += flux;
            out[1] += 0.5 * along * flux;
            out[2] += (r * u1 + z * e1.z - c1) * flux;
            out[3] += (r * u2 + z * e2.z - c2) * flux;
        }
    }
}

/// A rule's nodes step by step over all of them (the azimuths' sines and cosines, then the
/// generators' intervals in `b`, then the sums): each node's chain of a sine, a root and
/// divisions is long, and the nodes' chains are independent.
impl quadrature::Integrand<LATERAL> for &Integrand<'_> {
    fn at(&mut self, phi: f64) -> [f64; LATERAL] {
        Integrand::at(self, phi)
    }

    fn at_each(&mut self, phis: &[f64], out: &mut [[f64; LATERAL]]) {
        for (phis, out) in phis
            .chunks(MAX_RULE_NODES)
            .zip(out.chunks_mut(MAX_RULE_NODES))
        {
            let mut trig = [(0.0, 0.0); MAX_RULE_NODES];
            for (phi, (s, c)) in phis.iter().zip(&mut trig) {
                (*s, *c) = sin_cos(*phi);
            }
            let mut parts = [(0.0, 0.0); MAX_RULE_NODES];
            for (&(s, c), part) in trig.iter().zip(&mut parts).take(phis.len()) {
                *part = self.inside(c, s);
            }
            for ((&(s, c), &part), value) in trig.iter().zip(&parts).zip(out) {
                *value = self.on_generator(c, s, part);
            }
        }
    }
}

/// `1/√3`: the two Gauss points' offset from the middle, per half-width.
const FRAC_1_SQRT_3: f64 = 0.577_350_269_189_625_8;

impl Pair {
    /// The generator of `a` at azimuth `(c, s)` as a line seen by `b` (`m` is `b`'s
    /// quadratic form), formed directly from the points (the expanded [`Generators`]' check).
    #[cfg(test)]
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

    /// `[α, β, γ]` of `b`'s quadratic `α z² + 2β z + γ` along `a`'s generator at `φ`,
    /// formed directly.
    #[cfg(test)]
    pub(crate) fn generator_quadratic(&self, phi: f64) -> [f64; 3] {
        let (s, c) = phi.sin_cos();
        self.generator(&self.b.matrix(), c, s).quadratic
    }

    /// `[α, β, γ]` of the expanded generators at `φ`.
    #[cfg(test)]
    pub(crate) fn expanded_quadratic(&self, phi: f64) -> [f64; 3] {
        let (s, c) = phi.sin_cos();
        Generators::new(self).line(c, s).quadratic
    }

    /// The discriminant's trigonometric form (`events::discriminant_form`) of `a`'s
    /// generators against `b`.
    #[cfg(test)]
    pub(crate) fn discriminant_form(&self) -> [f64; 6] {
        events::discriminant_form(&Generators::new(self))
    }

    /// [`Pair::lateral`] with the fields radial from `apex` (in `a`'s frame) in place of the
    /// fields along `ŵ`: `(x − p)/3` and `(x − p)(x − p)ᵢ/4` (`i` = `a`'s `x`, `y`, `z`), of
    /// divergences 1 and `(x − p)ᵢ`, tangent to every lateral surface whose generators meet at
    /// `p` (a cone's through its apex). Their fluxes are the volume and the moments about `p`.
    pub(crate) fn lateral_radial(&self, apex: &Vector3) -> Lateral<'_> {
        let fields = Fields {
            centre: *apex,
            w: Vector3::x(),
            e1: Vector3::y(),
            e2: Vector3::z(),
        };
        let mut lateral = self.lateral(&fields);
        lateral.integrand.radial = Some(*apex);
        lateral
    }

    /// `a`'s lateral surface inside `b`, ready to integrate: its events and how well its
    /// generators meet `b`, the fields given in `a`'s frame.
    pub(crate) fn lateral(&self, fields: &Fields) -> Lateral<'_> {
        let integrand = Integrand::new(self, fields);
        let (cuts, n) = self.lateral_cuts(&integrand.generators);
        // The best-conditioned generator among the pieces' middles that meet `b`.
        let mut conditioning = 0.0f64;
        for piece in cuts[..n].windows(2) {
            let phi = 0.5 * (piece[0] + piece[1]);
            let (s, c) = phi.sin_cos();
            let line = integrand.generators.line(c, s);
            if let Some((enter, _, exit, _)) = interval_on_line(&self.b, &line) {
                if exit.min(self.a.len) > enter.max(0.0) {
                    let [alpha, beta, gamma] = line.quadratic;
                    let scale = beta * beta + (alpha * gamma).abs();
                    let disc = beta * beta - alpha * gamma;
                    // No real roots (a cone's inside along the whole line): caps only.
                    let ratio = if disc > 0.0 && scale > 0.0 {
                        disc / scale
                    } else {
                        1.0
                    };
                    conditioning = conditioning.max(ratio);
                }
            }
        }
        Lateral {
            integrand,
            cuts,
            n,
            conditioning,
        }
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

/// The fields' reference point: on the segment between the closest points of the two axes'
/// segments (`a`'s from the origin along `z`), the middle of the part of that line within
/// both solids' radii there (`u ∈ [d − r_b, r_a]` from `a`'s point, `d` the points'
/// distance): inside or near the intersection, so that the fluxes do not cancel far above
/// the volume (the points' midpoint lies a radius' difference away from a shallow crossing
/// of unequal radii, which then took a second pass about the centroid).
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
    let (on_a, on_b) = (d1 * s, b.origin + d2 * t);
    let (r_a, r_b) = (
        (a.r0 + a.slope * a.len * s).max(0.0),
        (b.r0 + b.slope * b.len * t).max(0.0),
    );
    let gap = on_b - on_a;
    let d = gap.norm();
    if d > 0.0 && (d - r_b + r_a).is_finite() {
        on_a + gap * (0.5 * (d - r_b + r_a) / d)
    } else {
        0.5 * (on_a + on_b)
    }
}
