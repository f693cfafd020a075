//! The `t` where the sliced integrand has a kink or a jump, found in closed form so the
//! adaptive rule need not hunt for them: the vertices of the intersection of cylinder `a`
//! with `b` (working frame of [`super::sliced`]).
//!
//! - `a`'s rim circles (`v = ±ℓ`) against each plane of `b`: a line meets a circle;
//! - `b`'s edges (lines or segments) against `a`'s side (a quadratic) and caps (linear);
//! - `b`'s vertices inside `a`;
//! - a second cylinder's rims against `a`'s caps;
//! - two (nearly) parallel cylinders: the corners of the lens their sections make, where
//!   `a`'s side edge and `b`'s, parallel in every slice, pass each other and the length of
//!   each inside the other jumps.
//!
//! Only points on (or within 1e-9 of) both solids are kept: a vertex of one solid outside the
//! other changes nothing in the intersection. A missing event costs halvings, not accuracy.

use super::sliced::{Bound, MAX_B_CUTS, SlicedPair};
use contact_core::{Vector2, Vector3};

/// Slack, in working units, for "on or inside" a solid.
const SLACK: f64 = 1e-9;

impl SlicedPair {
    /// Adds a cut at `t` (ignored when full or not finite).
    pub fn push_cut(&mut self, t: f64) {
        if t.is_finite() && self.cut_count < MAX_B_CUTS {
            self.cuts_b[self.cut_count] = t;
            self.cut_count += 1;
        }
    }

    /// True when `p = (t, u, v)` lies in `a` (within the slack).
    fn in_a(&self, p: &Vector3) -> bool {
        let r = self.radius_a + SLACK;
        p.x * p.x + p.y * p.y <= r * r && p.z.abs() <= self.half_length_a + SLACK
    }

    /// True when `p` lies in `b` (within the slack).
    fn in_b(&self, p: &Vector3) -> bool {
        self.bounds[..self.bound_count].iter().all(|b| match *b {
            Bound::Plane { normal, offset } => normal.dot(p) <= offset + SLACK,
            Bound::Side {
                across,
                centre,
                sign,
                t0,
                radius,
            } => {
                let x = p.x - t0;
                let s = sign * (across.dot(&p.yz()) - centre);
                x * x + s.max(0.0).powi(2) <= (radius + SLACK).powi(2)
            }
        })
    }

    /// `a`'s rim circles against every plane of `b`.
    pub fn add_rim_plane_events(&mut self) {
        let (r, hl) = (self.radius_a, self.half_length_a);
        for k in 0..self.bound_count {
            let Bound::Plane { normal, offset } = self.bounds[k] else {
                continue;
            };
            let g = Vector2::new(normal.x, normal.y);
            let q = g.norm();
            if q == 0.0 {
                continue;
            }
            for v in [hl, -hl] {
                let along = (offset - normal.z * v) / q;
                if along.abs() > r {
                    continue;
                }
                let foot = g * (along / q);
                let chord = ((r - along) * (r + along)).sqrt();
                let dir = Vector2::new(-g.y, g.x) / q;
                for s in [chord, -chord] {
                    let p = foot + s * dir;
                    let point = Vector3::new(p.x, p.y, v);
                    if self.in_b(&point) {
                        self.push_cut(p.x);
                    }
                }
            }
        }
    }

    /// `b`'s vertices inside `a`, and its edges (`origin + s·dir`, `s` in `range`) against
    /// `a`'s side and caps.
    pub fn add_polyhedron_events(&mut self, vertices: &[Vector3], edges: &[(Vector3, Vector3)]) {
        for v in vertices {
            if self.in_a(v) && self.in_b(v) {
                self.push_cut(v.x);
            }
        }
        let (r, hl) = (self.radius_a, self.half_length_a);
        for (origin, dir) in edges {
            // Side: |o.xy + s d.xy|² = r².
            let a = dir.x * dir.x + dir.y * dir.y;
            let b = origin.x * dir.x + origin.y * dir.y;
            let c = origin.x * origin.x + origin.y * origin.y - r * r;
            let disc = b * b - a * c;
            if a > 0.0 && disc >= 0.0 {
                let root = disc.sqrt();
                for s in [(-b - root) / a, (-b + root) / a] {
                    let p = origin + s * dir;
                    if p.z.abs() <= hl + SLACK && self.in_b(&p) {
                        self.push_cut(p.x);
                    }
                }
            }
            // Caps.
            if dir.z != 0.0 {
                for v in [hl, -hl] {
                    let p = origin + ((v - origin.z) / dir.z) * dir;
                    if self.in_a(&p) && self.in_b(&p) {
                        self.push_cut(p.x);
                    }
                }
            }
        }
    }

