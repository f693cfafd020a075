//! Mesh against mesh, regions by the pieces of each triangle: two regions that cross the same
//! large triangle of the other surface are two contacts, and the two loops of one annular
//! region are one. The oracle is the exact engine (its box–mesh and box–torus pairs, SPEC §4
//! written apart from this engine).

use crate::common::{Rng, engine, prepare, query_pair, u_shape};
use contact_core::geometry::{Cuboid, Torus};
use contact_core::nalgebra::Unit;
use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, UnitQuaternion, Vector3,
};

/// A 2 × 2 × 0.2 box whose top face is the square |x|, |y| ≤ 1 of the plane z = 0: two
/// triangles, split along one of the diagonals.
fn ground() -> (Geometry, Isometry3) {
    let cuboid = Cuboid::from_corner(2.0, 2.0, 0.2).unwrap();
    (
        Geometry::Cuboid(cuboid),
        Isometry3::translation(-1.0, -1.0, -0.2),
    )
}

fn exact(i: &Geometry, j: &Geometry, pose_i: &Isometry3, pose_j: &Isometry3) -> Vec<Contact> {
    let pair = engine_exact::ExactEngine
        .prepare(
            &[GeometryInstance::new(i.clone())],
            &[GeometryInstance::new(j.clone())],
        )
        .unwrap();
    query_pair(pair.as_ref(), *pose_i, *pose_j).0
}

fn by_x(mut contacts: Vec<Contact>) -> Vec<Contact> {
    contacts.sort_by(|a, b| a.point_i_w.x.total_cmp(&b.point_i_w.x));
    contacts
}

#[test]
fn two_legs_on_one_face_triangle_are_two_contacts() {
    // The U's legs pressed into the box's top face, the whole footprint (within 0.26 of its
    // centre) kept at (0, −0.6), 0.42 from both diagonals: both legs cross the same triangle
    // whichever diagonal splits the face. Flat faces on both sides: the faceted answer is the
    // exact one to round-off.
    let body = u_shape();
    let (box_geometry, box_pose) = ground();
    let pair = prepare(&engine(300.0028), body.clone(), box_geometry.clone());
    let centre = Vector3::new(0.25, 0.05, 0.0);
    let mut rng = Rng(0x0E5C);
    for k in 0..24 {
        let axis = Unit::new_normalize(Vector3::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            0.0,
        ));
        let tilt = UnitQuaternion::from_axis_angle(&axis, rng.range(0.0, 0.01));
        let yaw = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.range(-3.2, 3.2));
        let depth = rng.range(0.006, 0.03);
        let rotation = tilt * yaw;
        let shift = Vector3::new(0.0, -0.6, -depth) - rotation * centre;
        let pose = Isometry3::from_parts(shift.into(), rotation);
        let got = by_x(query_pair(pair.as_ref(), pose, box_pose).0);
        let want = by_x(exact(&body, &box_geometry, &pose, &box_pose));
        assert_eq!(want.len(), 2, "pose {k}: the oracle sees both legs");
        assert_eq!(got.len(), 2, "pose {k}: {got:?}");
        for (g, w) in got.iter().zip(&want) {
            let errors = [
                (g.penetration - w.penetration).abs(),
                (g.normal_w - w.normal_w).norm(),
                (g.point_i_w - w.point_i_w).norm(),
                (g.point_j_w - w.point_j_w).norm(),
                (g.area - w.area).abs(),
            ];
            assert!(
                errors.iter().all(|e| *e <= 1e-9),
                "pose {k}: errors {errors:?}\n got {g:?}\nwant {w:?}"
            );
        }
    }
}

#[test]
fn a_ring_pressed_into_one_face_triangle_is_one_contact() {
    // A torus lying flat, pressed into the box's top face: its region is an annulus, and both
    // of its loops (the outer and the inner circle) cross the same face triangles. One contact,
    // as the exact engine finds, with its normal and its area: the annulus `2πR·w`, its width
    // `w(d) = 2√(2 r d)` at depth `d`, moves by `2πR·(w(d + δ) − w(d))` when the tube's facets
    // lie within `δ` of it. (The depth is not compared: the line through an annulus' centroid
    // misses it, and each engine answers that case its own way.)
    let (major, minor) = (0.3, 0.08);
    let torus = Geometry::Torus(Torus::new(major, minor).unwrap());
    let (box_geometry, box_pose) = ground();
    let ft = 300.0028;
    let pair = prepare(&engine(ft), torus.clone(), box_geometry.clone());
    let deviation = (0.76f64.powi(2) * 2.0 + 0.16f64.powi(2)).sqrt() / ft;
    let width = |d: f64| 2.0 * (2.0 * minor * d).sqrt();
    let mut rng = Rng(0x7020);
    for k in 0..12 {
        let axis = Unit::new_normalize(Vector3::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            0.0,
        ));
        let tilt = UnitQuaternion::from_axis_angle(&axis, rng.range(0.0, 0.005));
        let yaw = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.range(-3.2, 3.2));
        let depth = rng.range(0.01, 0.03);
        let pose = Isometry3::from_parts(
            Vector3::new(rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), minor - depth).into(),
            tilt * yaw,
        );
        let got = query_pair(pair.as_ref(), pose, box_pose).0;
        let want = exact(&torus, &box_geometry, &pose, &box_pose);
        assert_eq!(want.len(), 1, "pose {k}: {want:?}");
        assert_eq!(got.len(), 1, "pose {k}: {got:?}");
        let area_bound =
            2.0 * std::f64::consts::PI * major * (width(depth + deviation) - width(depth));
        assert!(
            (got[0].area - want[0].area).abs() <= area_bound,
            "pose {k}: area {} against {} (bound {area_bound})",
            got[0].area,
            want[0].area
        );
        assert!(
            (got[0].normal_w - want[0].normal_w).norm() <= 1e-9,
            "pose {k}: {got:?} against {want:?}"
        );
    }
}
