//! Two cylinders with exactly parallel (or opposite) axes, in closed form: the intersection
//! is the lens where their discs overlap times the overlap of their axial ranges.
//!
//! In `a`'s frame (axis +z, discs centred on the axis, `0 ≤ z ≤ L_a`) `b`'s disc is centred
//! at distance `d` along the unit `u` and spans `[z_0, z_1]`. With `H` the axial overlap:
//! - **Lens.** For `|r_a − r_b| < d < r_a + r_b`, the chord's half-length is
//!   `h = √((r_a + r_b − d)(d + r_a − r_b)(d − r_a + r_b)(r_a + r_b + d))/(2d)` (each factor
//!   formed from the inputs, so a grazing overlap keeps its digits), its distance from `a`'s
//!   centre `x_a = (d² + r_a² − r_b²)/(2d)`, and the half-angles `α_a = atan2(h, x_a)`,
//!   `α_b = atan2(h, d − x_a)`. Area `A = r_a² f(α_a) + r_b² f(α_b)`, `f(α) = α − sin α cos α`
//!   (`segment_area_factor`: by its series below 1/2, where the difference cancels). Each
//!   segment's first moment about its own centre is `⅔h³` (`r sin α = h`), towards the other
//!   centre, so the lens's first moment about `a`'s centre is `d` times `b`'s segment:
//!   centroid `d·r_b² f(α_b)/A` along `u`. One disc inside the other (`d ≤ |r_a − r_b|`)
//!   gives the smaller disc.
//! - **Volume** `A·H`; **centroid** the lens's, at mid-overlap.
//! - **`a`'s surface inside `b`** (for the normal, [`super::volume_contact`]): its side's arc
//!   inside `b`, area vector `2hH·u` (none, or the whole circle summing to zero, when a disc
//!   holds the other), and each of its caps within `b`'s range, `±A·ẑ`. A cap or side that
//!   coincides with one of `b`'s counts half to each body: the mean of the limits of a
//!   vanishing tilt or offset one way and the other (the answer jumps there with their
//!   direction), and it keeps `S_a = −S_b` (the intersection's closed surface), so
//!   exchanging the bodies exchanges the contact.
//!
//! Touching (no overlap of discs or of ranges) is no contact.

use super::sliced::SlicedMoments;
use contact_core::{Vector2, Vector3};
use std::f64::consts::PI;

/// `b` as `a`'s frame sees it (lengths in the working unit): its disc's centre, radius, and
/// axial range.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ParallelB {
    /// Centre of `b`'s disc in `a`'s xy plane.
    pub centre: Vector2,
    /// Radius.
    pub radius: f64,
    /// Axial range `[z_0, z_1]` in `a`'s frame.
    pub range: (f64, f64),
}

/// The overlap of two discs: area, centroid along `u` from `a`'s centre, and the parts of
/// each rim inside the other disc (area vector of `a`'s arc per unit height, and each arc's
/// length; both whole rims for the same disc).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Lens {
    area: f64,
    centroid: f64,
    arc_vector_a: f64,
    arc_a: f64,
    arc_b: f64,
}

/// The lens of discs of radii `ra`, `rb` with centres `d ≥ 0` apart, or `None` when they do
/// not overlap with positive area.
fn lens(ra: f64, rb: f64, d: f64) -> Option<Lens> {
    if d >= ra + rb {
        return None;
    }
    if d == 0.0 && ra == rb {
        // The same disc: each rim lies on the other (the caller counts half to each body).
        return Some(Lens {
            area: PI * ra * ra,
            centroid: 0.0,
            arc_vector_a: 0.0,
            arc_a: 2.0 * PI * ra,
            arc_b: 2.0 * PI * rb,
        });
    }
    if d + ra <= rb {
        return Some(Lens {
            area: PI * ra * ra,
            centroid: 0.0,
            arc_vector_a: 0.0,
            arc_a: 2.0 * PI * ra,
            arc_b: 0.0,
        });
    }
    if d + rb <= ra {
        return Some(Lens {
            area: PI * rb * rb,
            centroid: d,
            arc_vector_a: 0.0,
            arc_a: 0.0,
            arc_b: 2.0 * PI * rb,
        });
    }
    let product = (ra + rb - d) * (d + ra - rb) * (d - ra + rb) * (ra + rb + d);
    let h = product.max(0.0).sqrt() / (2.0 * d);
    let x_a = ((d - rb) * (d + rb) + ra * ra) / (2.0 * d);
    let (alpha_a, alpha_b) = (h.atan2(x_a), h.atan2(d - x_a));
    let (segment_a, segment_b) = (
        ra * ra * segment_area_factor(alpha_a),
        rb * rb * segment_area_factor(alpha_b),
    );
    let area = segment_a + segment_b;
    if area.is_nan() || area <= 0.0 {
        return None;
    }
    Some(Lens {
        area,
        centroid: d * segment_b / area,
        arc_vector_a: 2.0 * h,
        arc_a: 2.0 * alpha_a * ra,
        arc_b: 2.0 * alpha_b * rb,
    })
}

