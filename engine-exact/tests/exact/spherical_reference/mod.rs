//! A third reference for two ellipsoids, by geodesic polar coordinates on each one's own
//! unit sphere: 1-D periodic integrals, converging geometrically.
//!
//! An ellipsoid `E = {c + L u : |u| ≤ 1}` carries the unit sphere's area vectors by
//! `cof(L) = det(L)·L⁻ᵀ`, so a patch `P` of its surface (the image of a region `Ω` of the
//! sphere) has, with `m₀ = ∫_Ω dA`, `m₁ = ∫_Ω u dA`, `m₂ = ∫_Ω u uᵀ dA`:
//!
//! - `∫_P n dA = cof(L)·m₁`;
//! - `∫_P x·n dA = c·cof(L)m₁ + det(L)·m₀` (since `(Lu)·(cof(L)u) = det(L)|u|²`);
//! - `∫_P x (x·n) dA = c (c·cof(L)m₁) + det(L)(c m₀ + L m₁) + L m₂ cof(L)ᵀ c`.
//!
//! The intersection `R = I ∩ J` is bounded by `I`'s surface inside `J` and `J`'s inside
//! `I`, so `V = ⅓∮x·n dA` and `∫_R x dV = ¼∮x (x·n) dA` (the divergences of `x` and of
//! `x_i x` are 3 and `4x_i`), and `S_I = cof(L_I)·m₁(Ω_I)`; `S_I + S_J = 0` checks both.
//!
//! Each `Ω` is seen from its deepest point `a`: with `u = cos ρ a + sin ρ d(φ)` and the
//! boundary crossings along each great circle (bisected; pairs near a tangency found at the
//! sampled extrema), the radial integrals are closed forms. When every ray crosses once the
//! moments are smooth periodic integrals in `φ`, which the trapezoid rule takes to
//! round-off; otherwise `φ` is cut where the number of crossings changes and each piece is
//! integrated by Gauss–Legendre through a map that smooths the square roots at the cuts.
//! Doubling the rule measures its error. No step is shared with the engine's planar sections or with the
//! divergence oracle's adaptive `(θ, φ)` patches.

use crate::ellipsoid_oracles::Moments;
use contact_core::{Point3, Vector3};
use nalgebra::Matrix3;
use std::f64::consts::{PI, TAU};

/// The moments `(m₀, m₁, m₂)` of a region of the unit sphere.
#[derive(Debug, Clone, Copy)]
pub struct SphereMoments {
    m0: f64,
    m1: Vector3,
    m2: Matrix3<f64>,
}

/// The ellipsoid `{c + L u : |u| ≤ 1}`.
#[derive(Debug, Clone, Copy)]
pub struct Ellipsoid {
    pub c: Vector3,
    pub l: Matrix3<f64>,
}

impl Ellipsoid {
    /// `x ↦ 1 − |L⁻¹(x − c)|²`: positive inside.
    fn margin(&self) -> impl Fn(&Vector3) -> f64 + use<> {
        let (c, inverse) = (self.c, self.l.try_inverse().unwrap());
        move |x| 1.0 - (inverse * (x - c)).norm_squared()
    }

    fn cofactor(&self) -> Matrix3<f64> {
        self.l.try_inverse().unwrap().transpose() * self.l.determinant()
    }
}

/// Samples along each ray (half a great circle) for the boundary's crossings.
const RADIAL_SAMPLES: usize = 192;

/// `R(φ)` along the great circle from `a` towards `d`: where `inside` (true at `a`) turns
/// false; `π` if it never does. `None` if it turns more than once (not star-shaped).
pub fn boundary(a: &Vector3, d: &Vector3, inside: &dyn Fn(&Vector3) -> bool) -> Option<f64> {
    let point = |rho: f64| a * rho.cos() + d * rho.sin();
    let at = |k: usize| PI * k as f64 / RADIAL_SAMPLES as f64;
    let mut crossing = None;
    let mut previous = true;
    for k in 1..=RADIAL_SAMPLES {
        let here = inside(&point(at(k)));
        if here != previous {
            if crossing.is_some() || here {
                return None;
            }
            let (mut lo, mut hi) = (at(k - 1), at(k));
            for _ in 0..64 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if inside(&point(mid)) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            crossing = Some(0.5 * (lo + hi));
        }
        previous = here;
    }
    Some(crossing.unwrap_or(PI))
}

