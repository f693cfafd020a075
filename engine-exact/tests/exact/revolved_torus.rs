//! Cylinder–torus and frustum–torus: coaxial pairs against the meridian closed form, general
//! poses and two-region rods against the divergence theorem ([`crate::torus_pair_oracles`]),
//! the degenerate branches (touching, grazing, containment both ways, rods through the hole
//! touching nothing or both sides, perpendicular axes, scales 1e-6 and 1e6), and the
//! invariants of [`crate::properties`].

use crate::common::{Expected, Rng, errors, instance, one, query};
use crate::properties::{Maker, Scene, check_motion, check_scale, check_swap, scaled_pose};
use crate::torus_pair_oracles::{Cone, coaxial, contact_of, divergence, rod_through_hole};
use contact_core::geometry::{Cylinder, Frustum, Torus};
use contact_core::{Contact, Geometry, GeometryInstance, Isometry3, UnitQuaternion, Vector3};
use nalgebra::Translation3;
use std::f64::consts::{FRAC_PI_2, PI};

const BIG: f64 = 2.0;
const SMALL: f64 = 0.5;

fn torus() -> GeometryInstance {
    instance(Geometry::Torus(Torus::new(BIG, SMALL).unwrap()))
}

/// The cylinder (`r0 == r1`, half the time) or frustum of `cone`.
pub(crate) fn solid(cone: &Cone, as_cylinder: bool) -> GeometryInstance {
    if as_cylinder && cone.r0 == cone.r1 {
        instance(Geometry::Cylinder(
            Cylinder::new(cone.r0, cone.len).unwrap(),
        ))
    } else {
        instance(Geometry::Frustum(
            Frustum::new(cone.r0, cone.r1, cone.len).unwrap(),
        ))
    }
}

fn well_formed(c: &Contact) {
    assert!(c.penetration.is_finite() && c.penetration > 0.0, "{c:?}");
    assert!((c.normal_w.norm() - 1.0).abs() < 1e-12, "{c:?}");
    assert!(c.area.is_finite() && c.area > 0.0, "{c:?}");
    assert!(
        c.point_i_w
            .coords
            .iter()
            .chain(c.point_j_w.coords.iter())
            .all(|v| v.is_finite()),
        "{c:?}"
    );
}

/// A random coaxial cylinder or frustum through the hole (touching the inner wall) or as a
/// sleeve over the ring, its bottom cap inside the tube's height, reaching above it.
pub(crate) fn coaxial_case(rng: &mut Rng) -> (Cone, f64) {
    let radius = |rng: &mut Rng| rng.uniform(BIG - 0.8 * SMALL, BIG + 1.5 * SMALL);
    let r0 = radius(rng);
    let r1 = if rng.uniform(0.0, 1.0) < 0.4 {
        r0
    } else {
        radius(rng)
    };
    let cone = Cone {
        r0,
        r1,
        len: rng.uniform(1.2, 2.0),
    };
    (cone, rng.uniform(-0.7, 0.7) * SMALL)
}

/// The worst (depth, normal, points) errors of the coaxial pairs against the meridian
/// closed form over `count` cases.
pub(crate) fn coaxial_errors(seed: u64, count: usize) -> [f64; 3] {
    let mut rng = Rng::new(seed);
    let mut worst = [0.0f64; 3];
    let mut seen = 0;
    while seen < count {
        let (cone, z0) = coaxial_case(&mut rng);
        let Some(want) = coaxial(&cone, z0, BIG, SMALL) else {
            continue;
        };
        let i = solid(&cone, seen % 2 == 0);
        let got = one(
            &i,
            &torus(),
            &Isometry3::translation(0.0, 0.0, z0),
            &Isometry3::identity(),
        );
        let e = errors(&got, &want, BIG + SMALL);
        for k in 0..3 {
            worst[k] = worst[k].max(e[k]);
        }
        seen += 1;
    }
    worst
}

#[test]
fn coaxial_rods_and_sleeves_match_the_meridian_closed_form() {
    let worst = coaxial_errors(0x70_1201, 40);
    assert!(worst.iter().all(|&e| e <= 1e-9), "{worst:?}");
}

