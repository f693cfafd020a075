//! A cap of the cylinder inside a closed polyhedron that need not be convex: the disc
//! `|p| ≤ r` of the plane `z = c` against the polyhedron's section there, in closed form.
//!
//! The section is the polyhedron's triangles crossing the plane, each a directed segment
//! with the solid on its left (`SlicedTriangle::segment`); the overlap's boundary is their
//! parts inside the disc (chords) and the rim's arcs inside the section, each running
//! counter-clockwise from a crossing where a segment leaves the disc to the next crossing,
//! where one enters. With no crossing the rim lies wholly inside the section or wholly
//! outside it, as the parity of the segments crossing a ray from a rim point tells. The area
//! and first moments are Green's sums over those pieces fanned from a point of the boundary
//! (so round-off is relative to the region, not to the disc): a triangle per chord, and per
//! arc its chord's triangle and the circular segment beyond it (as `disc_region` takes it).
//!
//! Where the combinatorics are not clear-cut — a vertex within 1e-12 of the pair's size of
//! the plane, a segment's end as close to the rim, two crossings as close together, crossings
//! that do not alternate, or more crossings than kept — the cap is not taken here (`None`)
//! and the caller slices the pair.

use crate::methods::cylinder_parallel::segment_area_factor;
use crate::methods::disc_region::{DiscRegion, RimArc};
use crate::pairs::revolved_mesh::section::{SlicedTriangle, clip_to_disc};
use contact_core::{Vector2, Vector3};
use std::f64::consts::PI;

/// Most rim crossings of one cap kept.
const MAX_CROSSINGS: usize = 32;

/// Distances within this fraction of the pair's size are taken as touching (see the module
/// doc).
const NEAR: f64 = 1e-12;

/// A crossing of the rim: its angle, whether the segment leaves the disc there, where, and the
/// triangle whose segment it is.
#[derive(Debug, Clone, Copy)]
struct Crossing {
    angle: f64,
    leaves: bool,
    at: Vector2,
    owner: usize,
}

/// The part of the disc of radius `r` on the plane `z = c` inside the section of the closed
/// polyhedron `triangles` (all of a component's, outward counter-clockwise), each bounding
/// rim arc passed to `arc` with the triangles whose chords it runs between (leaving, then
/// entering; none for the whole rim): `Some(None)` when they do not overlap with area, `None`
/// when the combinatorics are not clear-cut (see the module doc).
pub(crate) fn cap_region(
    r: f64,
    c: f64,
    triangles: &[[Vector3; 3]],
    mut arc: impl FnMut(&RimArc, Option<(usize, usize)>),
) -> Option<Option<DiscRegion>> {
    let near = NEAR * (r + c.abs());
    let Chords {
        mut crossings,
        count,
        origin,
        mut area,
        mut moment,
        edge_length,
        rim_inside,
    } = chords(r, c, near, triangles)?;
    let crossings = &mut crossings[..count];
    crossings.sort_unstable_by(|x, y| x.angle.total_cmp(&y.angle));
    for k in 0..count {
        let next = &crossings[(k + 1) % count];
        if next.leaves == crossings[k].leaves || (next.at - crossings[k].at).norm() <= near {
            return None;
        }
    }
    if count == 0 && rim_inside {
        arc(
            &RimArc {
                start: 0.0,
                half_angle: PI,
                half_chord: 0.0,
            },
            None,
        );
        area += PI * r * r;
    }
    if let Some(o) = origin {
        for k in (0..count).filter(|&k| crossings[k].leaves) {
            // The rim from v round to w, counter-clockwise.
            let (v, w) = (crossings[k].at, crossings[(k + 1) % count].at);
            let turn = v.perp(&w).atan2(v.dot(&w));
            let rim = RimArc {
                start: crossings[k].angle,
                half_angle: 0.5 * if turn > 0.0 { turn } else { turn + 2.0 * PI },
                half_chord: 0.5 * (w - v).norm(),
            };
            let twice = (v - o).perp(&(w - o));
            area += 0.5 * twice + r * r * segment_area_factor(rim.half_angle);
            moment +=
                twice / 6.0 * (o + v + w) + 2.0 / 3.0 * rim.half_chord.powi(3) * rim.bisector();
            let next = crossings[(k + 1) % count].owner;
            arc(&rim, Some((crossings[k].owner, next)));
        }
    }
    Some((area > 0.0).then_some(DiscRegion {
        area,
        moment,
        edge_length,
    }))
}

