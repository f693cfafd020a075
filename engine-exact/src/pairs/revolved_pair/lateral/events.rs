//! The events of a lateral integral ([`super`]): where the interval of `a`'s generators in
//! `b` stops being smooth in the azimuth — `a`'s rims against `b`'s lateral quadric and cap
//! planes, `b`'s rims piercing `a`'s lateral quadric, and the generators tangent to `b`'s
//! quadric (the zeros of their discriminant, a trigonometric form of degree two) — with the
//! rims clear of the other solid skipped.

use super::super::quadric::{Quadric, circle_crossings, sinusoid_roots, trig_roots, wrap};
use super::super::slice::{Pair, rim_axes};
use super::Generators;
use crate::quadrature::MAX_PIECES;
use contact_core::Vector3;
use std::f64::consts::PI;

impl Pair {
    /// The cuts in `φ ∈ [−π, π]` of `a`'s lateral surface inside `b`, sorted; how many.
    pub(super) fn lateral_cuts(&self, generators: &Generators) -> ([f64; MAX_PIECES + 1], usize) {
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
        // A rim clear of the other solid crosses none of its surface: its events (real
        // crossings lie on the solid) are skipped.
        // a's rims against b's lateral quadric and cap planes.
        for (z, r) in [(0.0, a.r0), (a.len, a.r0 + a.slope * a.len)] {
            let centre = Vector3::new(0.0, 0.0, z);
            if r <= 0.0 || circle_clear_of(&centre, &Vector3::z(), r, q) {
                continue;
            }
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
            let centre = q.origin + q.axis * h;
            if rim <= 0.0 || circle_clear_of(&centre, &q.axis, rim, a) {
                continue;
            }
            let (psi, k) = circle_crossings(a, &centre, &e1, &e2, rim);
            for &x in &psi[..k] {
                let point = centre + rim * (x.cos() * e1 + x.sin() * e2);
                if point.x != 0.0 || point.y != 0.0 {
                    push(point.y.atan2(point.x), &mut cuts);
                }
            }
        }
        // a's generators tangent to b's lateral quadric.
        let (psi, k) = trig_roots(&discriminant_form(generators));
        for &x in &psi[..k] {
            push(x, &mut cuts);
        }
        cuts[..n].sort_by(f64::total_cmp);
        (cuts, n)
    }
}

/// A frustum's bounding ball: centre at its axis' midpoint, radius to its wider rim.
fn ball(q: &Quadric) -> (Vector3, f64) {
    let r1 = q.r0 + q.slope * q.len;
    (
        q.origin + q.axis * (0.5 * q.len),
        q.r0.max(r1).hypot(0.5 * q.len),
    )
}

/// Whether the circle (centre `c`, unit normal `normal`, radius `r`) stays clear of the
/// frustum `q`, by more than round-off (1e-9 of the frustum's bounding ball), by any of three
/// tests, each of a region holding the frustum:
/// - its bounding ball: the circle's nearest point is `√((ρ − r)² + h²)` from the ball's
///   centre, `h` and `ρ` that centre's height over the circle's plane and distance from its
///   axis;
/// - the infinite cylinder of the frustum's wider radius about its axis: every point of the
///   circle is at least `D − r` from that axis, `D` the centre's distance from it;
/// - the slab between its cap planes: the circle spans `r·|normal × axis|` either side of its
///   centre's height along the axis.
///
/// The ball alone misses a long solid's rims crossing another far from its ends.
fn circle_clear_of(c: &Vector3, normal: &Vector3, r: f64, q: &Quadric) -> bool {
    let (centre, radius) = ball(q);
    let margin = 1e-9 * radius;
    let d = centre - c;
    let h = normal.dot(&d);
    let rho = (d - normal * h).norm();
    if (rho - r).hypot(h) > radius + margin {
        return true;
    }
    let from_origin = c - q.origin;
    let height = q.axis.dot(&from_origin);
    let across = (from_origin - q.axis * height).norm();
    let widest = q.r0.max(q.r0 + q.slope * q.len);
    let extent = r * normal.cross(&q.axis).norm();
    across - r > widest + margin || height - extent > q.len + margin || height + extent < -margin
}

/// The discriminant `β² − αγ` of `b`'s quadratic along `a`'s generators as the trigonometric
/// form of [`trig_roots`], from its five Fourier coefficients (it is of degree two, see the
/// module docs).
pub(super) fn discriminant_form(generators: &Generators) -> [f64; 6] {
    let (mut a0, mut a1, mut b1, mut a2, mut b2) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for j in 0..5 {
        let phi = 2.0 * PI * j as f64 / 5.0;
        let [alpha, beta, gamma] = generators.line(phi.cos(), phi.sin()).quadratic;
        let d = beta * beta - alpha * gamma;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;

    /// A circle called clear of a frustum has none of 4000 points on it inside the frustum's
    /// solid (brute force, radial distance against the radius at the point's height), over
    /// random frusta, cones and cylinders and circles around them; and the tests do call
    /// circles clear that the bounding ball alone would not (a long solid's far rims).
    #[test]
    fn a_circle_called_clear_of_a_frustum_has_no_point_in_it() {
        let mut rng = Rng(11);
        let (mut clear, mut beyond_ball) = (0, 0);
        for _ in 0..4000 {
            let q = Quadric::random(&mut rng);
            let (centre, normal, r) = (
                Vector3::new(
                    rng.uniform(-4.0, 4.0),
                    rng.uniform(-4.0, 4.0),
                    rng.uniform(-4.0, 4.0),
                ),
                rng.unit(),
                rng.uniform(0.05, 1.5),
            );
            if !circle_clear_of(&centre, &normal, r, &q) {
                continue;
            }
            clear += 1;
            let (ball_centre, ball_radius) = ball(&q);
            let (e1, e2) = rim_axes(&normal);
            let mut inside_ball = false;
            for k in 0..4000 {
                let psi = 2.0 * PI * k as f64 / 4000.0;
                let p = centre + r * (psi.cos() * e1 + psi.sin() * e2);
                assert!(!q.holds(&p), "{q:?} {centre:?} {normal:?} {r}: {p:?}");
                inside_ball |= (p - ball_centre).norm() <= ball_radius;
            }
            beyond_ball += usize::from(inside_ball);
        }
        assert!(clear > 1000 && beyond_ball > 100, "{clear} {beyond_ball}");
    }
}
