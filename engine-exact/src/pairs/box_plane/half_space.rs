//! A box against the half-space below one unbounded plane, in closed form.
//!
//! The contact is the one [`crate::methods::clipped`] defines for a plane (normal the plane's, points
//! on the line through the centroid of the part below the plane, area the cut section's), but
//! the part below is never built as a polyhedron: its volume, centroid and section come from
//! the box's corner heights alone. The work is in world axes from the plane's origin (lengths
//! over a power of two near the box's size): the plane enters only through its outward
//! normal `n`, so nothing is turned into the plane's frame and back.
//!
//! ## The prism along the steepest axis
//! Turn each half axis `A_k` to point up (its rise `r_k = n·A_k ≥ 0`, `n` the outward normal),
//! and take the box from its deepest corner `p₀`, with edges `E_k = 2A_k`:
//! `p = p₀ + a·E_i + b·E_j + c·E_m`, `(a, b, c) ∈ [0, 1]³`, where `m` is the axis of largest
//! rise and `i < j` the other two. Read as a prism along `E_m` over the unit square in
//! `(a, b)`, the column over `(a, b)` is below the plane for `c ≤ N(a, b)`, with
//! `N = ψ₀(a, b)/D` (`ψ₀` the depth below the plane of the bottom face `c = 0`, linear in
//! `(a, b)`; `D = 2r_m`), so the wet length of the column is `w = clamp(N, 0, 1) = N₊ −
//! (N − 1)₊`, and `N − 1 = ψ₁/D` with `ψ₁` the depth of the top face `c = 1`. Everything
//! is then an integral over the unit square of `ψ₊` times a polynomial, for `ψ = ψ₀` and
//! `ψ = ψ₁` (the latter only when the top face dips below the plane):
//!
//! - volume `J ∫w` (`J = 8 h_i h_j h_m`, the box's volume);
//! - centroid `(∫a·w, ∫b·w, ∫w²/2) / ∫w`, with `w² = ψ₀₊²/D² − ψ₁₊²/D² − 2ψ₁₊/D`;
//! - section area: the area of the strip `{0 ≤ N ≤ 1}` in `(a, b)` (cut out of the square
//!   by both lines, not taken as a difference of areas) scaled by the cap's slope over the
//!   square, `|∂_a p × ∂_b p|` on the plane (`J/D` for exactly orthonormal axes; taken from
//!   the axes themselves, so the area is that of the box the corners make).
//!
//! Each `{ψ ≥ 0}` is the unit square clipped by one line, a polygon of at most five vertices
//! fanned from the corner `(0, 0)`, where `ψ` is largest; on each triangle the integrand is a
//! polynomial of degree ≤ 2 in linear functions, integrated exactly from its vertex values.
//! The only divisions are by `D` (twice the largest rise, at least `2h_min/√3`, the axes being
//! orthonormal), by the wet volume, by `ψ_s − ψ_e` for a crossing between a corner below the
//! plane and one above (a fraction in `[0, 1]`), and by the positive rise of the face the
//! normal line leaves through; so a face or an edge flush with the plane (a rise of zero, a
//! level `ψ`) takes no branch of its own.
//!
//! ## Precision
//! The coordinates are taken from the deepest corner, and each crossing on a square edge is
//! interpolated from its end below the plane (the end nearer `(0, 0)`): a sliver under one
//! corner is a small triangle `(0, 0), (x, 0), (0, y)`, and its moments and the centroid's
//! offset from that corner are computed without cancellation. Each corner's depth is summed
//! on its own, from its face centre's height (where a sliver's depth cancels, exactly) and
//! then the two smaller rises, so a face a hair off level keeps its tilt. What remains is
//! the rounding of the heights themselves, about 1e-16 of the box's size.
//!
//! ## Branches
//! No corner below: no contact (the first test, or no wet volume). No corner above
//! (every corner at or below the plane, so a top face flush with it counts): the whole box,
//! its centre the centroid and a quarter of its surface the area, as for clipping's enclosed
//! case in [`crate::methods::clipped`]. One corner or more on each side: the prism above, with the
//! top face's square only when the top face's lowest corner is below the plane.

