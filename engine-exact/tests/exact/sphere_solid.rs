//! Sphere–box, –cylinder, –frustum and –torus at edges, rims, corners, with the centre
//! inside, on a frustum's side and on a torus' tube, against a brute-force oracle written
//! apart from the engine: only the solids' inside tests, sampled and bisected.
//!
//! The oracle ([`brute_force`]):
//! - the area vector `S` of the sphere's surface inside the solid, `r² ∫ u dΩ` over the
//!   directions `u` with `c + r u` inside: rings of the polar angle about a tilted pole
//!   (midpoint rule), each ring's inside arcs found by sampling and bisection and `∫ u dφ`
//!   over them in closed form;
//! - the intersection's volume and centroid, `∫ dΩ ∫ t² (1, u t) dt` over the rays from the
//!   centre: a midpoint grid of directions, each ray's inside intervals in `[0, r]` by
//!   sampling and bisection, the radial integrals in closed form;
//! - the contact by SPEC §4: `n = −S/|S|`, the line through the centroid along `n` leaving
//!   the sphere (closed form) and the solid (marched, then bisected).
//!
//! Its error is that of the midpoint rules across the kinks of the region's outline: about
//! 1e-5 of the size on these poses (measured by halving the grids), so the engine is held to
//! 2e-4 here; the old closest-point answer missed by up to 0.58 rad and 0.17 of the size.

use crate::common::{Rng, instance, query};
use contact_core::geometry::{Cuboid, Cylinder, Frustum, Torus};
use contact_core::{Geometry, Isometry3, Point3, Vector3};
use std::f64::consts::{PI, TAU};

/// The oracle's contact in the solid's frame: normal from the solid into the sphere, the
/// points on the sphere and on the solid, the depth.
#[derive(Debug, Clone, Copy)]
struct Oracle {
    normal: Vector3,
    point_sphere: Vector3,
    point_solid: Vector3,
    depth: f64,
}

/// The inside intervals of `[lo, hi]` for the test `inside`, by `samples` steps and
/// bisection of each change.
fn intervals(inside: impl Fn(f64) -> bool, lo: f64, hi: f64, samples: usize) -> Vec<(f64, f64)> {
    let at = |k: usize| lo + (hi - lo) * k as f64 / samples as f64;
    let refine = |mut a: f64, mut b: f64, a_inside: bool| {
        for _ in 0..60 {
            let mid = 0.5 * (a + b);
            if mid <= a || mid >= b {
                break;
            }
            if inside(mid) == a_inside {
                a = mid;
            } else {
                b = mid;
            }
        }
        0.5 * (a + b)
    };
    let mut out = Vec::new();
    let mut previous = inside(lo);
    let mut start = previous.then_some(lo);
    for k in 1..=samples {
        let here = inside(at(k));
        if here != previous {
            let x = refine(at(k - 1), at(k), previous);
            if here {
                start = Some(x);
            } else if let Some(s) = start.take() {
                out.push((s, x));
            }
        }
        previous = here;
    }
    if let Some(s) = start {
        out.push((s, hi));
    }
    out
}

/// SPEC §4 for the sphere of radius `r` centred at `c` against the solid `inside` (its frame),
/// on `2·grid` polar rings (1024 samples each) for the area vector and a direction grid of `grid/4` by `grid/2`
/// for the volume.
fn brute_force(c: &Vector3, r: f64, inside: &dyn Fn(&Vector3) -> bool, grid: usize) -> Oracle {
    let (s, g) = brute_force_moments(c, r, inside, grid);
    let normal = -s.normalize();
    // The sphere along −n from g: |g − t n − c| = r.
    let point_sphere = sphere_exit(c, r, &g, &-normal);
    // The solid along +n from g: march to the first outside point, then bisect.
    let point_solid = first_change(inside, &g, &normal, r);
    Oracle {
        normal,
        point_sphere,
        point_solid,
        depth: (point_solid - point_sphere).norm(),
    }
}

/// Where the line from `g` (inside the sphere) along the unit `d` leaves the sphere.
pub(crate) fn sphere_exit(c: &Vector3, r: f64, g: &Vector3, d: &Vector3) -> Vector3 {
    let w = g - c;
    let b = -w.dot(d);
    let t = b + (b * b - w.norm_squared() + r * r).sqrt();
    g + t * d
}

