//! A boundary placed in the plane of the pair's computation, as a chain of cubic arcs lifted
//! from its chords, with its material on the **left** of travel.
//!
//! Each point of the tessellation carries the true unit tangent of the shape,
//! `t = (−n_y, n_x)` from the outward normal `n` (outward is to the right of travel), so the
//! travel order follows from the normals: a flipped boundary, or one whose plane is seen from
//! below (a reflection), runs backwards. Each chord is lifted onto the cubic Hermite arc
//! through its ends with tangents `|chord|·t` there (Bézier control points
//! `p, p + |chord|·t₀/3, q − |chord|·t₁/3, q`): a straight line stays straight, and on a circle
//! of radius `R` a chord of angle `θ` departs by `R·θ²/8` where the arc departs by `O(R·θ⁴)`.
//! The arc is then cut into [`SUBDIVISIONS`] arcs (exactly: the same cubic), whose ends make
//! the chain's polyline — the one crossings and sides are decided on — so that polyline lies
//! within `d/16` of the lifted curve for a tessellation of chord deviation `d`.
//!
//! The chain's *forward parameter* `τ = k + s` names the point at `s ∈ [0, 1]` of arc `k`; a
//! closed chain wraps at `τ = N` (its number of arcs).

use super::boundary::Boundary;
use contact_core::Vector2;

/// How many sub-chords of its Hermite arc replace each chord of the tessellation.
pub const SUBDIVISIONS: usize = 4;

/// A chain of cubic arcs and the polyline of their ends.
#[derive(Debug, Clone, Default)]
pub(crate) struct Chain {
    /// The polyline's points in travel order (each arc's start; an open chain's last point
    /// ends it).
    pub points: Vec<Vector2>,
    /// The Bézier control points of each arc.
    pub arcs: Vec<[Vector2; 4]>,
    /// True when the last point joins the first.
    pub closed: bool,
    /// For an open chain: whether its start and its end are ends of the geometry (false for
    /// the cut ends of an unbounded line, which never close a region).
    pub real_ends: [bool; 2],
}

impl Chain {
    /// Refills the chain with `boundary` under `p ↦ m·p + t` (`m` a rotation or a reflection):
    /// each chord's Hermite arc, cut into [`SUBDIVISIONS`] arcs.
    pub fn fill_placed(&mut self, boundary: &Boundary, m: &nalgebra::Matrix2<f64>, t: &Vector2) {
        self.points.clear();
        self.arcs.clear();
        let normals = boundary.normals();
        let points = boundary.points();
        let count = points.len();
        // The polyline's own order has its outward normal on the right; a flip or a
        // reflection puts it on the left, and the chain then runs backwards.
        let forward = boundary.flip_side() * m.determinant() > 0.0;
        let at = |k: usize| {
            let k = if forward { k } else { count - 1 - k };
            let n = m * normals[k];
            (m * points[k].coords + t, Vector2::new(-n.y, n.x))
        };
        self.closed = boundary.is_closed();
        self.real_ends = [true; 2];
        let chords = match (self.closed, count) {
            (_, 0 | 1) => 0,
            (true, n) => n,
            (false, n) => n - 1,
        };
        for k in 0..chords {
            let ((p, tp), (q, tq)) = (at(k), at((k + 1) % count));
            let third = (q - p).norm() / 3.0;
            let whole = [p, p + third * tp, q - third * tq, q];
            for j in 0..SUBDIVISIONS {
                let s0 = j as f64 / SUBDIVISIONS as f64;
                let s1 = (j + 1) as f64 / SUBDIVISIONS as f64;
                let arc = sub_arc(&whole, s0, s1);
                self.points.push(arc[0]);
                self.arcs.push(arc);
            }
        }
        if !self.closed {
            if let Some(last) = self.arcs.last() {
                let end = last[3];
                self.points.push(end);
            } else if count == 1 {
                self.points.push(at(0).0);
            }
        }
    }

    /// Refills the chain with the x axis over `[x0, x1]` (finite); `real` says which of `x0`,
    /// `x1` are ends of the geometry; `side = −1` when flipped (material at `y ≥ 0`).
    pub fn fill_line(&mut self, x0: f64, x1: f64, real: [bool; 2], side: f64) {
        self.points.clear();
        self.arcs.clear();
        let (p, q) = (Vector2::new(x0, 0.0), Vector2::new(x1, 0.0));
        // Material at y ≤ 0 (outward +y): travel towards −x.
        let (from, to) = if side > 0.0 { (q, p) } else { (p, q) };
        self.real_ends = if side > 0.0 { [real[1], real[0]] } else { real };
        let third = (to - from) / 3.0;
        self.points.extend([from, to]);
        self.arcs.push([from, from + third, to - third, to]);
        self.closed = false;
    }

