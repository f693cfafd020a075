//! A 2-D boundary as a polyline: the signed distance of a point from it, with the closest
//! point and a normal interpolated between the true normals at the chord's ends.

use crate::tessellate::Polyline;
use contact_core::{Point2, Vector2};

/// A tessellated 2-D boundary (circle, arc or curve) with its material on the left of travel
/// (outward normal `tangent × z` to the right), or on the right when flipped.
#[derive(Debug, Clone, PartialEq)]
pub struct Boundary {
    points: Vec<Point2>,
    /// The true outward unit normal at each point, already reversed when flipped.
    normals: Vec<Vector2>,
    closed: bool,
    /// +1, or −1 when flipped (the chords' own normals are reversed with it).
    side: f64,
    /// Distance along the tangent past an open end still counted as "at the end".
    end_tolerance: f64,
}

/// The point of a boundary nearest to a query point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest {
    /// Signed distance: positive outside the material, negative inside.
    pub signed_distance: f64,
    /// The closest point on the polyline.
    pub point: Point2,
    /// The outward unit normal there, interpolated along the chord between the true normals
    /// at its ends (continuous as the query point moves).
    pub normal: Vector2,
}

impl Boundary {
    /// The boundary of `line`, flipped when `flip`; `length` is the geometry's size (open ends
    /// accept query points up to `1e-9·length` past them, as the exact engine does).
    pub fn new(line: Polyline, flip: bool, length: f64) -> Self {
        let side = if flip { -1.0 } else { 1.0 };
        Self {
            normals: line.normals.iter().map(|n| side * n).collect(),
            points: line.points,
            closed: line.closed,
            side,
            end_tolerance: 1e-9 * length,
        }
    }

    /// The polyline's points.
    pub fn points(&self) -> &[Point2] {
        &self.points
    }

    /// The true outward unit normal at each point (reversed when flipped).
    pub fn normals(&self) -> &[Vector2] {
        &self.normals
    }

    /// True for a closed polyline.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// +1, or −1 when flipped (the material on the right of the polyline's travel).
    pub fn flip_side(&self) -> f64 {
        self.side
    }

    /// Number of chords.
    pub fn chords(&self) -> usize {
        match (self.closed, self.points.len()) {
            (_, 0 | 1) => 0,
            (true, n) => n,
            (false, n) => n - 1,
        }
    }

    fn chord(&self, k: usize) -> (Point2, Point2) {
        (self.points[k], self.points[(k + 1) % self.points.len()])
    }

    /// The chord's own outward unit normal (to the right of travel, reversed when flipped).
    fn chord_normal(&self, k: usize) -> Option<Vector2> {
        let (a, b) = self.chord(k);
        let e = b - a;
        Vector2::new(e.y, -e.x)
            .try_normalize(0.0)
            .map(|n| self.side * n)
    }

    /// The nearest point to `p` and the signed distance; `None` when the nearest point is an
    /// open end and `p` lies beyond it along the tangent (no material there).
    ///
    /// The polyline's nearest chord is found first. The answer is then the point `x(t)` of that
    /// chord or a neighbour where the interpolated normal field `n(t) = (1 − t)·n₀ + t·n₁` is
    /// parallel to `p − x(t)` (a quadratic in `t`): the foot of `p` along the normal field,
    /// which moves continuously with `p` (the polyline's own nearest point sticks at convex
    /// corners), and which for a circle's polygon (radial vertex normals) lies exactly on the
    /// ray from the centre through `p`. Without such a foot, the polyline's nearest point.
    pub fn nearest(&self, p: &Point2) -> Option<Nearest> {
        let chords = self.chords();
        let mut best: Option<(f64, usize, f64)> = None;
        for k in 0..chords {
            let (a, b) = self.chord(k);
            let e = b - a;
            let ee = e.norm_squared();
            if ee == 0.0 {
                continue;
            }
            let t = ((p - a).dot(&e) / ee).clamp(0.0, 1.0);
            let d2 = (p - (a + t * e)).norm_squared();
            if best.is_none_or(|(b2, _, _)| d2 < b2) {
                best = Some((d2, k, t));
            }
        }
        let (_, k, t) = best?;
        if self.beyond_open_end(p, k, t) {
            return None;
        }
        let neighbours = [
            Some(k),
            if k > 0 {
                Some(k - 1)
            } else if self.closed {
                Some(chords - 1)
            } else {
                None
            },
            if k + 1 < chords {
                Some(k + 1)
            } else if self.closed {
                Some(0)
            } else {
                None
            },
        ];
        let mut foot: Option<(f64, usize, f64)> = None;
        for kk in neighbours.into_iter().flatten() {
            for tt in self.normal_feet(p, kk).into_iter().flatten() {
                let (a, b) = self.chord(kk);
                let d2 = (p - (a + tt * (b - a))).norm_squared();
                if foot.is_none_or(|(f2, _, _)| d2 < f2) {
                    foot = Some((d2, kk, tt));
                }
            }
        }
        if let Some((_, kk, tt)) = foot {
            let q = self.lifted(kk, tt);
            if let Some(normal) = self.interpolated_normal(kk, tt) {
                return Some(Nearest {
                    signed_distance: (p - q).dot(&normal),
                    point: q,
                    normal,
                });
            }
        }
        self.polyline_nearest(p, k, t)
    }