/// `α − sin α cos α` (twice a unit disc's segment of half-angle `α`), by its series
/// `Σ_{k≥1} (−1)^{k+1} (2α)^{2k+1} / (2·(2k+1)!)` below `α = ½`, where the difference
/// cancels (it is `⅔α³` at small `α`); each term is at most 1/20 of the one before.
pub(crate) fn segment_area_factor(alpha: f64) -> f64 {
    if alpha >= 0.5 {
        let (s, c) = alpha.sin_cos();
        return alpha - s * c;
    }
    let x = 2.0 * alpha;
    let x2 = x * x;
    let (mut term, mut sum) = (x * x2 / 12.0, 0.0f64);
    let mut k = 1.0f64;
    while term.abs() > 1e-18 * sum.abs() {
        sum += term;
        term *= -x2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
        k += 1.0;
    }
    sum
}

/// The share of a cap at height `z` of one body inside the other's axial range `(lo, hi)`:
/// 1 strictly inside, ½ on an end (the caps coincide), 0 outside.
pub(crate) fn cap_share(z: f64, (lo, hi): (f64, f64)) -> f64 {
    if z > lo && z < hi {
        1.0
    } else if z == lo || z == hi {
        0.5
    } else {
        0.0
    }
}

/// A section across the axis of two solids whose intersection is a prism along it (a
/// parallel cylinder's lens, an aligned box's part of the disc; lengths in the working unit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Section {
    /// Area.
    pub area: f64,
    /// First moment about the cylinder's axis.
    pub moment: Vector2,
    /// Area vector of the cylinder's rim inside the other solid, per unit height.
    pub rim_vector: Vector2,
    /// Length of that rim.
    pub rim_length: f64,
    /// Length of the other solid's boundary inside the cylinder's disc.
    pub other_length: f64,
}

/// The overlap of the cylinder's axial range `[0, len]` with `range`, or `None` when it has
/// no length.
pub(crate) fn axial_overlap(len: f64, range: (f64, f64)) -> Option<(f64, f64)> {
    let (z0, z1) = (range.0.max(0.0), range.1.min(len));
    (z1 - z0 > 0.0).then_some((z0, z1))
}

/// The moments of the prism of `section` over the axial `overlap` (from [`axial_overlap`])
/// of the cylinder (length `len`) and a solid spanning `range`, in the slicing pairs' working
/// frame (the cylinder's axes, origin at its centre). Caps and end faces within the other's
/// range count by [`cap_share`].
pub(crate) fn extrude(
    section: &Section,
    len: f64,
    range: (f64, f64),
    (z0, z1): (f64, f64),
) -> SlicedMoments {
    let height = z1 - z0;
    let (bottom_a, top_a) = (cap_share(0.0, range), cap_share(len, range));
    let (bottom_b, top_b) = (
        cap_share(range.0, (0.0, len)),
        cap_share(range.1, (0.0, len)),
    );
    let centroid = section.moment / section.area;
    let side = section.rim_vector * height;
    SlicedMoments {
        volume: section.area * height,
        centroid: Vector3::new(centroid.x, centroid.y, 0.5 * (z0 + z1) - 0.5 * len),
        area_vector_a: Vector3::new(side.x, side.y, (top_a - bottom_a) * section.area),
        area_a: section.rim_length * height + (bottom_a + top_a) * section.area,
        area_b: section.other_length * height + (bottom_b + top_b) * section.area,
    }
}

