//! A general-pose oracle for an ellipsoid against a frustum, rims included, written without
//! the engine's planar sections: the divergence theorem about the cone's apex.
//!
//! With the apex as origin the cone's side carries no flux of `x` (`x·n = 0` on it), so
//! `V = ⅓∮x·n dA` and `∫x dV = ¼∮x (x·n) dA` come from the ellipsoid's patch inside the
//! frustum and the caps' parts inside the ellipsoid, on which `x·n` is the cap's constant
//! height above or below the apex:
//!
//! - the ellipsoid's patch on its unit sphere ([`crate::spherical_reference`]'s geodesic
//!   polar coordinates about its deepest point), its boundary made of pieces where one of the
//!   three constraints (side, bottom, top) binds: the azimuth is cut where the binding one
//!   changes (a corner of the boundary, bisected) and each piece integrated by Gauss–Legendre,
//!   which converges geometrically on the smooth pieces;
//! - each cap's overlap with the ellipsoid's section: chords in `x` of the disc and the
//!   ellipse, cut where the binding bounds change (sign changes sampled, bisected), each piece
//!   through the map that smooths square-root ends.

use crate::ellipsoid_oracles::Moments;
use crate::ellipsoid_revolved::gauss;
use crate::spherical_reference::{
    Ellipsoid, SphereMoments, boundary, deepest, radial, surface_terms,
};
use contact_core::{Point3, Vector3};
use nalgebra::Matrix3;
use std::f64::consts::TAU;

