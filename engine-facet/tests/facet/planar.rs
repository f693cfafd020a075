//! 2-D contacts on polylines, against closed forms (circles, lines, arcs) and a brute-force
//! closest point on the true B-spline (curves), within the faceting bound `L/FT` per shape.

use crate::common::Rng;
use contact_core::geometry::{Arc, Circle, Curve, CurvePoints, Line};
use contact_core::{
    Contact, FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3, Point2,
    PrepareError, PreparedPair, QueryError, Vector2, Vector3, WorkCounters,
};
use engine_facet::FacetEngine;
use std::f64::consts::{PI, SQRT_2};

const TOLERANCES: [f64; 4] = [100.0, 300.0028, 1000.0, 3000.0];

fn engine(ft: f64) -> FacetEngine {
    FacetEngine::new(FacetingTolerance::new(ft).unwrap())
}

fn planar_pose(x: f64, y: f64, angle: f64) -> Isometry3 {
    Isometry3::new(Vector3::new(x, y, 0.0), Vector3::z() * angle)
}

fn instance(g: Geometry, flip: bool) -> GeometryInstance {
    let mut i = GeometryInstance::new(g);
    i.flip_normal = flip;
    i
}

fn prepare(e: &FacetEngine, i: GeometryInstance, j: GeometryInstance) -> Box<dyn PreparedPair> {
    e.prepare(&[i], &[j]).unwrap()
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

fn circle(r: f64) -> Geometry {
    Geometry::Circle(Circle::new(r).unwrap())
}

/// The chord deviation of a circle of radius `r` at `ft`: `L/FT`, `L = 2√2·r`.
fn circle_deviation(r: f64, ft: f64) -> f64 {
    2.0 * SQRT_2 * r / ft
}

fn angle_between(a: &Vector3, b: &Vector3) -> f64 {
    a.cross(b).norm().atan2(a.dot(b))
}

#[test]
fn two_circles_match_the_closed_form_within_both_deviations_and_converge() {
    let (ra, rb) = (0.4, 1.0);
    let mut worst_by_ft = Vec::new();
    for ft in TOLERANCES {
        let e = engine(ft);
        let pair = prepare(&e, instance(circle(ra), false), instance(circle(rb), false));
        // The polygons lie within d = L/FT of the circles; the foot and the support are lifted
        // onto Hermite arcs through the true tangents, which leaves an error second order in d.
        let deviations = circle_deviation(ra, ft) + circle_deviation(rb, ft);
        let bound = deviations * deviations / ra;
        let mut rng = Rng(0x2d_c1c1e);
        let mut worst = 0.0f64;
        for _ in 0..300 {
            let theta = rng.range(0.0, 2.0 * PI);
            let depth = rng.range(0.05, 0.3);
            let u = Vector3::new(theta.cos(), theta.sin(), 0.0);
            let d = ra + rb - depth;
            let pose_j = planar_pose(0.3, -0.2, rng.range(0.0, 2.0 * PI));
            let centre = pose_j.translation.vector + d * u;
            let pose_i = planar_pose(centre.x, centre.y, rng.range(0.0, 2.0 * PI));
            let found = query(pair.as_ref(), &pose_i, &pose_j);
            assert_eq!(found.len(), 1, "depth {depth} at θ {theta}");
            let c = found[0];
            let err = (c.penetration - depth).abs();
            assert!(err <= bound, "FT {ft}: depth error {err} > {bound}");
            // J's polygon carries radial normals: its normal field's foot lies on the ray
            // from J's centre, so the normal is exact.
            assert!(
                angle_between(&c.normal_w, &u) < 1e-9,
                "{:?} vs {u:?}",
                c.normal_w
            );
            let on_j = pose_j.translation.vector + rb * u;
            assert!((c.point_j_w.coords - on_j).norm() <= circle_deviation(rb, ft));
            worst = worst.max(err);
        }
        worst_by_ft.push(worst);
    }
    for w in worst_by_ft.windows(2) {
        assert!(
            w[1] < w[0],
            "depth error must shrink as FT rises: {worst_by_ft:?}"
        );
    }
}

#[test]
fn point_and_circle_in_holes_and_discs_match_closed_forms() {
    let ft = 300.0028;
    let e = engine(ft);
    let r = 1.0;
    let dev = circle_deviation(r, ft);
    let mut rng = Rng(77);
    for _ in 0..100 {
        let theta = rng.range(0.0, 2.0 * PI);
        let u = Vector3::new(theta.cos(), theta.sin(), 0.0);
        let spin = rng.range(0.0, 2.0 * PI);
        // A point at distance D < r inside a solid circle: δ = r − D, normal u (outward).
        let dist = rng.range(0.5, 0.98);
        let pair = prepare(
            &e,
            instance(Geometry::Point, false),
            instance(circle(r), false),
        );
        let p = planar_pose(dist * u.x, dist * u.y, 0.0);
        let c = query(pair.as_ref(), &p, &planar_pose(0.0, 0.0, spin))[0];
        assert!((c.penetration - (r - dist)).abs() <= dev);
        assert!(angle_between(&c.normal_w, &u) < 1e-9);
        // A point beyond r in a hole (flipped circle): δ = D − r, normal −u.
        let dist = rng.range(1.02, 1.5);
        let pair = prepare(
            &e,
            instance(Geometry::Point, false),
            instance(circle(r), true),
        );
        let p = planar_pose(dist * u.x, dist * u.y, 0.0);
        let c = query(pair.as_ref(), &p, &planar_pose(0.0, 0.0, spin))[0];
        assert!((c.penetration - (dist - r)).abs() <= dev);
        assert!(angle_between(&c.normal_w, &-u) < 1e-9);
        // A solid circle of radius 0.3 in the hole, centre at D: δ = D + 0.3 − r.
        let ra = 0.3;
        let dist = rng.range(0.75, 0.95);
        let hole = prepare(&e, instance(circle(r), true), instance(circle(ra), false));
        let pose_small = planar_pose(dist * u.x, dist * u.y, rng.range(0.0, 2.0 * PI));
        // I is the hole here: the contact is seen from the hole (normal from the disc, +u).
        let c = query(hole.as_ref(), &planar_pose(0.0, 0.0, spin), &pose_small)[0];
        assert!((c.penetration - (dist + ra - r)).abs() <= dev + circle_deviation(ra, ft));
        assert!(angle_between(&c.normal_w, &u) < 1e-9);
    }
}

#[test]
fn circle_on_a_line_is_exact_up_to_the_circle_polygon() {
    for ft in TOLERANCES {
        let e = engine(ft);
        let r = 0.25;
        let pair = prepare(
            &e,
            instance(circle(r), false),
            instance(Geometry::Line(Line::unbounded()), false),
        );
        let mut rng = Rng(5);
        for _ in 0..50 {
            let height = rng.range(-0.2, 0.24);
            let line_pose = planar_pose(1.0, 2.0, 0.7);
            let centre_local = Vector3::new(rng.range(-3.0, 3.0), height, 0.0);
            let centre = line_pose * nalgebra::Point3::from(centre_local);
            let pose_i = planar_pose(centre.x, centre.y, rng.range(0.0, 2.0 * PI));
            let c = query(pair.as_ref(), &pose_i, &line_pose)[0];
            assert!((c.penetration - (r - height)).abs() <= circle_deviation(r, ft));
            let n = line_pose.rotation * Vector3::y();
            assert!(angle_between(&c.normal_w, &n) < 1e-12);
            // The chord length is the exact 2√(h² − s²) of the polygon's reach h ≤ r.
            if height > 0.0 {
                let exact = 2.0 * (r * r - height * height).sqrt();
                assert!(c.area <= exact + 1e-12 && c.area > 0.0);
            }
        }
    }
}

#[test]
fn arcs_have_material_inside_and_no_contact_beyond_their_ends() {
    let e = engine(300.0028);
    let big = 2.0;
    let range = 1.5 * PI;
    let arc = Geometry::Arc(Arc::new(big, range).unwrap());
    let dev = arc.characteristic_length().unwrap() / 300.0028;
    let pair = prepare(
        &e,
        instance(Geometry::Point, false),
        instance(arc.clone(), false),
    );
    for k in 1..20 {
        let theta = range * k as f64 / 20.0;
        let u = Vector3::new(theta.cos(), theta.sin(), 0.0);
        let p = planar_pose(1.9 * u.x, 1.9 * u.y, 0.0);
        let c = query(pair.as_ref(), &p, &Isometry3::identity())[0];
        assert!(
            (c.penetration - 0.1).abs() <= dev,
            "θ {theta}: {}",
            c.penetration
        );
        let err = angle_between(&c.normal_w, &u);
        assert!(err < 1e-9, "θ {theta}: normal error {err}");
    }
    // Beyond the end at 3π/2 (the point below the arc's end, along its tangent): no contact.
    let beyond = planar_pose(0.3, -1.9, 0.0);
    assert!(query(pair.as_ref(), &beyond, &Isometry3::identity()).is_empty());
    // A circle inside the arc, flipped arc: material outside, so a circle inside is free.
    let flipped = prepare(&e, instance(circle(0.2), false), instance(arc, true));
    let inside = planar_pose(0.0, 1.0, 0.0);
    assert!(query(flipped.as_ref(), &inside, &Isometry3::identity()).is_empty());
    let pressing = planar_pose(0.0, 1.9, 0.0);
    let c = query(flipped.as_ref(), &pressing, &Isometry3::identity())[0];
    assert!((c.penetration - 0.1).abs() <= dev + circle_deviation(0.2, 300.0028));
    assert!(angle_between(&c.normal_w, &Vector3::new(0.0, -1.0, 0.0)) < 1e-9);
}

/// A closed cubic B-spline through control points of a lopsided blob.
fn blob() -> Curve {
    let points: Vec<Point2> = (0..12)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / 12.0;
            let r = 1.0 + 0.25 * (3.0 * t).cos();
            Point2::new(r * t.cos(), 0.8 * r * t.sin())
        })
        .collect();
    Curve::new(&points, 4, true, CurvePoints::Control).unwrap()
}

