//! The box against a frustum or torus, and frustums, tori and general ellipsoids against a
//! bounded plane: the invariants of [`crate::properties`] on random scenes, the torus' separate
//! regions, and the degenerate branches (containment, touching, grazing, coincident faces).

use crate::common::{Rng, assert_close, instance, one, query};
use crate::properties::{
    Maker, Scene, check_motion, check_scale, check_swap, general_ellipsoid, random_axes,
    random_box, scaled_pose,
};
use contact_core::geometry::{Cuboid, Frustum, Plane, Torus};
use contact_core::{Geometry, GeometryInstance, Isometry3, Point3, Vector3};
use nalgebra::Translation3;

fn frustum(r0: f64, r1: f64, len: f64) -> GeometryInstance {
    instance(Geometry::Frustum(Frustum::new(r0, r1, len).unwrap()))
}

fn torus(big: f64, small: f64) -> GeometryInstance {
    instance(Geometry::Torus(Torus::new(big, small).unwrap()))
}

fn cuboid(hx: f64, hy: f64, hz: f64) -> GeometryInstance {
    instance(Geometry::Cuboid(Cuboid::centered(hx, hy, hz).unwrap()))
}

/// A random frustum (a cone a third of the time) or torus at scale `s`, its size, and the
/// offset of its middle from its frame origin.
fn random_revolved(rng: &mut Rng, s: f64) -> (GeometryInstance, f64, Vector3) {
    if rng.uniform(0.0, 1.0) < 0.5 {
        let r0 = if rng.uniform(0.0, 1.0) < 0.33 {
            0.0
        } else {
            rng.uniform(0.3, 1.5)
        };
        let (r1, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 2.0));
        let size = r0.max(r1).max(len);
        (
            frustum(r0 * s, r1 * s, len * s),
            size,
            Vector3::new(0.0, 0.0, 0.5 * len),
        )
    } else {
        let big = rng.uniform(0.8, 2.0);
        let small = rng.uniform(0.1, 0.9) * big;
        (torus(big * s, small * s), big + small, Vector3::zeros())
    }
}

fn box_revolved(rng: &mut Rng, s: f64) -> Scene {
    let (b, box_size) = random_box(rng, s);
    let (solid, size, middle) = random_revolved(rng, s);
    let pose_j = rng.pose(3.0);
    let frame = pose_j * Isometry3::translation(middle.x, middle.y, middle.z);
    let offset = rng.unit_vector() * rng.uniform(0.0, 0.8 * (size + box_size / s));
    // The box's frame is its corner: centre it near the solid's middle.
    let turn = rng.rotation();
    let centre = turn * b.center().coords / s;
    let pose_i = frame * Isometry3::from_parts(Translation3::from(offset - centre), turn);
    Scene {
        i: instance(Geometry::Cuboid(b)),
        j: solid,
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: size * s + box_size,
    }
}

fn bounded_plane(rng: &mut Rng, s: f64) -> Plane {
    // One or two finite bounds crossing the solid's footprint.
    if rng.uniform(0.0, 1.0) < 0.5 {
        Plane::bounded(-0.3 * s, f64::INFINITY, -2.0 * s, 0.4 * s).unwrap()
    } else {
        Plane::bounded(-3.0 * s, 0.5 * s, -2.0 * s, 4.0 * s).unwrap()
    }
}

fn revolved_bounded_plane(rng: &mut Rng, s: f64) -> Scene {
    let (solid, size, middle) = random_revolved(rng, s);
    let plane_pose = rng.pose(3.0);
    let q = rng.rotation();
    let centre = q * middle;
    let pose_i = plane_pose
        * Isometry3::from_parts(
            Translation3::new(
                rng.uniform(-0.5, 0.5) - centre.x,
                0.1 - centre.y,
                rng.uniform(-0.8, 0.5) * size - centre.z,
            ),
            q,
        );
    Scene {
        i: solid,
        j: instance(Geometry::Plane(bounded_plane(rng, s))),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length: size * s,
    }
}