/// A random rod or frustum crossing the tube about the centre circle's point at azimuth 0
/// (one region).
pub(crate) fn crossing_case(rng: &mut Rng) -> (Cone, Isometry3) {
    let r0 = rng.uniform(0.1, 0.4);
    let r1 = if rng.uniform(0.0, 1.0) < 0.4 {
        r0
    } else {
        rng.uniform(0.05, 0.4)
    };
    let cone = Cone {
        r0,
        r1,
        len: rng.uniform(0.5, 1.5),
    };
    let turn = if rng.uniform(0.0, 1.0) < 0.25 {
        // Perpendicular to the torus' axis.
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, PI))
            * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), FRAC_PI_2)
    } else {
        rng.rotation()
    };
    let middle = Vector3::new(BIG, 0.0, 0.0) + rng.unit_vector() * rng.uniform(0.0, 0.6);
    let pose = Isometry3::from_parts(
        Translation3::from(middle - turn * Vector3::new(0.0, 0.0, 0.5 * cone.len)),
        turn,
    );
    (cone, pose)
}

/// The worst errors of general single-region poses against the divergence theorem, and the
/// oracle's worst own error (see [`divergence`]); each case within 1e-9 or ten times the
/// oracle's error.
pub(crate) fn crossing_errors(seed: u64, count: usize) -> ([f64; 3], f64) {
    let mut rng = Rng::new(seed);
    let (mut worst, mut oracle) = ([0.0f64; 3], 0.0f64);
    let mut seen = 0;
    while seen < count {
        let (cone, pose) = crossing_case(&mut rng);
        let i = solid(&cone, seen % 2 == 0);
        let found = query(&i, &torus(), &pose, &Isometry3::identity());
        let Some((m, change)) = divergence(&cone, &pose, BIG, SMALL, None, None, 1e-12) else {
            assert!(found.is_empty(), "{found:?}");
            continue;
        };
        // A sliver below the oracle's resolution is not compared, nor a frustum inside the
        // tube (no area vector: the containment test's branch).
        if m.volume < 1e-6 || m.area_vector_i.norm() < 1e-6 {
            continue;
        }
        assert_eq!(found.len(), 1, "{cone:?} {pose:?}");
        let want = contact_of(&m, &cone, &pose, BIG, SMALL);
        let e = errors(&found[0], &want, BIG + SMALL);
        // The engine within 1e-9, or within ten times the oracle's own error where that is
        // larger (its crossings' sampling missed a piece of an arc: the closure shows it).
        assert!(
            e.iter().all(|&x| x <= 1e-9 + 10.0 * change),
            "{e:?} oracle {change:e}: {cone:?} {pose:?}"
        );
        for k in 0..3 {
            worst[k] = worst[k].max(e[k]);
        }
        oracle = oracle.max(change);
        seen += 1;
    }
    (worst, oracle)
}

#[test]
fn general_poses_match_the_divergence_theorem() {
    let (worst, oracle) = crossing_errors(0x70_1202, 12);
    println!("general poses: {worst:?}, oracle {oracle:e}");
    // The oracle's sampling is at worst near 1e-6 (see the docs of `divergence`).
    assert!(oracle <= 1e-5, "{oracle:e}");
}

/// A rod along `x` through the hole, its ends inside the tube on both sides, tilted by
/// `tilt` about `y` and moved by `lift` along `z`.
fn rod_through(tilt: f64, lift: f64) -> (Cone, Isometry3) {
    let cone = Cone {
        r0: 0.2,
        r1: 0.2,
        len: 4.2,
    };
    let turn = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), FRAC_PI_2 + tilt);
    let pose = Isometry3::from_parts(
        Translation3::from(Vector3::new(0.0, 0.0, lift) - turn * Vector3::new(0.0, 0.0, 2.1)),
        turn,
    );
    (cone, pose)
}

/// The two regions of rods through the hole (at three heights, turned about the axis by
/// three azimuths) against their closed form; the worst errors.
pub(crate) fn two_region_errors() -> [f64; 3] {
    let mut worst = [0.0f64; 3];
    for (lift, azimuth) in [(0.0, 0.0), (0.1, 0.7), (-0.15, 2.0)] {
        let (cone, pose) = rod_through(0.0, lift);
        let turn = Isometry3::rotation(Vector3::z() * azimuth);
        let found = query(
            &solid(&cone, true),
            &torus(),
            &(turn * pose),
            &Isometry3::identity(),
        );
        assert_eq!(found.len(), 2, "{found:?}");
        for want in rod_through_hole(cone.r0, 0.5 * cone.len, lift, BIG, SMALL) {
            let want = want.moved(&turn);
            let got = found
                .iter()
                .find(|c| (c.point_j_w - want.point_j).norm() < 0.1)
                .unwrap_or_else(|| panic!("{found:?} {want:?}"));
            let e = errors(got, &want, BIG + SMALL);
            for k in 0..3 {
                worst[k] = worst[k].max(e[k]);
            }
        }
    }
    worst
}

