//! Degenerate branches of the sliced pairs (cylinder–cylinder, cylinder–box, cylinder–bounded
//! plane): identical coincident cylinders, one solid inside the other, grazing contact,
//! exactly perpendicular and parallel axes, extreme scales, and the refused flips.

use crate::common::{instance, one, query};
use crate::sliced_oracles as oracles;
use contact_core::geometry::{Cuboid, Cylinder, Plane};
use contact_core::{Contact, Geometry, GeometryEngine, Isometry3, UnitQuaternion, Vector3};
use engine_exact::ExactEngine;

fn cylinder(r: f64, l: f64) -> Geometry {
    Geometry::Cylinder(Cylinder::new(r, l).unwrap())
}

fn finite(c: &Contact) -> bool {
    c.penetration.is_finite()
        && c.area.is_finite()
        && c.normal_w.iter().all(|x| x.is_finite())
        && c.point_i_w.coords.iter().all(|x| x.is_finite())
        && c.point_j_w.coords.iter().all(|x| x.is_finite())
}

#[test]
fn identical_coincident_cylinders_take_the_nearest_face_normal() {
    let g = instance(cylinder(0.5, 2.0));
    let c = one(&g, &g, &Isometry3::identity(), &Isometry3::identity());
    assert!(finite(&c), "{c:?}");
    // The centroid is 0.5 from the side and 1 from each cap: the side is nearest; its area
    // a quarter of the whole surface.
    assert!(c.normal_w.z.abs() < 1e-12, "{c:?}");
    let surface = 2.0 * std::f64::consts::PI * 0.5 * (0.5 + 2.0);
    assert!((c.area - 0.25 * surface).abs() < 1e-9 * surface, "{c:?}");
}

#[test]
fn a_cylinder_inside_a_box_is_pushed_out_through_the_nearest_face() {
    let cyl = instance(cylinder(0.2, 0.5));
    let cube = instance(Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 1.0).unwrap()));
    // The cylinder's centroid at x = 0.7: the +x face is nearest.
    let c = one(
        &cyl,
        &cube,
        &Isometry3::translation(0.7, 0.0, -0.25),
        &Isometry3::identity(),
    );
    assert!(finite(&c), "{c:?}");
    assert!((c.normal_w - Vector3::x()).norm() < 1e-12, "{c:?}");
    assert!((c.penetration - 0.5).abs() < 1e-9, "{c:?}");
}

#[test]
fn a_box_inside_a_cylinder_gives_the_opposite_of_the_cylinders_nearest_face() {
    let cyl = instance(cylinder(1.0, 3.0));
    let cube = instance(Geometry::Cuboid(Cuboid::centered(0.1, 0.1, 0.1).unwrap()));
    // Box centre 0.3 above the bottom cap, well inside the side: the bottom is nearest.
    let c = one(
        &cyl,
        &cube,
        &Isometry3::identity(),
        &Isometry3::translation(0.0, 0.2, 0.3),
    );
    assert!(finite(&c), "{c:?}");
    assert!((c.normal_w - Vector3::z()).norm() < 1e-12, "{c:?}");
}

#[test]
fn grazing_contacts_are_finite_and_touching_is_none() {
    let (r, l) = (0.5, 2.0);
    let a = instance(cylinder(r, l));
    // Parallel axes, 1e-12 of the size apart from touching: a thin lens.
    let b = instance(cylinder(r, l));
    let d = 2.0 * r - 1e-12;
    let c = one(
        &a,
        &b,
        &Isometry3::identity(),
        &Isometry3::translation(d, 0.0, 0.5),
    );
    assert!(finite(&c) && c.penetration < 1e-11, "{c:?}");
    assert!((c.normal_w + Vector3::x()).norm() < 1e-6, "{c:?}");
    // Crossed at right angles, axes 1e-12 short of r_a + r_b apart.
    let crossed = Isometry3::from_parts(
        nalgebra::Translation3::new(-1.0, 2.0 * r - 1e-12, 1.0),
        UnitQuaternion::from_axis_angle(&Vector3::y_axis(), std::f64::consts::FRAC_PI_2),
    );
    let found = query(&a, &b, &Isometry3::identity(), &crossed);
    assert!(found.iter().all(finite), "{found:?}");
    // Exactly touching: no volume, no contact.
    let touching = query(
        &a,
        &b,
        &Isometry3::identity(),
        &Isometry3::translation(2.0 * r, 0.0, 0.0),
    );
    assert!(touching.is_empty(), "{touching:?}");
    // A box face exactly on the cylinder's side: no contact; 1e-12 into it: a finite one.
    let cube = instance(Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 1.0).unwrap()));
    for (gap, contacts) in [(0.0, 0), (-1e-12, 1)] {
        let found = query(
            &a,
            &cube,
            &Isometry3::identity(),
            &Isometry3::translation(r + 1.0 + gap, 0.0, 1.0),
        );
        assert_eq!(found.len(), contacts, "{gap}: {found:?}");
        assert!(found.iter().all(finite), "{found:?}");
    }
}

