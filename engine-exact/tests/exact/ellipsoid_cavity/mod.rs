//! Ellipsoids and spheres in cylinder-, frustum- and ellipsoid-shaped cavities (flipped
//! solids), against oracles written apart from the engine's slicing:
//!
//! - an ellipsoid through both ends of a cylindrical cavity: two caps, each the affine image
//!   of a unit sphere's cap (volume centroid in closed form), its area vector the flat
//!   section's, its points on the line through the cap's centroid;
//! - a ball pressed into a long bore's wall, and an elongated ellipsoid across a bore (two
//!   regions): the depth by symmetry, the area `|S|` from the wall inside the body (which
//!   closes the region: `S = ∫ ρ̂ dA` over the wall inside it, a 1-D integral in the azimuth
//!   by Gauss–Legendre);
//! - a ball wholly in the material: the whole ball, pushed to the cavity's nearest wall;
//! - a prolate spheroid across a spherical cavity: two caps in closed form;
//! - the same answers with I and J exchanged, and in every rigid frame;
//! - [`brute_force`]: balls at rims, on a cone's wall and in an ellipsoid cavity against the
//!   sampling oracle of `sphere_solid`;
//! - [`regions`]: the region count against a grid's connected pieces.

mod brute_force;
mod regions;

use crate::common::{Rng, instance, query};
use contact_core::geometry::{Cylinder, Ellipsoid, Frustum, Torus};
use contact_core::{Contact, Geometry, GeometryInstance, Isometry3, Point3, Vector3};
use nalgebra::{Matrix3, Translation3, UnitQuaternion};
use std::f64::consts::PI;

pub(crate) fn bore(radius: f64, length: f64) -> GeometryInstance {
    instance(Geometry::Cylinder(Cylinder::new(radius, length).unwrap())).flipped()
}

pub(crate) fn ellipsoid(a: f64, b: f64, c: f64) -> GeometryInstance {
    instance(Geometry::Ellipsoid(Ellipsoid::new(a, b, c).unwrap()))
}

/// `∫ f` over `[lo, hi]` by the substitution `x = mid + half·sin u` (which smooths the
/// square-root ends of the integrands here) and 400-point Gauss–Legendre in `u`.
fn integrate(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> f64 {
    let (nodes, weights) = gauss_legendre(400);
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    nodes
        .iter()
        .zip(&weights)
        .map(|(&x, &w)| {
            let u = 0.5 * PI * x;
            w * 0.5 * PI * half * u.cos() * f(mid + half * u.sin())
        })
        .sum()
}

/// Gauss–Legendre nodes and weights on `[−1, 1]` (Newton on the Legendre recurrence).
fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = vec![0.0; n];
    let mut weights = vec![0.0; n];
    for i in 0..n {
        let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            let dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
            let step = p1 / dp;
            x -= step;
            if step.abs() < 1e-16 {
                let (mut q0, mut q1) = (1.0, x);
                for k in 2..=n {
                    let q2 = ((2 * k - 1) as f64 * x * q1 - (k - 1) as f64 * q0) / k as f64;
                    q0 = q1;
                    q1 = q2;
                }
                let dq = n as f64 * (x * q1 - q0) / (x * x - 1.0);
                weights[i] = 2.0 / ((1.0 - x * x) * dq * dq);
                break;
            }
        }
        nodes[i] = x;
    }
    (nodes, weights)
}

/// The contact's depth, normal and points against the expected ones, relative to `size`.
fn check(
    got: &Contact,
    normal: &Vector3,
    point_i: &Point3,
    point_j: &Point3,
    area: f64,
    size: f64,
    tol: f64,
) {
    let normal_error = (got.normal_w - normal).norm();
    let depth = (point_i - point_j).norm();
    assert!(
        normal_error < tol,
        "normal {:?} want {normal:?}",
        got.normal_w
    );
    assert!(
        (got.penetration - depth).abs() < tol * size,
        "depth {} want {depth}",
        got.penetration
    );
    assert!(
        (got.point_i_w - point_i).norm() < tol * size,
        "I {:?} want {point_i:?}",
        got.point_i_w
    );
    assert!(
        (got.point_j_w - point_j).norm() < tol * size,
        "J {:?} want {point_j:?}",
        got.point_j_w
    );
    assert!(
        (got.area - area).abs() < tol * size * size,
        "area {} want {area}",
        got.area
    );
}

