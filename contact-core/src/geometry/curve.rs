//! B-spline curves (Adams `CURVE`), order 2 to 4, open or closed, from control points or
//! interpolating the given points.
//!
//! # Representation
//! A curve is stored as a B-spline of degree `p = order − 1` with control points `P` and knots
//! `t`, evaluated by de Boor's algorithm on `[t[p], t[len(P)]]`.
//! - **Open, control points:** clamped uniform knots (`p + 1` equal knots at each end), so the
//!   curve starts at the first point and ends at the last.
//! - **Closed, control points:** uniform periodic knots; the first `p` control points are
//!   repeated at the end, so the curve closes with `C^(p−1)` continuity.
//! - **Open, interpolated (`CURVE_POINTS`):** chord-length parameters and knots by averaging
//!   (Piegl & Tiller, *The NURBS Book*, eq. 9.8); the control points solve the collocation system
//!   so the curve passes through every given point.
//! - **Closed, interpolated:** uniform periodic knots; the given points are met at the knots for
//!   odd degree and at span midpoints for even degree (where collocation at knots is singular
//!   for an even number of points), which keeps the cyclic system diagonally dominant.
//!
//! ORDER 2 is a polyline. The collocation system is solved by dense LU once at construction:
//! `O(n³)` in the number of points, about 0.1 s at 1,000 points.
//!
//! # Normal
//! The tangent follows the point order and the binormal is +z of `G`, so the outward normal is
//! `tangent × z = (t_y, −t_x)`: to the right of the direction of travel (SPEC §2).

use crate::error::InvalidArgument;
use crate::{Point2, Vector2};
use nalgebra::DMatrix;

/// How the points of a curve are to be read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CurvePoints {
    /// The points are B-spline control points (Adams default).
    Control,
    /// The points lie on the curve (Adams `CURVE_POINTS`).
    Interpolated,
}

/// A planar B-spline curve in the x-y plane of its geometry frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    order: usize,
    closed: bool,
    control: Vec<Point2>,
    /// The control points as vectors, for allocation-free evaluation.
    coords: Vec<Vector2>,
    knots: Vec<f64>,
    /// Control points of the first derivative (degree p − 1, knots `knots[1..len − 1]`).
    d1: Vec<Vector2>,
    /// Control points of the second derivative (degree p − 2, knots `knots[2..len − 2]`).
    d2: Vec<Vector2>,
}

impl Curve {
    /// Builds a curve from `points` (x, y in `G`), B-spline `order` 2..=4, open or `closed`.
    ///
    /// An open curve needs at least `order` points; a closed one at least `max(order, 3)`, and
    /// its last point must not repeat the first (closure is implied). Interpolated curves need
    /// consecutive points to be distinct.
    pub fn new(
        points: &[Point2],
        order: usize,
        closed: bool,
        kind: CurvePoints,
    ) -> Result<Self, InvalidArgument> {
        if !(2..=4).contains(&order) {
            return Err(InvalidArgument::with_text(
                "ORDER",
                order.to_string(),
                "2, 3 or 4",
            ));
        }
        let needed = if closed { order.max(3) } else { order };
        if points.len() < needed {
            return Err(InvalidArgument::with_text(
                "CURVE points",
                format!("{} points", points.len()),
                format!(
                    "at least {needed} for ORDER = {order}, {}",
                    open_closed(closed)
                ),
            ));
        }
        for p in points {
            for c in p.iter() {
                crate::error::finite("CURVE point coordinate", *c)?;
            }
        }
        let scale = points
            .iter()
            .map(|p| p.coords.norm())
            .fold(0.0, f64::max)
            .max(f64::MIN_POSITIVE);
        let distinct = |a: &Point2, b: &Point2| (a - b).norm() > 1e-14 * scale;
        if closed && !distinct(&points[0], &points[points.len() - 1]) {
            return Err(InvalidArgument::with_text(
                "CURVE points",
                "last point equals the first",
                "distinct points: a CLOSED curve closes itself",
            ));
        }
        let p = order - 1;
        let (control, knots) = match (closed, kind) {
            (false, CurvePoints::Control) => {
                (points.to_vec(), clamped_uniform_knots(points.len(), p))
            }
            (true, CurvePoints::Control) => periodic(points, p),
            (false, CurvePoints::Interpolated) => {
                for (i, w) in points.windows(2).enumerate() {
                    if !distinct(&w[0], &w[1]) {
                        return Err(InvalidArgument::with_text(
                            "CURVE points",
                            format!("points {i} and {} coincide", i + 1),
                            "distinct consecutive points for CURVE_POINTS",
                        ));
                    }
                }
                interpolate_open(points, p)?
            }
            (true, CurvePoints::Interpolated) => interpolate_closed(points, p)?,
        };
        let coords: Vec<Vector2> = control.iter().map(|q| q.coords).collect();
        let d1 = derivative_points(&coords, &knots, p);
        let d2 = if p >= 2 {
            derivative_points(&d1, &knots[1..knots.len() - 1], p - 1)
        } else {
            Vec::new()
        };
        Ok(Self {
            order,
            closed,
            control,
            coords,
            knots,
            d1,
            d2,
        })
    }