    /// True when `(k, t)` is an open end and `p` lies beyond it along the tangent.
    fn beyond_open_end(&self, p: &Point2, k: usize, t: f64) -> bool {
        if self.closed {
            return false;
        }
        let last_chord = self.chords() - 1;
        let (a, b) = self.chord(k);
        let e = (b - a).normalize();
        if t == 0.0 && k == 0 {
            (p - a).dot(&-e) > self.end_tolerance
        } else if t == 1.0 && k == last_chord {
            (p - b).dot(&e) > self.end_tolerance
        } else {
            false
        }
    }

    /// `(1 − t)·n_k + t·n_{k+1}`, normalised.
    fn interpolated_normal(&self, k: usize, t: f64) -> Option<Vector2> {
        let next = (k + 1) % self.points.len();
        ((1.0 - t) * self.normals[k] + t * self.normals[next]).try_normalize(0.0)
    }

    /// The parameters `t ∈ [0, 1]` on chord `k` where `p − x(t)` is parallel to the
    /// interpolated normal (on either side of the chord): the roots of
    /// `(w − t·e) × (n₀ + t·m) = 0` with `w = p − a`, `e = b − a`, `m = n₁ − n₀`.
    fn normal_feet(&self, p: &Point2, k: usize) -> [Option<f64>; 2] {
        let (a, b) = self.chord(k);
        let next = (k + 1) % self.points.len();
        let (n0, n1) = (self.normals[k], self.normals[next]);
        let cross = |u: &Vector2, v: &Vector2| u.x * v.y - u.y * v.x;
        let (w, e, m) = (p - a, b - a, n1 - n0);
        // A t² + B t + C = 0.
        let qa = -cross(&e, &m);
        let qb = cross(&w, &m) - cross(&e, &n0);
        let qc = cross(&w, &n0);
        // A foot at a shared corner is a root at t = 1 of one chord and t = 0 of the next;
        // rounding must not push it out of both.
        let inside = |t: f64| {
            (-1e-12..=1.0 + 1e-12)
                .contains(&t)
                .then(|| t.clamp(0.0, 1.0))
        };
        quadratic_roots(qa, qb, qc).map(|t| t.and_then(inside))
    }

    /// The polyline's own nearest point `(k, t)` with the side from the chord (or, at a corner,
    /// the corner's pseudo-normal: the sum of its two chords' normals) and the interpolated
    /// normal.
    fn polyline_nearest(&self, p: &Point2, k: usize, t: f64) -> Option<Nearest> {
        let (a, b) = self.chord(k);
        let q = a + t * (b - a);
        let offset = p - q;
        let chord_normal = self.chord_normal(k)?;
        let n_count = self.points.len();
        let next = (k + 1) % n_count;
        let signed_distance = if t > 0.0 && t < 1.0 {
            offset.dot(&chord_normal)
        } else {
            let vertex = if t == 0.0 { k } else { next };
            let open_end = !self.closed && (vertex == 0 || vertex == n_count - 1);
            let pseudo = if open_end {
                chord_normal
            } else {
                let other = if vertex == k {
                    (k + self.chords() - 1) % self.chords()
                } else {
                    next
                };
                chord_normal + self.chord_normal(other).unwrap_or(chord_normal)
            };
            let d = offset.norm();
            if offset.dot(&pseudo) < 0.0 { -d } else { d }
        };
        let normal = self.interpolated_normal(k, t).unwrap_or(chord_normal);
        Some(Nearest {
            signed_distance,
            point: q,
            normal,
        })
    }