fn ellipsoid_bounded_plane(rng: &mut Rng, s: f64) -> Scene {
    let a = random_axes(rng);
    let plane_pose = rng.pose(3.0);
    let pose_i = plane_pose
        * Isometry3::from_parts(
            Translation3::new(
                rng.uniform(-0.5, 0.5),
                0.1,
                rng.uniform(-0.8, 0.8) * a.max(),
            ),
            rng.rotation(),
        );
    Scene {
        i: general_ellipsoid(&a, s),
        j: instance(Geometry::Plane(bounded_plane(rng, s))),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&plane_pose, s),
        length: a.max() * s,
    }
}

/// "sliced " names take the quadrature pairs' 1e-9 tolerance in [`crate::properties`].
const MAKERS: [(&str, Maker); 3] = [
    ("sliced box–frustum/torus", box_revolved),
    ("sliced frustum/torus–bounded plane", revolved_bounded_plane),
    ("sliced ellipsoid–bounded plane", ellipsoid_bounded_plane),
];

#[test]
fn exchanging_i_and_j_gives_the_swapped_contact() {
    check_swap(&MAKERS, 21);
}

#[test]
fn a_rigid_motion_of_both_bodies_moves_the_contact() {
    check_motion(&MAKERS, 22);
}

#[test]
fn scaling_the_scene_scales_depth_and_points() {
    check_scale(&MAKERS, 23);
}

/// A slab `x0 ≤ x ≤ x1` inside the hole's width crosses a flat torus' ring twice: two
/// contacts, mirror images in `y`, each the same as the one of the slab's half `y ≥ 0` (whose
/// face `y = 0` lies in the hole, so it meets the same region).
#[test]
fn a_slab_through_the_ring_makes_two_regions() {
    let (big, small) = (2.0, 0.6);
    let ring = torus(big, small);
    let (x0, x1) = (-0.9, 0.3);
    let slab = cuboid(0.5 * (x1 - x0), 4.0, 2.0);
    let pose_slab = Isometry3::translation(0.5 * (x0 + x1), 0.0, 0.2);
    let both = query(&slab, &ring, &pose_slab, &Isometry3::identity());
    assert_eq!(both.len(), 2, "{both:?}");
    let (up, down) = if both[0].point_i_w.y > 0.0 {
        (both[0], both[1])
    } else {
        (both[1], both[0])
    };
    let mirror = |p: &Point3| Point3::new(p.x, -p.y, p.z);
    assert!(
        (mirror(&down.point_i_w) - up.point_i_w).norm() < 1e-12,
        "{up:?} {down:?}"
    );
    assert!((mirror(&down.point_j_w) - up.point_j_w).norm() < 1e-12);
    assert!((down.penetration - up.penetration).abs() < 1e-12);
    assert!((down.area - up.area).abs() < 1e-12);
    // The slab's face x1 lies deeper in the tube than x0: the net push is along ∓x.
    assert!(up.normal_w.x.abs() > 0.99, "{up:?}");
    let half = cuboid(0.5 * (x1 - x0), 2.0, 2.0);
    let pose_half = Isometry3::translation(0.5 * (x0 + x1), 2.0, 0.2);
    let alone = one(&half, &ring, &pose_half, &Isometry3::identity());
    assert!(
        (alone.penetration - up.penetration).abs() < 1e-12 * big,
        "{alone:?} {up:?}"
    );
    assert!((alone.normal_w - up.normal_w).norm() < 1e-12);
    assert!((alone.point_i_w - up.point_i_w).norm() < 1e-12 * big);
    assert!((alone.point_j_w - up.point_j_w).norm() < 1e-12 * big);
    assert!((alone.area - up.area).abs() < 1e-12 * big * big);
    // Turned about the torus' axis by any angle, the same two contacts turned.
    for angle in [0.3, 1.9, 4.0] {
        let turn = Isometry3::rotation(Vector3::z() * angle);
        let turned = query(&slab, &ring, &(turn * pose_slab), &turn);
        assert_eq!(turned.len(), 2, "{angle}: {turned:?}");
    }
}

