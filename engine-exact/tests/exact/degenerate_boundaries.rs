//! Degenerate boundary–boundary pairs (arcs, curves, lines): touching, coincident, open ends,
//! containment, near-tangent and random simple shapes — finite answers, the documented values.

use crate::characterization::planar_overlap::{
    cubic_blob, planar_pose, polyline, rectangle, v_shape,
};
use crate::common::{instance, one, query};
use contact_core::geometry::{Arc, Line};
use contact_core::{Contact, Geometry, Isometry3, Point3, Vector3};
use std::f64::consts::TAU;
use std::sync::Arc as Shared;

fn circle_arc(r: f64) -> contact_core::GeometryInstance {
    instance(Geometry::Arc(Arc::new(r, TAU).unwrap()))
}

fn line() -> contact_core::GeometryInstance {
    instance(Geometry::Line(Line::unbounded()))
}

#[test]
fn touching_boundaries_give_no_contact_and_a_hair_deeper_a_finite_one() {
    // Two unit circles (full arcs) 2 apart touch at one point: no area. In f64 the
    // circles agree to round-off along a short stretch, so a contact of round-off depth
    // may appear; nothing deeper.
    let touching = query(
        &circle_arc(1.0),
        &circle_arc(1.0),
        &Isometry3::translation(2.0, 0.0, 0.0),
        &Isometry3::identity(),
    );
    assert!(
        touching.iter().all(|c| c.penetration < 1e-13),
        "{touching:?}"
    );
    // A unit circle resting on the line, then 1e-9 lower.
    let resting = query(
        &circle_arc(1.0),
        &line(),
        &planar_pose(0.3, 1.0, 0.0),
        &Isometry3::identity(),
    );
    assert!(resting.iter().all(|c| c.penetration < 1e-13), "{resting:?}");
    let c = one(
        &circle_arc(1.0),
        &line(),
        &planar_pose(0.3, 1.0 - 1e-9, 0.0),
        &Isometry3::identity(),
    );
    // A region 1e-5 as deep as it is wide: its centroid is conditioned ~1e5 worse than
    // round-off, still far inside the 1e-9 target.
    assert!((c.penetration - 1e-9).abs() < 1e-13, "{c:?}");
    assert!((c.normal_w - Vector3::y()).norm() < 1e-9, "{c:?}");
    // Chord 2√(2·1e-9): each crossing is found to round-off over the sine of its angle
    // (ε/4.5e-5 ≈ 2.5e-12).
    assert!((c.area - 2.0 * (2e-9f64).sqrt()).abs() < 1e-11, "{c:?}");
}

#[test]
fn coincident_boundaries_give_no_contact() {
    // Documented: coincident boundaries cross nowhere transversally and neither lies
    // strictly inside the other; the penetration along the shared boundary is zero.
    let blob = instance(Geometry::Curve(Shared::new(cubic_blob(1.0))));
    let pose = planar_pose(0.4, -0.2, 0.7);
    assert!(query(&blob, &blob, &pose, &pose).is_empty());
    assert!(query(&circle_arc(1.5), &circle_arc(1.5), &pose, &pose).is_empty());
    // A rectangle whose bottom edge lies on the line.
    let square = instance(rectangle(-1.0, 1.0, 0.0, 2.0));
    assert!(
        query(
            &square,
            &line(),
            &Isometry3::identity(),
            &Isometry3::identity()
        )
        .is_empty()
    );
    // Lowered a little, the overlap is the strip below the line.
    let c = one(
        &square,
        &line(),
        &planar_pose(0.0, -0.25, 0.0),
        &Isometry3::identity(),
    );
    assert!(
        (c.penetration - 0.25).abs() < 1e-12 && (c.area - 2.0).abs() < 1e-12,
        "{c:?}"
    );
}

fn truncated_v(end_y: f64) -> contact_core::GeometryInstance {
    // The V of depth 0.5 whose right arm (slope 0.75) stops at height `end_y`.
    let end_x = (end_y + 0.5) / 0.75;
    instance(polyline(&[[-2.0, 1.0], [0.0, -0.5], [end_x, end_y]], false))
}

fn close(a: &Contact, b: &Contact, tol: f64) -> bool {
    (a.point_i_w - b.point_i_w).norm() < tol
        && (a.point_j_w - b.point_j_w).norm() < tol
        && (a.normal_w - b.normal_w).norm() < tol
        && (a.penetration - b.penetration).abs() < tol
        && (a.area - b.area).abs() < tol
}

