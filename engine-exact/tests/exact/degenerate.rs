//! Degenerate and extreme input: every branch documented in the pair modules, each with a
//! finite answer (no NaN, no panic) and the documented value.

use crate::common::{boxes_mesh, instance, one, query};
use contact_core::geometry::{Circle, Cuboid, Ellipsoid, Line, Plane};
use contact_core::{
    Geometry, GeometryEngine, Isometry3, QueryError, Side, UnitQuaternion, Vector3, WorkCounters,
};
use engine_exact::ExactEngine;
use std::f64::consts::PI;

fn sphere(r: f64) -> contact_core::GeometryInstance {
    instance(Geometry::sphere(r).unwrap())
}

fn plane() -> contact_core::GeometryInstance {
    instance(Geometry::Plane(Plane::unbounded()))
}

fn cube(h: f64) -> contact_core::GeometryInstance {
    instance(Geometry::Cuboid(Cuboid::centered(h, h, h).unwrap()))
}

fn at(x: f64, y: f64, z: f64) -> Isometry3 {
    Isometry3::translation(x, y, z)
}

#[test]
fn touching_is_not_a_contact_and_grazing_is_a_tiny_one() {
    let id = Isometry3::identity();
    assert!(query(&sphere(1.0), &plane(), &at(0.0, 0.0, 1.0), &id).is_empty());
    let c = one(&sphere(1.0), &plane(), &at(0.0, 0.0, 1.0 - 1e-12), &id);
    // δ = r − d, with d = 1 − 1e-12 rounded to f64 (an error of at most 1.2e-16).
    assert!((c.penetration - 1e-12).abs() < 2e-16, "{c:?}");
    assert!(query(&sphere(1.0), &sphere(2.0), &at(3.0, 0.0, 0.0), &id).is_empty());
    // Boxes face to face, edge to edge, corner to corner: zero volume, no contact.
    assert!(query(&cube(1.0), &cube(1.0), &at(2.0, 0.0, 0.0), &id).is_empty());
    assert!(query(&cube(1.0), &cube(1.0), &at(2.0, 2.0, 0.0), &id).is_empty());
    assert!(query(&cube(1.0), &cube(1.0), &at(2.0, 2.0, 2.0), &id).is_empty());
    assert!(query(&cube(1.0), &plane(), &at(0.0, 0.0, 1.0), &id).is_empty());
    // A cube on its edge, 1e-9 into the plane: a thin wedge, finite and normal +z.
    let edge_down = Isometry3::from_parts(
        nalgebra::Translation3::new(0.0, 0.0, 2f64.sqrt() - 1e-9),
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), PI / 4.0),
    );
    let c = one(&cube(1.0), &plane(), &edge_down, &id);
    assert!((c.normal_w - Vector3::z()).norm() < 1e-9);
    assert!(c.penetration > 0.0 && c.penetration < 2e-9, "{c:?}");
    // Stacked boxes overlapping by 1e-12 of their size.
    let c = one(&cube(1.0), &cube(1.0), &at(0.0, 0.0, 2.0 - 1e-12), &id);
    assert!((c.normal_w - Vector3::z()).norm() < 1e-12);
    assert!((c.penetration - 1e-12).abs() < 1e-15, "{c:?}");
    assert!((c.area - 4.0).abs() < 1e-12);
}

#[test]
fn full_containment_keeps_depth_growing() {
    let id = Isometry3::identity();
    // Sphere far below the plane: δ = r − d, area = π r².
    let c = one(&sphere(1.0), &plane(), &at(0.0, 0.0, -5.0), &id);
    assert_eq!(c.penetration, 6.0);
    assert!((c.area - PI).abs() < 1e-14);
    // A small sphere inside a big one: δ = r_a + r_b − D grows as the centres approach.
    let d1 = one(&sphere(0.5), &sphere(3.0), &at(1.0, 0.0, 0.0), &id).penetration;
    let d2 = one(&sphere(0.5), &sphere(3.0), &at(0.5, 0.0, 0.0), &id).penetration;
    assert!(d2 > d1 && (d1 - 2.5).abs() < 1e-15);
    // An ellipsoid wholly under the plane: the centroid is its centre.
    let e = instance(Geometry::Ellipsoid(Ellipsoid::new(1.0, 2.0, 0.5).unwrap()));
    let c = one(&e, &plane(), &at(0.3, 0.0, -4.0), &id);
    assert!((c.penetration - 4.5).abs() < 1e-14, "{c:?}");
    // A small box inside a big one: the normal is the big box's nearest face (+x here).
    let small = instance(Geometry::Cuboid(Cuboid::centered(0.1, 0.2, 0.3).unwrap()));
    let c = one(&small, &cube(2.0), &at(1.5, 0.0, 0.0), &id);
    assert_eq!(c.normal_w, Vector3::x());
    assert!((c.penetration - 0.6).abs() < 1e-14, "{c:?}");
    // The big box seen from the other side: the swapped contact.
    let s = one(&cube(2.0), &small, &id, &at(1.5, 0.0, 0.0));
    assert!((s.normal_w + Vector3::x()).norm() < 1e-14, "{s:?}");
    // A box sunk wholly below the plane: normal is the plane's.
    let c = one(&cube(1.0), &plane(), &at(0.0, 0.0, -10.0), &id);
    assert_eq!(c.normal_w, Vector3::z());
    assert!((c.penetration - 11.0).abs() < 1e-13);
}