/// The cap of the ellipsoid `{c + L u : |u| ≤ 1}` beyond the plane `z = h` (upward when
/// `up`): its centroid and the area of its flat face, from the unit sphere's cap.
pub(crate) fn ellipsoid_cap(c: &Vector3, l: &Matrix3<f64>, h: f64, up: bool) -> (Point3, f64) {
    // In u: the plane (Lᵀe_z)·u = h − c_z, at distance s = (h − c_z)/|Lᵀe_z| along m̂.
    let m = l.transpose() * Vector3::z();
    let sign = if up { 1.0 } else { -1.0 };
    let m_hat = m.normalize() * sign;
    let s = sign * (h - c.z) / m.norm();
    let k = 1.0 - s; // the cap's height on the unit sphere
    let centroid_u = m_hat * (3.0 * (2.0 - k).powi(2) / (4.0 * (3.0 - k)));
    let flat_u = PI * (1.0 - s * s); // the unit disc's section area
    // The flat face's area scales by |det L| / |Lᵀ e_z| (the map's area change on that plane).
    let flat = flat_u * l.determinant().abs() / m.norm();
    (Point3::from(c + l * centroid_u), flat)
}

/// Where the line from `g` along unit `d` leaves the ellipsoid `{c + L u : |u| ≤ 1}`.
pub(crate) fn ellipsoid_exit_of(c: &Vector3, l: &Matrix3<f64>, g: &Point3, d: &Vector3) -> Point3 {
    let inv = l.try_inverse().unwrap();
    let (o, v) = (inv * (g.coords - c), inv * d);
    let (a, b, cc) = (v.dot(&v), 2.0 * o.dot(&v), o.dot(&o) - 1.0);
    let t = (-b + (b * b - 4.0 * a * cc).sqrt()) / (2.0 * a);
    g + t * d
}

#[test]
fn an_ellipsoid_through_both_ends_of_a_bore_has_two_caps() {
    let (radius, length) = (1.0, 3.0);
    let cavity = bore(radius, length);
    let semi = Vector3::new(0.5, 0.7, 2.0);
    let body = ellipsoid(semi.x, semi.y, semi.z);
    let mut rng = Rng::new(3);
    let mut checked = 0;
    while checked < 12 {
        // Tilted a little and moved off the axis, its sections at the ends inside the bore.
        let tilt = UnitQuaternion::from_scaled_axis(rng.unit_vector() * rng.uniform(0.0, 0.25));
        let c = Vector3::new(
            rng.uniform(-0.15, 0.15),
            rng.uniform(-0.15, 0.15),
            1.5 + rng.uniform(-0.2, 0.2),
        );
        let l = tilt.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
        // Every point of the ellipsoid within |z − c_z| ≤ the ends' reach stays inside the
        // radius: the sections' extent at the ends checked by sampling the boundary.
        let inside = (0..2000).all(|k| {
            let th = 2.0 * PI * k as f64 / 2000.0;
            (0..40).all(|j| {
                let ph = PI * j as f64 / 39.0;
                let p = c + l * Vector3::new(ph.sin() * th.cos(), ph.sin() * th.sin(), ph.cos());
                (p.z <= 0.0 || p.z >= length) || p.xy().norm() < radius * 0.98
            })
        });
        if !inside {
            continue;
        }
        let pose_i = Isometry3::from_parts(Translation3::from(c), tilt);
        let world = rng.pose(3.0);
        let got = query(&body, &cavity, &(world * pose_i), &world);
        assert_eq!(got.len(), 2, "{got:?}");
        for (h, up) in [(0.0, false), (length, true)] {
            let (g, flat) = ellipsoid_cap(&c, &l, h, up);
            let normal = if up { -Vector3::z() } else { Vector3::z() };
            let point_i = ellipsoid_exit_of(&c, &l, &g, &-normal);
            let point_j = Point3::new(g.x, g.y, h);
            let want_normal = world.rotation * normal;
            let found = got
                .iter()
                .find(|x| (x.normal_w - want_normal).norm() < 0.5)
                .expect("a cap");
            check(
                found,
                &want_normal,
                &(world * point_i),
                &(world * point_j),
                flat,
                2.0,
                1e-9,
            );
        }
        checked += 1;
    }
}