/// The intersection's moments for cylinder `a` (radius `ra`, length `la`, working unit
/// lengths) and `b`, in the slicing pairs' working frame: `a`'s axes, origin at `a`'s centre.
/// `None` when the discs or the axial ranges do not overlap.
pub(crate) fn moments(ra: f64, la: f64, b: &ParallelB) -> Option<SlicedMoments> {
    let overlap = axial_overlap(la, b.range)?;
    let d = b.centre.norm();
    let lens = lens(ra, b.radius, d)?;
    let u = if d > 0.0 { b.centre / d } else { Vector2::x() };
    // Coinciding sides (the same disc) count half to each body.
    let side_share = if d == 0.0 && ra == b.radius { 0.5 } else { 1.0 };
    let section = Section {
        area: lens.area,
        moment: lens.area * lens.centroid * u,
        rim_vector: lens.arc_vector_a * u,
        rim_length: side_share * lens.arc_a,
        other_length: side_share * lens.arc_b,
    };
    Some(extrude(&section, la, b.range, overlap))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lens against a brute-force count on a grid (area and centroid), for overlaps from
    /// grazing to one disc inside the other.
    #[test]
    fn the_lens_matches_a_grid_count() {
        for &(ra, rb, d) in &[
            (1.0, 0.5, 1.3),
            (0.7, 0.7, 0.3),
            (1.0, 0.4, 0.5),
            (0.4, 1.0, 0.5),
            (1.0, 1.0, 1.9),
            (0.6, 0.9, 0.31),
        ] {
            let lens = lens(ra, rb, d).unwrap();
            let n = 2000;
            let (lo, hi) = (-ra, ra);
            let step = (hi - lo) / n as f64;
            let (mut area, mut moment) = (0.0, 0.0);
            for i in 0..n {
                for j in 0..n {
                    let (x, y) = (lo + (i as f64 + 0.5) * step, lo + (j as f64 + 0.5) * step);
                    if x * x + y * y <= ra * ra && (x - d) * (x - d) + y * y <= rb * rb {
                        area += step * step;
                        moment += x * step * step;
                    }
                }
            }
            assert!(
                (lens.area - area).abs() <= 2e-3 * area,
                "{ra} {rb} {d}: {lens:?} {area}"
            );
            let centroid = moment / area;
            assert!(
                (lens.centroid - centroid).abs() <= 2e-3 * ra,
                "{lens:?} {centroid}"
            );
        }
    }

    /// The series of `f` meets the difference at ½ and follows it below (to the difference's
    /// own round-off, `ε/α³` relative), and `⅔α³` at tiny angles.
    #[test]
    fn the_segment_series_joins_the_difference() {
        let direct = |a: f64| a - a.sin() * a.cos();
        assert!((segment_area_factor(0.5 - 1e-16) - direct(0.5)).abs() <= 1e-15 * direct(0.5));
        for &a in &[0.4, 0.2, 0.1] {
            let tolerance = 4.0 * f64::EPSILON / (a * a * a) + 1e-15;
            assert!(
                (segment_area_factor(a) - direct(a)).abs() <= tolerance * segment_area_factor(a),
                "{a}"
            );
        }
        let a = 1e-7;
        assert!(
            (segment_area_factor(a) - 2.0 / 3.0 * a * a * a).abs()
                <= 1e-14 * segment_area_factor(a)
        );
    }

    /// Two cylinders side by side are a closed surface split between them: `a`'s area vector
    /// and `b`'s (by exchanging the bodies) sum to zero, coinciding caps and sides included.
    #[test]
    fn exchanging_the_bodies_negates_the_area_vector() {
        let cases = [
            (1.0, 2.0, 0.5, 3.0, Vector2::new(1.3, 0.0), -0.5),
            (1.0, 2.0, 0.5, 2.0, Vector2::new(0.9, 0.4), 0.0),
            (0.7, 1.0, 0.7, 1.0, Vector2::new(0.0, 0.0), 0.0),
            (0.7, 1.5, 0.7, 1.0, Vector2::new(0.0, 0.0), 0.5),
            (1.0, 2.0, 0.3, 1.0, Vector2::new(0.2, -0.1), 0.4),
        ];
        for (ra, la, rb, lb, c, zb) in cases {
            let ab = moments(
                ra,
                la,
                &ParallelB {
                    centre: c,
                    radius: rb,
                    range: (zb, zb + lb),
                },
            )
            .unwrap();
            let ba = moments(
                rb,
                lb,
                &ParallelB {
                    centre: -c,
                    radius: ra,
                    range: (-zb, la - zb),
                },
            )
            .unwrap();
            let sum = ab.area_vector_a + ba.area_vector_a;
            assert!(sum.norm() <= 1e-15, "{sum:?}");
            assert!((ab.volume - ba.volume).abs() <= 1e-15 * ab.volume);
            assert!((ab.area_a - ba.area_b).abs() <= 1e-15 * ab.area_a);
            assert!((ab.area_b - ba.area_a).abs() <= 1e-15 * (ab.area_b + 1.0));
        }
    }
}
