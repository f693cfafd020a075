//! A 2-D boundary (curve, arc or line) as a chain of simple pieces, oriented so that its
//! material lies on the **left** of travel.
//!
//! Each piece is a Bézier segment of degree 1–3 (one polynomial span of a B-spline, or a
//! line) or a circular arc of at most a quarter turn. The chain's *forward parameter*
//! `τ = k + s` names the point at local parameter `s ∈ [0, 1]` of piece `k`; a closed chain
//! wraps at `τ = N` (its number of pieces). The outward normal `tangent × z` (SPEC §2) is the
//! right-hand normal of the forward tangent, so a chain built from an unflipped curve or arc
//! keeps its own direction, a flipped one is reversed, and the unflipped line (material at
//! `y ≤ 0`) runs towards −x.
//!
//! Bounding boxes of the pieces come from the convex hull property (a Bézier segment lies in
//! the hull of its control points; an arc of sweep `σ ≤ π/2` in the triangle of its ends and
//! the meeting point of its end tangents, at `R / cos(σ/2)` from the centre).

use super::curve_eval::PlanarCurve;
use contact_core::Vector2;
use std::f64::consts::FRAC_PI_2;

/// One piece of a chain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Piece {
    /// A Bézier segment; `ctrl[..=degree]` are its control points.
    Bezier {
        /// Control points (unused entries are zero).
        ctrl: [Vector2; 4],
        /// 1, 2 or 3.
        degree: usize,
    },
    /// The arc of the circle (`centre`, `radius`) from angle `from` to angle `to`
    /// (counter-clockwise when `to > from`), `|to − from| ≤ π/2`.
    Arc {
        /// Centre.
        centre: Vector2,
        /// Radius.
        radius: f64,
        /// Start angle (rad).
        from: f64,
        /// End angle (rad).
        to: f64,
    },
}

impl Piece {
    /// A straight segment from `p` to `q`.
    pub fn segment(p: Vector2, q: Vector2) -> Self {
        Self::Bezier {
            ctrl: [p, q, Vector2::zeros(), Vector2::zeros()],
            degree: 1,
        }
    }

    /// The point at `s`.
    pub fn point(&self, s: f64) -> Vector2 {
        match *self {
            Self::Bezier { ctrl, degree } => {
                let mut d = ctrl;
                for r in 1..=degree {
                    for j in 0..=degree - r {
                        d[j] = d[j] * (1.0 - s) + d[j + 1] * s;
                    }
                }
                d[0]
            }
            Self::Arc {
                centre,
                radius,
                from,
                to,
            } => {
                let a = from + s * (to - from);
                centre + radius * Vector2::new(a.cos(), a.sin())
            }
        }
    }

    /// dP/ds at `s`.
    pub fn derivative(&self, s: f64) -> Vector2 {
        match *self {
            Self::Bezier { ctrl, degree } => {
                let mut d = [Vector2::zeros(); 3];
                for j in 0..degree {
                    d[j] = (ctrl[j + 1] - ctrl[j]) * degree as f64;
                }
                Self::Bezier {
                    ctrl: [d[0], d[1], d[2], Vector2::zeros()],
                    degree: degree - 1,
                }
                .point(s)
            }
            Self::Arc {
                radius, from, to, ..
            } => {
                let a = from + s * (to - from);
                radius * (to - from) * Vector2::new(-a.sin(), a.cos())
            }
        }
    }

    /// d²P/ds² at `s`.
    pub fn second_derivative(&self, s: f64) -> Vector2 {
        match *self {
            Self::Bezier { ctrl, degree } => {
                if degree < 2 {
                    return Vector2::zeros();
                }
                let k = (degree * (degree - 1)) as f64;
                let mut d = [Vector2::zeros(); 2];
                for j in 0..degree - 1 {
                    d[j] = (ctrl[j + 2] - 2.0 * ctrl[j + 1] + ctrl[j]) * k;
                }
                Self::Bezier {
                    ctrl: [d[0], d[1], Vector2::zeros(), Vector2::zeros()],
                    degree: degree - 2,
                }
                .point(s)
            }
            Self::Arc {
                radius, from, to, ..
            } => {
                let a = from + s * (to - from);
                let w = to - from;
                -radius * w * w * Vector2::new(a.cos(), a.sin())
            }
        }
    }