    /// The B-spline order (degree + 1), 2..=4.
    pub fn order(&self) -> usize {
        self.order
    }

    /// True for a closed curve.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The control points (for a closed curve, with the first `order − 1` repeated at the end).
    pub fn control_points(&self) -> &[Point2] {
        &self.control
    }

    /// The parameter domain `[u0, u1]`.
    pub fn domain(&self) -> [f64; 2] {
        let p = self.order - 1;
        [self.knots[p], self.knots[self.control.len()]]
    }

    /// The distinct knots inside the domain, ends included: the curve is a polynomial between
    /// consecutive breakpoints.
    pub fn breakpoints(&self) -> Vec<f64> {
        let [u0, u1] = self.domain();
        let mut out: Vec<f64> = Vec::new();
        for &k in &self.knots {
            if k >= u0 && k <= u1 && out.last().is_none_or(|&l| k > l) {
                out.push(k);
            }
        }
        out
    }

    /// The point at parameter `u` (clamped to the domain).
    pub fn point(&self, u: f64) -> Point2 {
        Point2::from(de_boor(
            &self.coords,
            &self.knots,
            self.order - 1,
            self.clamp(u),
        ))
    }

    /// The first derivative dC/du at `u` (clamped to the domain).
    pub fn derivative(&self, u: f64) -> Vector2 {
        de_boor(
            &self.d1,
            &self.knots[1..self.knots.len() - 1],
            self.order - 2,
            self.clamp(u),
        )
    }

    /// The second derivative d²C/du² at `u` (zero for a polyline).
    pub fn second_derivative(&self, u: f64) -> Vector2 {
        if self.order < 3 {
            return Vector2::zeros();
        }
        de_boor(
            &self.d2,
            &self.knots[2..self.knots.len() - 2],
            self.order - 3,
            self.clamp(u),
        )
    }

    /// The knot span holding `u` (clamped to the domain): the index of the polynomial piece
    /// that [`Self::point_in_span`] and its derivatives evaluate. A breakpoint belongs to the
    /// span it starts (the domain's end to the last).
    pub fn span(&self, u: f64) -> usize {
        find_span(
            &self.knots,
            self.order - 1,
            self.coords.len(),
            self.clamp(u),
        )
    }

    /// The point at `u` on the polynomial of knot span `span` (from [`Self::span`]), also for
    /// `u` at or a little past the span's ends (where [`Self::point`] would switch pieces).
    pub fn point_in_span(&self, span: usize, u: f64) -> Vector2 {
        de_boor_in(&self.coords, &self.knots, self.order - 1, span, u)
    }

    /// dC/du at `u` on the polynomial of knot span `span`, as [`Self::point_in_span`].
    pub fn derivative_in_span(&self, span: usize, u: f64) -> Vector2 {
        de_boor_in(
            &self.d1,
            &self.knots[1..self.knots.len() - 1],
            self.order - 2,
            span - 1,
            u,
        )
    }

