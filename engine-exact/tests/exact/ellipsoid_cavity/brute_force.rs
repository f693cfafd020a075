//! Balls at a cavity's rims, on a cone's slanted wall and against an ellipsoid cavity's
//! wall, both orders, against the brute-force oracle of `sphere_solid` with the cavity's
//! outside as the solid.

use super::ellipsoid;
use crate::common::{Rng, instance, query};
use crate::sphere_solid::{GRID, brute_force_moments, first_change, sphere_exit};
use contact_core::geometry::{Cylinder, Frustum, Torus};
use contact_core::{Geometry, GeometryInstance, Isometry3, Point3, Vector3};

/// SPEC §4's points for a region of the ball `(c, r)` outside a cavity (`in_hole` its inside
/// test), by marching: from a centroid in both bodies, the exits along `∓n`; from one in
/// the cavity, the nearer chord beside it whose middle lies in both.
fn brute_force_points(
    c: &Vector3,
    r: f64,
    in_hole: &dyn Fn(&Vector3) -> bool,
    g: &Vector3,
    n: &Vector3,
) -> (Vector3, Vector3) {
    let material = |p: &Vector3| !in_hole(p);
    if material(g) {
        return (sphere_exit(c, r, g, &-n), first_change(&material, g, n, r));
    }
    let mut best: Option<(f64, Vector3, Vector3)> = None;
    for side in [-1.0, 1.0] {
        let d = n * side;
        let pa = sphere_exit(c, r, g, &d);
        let pb = first_change(&material, g, &d, r);
        let middle = 0.5 * (pa + pb);
        if (pb - pa).dot(n) <= 0.0 || (middle - c).norm() >= r || !material(&middle) {
            continue;
        }
        let near = (pa - g).norm().min((pb - g).norm());
        if best.as_ref().is_none_or(|(x, _, _)| near < *x) {
            best = Some((near, pa, pb));
        }
    }
    let (_, pa, pb) = best.expect("a chord beside the centroid");
    (pa, pb)
}

/// The engine's answer for the ball `(c, r)` in `cavity` (flipped; `in_hole` its inside
/// test, own frame), both orders, seen from a random world frame, against the brute-force
/// oracle: returns the errors [normal, depth, points], each held to 2e-4.
fn against_brute_force(
    cavity: &GeometryInstance,
    in_hole: &dyn Fn(&Vector3) -> bool,
    r: f64,
    c: Vector3,
    rng: &mut Rng,
) -> [f64; 3] {
    let material = |p: &Vector3| !in_hole(p);
    let (s, g) = brute_force_moments(&c, r, &material, GRID);
    let n = -s.normalize();
    let (on_ball, on_cavity) = brute_force_points(&c, r, in_hole, &g, &n);
    let world = rng.pose(2.0);
    let pose_ball = world * Isometry3::from_parts(c.into(), rng.rotation());
    let ball = instance(Geometry::sphere(r).unwrap());
    let mut worst = [0.0f64; 3];
    for ball_is_i in [true, false] {
        let found = if ball_is_i {
            query(&ball, cavity, &pose_ball, &world)
        } else {
            query(cavity, &ball, &world, &pose_ball)
        };
        assert_eq!(found.len(), 1, "r = {r} c = {c:?}: {found:?}");
        let got = if ball_is_i {
            found[0]
        } else {
            found[0].swapped()
        };
        let e = [
            (got.normal_w - world.rotation * n).norm(),
            (got.penetration - (on_cavity - on_ball).norm()).abs(),
            (got.point_i_w - world * Point3::from(on_ball)).norm()
                + (got.point_j_w - world * Point3::from(on_cavity)).norm(),
        ];
        println!("ball r = {r} at {c:?}: [normal, depth, points] {e:?}");
        assert!(
            e.iter().all(|&x| x <= 2e-4),
            "r = {r} c = {c:?}: {e:?} {got:?}"
        );
        for k in 0..3 {
            worst[k] = worst[k].max(e[k]);
        }
    }
    worst
}

