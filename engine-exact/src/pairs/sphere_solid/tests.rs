//! The fast path against the general path (the sphere as an ellipsoid of equal semi-axes):
//! wherever the fast path fires the two agree to round-off, and it declines where the region
//! is not symmetric about the line through the centre along the normal.

use super::fast_path::fast_path;
use super::{Solid, general};
use crate::kernel::PairContact;
use crate::test_rng::Rng;
use contact_core::geometry::{Cuboid, Cylinder, Frustum, Torus};
use contact_core::{Isometry3, UnitQuaternion, Vector3, WorkCounters};

fn solids() -> [(Solid, f64); 4] {
    [
        (
            Solid::Box(Cuboid::centered(0.9, 0.6, 0.4).unwrap()),
            0.9f64.hypot(0.6).hypot(0.4),
        ),
        (Solid::Cylinder(Cylinder::new(0.7, 1.6).unwrap()), 1.6),
        (Solid::Frustum(Frustum::new(0.9, 0.4, 1.4).unwrap()), 1.4),
        (Solid::Torus(Torus::new(1.0, 0.3).unwrap()), 1.3),
    ]
}

fn general_one(
    r: f64,
    pose_sphere: &Isometry3,
    solid: &Solid,
    pose_solid: &Isometry3,
) -> Vec<PairContact> {
    let mut found = Vec::new();
    let mut work = WorkCounters::default();
    general(r, pose_sphere, solid, pose_solid, &mut work, &mut |c| {
        found.push(c)
    });
    found
}

/// Random centres about each solid (in its frame, then a random world frame): where the fast
/// path fires, its depth, normal, points and area equal the general path's to 1e-12 of the
/// pair's size.
#[test]
fn fast_path_equals_the_general_path() {
    let mut rng = Rng(0x5_F1E7);
    let mut fired = [0usize; 4];
    let mut worst = [0.0f64; 4];
    for (index, (solid, size)) in solids().iter().enumerate() {
        let mut tries = 0;
        while fired[index] < 40 && tries < 20_000 {
            tries += 1;
            let r = rng.uniform(0.05, 0.5);
            let c = match solid {
                Solid::Box(_) => Vector3::new(
                    rng.uniform(-1.4, 1.4),
                    rng.uniform(-1.1, 1.1),
                    rng.uniform(-0.9, 0.9),
                ),
                _ => Vector3::new(
                    rng.uniform(-1.4, 1.4),
                    rng.uniform(-1.4, 1.4),
                    rng.uniform(-0.5, 2.0),
                ),
            };
            let Some(local) = fast_path(r, &c, solid) else {
                continue;
            };
            let world = Isometry3::from_parts(
                (rng.unit() * rng.uniform(0.0, 3.0)).into(),
                UnitQuaternion::from_scaled_axis(rng.unit() * rng.uniform(0.0, 3.0)),
            );
            let pose_sphere = world
                * Isometry3::from_parts(
                    c.into(),
                    UnitQuaternion::from_scaled_axis(rng.unit() * rng.uniform(0.0, 3.0)),
                );
            let fast = local.to_world(r, &pose_sphere, &world);
            let slow = general_one(r, &pose_sphere, solid, &world);
            assert_eq!(slow.len(), 1, "{solid:?} r = {r} c = {c:?}");
            let e = fast.errors(&slow[0], *size);
            for k in 0..4 {
                worst[k] = worst[k].max(e[k]);
            }
            assert!(
                e.iter().all(|&x| x <= 1e-12),
                "{solid:?} r = {r} c = {c:?}: {e:?}\nfast {fast:?}\ngeneral {:?}",
                slow[0]
            );
            fired[index] += 1;
        }
    }
    println!("fast vs general, worst [depth, normal, points, area]: {worst:?}, fired {fired:?}");
    assert!(fired[..3].iter().all(|&n| n == 40), "{fired:?}");
    assert_eq!(fired[3], 0, "a torus has no fast path");
}

