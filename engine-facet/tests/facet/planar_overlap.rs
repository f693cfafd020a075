//! Two 2-D boundaries (arcs, curves, lines) on polylines against the exact engine's overlap
//! regions: second-order convergence as FT rises, within a bound from the chord deviation;
//! swap symmetry, rigid-motion invariance, scale covariance, degenerate scenes, and the
//! contact/no-contact answer of random closed-curve pairs.

use crate::common::Rng;
use contact_core::geometry::{Arc, Curve, CurvePoints, Line};
use contact_core::{
    Contact, FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3, Point2,
    PreparedPair, Vector3, WorkCounters,
};
use engine_exact::ExactEngine;
use engine_facet::FacetEngine;
use std::f64::consts::{PI, TAU};
use std::sync::Arc as Shared;

const TOLERANCES: [f64; 5] = [100.0, 300.0028, 1000.0, 3000.0, 10000.0];

fn facet(ft: f64) -> FacetEngine {
    FacetEngine::new(FacetingTolerance::new(ft).unwrap())
}

fn pose(x: f64, y: f64, angle: f64) -> Isometry3 {
    Isometry3::new(Vector3::new(x, y, 0.0), Vector3::z() * angle)
}

fn instance(g: &Geometry, flip: bool) -> GeometryInstance {
    let mut i = GeometryInstance::new(g.clone());
    i.flip_normal = flip;
    i
}

fn prepare(
    e: &dyn GeometryEngine,
    i: &Geometry,
    flip_i: bool,
    j: &Geometry,
    flip_j: bool,
) -> Box<dyn PreparedPair> {
    e.prepare(&[instance(i, flip_i)], &[instance(j, flip_j)])
        .unwrap()
}

fn query(pair: &dyn PreparedPair, pose_i: &Isometry3, pose_j: &Isometry3) -> Vec<Contact> {
    let mut out = Vec::new();
    pair.query(pose_i, pose_j, &mut out, &mut WorkCounters::default())
        .unwrap();
    for c in &out {
        assert!(c.is_well_formed(), "{c:?}");
    }
    out
}

fn angle_between(a: &Vector3, b: &Vector3) -> f64 {
    a.cross(b).norm().atan2(a.dot(b))
}

/// A closed interpolating cubic through `3n` points of `r·(1 + wave·cos(n·a))`.
fn blob(r: f64, n: usize, wave: f64) -> Geometry {
    let points: Vec<Point2> = (0..3 * n)
        .map(|k| {
            let a = TAU * k as f64 / (3 * n) as f64;
            let rho = r * (1.0 + wave * (n as f64 * a).cos());
            Point2::new(rho * a.cos(), rho * a.sin())
        })
        .collect();
    Geometry::Curve(Shared::new(
        Curve::new(&points, 4, true, CurvePoints::Interpolated).unwrap(),
    ))
}

/// An egg-shaped closed cam, scaled by `scale`.
fn cam_scaled(scale: f64) -> Geometry {
    let points: Vec<Point2> = (0..16)
        .map(|k| {
            let a = TAU * k as f64 / 16.0;
            Point2::new(1.2 * a.cos() + 0.2 * (2.0 * a).cos(), 0.9 * a.sin()) * scale
        })
        .collect();
    Geometry::Curve(Shared::new(
        Curve::new(&points, 4, true, CurvePoints::Interpolated).unwrap(),
    ))
}

/// An open cubic wave from x = −1.5 to 1.5 (material below it, outward normal up).
fn wave() -> Geometry {
    let points: Vec<Point2> = (0..9)
        .map(|k| {
            let x = -1.5 + 3.0 * k as f64 / 8.0;
            Point2::new(x, 0.15 * (2.0 * x).sin())
        })
        .collect();
    Geometry::Curve(Shared::new(
        Curve::new(&points, 4, false, CurvePoints::Interpolated).unwrap(),
    ))
}

fn cam() -> Geometry {
    cam_scaled(1.0)
}

fn arc(r: f64, range: f64) -> Geometry {
    Geometry::Arc(Arc::new(r, range).unwrap())
}