/// The area vector of the body's surface outside a bore of radius `radius`, from the wall
/// inside the body: `S = ∫ R ρ̂(φ) 2w(φ) dφ`, `2w(φ)` the wall's height inside the body at
/// azimuth `φ` (zero outside `[lo, hi]`).
fn wall_area_vector(
    radius: f64,
    (lo, hi): (f64, f64),
    half_height: impl Fn(f64) -> f64,
) -> Vector3 {
    let x = integrate(lo, hi, |p| radius * p.cos() * 2.0 * half_height(p));
    let y = integrate(lo, hi, |p| radius * p.sin() * 2.0 * half_height(p));
    Vector3::new(x, y, 0.0)
}

#[test]
fn a_ball_pressed_into_a_bore_wall_is_one_crescent() {
    let (big_r, length) = (1.0, 6.0);
    let cavity = bore(big_r, length);
    let mut rng = Rng::new(5);
    for _ in 0..10 {
        let r = rng.uniform(0.3, 0.8);
        // Centre d from the axis, overlap e = d + r − R from 1e-3 to 0.2 of r.
        let e = r * 10f64.powf(rng.uniform(-3.0, -0.7));
        let d = big_r - r + e;
        let azimuth = rng.uniform(0.0, 2.0 * PI);
        let radial = Vector3::new(azimuth.cos(), azimuth.sin(), 0.0);
        let z = rng.uniform(2.0, 4.0);
        let ball = instance(Geometry::sphere(r).unwrap());
        let pose_i = Isometry3::translation(d * radial.x, d * radial.y, z);
        let world = rng.pose(2.0);
        let got = query(&ball, &cavity, &(world * pose_i), &world);
        assert_eq!(got.len(), 1, "{got:?}");
        // The wall inside the ball at azimuth φ about the ball's: |R ρ̂ − d ρ̂₀|² + z² ≤ r².
        let c_max = (big_r * big_r + d * d - r * r) / (2.0 * big_r * d);
        let span = c_max.clamp(-1.0, 1.0).acos();
        let s = wall_area_vector(big_r, (-span, span), |p| {
            (r * r - big_r * big_r - d * d + 2.0 * big_r * d * p.cos())
                .max(0.0)
                .sqrt()
        });
        // S points along the ball's radial direction (its x here).
        assert!(s.y.abs() < 1e-12);
        let normal = world.rotation * -radial;
        let point_i = world * Point3::new((d + r) * radial.x, (d + r) * radial.y, z);
        let point_j = world * Point3::new(big_r * radial.x, big_r * radial.y, z);
        check(&got[0], &normal, &point_i, &point_j, s.x, 1.0, 1e-9);
        // Exchanged: the cavity as I.
        let back = query(&cavity, &ball, &world, &(world * pose_i));
        assert_eq!(back.len(), 1);
        assert!((back[0].normal_w + got[0].normal_w).norm() < 1e-12);
        assert!((back[0].penetration - got[0].penetration).abs() < 1e-12);
    }
}

#[test]
fn an_ellipsoid_across_a_bore_meets_both_walls_as_two_regions() {
    let (big_r, length) = (1.0, 6.0);
    let cavity = bore(big_r, length);
    let (a, b, c) = (1.35, 0.45, 0.5);
    let body = ellipsoid(a, b, c);
    let mut rng = Rng::new(9);
    for _ in 0..6 {
        let world = rng.pose(2.0);
        let pose_i = Isometry3::translation(0.0, 0.0, 3.0);
        let got = query(&body, &cavity, &(world * pose_i), &world);
        assert_eq!(got.len(), 2, "{got:?}");
        // The wall inside the ellipsoid: (R cos φ/a)² + (R sin φ/b)² + (z/c)² ≤ 1 near φ = 0.
        let half = |p: f64| {
            let q = 1.0 - (big_r * p.cos() / a).powi(2) - (big_r * p.sin() / b).powi(2);
            c * q.max(0.0).sqrt()
        };
        // The edge where q = 0: cos²φ (R²/a² − R²/b²) = 1 − R²/b².
        let cos2 =
            (1.0 - big_r * big_r / (b * b)) / (big_r * big_r / (a * a) - big_r * big_r / (b * b));
        let span = cos2.sqrt().acos();
        let s = wall_area_vector(big_r, (-span, span), half);
        for side in [1.0, -1.0] {
            let normal = world.rotation * Vector3::new(-side, 0.0, 0.0);
            let found = got
                .iter()
                .find(|x| (x.normal_w - normal).norm() < 0.5)
                .expect("one region per side");
            let point_i = world * Point3::new(side * a, 0.0, 3.0);
            let point_j = world * Point3::new(side * big_r, 0.0, 3.0);
            check(found, &normal, &point_i, &point_j, s.x, 1.0, 1e-9);
        }
    }
}