/// The moments of `{u : inside(u)}` on the unit sphere, star-shaped about `a`, by the
/// trapezoid rule on `n` rays.
fn region_moments(
    a: &Vector3,
    inside: &dyn Fn(&Vector3) -> bool,
    n: usize,
) -> Option<SphereMoments> {
    let helper = Vector3::ith(a.iamin(), 1.0);
    let e1 = a.cross(&helper).normalize();
    let e2 = a.cross(&e1);
    let aa = a * a.transpose();
    let mut out = SphereMoments {
        m0: 0.0,
        m1: Vector3::zeros(),
        m2: Matrix3::zeros(),
    };
    let w = TAU / n as f64;
    for k in 0..n {
        let phi = w * k as f64;
        let d = e1 * phi.cos() + e2 * phi.sin();
        let r = boundary(a, &d, inside)?;
        let (s, c) = r.sin_cos();
        out.m0 += w * (1.0 - c);
        out.m1 += (a * (0.5 * s * s) + d * (0.5 * (r - s * c))) * w;
        let ad = a * d.transpose();
        out.m2 += (aa * ((1.0 - c * c * c) / 3.0)
            + (ad + ad.transpose()) * (s * s * s / 3.0)
            + d * d.transpose() * ((2.0 - 3.0 * c + c * c * c) / 3.0))
            * w;
    }
    Some(out)
}

/// `∫₀^R (1, u, u uᵀ) sin ρ dρ` along the great circle from `a` towards `d`, times `w`.
pub fn radial(a: &Vector3, d: &Vector3, r: f64, w: f64) -> SphereMoments {
    let (s, c) = r.sin_cos();
    let ad = a * d.transpose();
    SphereMoments {
        m0: w * (1.0 - c),
        m1: (a * (0.5 * s * s) + d * (0.5 * (r - s * c))) * w,
        m2: (a * a.transpose() * ((1.0 - c * c * c) / 3.0)
            + (ad + ad.transpose()) * (s * s * s / 3.0)
            + d * d.transpose() * ((2.0 - 3.0 * c + c * c * c) / 3.0))
            * w,
    }
}

impl SphereMoments {
    pub fn zero() -> Self {
        Self {
            m0: 0.0,
            m1: Vector3::zeros(),
            m2: Matrix3::zeros(),
        }
    }

    pub fn add(&mut self, other: &Self, w: f64) {
        self.m0 += w * other.m0;
        self.m1 += other.m1 * w;
        self.m2 += other.m2 * w;
    }
}

/// Where `margin` (positive at `a`) changes sign along the half great circle from `a`
/// towards `d`: sign changes between samples, bisected, and pairs hidden between samples
/// near a tangency, found at each sampled extremum refined by golden section.
fn crossings(a: &Vector3, d: &Vector3, margin: &dyn Fn(&Vector3) -> f64) -> Vec<f64> {
    let f = |rho: f64| margin(&(a * rho.cos() + d * rho.sin()));
    let at = |k: usize| PI * k as f64 / RADIAL_SAMPLES as f64;
    let values: Vec<f64> = (0..=RADIAL_SAMPLES).map(|k| f(at(k))).collect();
    let bisect = |mut lo: f64, mut hi: f64| {
        let lo_inside = f(lo) > 0.0;
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if (f(mid) > 0.0) == lo_inside {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let mut out = Vec::new();
    for k in 1..=RADIAL_SAMPLES {
        if (values[k] > 0.0) != (values[k - 1] > 0.0) {
            out.push(bisect(at(k - 1), at(k)));
        }
    }
    for k in 1..RADIAL_SAMPLES {
        let (l, m, r) = (values[k - 1], values[k], values[k + 1]);
        let peak = m >= l && m >= r && l <= 0.0 && m <= 0.0 && r <= 0.0;
        let dip = m <= l && m <= r && l > 0.0 && m > 0.0 && r > 0.0;
        if !(peak || dip) {
            continue;
        }
        let sign = if peak { 1.0 } else { -1.0 };
        let (mut lo, mut hi) = (at(k - 1), at(k + 1));
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..90 {
            let x1 = hi - ratio * (hi - lo);
            let x2 = lo + ratio * (hi - lo);
            if sign * f(x1) > sign * f(x2) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        let best = 0.5 * (lo + hi);
        if (f(best) > 0.0) != (m > 0.0) {
            out.push(bisect(at(k - 1), best));
            out.push(bisect(best, at(k + 1)));
        }
    }
    out.sort_by(f64::total_cmp);
    out
}

/// The moments of the ray from `a` towards `d` inside (`margin > 0`, true at `a`), and how
/// many times it crosses the boundary.
fn ray(a: &Vector3, d: &Vector3, margin: &dyn Fn(&Vector3) -> f64) -> (SphereMoments, usize) {
    let cuts = crossings(a, d, margin);
    let mut ends = vec![0.0];
    ends.extend(&cuts);
    ends.push(PI);
    let mut out = SphereMoments::zero();
    for (k, w) in ends.windows(2).enumerate() {
        if k % 2 == 0 {
            out.add(&radial(a, d, w[1], 1.0), 1.0);
            out.add(&radial(a, d, w[0], 1.0), -1.0);
        }
    }
    (out, cuts.len())
}

/// Gauss–Legendre nodes and weights on `[0, 1]`.
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut z = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut slope = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, z);
                for k in 2..=n {
                    let k = k as f64;
                    (p0, p1) = (p1, ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k);
                }
                slope = n as f64 * (z * p1 - p0) / (z * z - 1.0);
                let step = p1 / slope;
                z -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            (0.5 * (1.0 + z), 1.0 / ((1.0 - z * z) * slope * slope))
        })
        .collect()
}

