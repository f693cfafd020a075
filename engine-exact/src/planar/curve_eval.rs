//! An allocation-free evaluator of a [`Curve`], and the closest point on it.
//!
//! `contact-core`'s [`Curve::point`] builds a temporary vector per call; the query path must
//! not allocate, so [`PlanarCurve`] copies the control points once at prepare time and
//! rebuilds the knot vector from the public breakpoints (clamped ends with `p + 1`-fold knots
//! for open curves, uniform periodic knots for closed ones — exactly the vectors
//! `contact-core` builds). [`PlanarCurve::new`] checks the rebuild against `Curve::point`.
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

/// A curve ready for allocation-free evaluation.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarCurve {
    degree: usize,
    closed: bool,
    control: Vec<Vector2>,
    knots: Vec<f64>,
    d1: Vec<Vector2>,
    d2: Vec<Vector2>,
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
    /// Copies `curve` for evaluation; `None` if its knot vector cannot be rebuilt from the
    /// breakpoints (never for curves `contact-core` builds today; checked, not assumed).
    pub fn new(curve: &Curve) -> Option<Self> {
        let degree = curve.order() - 1;
        let control: Vec<Vector2> = curve.control_points().iter().map(|p| p.coords).collect();
        let breakpoints = curve.breakpoints();
        let knots: Vec<f64> = if curve.is_closed() {
            (0..control.len() + degree + 1)
                .map(|j| j as f64 - degree as f64)
                .collect()
        } else {
            let [u0, u1] = curve.domain();
            let mut k = vec![u0; degree + 1];
            k.extend_from_slice(breakpoints.get(1..breakpoints.len().saturating_sub(1))?);
            k.extend(std::iter::repeat_n(u1, degree + 1));
            k
        };
        if knots.len() != control.len() + degree + 1 {
            return None;
        }
        let d1 = derivative_points(&control, &knots, degree);
        let d2 = if degree >= 2 {
            derivative_points(&d1, &knots[1..knots.len() - 1], degree - 1)
        } else {
            Vec::new()
        };
        let (lo, hi) = control.iter().fold(
            (
                Vector2::repeat(f64::INFINITY),
                Vector2::repeat(f64::NEG_INFINITY),
            ),
            |(lo, hi), p| (lo.inf(p), hi.sup(p)),
        );
        let built = Self {
            degree,
            closed: curve.is_closed(),
            control,
            knots,
            d1,
            d2,
            breakpoints,
            length: (hi - lo).norm(),
        };
        // The rebuilt knots must reproduce contact-core's curve.
        let agrees = built.breakpoints.windows(2).all(|w| {
            let u = 0.5 * (w[0] + w[1]);
            (built.point(u) - curve.point(u).coords).norm()
                <= 1e-12 * built.length.max(f64::MIN_POSITIVE)
        });
        agrees.then_some(built)
    }

    /// The control polygon's bounding-box diagonal.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// The polynomial degree (order − 1).
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// True for a closed curve.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The parameters where the polynomial spans meet, ends included.
    pub fn breakpoints(&self) -> &[f64] {
        &self.breakpoints
    }

    /// The parameter domain.
    pub fn domain(&self) -> [f64; 2] {
        [self.knots[self.degree], self.knots[self.control.len()]]
    }

    fn clamp(&self, u: f64) -> f64 {
        let [u0, u1] = self.domain();
        if self.closed {
            u0 + (u - u0).rem_euclid(u1 - u0)
        } else {
            u.clamp(u0, u1)
        }
    }

    /// The point at `u`.
    pub fn point(&self, u: f64) -> Vector2 {
        de_boor(&self.control, &self.knots, self.degree, self.clamp(u))
    }

    /// dC/du at `u` (the tests hold it to the curve's own derivative).
    #[cfg(test)]
    pub fn derivative(&self, u: f64) -> Vector2 {
        de_boor(
            &self.d1,
            &self.knots[1..self.knots.len() - 1],
            self.degree - 1,
            self.clamp(u),
        )
    }

    /// d²C/du² at `u` (zero for a polyline).
    pub fn second_derivative(&self, u: f64) -> Vector2 {
        if self.degree < 2 {
            return Vector2::zeros();
        }
        de_boor(
            &self.d2,
            &self.knots[2..self.knots.len() - 2],
            self.degree - 2,
            self.clamp(u),
        )
    }

    /// The closest point of the curve to `p`; adds the Newton steps taken to `iterations`.
    ///
    /// Each polynomial span is searched on its own (samples, then Newton kept inside the
    /// span), and the best of the spans' local minima wins: a span's polynomial is smooth, so
    /// Newton there converges, and no minimum is lost at a knot where the curve bends.
    pub fn closest(&self, p: &Point2, iterations: &mut u64) -> Closest {
        let target = p.coords;
        let tolerance = 1e-13 * self.length;
        let mut best = (f64::INFINITY, self.domain()[0], Vector2::zeros());
        for w in self.breakpoints.windows(2) {
            let (lo, hi) = (w[0], w[1]);
            // Evaluate this span's polynomial even at its end `hi`, where the knot lookup
            // would switch to the next span (a polyline's derivative jumps there).
            let span = find_span(&self.knots, self.degree, self.control.len(), lo);
            let spacing = (hi - lo) / SAMPLES_PER_SPAN as f64;
            let mut start = (f64::INFINITY, lo);
            for k in 0..=SAMPLES_PER_SPAN {
                let u = if k == SAMPLES_PER_SPAN {
                    hi
                } else {
                    lo + k as f64 * spacing
                };
                let d = (self.point_in(span, u) - target).norm_squared();
                if d < start.0 {
                    start = (d, u);
                }
            }
            let mut u = start.1;
            for _ in 0..MAX_NEWTON_STEPS {
                *iterations += 1;
                let c = self.point_in(span, u) - target;
                let d1 = self.derivative_in(span, u);
                let g = c.dot(&d1);
                let dg = d1.norm_squared() + c.dot(&self.second_derivative_in(span, u));
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
            let d = (self.point_in(span, u) - target).norm_squared();
            if d < best.0 {
                best = (d, u, self.derivative_in(span, u));
            }
        }
        let (_, u, tangent) = best;
        let [u0, u1] = self.domain();
        Closest {
            u,
            point: Point2::from(self.point(u)),
            tangent,
            at_end: !self.closed && (u <= u0 || u >= u1),
        }
    }

    /// The point at `u` on the polynomial of knot span `span`.
    fn point_in(&self, span: usize, u: f64) -> Vector2 {
        de_boor_in(&self.control, &self.knots, self.degree, span, u)
    }

    /// The derivative at `u` on the polynomial of knot span `span`.
    fn derivative_in(&self, span: usize, u: f64) -> Vector2 {
        de_boor_in(
            &self.d1,
            &self.knots[1..self.knots.len() - 1],
            self.degree - 1,
            span - 1,
            u,
        )
    }

    /// The second derivative at `u` on the polynomial of knot span `span`.
    fn second_derivative_in(&self, span: usize, u: f64) -> Vector2 {
        if self.degree < 2 {
            return Vector2::zeros();
        }
        de_boor_in(
            &self.d2,
            &self.knots[2..self.knots.len() - 2],
            self.degree - 2,
            span - 2,
            u,
        )
    }
}