/// The chords of the cap: each segment's part inside the disc, with the rim crossings and the
/// fan sums they add (see [`cap_region`]).
struct Chords {
    /// The rim crossings, the first `count`, in the triangles' order.
    crossings: [Crossing; MAX_CROSSINGS],
    /// How many crossings there are.
    count: usize,
    /// The fan's origin: the first chord's start (`None` without chords).
    origin: Option<Vector2>,
    /// The chords' fan triangles' area.
    area: f64,
    /// Their first moment.
    moment: Vector2,
    /// The chords' total length.
    edge_length: f64,
    /// The parity of the segments crossing the ray from the rim point `(r, 0)` along `+x`.
    rim_inside: bool,
}

/// The chords of the disc of radius `r` on the plane `z = c` through the section of
/// `triangles` (see [`cap_region`]); `None` where the cap is declined: a vertex within `near`
/// of the plane, a segment's end within `near` of the rim, more crossings than kept.
fn chords(r: f64, c: f64, near: f64, triangles: &[[Vector3; 3]]) -> Option<Chords> {
    let mut crossings = [Crossing {
        angle: 0.0,
        leaves: false,
        at: Vector2::zeros(),
        owner: 0,
    }; MAX_CROSSINGS];
    let mut count = 0;
    let mut overflow = false;
    let (mut origin, mut area, mut moment, mut edge_length) =
        (None::<Vector2>, 0.0, Vector2::zeros(), 0.0);
    // The parity of the segments crossing the ray from the rim point (r, 0) along +x.
    let mut rim_inside = false;
    for (owner, v) in triangles.iter().enumerate() {
        let (lo, hi) = (
            v[0].z.min(v[1].z).min(v[2].z),
            v[0].z.max(v[1].z).max(v[2].z),
        );
        if lo > c + near || hi < c - near {
            continue;
        }
        if v.iter().any(|p| (p.z - c).abs() <= near) {
            return None;
        }
        let (p, _, q, _) = SlicedTriangle::new(0, *v)?.segment(c);
        if (p.norm() - r).abs() <= near || (q.norm() - r).abs() <= near {
            return None;
        }
        if (p.y > 0.0) != (q.y > 0.0) && p.x + (0.0 - p.y) / (q.y - p.y) * (q.x - p.x) > r {
            rim_inside = !rim_inside;
        }
        let crossing = |at: Vector2, leaves: bool| {
            if count < MAX_CROSSINGS {
                crossings[count] = Crossing {
                    angle: at.y.atan2(at.x),
                    leaves,
                    at,
                    owner,
                };
                count += 1;
            } else {
                overflow = true;
            }
        };
        let Some((l0, l1)) = clip_to_disc(&p, &q, r, crossing) else {
            continue;
        };
        let a = if l0 == 0.0 { p } else { p + l0 * (q - p) };
        let e = if l1 == 1.0 { q } else { p + l1 * (q - p) };
        edge_length += (e - a).norm();
        let o = *origin.get_or_insert(a);
        let twice = (a - o).perp(&(e - o));
        area += 0.5 * twice;
        moment += twice / 6.0 * (o + a + e);
    }
    if overflow {
        return None;
    }
    Some(Chords {
        crossings,
        count,
        origin,
        area,
        moment,
        edge_length,
        rim_inside,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The faces of a prism over the polygon `corners` (counter-clockwise) from `z = -1` to
    /// `z = 1`, as triangles with outward normals (walls only: the caps never cross `z = 0`).
    fn prism_walls(corners: &[Vector2]) -> Vec<[Vector3; 3]> {
        let n = corners.len();
        let mut out = Vec::new();
        for k in 0..n {
            let (p, q) = (corners[k], corners[(k + 1) % n]);
            let (p0, q0) = (Vector3::new(p.x, p.y, -1.0), Vector3::new(q.x, q.y, -1.0));
            let (p1, q1) = (Vector3::new(p.x, p.y, 1.0), Vector3::new(q.x, q.y, 1.0));
            out.push([p0, q0, q1]);
            out.push([p0, q1, p1]);
        }
        out
    }

    /// The unit disc's area and first moments inside a polygon by a fine grid (an
    /// independent count).
    fn grid(inside: impl Fn(&Vector2) -> bool) -> (f64, Vector2) {
        let n = 2000;
        let h = 2.0 / n as f64;
        let (mut area, mut moment) = (0.0, Vector2::zeros());
        for i in 0..n {
            for j in 0..n {
                let p = Vector2::new(-1.0 + (i as f64 + 0.5) * h, -1.0 + (j as f64 + 0.5) * h);
                if p.norm_squared() <= 1.0 && inside(&p) {
                    area += h * h;
                    moment += p * h * h;
                }
            }
        }
        (area, moment)
    }

    /// An L-shaped section (not convex) across the disc: the grid's area and moments, with
    /// the rim arcs adding up to the rim's part inside the L.
    #[test]
    fn an_l_shaped_section_is_the_grids_overlap() {
        let l = [
            Vector2::new(-0.3, -2.0),
            Vector2::new(2.0, -2.0),
            Vector2::new(2.0, -0.2),
            Vector2::new(0.4, -0.2),
            Vector2::new(0.4, 2.0),
            Vector2::new(-0.3, 2.0),
        ];
        let inside = |p: &Vector2| {
            (p.x >= -0.3 && p.x <= 2.0 && p.y >= -2.0 && p.y <= -0.2)
                || (p.x >= -0.3 && p.x <= 0.4 && p.y >= -2.0 && p.y <= 2.0)
        };
        let mut sweep = 0.0;
        let got = cap_region(1.0, 0.0, &prism_walls(&l), |a, _| {
            sweep += 2.0 * a.half_angle
        })
        .unwrap()
        .unwrap();
        let (area, moment) = grid(inside);
        // The grid's error: about its cell times the boundary's length.
        assert!((got.area - area).abs() < 5e-3, "{got:?} {area}");
        assert!((got.moment - moment).norm() < 5e-3, "{got:?} {moment}");
        // The rim inside the L: from the angle of (−0.3, −√0.91) counter-clockwise through
        // the bottom right to y = −0.2, and from x = 0.4 over the top to x = −0.3.
        let bottom = (-(0.91f64.sqrt())).atan2(-0.3);
        let right = (-0.2f64).atan2(0.96f64.sqrt());
        let top_right = (0.84f64.sqrt()).atan2(0.4);
        let top_left = (0.91f64.sqrt()).atan2(-0.3);
        let want = (right - bottom) + (top_left - top_right);
        assert!((sweep - want).abs() < 1e-14, "{sweep} {want}");
    }

    /// A square hole through the disc's middle: the disc less the hole, one rim arc of a full
    /// turn.
    #[test]
    fn a_hole_inside_the_disc_leaves_the_whole_rim() {
        let outer = prism_walls(&[
            Vector2::new(-2.0, -2.0),
            Vector2::new(2.0, -2.0),
            Vector2::new(2.0, 2.0),
            Vector2::new(-2.0, 2.0),
        ]);
        // The hole's walls face into it: its corners run clockwise.
        let hole = prism_walls(&[
            Vector2::new(-0.2, -0.1),
            Vector2::new(-0.2, 0.3),
            Vector2::new(0.4, 0.3),
            Vector2::new(0.4, -0.1),
        ]);
        let triangles: Vec<_> = outer.into_iter().chain(hole).collect();
        let mut arcs = Vec::new();
        let got = cap_region(1.0, 0.0, &triangles, |a, _| arcs.push(*a))
            .unwrap()
            .unwrap();
        let hole_area = 0.6 * 0.4;
        assert!((got.area - (PI - hole_area)).abs() < 1e-15, "{got:?}");
        let hole_moment = Vector2::new(0.1, 0.1) * hole_area;
        assert!((got.moment + hole_moment).norm() < 1e-15, "{got:?}");
        assert_eq!(arcs.len(), 1);
        assert_eq!(arcs[0].half_angle, PI);
        // Outside the section altogether: nothing.
        let far: Vec<_> = prism_walls(&[
            Vector2::new(3.0, 3.0),
            Vector2::new(4.0, 3.0),
            Vector2::new(4.0, 4.0),
        ]);
        assert!(cap_region(1.0, 0.0, &far, |_, _| {}).unwrap().is_none());
    }

    /// A vertex on the cap's plane or a section corner on the rim is left to the slicing.
    #[test]
    fn unclear_combinatorics_are_declined() {
        let walls = prism_walls(&[
            Vector2::new(-2.0, -2.0),
            Vector2::new(2.0, -2.0),
            Vector2::new(2.0, 2.0),
            Vector2::new(-2.0, 2.0),
        ]);
        assert!(cap_region(1.0, 1.0, &walls, |_, _| {}).is_none());
        let corner_on_rim = prism_walls(&[
            Vector2::new(1.0, 0.0),
            Vector2::new(2.0, 0.0),
            Vector2::new(2.0, 1.0),
        ]);
        assert!(cap_region(1.0, 0.0, &corner_on_rim, |_, _| {}).is_none());
    }
}
