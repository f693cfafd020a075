//! Frustum–frustum and cylinder–frustum: a frustum of equal radii is a cylinder, so both
//! pairs must match the cylinder–cylinder pair (a different method: slicing perpendicular to
//! both axes, polygon sections) on general poses; coaxial pairs against their
//! one-dimensional closed forms; degenerate branches. Swap, motion and scale are in
//! [`crate::properties`], with [`scene`] as its maker.

use crate::common::{Rng, instance, one, query};
use crate::properties::{Scene, scaled_pose};
use contact_core::geometry::{Cylinder, Frustum};
use contact_core::{Contact, Geometry, Isometry3, UnitQuaternion, Vector3};
use nalgebra::Translation3;
use std::f64::consts::PI;

fn cylinder(r: f64, len: f64) -> Geometry {
    Geometry::Cylinder(Cylinder::new(r, len).unwrap())
}

fn frustum(r0: f64, r1: f64, len: f64) -> Geometry {
    Geometry::Frustum(Frustum::new(r0, r1, len).unwrap())
}

/// The errors (depth, normal, points, area) of `got` against `want`, relative to `length`.
fn errors(got: &Contact, want: &Contact, length: f64) -> [f64; 4] {
    [
        (got.penetration - want.penetration).abs() / length,
        (got.normal_w - want.normal_w).norm(),
        ((got.point_i_w - want.point_i_w).norm() + (got.point_j_w - want.point_j_w).norm())
            / length,
        (got.area - want.area).abs() / (length * length),
    ]
}

/// Random crossed/skew, near-parallel (1e-6 rad) and perpendicular poses: the equal-radius
/// frustum pairs (frustum–frustum, cylinder–frustum both ways) against the cylinder pair.
/// The worst errors seen and how many contacts were compared.
pub fn equal_radius_against_cylinders(seed: u64, count: usize) -> ([f64; 4], usize) {
    let mut rng = Rng::new(seed);
    let mut max = [0.0f64; 4];
    let mut compared = 0;
    for k in 0..count {
        let (ra, la) = (rng.uniform(0.3, 1.0), rng.uniform(0.4, 1.6));
        let (rb, lb) = (rng.uniform(0.3, 1.0), rng.uniform(0.4, 1.6));
        let turn = match k % 4 {
            0 | 1 => rng.rotation(),
            2 => UnitQuaternion::from_axis_angle(
                &nalgebra::Unit::new_normalize(rng.unit_vector()),
                1e-6 * rng.uniform(0.5, 5.0),
            ),
            _ => {
                UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.5 * PI)
                    * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, 6.0))
            }
        };
        let pose_a = rng.pose(2.0);
        let offset = Vector3::new(0.0, 0.0, 0.6) + rng.unit_vector() * rng.uniform(0.0, 0.8);
        let pose_b = pose_a * Isometry3::from_parts(Translation3::from(offset), turn);
        let (ca, cb) = (instance(cylinder(ra, la)), instance(cylinder(rb, lb)));
        let (fa, fb) = (instance(frustum(ra, ra, la)), instance(frustum(rb, rb, lb)));
        let want = query(&ca, &cb, &pose_a, &pose_b);
        for (i, j) in [(&fa, &fb), (&ca, &fb), (&fa, &cb)] {
            let got = query(i, j, &pose_a, &pose_b);
            assert_eq!(got.len(), want.len(), "case {k}: {got:?} vs {want:?}");
            if let (Some(g), Some(w)) = (got.first(), want.first()) {
                let e = errors(g, w, ra.max(la).max(rb).max(lb));
                for n in 0..4 {
                    max[n] = max[n].max(e[n]);
                }
                compared += 1;
            }
        }
    }
    (max, compared)
}

#[test]
fn equal_radius_frusta_match_the_cylinder_pair() {
    let (max, compared) = equal_radius_against_cylinders(0x5eed_f00d, 24);
    assert!(compared >= 40, "{compared}");
    assert!(max.iter().all(|&e| e <= 1e-9), "{max:?}");
}

/// `∫ r(z) dz` of a linear radius between `z0` and `z1`.
fn linear_integral(r: impl Fn(f64) -> f64, z0: f64, z1: f64) -> f64 {
    0.5 * (r(z0) + r(z1)) * (z1 - z0)
}