use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use contact_core::geometry::Cuboid;
use contact_core::{Isometry3, Point3, Vector3};

/// The integrals over `{ψ ≥ 0}` in the unit square of `1`, `ψ`, `a·ψ`, `b·ψ` and `ψ²`, each
/// times the integer that clears its triangle rule's denominator (2, 6, 24, 24, 24): the
/// factors cancel in the ratios taken from them, and leave no division on the way.
#[derive(Debug, Clone, Copy, Default)]
struct Moments {
    area: f64,
    first: f64,
    a: f64,
    b: f64,
    second: f64,
}

/// The unit square's corners, counter-clockwise: `(0, 0)`, `(1, 0)`, `(1, 1)`, `(0, 1)`.
const SQUARE: [(f64, f64); 4] = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];

/// The part of the unit square where the linear `ψ` (given at the [`SQUARE`] corners,
/// largest at `(0, 0)`) is not negative: `(a, b, ψ)` per vertex from `(0, 0)`, at most five
/// (`ψ` is 0 at the crossings), and their number.
#[inline(always)]
fn clip_square(psi: [f64; 4]) -> ([(f64, f64, f64); 5], usize) {
    let mut poly = [(0.0, 0.0, 0.0); 5];
    let mut len = 0;
    for p in 0..4 {
        let q = (p + 1) % 4;
        let (vp, vq) = (psi[p], psi[q]);
        if vp >= 0.0 && len < 5 {
            poly[len] = (SQUARE[p].0, SQUARE[p].1, vp);
            len += 1;
        }
        if ((vp > 0.0 && vq < 0.0) || (vp < 0.0 && vq > 0.0)) && len < 5 {
            // From the end below the plane, so a short piece keeps its relative precision.
            let (s, e, vs, ve) = if vp > 0.0 {
                (p, q, vp, vq)
            } else {
                (q, p, vq, vp)
            };
            let f = vs / (vs - ve);
            let (sa, sb) = SQUARE[s];
            let (ea, eb) = SQUARE[e];
            poly[len] = (sa + f * (ea - sa), sb + f * (eb - sb), 0.0);
            len += 1;
        }
    }
    (poly, len)
}

/// [`Moments`] of `ψ` over the polygon [`clip_square`] gives (`(0, 0)` first, when it has
/// any area): fanned from that corner, a triangle's doubled area is a single cross product.
/// On a triangle with vertex values `f_k`, `g_k` of two linear functions, `∫f = A·Σf/3` and
/// `∫f·g = A·(Σf_k g_k + Σf·Σg)/12`.
/// Inlined, so the moments stay in registers (read back from a returned copy, they would
/// wait on its stores).
#[inline(always)]
fn moments((poly, len): ([(f64, f64, f64); 5], usize)) -> Moments {
    let psi0 = poly[0].2;
    let mut m = Moments::default();
    for k in 1..len.saturating_sub(1) {
        let (a1, b1, p1) = poly[k];
        let (a2, b2, p2) = poly[k + 1];
        let twice = a1 * b2 - a2 * b1;
        let sum = psi0 + p1 + p2;
        m.area += twice;
        m.first += twice * sum;
        m.a += twice * (a1 * p1 + a2 * p2 + (a1 + a2) * sum);
        m.b += twice * (b1 * p1 + b2 * p2 + (b1 + b2) * sum);
        m.second += twice * (psi0 * psi0 + p1 * p1 + p2 * p2 + sum * sum);
    }
    m
}

