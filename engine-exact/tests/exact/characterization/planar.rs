//! Characterization rows of the 2-D pairs.

use super::{CURVE_SAMPLES, Case, ITERATIVE_BOUND, Row, SAMPLES, at, run};
use crate::common::{Expected, Rng, instance};
use crate::oracles;
use contact_core::geometry::{Arc, Circle, Curve, CurvePoints, Line};
use contact_core::{Geometry, Isometry3, Point2, Point3, UnitQuaternion, Vector3};
use nalgebra::Translation3;
use std::sync::Arc as Shared;

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let mut rows = circle_line_rows(rng);
    rows.extend(point_in_circle_rows(rng));
    rows.extend(polyline_rows(rng));
    rows.extend(spline_rows(rng));
    rows.extend(arc_rows(rng));
    rows
}

/// The rows of circle–circle (2-D), circle–line (2-D), point–line (2-D).
fn circle_line_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        run(
            rng,
            SAMPLES,
            "circle–circle (2-D)",
            "radii ∈ [0.2, 2], D ∈ (0.05, r_a + r_b)",
            "closed form",
            |rng| {
                let (ra, rb) = (rng.uniform(0.2, 2.0), rng.uniform(0.2, 2.0));
                let d = rng.uniform(0.05, ra + rb);
                let angle = rng.uniform(0.0, std::f64::consts::TAU);
                let u = Vector3::new(angle.cos(), angle.sin(), 0.0);
                Some(Case {
                    i: instance(Geometry::Circle(Circle::new(ra).unwrap())),
                    j: instance(Geometry::Circle(Circle::new(rb).unwrap())),
                    pose_i: Isometry3::from_parts(
                        Translation3::from(d * u),
                        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, 6.0)),
                    ),
                    pose_j: Isometry3::identity(),
                    expected: oracles::sphere_sphere(ra, rb, d, &u),
                    length: ra.max(rb),
                })
            },
        ),
        run(
            rng,
            SAMPLES,
            "circle–line (2-D)",
            "r ∈ [0.5, 2], centre height ∈ (−1.2r, r)",
            "closed form",
            |rng| {
                let r = rng.uniform(0.5, 2.0);
                let (x, d) = (rng.uniform(-3.0, 3.0), rng.uniform(-1.2 * r, r));
                Some(Case {
                    i: instance(Geometry::Circle(Circle::new(r).unwrap())),
                    j: instance(Geometry::Line(Line::unbounded())),
                    pose_i: at(x, d, 0.0),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::new(x, d - r, 0.0),
                        point_j: Point3::new(x, 0.0, 0.0),
                        normal: Vector3::y(),
                        depth: r - d,
                    },
                    length: r,
                })
            },
        ),
        run(
            rng,
            SAMPLES,
            "point–line (2-D)",
            "bounded line [−1, 2], point below it",
            "closed form",
            |rng| {
                let (x, y) = (rng.uniform(-1.0, 2.0), rng.uniform(-1.0, -1e-3));
                Some(Case {
                    i: instance(Geometry::Point),
                    j: instance(Geometry::Line(Line::bounded(-1.0, 2.0).unwrap())),
                    pose_i: at(x, y, 0.0),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::new(x, y, 0.0),
                        point_j: Point3::new(x, 0.0, 0.0),
                        normal: Vector3::y(),
                        depth: -y,
                    },
                    length: 3.0,
                })
            },
        ),
    ]
}

/// The rows of point–circle (2-D), circle–hole (2-D).
fn point_in_circle_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        run(
            rng,
            SAMPLES,
            "point–circle (2-D)",
            "point inside, D ∈ (0.01r, r)",
            "closed form",
            |rng| {
                let r = rng.uniform(0.5, 2.0);
                let d = rng.uniform(0.01 * r, r);
                let angle = rng.uniform(0.0, std::f64::consts::TAU);
                let u = Vector3::new(angle.cos(), angle.sin(), 0.0);
                Some(Case {
                    i: instance(Geometry::Point),
                    j: instance(Geometry::Circle(Circle::new(r).unwrap())),
                    pose_i: at(d * u.x, d * u.y, 0.0),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::from(d * u),
                        point_j: Point3::from(r * u),
                        normal: u,
                        depth: r - d,
                    },
                    length: r,
                })
            },
        ),
        run(
            rng,
            SAMPLES,
            "circle–hole (2-D)",
            "disc r_a in hole r_b > r_a, D ∈ (r_b − r_a, r_b)",
            "closed form",
            |rng| {
                let rb = rng.uniform(1.0, 2.0);
                let ra = rng.uniform(0.2, 0.9 * rb);
                let d = rng.uniform(rb - ra, rb);
                let angle = rng.uniform(0.0, std::f64::consts::TAU);
                let u = Vector3::new(angle.cos(), angle.sin(), 0.0);
                Some(Case {
                    i: instance(Geometry::Circle(Circle::new(ra).unwrap())),
                    j: instance(Geometry::Circle(Circle::new(rb).unwrap())).flipped(),
                    pose_i: at(d * u.x, d * u.y, 0.0),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::from(u * (d + ra)),
                        point_j: Point3::from(u * rb),
                        normal: -u,
                        depth: d + ra - rb,
                    },
                    length: rb,
                })
            },
        ),
    ]
}

