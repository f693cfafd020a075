//! Characterization rows and exact checks of the boundary–boundary 2-D pairs (curve–curve,
//! curve–line, arc–arc, arc–curve, arc–line) against oracles written here: polygon overlap
//! by hand, the circle–circle closed form, and a brute-force polygonization.

use super::{Case, ITERATIVE_BOUND, Row, run};
use crate::common::{Expected, Rng, instance, one};
use contact_core::geometry::{Arc, Curve, CurvePoints, Line};
use contact_core::{Geometry, Isometry3, Point2, Point3, UnitQuaternion, Vector3};
use nalgebra::Translation3;
use std::f64::consts::{PI, TAU};
use std::sync::Arc as Shared;

/// A closed (or open) polyline through `points`.
pub(crate) fn polyline(points: &[[f64; 2]], closed: bool) -> Geometry {
    let points: Vec<Point2> = points.iter().map(|p| Point2::new(p[0], p[1])).collect();
    Geometry::Curve(Shared::new(
        Curve::new(&points, 2, closed, CurvePoints::Control).unwrap(),
    ))
}

/// The counter-clockwise rectangle `[x0, x1] × [y0, y1]` (material inside).
pub(crate) fn rectangle(x0: f64, x1: f64, y0: f64, y1: f64) -> Geometry {
    polyline(&[[x0, y0], [x1, y0], [x1, y1], [x0, y1]], true)
}

/// The pose turning by `angle` about z and moving to `(x, y)`.
pub(crate) fn planar_pose(x: f64, y: f64, angle: f64) -> Isometry3 {
    Isometry3::from_parts(
        Translation3::new(x, y, 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), angle),
    )
}

/// The V from `(−2, 1)` down to `(0, −h)` and up to `(2, 1)`: its material is above it.
pub(crate) fn v_shape(h: f64) -> Geometry {
    polyline(&[[-2.0, 1.0], [0.0, -h], [2.0, 1.0]], false)
}

/// A convex closed cubic through points of `r(θ) = 1 + 0.1 cos 2θ`, scaled by `scale`.
pub(crate) fn cubic_blob(scale: f64) -> Curve {
    let points: Vec<Point2> = (0..12)
        .map(|k| {
            let t = TAU * k as f64 / 12.0;
            let r = scale * (1.0 + 0.1 * (2.0 * t).cos());
            Point2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    Curve::new(&points, 4, true, CurvePoints::Interpolated).unwrap()
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let mut rows = same_kind_rows(rng);
    rows.extend(mixed_rows(rng));
    rows
}

/// The rows of curve–curve (2-D, order 2), arc–arc (2-D).
fn same_kind_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                rng,
                40,
                "curve–curve (2-D, order 2)",
                "square 2×2 against a rectangle entering its right side",
                "overlap rectangle by hand",
                |rng| {
                    let x1 = rng.uniform(0.2, 1.8);
                    let (y0, h) = (rng.uniform(0.2, 0.8), rng.uniform(0.3, 0.9));
                    let gy = y0 + 0.5 * h;
                    Some(Case {
                        i: instance(rectangle(0.0, 2.0, 0.0, 2.0)),
                        j: instance(rectangle(x1, x1 + 3.0, y0, y0 + h)),
                        pose_i: Isometry3::identity(),
                        pose_j: Isometry3::identity(),
                        expected: Expected {
                            point_i: Point3::new(2.0, gy, 0.0),
                            point_j: Point3::new(x1, gy, 0.0),
                            normal: -Vector3::x(),
                            depth: 2.0 - x1,
                        },
                        length: 3.0,
                    })
                },
            )
        },
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                rng,
                40,
                "arc–arc (2-D)",
                "arcs of 1.6π with their gaps facing away, lens of the full circles",
                "circle–circle closed form",
                |rng| {
                    let (ra, rb) = (rng.uniform(0.3, 2.0), rng.uniform(0.3, 2.0));
                    let d = rng.uniform((ra - rb).abs() + 0.05, ra + rb - 0.02);
                    // Half-angles of the lens arcs seen from each centre must stay out of the
                    // gaps (±0.2π about the far side).
                    let cos_a = (d * d + ra * ra - rb * rb) / (2.0 * d * ra);
                    let cos_b = (d * d + rb * rb - ra * ra) / (2.0 * d * rb);
                    if cos_a.acos() > 0.75 * PI || cos_b.acos() > 0.75 * PI {
                        return None;
                    }
                    let range = 1.6 * PI;
                    let phi = rng.uniform(0.0, TAU);
                    let u = Vector3::new(phi.cos(), phi.sin(), 0.0);
                    let gap = PI + 0.5 * range;
                    Some(Case {
                        i: instance(Geometry::Arc(Arc::new(ra, range).unwrap())),
                        j: instance(Geometry::Arc(Arc::new(rb, range).unwrap())),
                        pose_i: planar_pose(d * u.x, d * u.y, phi - gap),
                        pose_j: planar_pose(0.0, 0.0, phi + PI - gap),
                        expected: crate::oracles::sphere_sphere(ra, rb, d, &u),
                        length: ra.max(rb),
                    })
                },
            )
        },
    ]
}

