//! A cylinder, frustum or torus against a closed mesh: agreement with the cylinder–box,
//! box–frustum and box–torus slicings where the mesh is a box (at any pose), separate regions, a hole in
//! the section, containment and touching, and the invariants of [`crate::properties`].

use crate::characterization::mesh_box::tube;
use crate::common::{Rng, assert_close, boxes_mesh, instance, nearest, one, query};
use crate::properties::{Maker, Scene, check_motion, check_scale, check_swap, scaled_pose};
use crate::voxel_oracle::Voxels;
use contact_core::geometry::{Cuboid, Cylinder, Frustum};
use contact_core::{Geometry, GeometryInstance, Isometry3, Point3, Vector3};
use std::f64::consts::PI;
use std::sync::Arc;

fn cylinder(r: f64, len: f64) -> GeometryInstance {
    instance(Geometry::Cylinder(Cylinder::new(r, len).unwrap()))
}

fn frustum(r0: f64, r1: f64, len: f64) -> GeometryInstance {
    instance(Geometry::Frustum(Frustum::new(r0, r1, len).unwrap()))
}

fn mesh(m: contact_core::geometry::TriangleMesh) -> GeometryInstance {
    instance(Geometry::Mesh(Arc::new(m)))
}

#[test]
fn a_box_mesh_gives_the_cylinder_box_and_box_frustum_answers_at_any_pose() {
    let mut rng = Rng::new(91);
    let h = Vector3::new(0.7, 0.5, 0.9);
    let box_mesh = mesh(boxes_mesh(&[(Point3::origin(), h)]));
    let cuboid = instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap()));
    for (solid, name) in [
        (cylinder(0.6, 1.4), "cylinder"),
        (frustum(0.8, 0.3, 1.2), "frustum"),
        (frustum(0.0, 0.7, 1.0), "cone"),
    ] {
        let mut seen = 0;
        for _ in 0..150 {
            let pose_j = rng.pose(2.0);
            let pose_i = pose_j * rng.pose(1.5);
            let reference = query(&solid, &cuboid, &pose_i, &pose_j);
            let got = query(&solid, &box_mesh, &pose_i, &pose_j);
            assert_eq!(
                got.len(),
                reference.len(),
                "{name}: {got:?} / {reference:?}"
            );
            for (g, r) in got.iter().zip(&reference) {
                assert_close(g, r, 2.0, 4.0, 1e-9, name);
                seen += 1;
            }
        }
        assert!(seen > 40, "{name}: only {seen} contacts");
    }
}

#[test]
fn a_cylinder_across_both_arms_of_a_u_gives_each_arms_contact() {
    // Two arms (cells x = 0 and x = 2, y = 1) on a base row y = 0; the cylinder lies along x
    // through both arms above the base, out of their tops (a regular normal in each).
    let mut cells = Vec::new();
    for i in 0..3 {
        cells.push([i, 0, 0]);
    }
    cells.push([0, 1, 0]);
    cells.push([2, 1, 0]);
    let u = Voxels { cells, size: 1.0 };
    let world = Rng::new(92).pose(3.0);
    let along_x = Isometry3::new(
        Vector3::new(-0.5, 1.6, 0.85),
        Vector3::new(0.0, 0.5 * PI, 0.0),
    );
    let r = 0.3;
    let solid = cylinder(r, 4.0);
    let got = query(&solid, &mesh(u.mesh()), &(world * along_x), &world);
    assert_eq!(got.len(), 2, "{got:?}");
    // Each arm alone, as a box.
    for x in [0.5, 2.5] {
        let arm = instance(Geometry::Cuboid(Cuboid::centered(0.5, 0.5, 0.5).unwrap()));
        let reference = one(
            &solid,
            &arm,
            &(world * along_x),
            &(world * Isometry3::translation(x, 1.5, 0.5)),
        );
        let g = nearest(&got, &reference.point_i_w);
        assert_close(g, &reference, 1.0, 1.0, 1e-9, "one arm");
    }
}