#[test]
fn a_ball_wholly_in_the_material_is_pushed_to_the_nearest_wall() {
    let cavity = bore(1.0, 4.0);
    let ball = instance(Geometry::sphere(0.3).unwrap());
    // Beside the bore, 0.5 outside its wall at mid-length.
    let pose_i = Isometry3::translation(1.8, 0.0, 2.0);
    let got = query(&ball, &cavity, &pose_i, &Isometry3::identity());
    assert_eq!(got.len(), 1, "{got:?}");
    let c = &got[0];
    assert!(
        (c.normal_w - Vector3::new(-1.0, 0.0, 0.0)).norm() < 1e-12,
        "{c:?}"
    );
    assert!((c.penetration - 1.1).abs() < 1e-12, "{c:?}");
    assert!((c.area - PI * 0.09).abs() < 1e-9 * 0.09, "{c:?}");
    // Below the bore's bottom end, on its axis: pushed up through the end.
    let pose_i = Isometry3::translation(0.2, 0.1, -0.7);
    let got = query(&ball, &cavity, &pose_i, &Isometry3::identity());
    assert_eq!(got.len(), 1, "{got:?}");
    assert!(
        (got[0].normal_w - Vector3::z()).norm() < 1e-12,
        "{:?}",
        got[0]
    );
    assert!((got[0].penetration - 1.0).abs() < 1e-12, "{:?}", got[0]);
}

#[test]
fn a_ball_clear_of_the_walls_has_no_contact() {
    let cavity = bore(1.0, 4.0);
    let ball = instance(Geometry::sphere(0.5).unwrap());
    for (x, z) in [(0.0, 2.0), (0.49, 0.51), (-0.4999, 3.4999)] {
        let got = query(
            &ball,
            &cavity,
            &Isometry3::translation(x, 0.0, z),
            &Isometry3::identity(),
        );
        assert!(got.is_empty(), "{x} {z}: {got:?}");
    }
    // A frustum cavity likewise.
    let cone = instance(Geometry::Frustum(Frustum::new(1.0, 0.6, 2.0).unwrap())).flipped();
    let got = query(
        &ball,
        &cone,
        &Isometry3::translation(0.0, 0.0, 0.6),
        &Isometry3::identity(),
    );
    assert!(got.is_empty(), "{got:?}");
}

/// Degenerate poses: a ball exactly the bore's size (touching all round: no contact), one a
/// hair larger (a thin ring: one contact, finite), a ball at a cone's apex, coaxial spheroids
/// at the ends' planes, and random poses at scales 1e-4 and 1e4: every answer well formed.
#[test]
fn degenerate_and_scaled_poses_give_well_formed_answers() {
    let cavity = bore(1.0, 4.0);
    let touching = instance(Geometry::sphere(1.0).unwrap());
    let at_mid = Isometry3::translation(0.0, 0.0, 2.0);
    assert!(query(&touching, &cavity, &at_mid, &Isometry3::identity()).is_empty());
    let ring = instance(Geometry::sphere(1.0 + 1e-6).unwrap());
    let got = query(&ring, &cavity, &at_mid, &Isometry3::identity());
    assert_eq!(got.len(), 1, "{got:?}");
    assert!(
        got[0].penetration > 0.0 && got[0].penetration < 1e-5,
        "{got:?}"
    );
    // A ball in a cone's apex, pressed in: one contact along the axis.
    let cone = instance(Geometry::Frustum(Frustum::new(1.0, 0.0, 2.0).unwrap())).flipped();
    let ball = instance(Geometry::sphere(0.3).unwrap());
    let got = query(
        &ball,
        &cone,
        &Isometry3::translation(0.0, 0.0, 1.5),
        &Isometry3::identity(),
    );
    assert_eq!(got.len(), 1, "{got:?}");
    assert!((got[0].normal_w + Vector3::z()).norm() < 1e-9, "{got:?}");
    // A spheroid on the axis reaching exactly the end plane, and just past it.
    let spheroid = ellipsoid(0.5, 0.5, 1.0);
    for (z, contacts) in [(3.0, 0), (3.0 + 1e-7, 1)] {
        let got = query(
            &spheroid,
            &cavity,
            &Isometry3::translation(0.0, 0.0, z),
            &Isometry3::identity(),
        );
        assert_eq!(got.len(), contacts, "{z}: {got:?}");
    }
    let mut rng = Rng::new(0xDE6);
    for scale in [1e-4, 1.0, 1e4] {
        let cavity = bore(scale, 3.0 * scale);
        let cone = instance(Geometry::Frustum(
            Frustum::new(scale, 0.4 * scale, 2.0 * scale).unwrap(),
        ))
        .flipped();
        for _ in 0..40 {
            let body = ellipsoid(
                scale * rng.uniform(0.1, 1.5),
                scale * rng.uniform(0.1, 1.5),
                scale * rng.uniform(0.1, 1.5),
            );
            let pose = Isometry3::from_parts(
                Translation3::from(
                    scale
                        * (Vector3::new(0.0, 0.0, 1.5) + rng.unit_vector() * rng.uniform(0.0, 2.0)),
                ),
                rng.rotation(),
            );
            for c in [&cavity, &cone] {
                // `query` asserts every contact is well formed.
                let _ = query(&body, c, &pose, &Isometry3::identity());
            }
        }
    }
}

