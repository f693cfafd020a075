//! The part of a crossing triangle inside the other solid, bounded by the triangle's own trace
//! (step 3 of [`crate::contact_region`]), so a region's volume and centroid are those of the
//! polyhedral intersection wherever the other surface is concave too.
//!
//! ## Method
//! The trace of the other surface on a triangle `T` is a set of segments; each is turned so
//! that the inside of the other solid lies on its left (about `T`'s outward normal: A's
//! segments as found, along `n_A × n_B`; B's reversed). Segments meeting end to start (within
//! `1e-12` of the mesh's size) form *chains*: closed, or open with both ends on `T`'s boundary.
//! The inside part of `T` is bounded, counter-clockwise, by its chains and by the stretches of
//! `T`'s boundary that run from a chain's end to the next chain's start (walking the boundary
//! counter-clockwise). With no open chain, the boundary is wholly inside or wholly outside: it
//! is inside when a corner lies on the inside of the trace segment nearest to it (the side of
//! the segment whose line lies farthest from the corner where several are nearest). The cone
//! sums from the region's apex `o` over that oriented boundary, each edge `(p, q)` closed by a
//! fixed point `c` of `T`'s plane (a point of the trace) into the triangle `(c, p, q)`, are the
//! cone sums over the
//! inside part (Green's theorem: the fan from `c` over a closed boundary covers the region
//! once, with signs).
//!
//! Where the chains are not clean — an end met by two starts, an open end off the boundary, two
//! ends in a row along the boundary, a split triangle wholly inside its boundary — the caller
//! clips by the crossed planes instead (exact where the other surface is convex there).

use crate::surface_sums::SurfaceSums;
use contact_core::Vector3;

/// Buffers for one triangle's boundary.
#[derive(Debug, Default)]
pub(crate) struct BoundaryScratch {
    /// The oriented trace segments `(start, end)`.
    pub segments: Vec<(Vector3, Vector3)>,
    next: Vec<u32>,
    has_previous: Vec<bool>,
    /// `(boundary parameter, is an end, point)`.
    events: Vec<(f64, bool, Vector3)>,
}

/// No following segment.
const NONE: u32 = u32::MAX;

/// Adds to `sums` the cone sums from `apex` over the part of the triangle `corners`
/// (counter-clockwise about its outward normal) inside the other solid, from the oriented trace
/// segments in `w.segments` (see the module docs); `boundary_inside` says whether the whole
/// boundary is inside when no chain reaches it (`None`: unknown). Returns false, adding
/// nothing, where the chains are not clean.
pub(crate) fn add_inside_part(
    corners: &[Vector3; 3],
    w: &mut BoundaryScratch,
    boundary_inside: impl FnOnce(&[(Vector3, Vector3)]) -> Option<bool>,
    touch: f64,
    apex: &Vector3,
    sums: &mut SurfaceSums,
) -> bool {
    let touch2 = touch * touch;
    w.segments.retain(|(p, q)| (q - p).norm_squared() > touch2);
    let k = w.segments.len();
    w.next.clear();
    w.next.resize(k, NONE);
    w.has_previous.clear();
    w.has_previous.resize(k, false);
    for i in 0..k {
        let end = w.segments[i].1;
        for j in 0..k {
            if j != i && (w.segments[j].0 - end).norm_squared() <= touch2 {
                if w.next[i] != NONE || w.has_previous[j] {
                    return false;
                }
                w.next[i] = j as u32;
                w.has_previous[j] = true;
            }
        }
    }
    w.events.clear();
    for i in 0..k {
        for (free, point, is_end) in [
            (!w.has_previous[i], w.segments[i].0, false),
            (w.next[i] == NONE, w.segments[i].1, true),
        ] {
            if free {
                let Some(at) = boundary_parameter(corners, &point, touch) else {
                    return false;
                };
                w.events.push((at, is_end, point));
            }
        }
    }
    // Ends before starts where they meet: the stretch between them is empty.
    w.events
        .sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.cmp(&a.1)));
    // The fan's point on the trace, so each term is of the inside part's size (a point far
    // from a small part would leave the sums to cancellation).
    let c = w.segments.first().map_or(corners[0], |s| s.0);
    let mut local = SurfaceSums::default();
    let mut edge = |p: &Vector3, q: &Vector3| local.add_triangle(&c, p, q, apex);
    if w.events.is_empty() {
        match boundary_inside(&w.segments) {
            Some(true) => {
                for e in 0..3 {
                    edge(&corners[e], &corners[(e + 1) % 3]);
                }
            }
            Some(false) => {}
            None => return false,
        }
    } else {
        let n = w.events.len();
        for (e, &(at, is_end, point)) in w.events.iter().enumerate() {
            if !is_end {
                continue;
            }
            let (to, to_is_end, to_point) = w.events[(e + 1) % n];
            if to_is_end {
                return false;
            }
            walk_boundary(corners, (at, point), (to, to_point), &mut edge);
        }
    }
    for (p, q) in &w.segments {
        edge(p, q);
    }
    sums.merge(&local);
    true
}

/// Whether `corner` lies on the inside of the trace: on the left (about the triangle's normal
/// `n`) of the segment nearest to it, or, where several are equally near (a corner of a chain),
/// of the one whose line lies farthest from it. `None` without segments or on the trace.
pub(crate) fn corner_inside(
    segments: &[(Vector3, Vector3)],
    n: &Vector3,
    corner: &Vector3,
) -> Option<bool> {
    let side = side_of_nearest(
        segments.iter().map(|(p, q)| (*p, *q, n.cross(&(q - p)))),
        corner,
    );
    (side != 0.0).then_some(side > 0.0)
}