#[test]
fn a_cylinder_around_the_tubes_hole_is_one_region_with_its_hole() {
    // The disc (radius 1.2 about (1.6, 1.5)) holds the hole [1, 2]² and lies in the tube's
    // wall: its circle is inside the mesh throughout, the hole a loop inside the disc. The
    // cylinder starts at z = 1 inside the tube and leaves its top.
    let world = Rng::new(93).pose(3.0);
    let r = 1.2;
    let pose = world * Isometry3::translation(1.6, 1.5, 1.0);
    let got = one(&cylinder(r, 5.0), &mesh(tube(1.0).mesh()), &pose, &world);
    let area = PI * r * r - 1.0;
    // The centroid (in the hole, at mid-height 2.5): the disc less the hole.
    let x = (1.6 * PI * r * r - 1.5) / area;
    // Normal +z (the bottom cap inside the mesh); the cylinder's point below the centroid on
    // its cap, the mesh's the closest point of the hole's wall x = 2 (the line along z misses
    // the tube).
    let expected_i = Point3::new(x, 1.5, 1.0);
    let expected_j = Point3::new(2.0, 1.5, 2.5);
    assert!(
        (got.normal_w - world.rotation * Vector3::z()).norm() <= 1e-9,
        "{got:?}"
    );
    assert!(
        (got.point_i_w - world * expected_i).norm() <= 1e-9,
        "{got:?}"
    );
    assert!(
        (got.point_j_w - world * expected_j).norm() <= 1e-9,
        "{got:?}"
    );
    assert!((got.area - area).abs() <= 1e-9 * area, "{got:?}");
}

#[test]
fn containment_touching_and_the_mesh_inside_the_solid() {
    let block = mesh(boxes_mesh(&[(
        Point3::origin(),
        Vector3::new(3.0, 3.0, 3.0),
    )]));
    // A cylinder inside the block, nearest its +x face: pushed out that way.
    let pose = Isometry3::translation(2.0, 0.3, -0.5);
    let got = one(&cylinder(0.5, 1.0), &block, &pose, &Isometry3::identity());
    assert!((got.normal_w - Vector3::x()).norm() <= 1e-9, "{got:?}");
    let volume_area = 0.25 * (2.0 * PI * 0.25 + 2.0 * PI * 0.5);
    assert!((got.area - volume_area).abs() <= 1e-9, "{got:?}");
    // A cylinder standing on the block's top face, and one beside it touching its side.
    for pose in [
        Isometry3::translation(0.4, 0.2, 3.0),
        Isometry3::translation(3.5, 0.0, -1.0),
    ] {
        let found = query(&cylinder(0.5, 1.0), &block, &pose, &Isometry3::identity());
        assert!(found.is_empty(), "{found:?}");
    }
    // A small box mesh inside a big cylinder: the contact of the box against it.
    let small = Vector3::new(0.2, 0.3, 0.1);
    let inner = mesh(boxes_mesh(&[(Point3::origin(), small)]));
    let cuboid = instance(Geometry::Cuboid(
        Cuboid::centered(small.x, small.y, small.z).unwrap(),
    ));
    let at = Isometry3::translation(0.3, -0.2, 0.8);
    let got = one(&cylinder(1.0, 2.0), &inner, &Isometry3::identity(), &at);
    let reference = one(&cylinder(1.0, 2.0), &cuboid, &Isometry3::identity(), &at);
    assert_close(&got, &reference, 2.0, 4.0, 1e-9, "mesh inside the cylinder");
}

fn cylinder_mesh_scene(rng: &mut Rng, s: f64) -> Scene {
    let pose_j = rng.pose(3.0);
    let pose_i = pose_j
        * Isometry3::from_parts(
            nalgebra::Translation3::new(
                rng.uniform(0.0, 3.0),
                rng.uniform(0.0, 1.0),
                rng.uniform(0.0, 2.0),
            ),
            rng.rotation(),
        );
    let pick = rng.uniform(0.0, 1.0);
    let solid = if pick < 0.33 {
        cylinder(rng.uniform(0.2, 0.8) * s, rng.uniform(0.5, 2.0) * s)
    } else if pick < 0.5 {
        instance(Geometry::Ellipsoid(
            contact_core::geometry::Ellipsoid::new(
                rng.uniform(0.5, 1.6) * s,
                rng.uniform(0.5, 1.6) * s,
                rng.uniform(0.5, 1.6) * s,
            )
            .unwrap(),
        ))
    } else if pick < 0.67 {
        let big = rng.uniform(0.6, 1.2);
        instance(Geometry::Torus(
            contact_core::geometry::Torus::new(big * s, rng.uniform(0.2, 0.5) * big * s).unwrap(),
        ))
    } else {
        frustum(
            rng.uniform(0.0, 0.8) * s,
            rng.uniform(0.2, 0.8) * s,
            rng.uniform(0.5, 2.0) * s,
        )
    };
    Scene {
        i: solid,
        j: mesh(crate::characterization::mesh_box::l_bar(s).mesh()),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: 5.0 * s,
    }
}