/// A prolate spheroid (semi-axes a > R > b = b) centred in a spherical cavity of radius R,
/// along a random axis: two mirror regions, each beyond the sphere's cap `x ≥ x₀` with
/// `x₀² = (1 − R²/b²)/(1/a² − 1/b²)`, whose area vector is the cap's projected disc
/// `π(R² − x₀²)`; the depth `a − R` along the axis. Then offset along the axis so only one
/// end reaches the wall: one region, depth `c + a − R`, in both orders.
#[test]
fn a_spheroid_across_a_spherical_cavity_meets_it_at_both_ends() {
    let (a, b, big_r) = (1.3, 0.4, 1.0);
    let socket = instance(Geometry::sphere(big_r).unwrap()).flipped();
    let body = ellipsoid(a, b, b);
    let x0 = ((1.0 - big_r * big_r / (b * b)) / (1.0 / (a * a) - 1.0 / (b * b))).sqrt();
    let area = PI * (big_r * big_r - x0 * x0);
    let mut rng = Rng::new(17);
    for _ in 0..6 {
        let world = rng.pose(2.0);
        let turn = rng.rotation();
        let axis = turn * Vector3::x();
        let pose_i = world * Isometry3::from_parts(Translation3::identity(), turn);
        let got = query(&body, &socket, &pose_i, &world);
        assert_eq!(got.len(), 2, "{got:?}");
        for side in [1.0, -1.0] {
            let normal = world.rotation * (-side * axis);
            let found = got
                .iter()
                .find(|x| (x.normal_w - normal).norm() < 0.5)
                .expect("one region per end");
            let point_i = world * Point3::from(side * a * axis);
            let point_j = world * Point3::from(side * big_r * axis);
            check(found, &normal, &point_i, &point_j, area, 1.0, 1e-9);
        }
        // Moved along its axis past a − R: only the far end in the wall.
        let c = 0.4;
        let pose_i = world * Isometry3::from_parts(Translation3::from(c * axis), turn);
        for body_is_i in [true, false] {
            let got = if body_is_i {
                query(&body, &socket, &pose_i, &world)
            } else {
                query(&socket, &body, &world, &pose_i)
                    .iter()
                    .map(Contact::swapped)
                    .collect()
            };
            assert_eq!(got.len(), 1, "{got:?}");
            let normal = world.rotation * -axis;
            assert!((got[0].normal_w - normal).norm() < 1e-9, "{got:?}");
            assert!(
                (got[0].penetration - (c + a - big_r)).abs() < 1e-9,
                "{got:?}"
            );
            assert!((got[0].point_i_w - world * Point3::from((c + a) * axis)).norm() < 1e-9);
            assert!((got[0].point_j_w - world * Point3::from(big_r * axis)).norm() < 1e-9);
        }
    }
}

