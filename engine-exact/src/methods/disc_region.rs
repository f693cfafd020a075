//! The part of a disc of radius `r` about the origin inside a convex polygon, in closed form:
//! its area, first moments and the length of the polygon's boundary inside the disc, with
//! each arc of the rim that bounds it handed to the caller (the cylinder pairs integrate
//! their lateral surface over those arcs).
//!
//! The region is bounded by the pieces of the polygon's edges inside the disc and by arcs of
//! the rim between a piece that leaves the disc and the next that enters it (both convex, so
//! the two alternate counter-clockwise). Its area and centroid: the polygon of the
//! boundary's vertices, fanned from its first vertex (so round-off is relative to the region,
//! not to the disc), plus each arc's circular segment beyond its chord: half-angle `α`, area
//! `r² f(α)` with `f(α) = α − sin α cos α` (by its series at small `α`,
//! [`super::cylinder_parallel::segment_area_factor`]), first moment about the disc's centre
//! `⅔c³` along the arc's bisector, `c` the half-chord. A disc inside the polygon is the whole
//! disc (one arc of a full turn); a polygon inside the disc has no arcs.

use super::cylinder_parallel::segment_area_factor;
use contact_core::Vector2;
use std::f64::consts::PI;

/// Most corners a polygon may have (a box's section clipped by the disc's square: 10).
pub(crate) const MAX_CORNERS: usize = 14;

/// One arc of the rim on the region's boundary, counter-clockwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RimArc {
    /// Angle of its start.
    pub start: f64,
    /// Its half-angle `α` (`0 < α ≤ π`).
    pub half_angle: f64,
    /// Half its chord (`r sin α`).
    pub half_chord: f64,
}

impl RimArc {
    /// The unit vector along the arc's bisector.
    pub fn bisector(&self) -> Vector2 {
        let (s, c) = (self.start + self.half_angle).sin_cos();
        Vector2::new(c, s)
    }
}

/// The region's area, first moment about the disc's centre and the length of the polygon's
/// edges inside the disc.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct DiscRegion {
    /// Area.
    pub area: f64,
    /// `∫ p dA`.
    pub moment: Vector2,
    /// Length of the polygon's boundary inside the disc.
    pub edge_length: f64,
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

/// The part of the disc of radius `r` about the origin inside the convex polygon `corners`
/// (counter-clockwise, at most [`MAX_CORNERS`]), each bounding arc passed to `arc`; `None`
/// when they do not overlap with positive area.
pub(crate) fn disc_region(
    r: f64,
    corners: &[Vector2],
    mut arc: impl FnMut(&RimArc),
) -> Option<DiscRegion> {
    let n = corners.len().min(MAX_CORNERS);
    if n < 3 {
        return None;
    }
    // The boundary's vertices in order, each marked when the rim leaves from it to the next.
    let mut vertices = [(Vector2::zeros(), false); 2 * MAX_CORNERS];
    let mut count = 0;
    let mut edge_length = 0.0;
    for k in 0..n {
        let (p, q) = (corners[k], corners[(k + 1) % n]);
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
        let inside = (0..n).all(|k| corners[k].perp(&corners[(k + 1) % n]) > 0.0);
        if inside {
            arc(&RimArc {
                start: 0.0,
                half_angle: PI,
                half_chord: 0.0,
            });
        }
        return inside.then(|| DiscRegion {
            area: PI * r * r,
            moment: Vector2::zeros(),
            edge_length: 0.0,
        });
    }
    let origin = vertices[0].0;
    let (mut area, mut moment) = (0.0, Vector2::zeros());
    for k in 0..count {
        let (v, leaves) = vertices[k];
        let w = vertices[(k + 1) % count].0;
        let (a, b) = (v - origin, w - origin);
        let twice = a.perp(&b);
        area += 0.5 * twice;
        moment += twice / 6.0 * (origin + v + w);
        if leaves {
            // The rim from v round to w, counter-clockwise.
            let turn = v.perp(&w).atan2(v.dot(&w));
            let rim = RimArc {
                start: v.y.atan2(v.x),
                half_angle: 0.5 * if turn > 0.0 { turn } else { turn + 2.0 * PI },
                half_chord: 0.5 * (w - v).norm(),
            };
            area += r * r * segment_area_factor(rim.half_angle);
            moment += 2.0 / 3.0 * rim.half_chord.powi(3) * rim.bisector();
            arc(&rim);
        }
    }
    (area > 0.0).then_some(DiscRegion {
        area,
        moment,
        edge_length,
    })
}