/// Twice the area of the strip of the unit square where `ψ₀ ≥ 0` and `ψ₁ ≤ 0` (both linear,
/// given at the [`SQUARE`] corners): the square is cut by one line and then the other, each
/// crossing interpolated from its end kept strictly inside, and the area fanned from the
/// first vertex; no two areas are subtracted.
fn strip_area(psi0: [f64; 4], psi1: [f64; 4]) -> f64 {
    // `(a, b, ψ₀)` per vertex; a square cut by two lines has at most six.
    let mut below = [(0.0, 0.0, 0.0); 6];
    let mut len = 0;
    for p in 0..4 {
        let q = (p + 1) % 4;
        let (hp, hq) = (-psi1[p], -psi1[q]);
        if hp >= 0.0 && len < 6 {
            below[len] = (SQUARE[p].0, SQUARE[p].1, psi0[p]);
            len += 1;
        }
        if ((hp > 0.0 && hq < 0.0) || (hp < 0.0 && hq > 0.0)) && len < 6 {
            let (s, e, hs, he) = if hp > 0.0 {
                (p, q, hp, hq)
            } else {
                (q, p, hq, hp)
            };
            let f = hs / (hs - he);
            let (sa, sb) = SQUARE[s];
            let (ea, eb) = SQUARE[e];
            let d = psi0[s] + f * (psi0[e] - psi0[s]);
            below[len] = (sa + f * (ea - sa), sb + f * (eb - sb), d);
            len += 1;
        }
    }
    let mut strip = [(0.0, 0.0); 6];
    let mut count = 0;
    for p in 0..len {
        let q = if p + 1 == len { 0 } else { p + 1 };
        let (vp, vq) = (below[p], below[q]);
        if vp.2 >= 0.0 && count < 6 {
            strip[count] = (vp.0, vp.1);
            count += 1;
        }
        if ((vp.2 > 0.0 && vq.2 < 0.0) || (vp.2 < 0.0 && vq.2 > 0.0)) && count < 6 {
            let (s, e) = if vp.2 > 0.0 { (vp, vq) } else { (vq, vp) };
            let f = s.2 / (s.2 - e.2);
            strip[count] = (s.0 + f * (e.0 - s.0), s.1 + f * (e.1 - s.1));
            count += 1;
        }
    }
    let (a0, b0) = strip[0];
    let mut twice = 0.0;
    for k in 1..count.saturating_sub(1) {
        let (a1, b1) = strip[k];
        let (a2, b2) = strip[k + 1];
        twice += (a1 - a0) * (b2 - b0) - (a2 - a0) * (b1 - b0);
    }
    twice
}

