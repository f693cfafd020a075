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

/// Touching, grazing, coincident, contained and scaled scenes: no panic, no NaN (every
/// contact is checked well formed), and the answers the module doc states.
#[test]
fn degenerate_scenes_answer_without_panic_or_nan() {
    let exact = ExactEngine;
    for ft in [100.0, 300.0028, 10000.0] {
        let e = facet(ft);
        let ring = arc(1.0, TAU);
        let pair = prepare(&e, &ring, false, &ring, false);
        // Coincident: the same closed boundary at the same pose, and a blob on itself.
        assert!(query(pair.as_ref(), &pose(0.3, 0.2, 0.1), &pose(0.3, 0.2, 0.1)).is_empty());
        let b = blob(0.5, 5, 0.15);
        let blobs = prepare(&e, &b, false, &b, false);
        assert!(query(blobs.as_ref(), &pose(0.0, 0.0, 1.0), &pose(0.0, 0.0, 1.0)).is_empty());
        // Touching and grazing: at most a contact of depth far below d.
        let d = ring.characteristic_length().unwrap() / ft;
        for gap in [0.0, 1e-12, -1e-12, -1e-9, 1e-9] {
            for c in query(
                pair.as_ref(),
                &pose(2.0 + gap, 0.0, 0.3),
                &pose(0.0, 0.0, 0.0),
            ) {
                assert!(c.penetration <= d * d, "FT {ft} gap {gap}: {c:?}");
            }
        }
        // Contained: a small ring inside a large one (no crossing, both closed), against
        // the exact engine.
        let small = arc(0.3, TAU);
        let big = arc(1.0, TAU);
        let (pi, pj) = (pose(0.4, 0.1, 0.2), pose(0.0, 0.0, 0.0));
        let f = query(prepare(&e, &small, false, &big, false).as_ref(), &pi, &pj);
        let x = query(
            prepare(&exact, &small, false, &big, false).as_ref(),
            &pi,
            &pj,
        );
        assert_eq!((f.len(), x.len()), (1, 1));
        let (de, ne, pe) = errors(&f[0], &x[0]);
        let bound = d * d / 0.3;
        // The contained branch's normal points at the closest point of the lifted arcs,
        // whose tangents are third order in the chord angle: (d/ρ)^(3/2).
        let normal_bound = (d / 0.3f64).powf(1.5);
        // The outer point is that foot: off along the outer chain by the normal's error
        // times the depth.
        let point_bound = bound + normal_bound * x[0].penetration;
        assert!(
            de <= bound && pe <= point_bound && ne <= normal_bound,
            "{f:?} vs {x:?}"
        );
        // Reversed roles: the big ring inside... the small one holds nothing; swapped I/J.
        let g = query(prepare(&e, &big, false, &small, false).as_ref(), &pj, &pi);
        assert_eq!(g.len(), 1);
        assert!((g[0].normal_w + f[0].normal_w).norm() <= 1e-9);
    }
    // Huge and tiny scenes: the contact scales with the scene.
    let reference = {
        let e = facet(300.0028);
        let pair = prepare(&e, &blob(0.5, 5, 0.15), false, &cam(), false);
        query(pair.as_ref(), &pose(1.3, 0.2, 0.4), &pose(0.0, 0.0, 0.0))
    };
    assert_eq!(reference.len(), 1);
    for scale in [1e-6, 1e6] {
        let e = facet(300.0028);
        let pair = prepare(
            &e,
            &blob(0.5 * scale, 5, 0.15),
            false,
            &cam_scaled(scale),
            false,
        );
        let found = query(
            pair.as_ref(),
            &pose(1.3 * scale, 0.2 * scale, 0.4),
            &pose(0.0, 0.0, 0.0),
        );
        assert_eq!(found.len(), 1, "scale {scale}");
        let (c, r) = (found[0], reference[0]);
        assert!((c.penetration / scale - r.penetration).abs() <= 1e-9 * r.penetration.max(1.0));
        assert!((c.normal_w - r.normal_w).norm() <= 1e-9);
        assert!((c.point_i_w / scale - r.point_i_w).norm() <= 1e-9);
        assert!((c.area / scale - r.area).abs() <= 1e-9);
    }
}