#[test]
fn coincident_centres_and_coincident_boxes_use_the_documented_axis() {
    let id = Isometry3::identity();
    let turned = Isometry3::rotation(Vector3::new(0.0, 0.3, 0.0));
    // Two spheres: +z of J's frame.
    let c = one(&sphere(1.0), &sphere(2.0), &id, &turned);
    assert!((c.normal_w - turned.rotation * Vector3::z()).norm() < 1e-15);
    assert_eq!(c.penetration, 3.0);
    // Ball in cavity with coincident centres: contact only when the ball is bigger.
    assert!(query(&sphere(1.0), &sphere(2.0).flipped(), &id, &id).is_empty());
    let c = one(&sphere(2.0), &sphere(1.0).flipped(), &id, &id);
    assert_eq!(c.penetration, 1.0);
    // Circles and a point at a circle's centre: +x of J's frame.
    let circle = |r| instance(Geometry::Circle(Circle::new(r).unwrap()));
    let c = one(&circle(1.0), &circle(1.0), &id, &id);
    assert_eq!(c.normal_w, Vector3::x());
    let c = one(&instance(Geometry::Point), &circle(1.0), &id, &id);
    assert_eq!((c.normal_w, c.penetration), (Vector3::x(), 1.0));
    // Two identical coincident cubes: nothing is cut, the normal is J's nearest face.
    let c = one(&cube(1.0), &cube(1.0), &id, &id);
    assert!(
        c.is_well_formed() && (c.penetration - 2.0).abs() < 1e-15,
        "{c:?}"
    );
    // Crossed bars (a 'plus'): J's surface inside I sums to zero; finite answer.
    let bar_x = instance(Geometry::Cuboid(Cuboid::centered(3.0, 0.5, 0.5).unwrap()));
    let bar_y = instance(Geometry::Cuboid(Cuboid::centered(0.5, 3.0, 0.5).unwrap()));
    let c = one(&bar_x, &bar_y, &id, &id);
    assert!(c.is_well_formed(), "{c:?}");
}

#[test]
fn parallel_faces_and_bounded_edges() {
    let id = Isometry3::identity();
    // A box straddling the +x edge of a bounded plane: the prism's top and its side face
    // are both inside the box, so the normal tilts from +z towards +x.
    let bounded = instance(Geometry::Plane(
        Plane::bounded(-5.0, 0.0, -5.0, 5.0).unwrap(),
    ));
    let c = one(&cube(1.0), &bounded, &at(0.0, 0.0, 0.5), &id);
    assert!(
        c.normal_w.x > 0.1 && c.normal_w.z > 0.1 && c.normal_w.y.abs() < 1e-15,
        "{c:?}"
    );
    // Off the bounded plane altogether: no contact.
    assert!(query(&cube(1.0), &bounded, &at(3.0, 0.0, 0.5), &id).is_empty());
    // A flipped plane: the material is above; a box below it is free, above it sinks.
    let up = plane().flipped();
    assert!(query(&cube(1.0), &up, &at(0.0, 0.0, -1.5), &id).is_empty());
    let c = one(&cube(1.0), &up, &at(0.0, 0.0, 0.5), &id);
    assert_eq!(c.normal_w, -Vector3::z());
    assert!((c.penetration - 1.5).abs() < 1e-15);
    // 2-D: a point on a bounded line's end is inside, beyond it is not.
    let line = instance(Geometry::Line(Line::bounded(0.0, 1.0).unwrap()));
    assert_eq!(
        one(&instance(Geometry::Point), &line, &at(1.0, -0.5, 0.0), &id).penetration,
        0.5
    );
    assert!(query(&instance(Geometry::Point), &line, &at(1.5, -0.5, 0.0), &id).is_empty());
}

