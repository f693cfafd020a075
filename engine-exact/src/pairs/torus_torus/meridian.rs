//! One meridian of torus `a` against torus `b`: the half-plane `H_φ` at azimuth `φ` about
//! `a`'s axis cuts `a` in its tube's disc (radius `ρ_a` about `(R_a, 0)` in `(radial, z)`
//! coordinates), integrated in polar coordinates `(ρ, ψ)` about the disc's centre, `ψ`
//! innermost.
//!
//! The circle of radius `ρ` about the disc's centre `c_φ`, `c_φ + ρ(cos ψ·u_φ + sin ψ·e_z)`,
//! meets `b` where `F = (|q|² + R_b² − ρ_b²)² − 4R_b²(q_x² + q_y²) < 0`, `q` the point in
//! `b`'s frame. Along the circle `|q|²` is of degree one in `(cos ψ, sin ψ)` and
//! `q_x² + q_y²` of degree two, so `F` is a trigonometric form of degree two: its zeros (four
//! at most) come from a quartic in `tan(ψ/2)` ([`trig_roots`]), each polished by Newton's
//! steps on the distance to `b`'s core circle. `F` is that distance's square less `ρ_b²`
//! times a factor positive for a ring torus, so its sign is inside or out. Over each arc
//! inside `b` the integrals in `ψ` are closed forms (the volume element is
//! `x ρ dψ dρ dφ`, `x = R_a + ρ cos ψ` the distance from `a`'s axis):
//! - volume `ρ ∫ x dψ`, radial moment `ρ ∫ x² dψ`, height moment `ρ² ∫ sin ψ · x dψ`;
//! - on the disc's rim `ρ = ρ_a`, `a`'s wall: the element `ρ_a x dψ dφ` with outward normal
//!   `cos ψ·u_φ + sin ψ·e_z`, closed forms over the rim's arcs inside `b`.
//!
//! So the integrand in `ρ` is continuous, with square-root corners where a circle turns
//! tangent to `b`'s section (arcs born or merging). Those radii are cuts, found by sampling
//! the circles' root count and bisecting ([`shape_events`]); one the sampling misses is a
//! corner the adaptive rule halves across (slower, not wrong). A section no sampled circle
//! meets (a sliver inside the disc) is looked for from the meridian gap's minimiser
//! ([`TorusTorus::gap`]).

use crate::methods::ellipsoid_sliced::shape_events;
use crate::methods::sliced::golden_search;
use crate::pairs::revolved_pair::quadric::{trig_roots, wrap};
use crate::pairs::revolved_pair::slice::ADAPTIVE;
use crate::quadrature::MAX_PIECES;
use contact_core::{Matrix3, Vector3, WorkCounters};
use std::f64::consts::{PI, TAU};

/// Components of a meridian's integral: volume, radial moment, height moment, `a`'s wall
/// inside `b` (its radial and axial area vector, its unsigned area).
pub(crate) const MERIDIAN: usize = 6;

/// Components of the integrand in `ρ`: volume, radial and height moments.
const RING: usize = 3;

/// Samples of `b`'s parallels in the search for its tangencies to `a`'s meridian planes.
const TANGENT_SAMPLES: usize = 512;

/// Directions of the coarse search for the gap's minimiser over the tube's disc.
const GAP_DIRECTIONS: usize = 24;

/// Rings of the coarse search (the centre, then `k/GAP_RINGS` of the radius).
const GAP_RINGS: usize = 4;

/// Golden-section steps per coordinate of the fine search: the bracket (about a quarter of
/// the radius) shrinks to about 1e-9 of it.
const GAP_STEPS: usize = 44;

/// Two ring tori in the working frame: `a` about the `z` axis, centred at the origin; `b`
/// centred at `origin`, its frame's axes the rows of `to_b` (a vector `v` of `a`'s frame is
/// `to_b·v` in `b`'s).
#[derive(Debug, Clone, Copy)]
pub(crate) struct TorusTorus {
    /// `a`'s major radius.
    pub big: f64,
    /// `a`'s tube radius.
    pub small: f64,
    /// `b`'s major radius.
    pub b_big: f64,
    /// `b`'s tube radius.
    pub b_small: f64,
    /// `b`'s centre.
    pub origin: Vector3,
    /// `a`'s frame to `b`'s.
    pub to_b: Matrix3,
}

/// One meridian in `b`'s frame: the disc's centre and the two directions spanning it.
struct Meridian {
    centre: Vector3,
    radial: Vector3,
    up: Vector3,
}

/// The arcs of one circle inside `b`: `(start, end)` with `end > start`, at most four.
struct Arcs {
    arcs: [(f64, f64); 4],
    count: usize,
}