/// A ball in a torus' tube (a toroidal groove: R = 1, ρ = 0.3), its centre in a meridian
/// plane on the tube's equator, pressed outward or inward: symmetric about that plane and
/// the equator's, so the normal is radial and the points lie on the radial line through the
/// centre, `δ = e + r − ρ` with `e` the centre's distance from the tube's core circle; both
/// orders. A long ellipsoid along the core circle's tangent leaves the tube at both ends:
/// two regions, mirror images.
#[test]
fn a_ball_in_a_toroidal_groove_meets_its_walls_radially() {
    let (big, small) = (1.0, 0.3);
    let groove = instance(Geometry::Torus(Torus::new(big, small).unwrap())).flipped();
    let mut rng = Rng::new(0x70_7E);
    for _ in 0..8 {
        let r = rng.uniform(0.1, 0.25);
        let e = small - r + r * 10f64.powf(rng.uniform(-3.0, -0.7));
        let outward = rng.uniform(0.0, 1.0) < 0.5;
        let sign = if outward { 1.0 } else { -1.0 };
        let azimuth = rng.uniform(0.0, 2.0 * PI);
        let radial = Vector3::new(azimuth.cos(), azimuth.sin(), 0.0);
        let centre = (big + sign * e) * radial;
        let world = rng.pose(2.0);
        let pose_ball = world * Isometry3::from_parts(centre.into(), rng.rotation());
        let ball = instance(Geometry::sphere(r).unwrap());
        let normal = world.rotation * (-sign * radial);
        let point_i = world * Point3::from((big + sign * (e + r)) * radial);
        let point_j = world * Point3::from((big + sign * small) * radial);
        let got = query(&ball, &groove, &pose_ball, &world);
        assert_eq!(got.len(), 1, "{got:?}");
        check_points(&got[0], &normal, &point_i, &point_j, 1e-9);
        let back = query(&groove, &ball, &world, &pose_ball);
        assert_eq!(back.len(), 1);
        check_points(&back[0].swapped(), &normal, &point_i, &point_j, 1e-9);
    }
    // A long ellipsoid along the tangent at (R, 0, 0).
    let body = ellipsoid(0.2, 0.9, 0.2);
    let got = query(
        &body,
        &groove,
        &Isometry3::translation(big, 0.0, 0.0),
        &Isometry3::identity(),
    );
    assert_eq!(got.len(), 2, "{got:?}");
    let (a, b) = (got[0], got[1]);
    assert!((a.penetration - b.penetration).abs() < 1e-9, "{got:?}");
    let mirror = |v: Vector3| Vector3::new(v.x, -v.y, v.z);
    assert!((mirror(a.normal_w) - b.normal_w).norm() < 1e-9, "{got:?}");
}

/// The normal and both points of `got` against the expected ones (absolute, lengths near 1).
fn check_points(got: &Contact, normal: &Vector3, point_i: &Point3, point_j: &Point3, tol: f64) {
    assert!(
        (got.normal_w - normal).norm() < tol,
        "{got:?} want {normal:?}"
    );
    assert!(
        (got.point_i_w - point_i).norm() < tol,
        "{got:?} want I {point_i:?}"
    );
    assert!(
        (got.point_j_w - point_j).norm() < tol,
        "{got:?} want J {point_j:?}"
    );
    assert!(
        (got.penetration - (point_i - point_j).norm()).abs() < tol,
        "{got:?}"
    );
}

/// The material of a torus cavity includes its hole: a ball in the hole, clear of the tube,
/// is wholly in the material (one contact, pushed toward the tube's nearest wall: `δ = r +`
/// its distance); a flat ellipsoid over the whole hole, through the tube at two sides, is one
/// region (its parts in the hole and outside the tube meet above and below the tube).
#[test]
fn a_torus_cavitys_hole_is_material() {
    let groove = instance(Geometry::Torus(Torus::new(1.0, 0.3).unwrap())).flipped();
    let ball = instance(Geometry::sphere(0.1).unwrap());
    let got = query(
        &ball,
        &groove,
        &Isometry3::translation(0.2, 0.0, 0.0),
        &Isometry3::identity(),
    );
    assert_eq!(got.len(), 1, "{got:?}");
    check_points(
        &got[0],
        &Vector3::x(),
        &Point3::new(0.1, 0.0, 0.0),
        &Point3::new(0.7, 0.0, 0.0),
        1e-9,
    );
    let flat = ellipsoid(1.5, 1.2, 0.5);
    let got = query(
        &flat,
        &groove,
        &Isometry3::translation(0.1, -0.05, 0.1),
        &Isometry3::identity(),
    );
    assert_eq!(got.len(), 1, "{got:?}");
}