/// The signed distance of `m` along the inward direction of the segment `(p, q, inward)`
/// nearest to it; among segments equally near (within 1e-9 relative: a corner of a chain),
/// the one whose line lies farthest from `m` (a point-in-polygon test by the nearest edge).
/// Zero without segments.
pub(crate) fn side_of_nearest(
    segments: impl Iterator<Item = (Vector3, Vector3, Vector3)> + Clone,
    m: &Vector3,
) -> f64 {
    let closest = |p: &Vector3, q: &Vector3| {
        let d = q - p;
        let len2 = d.norm_squared();
        let t = if len2 > 0.0 {
            ((m - p).dot(&d) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        p + d * t
    };
    let nearest = segments
        .clone()
        .map(|(p, q, _)| (m - closest(&p, &q)).norm())
        .fold(f64::INFINITY, f64::min);
    let tie = nearest * (1.0 + 1e-9) + f64::MIN_POSITIVE;
    segments
        .filter_map(|(p, q, inward)| {
            let c = closest(&p, &q);
            let inward = inward.try_normalize(0.0)?;
            ((m - c).norm() <= tie).then(|| (m - c).dot(&inward))
        })
        .max_by(|u, v| u.abs().total_cmp(&v.abs()))
        .unwrap_or(0.0)
}

/// The point's place on the boundary: `e + t` on edge `e` (corner `e` to `e + 1`) at fraction
/// `t`, or `None` when it lies farther than `touch` from every edge.
fn boundary_parameter(corners: &[Vector3; 3], p: &Vector3, touch: f64) -> Option<f64> {
    let mut best = (f64::INFINITY, 0.0);
    for e in 0..3 {
        let (a, b) = (corners[e], corners[(e + 1) % 3]);
        let d = b - a;
        let t = ((p - a).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
        let gap = (a + d * t - p).norm();
        if gap < best.0 {
            best = (gap, e as f64 + t);
        }
    }
    (best.0 <= touch).then_some(best.1 % 3.0)
}

/// The boundary counter-clockwise from `from` to `to` (parameters and points), corner by
/// corner, as edges.
fn walk_boundary(
    corners: &[Vector3; 3],
    from: (f64, Vector3),
    to: (f64, Vector3),
    edge: &mut impl FnMut(&Vector3, &Vector3),
) {
    let (mut at, mut point) = from;
    // The stretch runs forward; a target behind the start (or at it, after a full turn is not
    // meant) lies one turn on.
    let target = if to.0 >= at { to.0 } else { to.0 + 3.0 };
    loop {
        let next_corner = at.floor() + 1.0;
        if next_corner >= target {
            edge(&point, &to.1);
            return;
        }
        let corner = corners[(next_corner as usize) % 3];
        edge(&point, &corner);
        at = next_corner;
        point = corner;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> Vector3 {
        Vector3::new(x, y, 0.0)
    }

    fn area(corners: &[Vector3; 3], segments: &[(Vector3, Vector3)], inside: bool) -> Option<f64> {
        let mut w = BoundaryScratch {
            segments: segments.to_vec(),
            ..Default::default()
        };
        let mut sums = SurfaceSums::default();
        // Apex one unit below the plane: the cone volume is the area over 3.
        let apex = Vector3::new(0.0, 0.0, -1.0);
        add_inside_part(corners, &mut w, |_| Some(inside), 1e-12, &apex, &mut sums)
            .then_some(3.0 * sums.volume)
    }

    #[test]
    fn the_inside_part_of_a_triangle_from_its_trace() {
        let t = [v(0.0, 0.0), v(4.0, 0.0), v(0.0, 4.0)];
        // A cut across the corner at the origin, inside towards the corner (on the left of the
        // trace going from (1, 0) to (0, 1)): the small triangle, area 1/2.
        let cut = [(v(1.0, 0.0), v(0.5, 0.5)), (v(0.5, 0.5), v(0.0, 1.0))];
        assert!((area(&t, &cut, false).unwrap() - 0.5).abs() < 1e-15);
        // The same cut the other way: the rest, 8 − 1/2.
        let rest = [(v(0.0, 1.0), v(0.5, 0.5)), (v(0.5, 0.5), v(1.0, 0.0))];
        assert!((area(&t, &rest, false).unwrap() - 7.5).abs() < 1e-14);
        // Two cuts, each keeping its corner: two pieces of area 1/2.
        let two = [(v(1.0, 0.0), v(0.0, 1.0)), (v(3.0, 1.0), v(3.0, 0.0))];
        assert!((area(&t, &two, false).unwrap() - 1.0).abs() < 1e-14);
        // A closed square hole (clockwise: inside outside it) in a boundary that is inside.
        let hole = [
            (v(1.0, 1.0), v(1.0, 2.0)),
            (v(1.0, 2.0), v(2.0, 2.0)),
            (v(2.0, 2.0), v(2.0, 1.0)),
            (v(2.0, 1.0), v(1.0, 1.0)),
        ];
        assert!((area(&t, &hole, true).unwrap() - 7.0).abs() < 1e-14);
        // A closed island (counter-clockwise), boundary outside.
        let island: Vec<_> = hole.iter().map(|(p, q)| (*q, *p)).collect();
        assert!((area(&t, &island, false).unwrap() - 1.0).abs() < 1e-14);
        // Two ends in a row along the boundary are not a clean trace.
        let bad = [(v(0.0, 1.0), v(1.0, 0.0)), (v(3.0, 1.0), v(3.0, 0.0))];
        assert!(area(&t, &bad, false).is_none());
    }
}