#[test]
fn revolved_mesh_pairs_swap_move_and_scale_with_the_scene() {
    let makers: [(&str, Maker); 1] = [("sliced revolved–mesh", cylinder_mesh_scene)];
    check_swap(&makers, 94);
    check_motion(&makers, 95);
    check_scale(&makers, 96);
}

#[test]
fn a_box_mesh_gives_the_box_torus_answers_at_any_pose() {
    // Random poses, and slabs through the ring (two regions).
    let mut rng = Rng::new(97);
    let torus = instance(Geometry::Torus(
        contact_core::geometry::Torus::new(1.0, 0.35).unwrap(),
    ));
    let mut seen = [0usize; 3];
    let mut joined_slivers = 0;
    for case in 0..200 {
        let (h, pose_j, pose_i) = if case % 2 == 0 {
            let h = Vector3::new(0.7, 0.5, 0.9);
            let pose_j = rng.pose(2.0);
            (h, pose_j, pose_j * rng.pose(1.5))
        } else {
            // A slab across the ring: thin in x, long in y, through the tube.
            let h = Vector3::new(rng.uniform(0.1, 0.3), 2.0, rng.uniform(0.2, 0.6));
            let pose_i = rng.pose(2.0);
            let tilt = nalgebra::UnitQuaternion::from_euler_angles(
                rng.uniform(-0.3, 0.3),
                rng.uniform(-0.3, 0.3),
                rng.uniform(-3.0, 3.0),
            );
            let at = Isometry3::from_parts(
                nalgebra::Translation3::new(rng.uniform(-0.5, 0.5), 0.0, rng.uniform(-0.3, 0.3)),
                tilt,
            );
            (h, pose_i * at, pose_i)
        };
        let cuboid = instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap()));
        let box_mesh = mesh(boxes_mesh(&[(Point3::origin(), h)]));
        let reference = query(&torus, &cuboid, &pose_i, &pose_j);
        let got = query(&torus, &box_mesh, &pose_i, &pose_j);
        if got.len() < reference.len() {
            // The mesh pair joins regions by the connectivity of their chords; the box–torus
            // pair finds them as arcs of azimuth. They disagree where a box face runs tangent
            // to the tube's inner circle (2 of 400 poses): the mesh pair sees the two parts
            // joined by a sliver along that face, the box–torus pair two regions. Which is
            // right is not settled (a raster of the slices shows a sliver of about a pixel);
            // either way the one contact must be the union of the two: its area vector the
            // sum of theirs, to the sliver's own share.
            assert_eq!(got.len(), 1, "{got:?} / {reference:?}");
            let sum: Vector3 = reference.iter().map(|r| r.area * r.normal_w).sum();
            let total: f64 = reference.iter().map(|r| r.area).sum();
            let joined = got[0].area * got[0].normal_w;
            assert!(
                (joined - sum).norm() <= 1e-6 * total,
                "{got:?} / {reference:?}"
            );
            joined_slivers += 1;
            continue;
        }
        assert_eq!(got.len(), reference.len(), "{got:?} / {reference:?}");
        for r in &reference {
            let g = nearest(&got, &r.point_i_w);
            assert_close(g, r, 2.0, 4.0, 1e-9, "torus");
        }
        seen[reference.len().min(2)] += 1;
    }
    assert!(seen[1] > 30 && seen[2] > 10, "{seen:?}");
    assert!(joined_slivers <= 2, "{joined_slivers} poses joined");
}

#[test]
fn a_box_mesh_gives_the_ellipsoid_box_answer_at_any_pose() {
    let mut rng = Rng::new(98);
    let h = Vector3::new(0.7, 0.5, 0.9);
    let box_mesh = mesh(boxes_mesh(&[(Point3::origin(), h)]));
    let cuboid = instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap()));
    let ellipsoid = instance(Geometry::Ellipsoid(
        contact_core::geometry::Ellipsoid::new(0.9, 0.5, 0.35).unwrap(),
    ));
    let mut seen = 0;
    for _ in 0..120 {
        let pose_j = rng.pose(2.0);
        let pose_i = pose_j * rng.pose(1.4);
        let reference = query(&ellipsoid, &cuboid, &pose_i, &pose_j);
        let got = query(&ellipsoid, &box_mesh, &pose_i, &pose_j);
        assert_eq!(got.len(), reference.len(), "{got:?} / {reference:?}");
        for (g, r) in got.iter().zip(&reference) {
            assert_close(g, r, 2.0, 4.0, 1e-9, "ellipsoid");
            seen += 1;
        }
    }
    assert!(seen > 30, "only {seen} contacts");
}