/// The fast path declines at an edge, a rim and a corner in reach, with the ball reaching two
/// faces from inside, for containment, on a frustum's side, on the axis, and on a torus.
#[test]
fn fast_path_declines_off_symmetry() {
    let [(cuboid, _), (cylinder, _), (frustum, _), (torus, _)] = solids();
    let declines = [
        // Box (half-extents 0.9, 0.6, 0.4): over the +z face near the +x edge; an edge; a
        // corner; inside reaching +z and +x; inside reaching nothing.
        (cuboid, 0.3, Vector3::new(0.8, 0.0, 0.5)),
        (cuboid, 0.3, Vector3::new(1.0, 0.0, 0.5)),
        (cuboid, 0.3, Vector3::new(1.0, 0.7, 0.5)),
        (cuboid, 0.3, Vector3::new(0.75, 0.0, 0.3)),
        (cuboid, 0.1, Vector3::new(0.0, 0.0, 0.0)),
        // Cylinder (R 0.7, L 1.6): beside the side near the top rim; over the cap near the
        // rim; on the axis; a ball wrapping past a quarter turn.
        (cylinder, 0.3, Vector3::new(0.8, 0.0, 1.5)),
        (cylinder, 0.3, Vector3::new(0.5, 0.0, 1.7)),
        (cylinder, 0.3, Vector3::new(0.0, 0.0, 0.8)),
        (cylinder, 0.75, Vector3::new(0.0, 0.2, 0.8)),
        // Frustum: beside the slanted side.
        (frustum, 0.2, Vector3::new(0.75, 0.0, 0.7)),
        // Torus: on the outer equator, and on top of the tube.
        (torus, 0.2, Vector3::new(1.4, 0.0, 0.0)),
        (torus, 0.2, Vector3::new(1.0, 0.0, 0.4)),
    ];
    for (solid, r, c) in declines {
        assert!(
            fast_path(r, &c, &solid).is_none(),
            "{solid:?} r = {r} c = {c:?}"
        );
    }
    // And fires just clear of those: over the face's middle, beside the side's middle, over
    // a cap's middle, and over a frustum's caps.
    let fires = [
        (cuboid, 0.3, Vector3::new(0.2, 0.0, 0.5)),
        (cuboid, 0.3, Vector3::new(0.2, 0.0, 0.3)),
        (cylinder, 0.3, Vector3::new(0.8, 0.0, 0.8)),
        (cylinder, 0.3, Vector3::new(0.0, 0.2, 1.7)),
        (frustum, 0.2, Vector3::new(0.1, 0.0, 1.5)),
        (frustum, 0.2, Vector3::new(0.1, 0.0, -0.1)),
    ];
    for (solid, r, c) in fires {
        assert!(
            fast_path(r, &c, &solid).is_some(),
            "{solid:?} r = {r} c = {c:?}"
        );
    }
}

/// The side's area against a fine midpoint rule of its defining integral, over the arc.
#[test]
fn side_area_matches_its_integral() {
    for &(r, rho, radius) in &[
        (0.3, 0.9, 0.7),
        (0.3, 0.5, 0.7),
        (0.5, 0.3, 0.7),
        (0.05, 0.74, 0.7),
        (0.7, 0.9, 0.6),
    ] {
        let (a, b) = (r * r - radius * radius - rho * rho, 2.0 * radius * rho);
        let n = 2_000_000;
        let step = std::f64::consts::TAU / n as f64;
        let mut sum = 0.0;
        for j in 0..n {
            let phi = -std::f64::consts::PI + step * (j as f64 + 0.5);
            let v = a + b * phi.cos();
            if v > 0.0 {
                sum += phi.cos() * 2.0 * v.sqrt();
            }
        }
        let want = radius * sum * step;
        let got = super::fast_path::side_area(r, rho, radius);
        assert!(
            (got - want).abs() <= 1e-7 * want,
            "r {r} ρ {rho} R {radius}: {got} vs {want}"
        );
    }
}

/// Far apart: no contact from either path; touching: none either.
#[test]
fn apart_and_touching() {
    for (solid, _) in solids() {
        let pose = Isometry3::translation(5.0, 0.0, 0.0);
        let mut found = 0;
        let mut work = WorkCounters::default();
        super::contacts(
            0.3,
            &pose,
            &solid,
            &Isometry3::identity(),
            &mut work,
            &mut |_| found += 1,
        );
        assert_eq!(found, 0);
    }
    // Binary fractions, so the gap is exactly zero.
    let cuboid = Solid::Box(Cuboid::centered(0.5, 0.5, 0.5).unwrap());
    let mut work = WorkCounters::default();
    for touching in [
        Isometry3::translation(0.0, 0.0, 0.75),
        Isometry3::translation(0.5, 0.5, 0.75),
    ] {
        let found = super::contact(0.25, &touching, &cuboid, &Isometry3::identity(), &mut work);
        assert!(found.is_none(), "{found:?}");
    }
}