/// The first point from `g` along `d` where `inside` changes: marched in steps of 1e-3 of
/// `r`, then bisected.
pub(crate) fn first_change(
    inside: &dyn Fn(&Vector3) -> bool,
    g: &Vector3,
    d: &Vector3,
    r: f64,
) -> Vector3 {
    let start = inside(g);
    let step = 1e-3 * r;
    let mut t = 0.0;
    while inside(&(g + (t + step) * d)) == start && t < 1e3 * r {
        t += step;
    }
    let (mut lo, mut hi) = (t, t + step);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if inside(&(g + mid * d)) == start {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    g + 0.5 * (lo + hi) * d
}

/// The oracle's `S` (the sphere's surface inside, outward) and the intersection's centroid.
pub(crate) fn brute_force_moments(
    c: &Vector3,
    r: f64,
    inside: &dyn Fn(&Vector3) -> bool,
    grid: usize,
) -> (Vector3, Vector3) {
    let pole = Vector3::new(0.31, -0.52, 0.79).normalize();
    let e1 = pole.cross(&Vector3::x()).normalize();
    let e2 = pole.cross(&e1);
    let dir = |theta: f64, phi: f64| {
        let (st, ct) = theta.sin_cos();
        e1 * (st * phi.cos()) + e2 * (st * phi.sin()) + pole * ct
    };
    // S: rings.
    let mut s = Vector3::zeros();
    let rings = 2 * grid;
    let dtheta = PI / rings as f64;
    for i in 0..rings {
        let theta = dtheta * (i as f64 + 0.5);
        let (st, ct) = theta.sin_cos();
        for (a, b) in intervals(|phi| inside(&(c + r * dir(theta, phi))), 0.0, TAU, 1024) {
            // ∫ u dφ over [a, b].
            let integral = e1 * (st * (b.sin() - a.sin())) - e2 * (st * (b.cos() - a.cos()))
                + pole * (ct * (b - a));
            s += integral * (r * r * st * dtheta);
        }
    }
    // Volume and centroid: rays.
    let (rings, around) = (grid / 4, grid / 2);
    let (dt, dp) = (PI / rings as f64, TAU / around as f64);
    let (mut volume, mut moment) = (0.0, Vector3::zeros());
    for i in 0..rings {
        let theta = dt * (i as f64 + 0.5);
        let weight = theta.sin() * dt * dp;
        for j in 0..around {
            let u = dir(theta, dp * (j as f64 + 0.5));
            for (a, b) in intervals(|t| inside(&(c + t * u)), 0.0, r, 24) {
                volume += weight * (b.powi(3) - a.powi(3)) / 3.0;
                moment += (c * ((b.powi(3) - a.powi(3)) / 3.0)
                    + u * ((b.powi(4) - a.powi(4)) / 4.0))
                    * weight;
            }
        }
    }
    (s, moment / volume)
}

/// The oracle's grid (see [`brute_force`]).
pub(crate) const GRID: usize = 1600;

/// A solid with its inside test (own frame) and size.
struct Solid {
    name: &'static str,
    geometry: Geometry,
    inside: Box<dyn Fn(&Vector3) -> bool>,
    size: f64,
}

fn cuboid(h: Vector3) -> Solid {
    Solid {
        name: "box",
        geometry: Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap()),
        inside: Box::new(move |p: &Vector3| (0..3).all(|k| p[k].abs() <= h[k])),
        size: h.norm(),
    }
}

fn cylinder(radius: f64, length: f64) -> Solid {
    Solid {
        name: "cylinder",
        geometry: Geometry::Cylinder(Cylinder::new(radius, length).unwrap()),
        inside: Box::new(move |p: &Vector3| p.xy().norm() <= radius && p.z >= 0.0 && p.z <= length),
        size: radius.max(length),
    }
}

fn frustum(r0: f64, r1: f64, length: f64) -> Solid {
    Solid {
        name: "frustum",
        geometry: Geometry::Frustum(Frustum::new(r0, r1, length).unwrap()),
        inside: Box::new(move |p: &Vector3| {
            p.z >= 0.0 && p.z <= length && p.xy().norm() <= r0 + (r1 - r0) * p.z / length
        }),
        size: r0.max(r1).max(length),
    }
}

fn torus(big: f64, small: f64) -> Solid {
    Solid {
        name: "torus",
        geometry: Geometry::Torus(Torus::new(big, small).unwrap()),
        inside: Box::new(move |p: &Vector3| {
            let rho = p.xy().norm() - big;
            rho * rho + p.z * p.z <= small * small
        }),
        size: big + small,
    }
}

