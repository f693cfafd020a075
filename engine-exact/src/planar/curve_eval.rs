//! A [`Curve`] ready for the closest-point search.
//!
//! Evaluation is `contact-core`'s ([`Curve::point_in_span`] and its derivatives, free of
//! allocation); this module adds the closest point, the curve's length scale and, for a closed
//! curve, parameters wrapped onto the domain.
//!
//! ## Closest point
//! Each polynomial span is searched on its own: sampled at [`SAMPLES_PER_SPAN`] + 1
//! parameters, then Newton on `g(u) = (C(u) − p)·C′(u)` from the nearest sample (steps
//! limited to one sample spacing and kept inside the span) until a step moves the point by
//! less than `1e-13·L` (`L` the control polygon's diagonal), at most [`MAX_NEWTON_STEPS`]
//! steps; the nearest of the spans' answers wins. Cost grows with the number of spans. Within
//! one span, a polynomial that comes near `p` twice less than a sample spacing apart could
//! still lead Newton to the farther branch; the sampling density bounds that risk.

use contact_core::geometry::Curve;
use contact_core::{Point2, Vector2};

/// Samples per polynomial span for the starting guess.
pub const SAMPLES_PER_SPAN: usize = 8;
/// Newton steps allowed after sampling.
pub const MAX_NEWTON_STEPS: usize = 50;

/// A curve ready for the closest-point search.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarCurve {
    curve: Curve,
    breakpoints: Vec<f64>,
    /// Bounding-box diagonal of the control polygon: the curve's length scale.
    length: f64,
}

/// The closest point of a curve to a query point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Closest {
    /// Its parameter.
    pub u: f64,
    /// The point.
    pub point: Point2,
    /// The first derivative there.
    pub tangent: Vector2,
    /// True when `u` is an end of an open curve.
    pub at_end: bool,
}

impl PlanarCurve {
    /// The curve, with its breakpoints and length scale computed once.
    pub fn new(curve: &Curve) -> Self {
        let (lo, hi) = curve.control_points().iter().fold(
            (
                Vector2::repeat(f64::INFINITY),
                Vector2::repeat(f64::NEG_INFINITY),
            ),
            |(lo, hi), p| (lo.inf(&p.coords), hi.sup(&p.coords)),
        );
        Self {
            curve: curve.clone(),
            breakpoints: curve.breakpoints(),
            length: (hi - lo).norm(),
        }
    }

    /// The control polygon's bounding-box diagonal.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// The polynomial degree (order − 1).
    pub fn degree(&self) -> usize {
        self.curve.order() - 1
    }

    /// True for a closed curve.
    pub fn is_closed(&self) -> bool {
        self.curve.is_closed()
    }

    /// The parameters where the polynomial spans meet, ends included.
    pub fn breakpoints(&self) -> &[f64] {
        &self.breakpoints
    }

    /// The parameter domain.
    pub fn domain(&self) -> [f64; 2] {
        self.curve.domain()
    }

    /// `u` onto the domain: wrapped for a closed curve, clamped for an open one.
    fn wrap(&self, u: f64) -> f64 {
        let [u0, u1] = self.domain();
        if self.is_closed() {
            u0 + (u - u0).rem_euclid(u1 - u0)
        } else {
            u.clamp(u0, u1)
        }
    }

    /// The point at `u`.
    pub fn point(&self, u: f64) -> Vector2 {
        self.curve.point(self.wrap(u)).coords
    }

    /// d²C/du² at `u` (zero for a polyline).
    pub fn second_derivative(&self, u: f64) -> Vector2 {
        self.curve.second_derivative(self.wrap(u))
    }