#[test]
fn a_rod_through_the_hole_touching_both_sides_has_two_contacts() {
    let worst = two_region_errors();
    assert!(worst.iter().all(|&e| e <= 1e-9), "{worst:?}");
    // Tilted, off the mid-plane: two contacts still, one each side.
    let (cone, pose) = rod_through(0.05, 0.1);
    let found = query(&solid(&cone, true), &torus(), &pose, &Isometry3::identity());
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(
        found[0].point_j_w.x * found[1].point_j_w.x < 0.0,
        "{found:?}"
    );
}

#[test]
fn a_rod_through_the_hole_touching_nothing_has_no_contact() {
    // Coaxial, and tilted, inside the hole's waist.
    let rod = instance(Geometry::Cylinder(Cylinder::new(0.4, 3.0).unwrap()));
    for pose in [
        Isometry3::translation(0.0, 0.0, -1.5),
        Isometry3::new(Vector3::new(0.3, 0.0, -1.2), Vector3::new(0.25, 0.0, 0.0)),
    ] {
        assert!(query(&rod, &torus(), &pose, &Isometry3::identity()).is_empty());
    }
}

/// A vertical cylinder of radius `c` against the outer (`side = 1`) or inner (`−1`)
/// equator, sunk by `depth` (negative: a gap): by the mirror symmetries in `y` and `z` the
/// normal is `±x` and the points lie on the `x` axis.
fn equator(c: f64, side: f64, depth: f64) -> (GeometryInstance, Isometry3, Expected) {
    let foot = BIG + side * SMALL;
    let axis_x = foot + side * (c - depth);
    let expected = Expected {
        point_i: contact_core::Point3::new(foot - side * depth, 0.0, 0.0),
        point_j: contact_core::Point3::new(foot, 0.0, 0.0),
        normal: Vector3::x() * side,
        depth,
    };
    (
        instance(Geometry::Cylinder(Cylinder::new(c, 2.0).unwrap())),
        Isometry3::translation(axis_x, 0.0, -1.0),
        expected,
    )
}

#[test]
fn grazing_an_equator_has_the_depth_it_is_sunk_by_and_touching_is_none() {
    for side in [1.0, -1.0] {
        let c = 0.3;
        for gap in [0.0, 1e-9] {
            let (i, pose, _) = equator(c, side, -gap);
            assert!(query(&i, &torus(), &pose, &Isometry3::identity()).is_empty());
        }
        for depth in [1e-2, 1e-4, 1e-7] {
            let (i, pose, want) = equator(c, side, depth);
            let got = one(&i, &torus(), &pose, &Isometry3::identity());
            well_formed(&got);
            let e = errors(&got, &want, 1.0);
            // A thin lens keeps its depth and normal; its centroid is as good as the
            // quadrature's absolute floor over the lens' volume (see ellipsoid–torus).
            let (normal_tol, point_tol) = if depth < 1e-4 {
                (1e-6, 1e-6)
            } else {
                (1e-9, 1e-9)
            };
            assert!(
                e[0] <= 1e-9 && e[1] <= normal_tol && e[2] <= point_tol,
                "{side} {depth:e}: {e:?}\n{got:?}"
            );
        }
    }
}

#[test]
fn a_flat_cap_on_the_tube_top_is_a_curved_strip_with_a_finite_contact() {
    // The top circle is parabolic: a cap sunk δ meets it in a curved strip whose centroid lies
    // off it, so the points are the closest ones; the torus' surface in the strip leans
    // outwards a little more than inwards, so the normal tilts from +z by O(δ) (against the
    // divergence theorem at 1e-4; at 1e-7 within 1e-6).
    let cone = Cone {
        r0: 0.3,
        r1: 0.3,
        len: 1.0,
    };
    for depth in [1e-4, 1e-7] {
        let pose = Isometry3::translation(BIG, 0.0, SMALL - depth);
        let got = one(&solid(&cone, true), &torus(), &pose, &Isometry3::identity());
        well_formed(&got);
        if depth > 1e-5 {
            let (m, error) = divergence(&cone, &pose, BIG, SMALL, None, None, 1e-14).unwrap();
            assert!(error < 1e-10, "{error:e} {m:?}");
            let want = -m.area_vector_i.normalize();
            assert!((got.normal_w - want).norm() < 1e-9, "{got:?} {want:?}");
            assert!((got.normal_w - Vector3::z()).norm() > 1e-6, "{got:?}");
        } else {
            assert!((got.normal_w - Vector3::z()).norm() < 1e-6, "{got:?}");
        }
    }
}

