//! A cylinder against a box with an axis exactly parallel (or opposite) to the cylinder's, in
//! closed form: the intersection is the part of the cylinder's disc inside the box's
//! rectangular section, times the overlap of their axial ranges.
//!
//! In the cylinder's frame (axis +z, disc of radius `R` about the axis, `0 ≤ z ≤ L`) the box
//! is a convex polygon `P` (its section, counter-clockwise) over `[z_0, z_1]`. The region
//! `D ∩ P` is bounded by the pieces of `P`'s edges inside the disc and by arcs of the rim
//! between a piece that leaves the disc and the next that enters it (both convex, so the two
//! alternate counter-clockwise).
//! - **Area and centroid**: `disc_region` (the boundary's polygon fanned from its
//!   first vertex, plus each rim arc's circular segment).
//! - **The cylinder's surface inside the box**: each arc's area vector `2c` along its
//!   bisector per unit height (length `2Rα`), and the caps within the box's range, `±A·ẑ`;
//!   **the box's inside the cylinder**: its faces' pieces inside the disc times the overlap,
//!   and its end faces within the cylinder's range. A cap and an end face that coincide count
//!   half to each body: the mean of the limits of a vanishing tilt one way and the other (the
//!   answer jumps there with the tilt's direction).
//!
//! Touching (no overlap of section or range) is no contact.

use super::cylinder_parallel::{Section, axial_overlap, extrude};
use super::disc_region::disc_region;
use super::sliced::SlicedMoments;
use contact_core::Vector2;

/// The box as the cylinder's frame sees it (lengths in the working unit): its section's
/// corners, counter-clockwise, and its axial range.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Prism {
    /// The section's corners, counter-clockwise seen from +z.
    pub corners: [Vector2; 4],
    /// Axial range `[z_0, z_1]`.
    pub range: (f64, f64),
}

/// The region of the disc of radius `r` about the origin inside the convex polygon `corners`
/// (counter-clockwise), or `None` when they do not overlap with positive area.
fn section(r: f64, corners: &[Vector2; 4]) -> Option<Section> {
    let (mut rim_vector, mut rim_length) = (Vector2::zeros(), 0.0);
    let region = disc_region(r, corners, |arc| {
        rim_vector += 2.0 * arc.half_chord * arc.bisector();
        rim_length += 2.0 * r * arc.half_angle;
    })?;
    Some(Section {
        area: region.area,
        moment: region.moment,
        rim_vector,
        rim_length,
        other_length: region.edge_length,
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
    use std::f64::consts::PI;

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