#[test]
fn coaxial_stacks_have_the_closed_form_depth_normal_points_and_area() {
    // b stands on a's top cap, sunk by δ, coaxial: by symmetry the normal is −z (b pushes a
    // down), the points are on the axis at a's top and b's bottom, the depth δ; the area
    // |S_a| is a's top cap less the axial part of a's lateral surface inside b (where a's
    // radius is below b's): π r_a(L)² − 2π k_a ∫ r_a dz.
    let cases = [
        ((1.0, 0.6, 2.0), (0.9, 0.3, 1.0), 0.05),
        ((0.5, 0.5, 1.0), (0.8, 0.2, 0.7), 0.3),
        ((0.2, 0.7, 1.5), (1.0, 1.0, 0.5), 0.4),
    ];
    for ((r0a, r1a, la), (r0b, r1b, lb), delta) in cases {
        let pose_a = Isometry3::new(Vector3::new(0.3, -0.2, 0.1), Vector3::new(0.2, 0.4, -0.3));
        let pose_b = pose_a * Isometry3::translation(0.0, 0.0, la - delta);
        let a = instance(frustum(r0a, r1a, la));
        let b = instance(frustum(r0b, r1b, lb));
        let c = one(&a, &b, &pose_a, &pose_b);
        let k = (r1a - r0a) / la;
        let ra = |z: f64| r0a + k * z;
        let rb = |z: f64| r0b + (r1b - r0b) / lb * (z - (la - delta));
        assert!(ra(la) <= rb(la) && ra(la - delta) <= rb(la - delta));
        let area = PI * (ra(la) * ra(la) - 2.0 * k * linear_integral(ra, la - delta, la));
        let up = pose_a.rotation * Vector3::z();
        let size = la.max(lb).max(r0a).max(r1a).max(r0b).max(r1b);
        assert!((c.penetration - delta).abs() <= 1e-12 * size, "{c:?}");
        assert!((c.normal_w + up).norm() <= 1e-12, "{c:?}");
        assert!((c.point_i_w - pose_a * nalgebra::Point3::new(0.0, 0.0, la)).norm() <= 1e-12);
        assert!(
            (c.point_j_w - pose_a * nalgebra::Point3::new(0.0, 0.0, la - delta)).norm() <= 1e-12
        );
        assert!(
            (c.area - area).abs() <= 1e-11 * size * size,
            "{} vs {area}",
            c.area
        );
    }
}

#[test]
fn touching_and_apart_are_no_contact() {
    let a = instance(frustum(1.0, 0.6, 2.0));
    let b = instance(frustum(0.9, 0.3, 1.0));
    let pose_a = Isometry3::identity();
    for gap in [0.0, 1e-9, 0.5] {
        let pose_b = Isometry3::translation(0.0, 0.0, 2.0 + gap);
        assert!(query(&a, &b, &pose_a, &pose_b).is_empty(), "{gap}");
    }
    // Side by side, the lateral surfaces touching along a generator of parallel cylinders.
    let c = instance(cylinder(0.5, 1.0));
    let f = instance(frustum(0.5, 0.5, 1.0));
    assert!(query(&c, &f, &pose_a, &Isometry3::translation(1.0, 0.0, 0.0)).is_empty());
}

#[test]
fn one_inside_the_other_takes_the_nearest_face_normal() {
    // A small cone inside a large frustum, nearest a's... the container's top cap: the
    // normal pushes the inner solid out through it.
    let big = instance(frustum(2.0, 1.8, 3.0));
    let small = instance(frustum(0.3, 0.0, 0.5));
    let pose_big = Isometry3::identity();
    let pose_small = Isometry3::translation(0.1, 0.0, 2.2);
    let c = one(&small, &big, &pose_small, &pose_big);
    assert!((c.normal_w - Vector3::z()).norm() < 1e-12, "{c:?}");
    assert!(c.penetration.is_finite() && c.area > 0.0);
    // The other order: the container is I, pushed down (against the inner solid's way out).
    let d = one(&big, &small, &pose_big, &pose_small);
    assert!((d.normal_w + Vector3::z()).norm() < 1e-12, "{d:?}");
}

#[test]
fn identical_solids_give_a_finite_contact() {
    for (i, j) in [
        (
            instance(frustum(1.0, 0.4, 1.5)),
            instance(frustum(1.0, 0.4, 1.5)),
        ),
        (
            instance(cylinder(0.7, 1.2)),
            instance(frustum(0.7, 0.7, 1.2)),
        ),
    ] {
        let pose = Isometry3::new(Vector3::new(1.0, 2.0, 3.0), Vector3::new(0.3, 0.2, 0.1));
        let c = one(&i, &j, &pose, &pose);
        assert!(c.penetration > 0.0 && c.penetration.is_finite(), "{c:?}");
        assert!(
            (c.normal_w.norm() - 1.0).abs() < 1e-12 && c.area > 0.0,
            "{c:?}"
        );
    }
}

