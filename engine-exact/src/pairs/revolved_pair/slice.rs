//! One slice `z = t` of the frustum–frustum pair in polar coordinates about `a`'s axis: the
//! ray from the axis point `p = (0, 0, t)` along `u = (cos φ, sin φ, 0)` meets `b` in one
//! interval in closed form (a quadratic for the lateral surface, two planes for the caps), and
//! `a`'s disc in `0 ≤ ρ ≤ R(t)`. The section's area and first moments are then polynomials in
//! the interval's ends, integrated over `φ` between the cuts of [`super::quadric`] (the rays
//! tangent to `b`'s section, the rays through its corners — `b`'s rims piercing the slice —
//! and the crossings of `a`'s circle with `b`'s surface), on which every end is smooth or has
//! a square-root end the sine-mapped rule absorbs, and outside of which the section is empty
//! throughout a piece or nowhere in it.

use super::quadric::{Quadric, circle_crossings, sinusoid_roots, tangent_directions, wrap};
use crate::quadrature::{self, MAX_PIECES};
use contact_core::{Vector3, WorkCounters};
use std::f64::consts::PI;

/// Relative distance (working units) within which `a`'s circle counts as on `b`'s surface
/// (identical or touching solids: the comparison of equal radii is round-off).
pub(crate) const ON_SURFACE: f64 = 1e-12;

/// Components of the polar integrand: area, the two first moments, then for `a`'s circle
/// inside `b` its angle and `∫cos φ`, `∫sin φ`.
pub(crate) const POLAR: usize = 6;

/// The inner adaptive rule over the azimuth: error estimates within 1e-13 relative (the
/// torus pairs' slices share it).
pub(crate) const ADAPTIVE: quadrature::Adaptive = quadrature::Adaptive {
    tolerance: 1e-13,
    max_depth: 14,
    pair: crate::quadrature::Pair::Kronrod21,
};

/// The slices' absolute floor per disc area: inside the nested slicing, a slice's round-off
/// is not worth chasing below 1e-15 of the disc (the outer rule's tolerance is looser).
pub(crate) const SLICE_FLOOR: f64 = 1e-15;

/// Where an end of `b`'s interval along a ray lies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum End {
    /// On the lateral surface.
    Lateral,
    /// On a cap, outward normal `sign·w`.
    Cap(f64),
    /// At infinity (a ray inside the slab that never meets the lateral surface).
    Open,
}

/// The two solids in the working frame: `a` with bottom centre at the origin and axis `z`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Pair {
    /// `a`'s lateral quadric (origin 0, axis `z`).
    pub a: Quadric,
    /// `b`'s lateral quadric.
    pub b: Quadric,
}

/// What every ray of one slice shares: `b`'s quadric at the axis point and its quadratic
/// form in the slice's plane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Rays {
    /// `a`'s radius there.
    pub(crate) radius: f64,
    /// The axis point's height along `b`'s axis.
    height: f64,
    /// `b`'s axis' components in the slice's plane.
    axis: [f64; 2],
    /// `Q(p)`.
    value: f64,
    /// `∇Q(p)/2` in the slice's plane.
    gradient: [f64; 2],
    /// `[M₁₁, M₁₂, M₂₂]` of `Q`'s quadratic part.
    form: [f64; 3],
    /// How far `b`'s slab is widened (0, or [`ON_SURFACE`] for a cap's own slice).
    tol: f64,
}

impl Pair {
    /// The shared terms of the rays of slice `t` (`a`'s radius `r`); `closed` widens `b`'s
    /// slab by [`ON_SURFACE`] (a cap's own slice, whose height is round-off of `b`'s).
    fn rays(&self, t: f64, r: f64, closed: bool) -> Rays {
        rays_of(&self.b, t, r, closed)
    }

    /// `a`'s radius at height `t`.
    pub fn radius_a(&self, t: f64) -> f64 {
        (self.a.r0 + self.a.slope * t).max(0.0)
    }

    /// `b`'s interval `(enter, end, exit, end)` along the whole line `p + ρu` of the slice
    /// `rays`.
    fn interval(&self, rays: &Rays, c: f64, s: f64) -> Option<(f64, End, f64, End)> {
        interval_of(&self.b, rays, c, s)
    }

    /// The polar integrand at `(t, φ)`, `r` being `a`'s radius there (see [`POLAR`]).
    fn polar(&self, rays: &Rays, phi: f64) -> [f64; POLAR] {
        let mut out = [0.0; POLAR];
        let (s, c) = phi.sin_cos();
        let r = rays.radius;
        let Some((enter, _, exit, _)) = self.interval(rays, c, s) else {
            return out;
        };
        let (lo, hi) = (enter.max(0.0), exit.min(r));
        if hi <= lo {
            return out;
        }
        let (lo2, hi2) = (lo * lo, hi * hi);
        out[0] = 0.5 * (hi2 - lo2);
        let cube = (hi2 * hi - lo2 * lo) / 3.0;
        out[1] = cube * c;
        out[2] = cube * s;
        let tol = ON_SURFACE * r.max(1.0);
        if enter <= r + tol && exit >= r - tol {
            out[3] = 1.0;
            out[4] = c;
            out[5] = s;
        }
        out
    }