/// The closest point of the true curve to `p`: a dense scan of the curve's own evaluator, then
/// golden-section refinement; returns (signed distance, outward normal).
fn brute_closest(curve: &Curve, p: &Point2) -> (f64, Vector2) {
    let [u0, u1] = curve.domain();
    let n = 4_000;
    let dist = |u: f64| (p - curve.point(u)).norm();
    let mut best = (f64::INFINITY, u0);
    for k in 0..=n {
        let u = u0 + (u1 - u0) * k as f64 / n as f64;
        let d = dist(u);
        if d < best.0 {
            best = (d, u);
        }
    }
    let h = (u1 - u0) / n as f64;
    let (mut a, mut b) = ((best.1 - h).max(u0), (best.1 + h).min(u1));
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..60 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if dist(c) < dist(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let u = 0.5 * (a + b);
    let normal = curve.normal(u).unwrap();
    ((p - curve.point(u)).dot(&normal), normal)
}

#[test]
fn circle_on_a_curve_matches_a_brute_force_closest_point_and_converges() {
    let curve = blob();
    let length = Geometry::Curve(std::sync::Arc::new(curve.clone()))
        .characteristic_length()
        .unwrap();
    let r = 0.15;
    let mut worst = Vec::new();
    for ft in TOLERANCES {
        let e = engine(ft);
        let pair = prepare(
            &e,
            instance(circle(r), false),
            instance(Geometry::Curve(std::sync::Arc::new(curve.clone())), false),
        );
        let mut rng = Rng(99);
        let (mut depth_err, mut normal_err) = (0.0f64, 0.0f64);
        for _ in 0..100 {
            // A centre near the curve, inside or outside, within the roller's reach.
            let u = rng.range(curve.domain()[0], curve.domain()[1]);
            let n = curve.normal(u).unwrap();
            let centre = curve.point(u) + rng.range(-0.1, 0.12) * n;
            let (s, normal) = brute_closest(&curve, &centre);
            let pose_i = planar_pose(centre.x, centre.y, rng.range(0.0, 2.0 * PI));
            let found = query(pair.as_ref(), &pose_i, &Isometry3::identity());
            assert_eq!(found.len(), 1);
            let c = found[0];
            depth_err = depth_err.max((c.penetration - (r - s)).abs());
            let nw = Vector3::new(normal.x, normal.y, 0.0);
            normal_err = normal_err.max(angle_between(&c.normal_w, &nw));
        }
        let bound = circle_deviation(r, ft) + length / ft;
        assert!(
            depth_err <= bound,
            "FT {ft}: depth error {depth_err} > {bound}"
        );
        worst.push((depth_err, normal_err));
    }
    for w in worst.windows(2) {
        assert!(
            w[1].0 < w[0].0 && w[1].1 < w[0].1,
            "errors must shrink: {worst:?}"
        );
    }
    // At the default tolerance the normal is within 2° (the bound the 3-D pairs meet).
    assert!(worst[1].1 < 2f64.to_radians(), "{worst:?}");
}

#[test]
fn the_normal_turns_smoothly_as_a_point_slides_under_a_curve() {
    let curve = blob();
    let e = engine(100.0);
    let pair = prepare(
        &e,
        instance(Geometry::Point, false),
        instance(Geometry::Curve(std::sync::Arc::new(curve.clone())), false),
    );
    let steps = 4000;
    let [u0, u1] = curve.domain();
    let mut previous: Option<Vector3> = None;
    let mut largest_turn = 0.0f64;
    for k in 0..steps {
        let u = u0 + (u1 - u0) * k as f64 / steps as f64;
        let p = curve.point(u) - 0.02 * curve.normal(u).unwrap();
        let c = query(
            pair.as_ref(),
            &planar_pose(p.x, p.y, 0.0),
            &Isometry3::identity(),
        )[0];
        if let Some(prev) = previous {
            largest_turn = largest_turn.max(angle_between(&prev, &c.normal_w));
        }
        previous = Some(c.normal_w);
    }
    // The true normal turns by at most κ_max·Δs per step; the chords' own normals would jump
    // by their whole angle (several degrees at FT = 100) at every corner.
    assert!(
        largest_turn < 1.0f64.to_radians(),
        "largest turn {largest_turn} rad"
    );
}

#[test]
fn leaving_the_plane_is_an_error_not_a_miss() {
    let e = engine(300.0028);
    let pair = prepare(
        &e,
        instance(circle(0.5), false),
        instance(circle(1.0), false),
    );
    let tilted = Isometry3::new(Vector3::new(1.2, 0.0, 0.0), Vector3::x() * 0.01);
    let mut out = Vec::new();
    let err = pair
        .query(
            &tilted,
            &Isometry3::identity(),
            &mut out,
            &mut WorkCounters::default(),
        )
        .unwrap_err();
    assert!(matches!(err, QueryError::OutOfPlane { .. }), "{err}");
    // A plane with its z axis reversed is the same plane.
    let reversed = Isometry3::new(Vector3::new(1.2, 0.0, 0.0), Vector3::x() * PI);
    assert_eq!(
        query(pair.as_ref(), &reversed, &Isometry3::identity()).len(),
        1
    );
}

#[test]
fn pairs_without_an_area_to_overlap_are_refused_when_checked() {
    let e = engine(300.0028);
    let arc = Geometry::Arc(Arc::new(1.0, 1.0).unwrap());
    let curve = Geometry::Curve(std::sync::Arc::new(blob()));
    // Two boundaries overlap in regions (the exact engine's pairs, flips included).
    assert!(e.supports(&arc, &curve).is_ok());
    assert!(e.supports(&curve, &curve).is_ok());
    assert!(e.supports(&arc, &Geometry::Line(Line::unbounded())).is_ok());
    assert!(
        e.supports(&Geometry::Line(Line::unbounded()), &curve)
            .is_ok()
    );
    assert!(
        e.prepare(
            &[instance(arc.clone(), true)],
            &[instance(curve.clone(), true)]
        )
        .is_ok()
    );
    let lines = Geometry::Line(Line::unbounded());
    assert!(e.supports(&lines, &lines).is_err());
    assert!(e.supports(&Geometry::Point, &Geometry::Point).is_err());
    let bounded = Geometry::Line(Line::bounded(-1.0, 1.0).unwrap());
    assert!(e.supports(&circle(1.0), &bounded).is_err());
    assert!(e.supports(&Geometry::Point, &bounded).is_ok());
    assert!(e.supports(&circle(1.0), &curve).is_ok());
    assert!(e.supports(&curve, &circle(1.0)).is_ok());
    // Flips: two holes, a hole against a curve, and a flipped point.
    let holes = e.prepare(
        &[instance(circle(1.0), true)],
        &[instance(circle(2.0), true)],
    );
    assert!(matches!(holes, Err(PrepareError::Unsupported(_))));
    let hole_curve = e.prepare(&[instance(circle(1.0), true)], &[instance(curve, false)]);
    assert!(matches!(hole_curve, Err(PrepareError::Unsupported(_))));
    let point = e.prepare(
        &[instance(Geometry::Point, true)],
        &[instance(circle(2.0), false)],
    );
    assert!(matches!(point, Err(PrepareError::InvalidArgument { .. })));
}
