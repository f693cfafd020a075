//! One slice `z = t` of a mesh against the disc `|p| ≤ r`: the mesh's section as directed
//! segments (the mesh inside on their left), clipped by the disc into *chords* and the
//! circle's *crossings*, and the boundary pieces of each part of the overlap.
//!
//! The overlap's boundary is the chords (the mesh surface inside the solid) and the arcs of
//! the circle inside the mesh's section (the solid's surface inside the mesh). Walking the
//! circle counter-clockwise, an arc inside the section starts where a segment leaves the
//! disc (the section lies on its left, which is the counter-clockwise side there) and ends at
//! the next crossing, where one enters. Each piece is summed about the origin (the triangle
//! from the origin for a chord, the sector for an arc), so a part's pieces add up to its area
//! and first moments whatever its shape (Green's theorem).

use contact_core::{Vector2, Vector3};

/// A mesh triangle as the slices see it, in the solid's frame (working units).
#[derive(Debug, Clone, Copy)]
pub(crate) struct SlicedTriangle {
    /// The mesh triangle's index.
    pub index: u32,
    /// Its vertices by height: lowest, middle, highest, with their positions `0..3` in the
    /// triangle (for the edge across which the section continues).
    pub by_height: [(Vector3, u8); 3],
    /// Its outward normal's in-plane part, rotated a quarter turn: the section segment's
    /// direction (the mesh inside on the left).
    pub along: Vector2,
    /// `|n_xy| / |n|`: the triangle's area per unit of height and of segment length.
    pub slope: f64,
    /// The factor from its area here to its area in the caller's space (1 unless the slicing
    /// runs in a linearly mapped space, as for an ellipsoid).
    pub scale: f64,
}

impl SlicedTriangle {
    /// `None` for a triangle parallel to the slices (it meets them only at its height).
    pub fn new(index: u32, v: [Vector3; 3]) -> Option<Self> {
        let n = (v[1] - v[0]).cross(&(v[2] - v[0]));
        let g = n.xy().norm();
        let norm = n.norm();
        // A NaN normal counts as parallel too.
        if g.is_nan() || g <= 1e-14 * norm {
            return None;
        }
        let mut order = [(v[0], 0u8), (v[1], 1), (v[2], 2)];
        order.sort_by(|a, b| a.0.z.total_cmp(&b.0.z));
        if order[0].0.z == order[2].0.z {
            return None;
        }
        Some(Self {
            index,
            by_height: order,
            along: Vector2::new(-n.y, n.x),
            slope: g / norm,
            scale: 1.0,
        })
    }

    /// The lowest and highest heights.
    pub fn range(&self) -> (f64, f64) {
        (self.by_height[0].0.z, self.by_height[2].0.z)
    }

    /// The segment at height `t` (inside the triangle's range), directed with the mesh on its
    /// left: `(start, start's triangle edge, end, end's triangle edge)`, edges numbered as in
    /// the mesh (edge `k` from vertex `k` to `k + 1`).
    pub fn segment(&self, t: f64) -> (Vector2, u8, Vector2, u8) {
        let [(lo, ilo), (mid, imid), (hi, ihi)] = self.by_height;
        let at = |a: &Vector3, b: &Vector3| {
            let s = if b.z == a.z {
                0.5
            } else {
                ((t - a.z) / (b.z - a.z)).clamp(0.0, 1.0)
            };
            (a + (b - a) * s).xy()
        };
        let long = at(&lo, &hi);
        let (short, short_edge) = if t < mid.z {
            (at(&lo, &mid), edge_of(ilo, imid))
        } else {
            (at(&mid, &hi), edge_of(imid, ihi))
        };
        let long_edge = edge_of(ilo, ihi);
        if (short - long).dot(&self.along) >= 0.0 {
            (long, long_edge, short, short_edge)
        } else {
            (short, short_edge, long, long_edge)
        }
    }
}

/// The triangle edge joining vertex positions `a` and `b`.
fn edge_of(a: u8, b: u8) -> u8 {
    if (a + 1) % 3 == b { a } else { b }
}

/// Where a segment meets a circle: its angle, whether it leaves the circle's disc there, and
/// the chord it ends or starts (the slice's index).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Crossing {
    pub angle: f64,
    pub leaves: bool,
    pub chord: usize,
}