#[test]
fn an_open_end_inside_closes_its_region_at_its_foot_continuously() {
    // The end at (x_e, −0.25) is inside the line's material: the region is bounded by the
    // V from the left crossing (−4/3·0.5 = −2/3, 0) through the tip to the end, the
    // segment to the foot (x_e, 0), and the line back: a quadrilateral.
    let x_e = 0.25 / 0.75;
    let c = one(
        &truncated_v(-0.25),
        &line(),
        &Isometry3::identity(),
        &Isometry3::identity(),
    );
    // S = ½(S_a − S_b): S_a the V's chord from (−2/3, 0) to (x_e, −0.25) turned by −90°,
    // S_b the line's stretch from the foot (x_e, 0) back to (−2/3, 0), turned likewise.
    let (chord_a, chord_b) = ((x_e + 2.0 / 3.0, -0.25), (-2.0 / 3.0 - x_e, 0.0));
    let s = Vector3::new(
        0.5 * (chord_a.1 - chord_b.1),
        0.5 * (-chord_a.0 + chord_b.0),
        0.0,
    );
    let n = -s / s.norm();
    assert!((c.normal_w - n).norm() < 1e-12, "{c:?}");
    assert!((c.area - s.norm()).abs() < 1e-12, "{c:?}");
    // Oracle centroid of the quadrilateral (−2/3, 0), (0, −0.5), (x_e, −0.25), (x_e, 0).
    let quad = [(-2.0 / 3.0, 0.0), (0.0, -0.5), (x_e, -0.25), (x_e, 0.0)];
    let (mut a2, mut gx, mut gy) = (0.0, 0.0, 0.0);
    for k in 0..4 {
        let (p, q) = (quad[k], quad[(k + 1) % 4]);
        let cross = p.0 * q.1 - q.0 * p.1;
        a2 += cross;
        gx += (p.0 + q.0) * cross;
        gy += (p.1 + q.1) * cross;
    }
    let g = Point3::new(gx / (3.0 * a2), gy / (3.0 * a2), 0.0);
    // Both contact points lie on the line through the centroid along the normal.
    for p in [c.point_i_w, c.point_j_w] {
        assert!((p - g).cross(&n).norm() < 1e-12, "{c:?} {g:?}");
    }
    assert!(c.point_j_w.y.abs() < 1e-12, "{c:?}");
    // As the end rises through the line, the contact changes continuously.
    let below = one(
        &truncated_v(-1e-7),
        &line(),
        &Isometry3::identity(),
        &Isometry3::identity(),
    );
    let above = one(
        &truncated_v(1e-7),
        &line(),
        &Isometry3::identity(),
        &Isometry3::identity(),
    );
    assert!(close(&below, &above, 1e-6), "{below:?} vs {above:?}");
    // Against the whole V (both ends out) the answer is the triangle's.
    let full = one(
        &instance(v_shape(0.5)),
        &line(),
        &Isometry3::identity(),
        &Isometry3::identity(),
    );
    assert!((full.penetration - 0.5).abs() < 1e-12, "{full:?}");
}

#[test]
fn an_end_poking_straight_in_gives_no_contact() {
    // An open segment along the line's normal, ending 0.5 deep: no area is enclosed.
    let probe = instance(polyline(&[[0.0, 1.0], [0.0, -0.5]], false));
    assert!(
        query(
            &probe,
            &line(),
            &Isometry3::identity(),
            &Isometry3::identity()
        )
        .is_empty()
    );
}

#[test]
fn a_closed_boundary_inside_another_gives_one_contact_towards_the_way_out() {
    // Circle r = 0.5 at (0.8, 0) inside the circle R = 2: the way out is +x, the outer
    // point (2, 0), the inner (0.3, 0), depth 1.7, length the diameter 1.
    let c = one(
        &circle_arc(0.5),
        &circle_arc(2.0),
        &planar_pose(0.8, 0.0, 1.0),
        &Isometry3::identity(),
    );
    assert!((c.normal_w - Vector3::x()).norm() < 1e-12, "{c:?}");
    assert!(
        (c.point_j_w - Point3::new(2.0, 0.0, 0.0)).norm() < 1e-12,
        "{c:?}"
    );
    assert!(
        (c.point_i_w - Point3::new(0.3, 0.0, 0.0)).norm() < 1e-12,
        "{c:?}"
    );
    assert!((c.penetration - 1.7).abs() < 1e-12, "{c:?}");
    assert!((c.area - 1.0).abs() < 1e-6, "{c:?}");
    // The other order: the same contact, swapped.
    let d = one(
        &circle_arc(2.0),
        &circle_arc(0.5),
        &Isometry3::identity(),
        &planar_pose(0.8, 0.0, 1.0),
    );
    assert!((d.swapped().normal_w - c.normal_w).norm() < 1e-12, "{d:?}");
    assert!((d.penetration - c.penetration).abs() < 1e-12, "{d:?}");
}