/// `(∫x·n dA, ∫x (x·n) dA, ∫n dA)` over the part of `e`'s surface inside all of `margins`
/// (each positive inside its constraint), on `n` nodes per azimuth piece (zero when that part
/// is empty); `None` when it is not star-shaped about its deepest point.
fn patch_terms(
    e: &Ellipsoid,
    margins: &[&dyn Fn(&Vector3) -> f64],
    n: usize,
) -> Option<(f64, Vector3, Vector3)> {
    let each = |u: &Vector3, k: usize| margins[k](&(e.c + e.l * u));
    let margin = |u: &Vector3| {
        (0..margins.len())
            .map(|k| each(u, k))
            .fold(f64::INFINITY, f64::min)
    };
    let a = deepest(&margin);
    if margin(&a) <= 0.0 {
        return Some((0.0, Vector3::zeros(), Vector3::zeros()));
    }
    let helper = Vector3::ith(a.iamin(), 1.0);
    let e1 = a.cross(&helper).normalize();
    let e2 = a.cross(&e1);
    let dir = |phi: f64| e1 * phi.cos() + e2 * phi.sin();
    let reach = |phi: f64| boundary(&a, &dir(phi), &|u| margin(u) > 0.0);
    // The binding constraint where the ray leaves.
    let label = |phi: f64| -> Option<usize> {
        let r = reach(phi)?;
        let u = a * r.cos() + dir(phi) * r.sin();
        (0..margins.len()).min_by(|&i, &j| each(&u, i).total_cmp(&each(&u, j)))
    };
    let samples = 256;
    let at = |k: usize| TAU * k as f64 / samples as f64;
    let mut cuts = Vec::new();
    let mut previous = label(at(0))?;
    for k in 1..=samples {
        let here = label(at(k))?;
        if here != previous {
            let (mut lo, mut hi) = (at(k - 1), at(k));
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if label(mid)? == previous {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            cuts.push(0.5 * (lo + hi));
        }
        previous = here;
    }
    let mut m = SphereMoments::zero();
    if cuts.is_empty() {
        let rays = 8 * n;
        for k in 0..rays {
            let phi = TAU * k as f64 / rays as f64;
            m.add(&radial(&a, &dir(phi), reach(phi)?, 1.0), TAU / rays as f64);
        }
    } else {
        let rule = gauss(n);
        for k in 0..cuts.len() {
            let p0 = cuts[k];
            let p1 = if k + 1 < cuts.len() {
                cuts[k + 1]
            } else {
                cuts[0] + TAU
            };
            for &(x, w) in &rule {
                let phi = p0 + (p1 - p0) * x;
                m.add(&radial(&a, &dir(phi), reach(phi)?, 1.0), w * (p1 - p0));
            }
        }
    }
    Some(surface_terms(e, &m))
}

/// Area and first moment of the disc `|p| ≤ r` intersected with `{p : (p − k)ᵀQ(p − k) ≤ 1}`
/// (a filled ellipse), on `n` nodes per piece.
fn disc_ellipse_moments(r: f64, k: &[f64; 2], q: &Matrix3<f64>, n: usize) -> (f64, [f64; 2]) {
    // The ellipse's y-interval at x: q11 dx² + 2 q12 dx dy + q22 dy² ≤ 1, dy = y − k_y.
    let (q11, q12, q22) = (q[(0, 0)], q[(0, 1)], q[(1, 1)]);
    let ellipse = |x: f64| -> Option<(f64, f64)> {
        let dx = x - k[0];
        let disc = (q12 * dx).powi(2) - q22 * (q11 * dx * dx - 1.0);
        (disc >= 0.0).then(|| {
            let root = disc.sqrt();
            (
                k[1] + (-q12 * dx - root) / q22,
                k[1] + (-q12 * dx + root) / q22,
            )
        })
    };
    let chord = |x: f64| -> Option<(f64, f64)> {
        let d = (r * r - x * x).max(0.0).sqrt();
        let (lo, hi) = ellipse(x)?;
        let (lo, hi) = (lo.max(-d), hi.min(d));
        (hi > lo && x.abs() < r).then_some((lo, hi))
    };
    // Where a bound changes: the disc's and the ellipse's bounds crossing, and the chord's
    // ends (sampled over the disc, bisected).
    let marks: [&dyn Fn(f64) -> f64; 3] = [
        &|x| ellipse(x).map_or(-1.0, |(_, hi)| hi - (r * r - x * x).max(0.0).sqrt()),
        &|x| ellipse(x).map_or(-1.0, |(lo, _)| lo + (r * r - x * x).max(0.0).sqrt()),
        &|x| chord(x).map_or(-1.0, |(lo, hi)| hi - lo),
    ];
    let samples = 4000;
    let at = |j: usize| -r + 2.0 * r * j as f64 / samples as f64;
    let mut cuts = vec![-r, r];
    for f in marks {
        for j in 1..=samples {
            let (mut lo, mut hi) = (at(j - 1), at(j));
            let positive = f(lo) > 0.0;
            if (f(hi) > 0.0) == positive {
                continue;
            }
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if (f(mid) > 0.0) == positive {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            cuts.push(0.5 * (lo + hi));
        }
    }
    cuts.sort_by(f64::total_cmp);
    let rule = gauss(n);
    let (mut area, mut moment) = (0.0, [0.0; 2]);
    for w in cuts.windows(2) {
        let (x0, h) = (w[0], w[1] - w[0]);
        for &(sigma, weight) in &rule {
            let x = x0 + h * sigma * sigma * (3.0 - 2.0 * sigma);
            let jacobian = 6.0 * h * sigma * (1.0 - sigma) * weight;
            if let Some((lo, hi)) = chord(x) {
                area += jacobian * (hi - lo);
                moment[0] += jacobian * x * (hi - lo);
                moment[1] += jacobian * 0.5 * (hi * hi - lo * lo);
            }
        }
    }
    (area, moment)
}

/// The moments of the ellipsoid `{c + L u}` (I) and the frustum of radii `r0` (at `z = 0`),
/// `r1` (at `z = len`, `r1 ≠ r0`) by the divergence theorem about the apex, with the error
/// between 16 and 32 nodes per piece; `None` when the ellipsoid's patch is not star-shaped or
/// they do not overlap.
pub fn frustum_moments(
    c: &Vector3,
    l: &Matrix3<f64>,
    r0: f64,
    r1: f64,
    len: f64,
) -> Option<(Moments, f64)> {
    let k = (r1 - r0) / len;
    let apex = Vector3::new(0.0, 0.0, -r0 / k);
    let side = move |x: &Vector3| r0 + k * x.z - x.xy().norm();
    let bottom = |x: &Vector3| x.z;
    let top = move |x: &Vector3| len - x.z;
    let shifted = Ellipsoid { c: c - apex, l: *l };
    let inverse = l.try_inverse()?;
    let q = inverse.transpose() * inverse;
    let at = |n: usize| -> Option<Moments> {
        let margins: [&dyn Fn(&Vector3) -> f64; 3] =
            [&|x| side(&(x + apex)), &|x| bottom(&(x + apex)), &|x| {
                top(&(x + apex))
            }];
        let (mut xn, mut xxn, s) = patch_terms(&shifted, &margins, n)?;
        for (z, radius, up) in [(0.0, r0, false), (len, r1, true)] {
            // The section z = const of the ellipsoid: (p − k)ᵀQ₂(p − k) ≤ 1 − κ.
            let q2 = q.fixed_view::<2, 2>(0, 0).into_owned();
            let Some(q2_inv) = q2.try_inverse() else {
                continue;
            };
            let dz = z - c.z;
            let b = nalgebra::Vector2::new(q[(0, 2)], q[(1, 2)]) * dz;
            let centre = nalgebra::Vector2::new(c.x, c.y) - q2_inv * b;
            let kappa = q[(2, 2)] * dz * dz - b.dot(&(q2_inv * b));
            let room = 1.0 - kappa;
            if room <= 0.0 || radius <= 0.0 {
                continue;
            }
            let mut scaled = Matrix3::zeros();
            scaled.fixed_view_mut::<2, 2>(0, 0).copy_from(&(q2 / room));
            let (area, moment) = disc_ellipse_moments(radius, &[centre.x, centre.y], &scaled, n);
            let height = if up { z - apex.z } else { apex.z - z };
            let first = Vector3::new(moment[0], moment[1], z * area) - apex * area;
            xn += height * area;
            xxn += first * height;
        }
        let volume = xn / 3.0;
        (volume > 0.0).then_some(())?;
        Some(Moments {
            volume,
            centroid: Point3::from(xxn / 4.0 / volume + apex),
            area_vector_i: s,
        })
    };
    let coarse = at(16)?;
    let fine = at(32)?;
    let error = (fine.volume - coarse.volume)
        .abs()
        .max((fine.centroid - coarse.centroid).norm())
        .max((fine.area_vector_i - coarse.area_vector_i).norm());
    Some((fine, error))
}

#[test]
fn the_apex_oracle_reproduces_an_affine_cap_and_a_whole_frustum() {
    use crate::ellipsoid_oracles::ellipsoid_cap;
    // A small tilted ellipsoid on the top cap only: the affine spherical cap.
    let l = nalgebra::Rotation3::from_euler_angles(0.3, -0.5, 0.2).matrix()
        * Matrix3::from_diagonal(&Vector3::new(0.4, 0.3, 0.2));
    let c = Vector3::new(0.1, -0.2, 1.45);
    let (m, error) = frustum_moments(&c, &l, 1.2, 0.9, 1.5).unwrap();
    let expected = ellipsoid_cap(&c, &l, &Vector3::z(), 1.5);
    assert!(error < 1e-12, "{error:e}");
    assert!(
        (m.volume - expected.volume).abs() < 1e-13,
        "{} vs {}",
        m.volume,
        expected.volume
    );
    assert!((m.centroid - expected.centroid).norm() < 1e-12);
    assert!((m.area_vector_i - expected.area_vector_i).norm() < 1e-12);
    // A frustum inside a large ball: V = πL(r₀² + r₀r₁ + r₁²)/3.
    let (m, _) = frustum_moments(
        &Vector3::new(0.0, 0.0, 0.7),
        &(Matrix3::identity() * 4.0),
        1.2,
        0.5,
        1.5,
    )
    .unwrap();
    let v = std::f64::consts::PI * 1.5 * (1.44 + 0.6 + 0.25) / 3.0;
    assert!((m.volume - v).abs() < 1e-12, "{} vs {v}", m.volume);
}