    /// The cuts in `φ ∈ [−π, π]` of the slice `t` (`a`'s radius `r` there), sorted; how many.
    pub(crate) fn cuts(&self, t: f64, r: f64) -> ([f64; MAX_PIECES + 1], usize) {
        let mut cuts = [0.0; MAX_PIECES + 1];
        cuts[0] = -PI;
        cuts[1] = PI;
        let mut n = 2;
        let mut push = |x: f64, cuts: &mut [f64; MAX_PIECES + 1]| {
            if x.is_finite() && x > -PI && x < PI && n < cuts.len() {
                cuts[n] = x;
                n += 1;
            }
        };
        let p = Vector3::new(0.0, 0.0, t);
        let q = &self.b;
        let (dirs, count) = tangent_directions(q, &p);
        for &d in &dirs[..count] {
            push(d, &mut cuts);
        }
        // b's rims through the slice: their points' directions.
        let (e1, e2) = rim_axes(&q.axis);
        for (h, rim) in [(0.0, q.r0), (q.len, q.r0 + q.slope * q.len)] {
            let centre = q.origin + q.axis * h;
            let (psi, k) = sinusoid_roots(rim * e1.z, rim * e2.z, t - centre.z);
            for &x in &psi[..k] {
                let point = centre + rim * (x.cos() * e1 + x.sin() * e2);
                if point.x != 0.0 || point.y != 0.0 {
                    push(point.y.atan2(point.x), &mut cuts);
                }
            }
            // a's circle against the cap plane w·(x − centre) = 0.
            if r > 0.0 {
                let (psi, k) =
                    sinusoid_roots(r * q.axis.x, r * q.axis.y, -q.axis.dot(&(p - centre)));
                for &x in &psi[..k] {
                    push(x, &mut cuts);
                }
            }
        }
        if r > 0.0 {
            let (psi, k) = circle_crossings(q, &p, &Vector3::x(), &Vector3::y(), r);
            for &x in &psi[..k] {
                push(wrap(x), &mut cuts);
            }
        }
        cuts[..n].sort_by(f64::total_cmp);
        (cuts, n)
    }

    /// Whether the slice `t` meets both solids (with an area).
    pub fn not_empty(&self, t: f64) -> bool {
        let r = self.radius_a(t);
        if r <= 0.0 {
            return false;
        }
        let (cuts, n) = self.cuts(t, r);
        let rays = self.rays(t, r, false);
        cuts[..n]
            .windows(2)
            .any(|w| w[1] > w[0] && self.polar(&rays, 0.5 * (w[0] + w[1]))[0] > 0.0)
    }

    /// `∫ polar dφ` over the slice `t` (see [`POLAR`]).
    pub fn slice(&self, t: f64, closed: bool, work: &mut WorkCounters) -> [f64; POLAR] {
        self.slice_by((&ADAPTIVE, SLICE_FLOOR), t, closed, work)
    }

    /// [`Pair::slice`] by `rule`, each piece keeping an absolute error of `floor` times the
    /// disc's area besides the relative 1e-14 of the slice's.
    pub fn slice_by(
        &self,
        (rule, floor): (&quadrature::Adaptive, f64),
        t: f64,
        closed: bool,
        work: &mut WorkCounters,
    ) -> [f64; POLAR] {
        let r = self.radius_a(t);
        if r <= 0.0 {
            return [0.0; POLAR];
        }
        let (mut cuts, n) = self.cuts(t, r);
        let rays = self.rays(t, r, closed);
        let floor = |e: &[f64; POLAR]| {
            let v = (e[0].abs() * 1e-14)
                .max(floor * r * r)
                .max(f64::MIN_POSITIVE);
            let m = v * r;
            let angle = 1e-14;
            [v, m, m, angle, angle, angle]
        };
        rule.integrate_pieces(
            &mut cuts[..n],
            &mut |phi| self.polar(&rays, phi),
            &floor,
            work,
        )
    }
}

/// Two unit vectors completing the unit `w` to an orthonormal frame (the rims' planes).
pub(crate) fn rim_axes(w: &Vector3) -> (Vector3, Vector3) {
    let helper = if w.x.abs() <= w.y.abs() && w.x.abs() <= w.z.abs() {
        Vector3::x()
    } else if w.y.abs() <= w.z.abs() {
        Vector3::y()
    } else {
        Vector3::z()
    };
    let e1 = w.cross(&helper).normalize();
    (e1, w.cross(&e1))
}

/// The shared terms of the rays of slice `t` of `b = q` (`a`'s radius `r`); `closed` widens `b`'s
/// slab by [`ON_SURFACE`] (a cap's own slice, whose height is round-off of `b`'s).
pub(crate) fn rays_of(q: &Quadric, t: f64, r: f64, closed: bool) -> Rays {
    let p = Vector3::new(0.0, 0.0, t);
    let g = q.half_gradient(&p);
    let m = q.matrix();
    Rays {
        radius: r,
        height: q.height(&p),
        axis: [q.axis.x, q.axis.y],
        value: q.value(&p),
        gradient: [g.x, g.y],
        form: [m[(0, 0)], m[(0, 1)], m[(1, 1)]],
        tol: if closed { ON_SURFACE } else { 0.0 },
    }
}