/// Contact of `cuboid` at `pose_box` with the unbounded plane at `pose_plane` (flipped when
/// `side < 0`): `None` when no volume is below the plane.
// Inline into `box_plane::contact`, so the contact is not returned through one more copy.
#[inline]
pub(crate) fn contact(
    cuboid: &Cuboid,
    pose_box: &Isometry3,
    side: f64,
    pose_plane: &Isometry3,
) -> Option<PairContact> {
    // Working frame: world axes from the plane's origin, lengths divided by `unit` (a power
    // of two, so the scaling is exact). Only the outward normal `n` depends on the plane's
    // rotation, so nothing is turned into the plane's frame and back.
    let unit = unit_for(cuboid.half_extents().norm());
    let normal = pose_plane.rotation * Vector3::new(0.0, 0.0, side);
    let rotation = pose_box.rotation.to_rotation_matrix();
    let axes = rotation.matrix();
    let center = (pose_box.translation.vector - pose_plane.translation.vector
        + axes * cuboid.center().coords)
        / unit;
    let half = cuboid.half_extents() / unit;
    let mut up = [
        axes.column(0) * half.x,
        axes.column(1) * half.y,
        axes.column(2) * half.z,
    ];
    let height = normal.dot(&center);
    let mut rise = [0.0; 3];
    for (axis, r) in up.iter_mut().zip(rise.iter_mut()) {
        *r = normal.dot(axis);
        if *r < 0.0 {
            *axis = -*axis;
            *r = -*r;
        }
    }
    // No corner below the plane: no contact.
    if height - (rise[0] + rise[1] + rise[2]) >= 0.0 {
        return None;
    }
    // The prism's axis `m`, of largest rise (positive: the axes are orthonormal), and `i < j`.
    let (i, j, m) = if rise[0] >= rise[1] && rise[0] >= rise[2] {
        (1, 2, 0)
    } else if rise[1] >= rise[2] {
        (0, 2, 1)
    } else {
        (0, 1, 2)
    };
    // The highest corner's height; with the normal along a world axis it is summed as the
    // corner's own coordinate would be (the centre, then the axes in order), so a top face
    // exactly flush with the plane tests as flush.
    let top = height + rise[0] + rise[1] + rise[2];
    let (g, [a, b, c], area) = if top <= 0.0 {
        let [x, y, z] = [half.x, half.y, half.z];
        (center, [0.5; 3], 2.0 * (x * y + y * z + z * x))
    } else {
        wet_prism(&up, rise, (i, j, m), height, &normal, &center)?
    };
    // Along `−n` a box coordinate `x_k` falls at `2r_k/|E_k|²` per unit length (`|E_k|² =
    // 4h_k²`), so from `g` the line leaves through the bottom face that comes first,
    // `min_k 2x_k·h_k²/r_k` over the axes that rise (`m` always does). The least is found by
    // cross-multiplying, so only it is divided out.
    let (mut reach, mut rate) = (c * half[m] * half[m], rise[m]);
    for (x, k) in [(a, i), (b, j)] {
        let (to_face, r) = (x * half[k] * half[k], rise[k]);
        if r > 0.0 && to_face * rate < reach * r {
            (reach, rate) = (to_face, r);
        }
    }
    let exit = (2.0 * reach / rate).max(0.0);
    let below = normal.dot(&g);
    let g_w = pose_plane.translation.vector + g * unit;
    Some(PairContact {
        point_a: Point3::from(g_w - (exit * unit) * normal),
        point_b: Point3::from(g_w - (below * unit) * normal),
        normal,
        depth: (exit - below) * unit,
        area: area * unit * unit,
    })
}

/// The part of the box below the plane when a corner lies on each side: the prism along
/// axis `m` over the unit square in `(a, b)` (see the module doc), from the half axes `up`
/// turned to rise, their `rise`s along the outward `normal` and the centre's `height` above
/// the plane (`center` in the working frame). Its centroid, its `(a, b, c)` in the prism's
/// coordinates and the section's area; `None` when no volume is below.
// Inlined, as its caller is, so the moments stay in registers.
#[inline(always)]
fn wet_prism(
    up: &[Vector3; 3],
    rise: [f64; 3],
    (i, j, m): (usize, usize, usize),
    height: f64,
    normal: &Vector3,
    center: &Vector3,
) -> Option<(Vector3, [f64; 3], f64)> {
    let (step_i, step_j, step_m) = (2.0 * rise[i], 2.0 * rise[j], 2.0 * rise[m]);
    let per_step = 1.0 / step_m;
    // The cap over the square: `p = p₀ + a·E_i + b·E_j + N·E_m` on the plane, so
    // `|∂_a p × ∂_b p|` is the component along `n` of the cross product of
    // `E_i − (r_i/r_m)·E_m` and `E_j − (r_j/r_m)·E_m`, from three triple products.
    let (cross_j, cross_m) = (up[j].cross(normal), up[m].cross(normal));
    let (rho_i, rho_j) = (step_i * per_step, step_j * per_step);
    let slope = 4.0
        * (up[i].dot(&cross_j) - rho_j * up[i].dot(&cross_m) - rho_i * up[m].dot(&cross_j)).abs();
    // Depths below the plane at the square's corners on the bottom face (`c = 0`) and the
    // top (`c = 1`), each from its face centre's height and then the two smaller rises
    // (see the module's precision notes).
    let (ri, rj, rm) = (rise[i], rise[j], rise[m]);
    let (bottom_face, top_face) = (height - rm, height + rm);
    let levels = [-ri - rj, ri - rj, ri + rj, rj - ri];
    let bottom = [
        -(bottom_face + levels[0]),
        -(bottom_face + levels[1]),
        -(bottom_face + levels[2]),
        -(bottom_face + levels[3]),
    ];
    let z = moments(clip_square(bottom));
    let (o, strip) = if -(top_face + levels[0]) > 0.0 {
        // The top face dips below too: its part is taken off, and the section is the
        // strip between the two lines, cut out directly rather than as a difference of
        // two areas that may nearly cancel.
        let top = [
            -(top_face + levels[0]),
            -(top_face + levels[1]),
            -(top_face + levels[2]),
            -(top_face + levels[3]),
        ];
        (moments(clip_square(top)), strip_area(bottom, top))
    } else {
        (Moments::default(), z.area)
    };
    let wet = z.first - o.first;
    if wet <= 0.0 {
        return None;
    }
    // The centroid `(∫a·w, ∫b·w, ∫w²/2)/∫w` in the scaled moments.
    let per_wet = 1.0 / wet;
    let a = (z.a - o.a) * (0.25 * per_wet);
    let b = (z.b - o.b) * (0.25 * per_wet);
    let c = ((z.second - o.second) * (0.125 * per_step) - o.first) * per_wet;
    let corner = center - up[0] - up[1] - up[2];
    let g = corner + 2.0 * (a * up[i] + b * up[j] + c * up[m]);
    Some((g, [a, b, c], 0.5 * slope * strip))
}

