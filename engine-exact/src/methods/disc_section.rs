//! The overlap of a disc of radius `r` about the origin with a polygon whose edges carry
//! labels, in closed form: area, first moments, the circle's arcs inside the polygon (their
//! angle and `∫ν dφ`) and the length of each labelled edge inside the disc.
//!
//! The signed decomposition about the disc's centre: each directed edge `p → q` spans the
//! triangle `(0, p, q)`; its part inside the disc is a triangle where the edge runs inside the
//! circle and a circular sector where it runs outside (the edge's crossings with the circle:
//! a quadratic, solved without cancellation). The signed pieces add up to the overlap for any
//! simple counter-clockwise polygon, convex or not, and the sectors add up to the circle's
//! arcs inside it (arc integrals are additive in the angle). Computed for the unit disc on
//! the vertices divided by `r`, then scaled back, so the crossings see lengths near 1.

use super::section::MAX_LABELS;
use contact_core::Vector2;

/// What the disc and the polygon share.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct DiscSection {
    /// Area.
    pub area: f64,
    /// `∫ p dA`.
    pub moment: Vector2,
    /// `Σ ∫ (cos φ, sin φ) dφ` over the circle's arcs inside the polygon (the outward
    /// normal of the disc integrated over the arcs, per unit of radius).
    pub normal_integral: Vector2,
    /// `Σ (φ₁ − φ₀)` over those arcs.
    pub angle: f64,
    /// Length inside the disc of the polygon's edges, by label (labels past
    /// [`MAX_LABELS`] are not measured).
    pub lengths: [f64; MAX_LABELS],
}

/// One piece of the signed decomposition of the unit disc and a polygon (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Piece {
    /// Edge `edge` starts: how many times it crosses the circle, and whether its start
    /// vertex lies inside the disc.
    Edge {
        /// The edge's index (from vertex `edge` to `edge + 1`).
        edge: usize,
        /// Crossings with the circle strictly inside the edge (0 to 2).
        crossings: usize,
        /// Whether the edge's first vertex lies strictly inside the disc.
        starts_inside: bool,
    },
    /// A stretch `a → e` of edge `edge` inside the disc: the triangle `(0, a, e)`.
    Chord {
        /// The edge's index.
        edge: usize,
        /// Start of the stretch.
        a: Vector2,
        /// End of the stretch.
        e: Vector2,
    },
    /// A stretch outside the disc: the sector of the circle from angle `start` over `sweep`
    /// (signed, `|sweep| < π`).
    Arc {
        /// Start angle.
        start: f64,
        /// Signed angle swept.
        sweep: f64,
    },
}

/// The signed decomposition of the unit disc against the polygon `vertices` multiplied by
/// `scale` (so a disc of radius `1/scale` is seen as the unit disc): every edge's
/// crossings with the circle (a quadratic, solved without cancellation), then its stretches
/// inside the disc as chords and outside as arcs, in order. One walk shared by the overlaps
/// that need different sums of the same pieces.
pub(crate) fn unit_disc_pieces(vertices: &[Vector2], scale: f64, piece: &mut impl FnMut(Piece)) {
    let n = vertices.len();
    for (edge, v) in vertices.iter().enumerate() {
        let p = v * scale;
        let d = vertices[(edge + 1) % n] * scale - p;
        let dd = d.norm_squared();
        if dd == 0.0 {
            continue;
        }
        // |p + λ d|² = 1: dd λ² + 2 b λ + c = 0.
        let b = p.dot(&d);
        let c = p.norm_squared() - 1.0;
        let disc = b * b - dd * c;
        let mut cuts = [0.0, 1.0, 1.0, 1.0];
        let mut m = 1;
        if disc > 0.0 {
            let q_root = -(b + b.signum() * disc.sqrt());
            let mut roots = if q_root != 0.0 {
                [q_root / dd, c / q_root]
            } else {
                [0.0, 0.0]
            };
            roots.sort_by(f64::total_cmp);
            for r in roots {
                if r > 0.0 && r < 1.0 {
                    cuts[m] = r;
                    m += 1;
                }
            }
        }
        piece(Piece::Edge {
            edge,
            crossings: m - 1,
            starts_inside: c < 0.0,
        });
        cuts[m] = 1.0;
        for span in cuts[..=m].windows(2) {
            if span[1] <= span[0] {
                continue;
            }
            let a = p + span[0] * d;
            let e = p + span[1] * d;
            let mid = p + 0.5 * (span[0] + span[1]) * d;
            if mid.norm_squared() < 1.0 {
                piece(Piece::Chord { edge, a, e });
            } else {
                let (a_hat, e_hat) = (a.normalize(), e.normalize());
                let sweep = cross(&a_hat, &e_hat).atan2(a_hat.dot(&e_hat));
                if sweep.is_finite() {
                    let start = a_hat.y.atan2(a_hat.x);
                    piece(Piece::Arc { start, sweep });
                }
            }
        }
    }
}