/// The engine's answer in both orders, seen from a random world frame, against the oracle:
/// returns the worst (normal, depth/size, points/size) errors.
fn check(solid: &Solid, r: f64, c: Vector3, grid: usize, tol: f64, rng: &mut Rng) -> [f64; 3] {
    let oracle = brute_force(&c, r, solid.inside.as_ref(), grid);
    let world = rng.pose(2.0);
    let pose_sphere = world * Isometry3::from_parts(c.into(), rng.rotation());
    let sphere = instance(Geometry::sphere(r).unwrap());
    let body = instance(solid.geometry.clone());
    let want_normal = world.rotation * oracle.normal;
    let want_sphere = world * Point3::from(oracle.point_sphere);
    let want_solid = world * Point3::from(oracle.point_solid);
    let mut worst = [0.0f64; 3];
    for sphere_is_i in [true, false] {
        let found = if sphere_is_i {
            query(&sphere, &body, &pose_sphere, &world)
        } else {
            query(&body, &sphere, &world, &pose_sphere)
        };
        assert_eq!(
            found.len(),
            1,
            "{} r = {r} c = {c:?}: {found:?}",
            solid.name
        );
        let got = found[0];
        let (normal, on_sphere, on_solid) = if sphere_is_i {
            (got.normal_w, got.point_i_w, got.point_j_w)
        } else {
            (-got.normal_w, got.point_j_w, got.point_i_w)
        };
        let e = [
            (normal - want_normal).norm(),
            (got.penetration - oracle.depth).abs() / solid.size,
            ((on_sphere - want_sphere).norm() + (on_solid - want_solid).norm()) / solid.size,
        ];
        for k in 0..3 {
            worst[k] = worst[k].max(e[k]);
        }
        assert!(
            e.iter().all(|&x| x <= tol),
            "{} r = {r} c = {c:?} (sphere is I: {sphere_is_i}): errors {e:?}\n got {got:?}\n oracle {oracle:?}",
            solid.name
        );
    }
    worst
}

/// Poses at an edge, a corner, a rim, with the centre inside, on a frustum's side and on a
/// torus' tube, each in both orders and a random world frame.
#[test]
fn sphere_against_solids_matches_the_brute_force_oracle() {
    let mut rng = Rng::new(0x5_9E7E);
    let boxed = cuboid(Vector3::new(0.9, 0.6, 0.4));
    let cyl = cylinder(0.7, 1.6);
    let fru = frustum(0.9, 0.4, 1.4);
    let tor = torus(1.0, 0.3);
    let cases: [(&Solid, f64, Vector3); 12] = [
        // Box: an edge, a corner, over a face near an edge, inside near an edge.
        (&boxed, 0.3, Vector3::new(1.0, 0.0, 0.5)),
        (&boxed, 0.35, Vector3::new(1.0, 0.7, 0.5)),
        (&boxed, 0.3, Vector3::new(0.8, 0.1, 0.5)),
        (&boxed, 0.3, Vector3::new(0.75, -0.2, 0.3)),
        // Cylinder: the top rim from outside, over the cap near the rim, inside near the rim.
        (&cyl, 0.3, Vector3::new(0.8, 0.0, 1.7)),
        (&cyl, 0.3, Vector3::new(0.3, 0.4, 1.75)),
        (&cyl, 0.3, Vector3::new(0.45, -0.3, 1.5)),
        // Frustum: the slanted side, the top rim.
        (&fru, 0.2, Vector3::new(0.75, 0.0, 0.7)),
        (&fru, 0.25, Vector3::new(0.3, 0.35, 1.5)),
        // Torus: on top of the tube, across it off the equator, the inner side.
        (&tor, 0.2, Vector3::new(1.0, 0.0, 0.4)),
        (&tor, 0.25, Vector3::new(0.9, 0.8, -0.3)),
        (&tor, 0.35, Vector3::new(0.35, -0.2, 0.1)),
    ];
    let mut worst = [0.0f64; 3];
    for (solid, r, c) in cases {
        let e = check(solid, r, c, GRID, 2e-4, &mut rng);
        println!(
            "{} r = {r} c = {c:?}: [normal, depth, points] {e:?}",
            solid.name
        );
        for k in 0..3 {
            worst[k] = worst[k].max(e[k]);
        }
    }
    println!("sphere–solid vs brute force, worst [normal, depth, points]: {worst:?}");
}

/// The reproduction: `contact query sphere:r=0.6 torus:R=1,r=0.3 --engine exact` at
/// this pose gave depth 0.201664 (the closest point) and a normal 2.48° off; SPEC §4 gives
/// 0.201397.
#[test]
fn the_torus_reproduction_gives_the_definitions_depth() {
    let pose = Isometry3::from_parts(
        Vector3::new(
            -0.8905746147450594,
            -0.12550109474163762,
            -0.6910480248729591,
        )
        .into(),
        contact_core::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
            0.0497942563009202,
            0.37683251904947035,
            -0.8909945672040606,
            -0.24828706337446935,
        )),
    );
    let sphere = instance(Geometry::sphere(0.6).unwrap());
    let tor = torus(1.0, 0.3);
    let found = query(
        &sphere,
        &instance(tor.geometry.clone()),
        &pose,
        &Isometry3::identity(),
    );
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(
        (found[0].penetration - 0.201397).abs() < 1e-6,
        "{}",
        found[0].penetration
    );
    let mut rng = Rng::new(7);
    let e = check(&tor, 0.6, pose.translation.vector, GRID, 2e-4, &mut rng);
    println!("reproduction: [normal, depth, points] {e:?}");
}
