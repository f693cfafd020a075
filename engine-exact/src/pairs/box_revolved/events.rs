//! The slices where the box's section meets the revolved solid's section differently: the
//! cuts of the quadrature, all in closed form (roots of polynomials of degree ≤ 4).
//!
//! In the revolved solid's frame (axis `z`, working units) the box's section at height `t` is
//! a convex polygon whose vertices move linearly along the box's edges and whose edges lie on
//! the lines `g·p = e(t)`, `g` the unit in-plane part of a face normal and `e` linear in `t`.
//! The overlap with the disc (or annulus) changes shape where
//! - a vertex appears or vanishes: the heights of the box's corners;
//! - a vertex crosses a circle: an edge pierces the solid's surface — for a frustum
//!   `|p_xy|² = (r₀ + k z)²` (a quadratic along the edge), for a torus
//!   `(|p|² + R² − ρ²)² = 4R²|p_xy|²` (a quartic);
//! - an edge line is tangent to a circle: `|e(t)| = r(t)` — for a frustum two linear
//!   equations, for a torus `(e ∓ R)² + t² = ρ²` (two quadratics, inner and outer circles
//!   together);
//! - the solid's section appears or vanishes: its ends (`0`, `L` or `±ρ`), which are the ends
//!   of the integration range.
//!
//! These include every `t` where the overlap becomes empty or not (a first touch is a corner,
//! a face tangency, an edge's tangency — a double root — or a rim on a face at an end), so
//! between consecutive cuts the overlap is empty throughout or nowhere.
//! The quartic's real roots in `(0, 1)` are isolated between the real roots of its
//! derivative (recursively: cubic, quadratic) and each bracketed sign change is refined to
//! round-off by Newton's steps kept inside the bracket; a root pair closer than round-off (an edge touching the surface) shows no sign
//! change and is dropped: its slices' overlap is itself round-off.

use super::{FLAT, MAX_CUTS, Profile, Setup};
use contact_core::Vector3;

/// `p(x) = Σ c[k] x^k`.
fn eval(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &ck| acc * x + ck)
}