/// The rows of point–curve (2-D).
fn polyline_rows(rng: &mut Rng) -> Vec<Row> {
    vec![run(
        rng,
        CURVE_SAMPLES,
        "point–curve (2-D)",
        "open polyline (ORDER 2), 6 random vertices, point inside a segment's material side",
        "closest point (Newton); oracle: segment projection",
        |rng| {
            let vertices: Vec<Point2> = (0..6)
                .map(|k| Point2::new(k as f64 + rng.uniform(-0.3, 0.3), rng.uniform(-0.5, 0.5)))
                .collect();
            let curve = Curve::new(&vertices, 2, false, CurvePoints::Control).unwrap();
            let p = Point2::new(rng.uniform(0.5, 4.5), rng.uniform(-0.8, 0.8));
            // Oracle: the nearest segment by projection; skip vertices (normal undefined).
            let mut best = (
                f64::INFINITY,
                Point2::origin(),
                nalgebra::Vector2::zeros(),
                0.0,
            );
            for w in vertices.windows(2) {
                let d = w[1] - w[0];
                let t = ((p - w[0]).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
                let q = w[0] + t * d;
                if (p - q).norm() < best.0 {
                    best = (
                        (p - q).norm(),
                        q,
                        nalgebra::Vector2::new(d.y, -d.x).normalize(),
                        t,
                    );
                }
            }
            let (_, q, n, t) = best;
            let s = (p - q).dot(&n);
            if s >= -1e-3 || !(1e-6..=1.0 - 1e-6).contains(&t) {
                return None;
            }
            Some(Case {
                i: instance(Geometry::Point),
                j: instance(Geometry::Curve(Shared::new(curve))),
                pose_i: at(p.x, p.y, 0.0),
                pose_j: Isometry3::identity(),
                expected: Expected {
                    point_i: Point3::new(p.x, p.y, 0.0),
                    point_j: Point3::new(q.x, q.y, 0.0),
                    normal: Vector3::new(n.x, n.y, 0.0),
                    depth: -s,
                },
                length: 6.0,
            })
        },
    )]
}

/// The rows of point–curve (2-D), circle–curve (2-D).
fn spline_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                rng,
                CURVE_SAMPLES,
                "point–curve (2-D)",
                "cubic B-spline (ORDER 4), 7 control points, closed or open, point on the material side",
                "closest point (Newton); oracle: sampling + bisection",
                |rng| {
                    let closed = rng.uniform(0.0, 1.0) < 0.5;
                    let control: Vec<Point2> = (0..7)
                        .map(|k| {
                            let a = k as f64 * std::f64::consts::TAU / 7.0;
                            let r = rng.uniform(1.5, 2.5);
                            Point2::new(r * a.cos(), r * a.sin())
                        })
                        .collect();
                    let curve = Curve::new(&control, 4, closed, CurvePoints::Control).unwrap();
                    let angle = rng.uniform(0.3, 5.5);
                    let p = Point2::new(1.5 * angle.cos(), 1.5 * angle.sin());
                    let (s, q, n) = oracles::curve_closest(&curve, &p);
                    // An open curve's closest point at either end is no contact (beyond the
                    // end), and the normal is not the curve's there.
                    let at_end = curve
                        .domain()
                        .iter()
                        .any(|&u| (q - curve.point(u)).norm() < 1e-3);
                    if s >= -1e-3 || (!closed && at_end) {
                        return None;
                    }
                    Some(Case {
                        i: instance(Geometry::Point),
                        j: instance(Geometry::Curve(Shared::new(curve))),
                        pose_i: at(p.x, p.y, 0.0),
                        pose_j: Isometry3::identity(),
                        expected: Expected {
                            point_i: Point3::new(p.x, p.y, 0.0),
                            point_j: Point3::new(q.x, q.y, 0.0),
                            normal: Vector3::new(n.x, n.y, 0.0),
                            depth: -s,
                        },
                        length: 5.0,
                    })
                },
            )
        },
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                rng,
                CURVE_SAMPLES,
                "circle–curve (2-D)",
                "closed interpolated cubic (CURVE_POINTS) around the origin, disc of r ∈ [0.2, 0.6] crossing it",
                "closest point (Newton); oracle: sampling + bisection",
                |rng| {
                    let points: Vec<Point2> = (0..8)
                        .map(|k| {
                            let a = k as f64 * std::f64::consts::TAU / 8.0;
                            let r = rng.uniform(1.8, 2.2);
                            Point2::new(r * a.cos(), r * a.sin())
                        })
                        .collect();
                    let curve = Curve::new(&points, 4, true, CurvePoints::Interpolated).unwrap();
                    let r = rng.uniform(0.2, 0.6);
                    let angle = rng.uniform(0.0, std::f64::consts::TAU);
                    let reach = rng.uniform(1.6, 2.3);
                    let c = Point2::new(reach * angle.cos(), reach * angle.sin());
                    let (s, q, n) = oracles::curve_closest(&curve, &c);
                    if s >= r - 1e-3 {
                        return None;
                    }
                    let deepest = c - r * n;
                    Some(Case {
                        i: instance(Geometry::Circle(Circle::new(r).unwrap())),
                        j: instance(Geometry::Curve(Shared::new(curve))),
                        pose_i: at(c.x, c.y, 0.0),
                        pose_j: Isometry3::identity(),
                        expected: Expected {
                            point_i: Point3::new(deepest.x, deepest.y, 0.0),
                            point_j: Point3::new(q.x, q.y, 0.0),
                            normal: Vector3::new(n.x, n.y, 0.0),
                            depth: r - s,
                        },
                        length: 5.0,
                    })
                },
            )
        },
    ]
}