#[cfg(test)]
mod tests {
    use crate::kernel::PairContact;
    use crate::pairs::box_plane;
    use contact_core::geometry::{Cuboid, Plane};
    use contact_core::{Isometry3, UnitQuaternion, Vector3};
    use nalgebra::{Quaternion, Translation3};
    use std::f64::consts::FRAC_PI_4;

    /// The largest difference between two contacts over points, normal, depth and area.
    fn difference(a: &PairContact, b: &PairContact) -> f64 {
        [
            (a.point_a - b.point_a).norm(),
            (a.point_b - b.point_b).norm(),
            (a.normal - b.normal).norm(),
            (a.depth - b.depth).abs(),
            (a.area - b.area).abs(),
        ]
        .into_iter()
        .fold(0.0, f64::max)
    }

    /// The closed form and the general clipping (a bounded plane far wider than the box) at
    /// `pose_box` in the plane's frame `pose_plane`, on the side `side`: both `None`, or the
    /// closed form's answer and the two's difference.
    fn against_clipping(
        cuboid: &Cuboid,
        pose_box: &Isometry3,
        side: f64,
        pose_plane: &Isometry3,
    ) -> Option<(PairContact, f64)> {
        let wide = Plane::bounded(-1e3, 1e3, -1e3, 1e3).unwrap();
        let pose_box = pose_plane * pose_box;
        let closed = box_plane::contact(cuboid, &pose_box, &Plane::unbounded(), side, pose_plane);
        let clipped = box_plane::contact(cuboid, &pose_box, &wide, side, pose_plane);
        match (closed, clipped) {
            (None, None) => None,
            (Some(a), Some(b)) => Some((a, difference(&a, &b))),
            other => panic!("{pose_box:?} side {side}: {other:?}"),
        }
    }

    /// The rotations whose matrices are exact: the identity and the two cyclic permutations
    /// of the axes, so each box axis in turn is the vertical one and the others are exactly
    /// level (faces flush with the plane when the height says so).
    fn exact_turns() -> [UnitQuaternion; 3] {
        let cyclic = UnitQuaternion::new_unchecked(Quaternion::new(0.5, 0.5, 0.5, 0.5));
        [UnitQuaternion::identity(), cyclic, cyclic * cyclic]
    }