/// The rows of curve–line (2-D, order 2), arc–line (2-D), arc–curve (2-D).
fn mixed_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                rng,
                40,
                "curve–line (2-D, order 2)",
                "a V of depth h ∈ [0.1, 0.9] dipping below the line",
                "triangle by hand",
                |rng| {
                    let h = rng.uniform(0.1, 0.9);
                    let x = rng.uniform(-3.0, 3.0);
                    Some(Case {
                        i: instance(v_shape(h)),
                        j: instance(Geometry::Line(Line::unbounded())),
                        pose_i: planar_pose(x, 0.0, 0.0),
                        pose_j: Isometry3::identity(),
                        expected: Expected {
                            point_i: Point3::new(x, -h, 0.0),
                            point_j: Point3::new(x, 0.0, 0.0),
                            normal: Vector3::y(),
                            depth: h,
                        },
                        length: 2.0,
                    })
                },
            )
        },
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                rng,
                40,
                "arc–line (2-D)",
                "arc of 1.5π, gap up, centre height ∈ (−0.5R, 0.5R)",
                "circular segment: centroid on the vertical through the centre",
                |rng| {
                    let r = rng.uniform(0.5, 2.0);
                    let (x, y) = (rng.uniform(-2.0, 2.0), rng.uniform(-0.5 * r, 0.5 * r));
                    let range = 1.5 * PI;
                    // Gap centred on +y: the arc starts at π/2 + π/4.
                    Some(Case {
                        i: instance(Geometry::Arc(Arc::new(r, range).unwrap())),
                        j: instance(Geometry::Line(Line::unbounded())),
                        pose_i: planar_pose(x, y, 0.75 * PI),
                        pose_j: Isometry3::identity(),
                        expected: Expected {
                            point_i: Point3::new(x, y - r, 0.0),
                            point_j: Point3::new(x, 0.0, 0.0),
                            normal: Vector3::y(),
                            depth: r - y,
                        },
                        length: r,
                    })
                },
            )
        },
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                rng,
                40,
                "arc–curve (2-D)",
                "full arc (a circle) crossing the top edge of a 6×3 rectangle (ORDER 2)",
                "circular segment: centroid on the vertical through the centre",
                |rng| {
                    let r = rng.uniform(0.5, 1.5);
                    let (x, y) = (rng.uniform(-1.0, 1.0), rng.uniform(-0.7 * r, 0.7 * r));
                    Some(Case {
                        i: instance(Geometry::Arc(Arc::new(r, TAU).unwrap())),
                        j: instance(rectangle(-3.0, 3.0, -3.0, 0.0)),
                        pose_i: planar_pose(x, y, rng.uniform(0.0, TAU)),
                        pose_j: Isometry3::identity(),
                        expected: Expected {
                            point_i: Point3::new(x, y - r, 0.0),
                            point_j: Point3::new(x, 0.0, 0.0),
                            normal: Vector3::y(),
                            depth: r - y,
                        },
                        length: 3.0,
                    })
                },
            )
        },
    ]
}