    /// The piece restricted to `[s0, s1]` and reparametrised over `[0, 1]`.
    pub fn sub(&self, s0: f64, s1: f64) -> Self {
        match *self {
            Self::Bezier { degree, .. } => {
                // Blossom values: the control points of the restriction.
                let mut ctrl = [Vector2::zeros(); 4];
                for (i, c) in ctrl.iter_mut().enumerate().take(degree + 1) {
                    *c = self.blossom(degree, i, s0, s1);
                }
                Self::Bezier { ctrl, degree }
            }
            Self::Arc {
                centre,
                radius,
                from,
                to,
            } => Self::Arc {
                centre,
                radius,
                from: from + s0 * (to - from),
                to: from + s1 * (to - from),
            },
        }
    }

    /// The blossom of a Bézier segment with `degree − i` arguments `s0` and `i` arguments `s1`.
    fn blossom(&self, degree: usize, i: usize, s0: f64, s1: f64) -> Vector2 {
        let Self::Bezier { ctrl, .. } = *self else {
            return Vector2::zeros();
        };
        let mut d = ctrl;
        for r in 1..=degree {
            let s = if r <= degree - i { s0 } else { s1 };
            for j in 0..=degree - r {
                d[j] = d[j] * (1.0 - s) + d[j + 1] * s;
            }
        }
        d[0]
    }

    /// The same piece run backwards.
    pub fn reversed(&self) -> Self {
        match *self {
            Self::Bezier { ctrl, degree } => {
                let mut r = ctrl;
                for j in 0..=degree {
                    r[j] = ctrl[degree - j];
                }
                Self::Bezier { ctrl: r, degree }
            }
            Self::Arc {
                centre,
                radius,
                from,
                to,
            } => Self::Arc {
                centre,
                radius,
                from: to,
                to: from,
            },
        }
    }

    /// The piece under the affine map `p ↦ m·p + t` (`m` a rotation or a reflection).
    pub fn mapped(&self, m: &nalgebra::Matrix2<f64>, t: &Vector2) -> Self {
        match *self {
            Self::Bezier { ctrl, degree } => {
                let mut c = ctrl;
                for p in c.iter_mut().take(degree + 1) {
                    *p = m * *p + t;
                }
                Self::Bezier { ctrl: c, degree }
            }
            Self::Arc {
                centre,
                radius,
                from,
                to,
            } => {
                let start = m * Vector2::new(from.cos(), from.sin());
                let from_m = start.y.atan2(start.x);
                Self::Arc {
                    centre: m * centre + t,
                    radius,
                    from: from_m,
                    to: from_m + m.determinant().signum() * (to - from),
                }
            }
        }
    }

    /// A box `(lo, hi)` holding the piece.
    pub fn bounding_box(&self) -> (Vector2, Vector2) {
        let mut lo = Vector2::repeat(f64::INFINITY);
        let mut hi = Vector2::repeat(f64::NEG_INFINITY);
        let mut add = |p: Vector2| {
            lo = lo.inf(&p);
            hi = hi.sup(&p);
        };
        match *self {
            Self::Bezier { ctrl, degree } => ctrl.iter().take(degree + 1).for_each(|p| add(*p)),
            Self::Arc {
                centre,
                radius,
                from,
                to,
            } => {
                let half = 0.5 * (to - from);
                let mid = from + half;
                add(self.point(0.0));
                add(self.point(1.0));
                add(centre + radius / half.cos() * Vector2::new(mid.cos(), mid.sin()));
            }
        }
        (lo, hi)
    }
}

/// A chain of pieces with its material on the left.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Chain {
    /// The pieces in forward order.
    pub pieces: Vec<Piece>,
    /// True for a closed boundary (`τ` wraps at `pieces.len()`).
    pub closed: bool,
    /// For an open chain: whether its start and its end are ends of the geometry (false for
    /// the cut ends of an unbounded line, which never close a region).
    pub real_ends: [bool; 2],
}