    /// A half turn about x, exactly: heights change sign and nothing else.
    fn over() -> Isometry3 {
        Isometry3::from_parts(
            Translation3::identity(),
            UnitQuaternion::new_unchecked(Quaternion::new(0.0, 1.0, 0.0, 0.0)),
        )
    }

    /// Each axis as the prism's, with zero, one or two axes level (faces and edges parallel to
    /// the plane), at heights from a face, an edge or a corner on the plane (no contact)
    /// through a sliver, half depth and a top face or edge at the plane (the whole box) to
    /// fully sunk: the closed form gives the general clipping's answer.
    #[test]
    fn flush_faces_and_edges_agree_with_general_clipping() {
        let cuboid = Cuboid::centered(0.5, 0.25, 1.0).unwrap();
        let half = cuboid.half_extents();
        let edge = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), FRAC_PI_4);
        let tilt = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
        let mut contacts = 0;
        for turn in exact_turns() {
            for (q, exact) in [(turn, true), (turn * edge, false), (turn * tilt, false)] {
                let r = q.to_rotation_matrix();
                let extent: f64 = (0..3).map(|k| (r[(2, k)] * half[k]).abs()).sum();
                for t in [
                    1.0f64,
                    1.0 - 1e-12,
                    0.5,
                    0.0,
                    -0.5,
                    -(1.0 - 1e-12),
                    -1.0,
                    -3.0,
                ] {
                    // Touching, or a face or an edge flush at the top (the whole box), only
                    // where the heights are exact; elsewhere either path may round it either
                    // way.
                    if t.abs() == 1.0 && !exact {
                        continue;
                    }
                    let pose = Isometry3::from_parts(Translation3::new(0.1, -0.2, t * extent), q);
                    for side in [1.0, -1.0] {
                        // The flipped plane sees the box turned over about x, exactly.
                        let pose = if side > 0.0 { pose } else { over() * pose };
                        let found = against_clipping(&cuboid, &pose, side, &Isometry3::identity());
                        assert_eq!(found.is_none(), t == 1.0, "{pose:?} side {side}");
                        if let Some((c, d)) = found {
                            contacts += 1;
                            assert!(d < 1e-14, "{pose:?} side {side}: {c:?} differs by {d:e}");
                        }
                    }
                }
            }
        }
        assert_eq!(contacts, 3 * 2 * (7 + 6 + 6));
    }

    /// Where the line from `g` (box frame, half extents `half`) along `d` leaves the box.
    fn box_exit(half: &Vector3, g: &Vector3, d: &Vector3) -> f64 {
        (0..3)
            .filter(|&k| d[k] != 0.0)
            .map(|k| (half[k] * d[k].signum() - g[k]) / d[k])
            .fold(f64::INFINITY, f64::min)
    }

    /// The box `half` turned by `q` with its lowest corner (`top`: its highest) a height `e`
    /// beyond the plane z = 0, that corner's neighbours farther than `e` from it: the box's
    /// centre and, independently of the engine, `[x, y, depth, area]`: the foot of the
    /// centroid of the part below on the plane, the depth along z from there, the section's
    /// area. A tetrahedron cuts off that corner: its centroid is the mean of the corner and
    /// the three edge crossings, the section their triangle; with `top`, the part below is the
    /// box less the tetrahedron.
    fn corner_cut(
        half: &Vector3,
        q: &UnitQuaternion,
        e: f64,
        top: bool,
    ) -> Option<(Vector3, [f64; 4])> {
        let r = q.to_rotation_matrix();
        let corner = |s: [f64; 3]| r * Vector3::new(s[0] * half.x, s[1] * half.y, s[2] * half.z);
        let mut all = Vec::new();
        for sx in [-1.0, 1.0] {
            for sy in [-1.0, 1.0] {
                for sz in [-1.0, 1.0] {
                    all.push([sx, sy, sz]);
                }
            }
        }
        // Upside down for `top`: the corner beyond the plane first.
        let up = if top { -1.0 } else { 1.0 };
        all.sort_by(|a, b| (up * corner(*a).z).total_cmp(&(up * corner(*b).z)));
        let (cut, v0) = (all[0], corner(all[0]));
        if up * (corner(all[1]).z - v0.z) <= e {
            return None;
        }
        let center = Vector3::new(0.0, 0.0, -up * e - v0.z);
        let mut crossings = [Vector3::zeros(); 3];
        for (axis, p) in crossings.iter_mut().enumerate() {
            let mut s = cut;
            s[axis] = -s[axis];
            let v = corner(s);
            *p = (v - v0) * (e / (up * (v.z - v0.z)));
        }
        // From the cut corner, then from the box's centre.
        let tip = crossings.iter().sum::<Vector3>() / 4.0;
        let area = 0.5
            * (crossings[1] - crossings[0])
                .cross(&(crossings[2] - crossings[0]))
                .norm();
        let g = if top {
            let tet = crossings[0].dot(&crossings[1].cross(&crossings[2])).abs() / 6.0;
            let rest = 8.0 * half.x * half.y * half.z - tet;
            -(v0 + tip) * (tet / rest)
        } else {
            v0 + tip
        };
        let exit = box_exit(half, &(r.transpose() * g), &(r.transpose() * -Vector3::z()));
        let height = center.z + g.z;
        Some((
            center,
            [center.x + g.x, center.y + g.y, exit - height, area],
        ))
    }

    /// One corner below the plane, or one above it, by `e` (from a sliver of 1e-12 of the
    /// box's size to a tenth), under many tilts, on both sides of the plane, against
    /// [`corner_cut`]. Errors are held relative to the answer's own size plus the box's
    /// rounding (1e-16 of its size, so `1e-14/e` relative at a height `e`).
    #[test]
    fn one_corner_beyond_the_plane_is_a_tetrahedron_cut() {
        let cuboid = Cuboid::centered(0.7, 0.4, 1.1).unwrap();
        let half = cuboid.half_extents();
        let mut cases = 0;
        for k in 0..60 {
            let t = f64::from(k);
            let q = UnitQuaternion::from_euler_angles(0.37 * t + 0.1, 0.91 * t, 0.13 * t);
            for top in [false, true] {
                for e in [1e-12, 1e-9, 1e-6, 1e-3, 0.1] {
                    let Some((center, [x, y, depth, area])) = corner_cut(&half, &q, e, top) else {
                        continue;
                    };
                    for side in [1.0, -1.0] {
                        let pose = Isometry3::from_parts(Translation3::from(center), q);
                        let pose = if side > 0.0 { pose } else { over() * pose };
                        let c = box_plane::contact(
                            &cuboid,
                            &pose,
                            &Plane::unbounded(),
                            side,
                            &Isometry3::identity(),
                        )
                        .unwrap();
                        let mirror = if side > 0.0 { 1.0 } else { -1.0 };
                        let scale = if top { 1.0 } else { e };
                        let tolerance = 1e-11 + 1e-14 / e;
                        let foot =
                            ((c.point_b.x - x).powi(2) + (c.point_b.y - mirror * y).powi(2)).sqrt();
                        assert!(
                            foot <= tolerance * scale,
                            "{pose:?} {e}: {c:?} foot off by {foot:e}"
                        );
                        assert_eq!((c.point_b.z, c.normal.z), (0.0, side), "{c:?}");
                        assert!(
                            (c.depth - depth).abs() <= tolerance * depth,
                            "{pose:?} {e}: {c:?} vs depth {depth}"
                        );
                        assert!(
                            (c.area - area).abs() <= tolerance * area,
                            "{pose:?} {e}: {c:?} vs area {area}"
                        );
                        cases += 1;
                    }
                }
            }
        }
        assert!(cases > 400, "{cases}");
    }
}