    /// d²C/du² at `u` on the polynomial of knot span `span` (zero for a polyline), as
    /// [`Self::point_in_span`].
    pub fn second_derivative_in_span(&self, span: usize, u: f64) -> Vector2 {
        if self.order < 3 {
            return Vector2::zeros();
        }
        de_boor_in(
            &self.d2,
            &self.knots[2..self.knots.len() - 2],
            self.order - 3,
            span - 2,
            u,
        )
    }

    /// The outward unit normal at `u`: `tangent × z`, to the right of the direction of travel.
    /// `None` where the derivative vanishes (a cusp from repeated control points).
    pub fn normal(&self, u: f64) -> Option<Vector2> {
        let t = self.derivative(u);
        let n = t.norm();
        (n > 0.0).then(|| Vector2::new(t.y, -t.x) / n)
    }

    fn clamp(&self, u: f64) -> f64 {
        let [u0, u1] = self.domain();
        if u.is_nan() { u0 } else { u.clamp(u0, u1) }
    }
}

fn open_closed(closed: bool) -> &'static str {
    if closed { "CLOSED" } else { "OPEN" }
}

/// Knots `0,…,0, 1, 2, …, n−p−1, n−p,…,n−p` (p + 1 copies at each end).
fn clamped_uniform_knots(n: usize, p: usize) -> Vec<f64> {
    let inner = n - p;
    let mut knots = vec![0.0; p + 1];
    knots.extend((1..inner).map(|i| i as f64));
    knots.extend(std::iter::repeat_n(inner as f64, p + 1));
    knots
}

/// Control points wrapped by `p` and uniform knots `j − p`, domain `[0, n]`.
fn periodic(points: &[Point2], p: usize) -> (Vec<Point2>, Vec<f64>) {
    let n = points.len();
    let control: Vec<Point2> = (0..n + p).map(|i| points[i % n]).collect();
    let knots = (0..control.len() + p + 1)
        .map(|j| j as f64 - p as f64)
        .collect();
    (control, knots)
}

fn find_span(knots: &[f64], p: usize, n_ctrl: usize, u: f64) -> usize {
    if u >= knots[n_ctrl] {
        return n_ctrl - 1;
    }
    let mut lo = p;
    let mut hi = n_ctrl;
    // Invariant: knots[lo] <= u < knots[hi].
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if u < knots[mid] { hi = mid } else { lo = mid }
    }
    lo
}

/// De Boor evaluation of the degree-`p` spline with `ctrl` and `knots` at `u`.
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