/// The rows of point–arc (2-D), circle–arc (2-D).
fn arc_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        run(
            rng,
            SAMPLES,
            "point–arc (2-D)",
            "RANGLE ∈ [0.5, 2π], point inside the radius within the arc's angle",
            "closed form",
            |rng| {
                let (radius, range) = (
                    rng.uniform(0.5, 2.0),
                    rng.uniform(0.5, std::f64::consts::TAU),
                );
                let theta = rng.uniform(0.01, 0.99) * range;
                let d = rng.uniform(0.05, 0.99) * radius;
                let u = Vector3::new(theta.cos(), theta.sin(), 0.0);
                Some(Case {
                    i: instance(Geometry::Point),
                    j: instance(Geometry::Arc(Arc::new(radius, range).unwrap())),
                    pose_i: at(d * u.x, d * u.y, 0.0),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::from(d * u),
                        point_j: Point3::from(radius * u),
                        normal: u,
                        depth: radius - d,
                    },
                    length: radius,
                })
            },
        ),
        run(
            rng,
            SAMPLES,
            "circle–arc (2-D)",
            "flipped arc (material outside), disc crossing it within the arc's angle",
            "closed form",
            |rng| {
                let (radius, range) = (
                    rng.uniform(1.0, 2.0),
                    rng.uniform(0.5, std::f64::consts::TAU),
                );
                let r = rng.uniform(0.1, 0.5);
                let theta = rng.uniform(0.01, 0.99) * range;
                let d = radius - rng.uniform(0.01, 0.99) * r;
                let u = Vector3::new(theta.cos(), theta.sin(), 0.0);
                Some(Case {
                    i: instance(Geometry::Circle(Circle::new(r).unwrap())),
                    j: instance(Geometry::Arc(Arc::new(radius, range).unwrap())).flipped(),
                    pose_i: at(d * u.x, d * u.y, 0.0),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::from((d + r) * u),
                        point_j: Point3::from(radius * u),
                        normal: -u,
                        depth: r - (radius - d),
                    },
                    length: radius,
                })
            },
        ),
    ]
}