#[test]
fn grazing_and_random_near_tangent_scenes_stay_finite() {
    let mut rng = crate::common::Rng::new(77);
    let blob = instance(Geometry::Curve(Shared::new(cubic_blob(1.0))));
    for _ in 0..200 {
        // Centre distances within 1e-12 .. 1e-3 of tangency, either side.
        let gap = rng.uniform(-1.0, 1.0) * 10f64.powf(rng.uniform(-12.0, -3.0));
        let phi = rng.uniform(0.0, TAU);
        let d = 2.0 + gap;
        let pose = planar_pose(d * phi.cos(), d * phi.sin(), rng.uniform(0.0, TAU));
        for c in query(
            &circle_arc(1.0),
            &circle_arc(1.0),
            &pose,
            &Isometry3::identity(),
        ) {
            assert!(c.penetration <= 1e-3 + 1e-12, "{c:?}");
        }
        let lift = 0.9 + gap;
        for c in query(
            &blob,
            &line(),
            &planar_pose(0.0, lift, 0.0),
            &Isometry3::identity(),
        ) {
            assert!(c.penetration.is_finite() && c.area.is_finite(), "{c:?}");
        }
    }
}

#[test]
fn random_curves_arcs_and_lines_never_panic_or_give_nan() {
    use contact_core::Point2;
    use contact_core::geometry::{Curve, CurvePoints};
    let mut rng = crate::common::Rng::new(0xBAD5EED);
    let (mut contacts, mut symmetric) = (0, 0);
    for _ in 0..500 {
        let random_geometry = |rng: &mut crate::common::Rng| -> contact_core::GeometryInstance {
            let g = match (rng.uniform(0.0, 3.0) as usize).min(2) {
                0 => {
                    // Simple curves (a self-crossing boundary has no material to
                    // speak of): star-shaped closed ones, x-monotone open ones.
                    let count = 4 + (rng.uniform(0.0, 6.0) as usize);
                    let closed = rng.uniform(0.0, 1.0) < 0.5;
                    let mut ts: Vec<f64> = (0..count).map(|_| rng.uniform(0.0, 1.0)).collect();
                    ts.sort_by(f64::total_cmp);
                    let points: Vec<Point2> = ts
                        .iter()
                        .map(|t| {
                            if closed {
                                let (a, r) = (TAU * t, rng.uniform(0.7, 1.1));
                                Point2::new(r * a.cos(), r * a.sin())
                            } else {
                                Point2::new(4.0 * t - 2.0, rng.uniform(-0.8, 0.8))
                            }
                        })
                        .collect();
                    let order = 2 + (rng.uniform(0.0, 3.0) as usize).min(2);
                    let kind = if rng.uniform(0.0, 1.0) < 0.5 {
                        CurvePoints::Control
                    } else {
                        CurvePoints::Interpolated
                    };
                    match Curve::new(&points, order, closed, kind) {
                        Ok(c) => Geometry::Curve(Shared::new(c)),
                        Err(_) => Geometry::Arc(Arc::new(0.7, 4.0).unwrap()),
                    }
                }
                1 => Geometry::Arc(Arc::new(rng.uniform(0.2, 1.5), rng.uniform(0.1, TAU)).unwrap()),
                _ => Geometry::Line(
                    Line::bounded(rng.uniform(-3.0, 0.0), rng.uniform(0.1, 3.0)).unwrap(),
                ),
            };
            let g = instance(g);
            if rng.uniform(0.0, 1.0) < 0.3 {
                g.flipped()
            } else {
                g
            }
        };
        let (i, j) = (random_geometry(&mut rng), random_geometry(&mut rng));
        if matches!(*i.geometry, Geometry::Line(_)) && matches!(*j.geometry, Geometry::Line(_)) {
            continue;
        }
        let pose_i = planar_pose(
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(0.0, TAU),
        );
        // `query` asserts every contact is well formed (finite, unit normal, δ ≥ 0).
        let found = query(&i, &j, &pose_i, &Isometry3::identity());
        contacts += found.len();
        // Exchanging I and J gives the same contacts, swapped (in any order), when one
        // of the two is closed. Two open boundaries whose ends lie in each other's
        // material close their regions at feet that need not pair up, so their answers
        // may depend on the order (documented in `planar::overlap`).
        let closed = |g: &contact_core::GeometryInstance| match &*g.geometry {
            Geometry::Curve(c) => c.is_closed(),
            Geometry::Arc(a) => a.range_angle() >= TAU,
            _ => false,
        };
        if !(closed(&i) || closed(&j)) {
            continue;
        }
        symmetric += 1;
        let backward = query(&j, &i, &Isometry3::identity(), &pose_i);
        assert_eq!(found.len(), backward.len(), "{i:?}\n{j:?}\n{pose_i:?}");
        for f in &found {
            assert!(
                backward.iter().any(|b| {
                    let b = b.swapped();
                    (b.point_i_w - f.point_i_w).norm() < 1e-9
                        && (b.normal_w - f.normal_w).norm() < 1e-9
                        && (b.penetration - f.penetration).abs() < 1e-9
                }),
                "{f:?} not in {backward:?}"
            );
        }
    }
    assert!(symmetric > 100, "only {symmetric} symmetric checks");
    assert!(contacts > 50, "only {contacts} contacts");
}
