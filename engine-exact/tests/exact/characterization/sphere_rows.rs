//! Characterization rows of the sphere against a box, a cylinder, a frustum and a torus.

use super::{Case, ITERATIVE_BOUND, Row, SAMPLES, at, run};
use crate::common::{Expected, Rng, instance};
use crate::oracles;
use contact_core::geometry::{Cuboid, Cylinder, Frustum, Torus};
use contact_core::{Geometry, Isometry3, Point3, UnitQuaternion, Vector3};
use nalgebra::Translation3;

/// The rows of sphere–box.
pub(super) fn sphere_box_rows(rng: &mut Rng) -> Vec<Row> {
    vec![run(
        rng,
        SAMPLES,
        "sphere–box",
        "centre over a face, the cap clear of its edges and the opposite face (the fast path), 0 < distance < r",
        "closed form (the ball cut by one plane); oracle: clamping",
        |rng| {
            let h = Vector3::new(
                rng.uniform(0.3, 1.5),
                rng.uniform(0.3, 1.5),
                rng.uniform(0.3, 1.5),
            );
            let r = rng.uniform(0.2, 1.0).min(2.0 * h.min());
            let k = (rng.next_u64() % 3) as usize;
            let mut signs = [1.0; 3];
            let mut spread = [0.0; 3];
            for j in 0..3 {
                signs[j] = if rng.uniform(0.0, 1.0) < 0.5 {
                    -1.0
                } else {
                    1.0
                };
                spread[j] = rng.uniform(-1.0, 1.0);
            }
            let fraction = rng.uniform(0.01, 0.99);
            // Heights that keep the cap's base radius within 0.95 of the face's half-width.
            let a_max = 0.95
                * (0..3)
                    .filter(|&j| j != k)
                    .map(|j| h[j])
                    .fold(f64::INFINITY, f64::min);
            let d_min = (r * r - a_max * a_max).max(0.0).sqrt();
            let d = d_min + (r - d_min) * fraction;
            let a = ((r - d) * (r + d)).sqrt();
            let mut point = Vector3::zeros();
            for j in 0..3 {
                point[j] = if j == k {
                    signs[k] * h[k]
                } else {
                    spread[j] * (h[j] - a)
                };
            }
            let (centre, expected) =
                oracles::sphere_box(r, &h, &point, &Vector3::ith(k, signs[k]), d);
            Some(Case {
                i: instance(Geometry::sphere(r).unwrap()),
                j: instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap())),
                pose_i: at(centre.x, centre.y, centre.z),
                pose_j: Isometry3::identity(),
                expected,
                length: h.norm().max(r),
            })
        },
    )]
}