/// The real roots of `c[0] + c[1] x + c[2] x²` inside `(lo, hi)`, stably; degenerate
/// (linear) leading coefficients handled.
fn quadratic_in(c: &[f64; 3], lo: f64, hi: f64, out: &mut [f64; 4]) -> usize {
    let (a, b, c0) = (c[2], c[1], c[0]);
    let mut n = 0;
    let mut push = |x: f64| {
        if x > lo && x < hi && n < 4 {
            out[n] = x;
            n += 1;
        }
    };
    if a == 0.0 {
        if b != 0.0 {
            push(-c0 / b);
        }
        return n;
    }
    let disc = b * b - 4.0 * a * c0;
    if disc.is_nan() || disc < 0.0 {
        return n;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    if q != 0.0 {
        push(q / a);
        push(c0 / q);
    } else {
        push(0.0);
    }
    n
}

/// The real roots of the polynomial `c` (degree ≤ 4, `c[k]` of `x^k`) inside `(lo, hi)`,
/// sorted; how many.
pub(crate) fn roots_in(c: &[f64; 5], lo: f64, hi: f64) -> ([f64; 4], usize) {
    let mut out = [0.0; 4];
    let degree = (0..5).rev().find(|&k| c[k] != 0.0).unwrap_or(0);
    if degree <= 2 {
        let n = quadratic_in(&[c[0], c[1], c[2]], lo, hi, &mut out);
        out[..n].sort_by(f64::total_cmp);
        return (out, n);
    }
    // The derivative's roots split (lo, hi) into monotone pieces.
    let mut derivative = [0.0; 5];
    for k in 1..=degree {
        derivative[k - 1] = k as f64 * c[k];
    }
    let (critical, m) = roots_in(&derivative, lo, hi);
    let mut ends = [0.0; 6];
    ends[0] = lo;
    ends[1..=m].copy_from_slice(&critical[..m]);
    ends[m + 1] = hi;
    let mut n = 0;
    for piece in ends[..m + 2].windows(2) {
        let (a, b) = (piece[0], piece[1]);
        let (fa, fb) = (eval(c, a), eval(c, b));
        if fa == 0.0 && a > lo && n < 4 {
            out[n] = a;
            n += 1;
            continue;
        }
        // No sign change (a NaN product included): no root in this piece.
        if (fa * fb).is_nan() || fa * fb >= 0.0 {
            continue;
        }
        let rising = fb > 0.0;
        let root = newton_in_bracket(c, degree, rising, (a, b));
        if n < 4 {
            out[n] = root;
            n += 1;
        }
    }
    (out, n)
}

/// The root of the polynomial `c` (of `degree`) in the bracket `(a, b)` where it is monotone,
/// rising or not, with a sign change: Newton's steps from the middle, each kept inside the
/// bracket (a bisection when a step would leave it) and the bracket shrunk by each value's
/// sign, to round-off — as exact as bisecting to the last bit, in a handful of steps.
fn newton_in_bracket(c: &[f64; 5], degree: usize, rising: bool, (mut a, mut b): (f64, f64)) -> f64 {
    let mut x = 0.5 * (a + b);
    for _ in 0..200 {
        // The value and the slope by Horner's rule.
        let (mut f, mut df) = (c[degree], 0.0);
        for k in (0..degree).rev() {
            df = df * x + f;
            f = f * x + c[k];
        }
        if f == 0.0 {
            return x;
        }
        if (f > 0.0) == rising {
            b = x;
        } else {
            a = x;
        }
        let step = f / df;
        // A step at round-off of `x`: converged (one more would only trade ulps).
        if step.abs() <= 2.0 * f64::EPSILON * x.abs() {
            return x;
        }
        let mut next = x - step;
        if !(next > a && next < b) {
            next = 0.5 * (a + b);
        }
        // The bracket at round-off: nothing between its ends.
        if next <= a || next >= b {
            return x;
        }
        x = next;
    }
    x
}

/// The polynomial in `s` (coefficients of `s^k`) whose roots are where the edge `start + s·d`
/// crosses the cone `|p_xy| = r0 + slope·z` (a quadratic).
pub(crate) fn cone_piercing(r0: f64, slope: f64, start: &Vector3, d: &Vector3) -> [f64; 5] {
    let (pxy, dxy) = (start.xy(), d.xy());
    let (q0, q1) = (r0 + slope * start.z, slope * d.z);
    [
        pxy.norm_squared() - q0 * q0,
        2.0 * (pxy.dot(&dxy) - q0 * q1),
        dxy.norm_squared() - q1 * q1,
        0.0,
        0.0,
    ]
}

/// The same for the torus `(|p|² + R² − ρ²)² = 4R²|p_xy|²` (a quartic).
pub(crate) fn torus_piercing(big: f64, small: f64, start: &Vector3, d: &Vector3) -> [f64; 5] {
    let (pxy, dxy) = (start.xy(), d.xy());
    let (a, b) = (d.norm_squared(), 2.0 * start.dot(d));
    let c = start.norm_squared() + big * big - small * small;
    let (a2, b2, c2) = (dxy.norm_squared(), 2.0 * pxy.dot(&dxy), pxy.norm_squared());
    let four = 4.0 * big * big;
    [
        c * c - four * c2,
        2.0 * b * c - four * b2,
        b * b + 2.0 * a * c - four * a2,
        2.0 * a * b,
        a * a,
    ]
}

impl Setup {
    /// The quadrature's cuts inside `[lo, hi]` (see this module's docs), sorted, near-duplicates
    /// dropped; how many.
    pub(super) fn cuts(&self, lo: f64, hi: f64) -> ([f64; MAX_CUTS], usize) {
        let mut cuts = [0.0; MAX_CUTS];
        cuts[0] = lo;
        cuts[1] = hi;
        let mut n = 2;
        let mut push = |t: f64, cuts: &mut [f64; MAX_CUTS]| {
            if t > lo && t < hi && n < MAX_CUTS {
                cuts[n] = t;
                n += 1;
            }
        };
        for c in &self.corners {
            push(c.z, &mut cuts);
        }
        for (n_f, d) in &self.faces {
            let g = n_f.x.hypot(n_f.y);
            if g <= FLAT {
                continue;
            }
            let (e0, e1) = (d / g, -n_f.z / g);
            match self.profile {
                Profile::Frustum { r0, slope, .. } => {
                    for sigma in [1.0, -1.0] {
                        let denominator = e1 - sigma * slope;
                        if denominator != 0.0 {
                            push((sigma * r0 - e0) / denominator, &mut cuts);
                        }
                    }
                }
                Profile::Torus { big, small } => {
                    for sigma in [1.0, -1.0] {
                        let e = e0 - sigma * big;
                        let c = [e * e - small * small, 2.0 * e1 * e, e1 * e1 + 1.0, 0.0, 0.0];
                        let (roots, count) = roots_in(&c, lo, hi);
                        for &t in &roots[..count] {
                            push(t, &mut cuts);
                        }
                    }
                }
            }
        }
        for k in 0..3 {
            for (v, start) in self.corners.iter().enumerate() {
                if v & (1 << k) != 0 {
                    continue;
                }
                let d = self.corners[v | (1 << k)] - start;
                if d.z == 0.0 {
                    continue;
                }
                let c = self.piercing(start, &d);
                let (roots, count) = roots_in(&c, 0.0, 1.0);
                for &s in &roots[..count] {
                    push(start.z + s * d.z, &mut cuts);
                }
            }
        }
        cuts[..n].sort_by(f64::total_cmp);
        let mut unique = 1;
        for k in 1..n {
            if cuts[k] > cuts[unique - 1] + 1e-14 * (hi - lo) {
                cuts[unique] = cuts[k];
                unique += 1;
            }
        }
        // The last cut is `hi` itself (a cut just below it was merged into it).
        cuts[unique - 1] = hi;
        (cuts, unique)
    }

    /// The polynomial in `s` whose roots are where the edge `start + s·d` crosses the solid's
    /// surface (coefficients of `s^k`).
    fn piercing(&self, start: &Vector3, d: &Vector3) -> [f64; 5] {
        match self.profile {
            Profile::Frustum { r0, slope, .. } => cone_piercing(r0, slope, start, d),
            Profile::Torus { big, small } => torus_piercing(big, small, start, d),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quartic_with_four_known_roots() {
        // (x − 0.1)(x − 0.3)(x − 0.35)(x − 0.9), expanded.
        let r = [0.1, 0.3, 0.35, 0.9];
        let mut c = [1.0, 0.0, 0.0, 0.0, 0.0];
        for &root in &r {
            let mut next = [0.0; 5];
            for k in 0..4 {
                next[k + 1] += c[k];
                next[k] -= root * c[k];
            }
            c = next;
        }
        let (found, n) = roots_in(&c, 0.0, 1.0);
        assert_eq!(n, 4, "{found:?}");
        for k in 0..4 {
            assert!((found[k] - r[k]).abs() < 1e-13, "{found:?}");
        }
        // Only those inside the interval.
        let (found, n) = roots_in(&c, 0.2, 0.5);
        assert_eq!(n, 2);
        assert!((found[0] - 0.3).abs() < 1e-13 && (found[1] - 0.35).abs() < 1e-13);
        // A quadratic without real roots, and a linear one.
        assert_eq!(roots_in(&[1.0, 0.0, 1.0, 0.0, 0.0], -5.0, 5.0).1, 0);
        let (x, n) = roots_in(&[-1.0, 2.0, 0.0, 0.0, 0.0], 0.0, 1.0);
        assert!(n == 1 && (x[0] - 0.5).abs() < 1e-16);
    }
}
