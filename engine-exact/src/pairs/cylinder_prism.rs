//! A cylinder against a box with an axis exactly parallel (or opposite) to the cylinder's, in
//! closed form: the intersection is the part of the cylinder's disc inside the box's
//! rectangular section, times the overlap of their axial ranges.
//!
//! In the cylinder's frame (axis +z, disc of radius `R` about the axis, `0 ≤ z ≤ L`) the box
//! is a convex polygon `P` (its section, counter-clockwise) over `[z_0, z_1]`. The region
//! `D ∩ P` is bounded by the pieces of `P`'s edges inside the disc and by arcs of the rim
//! between a piece that leaves the disc and the next that enters it (both convex, so the two
//! alternate counter-clockwise).
//! - **Area and centroid**: the polygon of the boundary's vertices (fanned from its first
//!   vertex, so round-off is relative to the region, not to the disc) plus each arc's circular
//!   segment beyond its chord: half-angle `α`, area `R² f(α)` with `f(α) = α − sin α cos α`
//!   (by its series at small `α`, [`super::cylinder_parallel`]), first moment about the
//!   disc's centre `⅔c³` along the arc's bisector, `c` the half-chord. A disc inside `P` is
//!   the whole disc; a `P` inside the disc has no arcs.
//! - **The cylinder's surface inside the box**: each arc's area vector `2c` along its
//!   bisector per unit height (length `2Rα`), and the caps within the box's range, `±A·ẑ`;
//!   **the box's inside the cylinder**: its faces' pieces inside the disc times the overlap,
//!   and its end faces within the cylinder's range. A cap and an end face that coincide count
//!   half to each body: the mean of the limits of a vanishing tilt one way and the other (the
//!   answer jumps there with the tilt's direction).
//!
//! Touching (no overlap of section or range) is no contact.

use super::cylinder_parallel::{Section, axial_overlap, extrude, segment_area_factor};
use super::sliced::SlicedMoments;
use contact_core::Vector2;
use std::f64::consts::PI;

/// The box as the cylinder's frame sees it (lengths in the working unit): its section's
/// corners, counter-clockwise, and its axial range.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Prism {
    /// The section's corners, counter-clockwise seen from +z.
    pub corners: [Vector2; 4],
    /// Axial range `[z_0, z_1]`.
    pub range: (f64, f64),
}

/// Where the edge `p → q` runs inside the disc of radius `r` about the origin, as its
/// parameters `[t_0, t_1] ⊂ [0, 1]`, or `None` (outside, or touching at a point).
fn inside_part(p: &Vector2, q: &Vector2, r: f64) -> Option<(f64, f64)> {
    let e = q - p;
    let length_squared = e.norm_squared();
    if length_squared == 0.0 {
        return None;
    }
    // The foot of the origin on the edge's line, and the half-width of the chord there
    // (from (r − d)(r + d), free of the cancellation of r² − d²).
    let foot = -p.dot(&e) / length_squared;
    let distance = (p + foot * e).norm();
    if distance >= r {
        return None;
    }
    let half = ((r - distance) * (r + distance)).sqrt() / length_squared.sqrt();
    let (t0, t1) = ((foot - half).max(0.0), (foot + half).min(1.0));
    (t0 < t1).then_some((t0, t1))
}

/// The region of the disc of radius `r` about the origin inside the convex polygon `corners`
/// (counter-clockwise), or `None` when they do not overlap with positive area.
fn section(r: f64, corners: &[Vector2; 4]) -> Option<Section> {
    // The boundary's vertices in order, each marked when the rim leaves from it to the next.
    let mut vertices = [(Vector2::zeros(), false); 12];
    let mut count = 0;
    let mut edge_length = 0.0;
    for k in 0..4 {
        let (p, q) = (corners[k], corners[(k + 1) % 4]);
        let Some((t0, t1)) = inside_part(&p, &q, r) else {
            continue;
        };
        // A corner inside the disc is kept bit for bit, so the next edge starts where this
        // one ends.
        let s0 = if t0 == 0.0 { p } else { p + t0 * (q - p) };
        let s1 = if t1 == 1.0 { q } else { p + t1 * (q - p) };
        edge_length += (s1 - s0).norm();
        if t0 > 0.0 || count == 0 {
            vertices[count] = (s0, false);
            count += 1;
        }
        // Leaving the disc before the corner: the rim follows.
        vertices[count] = (s1, t1 < 1.0);
        count += 1;
    }
    // A first vertex at a corner inside the disc is also the last edge's end: drop the copy.
    if count > 1 && vertices[count - 1].0 == vertices[0].0 {
        let leaves = vertices[count - 1].1;
        vertices[0].1 |= leaves;
        count -= 1;
    }
    if count == 0 {
        // No edge reaches into the disc: the disc lies inside the polygon, or apart from it.
        let inside = (0..4).all(|k| corners[k].perp(&corners[(k + 1) % 4]) > 0.0);
        return inside.then(|| Section {
            area: PI * r * r,
            moment: Vector2::zeros(),
            rim_vector: Vector2::zeros(),
            rim_length: 2.0 * PI * r,
            other_length: 0.0,
        });
    }
    let origin = vertices[0].0;
    let (mut area, mut moment) = (0.0, Vector2::zeros());
    let (mut arc_vector, mut arc_length) = (Vector2::zeros(), 0.0);
    for k in 0..count {
        let (v, leaves) = vertices[k];
        let w = vertices[(k + 1) % count].0;
        let (a, b) = (v - origin, w - origin);
        let twice = a.perp(&b);
        area += 0.5 * twice;
        moment += twice / 6.0 * (origin + v + w);
        if leaves {
            // The rim from v round to w, counter-clockwise: half-angle α, bisector `mid`.
            let turn = v.perp(&w).atan2(v.dot(&w));
            let alpha = 0.5 * if turn > 0.0 { turn } else { turn + 2.0 * PI };
            let half_chord = 0.5 * (w - v).norm();
            let angle = v.y.atan2(v.x) + alpha;
            let mid = Vector2::new(angle.cos(), angle.sin());
            area += r * r * segment_area_factor(alpha);
            moment += 2.0 / 3.0 * half_chord.powi(3) * mid;
            arc_vector += 2.0 * half_chord * mid;
            arc_length += 2.0 * r * alpha;
        }
    }
    (area > 0.0).then_some(Section {
        area,
        moment,
        rim_vector: arc_vector,
        rim_length: arc_length,
        other_length: edge_length,
    })
}