/// The plane whose solid is `x ≥ at` (its +z along −x), as the wall of a cavity seen from a
/// body poking through it.
fn wall_x(at: f64) -> (GeometryInstance, Isometry3) {
    let turn = nalgebra::UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -0.5 * PI);
    (
        instance(Geometry::Plane(contact_core::geometry::Plane::unbounded())),
        Isometry3::from_parts(nalgebra::Translation3::new(at, 0.0, 0.0), turn),
    )
}

#[test]
fn solids_in_a_box_cavity_meet_its_wall_as_the_plane_beyond_it() {
    // A cavity of half extents 3 (a flipped box, and the same as a flipped box mesh): a body
    // crossing only the +x wall meets the half-space x ≥ 3, the pair against that plane.
    let mut rng = Rng::new(99);
    let w = 3.0;
    let cavity_box = instance(Geometry::Cuboid(Cuboid::centered(w, w, w).unwrap())).flipped();
    let cavity_mesh = mesh(boxes_mesh(&[(Point3::origin(), Vector3::repeat(w))])).flipped();
    let (plane, plane_pose) = wall_x(w);
    let solids = [
        (cylinder(0.5, 1.2), "cylinder"),
        (frustum(0.7, 0.2, 1.0), "frustum"),
        (
            instance(Geometry::Torus(
                contact_core::geometry::Torus::new(0.6, 0.2).unwrap(),
            )),
            "torus",
        ),
        (
            instance(Geometry::Ellipsoid(
                contact_core::geometry::Ellipsoid::new(0.8, 0.5, 0.3).unwrap(),
            )),
            "ellipsoid",
        ),
        (instance(Geometry::sphere(0.6).unwrap()), "sphere"),
    ];
    for (solid, name) in &solids {
        let mut seen = 0;
        for _ in 0..40 {
            let world = rng.pose(2.0);
            let at = Isometry3::from_parts(
                nalgebra::Translation3::new(rng.uniform(2.4, 3.0), rng.uniform(-1.0, 1.0), 0.0),
                rng.rotation(),
            );
            let reference = query(solid, &plane, &(world * at), &(world * plane_pose));
            for cavity in [&cavity_box, &cavity_mesh] {
                let got = query(solid, cavity, &(world * at), &world);
                assert_eq!(
                    got.len(),
                    reference.len(),
                    "{name}: {got:?} / {reference:?}"
                );
                for (g, r) in got.iter().zip(&reference) {
                    assert_close(g, r, 2.0, 4.0, 1e-9, name);
                }
                // The cavity as I: the swapped contact.
                let back = query(cavity, solid, &world, &(world * at));
                assert_eq!(back.len(), got.len(), "{name}");
                for (b, g) in back.iter().zip(&got) {
                    assert_close(&b.swapped(), g, 2.0, 4.0, 1e-9, name);
                }
            }
            seen += reference.len();
        }
        assert!(seen > 10, "{name}: only {seen} contacts");
    }
}

#[test]
fn a_ball_in_a_slot_meets_both_walls() {
    // A slot 1 wide (a flipped box 0.5 in half width along x), a ball of radius 0.7 in it:
    // one contact per wall, each the ball against that wall's plane.
    let slot = instance(Geometry::Cuboid(Cuboid::centered(0.5, 3.0, 3.0).unwrap())).flipped();
    let ball = instance(Geometry::sphere(0.7).unwrap());
    let world = Rng::new(100).pose(2.0);
    let at = Isometry3::translation(0.1, 0.2, -0.3);
    let got = query(&ball, &slot, &(world * at), &world);
    assert_eq!(got.len(), 2, "{got:?}");
    let (plane, right) = wall_x(0.5);
    let left = Isometry3::from_parts(
        nalgebra::Translation3::new(-0.5, 0.0, 0.0),
        nalgebra::UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 0.5 * PI),
    );
    for wall in [right, left] {
        let reference = one(&ball, &plane, &(world * at), &(world * wall));
        let g = nearest(&got, &reference.point_i_w);
        assert_close(g, &reference, 1.0, 1.0, 1e-9, "a wall of the slot");
    }
}