/// `a × b`, the 2-D cross product.
pub(crate) fn cross(a: &Vector2, b: &Vector2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The overlap of the disc `|p| ≤ radius` with the counter-clockwise polygon `vertices`,
/// edge `k` (from vertex `k` to `k + 1`) labelled `labels[k]`. Empty for `radius ≤ 0` or
/// fewer than three vertices.
pub(crate) fn disc_section(radius: f64, vertices: &[Vector2], labels: &[u8]) -> DiscSection {
    let mut out = DiscSection::default();
    if radius.is_nan() || radius <= 0.0 || vertices.len() < 3 {
        return out;
    }
    unit_disc_pieces(vertices, 1.0 / radius, &mut |piece| match piece {
        Piece::Edge { .. } => {}
        Piece::Chord { edge, a, e } => {
            let twice = cross(&a, &e);
            out.area += 0.5 * twice;
            out.moment += (a + e) * (twice / 6.0);
            let label = labels.get(edge).copied().unwrap_or(u8::MAX) as usize;
            if let Some(l) = out.lengths.get_mut(label) {
                *l += (e - a).norm();
            }
        }
        Piece::Arc { start, sweep } => {
            let end = start + sweep;
            let (s0, c0) = start.sin_cos();
            let (s1, c1) = end.sin_cos();
            out.area += 0.5 * sweep;
            out.moment += Vector2::new(s1 - s0, c0 - c1) / 3.0;
            out.normal_integral += Vector2::new(s1 - s0, c0 - c1);
            out.angle += sweep;
        }
    });
    let r2 = radius * radius;
    out.area *= r2;
    out.moment *= r2 * radius;
    for l in &mut out.lengths {
        *l *= radius;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(half: f64, centre: Vector2) -> [Vector2; 4] {
        [
            centre + Vector2::new(half, -half),
            centre + Vector2::new(half, half),
            centre + Vector2::new(-half, half),
            centre + Vector2::new(-half, -half),
        ]
    }

    /// A square around the whole disc: the disc, its whole circle, no edge inside.
    #[test]
    fn a_square_around_the_disc_gives_the_disc() {
        let s = disc_section(2.0, &square(3.0, Vector2::zeros()), &[0, 1, 2, 3]);
        assert!((s.area - 4.0 * std::f64::consts::PI).abs() < 1e-13, "{s:?}");
        assert!(s.moment.norm() < 1e-13);
        assert!((s.angle - std::f64::consts::TAU).abs() < 1e-14);
        assert!(s.normal_integral.norm() < 1e-14);
        assert!(s.lengths.iter().all(|&l| l == 0.0));
    }

    /// The half-plane `x ≥ 0` (a square's left edge on the y axis): a half disc, centroid at
    /// `4r/(3π)`, the edge's length `2r`, `∫ν dφ = (2, 0)`.
    #[test]
    fn a_half_disc_by_hand() {
        let r = 1.5;
        let v = [
            Vector2::new(5.0, -5.0),
            Vector2::new(5.0, 5.0),
            Vector2::new(0.0, 5.0),
            Vector2::new(0.0, -5.0),
        ];
        let s = disc_section(r, &v, &[0, 1, 2, 3]);
        let area = 0.5 * std::f64::consts::PI * r * r;
        assert!((s.area - area).abs() < 1e-14);
        let x = 4.0 * r / (3.0 * std::f64::consts::PI);
        assert!((s.moment.x / s.area - x).abs() < 1e-14 && s.moment.y.abs() < 1e-14);
        assert!((s.lengths[2] - 2.0 * r).abs() < 1e-14, "{s:?}");
        assert!((s.normal_integral - Vector2::new(2.0, 0.0)).norm() < 1e-14);
        assert!((s.angle - std::f64::consts::PI).abs() < 1e-14);
    }

    /// A non-convex L-shape: the signed sum equals the sum over its two convex halves.
    #[test]
    fn a_non_convex_polygon_is_the_sum_of_its_convex_parts() {
        let l_shape = [
            Vector2::new(-0.3, -0.9),
            Vector2::new(1.2, -0.9),
            Vector2::new(1.2, 0.1),
            Vector2::new(0.2, 0.1),
            Vector2::new(0.2, 1.1),
            Vector2::new(-0.3, 1.1),
        ];
        let whole = disc_section(1.0, &l_shape, &[0; 6]);
        let low = [
            Vector2::new(-0.3, -0.9),
            Vector2::new(1.2, -0.9),
            Vector2::new(1.2, 0.1),
            Vector2::new(-0.3, 0.1),
        ];
        let high = [
            Vector2::new(-0.3, 0.1),
            Vector2::new(0.2, 0.1),
            Vector2::new(0.2, 1.1),
            Vector2::new(-0.3, 1.1),
        ];
        let (a, b) = (
            disc_section(1.0, &low, &[0; 4]),
            disc_section(1.0, &high, &[0; 4]),
        );
        assert!((whole.area - a.area - b.area).abs() < 1e-14);
        assert!((whole.moment - a.moment - b.moment).norm() < 1e-14);
        assert!((whole.angle - a.angle - b.angle).abs() < 1e-14);
        assert!((whole.normal_integral - a.normal_integral - b.normal_integral).norm() < 1e-14);
    }
}