/// Two equal cylinders crossed at exactly 90° with intersecting axes, long enough that the
/// caps stay out: Steinmetz's bicylinder, `V = 16r³/3`, symmetric, so the area vector
/// vanishes and the normal falls back to a nearest face; every answer finite.
#[test]
fn perpendicular_axes_through_one_point() {
    let (r, l) = (0.5, 4.0);
    let a = instance(cylinder(r, l));
    let pose_a = Isometry3::translation(0.0, 0.0, -0.5 * l);
    let pose_b = Isometry3::from_parts(
        nalgebra::Translation3::new(-0.5 * l, 0.0, 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::y_axis(), std::f64::consts::FRAC_PI_2),
    );
    let c = one(&a, &a, &pose_a, &pose_b);
    assert!(finite(&c), "{c:?}");
    // Offset b sideways: a proper contact along the offset.
    let shifted = Isometry3::translation(0.0, 0.6, 0.0) * pose_b;
    let c = one(&a, &a, &pose_a, &shifted);
    assert!(finite(&c), "{c:?}");
    assert!((c.normal_w + Vector3::y()).norm() < 1e-9, "{c:?}");
}

#[test]
fn huge_and_tiny_scales_match_the_parallel_closed_form() {
    for s in [1e-6, 1e6] {
        let (ra, la, rb, lb, d, zb) = (0.7, 2.0, 0.4, 1.5, 0.9, 0.8);
        let expected = oracles::parallel_cylinders(ra, la, rb, zb, lb, d);
        let c = one(
            &instance(cylinder(ra * s, la * s)),
            &instance(cylinder(rb * s, lb * s)),
            &Isometry3::identity(),
            &Isometry3::translation(d * s, 0.0, zb * s),
        );
        assert!(
            (c.penetration - expected.depth * s).abs() <= 1e-12 * s,
            "{s}: {c:?} vs {expected:?}"
        );
        assert!((c.normal_w - expected.normal).norm() <= 1e-12, "{s}: {c:?}");
        assert!(
            (c.point_i_w.coords - expected.point_i.coords * s).norm() <= 1e-12 * s,
            "{s}: {c:?}"
        );
    }
}

#[test]
fn a_cylinder_over_the_middle_of_a_bounded_plane_matches_the_unbounded_plane() {
    let a = instance(cylinder(0.4, 1.0));
    let pose = Isometry3::from_parts(
        nalgebra::Translation3::new(0.1, -0.2, -0.1),
        UnitQuaternion::from_euler_angles(0.4, 0.3, 0.2),
    );
    let bounded = instance(Geometry::Plane(
        Plane::bounded(-5.0, 5.0, -5.0, 5.0).unwrap(),
    ));
    let unbounded = instance(Geometry::Plane(Plane::unbounded()));
    let x = one(&a, &bounded, &pose, &Isometry3::identity());
    let y = one(&a, &unbounded, &pose, &Isometry3::identity());
    crate::common::assert_close(&x, &y, 1.0, 1.0, 1e-10, "bounded vs unbounded plane");
}