/// Basis values `N_{s−p..=s, p}(u)` (Piegl & Tiller A2.2).
fn basis(knots: &[f64], p: usize, s: usize, u: f64) -> [f64; 4] {
    let mut n = [0.0; 4];
    let mut left = [0.0; 4];
    let mut right = [0.0; 4];
    n[0] = 1.0;
    for j in 1..=p {
        left[j] = u - knots[s + 1 - j];
        right[j] = knots[s + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            let denom = right[r + 1] + left[j - r];
            let temp = if denom > 0.0 { n[r] / denom } else { 0.0 };
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    }
    n
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

fn solve(a: DMatrix<f64>, points: &[Point2]) -> Result<Vec<Point2>, InvalidArgument> {
    let n = points.len();
    let mut rhs = DMatrix::<f64>::zeros(n, 2);
    for (i, q) in points.iter().enumerate() {
        rhs[(i, 0)] = q.x;
        rhs[(i, 1)] = q.y;
    }
    let sol = a.lu().solve(&rhs).ok_or_else(|| {
        InvalidArgument::with_text(
            "CURVE_POINTS",
            format!("{n} points"),
            "points that a B-spline can interpolate (the collocation system is singular)",
        )
    })?;
    Ok((0..n)
        .map(|i| Point2::new(sol[(i, 0)], sol[(i, 1)]))
        .collect())
}

fn interpolate_open(
    points: &[Point2],
    p: usize,
) -> Result<(Vec<Point2>, Vec<f64>), InvalidArgument> {
    let n = points.len();
    let chords: Vec<f64> = points.windows(2).map(|w| (w[1] - w[0]).norm()).collect();
    let total: f64 = chords.iter().sum();
    let mut params = vec![0.0; n];
    for i in 1..n {
        params[i] = params[i - 1] + chords[i - 1] / total;
    }
    params[n - 1] = 1.0;
    let mut knots = vec![0.0; p + 1];
    for j in 1..n - p {
        knots.push(params[j..j + p].iter().sum::<f64>() / p as f64);
    }
    knots.extend(std::iter::repeat_n(1.0, p + 1));
    let mut a = DMatrix::<f64>::zeros(n, n);
    for (i, &u) in params.iter().enumerate() {
        let s = find_span(&knots, p, n, u);
        let b = basis(&knots, p, s, u);
        for j in 0..=p {
            a[(i, s + j - p)] = b[j];
        }
    }
    Ok((solve(a, points)?, knots))
}

fn interpolate_closed(
    points: &[Point2],
    p: usize,
) -> Result<(Vec<Point2>, Vec<f64>), InvalidArgument> {
    let n = points.len();
    let (_, knots) = periodic(points, p);
    let offset = if p.is_multiple_of(2) { 0.5 } else { 0.0 };
    let mut a = DMatrix::<f64>::zeros(n, n);
    for i in 0..n {
        let u = i as f64 + offset;
        let s = find_span(&knots, p, n + p, u);
        let b = basis(&knots, p, s, u);
        for j in 0..=p {
            a[(i, (s + j - p) % n)] += b[j];
        }
    }
    let distinct = solve(a, points)?;
    let control = (0..n + p).map(|i| distinct[i % n]).collect();
    Ok((control, knots))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<Point2> {
        vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(0.0, 1.0),
        ]
    }

    #[test]
    fn open_control_curve_starts_and_ends_at_its_end_points() {
        let pts = square();
        for order in 2..=4 {
            let c = Curve::new(&pts, order, false, CurvePoints::Control).unwrap();
            let [u0, u1] = c.domain();
            assert!((c.point(u0) - pts[0]).norm() < 1e-15);
            assert!((c.point(u1) - pts[3]).norm() < 1e-15);
        }
    }

    #[test]
    fn order_two_is_the_polyline() {
        let pts = square();
        let c = Curve::new(&pts, 2, false, CurvePoints::Control).unwrap();
        assert_eq!(c.breakpoints(), vec![0.0, 1.0, 2.0, 3.0]);
        assert!((c.point(0.5) - Point2::new(0.5, 0.0)).norm() < 1e-15);
        assert!((c.point(1.25) - Point2::new(1.0, 0.25)).norm() < 1e-15);
        // Outward normal is to the right of travel: travelling +x, the normal is −y.
        assert!((c.normal(0.5).unwrap() - Vector2::new(0.0, -1.0)).norm() < 1e-15);
    }

    #[test]
    fn interpolated_curves_pass_through_their_points() {
        let pts: Vec<Point2> = (0..9)
            .map(|i| {
                let a = i as f64 * 0.7;
                Point2::new(a.cos() * (1.0 + 0.1 * i as f64), a.sin())
            })
            .collect();
        for order in 2..=4 {
            let c = Curve::new(&pts, order, false, CurvePoints::Interpolated).unwrap();
            let max = pts
                .iter()
                .map(|q| {
                    (0..2001)
                        .map(|k| (c.point(k as f64 / 2000.0) - q).norm())
                        .fold(f64::MAX, f64::min)
                })
                .fold(0.0, f64::max);
            // Sampled distance is bounded by the sampling step; the exact parameters hit exactly:
            assert!(max < 5e-3, "order {order}: {max}");
        }
    }

    #[test]
    fn closed_interpolation_meets_points_at_knots_or_midpoints() {
        let pts: Vec<Point2> = (0..6)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / 6.0;
                Point2::new(2.0 * a.cos(), a.sin())
            })
            .collect();
        for order in 2..=4 {
            let c = Curve::new(&pts, order, true, CurvePoints::Interpolated).unwrap();
            let offset = if (order - 1) % 2 == 0 { 0.5 } else { 0.0 };
            for (i, q) in pts.iter().enumerate() {
                let err = (c.point(i as f64 + offset) - q).norm();
                assert!(err < 1e-13, "order {order} point {i}: {err}");
            }
            // Closed: the curve ends where it starts, with matching tangent for order ≥ 3.
            let [u0, u1] = c.domain();
            assert!((c.point(u0) - c.point(u1)).norm() < 1e-13);
            if order >= 3 {
                assert!((c.derivative(u0) - c.derivative(u1)).norm() < 1e-12);
            }
        }
    }

    #[test]
    fn derivatives_match_central_differences() {
        let pts = vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(3.0, 3.0),
            Point2::new(4.0, 0.5),
            Point2::new(6.0, 1.0),
        ];
        let c = Curve::new(&pts, 4, false, CurvePoints::Control).unwrap();
        for &u in &[0.3, 0.9, 1.4, 1.95] {
            let h = 1e-6;
            let fd = (c.point(u + h) - c.point(u - h)) / (2.0 * h);
            assert!((fd - c.derivative(u)).norm() < 1e-6 * fd.norm().max(1.0));
            let fd2 = (c.derivative(u + h) - c.derivative(u - h)) / (2.0 * h);
            assert!((fd2 - c.second_derivative(u)).norm() < 1e-5 * fd2.norm().max(1.0));
        }
    }

    #[test]
    fn a_span_evaluates_its_own_polynomial_up_to_and_past_its_ends() {
        for order in 2..=4 {
            for closed in [false, true] {
                let curve = Curve::new(&square(), order, closed, CurvePoints::Control).unwrap();
                let [u0, u1] = curve.domain();
                for k in 0..=200 {
                    let u = u0 + (u1 - u0) * k as f64 / 200.0;
                    let s = curve.span(u);
                    assert_eq!(curve.point_in_span(s, u), curve.point(u).coords);
                    assert_eq!(curve.derivative_in_span(s, u), curve.derivative(u));
                    assert_eq!(
                        curve.second_derivative_in_span(s, u),
                        curve.second_derivative(u)
                    );
                }
                // At a span's far end its own polynomial continues: for a polyline the
                // derivative stays the segment's, where `derivative` takes the next one's.
                let breaks = curve.breakpoints();
                let (lo, hi) = (breaks[0], breaks[1]);
                let s = curve.span(lo);
                let inside = curve.derivative(0.5 * (lo + hi));
                let at_end = curve.derivative_in_span(s, hi);
                if order == 2 {
                    assert_eq!(at_end, inside);
                    assert_ne!(curve.derivative(hi), inside);
                }
                let h = 1e-6 * (hi - lo);
                let slope = (curve.point_in_span(s, hi) - curve.point_in_span(s, hi - h)) / h;
                assert!((slope - at_end).norm() < 1e-4 * at_end.norm().max(1.0));
            }
        }
    }

    #[test]
    fn bad_curves_are_rejected_with_the_argument_named() {
        let pts = square();
        let e = Curve::new(&pts, 5, false, CurvePoints::Control).unwrap_err();
        assert_eq!(e.argument, "ORDER");
        let e = Curve::new(&pts[..2], 3, false, CurvePoints::Control).unwrap_err();
        assert!(e.to_string().contains("at least 3"), "{e}");
        let mut dup = pts.clone();
        dup.push(pts[0]);
        let e = Curve::new(&dup, 3, true, CurvePoints::Control).unwrap_err();
        assert!(e.to_string().contains("closes itself"), "{e}");
        let e = Curve::new(
            &[pts[0], pts[0], pts[1]],
            2,
            false,
            CurvePoints::Interpolated,
        )
        .unwrap_err();
        assert!(e.to_string().contains("coincide"), "{e}");
    }
}
