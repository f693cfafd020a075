//! Oracles for the general ellipsoid against a ring torus, written without the engine's
//! planar sections or its azimuth search (used by [`crate::ellipsoid_torus`] and the
//! characterization rows):
//!
//! - [`coaxial_torus`]: an ellipsoid of revolution on the torus' axis: the sections are a
//!   disc and a concentric annulus, so the volume and its first moment are 1-D integrals of
//!   `π(clamp(ρ_e², (R − s)², (R + s)²) − (R − s)²)` in the tube's angle `ψ` (`z = ρ sin ψ`,
//!   `s = ρ cos ψ`), analytic between the angles where `ρ_e = R ± s` (sampled, bisected), by
//!   Gauss–Legendre; the ellipsoid's surface inside the torus is a set of bands whose area
//!   vector is `π(ρ_e(z₁)² − ρ_e(z₂)²) e_z` each.
//! - [`divergence_moments`]: any single-piece pose (or one piece in a half turn) by the
//!   divergence theorem: the ellipsoid's patch inside the torus on its unit sphere
//!   ([`crate::spherical_reference::patch_terms`]), the torus' patch inside the ellipsoid in
//!   the tube's coordinates `(ψ, φ)` (`x·n = R cos ψ + ρ`, `dA = ρ(R + ρ cos ψ) dψ dφ`): along
//!   each meridian circle the arcs inside the ellipsoid (sign changes sampled and bisected,
//!   pairs hidden between samples found at the sampled extrema), Gauss–Legendre on each arc;
//!   across `φ` cut where the number of arcs changes, each piece through the map that smooths
//!   square-root ends. `S_I + S_J = 0` checks both patches.
//! - [`torus_exit`]: where a ray leaves the tube (sampled, bisected), or the closest point
//!   from outside (`+x` from the axis), as the engine documents.

use crate::ellipsoid_oracles::Moments;
use crate::ellipsoid_revolved::gauss;
use crate::spherical_reference::{self, patch_terms};
use contact_core::{Point3, Vector3};
use nalgebra::Matrix3;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// `ρ − dist(x, core circle)`: positive inside the torus.
pub fn torus_margin(big: f64, small: f64, x: &Vector3) -> f64 {
    small - (x.xy().norm() - big).hypot(x.z)
}

/// The closest point of the torus' surface to `p` (`+x` as the radial direction on the axis).
pub fn torus_closest(big: f64, small: f64, p: &Vector3) -> Vector3 {
    let rho = p.xy().norm();
    let radial = if rho > 1e-12 * big {
        Vector3::new(p.x / rho, p.y / rho, 0.0)
    } else {
        Vector3::x()
    };
    let centre = radial * big;
    centre + (p - centre).normalize() * small
}

/// Where the ray from `g` along `d` leaves the torus: the first sign change of the margin over
/// 20 000 steps across the torus' reach, bisected; from outside, the closest point.
pub fn torus_exit(big: f64, small: f64, g: &Point3, d: &Vector3) -> Point3 {
    let margin = |s: f64| torus_margin(big, small, &(g.coords + d * s));
    if margin(0.0) <= 0.0 {
        return Point3::from(torus_closest(big, small, &g.coords));
    }
    let steps = 20_000;
    let h = 2.0 * (big + small) / steps as f64;
    for k in 1..=steps {
        let (mut inside, mut outside) = (h * (k - 1) as f64, h * k as f64);
        if margin(outside) > 0.0 {
            continue;
        }
        for _ in 0..100 {
            let mid = 0.5 * (inside + outside);
            if mid <= inside || mid >= outside {
                break;
            }
            if margin(mid) > 0.0 {
                inside = mid;
            } else {
                outside = mid;
            }
        }
        return g + d * (0.5 * (inside + outside));
    }
    *g
}