    /// Number of chords (the period of `τ` when closed).
    pub fn chords(&self) -> usize {
        self.arcs.len()
    }

    /// The number of chords as the end of the parameter range.
    pub fn count(&self) -> f64 {
        self.chords() as f64
    }

    /// The ends of chord `k`.
    pub fn chord(&self, k: usize) -> (Vector2, Vector2) {
        (self.points[k], self.points[(k + 1) % self.points.len()])
    }

    /// The Bézier control points of chord `k`'s arc.
    pub fn arc(&self, k: usize) -> [Vector2; 4] {
        self.arcs[k]
    }

    /// The chord index and local parameter of `τ` (wrapped on a closed chain, clamped on an
    /// open one).
    pub fn locate(&self, tau: f64) -> (usize, f64) {
        let n = self.chords();
        let tau = if self.closed {
            tau.rem_euclid(n as f64)
        } else {
            tau.clamp(0.0, n as f64)
        };
        let k = (tau.floor() as usize).min(n - 1);
        (k, tau - k as f64)
    }

    /// The lifted point at `τ`.
    pub fn point(&self, tau: f64) -> Vector2 {
        let (k, s) = self.locate(tau);
        bezier_point(&self.arc(k), s)
    }

    /// The lifted point and its first and second derivatives in `τ`.
    pub fn jet(&self, tau: f64) -> (Vector2, Vector2, Vector2) {
        let (k, s) = self.locate(tau);
        let c = self.arc(k);
        (
            bezier_point(&c, s),
            bezier_derivative(&c, s),
            bezier_second(&c, s),
        )
    }

    /// Whether `τ` lies in the chain's parameter range (always on a closed chain).
    pub fn holds(&self, tau: f64) -> bool {
        self.closed || (0.0..=self.count()).contains(&tau)
    }

    /// `τ` clamped to an open chain's range (unchanged on a closed chain).
    pub fn clamp(&self, tau: f64) -> f64 {
        if self.closed {
            tau
        } else {
            tau.clamp(0.0, self.count())
        }
    }

    /// Calls `f(arc, s0, s1)` for the lifted stretch from `τ = from` forward by `length`.
    pub fn walk(&self, from: f64, length: f64, mut f: impl FnMut(&[Vector2; 4], f64, f64)) {
        let mut tau = from;
        let mut left = length;
        let n = self.chords();
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
            f(&self.arc(k), s, s + step);
            left -= step;
            tau = k as f64 + s + step;
            if self.closed && tau >= n as f64 {
                tau -= n as f64;
            }
        }
    }

    /// The box `(lo, hi)` of the points.
    pub fn bounding_box(&self) -> (Vector2, Vector2) {
        self.points.iter().fold(
            (
                Vector2::repeat(f64::INFINITY),
                Vector2::repeat(f64::NEG_INFINITY),
            ),
            |(lo, hi), p| (lo.inf(p), hi.sup(p)),
        )
    }

    /// The polyline's own nearest point to `q`: `(chord, s, squared distance)`.
    pub fn polyline_nearest(&self, q: &Vector2) -> Option<(usize, f64, f64)> {
        let mut best: Option<(usize, f64, f64)> = None;
        for k in 0..self.chords() {
            let (a, b) = self.chord(k);
            let e = b - a;
            let ee = e.norm_squared();
            let s = if ee > 0.0 {
                ((q - a).dot(&e) / ee).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let d2 = (q - (a + s * e)).norm_squared();
            if best.is_none_or(|(_, _, b2)| d2 < b2) {
                best = Some((k, s, d2));
            }
        }
        best
    }

    /// The closest point of the lifted chain to `q`: the polyline's nearest point, then Newton
    /// on `(H(τ) − q)·H′(τ)` along the Hermite arcs (kept only where it comes closer).
    /// Returns `(τ, point)`.
    pub fn foot(&self, q: &Vector2, size: f64) -> Option<(f64, Vector2)> {
        let (k, s, _) = self.polyline_nearest(q)?;
        let mut tau = k as f64 + s;
        let start = self.point(tau);
        for _ in 0..MAX_NEWTON_STEPS {
            let (p, d1, d2) = self.jet(tau);
            let c = p - q;
            let g = c.dot(&d1);
            let dg = d1.norm_squared() + c.dot(&d2);
            if dg.is_nan() || dg <= 0.0 {
                break;
            }
            let mut next = tau - g / dg;
            if !self.closed {
                next = next.clamp(0.0, self.count());
            }
            let moved = (next - tau).abs() * d1.norm();
            tau = next;
            if moved <= 1e-15 * size {
                break;
            }
        }
        let p = self.point(tau);
        if (p - q).norm_squared() <= (start - q).norm_squared()
            && (tau - (k as f64 + s)).abs() < 2.0
        {
            Some((tau, p))
        } else {
            Some((k as f64 + s, start))
        }
    }

    /// True when `q` lies strictly inside the polyline's material: on the left of its nearest
    /// point (by the chord's normal, or at a corner by the sum of its two chords' normals), and
    /// not beyond an end of an open chain by more than `1e-9` of `size`.
    pub fn inside(&self, q: &Vector2, size: f64) -> bool {
        let Some((k, s, _)) = self.polyline_nearest(q) else {
            return false;
        };
        let (a, b) = self.chord(k);
        let Some(e) = (b - a).try_normalize(0.0) else {
            return false;
        };
        let right = |e: &Vector2| Vector2::new(e.y, -e.x);
        let foot = a + s * (b - a);
        let offset = q - foot;
        let chords = self.chords();
        let open_start = !self.closed && k == 0 && s == 0.0;
        let open_end = !self.closed && k + 1 == chords && s == 1.0;
        if open_start || open_end {
            let along = if open_start { -e } else { e };
            if offset.dot(&along) > 1e-9 * size {
                return false;
            }
            return offset.dot(&right(&e)) < -1e-12 * size;
        }
        let outward = if s > 0.0 && s < 1.0 {
            right(&e)
        } else {
            let other = if s == 0.0 {
                (k + chords - 1) % chords
            } else {
                (k + 1) % chords
            };
            let (c, d) = self.chord(other);
            right(&e) + right(&(d - c).try_normalize(0.0).unwrap_or(e))
        };
        offset.dot(&outward) < -1e-12 * size
    }
}