/// The rows of sphere–cylinder.
pub(super) fn sphere_cylinder_rows(rng: &mut Rng) -> Vec<Row> {
    vec![run(
        rng,
        SAMPLES,
        "sphere–cylinder",
        "centre beside the side or above a cap, the region clear of the rims (the fast path), 0 < distance < r",
        "closed form (the ball cut by the side or one plane); oracle: radial / axial",
        |rng| {
            let (big_r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 2.0));
            // At most a quarter turn about the side (r² ≤ 2R² ≤ ρ² + R²), clear of the
            // far cap.
            let r = rng.uniform(0.1, 0.5).min(1.4 * big_r).min(len);
            let fraction = rng.uniform(0.01, 0.99);
            let angle = rng.uniform(0.0, std::f64::consts::TAU);
            let radial = Vector3::new(angle.cos(), angle.sin(), 0.0);
            let side = rng.uniform(0.0, 1.0) < 0.5;
            let spread = rng.uniform(0.0, 1.0);
            // The cap's base radius (or the region's half-height) within reach.
            let a_max = if side { 0.45 * len } else { 0.95 * big_r };
            let d_min = (r * r - a_max * a_max).max(0.0).sqrt();
            let d = d_min + (r - d_min) * fraction;
            let a = ((r - d) * (r + d)).sqrt();
            let (centre, n, q) = if side {
                let z = a + spread * (len - 2.0 * a);
                let q = big_r * radial + Vector3::new(0.0, 0.0, z);
                (q + d * radial, radial, q)
            } else {
                let q = spread * (big_r - a) * radial + Vector3::new(0.0, 0.0, len);
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
    )]
}

/// The rows of sphere–frustum, sphere–torus.
pub(super) fn sphere_frustum_torus_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        run(
            rng,
            SAMPLES,
            "sphere–frustum",
            "centre over a cap, the region clear of the rims and the other cap (the fast path), 0 < distance < r",
            "closed form (the ball cut by one plane); oracle: axial",
            |rng| {
                let (rb, rt, len) = (
                    rng.uniform(0.5, 1.5),
                    rng.uniform(0.0, 1.5),
                    rng.uniform(0.5, 2.0),
                );
                let r = rng.uniform(0.05, 0.3);
                let t = rng.uniform(0.2, 0.8);
                let fraction = rng.uniform(0.01, 0.99);
                let angle = rng.uniform(0.0, std::f64::consts::TAU);
                // The radius the region can use: the smaller of the cap's and the radius a
                // ball's length away from it (linear in the height; the region spans less).
                let room = |cap: f64, other: f64| cap.min(cap + (other - cap) * r / len);
                let top = t >= 0.5 && room(rt, rb) > 0.05;
                let (cap_z, up, available) = if top {
                    (len, 1.0, room(rt, rb))
                } else {
                    (0.0, -1.0, room(rb, rt))
                };
                let a_max = 0.9 * available;
                let d_min = (r * r - a_max * a_max).max(0.0).sqrt();
                let d = d_min + (r - d_min) * fraction;
                let a = ((r - d) * (r + d)).sqrt();
                let rho = ((t - 0.2) / 0.3).fract() * (available - a);
                let foot = Vector3::new(rho * angle.cos(), rho * angle.sin(), cap_z);
                let n = Vector3::new(0.0, 0.0, up);
                let c = foot + d * n;
                Some(Case {
                    i: instance(Geometry::sphere(r).unwrap()),
                    j: instance(Geometry::Frustum(Frustum::new(rb, rt, len).unwrap())),
                    pose_i: Isometry3::from_parts(
                        Translation3::from(c),
                        UnitQuaternion::identity(),
                    ),
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: Point3::from(c - r * n),
                        point_j: Point3::from(foot),
                        normal: n,
                        depth: r - d,
                    },
                    length: rb.max(rt).max(len),
                })
            },
        ),
        Row {
            bound: ITERATIVE_BOUND,
            ..run(
                rng,
                SAMPLES,
                "sphere–torus",
                "centre on the outer equator (the region symmetric about it and the meridian plane), 0 < distance < r",
                "general ellipsoid slicing, equal semi-axes; oracle: nearest tube centre",
                |rng| {
                    let big = rng.uniform(1.0, 2.0);
                    let small = rng.uniform(0.1, 0.8) * big;
                    let r = rng.uniform(0.1, 0.5);
                    let phi = rng.uniform(0.0, std::f64::consts::TAU);
                    let dist = small + rng.uniform(0.01, 0.99) * r;
                    // The draws' old rejection, kept so the stream is unchanged.
                    if big + dist * phi.cos() <= 0.05 {
                        return None;
                    }
                    let rho = big + dist;
                    let turn =
                        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, 6.0));
                    Some(Case {
                        i: instance(Geometry::sphere(r).unwrap()),
                        j: instance(Geometry::Torus(Torus::new(big, small).unwrap())),
                        pose_i: turn.inverse() * at(rho, 0.0, 0.0),
                        pose_j: Isometry3::from_parts(Translation3::identity(), turn.inverse()),
                        expected: oracles::sphere_torus(r, big, small, rho, 0.0).moved(
                            &Isometry3::from_parts(Translation3::identity(), turn.inverse()),
                        ),
                        length: big + small,
                    })
                },
            )
        },
    ]
}