#[test]
fn two_squares_overlapping_in_a_rectangle_give_its_area_centroid_and_length() {
    // Overlap [1.25, 2] × [0.5, 1.5]: length (the chord of I inside J) 1, depth 0.75.
    let c = one(
        &instance(rectangle(0.0, 2.0, 0.0, 2.0)),
        &instance(rectangle(1.25, 4.0, 0.5, 1.5)),
        &Isometry3::identity(),
        &Isometry3::identity(),
    );
    assert!((c.normal_w - -Vector3::x()).norm() < 1e-12, "{c:?}");
    assert!((c.penetration - 0.75).abs() < 1e-12, "{c:?}");
    assert!((c.area - 1.0).abs() < 1e-12, "{c:?}");
    assert!(
        (c.point_i_w - Point3::new(2.0, 1.0, 0.0)).norm() < 1e-12,
        "{c:?}"
    );
    assert!(
        (c.point_j_w - Point3::new(1.25, 1.0, 0.0)).norm() < 1e-12,
        "{c:?}"
    );
}

#[test]
fn a_square_crossing_a_corner_gives_the_diagonal_normal() {
    // J's corner region [1, 2] × [1, 2] inside I: the chord of I inside J runs from (2, 1)
    // to (1, 2) along I's boundary, S = (1, 1), so n = −(1, 1)/√2; the centroid (1.5, 1.5),
    // I's point on the ray along −n is the corner (2, 2), J's is (1, 1).
    let c = one(
        &instance(rectangle(0.0, 2.0, 0.0, 2.0)),
        &instance(rectangle(1.0, 3.0, 1.0, 3.0)),
        &Isometry3::identity(),
        &Isometry3::identity(),
    );
    let n = -Vector3::new(1.0, 1.0, 0.0) / 2f64.sqrt();
    assert!((c.normal_w - n).norm() < 1e-12, "{c:?}");
    assert!((c.area - 2f64.sqrt()).abs() < 1e-12, "{c:?}");
    assert!(
        (c.point_i_w - Point3::new(2.0, 2.0, 0.0)).norm() < 1e-12,
        "{c:?}"
    );
    assert!(
        (c.point_j_w - Point3::new(1.0, 1.0, 0.0)).norm() < 1e-12,
        "{c:?}"
    );
    assert!((c.penetration - 2f64.sqrt()).abs() < 1e-12, "{c:?}");
}

#[test]
fn a_w_shape_below_a_line_gives_two_contacts() {
    // Two V tips of depth 0.5 at x = ±1: two triangles.
    let w = polyline(
        &[
            [-2.0, 1.0],
            [-1.0, -0.5],
            [0.0, 1.0],
            [1.0, -0.5],
            [2.0, 1.0],
        ],
        false,
    );
    let mut found = crate::common::query(
        &instance(w),
        &instance(Geometry::Line(Line::unbounded())),
        &Isometry3::identity(),
        &Isometry3::identity(),
    );
    found.sort_by(|a, b| a.point_i_w.x.total_cmp(&b.point_i_w.x));
    assert_eq!(found.len(), 2, "{found:?}");
    for (c, x) in found.iter().zip([-1.0, 1.0]) {
        assert!(
            (c.point_i_w - Point3::new(x, -0.5, 0.0)).norm() < 1e-12,
            "{c:?}"
        );
        assert!(
            (c.point_j_w - Point3::new(x, 0.0, 0.0)).norm() < 1e-12,
            "{c:?}"
        );
        assert!((c.penetration - 0.5).abs() < 1e-12);
    }
}

/// The polygon of the blob at `n` equally spaced parameters.
fn polygonize(curve: &Curve, n: usize) -> Vec<Point2> {
    let [u0, u1] = curve.domain();
    (0..n)
        .map(|k| curve.point(u0 + (u1 - u0) * k as f64 / n as f64))
        .collect()
}