impl Chain {
    /// The chain of a curve; `side = −1` for a flipped curve.
    pub fn from_curve(curve: &PlanarCurve, side: f64) -> Self {
        let breaks = curve.breakpoints();
        let mut pieces: Vec<Piece> = breaks
            .windows(2)
            .map(|w| span_bezier(curve, w[0], w[1]))
            .collect();
        orient(&mut pieces, side);
        Self {
            pieces,
            closed: curve.is_closed(),
            real_ends: [true; 2],
        }
    }

    /// The chain of an arc of `radius` through `range` rad; `side = −1` when flipped. A full
    /// turn (`range = 2π`) is a closed circle.
    pub fn from_arc(radius: f64, range: f64, side: f64) -> Self {
        let count = (range / FRAC_PI_2).ceil().max(1.0) as usize;
        let step = range / count as f64;
        let mut pieces: Vec<Piece> = (0..count)
            .map(|k| Piece::Arc {
                centre: Vector2::zeros(),
                radius,
                from: k as f64 * step,
                to: if k + 1 == count {
                    range
                } else {
                    (k + 1) as f64 * step
                },
            })
            .collect();
        orient(&mut pieces, side);
        Self {
            pieces,
            closed: range >= std::f64::consts::TAU,
            real_ends: [true; 2],
        }
    }

    /// The chain of the x axis over `[x0, x1]` (finite); `real` says which of `x0`, `x1` are
    /// ends of the geometry; `side = −1` when flipped (material at `y ≥ 0`).
    pub fn from_line(x0: f64, x1: f64, real: [bool; 2], side: f64) -> Self {
        let (p, q) = (Vector2::new(x0, 0.0), Vector2::new(x1, 0.0));
        if side > 0.0 {
            Self {
                pieces: vec![Piece::segment(q, p)],
                closed: false,
                real_ends: [real[1], real[0]],
            }
        } else {
            Self {
                pieces: vec![Piece::segment(p, q)],
                closed: false,
                real_ends: real,
            }
        }
    }

    /// The chain under `p ↦ m·p + t`; a reflection reverses it so its material stays on the
    /// left.
    pub fn mapped(&self, m: &nalgebra::Matrix2<f64>, t: &Vector2) -> Self {
        let mut pieces: Vec<Piece> = self.pieces.iter().map(|p| p.mapped(m, t)).collect();
        let mut real_ends = self.real_ends;
        if m.determinant() < 0.0 {
            orient(&mut pieces, -1.0);
            real_ends.reverse();
        }
        Self {
            pieces,
            closed: self.closed,
            real_ends,
        }
    }

    /// The number of pieces (the period of `τ` when closed).
    pub fn count(&self) -> f64 {
        self.pieces.len() as f64
    }

    /// The piece index and local parameter of `τ`.
    pub fn locate(&self, tau: f64) -> (usize, f64) {
        let n = self.pieces.len();
        let tau = if self.closed {
            tau.rem_euclid(n as f64)
        } else {
            tau.clamp(0.0, n as f64)
        };
        let k = (tau.floor() as usize).min(n - 1);
        (k, tau - k as f64)
    }

    /// The point at `τ`.
    pub fn point(&self, tau: f64) -> Vector2 {
        let (k, s) = self.locate(tau);
        self.pieces[k].point(s)
    }

    /// The box holding the chain.
    pub fn bounding_box(&self) -> (Vector2, Vector2) {
        self.pieces.iter().fold(
            (
                Vector2::repeat(f64::INFINITY),
                Vector2::repeat(f64::NEG_INFINITY),
            ),
            |(lo, hi), p| {
                let (a, b) = p.bounding_box();
                (lo.inf(&a), hi.sup(&b))
            },
        )
    }