/// The moments of `{u : margin(u) > 0}` (positive at `a`) on the unit sphere, whatever its
/// shape: rays from `a` may cross the boundary several times; where their number of
/// crossings changes (a ray tangent to the boundary) the `φ` range is cut (bisected), and
/// each piece is integrated by `n` Gauss–Legendre nodes through
/// `φ = φ₀ + (φ₁ − φ₀)(3σ² − 2σ³)`, which makes the square-root behaviour at the cuts
/// smooth. Without cuts the trapezoid rule on `8n` rays.
fn general_moments(a: &Vector3, margin: &dyn Fn(&Vector3) -> f64, n: usize) -> SphereMoments {
    let helper = Vector3::ith(a.iamin(), 1.0);
    let e1 = a.cross(&helper).normalize();
    let e2 = a.cross(&e1);
    let dir = |phi: f64| e1 * phi.cos() + e2 * phi.sin();
    let count = |phi: f64| ray(a, &dir(phi), margin).1;
    let samples = 128;
    let at = |k: usize| TAU * k as f64 / samples as f64;
    let mut cuts = Vec::new();
    for k in 1..=samples {
        let (c0, c1) = (count(at(k - 1)), count(at(k)));
        if c0 != c1 {
            let (mut lo, mut hi) = (at(k - 1), at(k));
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if count(mid) == c0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            cuts.push(0.5 * (lo + hi));
        }
    }
    let mut out = SphereMoments::zero();
    if cuts.is_empty() {
        let rays = 8 * n;
        for k in 0..rays {
            out.add(
                &ray(a, &dir(TAU * k as f64 / rays as f64), margin).0,
                TAU / rays as f64,
            );
        }
        return out;
    }
    let rule = gauss_legendre(n);
    for k in 0..cuts.len() {
        let (p0, p1) = (
            cuts[k],
            if k + 1 < cuts.len() {
                cuts[k + 1]
            } else {
                cuts[0] + TAU
            },
        );
        let h = p1 - p0;
        for &(sigma, w) in &rule {
            let phi = p0 + h * sigma * sigma * (3.0 - 2.0 * sigma);
            let jacobian = 6.0 * h * sigma * (1.0 - sigma);
            out.add(&ray(a, &dir(phi), margin).0, w * jacobian);
        }
    }
    out
}