#[test]
fn a_cubic_blob_against_a_line_matches_a_million_point_polygonization() {
    // Oracle: the blob as a 10⁶-gon, clipped to y ≤ 0 (the line's material) by hand; its
    // area and centroid by the shoelace formula; the contact points on the vertical through
    // the centroid (the normal is +y: the chord of the blob below the line is horizontal).
    // Error of the polygon: sagitta κh²/8 with h ≈ 7·10⁻⁶ and κ ≲ 2, about 1e-11, so the
    // centroid agrees to ~1e-11 and depth and points to the same order.
    let curve = cubic_blob(1.0);
    let lift = 0.6;
    let polygon = polygonize(&curve, 1_000_000);
    let shifted: Vec<Point2> = polygon
        .iter()
        .map(|p| Point2::new(p.x, p.y + lift))
        .collect();
    let mut clipped: Vec<Point2> = Vec::new();
    for k in 0..shifted.len() {
        let (p, q) = (shifted[k], shifted[(k + 1) % shifted.len()]);
        if p.y <= 0.0 {
            clipped.push(p);
        }
        if (p.y <= 0.0) != (q.y <= 0.0) {
            let t = p.y / (p.y - q.y);
            clipped.push(Point2::new(p.x + t * (q.x - p.x), 0.0));
        }
    }
    let crossings: Vec<f64> = clipped.iter().filter(|p| p.y == 0.0).map(|p| p.x).collect();
    assert_eq!(crossings.len(), 2);
    let chord = (crossings[0] - crossings[1]).abs();
    let (mut a2, mut mx) = (0.0, 0.0);
    for k in 0..clipped.len() {
        let (p, q) = (clipped[k], clipped[(k + 1) % clipped.len()]);
        let cross = p.x * q.y - q.x * p.y;
        a2 += cross;
        mx += (p.x + q.x) * cross;
    }
    let gx = mx / (3.0 * a2);
    // The lowest point of the polygon on the vertical x = gx.
    let mut bottom = f64::INFINITY;
    for k in 0..shifted.len() {
        let (p, q) = (shifted[k], shifted[(k + 1) % shifted.len()]);
        if (p.x - gx) * (q.x - gx) <= 0.0 && p.x != q.x {
            let t = (gx - p.x) / (q.x - p.x);
            bottom = bottom.min(p.y + t * (q.y - p.y));
        }
    }
    let c = one(
        &instance(Geometry::Curve(Shared::new(curve))),
        &instance(Geometry::Line(Line::unbounded())),
        &planar_pose(0.0, lift, 0.0),
        &Isometry3::identity(),
    );
    assert!((c.normal_w - Vector3::y()).norm() < 1e-12, "{c:?}");
    assert!(
        (c.point_j_w - Point3::new(gx, 0.0, 0.0)).norm() < 1e-9,
        "{c:?} vs {gx}"
    );
    assert!(
        (c.point_i_w - Point3::new(gx, bottom, 0.0)).norm() < 1e-9,
        "{c:?}"
    );
    assert!((c.penetration + bottom).abs() < 1e-9, "{c:?}");
    assert!((c.area - chord).abs() < 1e-9, "{c:?} vs {chord}");
}

#[test]
fn full_arcs_agree_with_the_circle_circle_answer_including_the_chord() {
    use contact_core::geometry::Circle;
    let mut rng = Rng::new(21);
    for _ in 0..50 {
        let (ra, rb) = (rng.uniform(0.3, 2.0), rng.uniform(0.3, 2.0));
        let d = rng.uniform((ra - rb).abs() + 0.01, ra + rb - 0.01);
        let phi = rng.uniform(0.0, TAU);
        let pose_i = planar_pose(d * phi.cos(), d * phi.sin(), rng.uniform(0.0, TAU));
        let world = rng.pose(3.0);
        let arcs = one(
            &instance(Geometry::Arc(Arc::new(ra, TAU).unwrap())),
            &instance(Geometry::Arc(Arc::new(rb, TAU).unwrap())),
            &(world * pose_i),
            &world,
        );
        let circles = one(
            &instance(Geometry::Circle(Circle::new(ra).unwrap())),
            &instance(Geometry::Circle(Circle::new(rb).unwrap())),
            &(world * pose_i),
            &world,
        );
        // The length is the common chord (SPEC §4 here: |S| = |P₂ − P₁|); circles.rs widens it
        // to a diameter once a centre is inside the other disc, so only then do they differ.
        let x = (d * d + rb * rb - ra * ra) / (2.0 * d);
        let chord = 2.0 * ((rb - x) * (rb + x)).sqrt();
        if x >= 0.0 && d - x >= 0.0 {
            assert!(
                (circles.area - chord).abs() < 1e-12,
                "{circles:?} vs {chord}"
            );
        }
        let expected = contact_core::Contact {
            area: chord,
            ..circles
        };
        let length = ra.max(rb);
        crate::common::assert_close(&arcs, &expected, length, length, 1e-12, "arc–arc lens");
    }
}