fn find_span(knots: &[f64], p: usize, n_ctrl: usize, u: f64) -> usize {
    if u >= knots[n_ctrl] {
        return n_ctrl - 1;
    }
    let (mut lo, mut hi) = (p, n_ctrl);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if u < knots[mid] { hi = mid } else { lo = mid }
    }
    lo
}

fn de_boor(ctrl: &[Vector2], knots: &[f64], p: usize, u: f64) -> Vector2 {
    de_boor_in(ctrl, knots, p, find_span(knots, p, ctrl.len(), u), u)
}

/// De Boor's algorithm on the polynomial of knot span `s` (valid for `u` in or near it).
fn de_boor_in(ctrl: &[Vector2], knots: &[f64], p: usize, s: usize, u: f64) -> Vector2 {
    let mut d = [Vector2::zeros(); 4];
    d[..=p].copy_from_slice(&ctrl[s - p..=s]);
    for r in 1..=p {
        for j in (r..=p).rev() {
            let i = s + j - p;
            let denom = knots[i + p + 1 - r] - knots[i];
            let alpha = if denom > 0.0 {
                (u - knots[i]) / denom
            } else {
                0.0
            };
            d[j] = d[j - 1] * (1.0 - alpha) + d[j] * alpha;
        }
    }
    d[p]
}

fn derivative_points(ctrl: &[Vector2], knots: &[f64], p: usize) -> Vec<Vector2> {
    (0..ctrl.len() - 1)
        .map(|i| {
            let denom = knots[i + p + 1] - knots[i + 1];
            if denom > 0.0 {
                (ctrl[i + 1] - ctrl[i]) * (p as f64 / denom)
            } else {
                Vector2::zeros()
            }
        })
        .collect()
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
    fn the_rebuilt_curve_matches_contact_core_for_every_kind() {
        for order in 2..=4 {
            for closed in [false, true] {
                for kind in [CurvePoints::Control, CurvePoints::Interpolated] {
                    let curve = Curve::new(&points(), order, closed, kind).unwrap();
                    let ours = PlanarCurve::new(&curve).unwrap();
                    let [u0, u1] = curve.domain();
                    // u1 itself is left out: a closed curve wraps it to u0, where a polyline's
                    // derivative jumps (C⁰), while contact-core clamps it.
                    for k in 0..100 {
                        let u = u0 + (u1 - u0) * k as f64 / 100.0;
                        assert!((ours.point(u) - curve.point(u).coords).norm() < 1e-13);
                        assert!((ours.derivative(u) - curve.derivative(u)).norm() < 1e-12);
                    }
                }
            }
        }
    }
}
