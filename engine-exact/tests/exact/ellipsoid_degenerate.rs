//! The general ellipsoid pairs at their degenerate branches: coincident identical
//! ellipsoids, full containment either way, grazing contact (depth 1e-12 of the size), a
//! needle (axis ratio 1e3), and scenes at 1e-6 and 1e6.

use crate::common::{errors, instance, one, query};
use crate::ellipsoid_oracles::{box_exit, contact_from, ellipsoid_cap, ellipsoid_exit};
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid};
use contact_core::{Contact, Geometry, GeometryInstance, Isometry3, UnitQuaternion, Vector3};
use nalgebra::{Matrix3, Translation3};

fn ellipsoid(a: f64, b: f64, c: f64) -> GeometryInstance {
    instance(Geometry::Ellipsoid(Ellipsoid::new(a, b, c).unwrap()))
}

fn well_formed(c: &Contact) {
    assert!(c.penetration.is_finite() && c.penetration >= 0.0, "{c:?}");
    assert!((c.normal_w.norm() - 1.0).abs() < 1e-12, "{c:?}");
    assert!(c.area.is_finite() && c.area > 0.0, "{c:?}");
    assert!(
        c.point_i_w
            .coords
            .iter()
            .chain(c.point_j_w.coords.iter())
            .all(|v| v.is_finite())
    );
}

#[test]
fn coincident_identical_ellipsoids_touch_along_b_z() {
    let e = ellipsoid(1.0, 0.6, 0.3);
    let pose = Isometry3::from_parts(
        Translation3::new(0.3, -0.2, 0.1),
        UnitQuaternion::from_euler_angles(0.4, 0.1, -0.3),
    );
    let c = one(&e, &e, &pose, &pose);
    well_formed(&c);
    // The area vector vanishes: the normal is b's +z, the points on the z semi-axis.
    let z = pose.rotation * Vector3::z();
    assert!((c.normal_w - z).norm() < 1e-12, "{c:?}");
    assert!((c.penetration - 0.6).abs() < 1e-9, "{c:?}");
}

#[test]
fn an_ellipsoid_inside_another_or_inside_a_box_or_cylinder_has_a_finite_contact() {
    let small = ellipsoid(0.3, 0.2, 0.1);
    let inner = Isometry3::from_parts(
        Translation3::new(0.2, 0.1, 0.05),
        UnitQuaternion::from_euler_angles(0.2, 0.5, 0.1),
    );
    let big = ellipsoid(1.5, 1.0, 0.8);
    let c = one(&small, &big, &inner, &Isometry3::identity());
    well_formed(&c);
    // Normal along the line of centres (from b's centre to a's).
    let u = inner.translation.vector.normalize();
    assert!((c.normal_w - u).norm() < 1e-12, "{c:?}");
    let cube = instance(Geometry::Cuboid(Cuboid::centered(1.0, 0.9, 0.4).unwrap()));
    let c = one(&small, &cube, &inner, &Isometry3::identity());
    well_formed(&c);
    // The box's face nearest the centroid (at z = 0.05 + ..., nearest: +z at 0.4).
    assert!((c.normal_w - Vector3::z()).norm() < 1e-12, "{c:?}");
    let can = instance(Geometry::Cylinder(Cylinder::new(1.0, 0.5).unwrap()));
    let c = one(
        &small,
        &can,
        &Isometry3::translation(0.1, 0.0, 0.25),
        &Isometry3::identity(),
    );
    well_formed(&c);
    // A box and a cylinder inside a large ellipsoid.
    let huge = ellipsoid(5.0, 4.0, 3.0);
    let c = one(
        &huge,
        &cube,
        &Isometry3::translation(0.2, 0.1, 0.0),
        &Isometry3::identity(),
    );
    well_formed(&c);
    let c = one(
        &huge,
        &can,
        &Isometry3::translation(0.2, 0.1, 0.0),
        &Isometry3::identity(),
    );
    well_formed(&c);
}

#[test]
fn grazing_contacts_are_tiny_and_touching_is_none() {
    let e = ellipsoid(0.7, 0.4, 0.5);
    let q = UnitQuaternion::from_euler_angles(0.3, 0.6, -0.2);
    let l = q.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&Vector3::new(0.7, 0.4, 0.5));
    let reach = (l.transpose() * Vector3::z()).norm();
    let cube = instance(Geometry::Cuboid(Cuboid::centered(2.0, 2.0, 1.0).unwrap()));
    let can = instance(Geometry::Cylinder(Cylinder::new(2.0, 1.0).unwrap()));
    for (j, top) in [(&cube, 1.0), (&can, 1.0)] {
        let graze = Isometry3::from_parts(Translation3::new(0.1, 0.2, top + reach - 1e-12), q);
        let c = one(&e, j, &graze, &Isometry3::identity());
        well_formed(&c);
        assert!(c.penetration <= 2e-12, "{c:?}");
        assert!((c.normal_w - Vector3::z()).norm() < 1e-6, "{c:?}");
        let apart = Isometry3::from_parts(Translation3::new(0.1, 0.2, top + reach * 1.001), q);
        assert!(query(&e, j, &apart, &Isometry3::identity()).is_empty());
    }
    // Two ellipsoids of one shape (the affine image of two spheres) at 1e-12 overlap.
    let (a, b) = (ellipsoid(0.5, 0.25, 0.4), ellipsoid(1.0, 0.5, 0.8));
    let graze = Isometry3::translation(1.5 - 1e-12, 0.0, 0.0);
    let c = one(&a, &b, &graze, &Isometry3::identity());
    well_formed(&c);
    assert!(c.penetration <= 2e-12, "{c:?}");
    let apart = Isometry3::translation(1.5 + 1e-9, 0.0, 0.0);
    assert!(query(&a, &b, &apart, &Isometry3::identity()).is_empty());
}

/// A needle (semi-axes 1e-3, 1e-3, 1) tilted through a box's top face, at scale `s`,
/// against the affine spherical cap.
fn needle_through_a_face(s: f64) {
    let semi = Vector3::new(1e-3, 1e-3, 1.0) * s;
    let q = UnitQuaternion::from_euler_angles(0.4, -0.3, 0.2);
    let l = q.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
    let half = Vector3::new(2.0, 2.0, 1.0) * s;
    let c = Vector3::new(0.1, -0.2, 1.0 + 0.6) * s;
    let moments = ellipsoid_cap(&c, &l, &Vector3::z(), half.z);
    let expected = contact_from(
        &moments,
        |g, d| ellipsoid_exit(&c, &l, g, d),
        |g, d| box_exit(&half, g, d),
    );
    let got = one(
        &instance(Geometry::Ellipsoid(
            Ellipsoid::new(semi.x, semi.y, semi.z).unwrap(),
        )),
        &instance(Geometry::Cuboid(
            Cuboid::centered(half.x, half.y, half.z).unwrap(),
        )),
        &Isometry3::from_parts(Translation3::from(c), q),
        &Isometry3::identity(),
    );
    let e = errors(&got, &expected, s);
    assert!(
        e.iter().all(|&x| x < 1e-9),
        "scale {s:e}: {e:?}\n{got:?}\n{expected:?}"
    );
}

#[test]
fn a_needle_through_a_face_matches_the_cap_at_every_scale() {
    for s in [1.0, 1e-6, 1e6] {
        needle_through_a_face(s);
    }
}
