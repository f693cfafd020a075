//! Characterization rows of a circle against a bounded 2-D line, with an oracle written here
//! by vertical slices: the disc `u² + v² ≤ r²` (centred frame) cut by the line's half-strip
//! `a ≤ u ≤ b, v ≤ k` is, at each `u`, the slice `−w(u) ≤ v ≤ min(k, w(u))`,
//! `w = √(r² − u²)`; area and first moments are integrals of those slices, in closed form
//! through `∫w du = ½(u w + r² atan2(u, w))`, `∫u w du = −w³/3` and `∫w² du = r²u − u³/3`
//! on the pieces of `[a, b]` where the line caps the slice or not. The circle's outward normal
//! integrated over the region's arcs comes from the two graphs `v = ∓w(u)`:
//! `∫(−w′, ∓1)…` in closed form, `(w(u₁) − w(u₂), −(u₂ − u₁))` for the lower one. The engine
//! works instead from the outline: polygon fans and circular segments, and `S_a` from the
//! lengths of the verticals through the ends.
//!
//! From those, the contact as `engine_exact::planar::circle_bounded_line` defines it:
//! `S = ½(S_a − (0, W))`, `W` the region's width along the line; `n = −S/|S|`; the points
//! where the line through the centroid along `n` meets the circle (along `−n`) and the line
//! (along `+n`, clamped to its range); δ their distance.

use super::{Case, Row, SAMPLES, run};
use crate::common::{Expected, Rng, instance};
use contact_core::geometry::{Circle, Line};
use contact_core::{Geometry, Isometry3, Point3, Vector2, Vector3};

/// The oracle's region and contact, in the frame centred on the circle with the material
/// below `v = k`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Strip {
    pub(crate) area: f64,
    pub(crate) centroid: Vector2,
    pub(crate) normal: Vector2,
    pub(crate) on_circle: Vector2,
    pub(crate) on_line: Vector2,
}

impl Strip {
    pub(crate) fn depth(&self) -> f64 {
        (self.on_line - self.on_circle).norm()
    }

    /// The expected contact of circle I (centre `(x, y)` in the line's frame, the line J at
    /// the identity) against the line whose material lies at `side·y ≤ 0`.
    pub(crate) fn expected(&self, x: f64, y: f64, side: f64) -> Expected {
        let back = |p: Vector2| Point3::new(x + p.x, y + side * p.y, 0.0);
        Expected {
            point_i: back(self.on_circle),
            point_j: back(self.on_line),
            normal: Vector3::new(self.normal.x, side * self.normal.y, 0.0),
            depth: self.depth(),
        }
    }
}

/// The disc of radius `r` about the origin against the strip `a ≤ u ≤ b, v ≤ k`, by
/// vertical slices; `None` without area.
pub(crate) fn disc_in_strip(r: f64, k: f64, a: f64, b: f64) -> Option<Strip> {
    let (lo, hi) = (a.max(-r), b.min(r));
    if k <= -r || lo >= hi {
        return None;
    }
    let w = |u: f64| ((r - u) * (r + u)).max(0.0).sqrt();
    let f = |u: f64| 0.5 * (u * w(u) + r * r * u.atan2(w(u)));
    let g = |u: f64| -w(u).powi(3) / 3.0;
    let h = |u: f64| r * r * u - u.powi(3) / 3.0;
    // Where the line meets the circle: the slices are capped by the line inside ±u_k.
    let u_k = if k.abs() < r { w(k) } else { 0.0 };
    let mut cuts = vec![lo, hi];
    for c in [-u_k, u_k] {
        if c > lo && c < hi {
            cuts.push(c);
        }
    }
    cuts.sort_by(f64::total_cmp);
    let (mut area, mut mu, mut mv) = (0.0, 0.0, 0.0);
    let mut s_a = Vector2::zeros();
    let mut width = 0.0;
    for span in cuts.windows(2) {
        let (u1, u2) = (span[0], span[1]);
        let capped = k.abs() < r && (0.5 * (u1 + u2)).abs() < u_k;
        if capped {
            // Slice [−w, k].
            area += k * (u2 - u1) + f(u2) - f(u1);
            mu += 0.5 * k * (u2 * u2 - u1 * u1) + g(u2) - g(u1);
            mv += 0.5 * (k * k * (u2 - u1) - (h(u2) - h(u1)));
            s_a += Vector2::new(w(u1) - w(u2), -(u2 - u1));
            width += u2 - u1;
        } else if k >= 0.0 {
            // The whole chord [−w, w]: both graphs bound the region.
            area += 2.0 * (f(u2) - f(u1));
            mu += 2.0 * (g(u2) - g(u1));
            s_a += Vector2::new(2.0 * (w(u1) - w(u2)), 0.0);
            width += u2 - u1;
        }
    }
    if area <= 0.0 {
        return None;
    }
    let centroid = Vector2::new(mu, mv) / area;
    let s = 0.5 * (s_a - Vector2::new(0.0, width));
    let normal = -s / s.norm();
    let gn = centroid.dot(&normal);
    let back = gn + (r * r - centroid.norm_squared() + gn * gn).sqrt();
    let reach = (k - centroid.y) / normal.y;
    Some(Strip {
        area,
        centroid,
        normal,
        on_circle: centroid - back * normal,
        on_line: Vector2::new((centroid.x + reach * normal.x).clamp(a, b), k),
    })
}