#[test]
fn flipped_arcs_and_curves_are_holes() {
    // I: the rectangle [1, 3] × [−0.5, 0.5]; J: a hole of radius 2 (a flipped full arc) or
    // the hole [−2, 2]² (a flipped square). The part of I outside J's hole pushes I inwards
    // (−x); on the centroid's line y = 0 the points are (3, 0) and (2, 0), depth 1; the
    // chord of I in J's material runs from the lower to the upper crossing: length 1.
    let rect = instance(rectangle(1.0, 3.0, -0.5, 0.5));
    for hole in [
        instance(Geometry::Arc(Arc::new(2.0, TAU).unwrap())).flipped(),
        instance(rectangle(-2.0, 2.0, -2.0, 2.0)).flipped(),
    ] {
        let c = one(&rect, &hole, &Isometry3::identity(), &Isometry3::identity());
        assert!((c.normal_w + Vector3::x()).norm() < 1e-12, "{c:?}");
        assert!(
            (c.point_i_w - Point3::new(3.0, 0.0, 0.0)).norm() < 1e-12,
            "{c:?}"
        );
        assert!(
            (c.point_j_w - Point3::new(2.0, 0.0, 0.0)).norm() < 1e-12,
            "{c:?}"
        );
        assert!(
            (c.penetration - 1.0).abs() < 1e-12 && (c.area - 1.0).abs() < 1e-12,
            "{c:?}"
        );
    }
}

#[test]
fn a_curve_whose_marker_z_is_reversed_keeps_its_material() {
    // Rotating the rectangle [0, 2]² by π about x and lifting it by 2 puts it back on
    // [0, 2]², traversed clockwise with binormal −z: the same solid, the same contact.
    let mirrored = Isometry3::from_parts(
        Translation3::new(0.0, 2.0, 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), PI),
    );
    let j = instance(rectangle(1.25, 4.0, 0.5, 1.5));
    let i = instance(rectangle(0.0, 2.0, 0.0, 2.0));
    let plain = one(&i, &j, &Isometry3::identity(), &Isometry3::identity());
    let flipped_frame = one(&i, &j, &mirrored, &Isometry3::identity());
    crate::common::assert_close(&flipped_frame, &plain, 2.0, 2.0, 1e-12, "mirrored marker");
}

/// Points of an ellipse at sorted random angles: a convex counter-clockwise polygon.
fn convex_polygon(rng: &mut Rng, centre: [f64; 2]) -> Vec<[f64; 2]> {
    let (a, b, turn) = (
        rng.uniform(0.5, 1.5),
        rng.uniform(0.5, 1.5),
        rng.uniform(0.0, TAU),
    );
    let count = 5 + (rng.uniform(0.0, 5.0) as usize);
    let mut angles: Vec<f64> = (0..count).map(|_| rng.uniform(0.0, TAU)).collect();
    angles.sort_by(f64::total_cmp);
    angles
        .iter()
        .map(|t| {
            let (x, y) = (a * t.cos(), b * t.sin());
            let (c, s) = (turn.cos(), turn.sin());
            [centre[0] + c * x - s * y, centre[1] + s * x + c * y]
        })
        .collect()
}

fn cross(o: [f64; 2], p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])
}