#[test]
fn flipped_cylinders_boxes_and_cylinders_on_flipped_bounded_planes() {
    let cyl = instance(cylinder(0.5, 1.0));
    let cube = instance(Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 1.0).unwrap()));
    let plane = instance(Geometry::Plane(
        Plane::bounded(-1.0, 1.0, -1.0, 1.0).unwrap(),
    ));
    for (i, j) in [
        (cyl.clone().flipped(), cyl.clone()),
        (cyl.clone(), cyl.clone().flipped()),
        (cyl.clone().flipped(), cube.clone()),
        (cyl.clone().flipped(), plane.clone()),
    ] {
        let err = ExactEngine.prepare(&[i], &[j]).map(|_| ()).unwrap_err();
        assert!(err.to_string().contains("flipped"), "{err}");
    }
    // A flipped box is a cavity a cylinder may sit in (its answers: mesh_revolved's tests).
    assert!(
        ExactEngine
            .prepare(std::slice::from_ref(&cyl), &[cube.clone().flipped()])
            .is_ok()
    );
    // A flipped bounded plane is built: its material lies above.
    let found = query(
        &cyl,
        &plane.flipped(),
        &Isometry3::translation(0.0, 0.0, -0.8),
        &Isometry3::identity(),
    );
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(
        (found[0].normal_w + Vector3::z()).norm() < 1e-12,
        "{found:?}"
    );
}
/// Axes parallel to the round-off of composed poses (both cylinders moved by the same seeded
/// rigid motion) take the parallel closed form, with no quadrature, and match the oracle
/// moved by that motion; a tilt of 1e-9 rad is sliced.
#[test]
fn axes_parallel_to_round_off_take_the_closed_form() {
    let (ra, la, rb, lb, d, zb) = (0.7, 2.0, 0.4, 1.5, 0.9, 0.8);
    let expected = oracles::parallel_cylinders(ra, la, rb, zb, lb, d);
    let pair = ExactEngine
        .prepare(&[instance(cylinder(ra, la))], &[instance(cylinder(rb, lb))])
        .unwrap();
    let mut rng = crate::common::Rng::new(17);
    let iterations = |pose_i: &Isometry3, pose_j: &Isometry3| {
        let (mut out, mut work) = (Vec::new(), contact_core::WorkCounters::default());
        pair.query(pose_i, pose_j, &mut out, &mut work).unwrap();
        (out, work.iterations)
    };
    for _ in 0..20 {
        let world = rng.pose(3.0);
        let pose_j = world * Isometry3::translation(d, 0.0, zb);
        let (out, count) = iterations(&world, &pose_j);
        assert_eq!((out.len(), count), (1, 0), "{out:?}");
        let c = out[0];
        assert!((c.penetration - expected.depth).abs() <= 1e-12, "{c:?}");
        assert!((c.normal_w - world.rotation * expected.normal).norm() <= 1e-12);
        assert!((c.point_i_w - world * expected.point_i).norm() <= 1e-12);
        let tilted = pose_j * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 1e-9);
        assert!(iterations(&world, &tilted).1 > 0);
    }
}

/// A box with an axis exactly parallel to the cylinder's takes the closed form, a box tilted
/// 1e-12 rad from it the slicing: the two agree to the slicing's accuracy, across poses where
/// the section has corners inside the disc, the disc's centre outside it, and caps within the
/// box's range or beyond it. (Where a cap and an end face coincide the answer jumps with the
/// tilt's direction; the closed form takes the mean of the two sides there.)
#[test]
fn an_aligned_box_meets_the_nearly_aligned_slicing() {
    let cyl = instance(cylinder(0.5, 2.0));
    let cases = [
        (Vector3::new(0.6, 0.4, 1.0), [0.4, 0.3, 1.5], 0.3),
        (Vector3::new(1.2, 0.0, 0.5), [1.0, 1.0, 1.0], 0.0),
        (Vector3::new(0.1, -0.2, 2.2), [0.3, 0.2, 0.4], 1.1),
        (Vector3::new(-0.3, 0.5, 1.0), [0.5, 0.3, 0.9], -0.6),
    ];
    for (centre, half, spin) in cases {
        let cube = instance(Geometry::Cuboid(
            Cuboid::centered(half[0], half[1], half[2]).unwrap(),
        ));
        let at = |tilt: f64| {
            let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt)
                * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), spin);
            Isometry3::from_parts(centre.into(), q)
        };
        let exact = one(&cyl, &cube, &Isometry3::identity(), &at(0.0));
        let sliced = one(&cyl, &cube, &Isometry3::identity(), &at(1e-12));
        assert!(finite(&exact), "{exact:?}");
        assert!(
            (exact.normal_w - sliced.normal_w).norm() <= 1e-9,
            "{exact:?} {sliced:?}"
        );
        assert!(
            (exact.penetration - sliced.penetration).abs() <= 1e-9,
            "{exact:?} {sliced:?}"
        );
        assert!(
            (exact.point_i_w - sliced.point_i_w).norm() <= 1e-9,
            "{exact:?} {sliced:?}"
        );
        assert!(
            (exact.area - sliced.area).abs() <= 1e-9,
            "{exact:?} {sliced:?}"
        );
    }
}