/// Open and closed curves against lines (bounded and not, flipped, the line as I or J) match
/// the exact engine within d²/ρ.
#[test]
fn curves_on_lines_match_the_exact_engine() {
    let exact = ExactEngine;
    let lines = [
        Geometry::Line(Line::unbounded()),
        Geometry::Line(Line::bounded(-0.4, 5.0).unwrap()),
    ];
    let shapes = [wave(), blob(0.5, 5, 0.15)];
    let mut rng = Rng(404);
    for line in &lines {
        for shape in &shapes {
            for flip_line in [false, true] {
                let ft = 1000.0;
                let rho = smallest_radius(shape);
                let d = shape.characteristic_length().unwrap() / ft;
                let bound = d * d / rho;
                let f_pair = prepare(&facet(ft), shape, false, line, flip_line);
                let x_pair = prepare(&exact, shape, false, line, flip_line);
                let f_back = prepare(&facet(ft), line, flip_line, shape, false);
                let mut compared = 0;
                for _ in 0..30 {
                    let pose_j = pose(
                        rng.range(-1.0, 1.0),
                        rng.range(-1.0, 1.0),
                        rng.range(0.0, TAU),
                    );
                    let rel = pose(
                        rng.range(-0.5, 0.5),
                        rng.range(-0.3, 0.3),
                        rng.range(0.0, TAU),
                    );
                    let pose_i = pose_j * rel;
                    let x = query(x_pair.as_ref(), &pose_i, &pose_j);
                    let f = query(f_pair.as_ref(), &pose_i, &pose_j);
                    let back = query(f_back.as_ref(), &pose_j, &pose_i);
                    assert_eq!(f.len(), back.len());
                    for (c, s) in f.iter().zip(&back) {
                        assert!((c.penetration - s.penetration).abs() <= 1e-9);
                        assert!((c.normal_w + s.normal_w).norm() <= 1e-9);
                    }
                    // Compare where every exact region is deep enough to be decided on the
                    // polylines.
                    if x.iter().all(|c| c.penetration > 0.02) && x.len() == f.len() {
                        for c in &f {
                            let xc = x
                                .iter()
                                .min_by(|a, b| {
                                    (a.point_i_w - c.point_i_w)
                                        .norm()
                                        .total_cmp(&(b.point_i_w - c.point_i_w).norm())
                                })
                                .unwrap();
                            let best = x
                                .iter()
                                .map(|xx| errors(c, xx))
                                .min_by(|a, b| a.2.total_cmp(&b.2))
                                .unwrap();
                            // The normal's error d²/(ρ·w) carried along the depth adds to
                            // the points' and the depth's.
                            // The open wave's Hermite error follows its fourth derivative
                            // (h⁴·|x⁗|/384), large against its curvature: a factor 4.
                            let bound = 4.0 * bound * (1.0 + xc.penetration / xc.area);
                            assert!(
                                best.0 <= bound && best.2 <= bound,
                                "{best:?} > {bound} for {shape:?} on {line:?} flipped \
                                 {flip_line}: {c:?} vs {x:?}"
                            );
                        }
                        compared += x.len();
                    }
                }
                assert!(
                    compared > 0,
                    "no contact compared for {shape:?} on {line:?}"
                );
            }
        }
    }
}

/// The contact/no-contact answer of random closed-curve pairs agrees with the exact engine
/// wherever the pose is farther than the chord deviation from touching: a contact of depth
/// above `2d`, or curves more than `2d` apart (a dense sample of the true curves).
#[test]
fn random_closed_curves_agree_with_the_exact_engine_away_from_touching() {
    let exact = ExactEngine;
    let ft = 1000.0;
    let mut rng = Rng(2024);
    let (mut agreed_contact, mut agreed_free) = (0, 0);
    for _ in 0..12 {
        let gi = blob(
            rng.range(0.3, 0.7),
            3 + (rng.next_f64() * 4.0) as usize,
            rng.range(0.0, 0.2),
        );
        let gj = blob(
            rng.range(0.3, 0.7),
            3 + (rng.next_f64() * 4.0) as usize,
            rng.range(0.0, 0.2),
        );
        let d = gi
            .characteristic_length()
            .unwrap()
            .max(gj.characteristic_length().unwrap())
            / ft;
        let f_pair = prepare(&facet(ft), &gi, false, &gj, false);
        let x_pair = prepare(&exact, &gi, false, &gj, false);
        let samples = |g: &Geometry, p: &Isometry3| -> Vec<Vector3> {
            let Geometry::Curve(c) = g else {
                unreachable!()
            };
            let [u0, u1] = c.domain();
            (0..600)
                .map(|k| {
                    let q = c.point(u0 + (u1 - u0) * k as f64 / 600.0);
                    (p * nalgebra::Point3::new(q.x, q.y, 0.0)).coords
                })
                .collect()
        };
        for _ in 0..10 {
            let a = rng.range(0.0, TAU);
            let dist = rng.range(0.4, 1.6);
            let pose_j = pose(0.0, 0.0, rng.range(0.0, TAU));
            let pose_i = pose(dist * a.cos(), dist * a.sin(), rng.range(0.0, TAU));
            let x = query(x_pair.as_ref(), &pose_i, &pose_j);
            let f = query(f_pair.as_ref(), &pose_i, &pose_j);
            if !x.is_empty() && x.iter().all(|c| c.penetration > 2.0 * d) {
                assert_eq!(f.len(), x.len(), "{f:?} vs {x:?}");
                agreed_contact += 1;
            } else if x.is_empty() {
                let (si, sj) = (samples(&gi, &pose_i), samples(&gj, &pose_j));
                let spacing = si
                    .windows(2)
                    .chain(sj.windows(2))
                    .map(|w| (w[1] - w[0]).norm())
                    .fold(0.0, f64::max);
                let gap = si
                    .iter()
                    .flat_map(|p| sj.iter().map(move |q| (p - q).norm()))
                    .fold(f64::INFINITY, f64::min);
                if gap > 2.0 * d + spacing {
                    assert!(f.is_empty(), "gap {gap}: {f:?}");
                    agreed_free += 1;
                }
            }
        }
    }
    assert!(
        agreed_contact >= 20 && agreed_free >= 10,
        "{agreed_contact} {agreed_free}"
    );
}
