//! The part of a slice's overlap inside a wedge of azimuths about the torus' axis, one
//! region's share when the torus meets the ellipsoid in several.
//!
//! The overlap of [`disc_ellipse`](crate::methods::ellipsoid_sliced::disc_overlap::disc_ellipse)
//! is bounded by arcs of the unit circle (the ellipsoid's section, angle `θ`) and of the
//! ellipse `q + K u(φ)` (a circle of radius `ρ_c` about the axis, mapped: `q` is the axis and
//! `φ` the slice's azimuth). The wedge's two rays run through the axis, so in Green's
//! integrals taken about `q` (`½∮(p − q) × dp`, `⅓∮(p − q)((p − q) × dp)`) they contribute
//! nothing: the overlap inside the wedge is the sum over the boundary arcs' parts inside it.
//! The ellipse arcs are cut in `φ` directly; a circle arc is cut where its slice point
//! `c + M u(θ)` crosses a ray's line (`cross(d, c + M u(θ)) = 0`, a linear trigonometric
//! equation) and each piece kept when its middle lies inside.

use crate::methods::ellipsoid_sliced::disc_overlap::{DiscOverlap, trig_product_integral};
use nalgebra::{Matrix2, Vector2};
use std::f64::consts::TAU;

/// The azimuths `start ≤ φ ≤ end` (`0 < end − start ≤ 2π`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Wedge {
    /// First azimuth.
    pub start: f64,
    /// Last azimuth.
    pub end: f64,
}

impl Wedge {
    /// Whether the slice point `p` lies inside.
    pub(crate) fn contains(&self, p: &Vector2<f64>) -> bool {
        (p.y.atan2(p.x) - self.start).rem_euclid(TAU) <= self.end - self.start
    }
}

/// `(a × b)` in the plane.
fn cross(a: &Vector2<f64>, b: &Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The part inside `wedge` of `o`, the overlap of the ellipsoid's section
/// `center + matrix·u(θ)` (slice coordinates, the axis at the origin) with the disc of
/// `radius` about the axis, in the section's disc coordinates like `o` (moments about the
/// disc's centre).
pub(crate) fn restrict(
    o: &DiscOverlap,
    center: &Vector2<f64>,
    matrix: &Matrix2<f64>,
    radius: f64,
    wedge: &Wedge,
) -> DiscOverlap {
    let mut out = DiscOverlap {
        shape: o.shape,
        ..DiscOverlap::default()
    };
    let Some(inverse) = matrix.try_inverse() else {
        return out;
    };
    let q = inverse * -center;
    let mut moment_q = Vector2::zeros();
    // The circle's arcs, cut at the rays' lines.
    let rays = [wedge.start, wedge.end].map(|a| Vector2::new(a.cos(), a.sin()));
    let (m0, m1) = (matrix.column(0).into_owned(), matrix.column(1).into_owned());
    for &(t0, t1) in o.arcs.spans() {
        let mut cuts = [0.0; 6];
        let mut n = 0;
        cuts[n] = t0;
        n += 1;
        for d in &rays {
            let (a, b, c) = (cross(d, center), cross(d, &m0), cross(d, &m1));
            let h = b.hypot(c);
            if h == 0.0 || a.abs() > h {
                continue;
            }
            let (base, spread) = (c.atan2(b), (-a / h).acos());
            for root in [base + spread, base - spread] {
                let r = t0 + (root - t0).rem_euclid(TAU);
                if r > t0 && r < t1 {
                    cuts[n] = r;
                    n += 1;
                }
            }
        }
        cuts[n] = t1;
        n += 1;
        cuts[..n].sort_by(f64::total_cmp);
        for w in cuts[..n].windows(2) {
            let (a, b) = (w[0], w[1]);
            let mid = 0.5 * (a + b);
            if b <= a || !wedge.contains(&(center + matrix * Vector2::new(mid.cos(), mid.sin()))) {
                continue;
            }
            let weight = [1.0, -q.x, -q.y];
            out.area += 0.5 * trig_product_integral(&weight, &[1.0, 0.0, 0.0], a, b);
            moment_q += Vector2::new(
                trig_product_integral(&[-q.x, 1.0, 0.0], &weight, a, b),
                trig_product_integral(&[-q.y, 0.0, 1.0], &weight, a, b),
            ) / 3.0;
            out.chord += Vector2::new(b.cos() - a.cos(), b.sin() - a.sin());
            out.angle += b - a;
            out.arcs.push(a, b);
        }
    }
    // The mapped circle's arcs, cut in the azimuth.
    let k = inverse * radius;
    let det = k.determinant();
    let span = wedge.end - wedge.start;
    for &(f0, f1) in o.other_arcs.spans() {
        let base = wedge.start + TAU * ((f0 - wedge.start) / TAU).floor();
        for shift in [-1.0, 0.0, 1.0] {
            let lo = base + shift * TAU;
            let (a, b) = (f0.max(lo), f1.min(lo + span));
            if b <= a {
                continue;
            }
            out.area += 0.5 * det * (b - a);
            moment_q += k * Vector2::new(b.sin() - a.sin(), a.cos() - b.cos()) * (det / 3.0);
            out.other_arcs.push(a, b);
        }
    }
    out.moment = moment_q + q * out.area;
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods::ellipsoid_sliced::disc_overlap::disc_ellipse;
    use std::f64::consts::PI;

    #[test]
    fn two_half_turns_add_up_to_the_whole_overlap() {
        // A tilted ellipse section across a circle of radius 1.3 about the axis.
        let center = Vector2::new(1.1, 0.4);
        let matrix = Matrix2::new(0.5, 0.2, -0.1, 0.3);
        let inverse = matrix.try_inverse().unwrap();
        let o = disc_ellipse(&(inverse * -center), &(inverse * 1.3));
        let halves = [
            Wedge {
                start: 0.2,
                end: 0.2 + PI,
            },
            Wedge {
                start: 0.2 + PI,
                end: 0.2 + 2.0 * PI,
            },
        ]
        .map(|w| restrict(&o, &center, &matrix, 1.3, &w));
        let sum = |f: &dyn Fn(&DiscOverlap) -> f64| f(&halves[0]) + f(&halves[1]);
        assert!((sum(&|h| h.area) - o.area).abs() < 1e-14, "{}", o.area);
        assert!((sum(&|h| h.moment.x) - o.moment.x).abs() < 1e-14);
        assert!((sum(&|h| h.moment.y) - o.moment.y).abs() < 1e-14);
        assert!((sum(&|h| h.angle) - o.angle).abs() < 1e-14);
        assert!((sum(&|h| h.chord.x) - o.chord.x).abs() < 1e-14);
        // The whole turn is the overlap itself.
        let whole = restrict(
            &o,
            &center,
            &matrix,
            1.3,
            &Wedge {
                start: -1.0,
                end: -1.0 + 2.0 * PI,
            },
        );
        assert!((whole.area - o.area).abs() < 1e-14 && (whole.moment - o.moment).norm() < 1e-14);
    }
}