/// One configuration family: geometries, flips, and a pose generator for I (J at a random
/// rigid pose of the plane).
struct Family {
    name: &'static str,
    i: Geometry,
    flip_i: bool,
    j: Geometry,
    flip_j: bool,
    /// I's pose relative to J from three uniform numbers in [0, 1).
    place: fn(f64, f64, f64) -> Isometry3,
}

fn families() -> Vec<Family> {
    vec![
        Family {
            name: "curve_curve",
            i: blob(0.5, 5, 0.15),
            flip_i: false,
            j: cam(),
            flip_j: false,
            place: |u, v, w| {
                let a = TAU * u;
                let d = 1.45 - 0.25 * v;
                pose(1.2 * d * a.cos(), 0.9 * d * a.sin(), TAU * w)
            },
        },
        Family {
            name: "arc_curve",
            // A blob pressed into the inside of a three-quarter ring (material inside).
            i: blob(0.5, 5, 0.15),
            flip_i: false,
            j: arc(2.0, 1.5 * PI),
            flip_j: true,
            place: |u, v, w| {
                let a = 1.5 * PI * (0.15 + 0.7 * u);
                let d = 1.45 + 0.15 * v;
                pose(d * a.cos(), d * a.sin(), TAU * w)
            },
        },
        Family {
            name: "arc_arc",
            // A half-disc arc crossing a quarter-turn arc's material.
            i: arc(0.6, PI),
            flip_i: false,
            j: arc(1.5, 1.5 * PI),
            flip_j: false,
            place: |u, v, w| {
                let a = 1.5 * PI * (0.2 + 0.6 * u);
                let d = 1.6 + 0.3 * v;
                // I's arc opens away from J's centre, so its bulge crosses J's arc.
                pose(d * a.cos(), d * a.sin(), a + PI / 2.0 + 0.4 * (w - 0.5))
            },
        },
    ]
}

/// Errors of the faceted contact against the exact one: (depth, normal rad, points).
fn errors(f: &Contact, x: &Contact) -> (f64, f64, f64) {
    let points = (f.point_i_w - x.point_i_w)
        .norm()
        .max((f.point_j_w - x.point_j_w).norm());
    (
        (f.penetration - x.penetration).abs(),
        angle_between(&f.normal_w, &x.normal_w),
        points,
    )
}

/// The smallest radius of curvature of an arc (its radius) or a curve (sampled densely).
fn smallest_radius(g: &Geometry) -> f64 {
    match g {
        Geometry::Arc(a) => a.radius(),
        Geometry::Curve(c) => {
            let [u0, u1] = c.domain();
            (0..=4000)
                .map(|k| {
                    let u = u0 + (u1 - u0) * k as f64 / 4000.0;
                    let (d1, d2) = (c.derivative(u), c.second_derivative(u));
                    d1.norm().powi(3) / (d1.x * d2.y - d1.y * d2.x).abs()
                })
                .fold(f64::INFINITY, f64::min)
        }
        _ => f64::INFINITY,
    }
}

/// The poses of a family where the exact engine finds one region at least 1% of `L` deep.
fn exact_poses(fam: &Family, count: usize, seed: u64) -> Vec<(Isometry3, Isometry3, Contact)> {
    let exact = ExactEngine;
    let pair = prepare(&exact, &fam.i, fam.flip_i, &fam.j, fam.flip_j);
    let length = pair_length(fam);
    let mut rng = Rng(seed);
    let mut poses = Vec::new();
    while poses.len() < count {
        let pose_j = pose(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(0.0, TAU),
        );
        let rel = (fam.place)(rng.next_f64(), rng.next_f64(), rng.next_f64());
        let pose_i = pose_j * rel;
        let x = query(pair.as_ref(), &pose_i, &pose_j);
        if x.len() == 1 && x[0].penetration > 0.01 * length {
            poses.push((pose_i, pose_j, x[0]));
        }
    }
    poses
}

fn pair_length(fam: &Family) -> f64 {
    fam.i
        .characteristic_length()
        .unwrap()
        .max(fam.j.characteristic_length().unwrap())
}