#[test]
fn a_cylinder_tilting_through_parallel_changes_continuously() {
    let cylinder = instance(Geometry::Cylinder(
        contact_core::geometry::Cylinder::new(0.5, 2.0).unwrap(),
    ));
    let id = Isometry3::identity();
    let on_side = |tilt: f64| {
        let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), PI / 2.0 + tilt);
        one(
            &cylinder,
            &plane(),
            &Isometry3::from_parts(nalgebra::Translation3::new(-1.0, 0.0, 0.4), q),
            &id,
        )
    };
    let exact = on_side(0.0);
    assert!((exact.penetration - 0.1).abs() < 1e-15, "{exact:?}");
    // The contact patch of a wheel: chord 2√(R² − d²) times the length.
    assert!(
        (exact.area - 2.0 * (0.25f64 - 0.16).sqrt() * 2.0).abs() < 1e-12,
        "{exact:?}"
    );
    for tilt in [1e-14, 1e-10, 1e-6] {
        let c = on_side(tilt);
        assert!(
            (c.penetration - exact.penetration).abs() < 4.0 * tilt + 1e-14,
            "{tilt}: {c:?}"
        );
        assert!(
            (c.area - exact.area).abs() < 1e-6 * exact.area + 10.0 * tilt,
            "{tilt}: {c:?}"
        );
    }
    // Wholly under the plane: finite, the shadow as area.
    let c = one(&cylinder, &plane(), &at(0.0, 0.0, -5.0), &id);
    assert!(
        (c.penetration - 5.0).abs() < 1e-14 && (c.area - PI * 0.25).abs() < 1e-14,
        "{c:?}"
    );
    // Touching on a cap or along a side line: no contact.
    assert!(query(&cylinder, &plane(), &id, &id).is_empty());
}

#[test]
fn huge_and_tiny_scenes_give_finite_scaled_answers() {
    let id = Isometry3::identity();
    let tilt = Isometry3::rotation(Vector3::new(0.2, -0.1, 0.3));
    let boxes = |s: f64| {
        one(
            &cube(s),
            &cube(s),
            &(at(0.5 * s, 0.25 * s, 1.5 * s) * tilt),
            &id,
        )
    };
    let reference = boxes(1.0);
    let reference_ball = one(&sphere(1.0), &plane(), &at(0.0, 0.0, 0.5), &id);
    for s in [1e-100, 1e100] {
        let c = one(&sphere(s), &plane(), &at(0.0, 0.0, 0.5 * s), &id);
        assert!((c.penetration / s - reference_ball.penetration).abs() < 1e-15);
        assert!((c.area / (s * s) - reference_ball.area).abs() < 1e-14);
        let c = boxes(s);
        assert!(c.is_well_formed(), "{c:?}");
        assert!(
            (c.penetration / s - reference.penetration).abs() < 1e-14,
            "{c:?}"
        );
        assert!((c.normal_w - reference.normal_w).norm() < 1e-14, "{c:?}");
        assert!((c.point_i_w.coords / s - reference.point_i_w.coords).norm() < 1e-14);
        assert!((c.area / (s * s) - reference.area).abs() < 1e-13, "{c:?}");
    }
    // Small shapes far from the origin: still finite.
    let far = at(1e12, -1e12, 1e12);
    let c = one(&sphere(1.0), &plane(), &(far * at(0.0, 0.0, 0.5)), &far);
    assert!(c.is_well_formed());
}

#[test]
fn bad_poses_and_leaving_the_plane_are_typed_errors() {
    let pair = ExactEngine.prepare(&[sphere(1.0)], &[plane()]).unwrap();
    let mut out = Vec::new();
    let mut work = WorkCounters::default();
    let bad = at(f64::NAN, 0.0, 0.0);
    let err = pair
        .query(&bad, &Isometry3::identity(), &mut out, &mut work)
        .unwrap_err();
    assert!(
        matches!(err, QueryError::NonFinitePose { side: Side::I, .. }),
        "{err}"
    );

    let circle = instance(Geometry::Circle(Circle::new(1.0).unwrap())).labeled("wheel");
    let line = instance(Geometry::Line(Line::unbounded())).labeled("road");
    let pair = ExactEngine.prepare(&[circle], &[line]).unwrap();
    let tilted = Isometry3::rotation(Vector3::new(1e-3, 0.0, 0.0));
    let err = pair
        .query(&tilted, &Isometry3::identity(), &mut out, &mut work)
        .unwrap_err();
    assert!(matches!(err, QueryError::OutOfPlane { .. }), "{err}");
    let message = err.to_string();
    assert!(
        message.contains("wheel") && message.contains("road"),
        "{message}"
    );
    let lifted = at(0.0, 0.0, 1e-3);
    assert!(
        pair.query(&lifted, &Isometry3::identity(), &mut out, &mut work)
            .is_err()
    );
    // A marker with its z axis reversed spans the same plane: accepted.
    let reversed = Isometry3::rotation(Vector3::new(PI, 0.0, 0.0)) * at(0.0, 0.5, 0.0);
    pair.query(&reversed, &Isometry3::identity(), &mut out, &mut work)
        .unwrap();
    assert_eq!(out.len(), 1);
    assert!((out[0].penetration - 1.5).abs() < 1e-15, "{:?}", out[0]);
}

