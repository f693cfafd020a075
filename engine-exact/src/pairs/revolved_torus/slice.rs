//! One slice `z = t` of a ring torus (`a`: axis `z`, centre at the origin) against a cylinder
//! or frustum `b`, in polar coordinates about the torus' axis: the ray from `p = (0, 0, t)`
//! along `u = (cos φ, sin φ, 0)` meets `b` in one interval in closed form
//! ([`interval_of`]: a quadratic and two planes), clipped to the annulus
//! `R − s ≤ ρ ≤ R + s`, `s = √(ρ_t² − t²)` (`ρ_t` the minor radius). The section's area and
//! first moments are polynomials in the clipped interval's ends, and the torus' walls at the
//! two circles are inside `b` where their radii lie in `b`'s interval. The `φ` integral is
//! taken over a wedge of azimuths (one region's, or the whole turn), cut at the rays tangent
//! to `b`'s section, at `b`'s rims through the slice, and where each of the two circles crosses
//! `b`'s lateral surface or a cap plane: between those cuts every end is smooth or has a
//! square-root end, and the section is empty throughout a piece or nowhere in it.

use crate::pairs::revolved_pair::quadric::{
    Quadric, circle_crossings, sinusoid_roots, tangent_directions,
};
use crate::pairs::revolved_pair::slice::{ADAPTIVE, ON_SURFACE, interval_of, rays_of, rim_axes};
use crate::quadrature::MAX_PIECES;
use contact_core::{Vector3, WorkCounters};
use std::f64::consts::TAU;

/// Components of the polar integrand: area, the two first moments, then for the outer
/// circle inside `b` its angle, `∫cos φ`, `∫sin φ`, and the same for the inner circle.
pub(crate) const POLAR: usize = 9;

/// The azimuths `start ≤ φ ≤ end` of one region (`0 < end − start ≤ 2π`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Wedge {
    /// First azimuth.
    pub start: f64,
    /// Last azimuth.
    pub end: f64,
}

impl Wedge {
    /// The whole turn.
    pub(crate) const WHOLE: Self = Self {
        start: -std::f64::consts::PI,
        end: std::f64::consts::PI,
    };

    /// Whether the azimuth `phi` lies inside.
    pub(crate) fn contains(&self, phi: f64) -> bool {
        (phi - self.start).rem_euclid(TAU) <= self.end - self.start
    }

    /// `phi` moved by whole turns into `[start, start + 2π)`.
    fn lift(&self, phi: f64) -> f64 {
        self.start + (phi - self.start).rem_euclid(TAU)
    }
}

/// The torus (`big` = R, `small` = ρ_t) and `b`'s quadric in the torus' frame, working units.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TorusPair {
    /// Major radius.
    pub big: f64,
    /// Minor radius.
    pub small: f64,
    /// The cylinder or frustum.
    pub b: Quadric,
}

/// The slice at tube angle `ψ`: height `t = ρ_t sin ψ`, half-width `s = ρ_t cos ψ`, and the
/// annulus' radii.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Level {
    /// Height.
    pub t: f64,
    /// Half-width of the tube's section.
    pub s: f64,
    /// Inner radius `R − s`.
    pub inner: f64,
    /// Outer radius `R + s`.
    pub outer: f64,
}

impl TorusPair {
    /// The slice at tube angle `psi` (`|ψ| ≤ π/2`).
    pub(crate) fn level(&self, psi: f64) -> Level {
        let (sin, cos) = psi.sin_cos();
        let s = (self.small * cos).max(0.0);
        Level {
            t: self.small * sin,
            s,
            inner: self.big - s,
            outer: self.big + s,
        }
    }

    /// The polar integrand at `phi` (see [`POLAR`]).
    fn polar(
        &self,
        rays: &crate::pairs::revolved_pair::slice::Rays,
        lv: &Level,
        phi: f64,
    ) -> [f64; POLAR] {
        let mut out = [0.0; POLAR];
        let (s, c) = phi.sin_cos();
        let Some((enter, _, exit, _)) = interval_of(&self.b, rays, c, s) else {
            return out;
        };
        let (lo, hi) = (enter.max(lv.inner), exit.min(lv.outer));
        if hi <= lo {
            return out;
        }
        let (lo2, hi2) = (lo * lo, hi * hi);
        out[0] = 0.5 * (hi2 - lo2);
        let cube = (hi2 * hi - lo2 * lo) / 3.0;
        out[1] = cube * c;
        out[2] = cube * s;
        // A circle on b's surface within round-off counts as inside (a coaxial b of the
        // circle's radius: the comparison of equal radii is round-off).
        let tol = ON_SURFACE * lv.outer.max(1.0);
        for (k, radius) in [(3, lv.outer), (6, lv.inner)] {
            if enter <= radius + tol && exit >= radius - tol {
                out[k] = 1.0;
                out[k + 1] = c;
                out[k + 2] = s;
            }
        }
        out
    }