/// A frustum inside a box, near its `+x` face: one contact pushing the frustum out through
/// that face, area a quarter of the frustum's surface.
#[test]
fn a_frustum_inside_a_box() {
    let (r0, r1, len) = (0.5, 0.3, 0.8);
    let cone = frustum(r0, r1, len);
    let room = cuboid(3.0, 3.0, 3.0);
    let c = one(
        &cone,
        &room,
        &Isometry3::translation(2.0, 0.0, -0.4),
        &Isometry3::identity(),
    );
    assert!((c.normal_w - Vector3::x()).norm() < 1e-12, "{c:?}");
    let slant = (r0 - r1).hypot(len);
    let surface = std::f64::consts::PI * (r0 * r0 + r1 * r1 + (r0 + r1) * slant);
    assert!((c.area - 0.25 * surface).abs() < 1e-9 * surface, "{c:?}");
    assert!(c.penetration > 0.0 && c.penetration.is_finite());
}

/// A small box inside a torus' tube, above its centre circle: the box is pushed out through
/// the tube's nearest surface (up), area a quarter of the box's surface.
#[test]
fn a_box_inside_a_torus_tube() {
    let ring = torus(2.0, 0.5);
    let small = cuboid(0.1, 0.05, 0.08);
    let c = one(
        &small,
        &ring,
        &Isometry3::translation(2.0, 0.0, 0.2),
        &Isometry3::identity(),
    );
    assert!((c.normal_w - Vector3::z()).norm() < 1e-9, "{c:?}");
    let surface = 8.0 * (0.1 * 0.05 + 0.05 * 0.08 + 0.1 * 0.08);
    assert!((c.area - 0.25 * surface).abs() < 1e-9 * surface, "{c:?}");
    // The whole torus inside a box: pushed out through the box's nearest face (+z here).
    let room = cuboid(4.0, 4.0, 1.0);
    let c = one(
        &ring,
        &room,
        &Isometry3::translation(0.0, 0.0, 0.3),
        &Isometry3::identity(),
    );
    assert!((c.normal_w - Vector3::z()).norm() < 1e-12, "{c:?}");
}

/// Touching is no contact: a box on a frustum's top cap, on a torus' top, against a cone's
/// side; a bounded plane's rectangle ending where a torus begins.
#[test]
fn touching_is_no_contact() {
    let cone = frustum(1.0, 0.5, 2.0);
    let slab = cuboid(2.0, 2.0, 0.5);
    assert!(
        query(
            &slab,
            &cone,
            &Isometry3::translation(0.0, 0.0, 2.5),
            &Isometry3::identity()
        )
        .is_empty()
    );
    assert!(
        query(
            &slab,
            &cone,
            &Isometry3::translation(0.0, 0.0, -0.5),
            &Isometry3::identity()
        )
        .is_empty()
    );
    let ring = torus(2.0, 0.5);
    assert!(
        query(
            &slab,
            &ring,
            &Isometry3::translation(0.0, 0.0, 1.0),
            &Isometry3::identity()
        )
        .is_empty()
    );
    assert!(
        query(
            &slab,
            &ring,
            &Isometry3::translation(4.5, 0.0, 0.0),
            &Isometry3::identity()
        )
        .is_empty()
    );
    // A box face against the cone's side: the side's line (r = 1 − z/4) in the x-z plane.
    let side = Vector3::new(1.0, 0.0, 0.25).normalize();
    let wall = cuboid(1.0, 3.0, 3.0);
    let foot = Point3::new(1.0, 0.0, 0.0) + 1.0 * side;
    let pose = Isometry3::from_parts(
        Translation3::from(foot.coords + 1.0 * side),
        nalgebra::UnitQuaternion::rotation_between(&Vector3::x(), &side).unwrap(),
    );
    let found = query(&wall, &cone, &pose, &Isometry3::identity());
    assert!(
        found.is_empty() || found[0].penetration < 1e-12,
        "{found:?}"
    );
    let rim = instance(Geometry::Plane(
        Plane::bounded(2.5, f64::INFINITY, -5.0, 5.0).unwrap(),
    ));
    assert!(
        query(
            &ring,
            &rim,
            &Isometry3::translation(0.0, 0.0, 0.2),
            &Isometry3::identity()
        )
        .is_empty()
    );
}