impl Arcs {
    /// `∫ (1, cos ψ, sin ψ, cos²ψ, sin ψ cos ψ) dψ` over the arcs.
    fn sums(&self) -> [f64; 5] {
        let mut out = [0.0; 5];
        for &(a, b) in &self.arcs[..self.count] {
            let ((sa, ca), (sb, cb)) = (a.sin_cos(), b.sin_cos());
            out[0] += b - a;
            out[1] += sb - sa;
            out[2] += ca - cb;
            // ∫cos² = ψ/2 + sin ψ cos ψ/2; ∫sin cos = sin²/2.
            out[3] += 0.5 * (b - a) + 0.5 * (sb * cb - sa * ca);
            out[4] += 0.5 * (sb * sb - sa * sa);
        }
        out
    }
}

impl TorusTorus {
    /// The distance to `b`'s core circle less its tube radius (1-Lipschitz, negative inside
    /// `b`), at the point `x` of `a`'s frame.
    pub(crate) fn inside_b(&self, x: &Vector3) -> f64 {
        self.inside_b_local(&(self.to_b * (x - self.origin)))
    }

    /// [`Self::inside_b`] at the point `q` of `b`'s frame.
    fn inside_b_local(&self, q: &Vector3) -> f64 {
        (q.x.hypot(q.y) - self.b_big).hypot(q.z) - self.b_small
    }

    fn meridian(&self, phi: f64) -> Meridian {
        let (s, c) = phi.sin_cos();
        let radial = Vector3::new(c, s, 0.0);
        Meridian {
            centre: self.to_b * (self.big * radial - self.origin),
            radial: self.to_b * radial,
            up: self.to_b * Vector3::z(),
        }
    }

    /// The arcs of the circle of radius `rho` of meridian `m` inside `b`.
    fn arcs(&self, m: &Meridian, rho: f64) -> Arcs {
        let (u, z, q0) = (&m.radial, &m.up, &m.centre);
        let big2 = self.b_big * self.b_big;
        let l = q0.norm_squared() + rho * rho + big2 - self.b_small * self.b_small;
        let (alpha, beta) = (q0.dot(u), q0.dot(z));
        let form = [
            4.0 * rho * rho * (alpha * alpha - big2 * (u.x * u.x + u.y * u.y)),
            4.0 * rho * rho * (alpha * beta - big2 * (u.x * z.x + u.y * z.y)),
            4.0 * rho * rho * (beta * beta - big2 * (z.x * z.x + z.y * z.y)),
            2.0 * rho * (l * alpha - 2.0 * big2 * (q0.x * u.x + q0.y * u.y)),
            2.0 * rho * (l * beta - 2.0 * big2 * (q0.x * z.x + q0.y * z.y)),
            l * l - 4.0 * big2 * (q0.x * q0.x + q0.y * q0.y),
        ];
        let at = |psi: f64| {
            let (s, c) = psi.sin_cos();
            q0 + rho * (c * u + s * z)
        };
        let (mut roots, n) = trig_roots(&form);
        for root in &mut roots[..n] {
            *root = wrap(self.polished(rho, &at, *root, u, z));
        }
        roots[..n].sort_by(f64::total_cmp);
        let mut out = Arcs {
            arcs: [(0.0, 0.0); 4],
            count: 0,
        };
        if n == 0 {
            if self.inside_b_local(&at(0.0)) < 0.0 {
                out.arcs[0] = (-PI, PI);
                out.count = 1;
            }
            return out;
        }
        for k in 0..n {
            let start = roots[k];
            let end = if k + 1 < n {
                roots[k + 1]
            } else {
                roots[0] + TAU
            };
            if end > start && self.inside_b_local(&at(0.5 * (start + end))) < 0.0 && out.count < 4 {
                out.arcs[out.count] = (start, end);
                out.count += 1;
            }
        }
        out
    }

    /// A zero of the circle's form polished by Newton's steps on the distance to `b`'s core
    /// circle less its tube radius: the form's value near its zeros is the difference of
    /// terms near `(R_b + ρ_b)⁴`, whose round-off moves a zero by far more than the
    /// distance's does (the rule in `ρ` would then halve on noise). A step longer than 1e-6
    /// rad (near a tangency, where the distance's slope vanishes) keeps the form's zero.
    fn polished(
        &self,
        rho: f64,
        at: &impl Fn(f64) -> Vector3,
        root: f64,
        u: &Vector3,
        z: &Vector3,
    ) -> f64 {
        let mut psi = root;
        for _ in 0..3 {
            let q = at(psi);
            let w = q.x.hypot(q.y);
            if w == 0.0 {
                return root;
            }
            let v = Vector3::new(q.x - self.b_big * q.x / w, q.y - self.b_big * q.y / w, q.z);
            let d = v.norm();
            let (s, c) = psi.sin_cos();
            let tangent = rho * (c * z - s * u);
            let step = (d - self.b_small) / (v.dot(&tangent) / d);
            if !step.is_finite() || (psi - step - root).abs() > 1e-6 {
                return psi;
            }
            psi -= step;
            if step.abs() <= 4.0 * f64::EPSILON {
                break;
            }
        }
        psi
    }