#[test]
fn containment_either_way_has_finite_contacts_along_the_nearest_face() {
    // A small cylinder inside the tube: pushed out through the torus' surface nearest the
    // centroid (its outer wall, +x).
    let small_rod = instance(Geometry::Cylinder(Cylinder::new(0.1, 0.3).unwrap()));
    let got = one(
        &small_rod,
        &torus(),
        &Isometry3::translation(BIG + 0.2, 0.0, -0.15),
        &Isometry3::identity(),
    );
    well_formed(&got);
    assert!((got.normal_w - Vector3::x()).norm() < 1e-9, "{got:?}");
    // The torus inside a big cylinder: the torus leaves through the cylinder's face nearest
    // the centroid (its top, the torus' centre lying 0.9 below it and 1.1 above the bottom,
    // 3.0 from the side), so the cylinder is pushed along −z.
    let drum = instance(Geometry::Cylinder(Cylinder::new(3.0, 2.0).unwrap()));
    let got = one(
        &drum,
        &torus(),
        &Isometry3::translation(0.0, 0.0, -1.1),
        &Isometry3::identity(),
    );
    well_formed(&got);
    assert!((got.normal_w + Vector3::z()).norm() < 1e-9, "{got:?}");
    // A coaxial rod filling the hole, symmetric about the mid-plane: the area vector vanishes;
    // the normal from J into I is the torus' outward normal at its surface point nearest the
    // centroid (on the axis: the inner equator at +x, whose normal is −x), the depth the
    // radial overlap 1.7 − 1.5.
    let plug = instance(Geometry::Cylinder(Cylinder::new(1.7, 2.0).unwrap()));
    let got = one(
        &plug,
        &torus(),
        &Isometry3::translation(0.0, 0.0, -1.0),
        &Isometry3::identity(),
    );
    well_formed(&got);
    assert!((got.normal_w + Vector3::x()).norm() < 1e-9, "{got:?}");
    assert!((got.penetration - 0.2).abs() < 1e-9, "{got:?}");
}

#[test]
fn extreme_scales_scale_depth_and_points() {
    let (cone, pose) = rod_through(0.05, 0.1);
    let cases = [
        (cone, pose),
        crossing_case(&mut Rng::new(7)),
        (
            Cone {
                r0: 1.8,
                r1: 1.6,
                len: 1.5,
            },
            Isometry3::translation(0.0, 0.0, 0.1),
        ),
    ];
    for (cone, pose) in cases {
        let reference = query(
            &solid(&cone, false),
            &torus(),
            &pose,
            &Isometry3::identity(),
        );
        assert!(!reference.is_empty());
        for s in [1e-6, 1e6] {
            let scaled = Cone {
                r0: cone.r0 * s,
                r1: cone.r1 * s,
                len: cone.len * s,
            };
            let t = instance(Geometry::Torus(Torus::new(BIG * s, SMALL * s).unwrap()));
            let got = query(
                &solid(&scaled, false),
                &t,
                &scaled_pose(&pose, s),
                &Isometry3::identity(),
            );
            assert_eq!(got.len(), reference.len());
            for (g, r) in got.iter().zip(&reference) {
                let e = [
                    (g.penetration / s - r.penetration).abs(),
                    (g.normal_w - r.normal_w).norm(),
                    (g.point_i_w.coords / s - r.point_i_w.coords).norm()
                        + (g.point_j_w.coords / s - r.point_j_w.coords).norm(),
                ];
                assert!(e.iter().all(|&x| x <= 1e-9 * (BIG + SMALL)), "{s:e}: {e:?}");
            }
        }
    }
}

fn revolved_torus(rng: &mut Rng, s: f64) -> Scene {
    let pose_j = rng.pose(3.0);
    let (cone, pose) = match rng.next_u64() % 3 {
        0 => {
            let (cone, z0) = coaxial_case(rng);
            (cone, Isometry3::translation(0.0, 0.0, z0))
        }
        1 => rod_through(rng.uniform(-0.1, 0.1), rng.uniform(-0.2, 0.2)),
        _ => crossing_case(rng),
    };
    let scaled = Cone {
        r0: cone.r0 * s,
        r1: cone.r1 * s,
        len: cone.len * s,
    };
    let cylinder = rng.uniform(0.0, 1.0) < 0.5;
    Scene {
        i: solid(&scaled, cylinder),
        j: instance(Geometry::Torus(Torus::new(BIG * s, SMALL * s).unwrap())),
        pose_i: scaled_pose(&(pose_j * pose), s),
        pose_j: scaled_pose(&pose_j, s),
        length: (BIG + SMALL) * s,
    }
}