/// Grazing: a box's top face `ε` into a frustum's bottom gives a contact of depth `ε` along
/// the axis, down to 1e-9 of the size; into a torus' bottom, the torus–plane contact.
#[test]
fn grazing_contacts_have_the_depth_they_are_sunk_by() {
    let cone = frustum(1.0, 0.5, 2.0);
    let slab = cuboid(2.0, 2.0, 0.5);
    for eps in [1e-3, 1e-6, 1e-9] {
        let c = one(
            &cone,
            &slab,
            &Isometry3::translation(0.1, 0.0, -eps),
            &Isometry3::translation(0.0, 0.0, -0.5),
        );
        assert!((c.penetration - eps).abs() < 1e-6 * eps, "{eps}: {c:?}");
        assert!((c.normal_w - Vector3::z()).norm() < 1e-9, "{c:?}");
        let area = std::f64::consts::PI * (1.0 - eps / 4.0).powi(2);
        assert!((c.area - area).abs() < 1e-9, "{c:?}");
    }
    // A torus lying flat: its region's centroid is on the axis, in the hole, so its points are
    // the closest ones (as on an unbounded plane, whose pair integrates over the azimuth
    // instead: the same answer).
    let ring = torus(2.0, 0.5);
    let slab = cuboid(4.0, 4.0, 0.5);
    let ground = instance(Geometry::Plane(Plane::unbounded()));
    for eps in [1e-3, 1e-6, 1e-9] {
        let pose = Isometry3::translation(0.0, 0.0, 0.5 - eps);
        let c = one(&ring, &slab, &pose, &Isometry3::translation(0.0, 0.0, -0.5));
        let p = one(&ring, &ground, &pose, &Isometry3::identity());
        assert_close(&c, &p, 2.5, 6.25, 1e-9, "grazing torus");
    }
}

/// A box face in the plane of a frustum's base with both solids above it (coincident
/// faces): the shared face is the box's, the contact well formed and along the axis; the
/// same within round-off when the box is moved by 1e-15 either way.
#[test]
fn a_box_face_in_the_plane_of_a_cap() {
    let cone = frustum(1.0, 0.5, 2.0);
    let block = cuboid(2.0, 2.0, 0.5);
    let at = |dz: f64| {
        one(
            &block,
            &cone,
            &Isometry3::translation(0.2, 0.0, 0.5 + dz),
            &Isometry3::identity(),
        )
    };
    let c = at(0.0);
    assert!(
        c.normal_w.x.abs() < 1e-12 && c.normal_w.y.abs() < 1e-12,
        "{c:?}"
    );
    assert!(c.penetration > 0.0 && c.penetration.is_finite());
    // The cone narrows upward: the box's top face inside it is smaller than the shared base,
    // so the box's surface inside points down and it is pushed up.
    assert!(c.normal_w.z > 0.99, "{c:?}");
    // A general ellipsoid on a bounded plane's edge: well formed in any case.
    let e = general_ellipsoid(&Vector3::new(0.5, 0.3, 0.4), 1.0);
    let edge = instance(Geometry::Plane(
        Plane::bounded(0.0, 1.0, -1.0, 1.0).unwrap(),
    ));
    let c = one(
        &e,
        &edge,
        &Isometry3::translation(0.0, 0.0, 0.1),
        &Isometry3::identity(),
    );
    assert!(c.penetration > 0.0 && c.normal_w.iter().all(|v| v.is_finite()));
}