    /// The cuts in `φ` of the slice `lv` inside `wedge`, sorted; how many.
    pub(crate) fn cuts(&self, lv: &Level, wedge: &Wedge) -> ([f64; MAX_PIECES + 1], usize) {
        let mut cuts = [0.0; MAX_PIECES + 1];
        cuts[0] = wedge.start;
        cuts[1] = wedge.end;
        let mut n = 2;
        let mut push = |x: f64, cuts: &mut [f64; MAX_PIECES + 1]| {
            if !x.is_finite() {
                return;
            }
            let x = wedge.lift(x);
            if x > wedge.start && x < wedge.end && n < cuts.len() {
                cuts[n] = x;
                n += 1;
            }
        };
        let p = Vector3::new(0.0, 0.0, lv.t);
        let q = &self.b;
        let (dirs, count) = tangent_directions(q, &p);
        for &d in &dirs[..count] {
            push(d, &mut cuts);
        }
        // b's rims through the slice: their points' directions.
        let (e1, e2) = rim_axes(&q.axis);
        for (h, rim) in [(0.0, q.r0), (q.len, q.r0 + q.slope * q.len)] {
            let centre = q.origin + q.axis * h;
            let (psi, k) = sinusoid_roots(rim * e1.z, rim * e2.z, lv.t - centre.z);
            for &x in &psi[..k] {
                let point = centre + rim * (x.cos() * e1 + x.sin() * e2);
                if point.x != 0.0 || point.y != 0.0 {
                    push(point.y.atan2(point.x), &mut cuts);
                }
            }
            // The annulus' circles against the cap plane w·(x − centre) = 0.
            for r in [lv.outer, lv.inner] {
                if r > 0.0 {
                    let (psi, k) =
                        sinusoid_roots(r * q.axis.x, r * q.axis.y, -q.axis.dot(&(p - centre)));
                    for &x in &psi[..k] {
                        push(x, &mut cuts);
                    }
                }
            }
        }
        for r in [lv.outer, lv.inner] {
            if r > 0.0 {
                let (psi, k) = circle_crossings(q, &p, &Vector3::x(), &Vector3::y(), r);
                for &x in &psi[..k] {
                    push(x, &mut cuts);
                }
            }
        }
        cuts[..n].sort_by(f64::total_cmp);
        (cuts, n)
    }

    /// Whether the slice at `psi` meets `b` inside `wedge` (with an area).
    pub(crate) fn not_empty(&self, psi: f64, wedge: &Wedge) -> bool {
        let lv = self.level(psi);
        if lv.s <= 0.0 {
            return false;
        }
        let (cuts, n) = self.cuts(&lv, wedge);
        let rays = rays_of(&self.b, lv.t, lv.outer, false);
        cuts[..n]
            .windows(2)
            .any(|w| w[1] > w[0] && self.polar(&rays, &lv, 0.5 * (w[0] + w[1]))[0] > 0.0)
    }

    /// `∫ polar dφ` over the slice at `psi` inside `wedge` (see [`POLAR`]).
    pub(crate) fn slice(&self, psi: f64, wedge: &Wedge, work: &mut WorkCounters) -> [f64; POLAR] {
        let lv = self.level(psi);
        if lv.s <= 0.0 {
            return [0.0; POLAR];
        }
        let (mut cuts, n) = self.cuts(&lv, wedge);
        let rays = rays_of(&self.b, lv.t, lv.outer, false);
        let r = lv.outer;
        let floor = |e: &[f64; POLAR]| {
            let v = (e[0].abs() * 1e-14).max(1e-15 * r * r);
            let m = v * r;
            let angle = 1e-14;
            [v, m, m, angle, angle, angle, angle, angle, angle]
        };
        ADAPTIVE.integrate_pieces(
            &mut cuts[..n],
            &mut |phi| self.polar(&rays, &lv, phi),
            &floor,
            work,
        )
    }

    /// How many times each of the annulus' circles at `psi` crosses `b`'s lateral surface
    /// (between the caps) and its cap discs, packed in one number: the slices' shape, which
    /// changes where a circle turns tangent to `b`'s surface or a rim of `b` pierces the
    /// torus (a crossing moving from the lateral surface to a cap), the events the closed
    /// forms do not give.
    pub(crate) fn shape(&self, psi: f64) -> usize {
        let lv = self.level(psi);
        let q = &self.b;
        let p = Vector3::new(0.0, 0.0, lv.t);
        let mut shape = 0;
        for (base, r) in [(1, lv.outer), (256, lv.inner)] {
            if r <= 0.0 {
                continue;
            }
            let at = |psi: f64| p + r * Vector3::new(psi.cos(), psi.sin(), 0.0);
            let (roots, k) = circle_crossings(q, &p, &Vector3::x(), &Vector3::y(), r);
            let lateral = roots[..k]
                .iter()
                .filter(|&&x| (0.0..=q.len).contains(&q.height(&at(x))))
                .count();
            let mut caps = 0;
            for (h, rim) in [(0.0, q.r0), (q.len, q.r0 + q.slope * q.len)] {
                let centre = q.origin + q.axis * h;
                let (roots, k) =
                    sinusoid_roots(r * q.axis.x, r * q.axis.y, -q.axis.dot(&(p - centre)));
                caps += roots[..k]
                    .iter()
                    .filter(|&&x| q.across(&at(x)).norm() <= rim)
                    .count();
            }
            shape += base * (lateral.min(15) + 16 * caps.min(15));
        }
        shape
    }
}
