//! The accuracy contract: one row per pair, measured against an independent closed form
//! (see [`crate::oracles`]) over seeded random configurations, each seen from a random world
//! frame. Run with `--nocapture` to print the table.
//!
//! Bounds: 1e-12 relative to the pair's size for closed forms and exact clipping, 1e-9 for
//! quadrature and iterative pairs (cylinder–plane tilted, curves); depth, normal and points
//! are each checked.

use crate::common::{Expected, Rng, errors, instance, query};
use crate::oracles;
use contact_core::geometry::{
    Circle, Cuboid, Curve, CurvePoints, Cylinder, Ellipsoid, Frustum, Line, Plane, Torus,
};
use contact_core::{Geometry, GeometryInstance, Isometry3, Point3, UnitQuaternion, Vector3};
use contact_core::{Point2, Vector2};
use nalgebra::Translation3;
use std::sync::Arc as Shared;

const SAMPLES: usize = 200;
/// Curve rows are fewer: the oracle's evaluator allocates per call and runs unoptimized.
const CURVE_SAMPLES: usize = 60;
const CLOSED_FORM_BOUND: f64 = 1e-12;
/// Quadrature pairs (and their Simpson oracles) are held to the iterative bound.
const ITERATIVE_BOUND: f64 = 1e-9;

struct Row {
    bound: f64,
    pair: &'static str,
    family: &'static str,
    method: &'static str,
    worst: [f64; 3],
    samples: usize,
}

/// One case: the I and J instances, the part poses in the canonical frame, the expected
/// answer there, and the pair's size.
struct Case {
    i: GeometryInstance,
    j: GeometryInstance,
    pose_i: Isometry3,
    pose_j: Isometry3,
    expected: Expected,
    length: f64,
}

fn run(
    rng: &mut Rng,
    count: usize,
    pair: &'static str,
    family: &'static str,
    method: &'static str,
    mut make: impl FnMut(&mut Rng) -> Option<Case>,
) -> Row {
    let mut worst = [0.0f64; 3];
    let mut samples = 0;
    while samples < count {
        let Some(case) = make(rng) else { continue };
        let world = rng.pose(2.0 * case.length);
        let found = query(
            &case.i,
            &case.j,
            &(world * case.pose_i),
            &(world * case.pose_j),
        );
        assert_eq!(
            found.len(),
            1,
            "{pair} ({family}): {found:?} for {:?}",
            case.expected
        );
        let got = found[0];
        let e = errors(&got, &case.expected.moved(&world), case.length);
        for k in 0..3 {
            // NaN must fail the row, so it counts as infinite.
            worst[k] = worst[k].max(if e[k].is_nan() { f64::INFINITY } else { e[k] });
        }
        samples += 1;
    }
    Row {
        bound: CLOSED_FORM_BOUND,
        pair,
        family,
        method,
        worst,
        samples,
    }
}

fn at(x: f64, y: f64, z: f64) -> Isometry3 {
    Isometry3::translation(x, y, z)
}