/// The point of the unit sphere where `margin` is largest, from a spiral of samples refined
/// by shrinking local searches.
pub fn deepest(margin: &dyn Fn(&Vector3) -> f64) -> Vector3 {
    let count = 4000;
    let golden = PI * (3.0 - 5f64.sqrt());
    let mut best = (Vector3::z(), f64::NEG_INFINITY);
    for k in 0..count {
        let z = 1.0 - 2.0 * (k as f64 + 0.5) / count as f64;
        let r = (1.0 - z * z).sqrt();
        let t = golden * k as f64;
        let u = Vector3::new(r * t.cos(), r * t.sin(), z);
        let m = margin(&u);
        if m > best.1 {
            best = (u, m);
        }
    }
    let mut step = 0.05;
    while step > 1e-9 {
        let helper = Vector3::ith(best.0.iamin(), 1.0);
        let e1 = best.0.cross(&helper).normalize();
        let e2 = best.0.cross(&e1);
        let mut moved = false;
        for (x, y) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
            let u = (best.0 + (e1 * x + e2 * y) * step).normalize();
            let m = margin(&u);
            if m > best.1 {
                best = (u, m);
                moved = true;
            }
        }
        if !moved {
            step *= 0.5;
        }
    }
    best.0
}

/// The region of `e`'s unit sphere inside `other`, on `n` rays when it is star-shaped about
/// its deepest point, else by [`general_moments`]. `None` if it is empty.
fn patch(e: &Ellipsoid, other: &Ellipsoid, n: usize) -> Option<SphereMoments> {
    let inside_other = other.margin();
    let margin = |u: &Vector3| inside_other(&(e.c + e.l * u));
    let a = deepest(&margin);
    if margin(&a) <= 0.0 {
        return None;
    }
    region_moments(&a, &|u| margin(u) > 0.0, n)
        .or_else(|| Some(general_moments(&a, &margin, n / 2)))
}

/// The surface integrals `(∫x·n dA, ∫x (x·n) dA, ∫n dA)` of `e`'s patch `m`.
pub fn surface_terms(e: &Ellipsoid, m: &SphereMoments) -> (f64, Vector3, Vector3) {
    let cof = e.cofactor();
    let det = e.l.determinant();
    let s = cof * m.m1;
    let c = e.c;
    let xn = c.dot(&s) + det * m.m0;
    let xxn = c * c.dot(&s) + (c * m.m0 + e.l * m.m1) * det + e.l * m.m2 * cof.transpose() * c;
    (xn, xxn, s)
}

/// The surface integrals `(∫x·n dA, ∫x (x·n) dA, ∫n dA)` over the part of `e`'s surface
/// where `margin_j` is positive (all of its pieces: rays crossing several times are
/// [`general_moments`]'), on `n` rays; `None` when that part is empty.
pub fn patch_terms(
    e: &Ellipsoid,
    margin_j: &dyn Fn(&Vector3) -> f64,
    n: usize,
) -> Option<(f64, Vector3, Vector3)> {
    let margin = |u: &Vector3| margin_j(&(e.c + e.l * u));
    let a = deepest(&margin);
    if margin(&a) <= 0.0 {
        return None;
    }
    let m = region_moments(&a, &|u| margin(u) > 0.0, n)
        .unwrap_or_else(|| general_moments(&a, &margin, n / 2));
    Some(surface_terms(e, &m))
}

/// The moments of `I ∩ J` on `n` rays per surface, and `|S_I + S_J|` (zero exactly);
/// `None` when a surface's part inside the other is empty or not star-shaped.
pub fn moments(i: &Ellipsoid, j: &Ellipsoid, n: usize) -> Option<(Moments, f64)> {
    let (pi, pj) = (patch(i, j, n)?, patch(j, i, n)?);
    let (xn_i, xxn_i, s_i) = surface_terms(i, &pi);
    let (xn_j, xxn_j, s_j) = surface_terms(j, &pj);
    let volume = (xn_i + xn_j) / 3.0;
    let first = (xxn_i + xxn_j) / 4.0;
    Some((
        Moments {
            volume,
            centroid: Point3::from(first / volume),
            area_vector_i: s_i,
        },
        (s_i + s_j).norm(),
    ))
}

/// [`moments`] on 512 rays, with its error measured against 256 rays: `(moments, error
/// estimate, |S_I + S_J|)`.
pub fn converged(i: &Ellipsoid, j: &Ellipsoid) -> Option<(Moments, f64, f64)> {
    let (coarse, _) = moments(i, j, 256)?;
    let (fine, closure) = moments(i, j, 512)?;
    let error = (fine.volume - coarse.volume)
        .abs()
        .max((fine.centroid - coarse.centroid).norm())
        .max((fine.area_vector_i - coarse.area_vector_i).norm());
    Some((fine, error, closure))
}

mod checks;