    /// A second cylinder `b` (centre `centre`, unit axis `axis` in the slicing planes, radius
    /// `radius`, half length `half_length`): its rims against `a`'s caps, and when the axes
    /// are within 1e-3 rad of parallel the lens corners at both ends of `a`.
    pub fn add_cylinder_events(
        &mut self,
        centre: &Vector3,
        axis: &Vector3,
        radius: f64,
        half_length: f64,
    ) {
        let across = Vector3::new(0.0, -axis.z, axis.y);
        for end in [half_length, -half_length] {
            let rim = centre + end * axis;
            // rim + radius (cos φ x̂ + sin φ across), on the plane v = ±ℓ.
            if across.z == 0.0 {
                continue;
            }
            for v in [self.half_length_a, -self.half_length_a] {
                let sin = (v - rim.z) / (radius * across.z);
                if sin.abs() > 1.0 {
                    continue;
                }
                let cos = ((1.0 - sin) * (1.0 + sin)).sqrt();
                for c in [cos, -cos] {
                    let p = rim + radius * (c * Vector3::x() + sin * across);
                    if self.in_a(&p) && self.in_b(&p) {
                        self.push_cut(p.x);
                    }
                }
            }
        }
        // Rims against sides: the zeros of (distance to the other axis)² − r² along each
        // rim, a trigonometric quadratic; bracketed on 64 samples, then bisected.
        let (ra, hla) = (self.radius_a, self.half_length_a);
        for v in [hla, -hla] {
            let rim = |phi: f64| Vector3::new(ra * phi.cos(), ra * phi.sin(), v);
            let gap = |phi: f64| {
                let d = rim(phi) - centre;
                d.norm_squared() - d.dot(axis).powi(2) - radius * radius
            };
            self.add_rim_roots(rim, gap);
        }
        for end in [half_length, -half_length] {
            let rim_centre = centre + end * axis;
            let rim =
                |phi: f64| rim_centre + radius * (phi.cos() * Vector3::x() + phi.sin() * across);
            let gap = |phi: f64| {
                let p = rim(phi);
                p.x * p.x + p.y * p.y - ra * ra
            };
            self.add_rim_roots(rim, gap);
        }
        if axis.z.abs() < 1.0 - 5e-7 {
            return;
        }
        // Lens corners: circles of radius r_a about the origin and r_b about b's axis, in
        // the planes v = ±ℓ (b's section is a circle there to within 1e-6).
        for v in [self.half_length_a, -self.half_length_a] {
            let on_axis = centre + ((v - centre.z) / axis.z) * axis;
            let d = Vector2::new(on_axis.x, on_axis.y);
            let dist = d.norm();
            let (ra, rb) = (self.radius_a, radius);
            if dist == 0.0 || dist >= ra + rb || dist <= (ra - rb).abs() {
                continue;
            }
            let x = (dist * dist + ra * ra - rb * rb) / (2.0 * dist);
            let h = ((ra - x) * (ra + x)).max(0.0).sqrt();
            let (along, normal) = (d / dist, Vector2::new(-d.y, d.x) / dist);
            for s in [h, -h] {
                self.push_cut((x * along + s * normal).x);
            }
        }
    }

    /// Cuts at the zeros of `gap` along the rim `rim(φ)`, kept when the point lies in both
    /// solids.
    fn add_rim_roots(&mut self, rim: impl Fn(f64) -> Vector3, gap: impl Fn(f64) -> f64) {
        const SAMPLES: usize = 64;
        let step = std::f64::consts::TAU / SAMPLES as f64;
        let mut previous = gap(0.0);
        for k in 1..=SAMPLES {
            let (lo, hi) = ((k - 1) as f64 * step, k as f64 * step);
            let current = gap(hi);
            if (previous < 0.0) != (current < 0.0) {
                let (mut a, mut b, mut ga) = (lo, hi, previous);
                for _ in 0..60 {
                    let m = 0.5 * (a + b);
                    let gm = gap(m);
                    if (gm < 0.0) == (ga < 0.0) {
                        a = m;
                        ga = gm;
                    } else {
                        b = m;
                    }
                }
                let p = rim(0.5 * (a + b));
                if self.in_a(&p) && self.in_b(&p) {
                    self.push_cut(p.x);
                }
            }
            previous = current;
        }
    }
}