/// `b`'s interval `(enter, end, exit, end)` along the whole line `p + ρu` of the slice
/// `rays`.
pub(crate) fn interval_of(
    q: &Quadric,
    rays: &Rays,
    c: f64,
    s: f64,
) -> Option<(f64, End, f64, End)> {
    let [m11, m12, m22] = rays.form;
    let a = m11 * c * c + 2.0 * m12 * c * s + m22 * s * s;
    let b = rays.gradient[0] * c + rays.gradient[1] * s;
    let line = Line {
        height: rays.height,
        rate: rays.axis[0] * c + rays.axis[1] * s,
        quadratic: [a, b, rays.value],
        tol: rays.tol,
    };
    interval_on_line(q, &line)
}

/// A line `p + ρv` seen by a frustum `q`: the height along `q`'s axis at `ρ = 0` and its rate,
/// and `q`'s lateral quadric along it, `Q(p + ρv) = a ρ² + 2 b ρ + c` as `[a, b, c]`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Line {
    /// `w·(p − o)`.
    pub height: f64,
    /// `w·v`.
    pub rate: f64,
    /// `[vᵀMv, vᵀ∇Q(p)/2, Q(p)]`.
    pub quadratic: [f64; 3],
    /// How far `q`'s slab is widened.
    pub tol: f64,
}

/// `q`'s interval `(enter, end, exit, end)` along `line` (in its parameter `ρ`), or `None`
/// when the line misses `q`.
pub(crate) fn interval_on_line(q: &Quadric, line: &Line) -> Option<(f64, End, f64, End)> {
    let (zd, wu) = (line.height, line.rate);
    // The slab 0 ≤ z ≤ L along the line.
    let (mut lo, mut lo_end, mut hi, mut hi_end) =
        (f64::NEG_INFINITY, End::Open, f64::INFINITY, End::Open);
    if wu == 0.0 {
        if zd < -line.tol || zd > q.len + line.tol {
            return None;
        }
    } else {
        // One division for both caps (the chain of divisions and the root is the cost).
        let inverse = 1.0 / wu;
        let bottom = (-line.tol - zd) * inverse;
        let top = (q.len + line.tol - zd) * inverse;
        if wu > 0.0 {
            (lo, lo_end, hi, hi_end) = (bottom, End::Cap(-1.0), top, End::Cap(1.0));
        } else {
            (lo, lo_end, hi, hi_end) = (top, End::Cap(1.0), bottom, End::Cap(-1.0));
        }
    }
    // The quadric a ρ² + 2 b ρ + c ≤ 0.
    let [a, b, c] = line.quadratic;
    let pieces: [(f64, f64); 2] = if a == 0.0 {
        if b > 0.0 {
            [(f64::NEG_INFINITY, -0.5 * c / b), (1.0, 0.0)]
        } else if b < 0.0 {
            [(-0.5 * c / b, f64::INFINITY), (1.0, 0.0)]
        } else if c <= 0.0 {
            [(f64::NEG_INFINITY, f64::INFINITY), (1.0, 0.0)]
        } else {
            return None;
        }
    } else {
        let disc = b * b - a * c;
        if disc < 0.0 || disc.is_nan() {
            if a > 0.0 {
                return None;
            }
            [(f64::NEG_INFINITY, f64::INFINITY), (1.0, 0.0)]
        } else {
            let root = -(b + b.signum() * disc.sqrt());
            let (mut r1, mut r2) = if root == 0.0 {
                (0.0, 0.0)
            } else {
                (root / a, c / root)
            };
            if r1 > r2 {
                std::mem::swap(&mut r1, &mut r2);
            }
            if a > 0.0 {
                [(r1, r2), (1.0, 0.0)]
            } else {
                [(f64::NEG_INFINITY, r1), (r2, f64::INFINITY)]
            }
        }
    };
    // The piece inside the slab on the frustum's own nappe (radius ≥ 0); a cylinder
    // (a > 0 or a linear quadric) has only one.
    let mut best: Option<(f64, End, f64, End)> = None;
    for (l0, l1) in pieces {
        if l0 > l1 {
            continue;
        }
        let (enter, enter_end) = if l0 > lo {
            (l0, End::Lateral)
        } else {
            (lo, lo_end)
        };
        let (exit, exit_end) = if l1 < hi {
            (l1, End::Lateral)
        } else {
            (hi, hi_end)
        };
        if enter > exit {
            continue;
        }
        if q.slope != 0.0 {
            let mid = if enter.is_finite() && exit.is_finite() {
                0.5 * (enter + exit)
            } else if enter.is_finite() {
                enter + 1.0
            } else if exit.is_finite() {
                exit - 1.0
            } else {
                0.0
            };
            if q.r0 + q.slope * (zd + mid * wu) < 0.0 {
                continue;
            }
        }
        if best.is_none_or(|(e0, _, e1, _)| exit - enter > e1 - e0) {
            best = Some((enter, enter_end, exit, exit_end));
        }
    }
    best
}
