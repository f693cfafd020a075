//! Mesh against mesh, regions by the pieces of each triangle: two regions that cross the same
//! large triangle of the other surface are two contacts, and the two loops of one annular
//! region are one; a ring pressed through the roof of a box with a hole crosses the roof's two
//! large faces twice, two regions 1.5 apart. The oracle is the exact engine (its box–mesh,
//! box–torus and torus–mesh pairs, SPEC §4 written apart from this engine).

use crate::common::{Rng, engine, prepare, query_pair, u_shape};
use contact_core::geometry::{Cuboid, Torus, TriangleMesh};
use contact_core::nalgebra::Unit;
use contact_core::{
    Contact, Geometry, GeometryEngine, GeometryInstance, Isometry3, Point3, UnitQuaternion, Vector3,
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

/// A box `[x0, x1]×[y0, y1]×[z0, z1]` with a hole `[hx0, hx1]×[hy0, hy1]` through it along z:
/// every side face and every wall of the hole two triangles, the top and bottom rings eight.
fn box_with_a_hole(outer: [f64; 4], hole: [f64; 4], z: [f64; 2]) -> Geometry {
    let ring = |r: [f64; 4]| [[r[0], r[2]], [r[1], r[2]], [r[1], r[3]], [r[0], r[3]]];
    let mut vertices = Vec::new();
    // Outer bottom 0..4, outer top 4..8, hole bottom 8..12, hole top 12..16.
    for square in [ring(outer), ring(hole)] {
        for zz in z {
            vertices.extend(square.iter().map(|p| Point3::new(p[0], p[1], zz)));
        }
    }
    let mut triangles = Vec::new();
    let mut quad = |q: [u32; 4]| {
        triangles.push([q[0], q[1], q[2]]);
        triangles.push([q[0], q[2], q[3]]);
    };
    for k in 0..4 {
        let k1 = (k + 1) % 4;
        quad([4 + k, 4 + k1, 12 + k1, 12 + k]);
        quad([k1, k, 8 + k, 8 + k1]);
        quad([k, k1, 4 + k1, 4 + k]);
        quad([8 + k1, 8 + k, 12 + k, 12 + k1]);
    }
    Geometry::Mesh(std::sync::Arc::new(
        TriangleMesh::new(vertices, triangles).unwrap(),
    ))
}

#[test]
fn a_ring_through_the_roof_of_a_hole_is_two_contacts() {
    // The roof: the box's side y ∈ [0.9, 1] over a hole y ∈ [−0.5, 0.9], its outer face y = 1
    // two triangles. A ring (R = 1, r = 0.1) lying in the x–y plane, its centre 0.66 beyond
    // that face, dips through the roof into the hole: it crosses the roof at x ≈ ±0.75, two
    // regions on the same two faces. Each against the exact torus–mesh contact: the normal
    // (±y, from the roof's flat faces) to round-off, the depth and points within the faceting
    // deviation δ = L/FT of the ring.
    let (major, minor) = (1.0, 0.1);
    let torus = Geometry::Torus(Torus::new(major, minor).unwrap());
    let holed = box_with_a_hole([-2.5, 2.5, -1.0, 1.0], [-1.5, 1.5, -0.5, 0.9], [-0.5, 0.5]);
    let ft = 300.0028;
    let pair = prepare(&engine(ft), torus.clone(), holed.clone());
    let reach = major + minor;
    let deviation = (8.0 * reach * reach + 4.0 * minor * minor).sqrt() / ft;
    let mut rng = Rng(0x4013);
    for k in 0..16 {
        let pose = Isometry3::from_parts(
            Vector3::new(
                rng.range(-0.1, 0.1),
                1.66 + rng.range(-0.03, 0.03),
                rng.range(-0.1, 0.1),
            )
            .into(),
            UnitQuaternion::from_scaled_axis(rng.unit_vector() * rng.range(0.0, 0.05)),
        );
        let got = by_x(query_pair(pair.as_ref(), pose, Isometry3::identity()).0);
        let want = by_x(exact(&torus, &holed, &pose, &Isometry3::identity()));
        assert_eq!(want.len(), 2, "pose {k}: the oracle sees both crossings");
        assert_eq!(got.len(), 2, "pose {k}: {got:?}");
        assert!((want[1].point_i_w - want[0].point_i_w).norm() > 1.2);
        for (g, w) in got.iter().zip(&want) {
            let errors = [
                (g.penetration - w.penetration).abs(),
                (g.point_i_w - w.point_i_w).norm(),
                (g.point_j_w - w.point_j_w).norm(),
            ];
            assert!(
                (g.normal_w - w.normal_w).norm() <= 1e-9 && errors.iter().all(|e| *e <= deviation),
                "pose {k}: errors {errors:?} (δ = {deviation})\n got {g:?}\nwant {w:?}"
            );
        }
    }
}