/// The line over `[x0, x1]` (the unbounded line when both are infinite).
pub(crate) fn line(x0: f64, x1: f64) -> Geometry {
    Geometry::Line(Line::bounded(x0, x1).unwrap())
}

/// A circle with a bounded line's end over it: radius, centre, range, side. Either end may be
/// the one over the disc; the other is infinite, finite beyond the disc, or over it too.
pub(crate) fn end_over_disc(rng: &mut Rng) -> (f64, [f64; 2], [f64; 2], f64) {
    let r = rng.uniform(0.5, 2.0);
    let x = rng.uniform(-3.0, 3.0);
    let side = if rng.uniform(0.0, 1.0) < 0.5 {
        1.0
    } else {
        -1.0
    };
    let height = rng.uniform(-0.8, 0.8) * r;
    let x0 = x + rng.uniform(-0.95, 0.95) * r;
    let x1 = match (rng.uniform(0.0, 3.0) as usize).min(2) {
        0 => f64::INFINITY,
        1 => x0 + rng.uniform(0.2, 1.5) * r,
        _ => x + rng.uniform(1.05, 3.0) * r,
    };
    // Mirrored about the centre half the time, so XMAX is the end over the disc.
    let range = if rng.uniform(0.0, 1.0) < 0.5 {
        [x0, x1]
    } else {
        [2.0 * x - x1, 2.0 * x - x0]
    };
    (r, [x, side * height], range, side)
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        run(
            rng,
            SAMPLES,
            "circle–bounded line (2-D)",
            "r ∈ [0.5, 2], centre height ∈ (−0.8r, 0.8r), an end over the disc (either, the other infinite or finite), flipped or not, region ≥ 0.02r²",
            "disc ∩ half-strip by vertical slices",
            |rng| {
                let (r, [x, y], range, side) = end_over_disc(rng);
                let strip = disc_in_strip(r, -side * y, range[0] - x, range[1] - x)?;
                if strip.area < 0.02 * r * r {
                    return None;
                }
                let j = instance(line(range[0], range[1]));
                Some(Case {
                    i: instance(Geometry::Circle(Circle::new(r).unwrap())),
                    j: if side < 0.0 { j.flipped() } else { j },
                    pose_i: Isometry3::translation(x, y, 0.0),
                    pose_j: Isometry3::identity(),
                    expected: strip.expected(x, y, side),
                    length: r,
                })
            },
        ),
        run(
            rng,
            SAMPLES,
            "circle–bounded line (2-D)",
            "range covering the disc's span (ends 0 to 2r beyond it), centre height ∈ (−1.2r, r)",
            "the unbounded line's closed form",
            |rng| {
                let r = rng.uniform(0.5, 2.0);
                let (x, d) = (rng.uniform(-3.0, 3.0), rng.uniform(-1.2 * r, r));
                let x0 = x - r - rng.uniform(0.0, 2.0) * r;
                let x1 = x + r + rng.uniform(0.0, 2.0) * r;
                Some(Case {
                    i: instance(Geometry::Circle(Circle::new(r).unwrap())),
                    j: instance(line(x0, x1)),
                    pose_i: Isometry3::translation(x, d, 0.0),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::new(x, d - r, 0.0),
                        point_j: Point3::new(x, 0.0, 0.0),
                        normal: Vector3::y(),
                        depth: r - d,
                    },
                    length: r,
                })
            },
        ),
    ]
}

#[test]
fn the_oracle_cuts_a_quarter_and_a_half_disc_by_hand() {
    use std::f64::consts::PI;
    let r = 1.3;
    // Centre on the end, at the line: the quarter below and right, centroid (4r/3π)(1, −1).
    let q = disc_in_strip(r, 0.0, 0.0, f64::INFINITY).unwrap();
    let c = 4.0 * r / (3.0 * PI);
    assert!((q.area - 0.25 * PI * r * r).abs() < 1e-14, "{q:?}");
    assert!((q.centroid - Vector2::new(c, -c)).norm() < 1e-14, "{q:?}");
    // Sunk below the line, centre on the end: the right half, centroid (4r/3π, 0).
    let h = disc_in_strip(r, 2.0 * r, 0.0, f64::INFINITY).unwrap();
    assert!((h.area - 0.5 * PI * r * r).abs() < 1e-14, "{h:?}");
    assert!((h.centroid - Vector2::new(c, 0.0)).norm() < 1e-14, "{h:?}");
}
