//! Whether any cap of a frustum pair can meet the intersection: where none can, its boundary
//! is lateral surface only, and one lateral surface's fluxes give its moments
//! ([`super::divergence`]).

use super::quadric::{Quadric, trig_roots};
use super::slice::{Pair, rim_axes};
use contact_core::Vector3;

/// Whether no cap of either solid meets the other solid: each cap is clear when the other
/// solid lies wholly on one side of its plane (by 1e-9 of the longer solid; a frustum is the
/// hull of its rims, so its extent along a direction is its rims': a rim of radius `r` about
/// an axis `â` spans `r·|d × â|` either side of its centre's height along `d`), or when the
/// cap's disc stays outside the infinite cylinder of the other's wider radius about its axis
/// ([`disc_clear_of`]), as a solid crossing a long one obliquely does beyond its caps.
pub(super) fn caps_clear(pair: &Pair) -> bool {
    let (a, b) = (&pair.a, &pair.b);
    let margin = 1e-9 * a.len.max(b.len);
    let extent = |q: &Quadric, d: &Vector3, from: &Vector3| {
        let spread = d.cross(&q.axis).norm();
        let mut range = (f64::INFINITY, f64::NEG_INFINITY);
        for (t, r) in [(0.0, q.r0), (q.len, q.r0 + q.slope * q.len)] {
            let centre = d.dot(&(q.origin + q.axis * t - from));
            range = (
                range.0.min(centre - r * spread),
                range.1.max(centre + r * spread),
            );
        }
        range
    };
    // x's caps against y, whose extent along x's axis (from x's origin) is `(lo, hi)`.
    let caps_of = |x: &Quadric, y: &Quadric, (lo, hi): (f64, f64)| {
        [
            (0.0, x.r0, lo > margin),
            (x.len, x.r0 + x.slope * x.len, hi < x.len - margin),
        ]
        .into_iter()
        .all(|(t, r, beside)| {
            beside || r <= 0.0 || disc_clear_of(&(x.origin + x.axis * t), &x.axis, r, y, margin)
        })
    };
    caps_of(a, b, extent(b, &Vector3::z(), &Vector3::zeros()))
        && caps_of(b, a, extent(a, &b.axis, &b.origin))
}

/// Whether the disc (centre `c`, unit normal `normal`, radius `r`) stays outside the infinite
/// cylinder of `q`'s wider radius (plus `margin`) about `q`'s axis, which holds `q`: its rim
/// is wholly outside the cylinder (the squared distance of the rim's points from the axis,
/// less the radius squared, a trigonometric form of degree two in the rim's angle, has no
/// zero and is positive), and the axis does not pierce the disc (the cylinder's section by
/// the disc's plane, an ellipse about the piercing point, would otherwise lie inside the
/// disc; a plane parallel to the axis cuts an unbounded strip, which cannot).
fn disc_clear_of(c: &Vector3, normal: &Vector3, r: f64, q: &Quadric, margin: f64) -> bool {
    let widest = q.r0.max(q.r0 + q.slope * q.len) + margin;
    let d = q.axis;
    let w0 = c - q.origin;
    let along = w0.dot(&d);
    let piercing = normal.dot(&d);
    if piercing.abs() > 1e-12 {
        let x = w0 - d * (normal.dot(&w0) / piercing);
        if x.norm() <= r + margin {
            return false;
        }
    }
    // The rim's points c + r(C e₁ + S e₂): |w|² − (w·d)² − R² with w = w₀ + r(C e₁ + S e₂).
    let (e1, e2) = rim_axes(normal);
    let (b1, b2) = (e1.dot(&d), e2.dot(&d));
    let rr = r * r;
    let form = [
        rr * (1.0 - b1 * b1),
        -rr * b1 * b2,
        rr * (1.0 - b2 * b2),
        r * (w0.dot(&e1) - along * b1),
        r * (w0.dot(&e2) - along * b2),
        w0.norm_squared() - along * along - widest * widest,
    ];
    let at_zero = form[0] + 2.0 * form[3] + form[5];
    at_zero > 0.0 && trig_roots(&form).1 == 0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;
    use std::f64::consts::PI;

    /// A disc called clear of a frustum has none of its points (a polar grid of 40 × 200)
    /// inside the frustum's solid, over random frusta and discs around them; and discs are
    /// called clear whose ball (centre, radius) would meet the frustum's cylinder.
    #[test]
    fn a_disc_called_clear_of_a_frustum_has_no_point_in_it() {
        let mut rng = Rng(23);
        let (mut clear, mut beyond_ball) = (0, 0);
        for _ in 0..6000 {
            let q = Quadric::random(&mut rng);
            let centre = Vector3::new(
                rng.uniform(-3.0, 3.0),
                rng.uniform(-3.0, 3.0),
                rng.uniform(-3.0, 3.0),
            );
            let (normal, r) = (rng.unit(), rng.uniform(0.05, 1.5));
            if !disc_clear_of(&centre, &normal, r, &q, 0.0) {
                continue;
            }
            clear += 1;
            let (e1, e2) = rim_axes(&normal);
            for i in 1..=40 {
                for k in 0..200 {
                    let (rho, psi) = (r * f64::from(i) / 40.0, 2.0 * PI * f64::from(k) / 200.0);
                    let p = centre + rho * (psi.cos() * e1 + psi.sin() * e2);
                    assert!(!q.holds(&p), "{q:?} {centre:?} {normal:?} {r}: {p:?}");
                }
            }
            let widest = q.r0.max(q.r0 + q.slope * q.len);
            beyond_ball += usize::from(q.across(&centre).norm() - r <= widest);
        }
        assert!(clear > 1000 && beyond_ball > 100, "{clear} {beyond_ball}");
    }
}