    /// Calls `f(k, piece k, s0, s1)` for the stretch from `τ = from` forward by `length`.
    pub fn walk(&self, from: f64, length: f64, mut f: impl FnMut(usize, &Piece, f64, f64)) {
        let mut tau = from;
        let mut left = length;
        let n = self.pieces.len();
        while left > 0.0 {
            let (mut k, mut s) = self.locate(tau);
            if s >= 1.0 && k + 1 < n {
                k += 1;
                s = 0.0;
            }
            let step = (1.0 - s).min(left);
            if step <= 0.0 {
                return;
            }
            f(k, &self.pieces[k], s, s + step);
            left -= step;
            tau = k as f64 + s + step;
            if self.closed && tau >= n as f64 {
                tau -= n as f64;
            }
        }
    }
}

/// Reverses the chain when `side` is negative (a flipped geometry).
fn orient(pieces: &mut [Piece], side: f64) {
    if side < 0.0 {
        pieces.reverse();
        for p in pieces.iter_mut() {
            *p = p.reversed();
        }
    }
}

/// The Bézier form of the curve's polynomial on `[u0, u1]`, from its values at equally
/// spaced parameters (points are continuous at the knots, so the span ends evaluate right).
fn span_bezier(curve: &PlanarCurve, u0: f64, u1: f64) -> Piece {
    let degree = curve.degree();
    let at = |f: f64| curve.point(u0 + f * (u1 - u0));
    let mut ctrl = [Vector2::zeros(); 4];
    match degree {
        1 => {
            ctrl[0] = at(0.0);
            ctrl[1] = at(1.0);
        }
        2 => {
            let (p0, pm, p1) = (at(0.0), at(0.5), at(1.0));
            ctrl[0] = p0;
            ctrl[1] = 2.0 * pm - 0.5 * (p0 + p1);
            ctrl[2] = p1;
        }
        _ => {
            // Inverse of the Bernstein matrix at s = 0, 1/3, 2/3, 1.
            let (p0, pa, pb, p1) = (at(0.0), at(1.0 / 3.0), at(2.0 / 3.0), at(1.0));
            ctrl[0] = p0;
            ctrl[1] = (-5.0 * p0 + 18.0 * pa - 9.0 * pb + 2.0 * p1) / 6.0;
            ctrl[2] = (2.0 * p0 - 9.0 * pa + 18.0 * pb - 5.0 * p1) / 6.0;
            ctrl[3] = p1;
        }
    }
    Piece::Bezier {
        ctrl,
        degree: degree.clamp(1, 3),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::Point2;
    use contact_core::geometry::{Curve, CurvePoints};

    #[test]
    fn bezier_spans_reproduce_the_curve_and_sub_pieces_their_parent() {
        let points: Vec<Point2> = (0..7)
            .map(|i| {
                let a = i as f64 * 0.9;
                Point2::new(a.cos() * (1.0 + 0.2 * i as f64), a.sin())
            })
            .collect();
        for order in 2..=4 {
            for closed in [false, true] {
                let curve = Curve::new(&points, order, closed, CurvePoints::Control).unwrap();
                let planar = PlanarCurve::new(&curve);
                let chain = Chain::from_curve(&planar, 1.0);
                let breaks = planar.breakpoints();
                for (k, w) in breaks.windows(2).enumerate() {
                    for i in 0..=10 {
                        let s = i as f64 / 10.0;
                        let u = w[0] + s * (w[1] - w[0]);
                        let expected = curve.point(u.min(w[1] - 1e-15)).coords;
                        assert!((chain.pieces[k].point(s) - expected).norm() < 1e-12);
                    }
                    let sub = chain.pieces[k].sub(0.25, 0.75);
                    let d = chain.pieces[k].point(0.25 + 0.5 * 0.3) - sub.point(0.3);
                    assert!(d.norm() < 1e-13);
                }
            }
        }
    }

    #[test]
    fn arc_boxes_hold_their_arcs() {
        let chain = Chain::from_arc(2.0, 5.0, 1.0);
        for p in &chain.pieces {
            let (lo, hi) = p.bounding_box();
            for i in 0..=20 {
                let q = p.point(i as f64 / 20.0);
                assert!(q.x >= lo.x - 1e-12 && q.y >= lo.y - 1e-12);
                assert!(q.x <= hi.x + 1e-12 && q.y <= hi.y + 1e-12);
            }
        }
    }
}