/// Sign changes of `f` over `[a, b]` on `samples` samples, bisected.
fn sign_changes(f: &dyn Fn(f64) -> f64, a: f64, b: f64, samples: usize) -> Vec<f64> {
    let at = |k: usize| a + (b - a) * k as f64 / samples as f64;
    let mut out = Vec::new();
    let mut previous = f(a) > 0.0;
    for k in 1..=samples {
        let here = f(at(k)) > 0.0;
        if here != previous {
            let (mut lo, mut hi) = (at(k - 1), at(k));
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if (f(mid) > 0.0) == previous {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            out.push(0.5 * (lo + hi));
        }
        previous = here;
    }
    out
}

/// The pairs of sign changes of `f` hidden between two samples of `[a, b]` (`samples`
/// intervals): each sampled local maximum below zero (minimum above) refined by golden
/// section, and when it crosses zero the two roots about it bisected.
fn hidden_pairs(f: &dyn Fn(f64) -> f64, a: f64, b: f64, samples: usize) -> Vec<f64> {
    let at = |k: usize| a + (b - a) * k as f64 / samples as f64;
    let values: Vec<f64> = (0..=samples).map(|k| f(at(k))).collect();
    let bisect = |mut lo: f64, mut hi: f64| {
        let lo_positive = f(lo) > 0.0;
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if (f(mid) > 0.0) == lo_positive {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let mut out = Vec::new();
    for k in 1..samples {
        let (l, m, r) = (values[k - 1], values[k], values[k + 1]);
        let peak = m >= l && m >= r && m <= 0.0;
        let dip = m <= l && m <= r && m > 0.0 && l > 0.0 && r > 0.0;
        if !(peak || dip) {
            continue;
        }
        let sign = if peak { 1.0 } else { -1.0 };
        let (mut lo, mut hi) = (at(k - 1), at(k + 1));
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..100 {
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
    out
}

/// The ellipsoid of revolution (`a`, `a`, `c`) centred at height `zc` on the axis of the
/// torus (`big`, `small`): its moments (I the ellipsoid), `None` apart; with the error
/// measured between 24 and 48 nodes per piece.
pub fn coaxial_torus(a: f64, c: f64, zc: f64, big: f64, small: f64) -> Option<(Moments, f64)> {
    let rho2 = |z: f64| a * a * (1.0 - ((z - zc) / c).powi(2));
    let z_of = |psi: f64| small * psi.sin();
    let s_of = |psi: f64| small * psi.cos();
    let h_out = |psi: f64| rho2(z_of(psi)) - (big + s_of(psi)).powi(2);
    let h_in = |psi: f64| rho2(z_of(psi)) - (big - s_of(psi)).powi(2);
    let mut cuts = vec![-FRAC_PI_2, FRAC_PI_2];
    cuts.extend(sign_changes(&h_out, -FRAC_PI_2, FRAC_PI_2, 4000));
    cuts.extend(sign_changes(&h_in, -FRAC_PI_2, FRAC_PI_2, 4000));
    cuts.sort_by(f64::total_cmp);
    let run = |nodes: usize| {
        let rule = gauss(nodes);
        let (mut volume, mut first, mut s_z) = (0.0, 0.0, 0.0);
        for w in cuts.windows(2) {
            let (p0, p1) = (w[0], w[1]);
            for &(x, weight) in &rule {
                let psi = p0 + (p1 - p0) * x;
                let (z, s) = (z_of(psi), s_of(psi));
                let (inner, outer) = ((big - s).powi(2), (big + s).powi(2));
                let area = PI * (rho2(z).clamp(inner, outer) - inner);
                // dz = s dψ.
                volume += weight * (p1 - p0) * area * s;
                first += weight * (p1 - p0) * z * area * s;
            }
            let mid = 0.5 * (p0 + p1);
            if h_in(mid) > 0.0 && h_out(mid) < 0.0 {
                s_z += PI * (rho2(z_of(p0)).max(0.0) - rho2(z_of(p1)).max(0.0));
            }
        }
        (volume, first, s_z)
    };
    let (v1, f1, _) = run(24);
    let (volume, first, s_z) = run(48);
    if volume <= 0.0 {
        return None;
    }
    let error = (volume - v1).abs() + (first / volume - f1 / v1).abs();
    Some((
        Moments {
            volume,
            centroid: Point3::new(0.0, 0.0, first / volume),
            area_vector_i: Vector3::z() * s_z,
        },
        error,
    ))
}

/// The arcs of `ψ ∈ [0, 2π)` (a meridian circle, periodic) where `f(ψ) > 0`, as `(a, b)`
/// with `b` past `2π` for the arc across `ψ = 0`: cut at `f`'s sign changes and hidden pairs
/// of crossings among 720 samples.
pub fn arcs_inside(f: &dyn Fn(f64) -> f64) -> Vec<(f64, f64)> {
    let mut cuts = sign_changes(f, 0.0, TAU, 720);
    cuts.extend(hidden_pairs(f, 0.0, TAU, 720));
    cuts.sort_by(f64::total_cmp);
    if cuts.is_empty() {
        return if f(0.0) > 0.0 {
            vec![(0.0, TAU)]
        } else {
            vec![]
        };
    }
    let mut out = Vec::new();
    for k in 0..cuts.len() {
        let (a, b) = (
            cuts[k],
            if k + 1 < cuts.len() {
                cuts[k + 1]
            } else {
                cuts[0] + TAU
            },
        );
        if f(0.5 * (a + b)) > 0.0 {
            out.push((a, b));
        }
    }
    out
}

/// The azimuths in `[start, start + span]` where `count` changes, found between `samples`
/// equal steps and bisected.
pub fn count_changes(
    count: &dyn Fn(f64) -> usize,
    start: f64,
    span: f64,
    samples: usize,
) -> Vec<f64> {
    let mut cuts = Vec::new();
    for k in 0..samples {
        let (p0, p1) = (
            start + span * k as f64 / samples as f64,
            start + span * (k + 1) as f64 / samples as f64,
        );
        let c0 = count(p0);
        if c0 != count(p1) {
            let (mut lo, mut hi) = (p0, p1);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if count(mid) == c0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            cuts.push(0.5 * (lo + hi));
        }
    }
    cuts
}

/// `(∫x·n dA, ∫x (x·n) dA, ∫n dA)` over the torus' surface inside the ellipsoid
/// `|L⁻¹(x − c)| < 1` (at azimuths within a quarter turn of `half` when given), on `n` Gauss
/// nodes per `φ` piece.
pub fn torus_patch(
    c: &Vector3,
    l: &Matrix3<f64>,
    big: f64,
    small: f64,
    n: usize,
    half: Option<f64>,
) -> (f64, Vector3, Vector3) {
    let inverse = l.try_inverse().unwrap();
    let point = |psi: f64, phi: f64| {
        let rc = big + small * psi.cos();
        Vector3::new(rc * phi.cos(), rc * phi.sin(), small * psi.sin())
    };
    let inside = |psi: f64, phi: f64| 1.0 - (inverse * (point(psi, phi) - c)).norm_squared();
    let arcs = |phi: f64| arcs_inside(&|psi: f64| inside(psi, phi));
    let rule = gauss(40);
    // The φ-integrand: the meridian circle's arcs inside, by Gauss–Legendre in ψ.
    let meridian = |phi: f64| {
        let (mut xn, mut xxn, mut s) = (0.0, Vector3::zeros(), Vector3::zeros());
        for (a, b) in arcs(phi) {
            for &(x, w) in &rule {
                let psi = a + (b - a) * x;
                let weight = w * (b - a) * small * (big + small * psi.cos());
                let p = point(psi, phi);
                let normal = Vector3::new(psi.cos() * phi.cos(), psi.cos() * phi.sin(), psi.sin());
                let dot = big * psi.cos() + small;
                xn += weight * dot;
                xxn += p * (weight * dot);
                s += normal * weight;
            }
        }
        (xn, xxn, s)
    };
    let count = |phi: f64| arcs(phi).len();
    // The azimuths: the whole turn, or the half turn about `half`.
    let (start, span, samples) = match half {
        Some(mid) => (mid - FRAC_PI_2, PI, 180),
        None => (0.0, TAU, 360),
    };
    let cuts = count_changes(&count, start, span, samples);
    let (mut xn, mut xxn, mut s) = (0.0, Vector3::zeros(), Vector3::zeros());
    if cuts.is_empty() && half.is_none() {
        let m = 8 * n;
        for k in 0..m {
            let (a, b, c) = meridian(TAU * k as f64 / m as f64);
            let w = TAU / m as f64;
            xn += a * w;
            xxn += b * w;
            s += c * w;
        }
        return (xn, xxn, s);
    }
    // Pieces between the cuts: around the turn, or from the half's start to its end.
    let mut ends = Vec::new();
    if half.is_some() {
        ends.push(start);
        ends.extend(&cuts);
        ends.push(start + span);
    } else {
        ends.extend(&cuts);
        ends.push(cuts[0] + TAU);
    }
    let outer = gauss(n);
    for w in ends.windows(2) {
        let (p0, h) = (w[0], w[1] - w[0]);
        for &(sigma, w) in &outer {
            let phi = p0 + h * sigma * sigma * (3.0 - 2.0 * sigma);
            let jacobian = 6.0 * h * sigma * (1.0 - sigma) * w;
            let (a, b, c) = meridian(phi);
            xn += a * jacobian;
            xxn += b * jacobian;
            s += c * jacobian;
        }
    }
    (xn, xxn, s)
}

/// The moments of the ellipsoid `{c + L u}` (I) and the torus (J) by the divergence theorem,
/// for an intersection in one piece (or one piece in the half-space of azimuths within a
/// quarter turn of `half`, whose bounding plane through the axis must miss the
/// intersection): `(moments, error between n and 2n nodes, |S_I + S_J|)`; `None` when a
/// patch is empty.
pub fn divergence_moments(
    c: &Vector3,
    l: &Matrix3<f64>,
    big: f64,
    small: f64,
    half: Option<f64>,
) -> Option<(Moments, f64, f64)> {
    let e = spherical_reference::Ellipsoid { c: *c, l: *l };
    let side = half.map(|mid| Vector3::new(mid.cos(), mid.sin(), 0.0));
    let margin = |x: &Vector3| {
        let m = torus_margin(big, small, x);
        side.map_or(m, |v| m.min(x.dot(&v)))
    };
    let at = |n: usize| -> Option<(Moments, f64)> {
        let (xn_i, xxn_i, s_i) = patch_terms(&e, &margin, 16 * n)?;
        let (xn_j, xxn_j, s_j) = torus_patch(c, l, big, small, n, half);
        let volume = (xn_i + xn_j) / 3.0;
        Some((
            Moments {
                volume,
                centroid: Point3::from((xxn_i + xxn_j) / 4.0 / volume),
                area_vector_i: s_i,
            },
            (s_i + s_j).norm(),
        ))
    };
    let (coarse, _) = at(16)?;
    let (fine, closure) = at(32)?;
    let error = (fine.volume - coarse.volume)
        .abs()
        .max((fine.centroid - coarse.centroid).norm())
        .max((fine.area_vector_i - coarse.area_vector_i).norm());
    Some((fine, error, closure))
}
