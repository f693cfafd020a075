//! A tessellated sphere or ellipsoid on one face of a faceted box answers as the solid it
//! stands for on that face's plane: the exact engine's ellipsoid–plane contact (its own closed
//! form, written apart) wherever the solid reaches no other face, in either order of the pair;
//! over an edge, where the facets answer, within the chord deviation of the exact engine's
//! ellipsoid–box contact.

use crate::common::{Rng, engine, prepare, query_pair};
use contact_core::geometry::{Cuboid, Ellipsoid, Plane};
use contact_core::{Contact, Vector3};
use contact_core::{FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3};

const SPHERE: [f64; 3] = [0.1, 0.1, 0.1];
const ELLIPSOID: [f64; 3] = [0.1, 0.07, 0.05];

fn solid(semi: [f64; 3]) -> Geometry {
    Geometry::Ellipsoid(Ellipsoid::new(semi[0], semi[1], semi[2]).unwrap())
}

/// A 2 × 2 × 0.2 box whose top face is the square |x|, |y| ≤ 1 of the plane z = 0.
fn ground() -> (Geometry, Isometry3) {
    let cuboid = Cuboid::from_corner(2.0, 2.0, 0.2).unwrap();
    let pose = Isometry3::translation(-1.0, -1.0, -0.2);
    (Geometry::Cuboid(cuboid), pose)
}

/// The solid at a seeded orientation, its centre over (x, y) and `d = k·(1 − t)` above z = 0,
/// which puts the cap's height in the solid's unit-ball image at `t` (`k` its support function).
fn pose(semi: [f64; 3], rng: &mut Rng, x: f64, y: f64, t: f64) -> Isometry3 {
    let rotation = rng.rotation();
    let n = rotation.inverse_transform_vector(&Vector3::z());
    let k = Vector3::from(semi).component_mul(&n).norm();
    Isometry3::from_parts(Vector3::new(x, y, k * (1.0 - t)).into(), rotation)
}

fn exact(semi: [f64; 3], j: Geometry, pose_i: &Isometry3, pose_j: &Isometry3) -> Vec<Contact> {
    let pair = engine_exact::ExactEngine
        .prepare(
            &[GeometryInstance::new(solid(semi))],
            &[GeometryInstance::new(j)],
        )
        .unwrap();
    query_pair(pair.as_ref(), *pose_i, *pose_j).0
}

fn errors(got: &Contact, want: &Contact) -> [f64; 4] {
    [
        (got.penetration - want.penetration).abs(),
        (got.normal_w - want.normal_w).norm(),
        (got.point_i_w - want.point_i_w).norm() + (got.point_j_w - want.point_j_w).norm(),
        (got.area - want.area).abs(),
    ]
}

fn swapped(c: &Contact) -> Contact {
    Contact {
        point_i_w: c.point_j_w,
        point_j_w: c.point_i_w,
        normal_w: -c.normal_w,
        ..*c
    }
}

#[test]
fn a_solid_on_one_face_is_the_exact_engines_contact_with_its_plane_in_either_order() {
    let (ground, ground_pose) = ground();
    for semi in [SPHERE, ELLIPSOID] {
        for ft in [30.0, 300.0028, 3000.0] {
            let facet = engine(ft);
            let on_box = prepare(&facet, solid(semi), ground.clone());
            let box_on = prepare(&facet, ground.clone(), solid(semi));
            let mut rng = Rng(0x5eed_b0c5);
            let mut compared = 0;
            for k in 0..120 {
                // Caps from just apart to 1/8 of the unit ball, anywhere over the face's
                // middle (the solid reaches no side).
                let t = -0.01 + 0.135 * f64::from(k % 20) / 19.0;
                let (x, y) = (rng.range(-0.8, 0.8), rng.range(-0.8, 0.8));
                let pose = pose(semi, &mut rng, x, y, t);
                let plane = Geometry::Plane(Plane::unbounded());
                let want = exact(semi, plane, &pose, &Isometry3::identity());
                let (got, _) = query_pair(on_box.as_ref(), pose, ground_pose);
                let (got_swapped, _) = query_pair(box_on.as_ref(), ground_pose, pose);
                let label = format!("{semi:?}, FT {ft}, {k}, t = {t}");
                assert_eq!(got.len(), want.len(), "{label}: {got:?} against {want:?}");
                assert_eq!(got_swapped.len(), want.len(), "{label}");
                for ((g, s), w) in got.iter().zip(&got_swapped).zip(&want) {
                    for found in [*g, swapped(s)] {
                        let [depth, normal, points, area] = errors(&found, w);
                        // Round-off of the fit (some 1e-13 of the size) and of the face's frame.
                        assert!(
                            depth < 1e-12 * semi[0]
                                && normal < 1e-13
                                && points < 1e-12 * semi[0]
                                && area < 1e-12 * semi[0] * semi[0],
                            "{label}: {:?}",
                            errors(&found, w)
                        );
                    }
                    compared += 1;
                }
            }
            assert!(compared > 90, "{compared}");
        }
    }
}