/// A segment `p → q` against the circle of radius `r`: the chord inside (if any) as
/// parameters `(λ0, λ1)` along it, and the crossings strictly inside the segment.
pub(crate) fn clip_to_disc(
    p: &Vector2,
    q: &Vector2,
    r: f64,
    mut crossing: impl FnMut(Vector2, bool),
) -> Option<(f64, f64)> {
    let d = q - p;
    let dd = d.norm_squared();
    let c = p.norm_squared() - r * r;
    if dd == 0.0 {
        return None;
    }
    // |p + λ d|² = r²: dd λ² + 2 b λ + c = 0.
    let b = p.dot(&d);
    let disc = b * b - dd * c;
    if disc.is_nan() || disc <= 0.0 {
        return None;
    }
    let root = -(b + b.signum() * disc.sqrt());
    let (mut l0, mut l1) = if root != 0.0 {
        (root / dd, c / root)
    } else {
        (0.0, 0.0)
    };
    if l0 > l1 {
        std::mem::swap(&mut l0, &mut l1);
    }
    if l0 > 0.0 && l0 < 1.0 {
        crossing(p + l0 * d, false);
    }
    if l1 > 0.0 && l1 < 1.0 {
        crossing(p + l1 * d, true);
    }
    let (a, e) = (l0.max(0.0), l1.min(1.0));
    (e > a).then_some((a, e))
}

/// A boundary piece's sums about the origin: `[area, ∫x, ∫y]` of its signed triangle (chord)
/// or sector (arc).
pub(crate) fn chord_moments(a: &Vector2, e: &Vector2) -> [f64; 3] {
    let twice = a.x * e.y - a.y * e.x;
    [
        0.5 * twice,
        (a.x + e.x) * twice / 6.0,
        (a.y + e.y) * twice / 6.0,
    ]
}

/// The arc of radius `r` from `start` over `sweep` (counter-clockwise, ≥ 0): `[area, ∫x, ∫y]`
/// of its sector and `∫(cos φ, sin φ) dφ`.
pub(crate) fn arc_moments(r: f64, start: f64, sweep: f64) -> ([f64; 3], Vector2) {
    let (s0, c0) = start.sin_cos();
    let (s1, c1) = (start + sweep).sin_cos();
    let normal = Vector2::new(s1 - s0, c0 - c1);
    let r3 = r * r * r / 3.0;
    ([0.5 * r * r * sweep, r3 * normal.x, r3 * normal.y], normal)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A wall `x = 0.5` facing +x (mesh at x < 0.5) cut by the unit circle: the segment runs
    /// up (+y), enters the disc at y = −√0.75 and leaves at +√0.75.
    #[test]
    fn a_wall_through_the_disc() {
        let t = SlicedTriangle::new(
            0,
            [
                Vector3::new(0.5, -2.0, -1.0),
                Vector3::new(0.5, 2.0, -1.0),
                Vector3::new(0.5, 0.0, 1.0),
            ],
        )
        .unwrap();
        let (p, _, q, _) = t.segment(-0.5);
        assert!(q.y > p.y, "{p} {q}");
        let mut crossings = Vec::new();
        let chord = clip_to_disc(&p, &q, 1.0, |x, leaves| crossings.push((x, leaves))).unwrap();
        let (a, e) = (p + chord.0 * (q - p), p + chord.1 * (q - p));
        assert!((a - Vector2::new(0.5, -0.75f64.sqrt())).norm() < 1e-15);
        assert!((e - Vector2::new(0.5, 0.75f64.sqrt())).norm() < 1e-15);
        assert_eq!(crossings.len(), 2);
        assert!(!crossings[0].1 && crossings[1].1);
        // The part x < 0.5 of the disc: the chord's triangle and the arc from the leaving
        // crossing counter-clockwise to the entering one.
        let start = e.y.atan2(e.x);
        let sweep = std::f64::consts::TAU - 2.0 * start;
        let area = chord_moments(&a, &e)[0] + arc_moments(1.0, start, sweep).0[0];
        let segment = (0.5f64).acos() - 0.5 * 0.75f64.sqrt();
        assert!(
            (area - (std::f64::consts::PI - segment)).abs() < 1e-14,
            "{area}"
        );
    }
}