#[test]
fn perpendicular_and_near_parallel_axes_at_extreme_scales_stay_finite() {
    for scale in [1e-6, 1.0, 1e6] {
        let a = instance(frustum(0.6 * scale, 0.3 * scale, 1.0 * scale));
        let b = instance(cylinder(0.2 * scale, 2.0 * scale));
        let pose_a = Isometry3::identity();
        for turn in [0.5 * PI, 1e-9] {
            let pose_b = Isometry3::from_parts(
                Translation3::new(0.1 * scale, -scale, 0.5 * scale),
                UnitQuaternion::from_axis_angle(&Vector3::x_axis(), -turn),
            );
            let c = query(&a, &b, &pose_a, &pose_b);
            if turn > 1.0 {
                assert_eq!(c.len(), 1, "{scale} {turn}: {c:?}");
            }
        }
    }
}

#[test]
fn a_grazing_coaxial_stack_has_the_depth_it_is_sunk_by() {
    // The intersection a disc-like sliver δ thick: found by the extent search, depth δ.
    let a = instance(frustum(1.0, 0.6, 2.0));
    let b = instance(frustum(0.9, 0.3, 1.0));
    for delta in [1e-4, 1e-7] {
        let c = one(
            &a,
            &b,
            &Isometry3::identity(),
            &Isometry3::translation(0.0, 0.0, 2.0 - delta),
        );
        assert!((c.penetration - delta).abs() <= 1e-12, "{delta}: {c:?}");
        assert!((c.normal_w + Vector3::z()).norm() <= 1e-9, "{delta}: {c:?}");
    }
}

#[test]
fn a_rod_through_a_disc_follows_the_cylinder_pairs_fallback() {
    // The rod crosses both caps of the disc: the rod's surface inside is a band whose area
    // vector vanishes, so the normal and area are the containment fallback's, which depends
    // on which solid the kernel slices along (the cylinder of a cylinder–frustum pair; I of a
    // frustum pair, as I of the cylinder pair): the same as the cylinder pair's either way.
    let pose_rod = Isometry3::new(Vector3::new(0.1, -0.05, -1.5), Vector3::new(0.2, -0.1, 0.0));
    let pose_disc = Isometry3::translation(0.0, 0.0, -0.2);
    let (rod, disc) = (
        instance(cylinder(0.3, 3.0)),
        instance(frustum(1.0, 1.0, 0.4)),
    );
    let disc_cylinder = instance(cylinder(1.0, 0.4));
    let rod_frustum = instance(frustum(0.3, 0.3, 3.0));
    for (got, want) in [
        (
            one(&rod, &disc, &pose_rod, &pose_disc),
            one(&rod, &disc_cylinder, &pose_rod, &pose_disc),
        ),
        (
            one(&disc, &rod_frustum, &pose_disc, &pose_rod),
            one(&disc_cylinder, &rod, &pose_disc, &pose_rod),
        ),
    ] {
        let e = errors(&got, &want, 3.0);
        assert!(e.iter().all(|&x| x <= 1e-9), "{e:?}\n{got:?}\n{want:?}");
    }
}

/// A frustum (or cone) against a frustum or a cylinder, general poses, a quarter coaxial.
pub(crate) fn scene(rng: &mut Rng, s: f64) -> Scene {
    let (r0a, r1a, la) = (
        rng.uniform(0.0, 1.2),
        rng.uniform(0.3, 1.2),
        rng.uniform(0.4, 2.0),
    );
    let (r0b, r1b, lb) = (
        rng.uniform(0.3, 1.2),
        rng.uniform(0.0, 1.2),
        rng.uniform(0.4, 2.0),
    );
    let pose_j = rng.pose(3.0);
    let coaxial = rng.uniform(0.0, 1.0) < 0.25;
    let turn = if coaxial {
        nalgebra::UnitQuaternion::identity()
    } else {
        rng.rotation()
    };
    let offset = if coaxial {
        Vector3::z() * rng.uniform(-0.8 * la, 0.8 * lb)
    } else {
        rng.unit_vector() * rng.uniform(0.0, 0.5 * (r0a + r1b + la + lb))
    };
    let pose_i = pose_j * Isometry3::from_parts(Translation3::from(offset), turn);
    let j = if rng.uniform(0.0, 1.0) < 0.3 {
        Geometry::Cylinder(Cylinder::new(r0b.max(r1b) * s, lb * s).unwrap())
    } else {
        Geometry::Frustum(Frustum::new(r0b * s, r1b * s, lb * s).unwrap())
    };
    Scene {
        i: instance(Geometry::Frustum(
            Frustum::new(r0a * s, r1a * s, la * s).unwrap(),
        )),
        j: instance(j),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: r0a.max(r1a).max(la).max(r0b).max(r1b).max(lb) * s,
    }
}