/// Balls at a bore's rim (pressed into the wall and through the end at once), near the
/// bottom rim, on a conical cavity's slanted wall and at its top rim, both orders, against
/// the brute-force oracle of `sphere_solid` with the cavity's outside as the solid (its
/// midpoint rules hold it to about 1e-5 of the size, so the engine is held to 2e-4).
#[test]
fn balls_at_a_cavitys_rims_and_slanted_wall_match_the_brute_force_oracle() {
    let mut rng = Rng::new(0xCA_5E);
    let cylinder = |p: &Vector3| p.xy().norm() <= 0.7 && p.z >= 0.0 && p.z <= 1.6;
    let cone = |p: &Vector3| p.z >= 0.0 && p.z <= 1.4 && p.xy().norm() <= 0.9 - 0.5 * p.z / 1.4;
    let bore_g = Geometry::Cylinder(Cylinder::new(0.7, 1.6).unwrap());
    let cone_g = Geometry::Frustum(Frustum::new(0.9, 0.4, 1.4).unwrap());
    type Case<'a> = (&'a Geometry, &'a dyn Fn(&Vector3) -> bool, f64, Vector3);
    let cases: [Case; 5] = [
        (&bore_g, &cylinder, 0.3, Vector3::new(0.6, 0.0, 1.65)),
        (&bore_g, &cylinder, 0.3, Vector3::new(0.45, 0.3, 0.1)),
        (&bore_g, &cylinder, 0.25, Vector3::new(-0.55, 0.1, 0.8)),
        (&cone_g, &cone, 0.2, Vector3::new(0.55, 0.0, 0.7)),
        (&cone_g, &cone, 0.25, Vector3::new(0.3, 0.3, 1.45)),
    ];
    let mut worst = [0.0f64; 3];
    for (geometry, in_hole, r, c) in cases {
        let cavity = instance(geometry.clone()).flipped();
        let e = against_brute_force(&cavity, in_hole, r, c, &mut rng);
        for k in 0..3 {
            worst[k] = worst[k].max(e[k]);
        }
    }
    println!("balls in cavities vs brute force, worst [normal, depth, points]: {worst:?}");
}

/// Balls against the wall of a general ellipsoid cavity (semi-axes 1, 0.7, 0.5), both
/// orders, against the brute-force oracle of `sphere_solid` with the cavity's outside as the
/// solid (held to 2e-4, as there).
#[test]
fn balls_in_an_ellipsoid_cavity_match_the_brute_force_oracle() {
    let mut rng = Rng::new(0xE111);
    let semi = Vector3::new(1.0, 0.7, 0.5);
    let in_hole = |p: &Vector3| p.component_div(&semi).norm_squared() <= 1.0;
    let cavity = ellipsoid(semi.x, semi.y, semi.z).flipped();
    let cases = [
        (0.25, Vector3::new(0.85, 0.0, 0.0)),
        (0.2, Vector3::new(0.3, 0.45, 0.2)),
        (0.3, Vector3::new(-0.4, -0.2, -0.35)),
    ];
    for (r, c) in cases {
        against_brute_force(&cavity, &in_hole, r, c, &mut rng);
    }
}

/// Balls in a torus' tube (R = 1, ρ = 0.3) off its symmetry planes, against the wall's
/// outer, inner and upper sides, both orders, against the brute-force oracle (2e-4).
#[test]
fn balls_in_a_toroidal_groove_match_the_brute_force_oracle() {
    let mut rng = Rng::new(0x70_7F);
    let in_hole = |p: &Vector3| {
        let rho = p.xy().norm() - 1.0;
        rho * rho + p.z * p.z <= 0.09
    };
    let cavity = instance(Geometry::Torus(Torus::new(1.0, 0.3).unwrap())).flipped();
    let cases = [
        (0.15, Vector3::new(1.16, 0.1, 0.06)),
        (0.2, Vector3::new(0.72, -0.3, -0.05)),
        (0.12, Vector3::new(-0.4, 0.9, 0.2)),
    ];
    for (r, c) in cases {
        against_brute_force(&cavity, &in_hole, r, c, &mut rng);
    }
}