/// Newton steps for the closest point on the lifted arcs.
const MAX_NEWTON_STEPS: usize = 12;

/// The restriction of the cubic `c` to `[s0, s1]`, reparametrised over `[0, 1]` (exact: the
/// Hermite form of a cubic's restriction).
fn sub_arc(c: &[Vector2; 4], s0: f64, s1: f64) -> [Vector2; 4] {
    let h = (s1 - s0) / 3.0;
    let (p, q) = (bezier_point(c, s0), bezier_point(c, s1));
    [
        p,
        p + h * bezier_derivative(c, s0),
        q - h * bezier_derivative(c, s1),
        q,
    ]
}

/// The cubic Bézier point at `s`.
pub(crate) fn bezier_point(c: &[Vector2; 4], s: f64) -> Vector2 {
    let r = 1.0 - s;
    c[0] * (r * r * r) + c[1] * (3.0 * r * r * s) + c[2] * (3.0 * r * s * s) + c[3] * (s * s * s)
}

/// The cubic Bézier derivative at `s`.
pub(crate) fn bezier_derivative(c: &[Vector2; 4], s: f64) -> Vector2 {
    let r = 1.0 - s;
    (c[1] - c[0]) * (3.0 * r * r) + (c[2] - c[1]) * (6.0 * r * s) + (c[3] - c[2]) * (3.0 * s * s)
}

/// The cubic Bézier second derivative at `s`.
pub(crate) fn bezier_second(c: &[Vector2; 4], s: f64) -> Vector2 {
    (c[2] - c[1] * 2.0 + c[0]) * (6.0 * (1.0 - s)) + (c[3] - c[2] * 2.0 + c[1]) * (6.0 * s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tessellate::arc_polyline;
    use contact_core::geometry::Arc;

    #[test]
    fn the_foot_is_a_stationary_point_of_the_distance_on_the_lifted_arcs() {
        let arc = Arc::new(1.0, std::f64::consts::TAU).unwrap();
        let boundary = Boundary::new(arc_polyline(&arc, 2.83 / 300.0), false, 2.83);
        let mut chain = Chain::default();
        chain.fill_placed(&boundary, &nalgebra::Matrix2::identity(), &Vector2::zeros());
        for g in [Vector2::new(0.4, 0.1), Vector2::new(-1.3, 0.2)] {
            let (tau, q) = chain.foot(&g, 2.0).unwrap();
            let (_, d1, _) = chain.jet(tau);
            assert!(((q - g).dot(&d1) / d1.norm()).abs() < 1e-12, "{q:?}");
            // On the circle to the lifted arcs' accuracy, near the ray from the centre.
            assert!((q.norm() - 1.0).abs() < 1e-5);
            assert!((q.normalize() - g.normalize()).norm() < 2e-3);
        }
    }
}