#[test]
fn over_an_edge_the_facets_answer_within_the_chord_deviation() {
    let (ground, ground_pose) = ground();
    for semi in [SPHERE, ELLIPSOID] {
        let length = solid(semi).characteristic_length().unwrap();
        for ft in [300.0028, 3000.0] {
            let deviation = FacetingTolerance::new(ft).unwrap().chord_deviation(length);
            let on_box = prepare(&engine(ft), solid(semi), ground.clone());
            let mut rng = Rng(0xed9e);
            let mut touching = 0;
            for k in 0..60 {
                // Centres over the edge x = 1, the cap 1/16 deep: the solid reaches the side.
                let x = 1.0 + rng.range(-0.02, 0.02);
                let pose = pose(semi, &mut rng, x, 0.3, 0.0625);
                let want = exact(semi, ground.clone(), &pose, &ground_pose);
                let (got, _) = query_pair(on_box.as_ref(), pose, ground_pose);
                assert!(want.len() <= 1, "{semi:?}, FT {ft}, {k}: {want:?}");
                let Some(want) = want.first() else {
                    // Clear of the box: so are the facets, inscribed in the solid.
                    assert!(got.is_empty(), "{semi:?}, FT {ft}, {k}: {got:?}");
                    continue;
                };
                touching += 1;
                // The inscribed facets miss a contact shallower than their chord deviation.
                let got_depth = got.first().map_or(0.0, |c| c.penetration);
                assert!(got.len() <= 1, "{semi:?}, FT {ft}, {k}: {got:?}");
                let depth = (got_depth - want.penetration).abs();
                assert!(
                    depth <= deviation,
                    "{semi:?}, FT {ft}, {k}: {depth:e} > {deviation:e}"
                );
            }
            assert!(touching > 40, "{touching}");
        }
    }
}

#[test]
fn the_hand_over_to_the_facets_at_an_edge_is_continuous() {
    // The solid slid at a fixed height across the face towards the edge x = 1, through the
    // band where the plane answer hands over to the facets' (the module docs of
    // `solid_on_face`): consecutive contacts differ by at most a few times the slide step, and
    // every one is within the chord deviation of the exact engine's solid–box contact. A
    // switch without the blend moves the point by up to 2e-4 (0.2 % of the radius) in one step.
    let (ground, ground_pose) = ground();
    let step = 1e-5;
    for semi in [SPHERE, ELLIPSOID] {
        let length = solid(semi).characteristic_length().unwrap();
        for ft in [300.0028, 3000.0] {
            let deviation = FacetingTolerance::new(ft).unwrap().chord_deviation(length);
            let on_box = prepare(&engine(ft), solid(semi), ground.clone());
            let base = pose(semi, &mut Rng(0xed9f), 0.0, 0.3, 0.0625);
            let mut last: Option<Contact> = None;
            let (mut depth_step, mut point_step) = (0.0f64, 0.0f64);
            for k in 0..7_000 {
                let mut pose = base;
                pose.translation.vector.x = 0.93 + step * f64::from(k);
                let (got, _) = query_pair(on_box.as_ref(), pose, ground_pose);
                let label = format!("{semi:?}, FT {ft}, x = {}", pose.translation.vector.x);
                assert_eq!(got.len(), 1, "{label}: {got:?}");
                let c = got[0];
                if k % 10 == 0 {
                    let want = exact(semi, ground.clone(), &pose, &ground_pose);
                    assert_eq!(want.len(), 1, "{label}: {want:?}");
                    assert!(
                        (c.penetration - want[0].penetration).abs() <= deviation,
                        "{label}: {c:?} against {want:?}"
                    );
                }
                if let Some(l) = last {
                    depth_step = depth_step.max((c.penetration - l.penetration).abs());
                    point_step = point_step.max((c.point_i_w - l.point_i_w).norm());
                }
                last = Some(c);
            }
            assert!(
                depth_step <= 5.0 * step && point_step <= 5.0 * step,
                "{semi:?}, FT {ft}: depth step {depth_step:e}, point step {point_step:e}"
            );
        }
    }
}