const MAKERS: [(&str, Maker); 1] = [("cylinder/frustum–torus", revolved_torus)];

#[test]
fn exchanging_i_and_j_gives_the_swapped_contact() {
    check_swap(&MAKERS, 61);
}

#[test]
fn a_rigid_motion_of_both_bodies_moves_the_contact() {
    check_motion(&MAKERS, 62);
}

#[test]
fn scaling_the_scene_scales_depth_and_points() {
    check_scale(&MAKERS, 63);
}

#[test]
fn coaxial_solids_touching_an_equator_or_the_top_circle_have_no_contact() {
    // A rod filling the hole to the inner equator, a sleeve at the outer equator, a cap on
    // the plane of the top circle: touching all round, no volume.
    for (r, z0, len) in [
        (BIG - SMALL, -1.0, 2.0),
        (BIG + SMALL + 0.3, -1.0, 2.0),
        (BIG + SMALL, SMALL, 1.0),
    ] {
        let outer = instance(Geometry::Cylinder(Cylinder::new(r, len).unwrap()));
        let found = query(
            &outer,
            &torus(),
            &Isometry3::translation(0.0, 0.0, z0),
            &Isometry3::identity(),
        );
        // The sleeve (radius beyond the ring) holds the whole torus: that one is a contact.
        if r > BIG + SMALL + 0.1 {
            assert_eq!(found.len(), 1, "{found:?}");
        } else {
            assert!(found.is_empty(), "{r} {z0}: {found:?}");
        }
    }
}

/// Random poses of needles, plates, cones (an apex included) and rods against thin and fat
/// tori at 1e-6, 1 and 1e6: every answer well formed (no NaN, no panic), each depth within
/// the two bodies' reach.
#[test]
fn random_extreme_shapes_give_well_formed_contacts() {
    let mut rng = Rng::new(0x70_12E5);
    let mut seen = 0;
    for k in 0..150 {
        let scale = [1.0, 1e-6, 1e6][k % 3];
        let (r0, r1, len) = [
            (1e-3, 1e-3, 1.0),
            (1.0, 1.0, 1e-3),
            (0.6, 0.0, 0.8),
            (0.0, 0.4, 0.5),
            (0.3, 0.5, 3.0),
        ][k % 5];
        let i = instance(Geometry::Frustum(
            Frustum::new(r0 * scale, r1 * scale, len * scale).unwrap(),
        ));
        let small = [0.05, 0.5, 0.95][k % 3];
        let j = instance(Geometry::Torus(Torus::new(scale, small * scale).unwrap()));
        let reach = (1.0 + small + r0.max(r1) + len) * scale;
        let pose = Isometry3::from_parts(
            Translation3::from(rng.unit_vector() * rng.uniform(0.0, (1.0 + small) * scale)),
            rng.rotation(),
        );
        for c in query(&i, &j, &pose, &Isometry3::identity()) {
            well_formed(&c);
            assert!(c.penetration <= 2.0 * reach, "{c:?}");
            seen += 1;
        }
    }
    assert!(seen > 40, "{seen}");
}

/// A needle (radius 0.005–0.03) poking into the outer equator, the inner equator or the
/// top at a random azimuth, narrower than the region search's azimuth samples: found, with
/// its depth within its own reach.
#[test]
fn a_needle_between_azimuth_samples_is_found() {
    let mut rng = Rng::new(0x70_12EE);
    for k in 0..45 {
        let r = rng.uniform(0.005, 0.03);
        let phi = rng.uniform(0.0, std::f64::consts::TAU);
        let radial = Vector3::new(phi.cos(), phi.sin(), 0.0);
        let (foot, outward) = match k % 3 {
            0 => (radial * (BIG + SMALL), radial),
            1 => (radial * (BIG - SMALL), -radial),
            _ => (radial * BIG + Vector3::z() * SMALL, Vector3::z()),
        };
        let sink = rng.uniform(0.01, 0.2);
        // The needle along the outward normal, its bottom cap `sink` inside.
        let turn = UnitQuaternion::rotation_between(&Vector3::z(), &outward).unwrap();
        let pose = Isometry3::from_parts(Translation3::from(foot - outward * sink), turn);
        let needle = instance(Geometry::Cylinder(Cylinder::new(r, 1.0).unwrap()));
        let found = query(&needle, &torus(), &pose, &Isometry3::identity());
        assert_eq!(found.len(), 1, "{k}: {found:?}");
        well_formed(&found[0]);
        assert!(
            (found[0].penetration - sink).abs() < 0.1 * sink,
            "{k}: {found:?}"
        );
    }
}