/// The intersection's moments for the cylinder (radius `r`, length `len`, working unit) and
/// the box `prism`, in the slicing pairs' working frame: the cylinder's axes, origin at its
/// centre. `None` when the section or the axial ranges do not overlap.
pub(crate) fn moments(r: f64, len: f64, prism: &Prism) -> Option<SlicedMoments> {
    let overlap = axial_overlap(len, prism.range)?;
    let section = section(r, &prism.corners)?;
    Some(extrude(&section, len, prism.range, overlap))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The disc's part inside rectangles (corners inside and outside the disc, the disc's
    /// centre inside and outside, the disc wholly inside, a rectangle wholly inside) against
    /// a grid count of area and centroid, and the rim inside against a count of rim samples.
    #[test]
    fn the_section_matches_a_grid_count() {
        let rectangle = |c: Vector2, angle: f64, hu: f64, hv: f64| {
            let (u, v) = (
                Vector2::new(angle.cos(), angle.sin()),
                Vector2::new(-angle.sin(), angle.cos()),
            );
            [
                c + hu * u + hv * v,
                c - hu * u + hv * v,
                c - hu * u - hv * v,
                c + hu * u - hv * v,
            ]
        };
        let r = 0.5;
        for (c, angle, hu, hv) in [
            (Vector2::new(1.3, 0.0), 0.0, 1.0, 1.0),
            (Vector2::new(0.6, 0.5), 0.4, 0.4, 0.3),
            (Vector2::new(0.1, -0.05), 1.0, 0.2, 0.1),
            (Vector2::new(0.0, 0.0), 0.3, 2.0, 2.0),
            (Vector2::new(0.2, 0.1), -0.7, 0.6, 0.15),
            (Vector2::new(-0.55, 0.3), 2.0, 0.3, 0.5),
        ] {
            let corners = rectangle(c, angle, hu, hv);
            let s = section(r, &corners).unwrap();
            let inside_p = |x: Vector2| {
                (0..4).all(|k| (corners[(k + 1) % 4] - corners[k]).perp(&(x - corners[k])) >= 0.0)
            };
            let n = 1500;
            let step = 2.0 * r / n as f64;
            let (mut area, mut moment) = (0.0, Vector2::zeros());
            for i in 0..n {
                for j in 0..n {
                    let x =
                        Vector2::new(-r + (i as f64 + 0.5) * step, -r + (j as f64 + 0.5) * step);
                    if x.norm_squared() <= r * r && inside_p(x) {
                        area += step * step;
                        moment += x * step * step;
                    }
                }
            }
            assert!((s.area - area).abs() <= 3e-3 * area, "{c:?}: {s:?} {area}");
            assert!(
                (s.moment / s.area - moment / area).norm() <= 3e-3 * r,
                "{c:?}: {s:?}"
            );
            let m = 100_000;
            let (mut length, mut vector) = (0.0, Vector2::zeros());
            for k in 0..m {
                let t = (k as f64 + 0.5) / m as f64 * 2.0 * PI;
                let normal = Vector2::new(t.cos(), t.sin());
                if inside_p(r * normal) {
                    length += r * 2.0 * PI / m as f64;
                    vector += normal * r * 2.0 * PI / m as f64;
                }
            }
            assert!(
                (s.rim_length - length).abs() <= 1e-4,
                "{c:?}: {s:?} {length}"
            );
            assert!(
                (s.rim_vector - vector).norm() <= 1e-4,
                "{c:?}: {s:?} {vector:?}"
            );
        }
    }

    /// A rectangle apart from the disc, or touching it along a tangent edge, is no section.
    #[test]
    fn apart_and_tangent_are_no_section() {
        let square = |x: f64| {
            [
                Vector2::new(x + 1.0, -1.0),
                Vector2::new(x + 1.0, 1.0),
                Vector2::new(x, 1.0),
                Vector2::new(x, -1.0),
            ]
        };
        assert!(section(0.5, &square(0.7)).is_none());
        assert!(section(0.5, &square(0.5)).is_none());
        assert!(section(0.5, &square(0.4)).is_some());
    }
}