#[test]
fn a_mesh_on_two_feet_gives_one_contact_per_foot() {
    let id = Isometry3::identity();
    let feet = [
        (
            contact_core::Point3::new(-2.0, 0.0, 0.0),
            Vector3::new(0.5, 0.4, 1.0),
        ),
        (
            contact_core::Point3::new(1.5, 0.5, 0.3),
            Vector3::new(0.3, 0.6, 1.3),
        ),
    ];
    let mesh = instance(Geometry::Mesh(std::sync::Arc::new(boxes_mesh(&feet))));
    // Tilt and sink the part so both feet cross the plane by different amounts.
    let pose = Isometry3::from_parts(
        nalgebra::Translation3::new(0.1, -0.2, 0.8),
        UnitQuaternion::from_euler_angles(0.05, -0.08, 0.3),
    );
    let found = query(&mesh, &plane(), &pose, &id);
    assert_eq!(found.len(), 2, "{found:?}");
    // Each foot alone, as an exact box, answers the same.
    for ((centre, half), got) in feet.iter().zip(&found) {
        let foot = instance(Geometry::Cuboid(
            Cuboid::centered(half.x, half.y, half.z).unwrap(),
        ))
        .at(Isometry3::translation(centre.x, centre.y, centre.z));
        let expected = one(&foot, &plane(), &pose, &id);
        crate::common::assert_close(got, &expected, 2.0, 4.0, 1e-12, "foot");
    }
    // Lifted clear, then resting exactly on the plane: no contact.
    assert!(query(&mesh, &plane(), &at(0.0, 0.0, 5.0), &id).is_empty());
    assert!(query(&mesh, &plane(), &at(0.0, 0.0, 1.0), &id).is_empty());
}

#[test]
fn an_arc_has_no_material_beyond_its_ends_and_a_middle_at_its_centre() {
    let id = Isometry3::identity();
    let arc = instance(Geometry::Arc(
        contact_core::geometry::Arc::new(1.0, PI / 2.0).unwrap(),
    ));
    let point = instance(Geometry::Point);
    // Inside the radius but at 135°, beyond the quarter arc: no contact.
    assert!(query(&point, &arc, &at(-0.3, 0.3, 0.0), &id).is_empty());
    // At the centre: the middle direction, 45°.
    let c = one(&point, &arc, &id, &id);
    let mid = Vector3::new(1.0, 1.0, 0.0).normalize();
    assert!(
        (c.normal_w - mid).norm() < 1e-15 && c.penetration == 1.0,
        "{c:?}"
    );
}

#[test]
fn a_sphere_centred_inside_a_mesh_is_pushed_out_through_the_nearest_face() {
    let id = Isometry3::identity();
    let h = Vector3::new(1.0, 2.0, 3.0);
    let mesh = instance(Geometry::Mesh(std::sync::Arc::new(boxes_mesh(&[(
        contact_core::Point3::origin(),
        h,
    )]))));
    let c = one(&sphere(0.5), &mesh, &at(0.7, 0.1, -0.2), &id);
    // Nearest face +x at 0.3: δ = r + 0.3, normal +x, the same as the exact box (the
    // closest point comes from barycentric weights on triangles of size ~3, the normal from
    // its difference with a point 0.3 away: a few ulps times 10).
    assert!(
        (c.penetration - 0.8).abs() < 1e-14 && (c.normal_w - Vector3::x()).norm() < 1e-14,
        "{c:?}"
    );
    let exact_box = instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap()));
    let b = one(&sphere(0.5), &exact_box, &at(0.7, 0.1, -0.2), &id);
    crate::common::assert_close(&c, &b, 3.0, 9.0, 1e-14, "mesh vs box");
    // Far away: no contact; the winding number is 0 there.
    assert!(query(&sphere(0.5), &mesh, &at(5.0, 0.0, 0.0), &id).is_empty());
}

mod boundaries {
    //! Boundary–boundary pairs (arcs, curves, lines): touching, coincident, open ends,
    //! containment.

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
                    1 => Geometry::Arc(
                        Arc::new(rng.uniform(0.2, 1.5), rng.uniform(0.1, TAU)).unwrap(),
                    ),
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
            if matches!(*i.geometry, Geometry::Line(_)) && matches!(*j.geometry, Geometry::Line(_))
            {
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
}