#[test]
fn overlap_errors_fall_at_second_order_against_the_exact_engine() {
    for fam in families() {
        let poses = exact_poses(&fam, 40, 0x0e_2d);
        let length = pair_length(&fam);
        let rho = smallest_radius(&fam.i).min(smallest_radius(&fam.j));
        let narrowest = poses.iter().map(|p| p.2.area).fold(f64::INFINITY, f64::min);
        let mut table = Vec::new();
        for ft in TOLERANCES {
            let pair = prepare(&facet(ft), &fam.i, fam.flip_i, &fam.j, fam.flip_j);
            let mut worst = (0.0f64, 0.0f64, 0.0f64);
            for (pose_i, pose_j, x) in &poses {
                let found = query(pair.as_ref(), pose_i, pose_j);
                assert_eq!(found.len(), 1, "{} FT {ft}: {found:?} vs {x:?}", fam.name);
                let e = errors(&found[0], x);
                worst = (worst.0.max(e.0), worst.1.max(e.1), worst.2.max(e.2));
            }
            // The module's bound: the lifted arcs lie within O(d²/ρ) of the shapes, so the
            // depth and the points move by about d²/ρ and the normal by d²/(ρ·w).
            let d = length / ft;
            let bound = d * d / rho;
            println!(
                "{} FT {ft}: d {d:.3e} bound {bound:.3e} | depth {:.3e} normal {:.3e} rad \
                 points {:.3e}",
                fam.name, worst.0, worst.1, worst.2
            );
            assert!(
                worst.0 <= bound && worst.2 <= bound,
                "{} FT {ft}: {worst:?} > {bound}",
                fam.name
            );
            assert!(
                worst.1 <= bound / narrowest,
                "{} FT {ft}: {worst:?}",
                fam.name
            );
            table.push(worst);
        }
        for w in table.windows(2) {
            assert!(
                w[1].0 < w[0].0 && w[1].1 < w[0].1 && w[1].2 < w[0].2,
                "{}: errors must fall at every FT step: {table:?}",
                fam.name
            );
        }
    }
}

/// The faceted contact with I and J exchanged is the swapped contact (to round-off), and a
/// rigid motion of the plane moves the contact with it.
#[test]
fn swapping_and_moving_the_pair_moves_the_contact() {
    let e = facet(300.0028);
    let mut rng = Rng(31);
    for fam in families() {
        let length = pair_length(&fam);
        let forward = prepare(&e, &fam.i, fam.flip_i, &fam.j, fam.flip_j);
        let backward = prepare(&e, &fam.j, fam.flip_j, &fam.i, fam.flip_i);
        for (pose_i, pose_j, _) in exact_poses(&fam, 15, 0x5a_5a) {
            let c = query(forward.as_ref(), &pose_i, &pose_j);
            let s = query(backward.as_ref(), &pose_j, &pose_i);
            assert_eq!(c.len(), 1);
            assert_eq!(s.len(), 1);
            let (c, s) = (c[0], s[0]);
            let tol = 1e-9 * length;
            assert!((c.penetration - s.penetration).abs() <= tol, "{c:?} {s:?}");
            assert!((c.normal_w + s.normal_w).norm() <= 1e-9);
            assert!((c.point_i_w - s.point_j_w).norm() <= tol);
            assert!((c.point_j_w - s.point_i_w).norm() <= tol);
            assert!((c.area - s.area).abs() <= tol);
            // A rigid motion of the plane (a turn about z and a shift).
            let motion = pose(
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
                rng.range(0.0, TAU),
            );
            let m = query(forward.as_ref(), &(motion * pose_i), &(motion * pose_j))[0];
            assert!((m.penetration - c.penetration).abs() <= tol);
            assert!((m.normal_w - motion.rotation * c.normal_w).norm() <= 1e-9);
            assert!((m.point_i_w - motion * c.point_i_w).norm() <= 10.0 * tol);
            assert!((m.point_j_w - motion * c.point_j_w).norm() <= 10.0 * tol);
        }
    }
}