    /// The closest point of the curve to `p`; adds the Newton steps taken to `iterations`.
    ///
    /// Each polynomial span is searched on its own (samples, then Newton kept inside the
    /// span), and the best of the spans' local minima wins: a span's polynomial is smooth, so
    /// Newton there converges, and no minimum is lost at a knot where the curve bends.
    pub fn closest(&self, p: &Point2, iterations: &mut u64) -> Closest {
        let c = &self.curve;
        let target = p.coords;
        let tolerance = 1e-13 * self.length;
        let mut best = (f64::INFINITY, self.domain()[0], Vector2::zeros());
        for w in self.breakpoints.windows(2) {
            let (lo, hi) = (w[0], w[1]);
            // Evaluate this span's polynomial even at its end `hi`, where the knot lookup
            // would switch to the next span (a polyline's derivative jumps there).
            let span = c.span(lo);
            let spacing = (hi - lo) / SAMPLES_PER_SPAN as f64;
            let mut start = (f64::INFINITY, lo);
            for k in 0..=SAMPLES_PER_SPAN {
                let u = if k == SAMPLES_PER_SPAN {
                    hi
                } else {
                    lo + k as f64 * spacing
                };
                let d = (c.point_in_span(span, u) - target).norm_squared();
                if d < start.0 {
                    start = (d, u);
                }
            }
            let mut u = start.1;
            for _ in 0..MAX_NEWTON_STEPS {
                *iterations += 1;
                let off = c.point_in_span(span, u) - target;
                let d1 = c.derivative_in_span(span, u);
                let g = off.dot(&d1);
                let dg = d1.norm_squared() + off.dot(&c.second_derivative_in_span(span, u));
                if dg <= 0.0 {
                    break;
                }
                let next = (u - (g / dg).clamp(-spacing, spacing)).clamp(lo, hi);
                let moved = (next - u).abs() * d1.norm();
                u = next;
                if moved <= tolerance {
                    break;
                }
            }
            let d = (c.point_in_span(span, u) - target).norm_squared();
            if d < best.0 {
                best = (d, u, c.derivative_in_span(span, u));
            }
        }
        let (_, u, tangent) = best;
        let [u0, u1] = self.domain();
        Closest {
            u,
            point: Point2::from(self.point(u)),
            tangent,
            at_end: !self.is_closed() && (u <= u0 || u >= u1),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::geometry::CurvePoints;

    fn points() -> Vec<Point2> {
        (0..7)
            .map(|i| {
                let a = i as f64 * 0.9;
                Point2::new(a.cos() * (1.0 + 0.2 * i as f64), a.sin())
            })
            .collect()
    }

    #[test]
    fn the_closest_point_is_the_densest_samples_nearest() {
        // Oracle: the nearest of 4,000 evenly spaced parameters per span, its ends (the
        // polyline's vertices) included.
        for order in 2..=4 {
            for closed in [false, true] {
                for kind in [CurvePoints::Control, CurvePoints::Interpolated] {
                    let curve = Curve::new(&points(), order, closed, kind).unwrap();
                    let ours = PlanarCurve::new(&curve);
                    let samples: Vec<Vector2> = curve
                        .breakpoints()
                        .windows(2)
                        .flat_map(|w| {
                            (0..=4000).map(move |j| w[0] + (w[1] - w[0]) * j as f64 / 4000.0)
                        })
                        .map(|u| curve.point(u).coords)
                        .collect();
                    for k in 0..40 {
                        let a = k as f64 * 0.77;
                        let p = Point2::new(2.5 * a.cos(), 1.8 * a.sin() + 0.1 * k as f64 / 40.0);
                        let found = ours.closest(&p, &mut 0);
                        let got = (found.point - p).norm();
                        let best = samples
                            .iter()
                            .map(|q| (q - p.coords).norm())
                            .fold(f64::INFINITY, f64::min);
                        // Never above the samples' best; below it only by the samples' spacing
                        // squared over the distance (a smooth minimum between two samples).
                        assert!(got <= best + 1e-12, "{order} {closed} {kind:?} {k}");
                        assert!(
                            best - got < 1e-6,
                            "{order} {closed} {kind:?} {k}: {got} {best}"
                        );
                    }
                }
            }
        }
    }
}