    /// The integrand in `ρ` of meridian `m` (see [`RING`]).
    fn ring(&self, m: &Meridian, rho: f64) -> [f64; RING] {
        let arcs = self.arcs(m, rho);
        if arcs.count == 0 {
            return [0.0; RING];
        }
        let [one, cos, sin, cos2, sin_cos] = arcs.sums();
        let big = self.big;
        [
            rho * (big * one + rho * cos),
            rho * (big * big * one + 2.0 * big * rho * cos + rho * rho * cos2),
            rho * rho * (big * sin + rho * sin_cos),
        ]
    }

    /// The count of arcs of the circle of radius `rho`, for the cuts in `ρ`.
    fn class(&self, m: &Meridian, rho: f64) -> usize {
        let arcs = self.arcs(m, rho);
        let whole = usize::from(arcs.count == 1 && arcs.arcs[0].1 - arcs.arcs[0].0 >= TAU);
        arcs.count + 8 * whole
    }

    /// The cuts in `ρ` of the meridian at `phi`: `0`, the radii where the arcs change, `ρ_a`;
    /// how many, and whether any circle meets `b`.
    pub(crate) fn cuts(&self, phi: f64) -> ([f64; MAX_PIECES + 1], usize, bool) {
        let m = self.meridian(phi);
        let class = |rho: f64| self.class(&m, rho);
        let mut cuts = [0.0; MAX_PIECES + 1];
        cuts[1] = self.small;
        let mut n = 2;
        shape_events(0.0, self.small, class, &mut cuts, &mut n);
        cuts[..n].sort_by(f64::total_cmp);
        let mut meets = cuts[..n]
            .windows(2)
            .any(|w| w[1] > w[0] && self.arcs(&m, 0.5 * (w[0] + w[1])).count > 0);
        if !meets {
            // A sliver between the sampled circles: bisect about the gap's minimiser.
            let (gap, x, z) = self.gap(phi);
            let rho = (x - self.big).hypot(z);
            if gap < 0.0 && rho < self.small {
                shape_events(0.0, rho, class, &mut cuts, &mut n);
                shape_events(rho, self.small, class, &mut cuts, &mut n);
                cuts[..n].sort_by(f64::total_cmp);
                meets = true;
            }
        }
        (cuts, n, meets)
    }

    /// The outer rule's class of the meridian at `phi`: the class of its rim circle, whose
    /// arcs carry `a`'s wall. Its changes are the corners of the integrand in `φ` where the
    /// section's boundary turns tangent to the rim; the radii where circles about the centre
    /// turn tangent to the section are corners of the polar coordinates only (the section's
    /// moments are smooth across them).
    pub(crate) fn rim_class(&self, phi: f64) -> usize {
        self.class(&self.meridian(phi), self.small)
    }

    /// The azimuths where `b`'s surface is tangent to a meridian half-plane of `a` at a point
    /// inside `a`'s tube: there the section splits or joins, a corner of the integrand in `φ`
    /// that no circle of the rim sees. At such a point `b`'s normal `n` is horizontal and
    /// normal to the point's radial direction: with `b`'s surface at `(θ, χ)`, `n_z = 0`
    /// gives `χ(θ)` (two branches) and `n·x = 0` is a smooth function of `θ`, sampled at
    /// [`TANGENT_SAMPLES`] and its sign changes bisected.
    pub(crate) fn tangent_azimuths(&self) -> Vec<f64> {
        let axes = [0, 1, 2]
            .map(|k| Vector3::new(self.to_b[(k, 0)], self.to_b[(k, 1)], self.to_b[(k, 2)]));
        let (e1, e2, w) = (axes[0], axes[1], axes[2]);
        let point = |theta: f64, branch: f64| {
            let u = theta.cos() * e1 + theta.sin() * e2;
            let chi = (-u.z).atan2(w.z) + branch * PI;
            let (s, c) = chi.sin_cos();
            let normal = c * u + s * w;
            let x = self.origin + (self.b_big + self.b_small * c) * u + self.b_small * s * w;
            (normal.dot(&x), x)
        };
        let mut out = Vec::new();
        for branch in [0.0, 1.0] {
            let value = |theta: f64| point(theta, branch).0;
            let step = TAU / TANGENT_SAMPLES as f64;
            for k in 0..TANGENT_SAMPLES {
                let (mut a, mut b) = (step * k as f64, step * (k + 1) as f64);
                let positive = value(a) > 0.0;
                if positive == (value(b) > 0.0) {
                    continue;
                }
                for _ in 0..60 {
                    let mid = 0.5 * (a + b);
                    if mid <= a || mid >= b {
                        break;
                    }
                    if (value(mid) > 0.0) == positive {
                        a = mid;
                    } else {
                        b = mid;
                    }
                }
                let x = point(0.5 * (a + b), branch).1;
                let in_tube = (x.x.hypot(x.y) - self.big).hypot(x.z) < self.small;
                if in_tube && (x.x != 0.0 || x.y != 0.0) {
                    out.push(x.y.atan2(x.x));
                }
            }
        }
        out
    }