#[test]
fn characterization_table() {
    let mut rng = Rng::new(0x5EED_0003);
    let plane = || instance(Geometry::Plane(Plane::unbounded()));
    let rows = vec![
        run(
            &mut rng,
            SAMPLES,
            "sphere–plane",
            "r ∈ [0.5, 2], centre height d ∈ (−1.2r, r)",
            "closed form",
            |rng| {
                let r = rng.uniform(0.5, 2.0);
                let d = rng.uniform(-1.2 * r, r);
                Some(Case {
                    i: instance(Geometry::sphere(r).unwrap()),
                    j: plane(),
                    pose_i: at(0.0, 0.0, d),
                    pose_j: Isometry3::identity(),
                    expected: oracles::sphere_plane(r, d),
                    length: r,
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "sphere–sphere",
            "radii ∈ [0.2, 2], D ∈ (0.05, r_a + r_b), containment included",
            "closed form",
            |rng| {
                let (ra, rb) = (rng.uniform(0.2, 2.0), rng.uniform(0.2, 2.0));
                let d = rng.uniform(0.05, ra + rb);
                let u = rng.unit_vector();
                Some(Case {
                    i: instance(Geometry::sphere(ra).unwrap()),
                    j: instance(Geometry::sphere(rb).unwrap()),
                    pose_i: Isometry3::from_parts(Translation3::from(d * u), rng.rotation()),
                    pose_j: Isometry3::identity(),
                    expected: oracles::sphere_sphere(ra, rb, d, &u),
                    length: ra.max(rb),
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "sphere–cavity",
            "ball r_a in cavity r_b > r_a, D ∈ (r_b − r_a, r_b)",
            "closed form",
            |rng| {
                let rb = rng.uniform(1.0, 2.0);
                let ra = rng.uniform(0.2, 0.9 * rb);
                let d = rng.uniform(rb - ra, rb);
                let u = rng.unit_vector();
                // Ball in cavity: the normal points back towards the cavity's centre.
                let expected = Expected {
                    point_i: Point3::from(u * (d + ra)),
                    point_j: Point3::from(u * rb),
                    normal: -u,
                    depth: d + ra - rb,
                };
                Some(Case {
                    i: instance(Geometry::sphere(ra).unwrap()),
                    j: instance(Geometry::sphere(rb).unwrap()).flipped(),
                    pose_i: at(d * u.x, d * u.y, d * u.z),
                    pose_j: Isometry3::identity(),
                    expected,
                    length: rb,
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "ellipsoid–plane",
            "semi-axes ∈ [0.3, 2], any orientation, cap to beyond the centre",
            "closed form (affine cap); oracle by slicing",
            |rng| {
                let s = Vector3::new(
                    rng.uniform(0.3, 2.0),
                    rng.uniform(0.3, 2.0),
                    rng.uniform(0.3, 2.0),
                );
                let q = rng.rotation();
                let n = q.inverse_transform_vector(&Vector3::z());
                let k = (s.component_mul(&n)).norm();
                let z0 = k * rng.uniform(-0.9, 0.999);
                Some(Case {
                    i: instance(Geometry::Ellipsoid(Ellipsoid::new(s.x, s.y, s.z).unwrap())),
                    j: plane(),
                    pose_i: Isometry3::from_parts(Translation3::new(0.0, 0.0, z0), q),
                    pose_j: Isometry3::identity(),
                    expected: oracles::ellipsoid_plane(&s, &q, z0),
                    length: s.max(),
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "box–plane",
            "any orientation, one corner below the plane",
            "exact clipping; oracle: corner tetrahedron",
            |rng| {
                let h = Vector3::new(
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                );
                let q = rng.rotation();
                let e = rng.uniform(0.01, 0.3) * h.min();
                let (centre, expected) = oracles::box_corner_plane(&h, &q, e)?;
                Some(Case {
                    i: instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap())),
                    j: plane(),
                    pose_i: Isometry3::from_parts(Translation3::from(centre.coords), q),
                    pose_j: Isometry3::identity(),
                    expected,
                    length: h.norm(),
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "box–plane",
            "face parallel to the plane, sunk by up to the full height",
            "exact clipping; oracle: slab",
            |rng| {
                let h = Vector3::new(
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                );
                let (x, y) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
                let z0 = rng.uniform(-0.9, 0.99) * h.z;
                let expected = Expected {
                    point_i: Point3::new(x, y, z0 - h.z),
                    point_j: Point3::new(x, y, 0.0),
                    normal: Vector3::z(),
                    depth: h.z - z0,
                };
                Some(Case {
                    i: instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap())),
                    j: plane(),
                    pose_i: at(x, y, z0),
                    pose_j: Isometry3::identity(),
                    expected,
                    length: h.norm(),
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "box–box",
            "faces parallel, partial overlap on every axis",
            "exact clipping; oracle: per-axis overlap",
            |rng| {
                let ha = Vector3::new(
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                );
                let hb = Vector3::new(
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                );
                let offset = Vector3::new(
                    rng.uniform(-0.95, 0.95) * (ha.x + hb.x),
                    rng.uniform(-0.95, 0.95) * (ha.y + hb.y),
                    rng.uniform(-0.95, 0.95) * (ha.z + hb.z),
                );
                let ca = Point3::from(offset);
                // a wholly inside b has no b surface inside a: that branch is in `degenerate`.
                if (0..3).all(|k| offset[k].abs() + ha[k] < hb[k]) {
                    return None;
                }
                Some(Case {
                    i: instance(Geometry::Cuboid(
                        Cuboid::centered(ha.x, ha.y, ha.z).unwrap(),
                    )),
                    j: instance(Geometry::Cuboid(
                        Cuboid::centered(hb.x, hb.y, hb.z).unwrap(),
                    )),
                    pose_i: at(ca.x, ca.y, ca.z),
                    pose_j: Isometry3::identity(),
                    // No net surface normal (containment, crossing boxes): see `degenerate`.
                    expected: oracles::aligned_boxes(&ca, &ha, &Point3::origin(), &hb)?,
                    length: ha.norm().max(hb.norm()),
                })
            },
        ),
        run(
            &mut rng,
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
            &mut rng,
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
            &mut rng,
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
        run(
            &mut rng,
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
            &mut rng,
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
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                &mut rng,
                SAMPLES,
                "cylinder–plane",
                "R ∈ [0.3, 1.5], L ∈ [0.2, 3], axis tilted 12°–78° from the normal, cap corner to full immersion",
                "quadrature of chords; oracle: Simpson over axial slices",
                |rng| {
                    let (r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.2, 3.0));
                    let alpha = rng.uniform(0.2, 1.37)
                        * if rng.uniform(0.0, 1.0) < 0.5 {
                            1.0
                        } else {
                            -1.0
                        };
                    let (a, b) = (alpha.sin().abs(), alpha.cos());
                    let h_min = (b * len).min(0.0) - a * r;
                    let h_max = (b * len).max(0.0) + a * r;
                    let h = h_min + rng.uniform(0.01, 1.2) * (h_max - h_min);
                    let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), alpha);
                    Some(Case {
                        i: instance(Geometry::Cylinder(Cylinder::new(r, len).unwrap())),
                        j: plane(),
                        pose_i: Isometry3::from_parts(Translation3::new(0.0, 0.0, -h), q),
                        pose_j: Isometry3::identity(),
                        expected: oracles::cylinder_plane_tilted(r, len, alpha, -h),
                        length: r.max(len),
                    })
                },
            )
        },
        run(
            &mut rng,
            SAMPLES,
            "cylinder–plane",
            "axis parallel to the plane (a wheel), centre height ∈ (−R, R)",
            "quadrature of chords; oracle: line of centres",
            |rng| {
                let (r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.2, 3.0));
                let d = rng.uniform(-0.99, 0.99) * r;
                // Axis along world x: the base centre at the origin, the axis midpoint at L/2.
                let q = UnitQuaternion::from_axis_angle(
                    &Vector3::y_axis(),
                    std::f64::consts::FRAC_PI_2,
                );
                Some(Case {
                    i: instance(Geometry::Cylinder(Cylinder::new(r, len).unwrap())),
                    j: plane(),
                    pose_i: Isometry3::from_parts(Translation3::new(-len / 2.0, 0.0, d), q),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::new(0.0, 0.0, d - r),
                        point_j: Point3::origin(),
                        normal: Vector3::z(),
                        depth: r - d,
                    },
                    length: r.max(len),
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "cylinder–plane",
            "standing on a cap, sunk by up to its length",
            "quadrature of chords; oracle: slab",
            |rng| {
                let (r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.2, 3.0));
                let sunk = rng.uniform(0.01, 0.99) * len;
                let (x, y) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
                Some(Case {
                    i: instance(Geometry::Cylinder(Cylinder::new(r, len).unwrap())),
                    j: plane(),
                    pose_i: at(x, y, -sunk),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::new(x, y, -sunk),
                        point_j: Point3::new(x, y, 0.0),
                        normal: Vector3::z(),
                        depth: sunk,
                    },
                    length: r.max(len),
                })
            },
        ),
        run(
            &mut rng,
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
        ),
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                &mut rng,
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
                    if s >= -1e-3 || (!closed && (q - curve.point(curve.domain()[0])).norm() < 1e-3)
                    {
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
                &mut rng,
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
        run(
            &mut rng,
            SAMPLES,
            "sphere–box",
            "centre outside a face, an edge or a corner, 0 < distance < r",
            "closed form (signed distance); oracle: clamping",
            |rng| {
                let h = Vector3::new(
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.3, 1.5),
                );
                let r = rng.uniform(0.2, 1.0);
                // A surface point with `outside` axes at ±h (1: face, 2: edge, 3: corner) and the
                // others strictly inside; the outward direction in that feature's normal cone.
                let outside = 1 + (rng.next_u64() % 3) as usize;
                let mut point = Vector3::zeros();
                let mut outward = Vector3::zeros();
                for k in 0..3 {
                    let sign = if rng.uniform(0.0, 1.0) < 0.5 {
                        -1.0
                    } else {
                        1.0
                    };
                    if k < outside {
                        point[k] = sign * h[k];
                        outward[k] = sign * rng.uniform(0.2, 1.0);
                    } else {
                        point[k] = rng.uniform(-0.9, 0.9) * h[k];
                    }
                }
                let d = rng.uniform(0.01, 0.99) * r;
                let (centre, expected) =
                    oracles::sphere_box(r, &h, &point, &outward.normalize(), d);
                Some(Case {
                    i: instance(Geometry::sphere(r).unwrap()),
                    j: instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap())),
                    pose_i: at(centre.x, centre.y, centre.z),
                    pose_j: Isometry3::identity(),
                    expected,
                    length: h.norm().max(r),
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "sphere–cylinder",
            "centre beside the side or above a cap, 0 < distance < r",
            "closed form (signed distance); oracle: radial / axial",
            |rng| {
                let (big_r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 2.0));
                let r = rng.uniform(0.1, 0.5);
                let d = rng.uniform(0.01, 0.99) * r;
                let angle = rng.uniform(0.0, std::f64::consts::TAU);
                let radial = Vector3::new(angle.cos(), angle.sin(), 0.0);
                let (centre, n, q) = if rng.uniform(0.0, 1.0) < 0.5 {
                    let z = rng.uniform(0.05, 0.95) * len;
                    let q = big_r * radial + Vector3::new(0.0, 0.0, z);
                    (q + d * radial, radial, q)
                } else {
                    let q = rng.uniform(0.0, 0.95) * big_r * radial + Vector3::new(0.0, 0.0, len);
                    (q + d * Vector3::z(), Vector3::z(), q)
                };
                Some(Case {
                    i: instance(Geometry::sphere(r).unwrap()),
                    j: instance(Geometry::Cylinder(Cylinder::new(big_r, len).unwrap())),
                    pose_i: at(centre.x, centre.y, centre.z),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::from(centre - r * n),
                        point_j: Point3::from(q),
                        normal: n,
                        depth: r - d,
                    },
                    length: big_r.max(len),
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "sphere–frustum",
            "centre outside the slanted side, 0 < distance < r",
            "closed form (signed distance); oracle: distance to the side line",
            |rng| {
                let (rb, rt, len) = (
                    rng.uniform(0.5, 1.5),
                    rng.uniform(0.0, 1.5),
                    rng.uniform(0.5, 2.0),
                );
                let r = rng.uniform(0.05, 0.3);
                // Outward normal of the side in the (ρ, z) half-plane, and a point of the side.
                let side = Vector2::new(len, rb - rt).normalize();
                let t = rng.uniform(0.2, 0.8);
                let foot = Vector2::new(rb + t * (rt - rb), t * len);
                let d = rng.uniform(0.01, 0.99) * r;
                let c2 = foot + d * side;
                let angle = rng.uniform(0.0, std::f64::consts::TAU);
                let lift = |v: Vector2| Vector3::new(v.x * angle.cos(), v.x * angle.sin(), v.y);
                let n = lift(side);
                Some(Case {
                    i: instance(Geometry::sphere(r).unwrap()),
                    j: instance(Geometry::Frustum(Frustum::new(rb, rt, len).unwrap())),
                    pose_i: Isometry3::from_parts(
                        Translation3::from(lift(c2)),
                        UnitQuaternion::identity(),
                    ),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::from(lift(c2) - r * n),
                        point_j: Point3::from(lift(foot)),
                        normal: n,
                        depth: r - d,
                    },
                    length: rb.max(rt).max(len),
                })
            },
        ),
        run(
            &mut rng,
            SAMPLES,
            "sphere–torus",
            "centre around the tube, inside the hole or outside the ring",
            "closed form (signed distance); oracle: nearest tube centre",
            |rng| {
                let big = rng.uniform(1.0, 2.0);
                let small = rng.uniform(0.1, 0.8) * big;
                let r = rng.uniform(0.1, 0.5);
                let phi = rng.uniform(0.0, std::f64::consts::TAU);
                let dist = small + rng.uniform(0.01, 0.99) * r;
                let (rho, z) = (big + dist * phi.cos(), dist * phi.sin());
                if rho <= 0.05 {
                    return None;
                }
                let turn =
                    UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, 6.0));
                Some(Case {
                    i: instance(Geometry::sphere(r).unwrap()),
                    j: instance(Geometry::Torus(Torus::new(big, small).unwrap())),
                    pose_i: turn.inverse() * at(rho, 0.0, z),
                    pose_j: Isometry3::from_parts(Translation3::identity(), turn.inverse()),
                    expected: oracles::sphere_torus(r, big, small, rho, z).moved(
                        &Isometry3::from_parts(Translation3::identity(), turn.inverse()),
                    ),
                    length: big + small,
                })
            },
        ),
    ];
    println!(
        "| pair | configuration family | method | samples | max depth err | max normal err | max point err | bound |"
    );
    println!("| --- | --- | --- | --- | --- | --- | --- | --- |");
    for r in &rows {
        println!(
            "| {} | {} | {} | {} | {:.1e} | {:.1e} | {:.1e} | {:.0e} |",
            r.pair, r.family, r.method, r.samples, r.worst[0], r.worst[1], r.worst[2], r.bound
        );
    }
    for r in &rows {
        assert!(
            r.worst.iter().all(|&e| e <= r.bound),
            "{} ({}): errors {:?} exceed {:e}",
            r.pair,
            r.family,
            r.worst,
            r.bound
        );
    }
}