/// Distance of `p` from the polygon's boundary.
fn boundary_distance(poly: &[[f64; 2]], p: [f64; 2]) -> f64 {
    (0..poly.len())
        .map(|k| {
            let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
            let d = [b[0] - a[0], b[1] - a[1]];
            let t = (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1]))
                .clamp(0.0, 1.0);
            ((p[0] - a[0] - t * d[0]).powi(2) + (p[1] - a[1] - t * d[1]).powi(2)).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn random_convex_polygons_match_clipping_by_hand() {
    // Oracle, independent of the engine: S = Σ over I's edges of the part inside convex J
    // (Cyrus–Beck clipping of each edge by J's half-planes), turned by −90°; the region's
    // centroid by Sutherland–Hodgman clipping of I by J and the shoelace formula.
    let mut rng = Rng::new(0xC11F);
    let mut checked = 0;
    while checked < 100 {
        let i = convex_polygon(&mut rng, [0.0, 0.0]);
        let centre = [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)];
        let j = convex_polygon(&mut rng, centre);
        let mut s = [0.0, 0.0];
        for k in 0..i.len() {
            let (a, b) = (i[k], i[(k + 1) % i.len()]);
            let (mut t0, mut t1) = (0.0f64, 1.0f64);
            for m in 0..j.len() {
                let (p, q) = (j[m], j[(m + 1) % j.len()]);
                let (fa, fb) = (cross(p, q, a), cross(p, q, b));
                if fa < 0.0 && fb < 0.0 {
                    t1 = -1.0;
                } else if fa < 0.0 {
                    t0 = t0.max(fa / (fa - fb));
                } else if fb < 0.0 {
                    t1 = t1.min(fa / (fa - fb));
                }
            }
            if t1 > t0 {
                let d = [(t1 - t0) * (b[0] - a[0]), (t1 - t0) * (b[1] - a[1])];
                s = [s[0] + d[1], s[1] - d[0]];
            }
        }
        let mut region = i.clone();
        for m in 0..j.len() {
            let (p, q) = (j[m], j[(m + 1) % j.len()]);
            let mut next = Vec::new();
            for k in 0..region.len() {
                let (a, b) = (region[k], region[(k + 1) % region.len()]);
                let (fa, fb) = (cross(p, q, a), cross(p, q, b));
                if fa >= 0.0 {
                    next.push(a);
                }
                if (fa >= 0.0) != (fb >= 0.0) {
                    let t = fa / (fa - fb);
                    next.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
                }
            }
            region = next;
        }
        let (mut a2, mut gx, mut gy) = (0.0, 0.0, 0.0);
        for k in 0..region.len() {
            let (p, q) = (region[k], region[(k + 1) % region.len()]);
            let c = p[0] * q[1] - q[0] * p[1];
            a2 += c;
            gx += (p[0] + q[0]) * c;
            gy += (p[1] + q[1]) * c;
        }
        let length = (s[0] * s[0] + s[1] * s[1]).sqrt();
        // Skip containment, no overlap and slivers (the oracle's own conditioning).
        if region.len() < 3 || a2 < 1e-3 || length < 1e-2 {
            continue;
        }
        let g = Point3::new(gx / (3.0 * a2), gy / (3.0 * a2), 0.0);
        let n = Vector3::new(-s[0], -s[1], 0.0) / length;
        let c = one(
            &instance(polyline(&i, true)),
            &instance(polyline(&j, true)),
            &Isometry3::identity(),
            &Isometry3::identity(),
        );
        let what = format!("I {i:?}\nJ {j:?}\n{c:?}");
        assert!((c.normal_w - n).norm() < 1e-12, "{what}");
        assert!((c.area - length).abs() < 1e-12, "{what}");
        for (p, poly) in [(c.point_i_w, &i), (c.point_j_w, &j)] {
            assert!((p - g).cross(&n).norm() < 1e-12, "{what}");
            assert!(boundary_distance(poly, [p.x, p.y]) < 1e-12, "{what}");
        }
        assert!(
            ((c.point_j_w - c.point_i_w).dot(&n) - c.penetration).abs() < 1e-12,
            "{what}"
        );
        checked += 1;
    }
}