    /// Whether the meridian at `phi` meets `b`.
    pub(crate) fn not_empty(&self, phi: f64) -> bool {
        self.cuts(phi).2
    }

    /// `a`'s wall inside `b` on the meridian `m`: `[S_radial, S_z, area]` per unit of `φ`.
    fn wall(&self, m: &Meridian) -> [f64; 3] {
        let arcs = self.arcs(m, self.small);
        if arcs.count == 0 {
            return [0.0; 3];
        }
        let [one, cos, sin, cos2, sin_cos] = arcs.sums();
        let (big, r) = (self.big, self.small);
        [
            r * (big * cos + r * cos2),
            r * (big * sin + r * sin_cos),
            r * (big * one + r * cos),
        ]
    }

    /// The meridian's integral at `phi` (see [`MERIDIAN`]).
    pub(crate) fn integral(&self, phi: f64, work: &mut WorkCounters) -> [f64; MERIDIAN] {
        let (mut cuts, n, meets) = self.cuts(phi);
        if !meets {
            return [0.0; MERIDIAN];
        }
        let m = self.meridian(phi);
        let (big, small) = (self.big, self.small);
        let floor = |e: &[f64; RING]| {
            let v = (e[0].abs() * 1e-14).max(1e-15 * small * small * big);
            let moment = v * (big + small);
            [v, moment, moment]
        };
        let r =
            ADAPTIVE.integrate_pieces(&mut cuts[..n], &mut |rho| self.ring(&m, rho), &floor, work);
        let w = self.wall(&m);
        [r[0], r[1], r[2], w[0], w[1], w[2]]
    }

    /// The meridian gap `g(φ) = min over a's tube disc of max(h_b, h_tube)` (negative
    /// exactly where `H_φ` meets both solids) and its minimiser `(radial, z)`: the least of a
    /// polar grid over the disc, refined by nested golden sections in a box about it that
    /// reaches every point nearer to it than to the other grid points. `b`'s section need not
    /// be convex, so the grid picks the basin.
    pub(crate) fn gap(&self, phi: f64) -> (f64, f64, f64) {
        let (s, c) = phi.sin_cos();
        let (big, small) = (self.big, self.small);
        let margin = |x: f64, z: f64| {
            let p = Vector3::new(x * c, x * s, z);
            self.inside_b(&p).max((x - big).hypot(z) - small)
        };
        let mut best = (margin(big, 0.0), big, 0.0);
        for ring in 1..=GAP_RINGS {
            let r = small * ring as f64 / GAP_RINGS as f64;
            for k in 0..GAP_DIRECTIONS {
                let psi = TAU * k as f64 / GAP_DIRECTIONS as f64;
                let (x, z) = (big + r * psi.cos(), r * psi.sin());
                let v = margin(x, z);
                if v < best.0 {
                    best = (v, x, z);
                }
            }
        }
        // Every point of the disc lies within `half` of a grid point, and the margin is
        // 1-Lipschitz: a grid minimum above `half` bounds the gap away from zero.
        let half = 0.5 * small / GAP_RINGS as f64 + small * PI / GAP_DIRECTIONS as f64;
        if best.0 > half {
            return best;
        }
        let (x0, z0) = (best.1, best.2);
        let across = |z: f64| golden_search(x0 - half, x0 + half, GAP_STEPS, |x| -margin(x, z));
        let (z, fine) = golden_search(z0 - half, z0 + half, GAP_STEPS, |z| across(z).1);
        let x = across(z).0;
        if -fine < best.0 { (-fine, x, z) } else { best }
    }
}