    /// The travel tangent at point `k` scaled for chord `chord_length`, from the true normal
    /// (`n = t × z`, so `t = (−n_y, n_x)`, with the flip undone).
    fn tangent(&self, k: usize, chord_length: f64) -> Vector2 {
        let n = self.normals[k];
        self.side * chord_length * Vector2::new(-n.y, n.x)
    }

    /// The point at parameter `t` of chord `k` lifted onto the cubic Hermite curve through the
    /// chord's ends with the true tangents there (the 2-D counterpart of the PN triangle): it
    /// departs from a circle by `O(R·θ⁴)` for a chord of angle θ, where the chord departs by
    /// `R·θ²/8`.
    pub fn lifted(&self, k: usize, t: f64) -> Point2 {
        let (a, b) = self.chord(k);
        let next = (k + 1) % self.points.len();
        let length = (b - a).norm();
        let (t0, t1) = (self.tangent(k, length), self.tangent(next, length));
        let (t2, t3) = (t * t, t * t * t);
        let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
        let h10 = t3 - 2.0 * t2 + t;
        let h01 = -2.0 * t3 + 3.0 * t2;
        let h11 = t3 - t2;
        Point2::from(h00 * a.coords + h10 * t0 + h01 * b.coords + h11 * t1)
    }

    /// The support of the lifted curve along `direction`: `max x·direction` over the points
    /// and the Hermite arcs on either side of the best point (a closed convex outline's
    /// maximum lies on one of them).
    pub fn support(&self, direction: &Vector2) -> f64 {
        let mut best = (f64::NEG_INFINITY, 0);
        for (k, p) in self.points.iter().enumerate() {
            let h = p.coords.dot(direction);
            if h > best.0 {
                best = (h, k);
            }
        }
        let (mut h, k) = best;
        let chords = self.chords();
        if chords == 0 {
            return h;
        }
        let before = if k > 0 {
            Some(k - 1)
        } else if self.closed {
            Some(chords - 1)
        } else {
            None
        };
        let after = (k < chords).then_some(k);
        for c in [before, after].into_iter().flatten() {
            for t in self.stationary(c, direction).into_iter().flatten() {
                h = h.max(self.lifted(c, t).coords.dot(direction));
            }
        }
        h
    }

    /// Parameters in (0, 1) where `x(t)·d` is stationary on chord `k`'s Hermite arc.
    fn stationary(&self, k: usize, d: &Vector2) -> [Option<f64>; 2] {
        let (a, b) = self.chord(k);
        let next = (k + 1) % self.points.len();
        let length = (b - a).norm();
        let (ad, bd) = (a.coords.dot(d), b.coords.dot(d));
        let (t0, t1) = (
            self.tangent(k, length).dot(d),
            self.tangent(next, length).dot(d),
        );
        let qa = 6.0 * ad + 3.0 * t0 - 6.0 * bd + 3.0 * t1;
        let qb = -6.0 * ad - 4.0 * t0 + 6.0 * bd - 2.0 * t1;
        let qc = t0;
        let inside = |t: f64| (t > 0.0 && t < 1.0).then_some(t);
        quadratic_roots(qa, qb, qc).map(|t| t.and_then(inside))
    }

    /// Heap bytes held.
    pub fn heap_bytes(&self) -> usize {
        self.points.capacity() * std::mem::size_of::<Point2>()
            + self.normals.capacity() * std::mem::size_of::<Vector2>()
    }
}

/// The real roots of `a t² + b t + c`, computed without cancellation; a linear equation when
/// `|a|` is below 1e-14 of `|b|, |c|` (where the quadratic term is round-off).
fn quadratic_roots(a: f64, b: f64, c: f64) -> [Option<f64>; 2] {
    let scale = b.abs().max(c.abs());
    if a.abs() <= 1e-14 * scale.max(f64::MIN_POSITIVE) {
        return [(b != 0.0).then(|| -c / b), None];
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return [None, None];
    }
    let r = -0.5 * (b + b.signum() * disc.sqrt());
    if r == 0.0 {
        [Some(0.0), Some(-b / a)]
    } else {
        [Some(r / a), Some(c / r)]
    }
}
