//! General ellipsoids against frustums (and cones): the oracles the characterization rows use,
//! written without the engine's planar sections, and the degenerate branches (touching,
//! grazing, containment both ways, coincident axes and centres, parallel and perpendicular
//! axes, a cone's apex inside the ellipsoid).
//!
//! - [`coaxial_frustum`]: an ellipsoid of revolution (a sphere included) on the frustum's
//!   axis: the sections are concentric discs, so the volume and its first moment are 1-D
//!   integrals of `π min(ρ_e, r)²`, polynomials of degree ≤ 3 between the heights where the
//!   two radii cross (a quadratic's roots), integrated exactly by Gauss–Legendre; the
//!   ellipsoid's surface inside the frustum is a set of bands whose area vector is
//!   `π(ρ_e(z₁)² − ρ_e(z₂)²) e_z` each.
//! - [`moments_in_cone`]: an ellipsoid across a cone's side (no cap inside it) by the
//!   divergence theorem about the apex, where the cone's surface carries no flux of `x`: the
//!   ellipsoid's own patch, in geodesic polar coordinates on its unit sphere
//!   ([`crate::spherical_reference::patch_terms`]).
//! - [`frustum_exit`]: where a ray leaves the frustum (the caps, then the side by bisection).

use crate::common::{Rng, instance, one, query};
use crate::ellipsoid_oracles::Moments;
use crate::properties::{
    Maker, Scene, check_motion, check_scale, check_swap, ellipsoid_near, general_ellipsoid,
    random_axes, scaled_pose,
};
use crate::spherical_reference;
use contact_core::geometry::{Cylinder, Ellipsoid, Frustum};
use contact_core::{
    Contact, Geometry, GeometryInstance, Isometry3, Point3, UnitQuaternion, Vector3,
};
use nalgebra::{Matrix3, Translation3};
use std::f64::consts::PI;

/// Where the ray from `g` (inside) along `d` leaves the frustum of radii `r0` (at `z = 0`),
/// `r1` (at `z = len`): the caps' planes, then the side by bisection on
/// `h(s) = r(z(s)) − |xy(s)|`, concave along the ray (linear less convex) and positive at `g`,
/// so the points of the ray inside the cone are one interval from `g` (on the axis through a
/// cone's apex `h` is linear and the bisection lands on the apex to round-off, where the
/// cone's quadratic has a double root).
pub fn frustum_exit(r0: f64, r1: f64, len: f64, g: &Point3, d: &Vector3) -> Point3 {
    let k = (r1 - r0) / len;
    let reach = 4.0 * (r0.max(r1) + len);
    let mut s = reach;
    if d.z > 0.0 {
        s = s.min((len - g.z) / d.z);
    } else if d.z < 0.0 {
        s = s.min(-g.z / d.z);
    }
    let h = |s: f64| {
        let p = g + d * s;
        r0 + k * p.z - p.coords.xy().norm()
    };
    if h(s) < 0.0 {
        let (mut inside, mut outside) = (0.0, s);
        for _ in 0..200 {
            let mid = 0.5 * (inside + outside);
            if mid <= inside || mid >= outside {
                break;
            }
            if h(mid) >= 0.0 {
                inside = mid;
            } else {
                outside = mid;
            }
        }
        s = 0.5 * (inside + outside);
    }
    g + d * s.max(0.0)
}

/// Gauss–Legendre nodes and weights on `[0, 1]` (`n` nodes).
pub fn gauss(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut z = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut slope = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, z);
                for k in 2..=n {
                    let k = k as f64;
                    (p0, p1) = (p1, ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k);
                }
                slope = n as f64 * (z * p1 - p0) / (z * z - 1.0);
                let step = p1 / slope;
                z -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            (0.5 * (1.0 + z), 1.0 / ((1.0 - z * z) * slope * slope))
        })
        .collect()
}

/// The ellipsoid of revolution with equatorial radius `a` and polar semi-axis `c`, centred
/// at height `zc` on the axis of the frustum (`r0`, `r1`, `len`): its moments (I the
/// ellipsoid), `None` when they do not overlap.
pub fn coaxial_frustum(a: f64, c: f64, zc: f64, r0: f64, r1: f64, len: f64) -> Option<Moments> {
    let k = (r1 - r0) / len;
    let (lo, hi) = ((zc - c).max(0.0), (zc + c).min(len));
    if lo >= hi {
        return None;
    }
    let rho2 = |z: f64| a * a * (1.0 - ((z - zc) / c).powi(2));
    let r = |z: f64| r0 + k * z;
    // ρ_e² = r²: a²(1 − (z − zc)²/c²) = (r0 + k z)², a quadratic A z² + B z + C = 0.
    let (aa, bb, cc) = (
        -a * a / (c * c) - k * k,
        2.0 * a * a * zc / (c * c) - 2.0 * r0 * k,
        a * a * (1.0 - zc * zc / (c * c)) - r0 * r0,
    );
    let mut cuts = vec![lo, hi];
    let disc = bb * bb - 4.0 * aa * cc;
    if disc > 0.0 {
        for z in [
            (-bb + disc.sqrt()) / (2.0 * aa),
            (-bb - disc.sqrt()) / (2.0 * aa),
        ] {
            if z > lo && z < hi {
                cuts.push(z);
            }
        }
    }
    cuts.sort_by(f64::total_cmp);
    let rule = gauss(8);
    let (mut volume, mut first, mut s_z) = (0.0, 0.0, 0.0);
    for w in cuts.windows(2) {
        let (z0, z1) = (w[0], w[1]);
        let mid = 0.5 * (z0 + z1);
        let ellipsoid_inside = rho2(mid) < r(mid).powi(2);
        for &(x, weight) in &rule {
            let z = z0 + (z1 - z0) * x;
            let area = PI * rho2(z).min(r(z).powi(2)).max(0.0);
            volume += weight * (z1 - z0) * area;
            first += weight * (z1 - z0) * z * area;
        }
        if ellipsoid_inside {
            s_z += PI * (rho2(z0).max(0.0) - rho2(z1).max(0.0));
        }
    }
    (volume > 0.0).then(|| Moments {
        volume,
        centroid: Point3::new(0.0, 0.0, first / volume),
        area_vector_i: Vector3::z() * s_z,
    })
}

/// The moments of `I ∩ J` for an ellipsoid `I` and a solid `J` whose surface inside `I` is
/// part of a cone with its apex at `apex` (a frustum's side; no cap inside `I`): on such a
/// surface `(x − apex)·n = 0`, so with the apex as origin only `I`'s patch (where `margin_j`,
/// positive inside `J`, is positive) carries `⅓∮x·n dA` and `¼∮x (x·n) dA`. On `n` rays;
/// `None` when the patch is empty.
pub fn moments_in_cone(
    i: &spherical_reference::Ellipsoid,
    margin_j: &dyn Fn(&Vector3) -> f64,
    apex: &Vector3,
    n: usize,
) -> Option<Moments> {
    let shifted = spherical_reference::Ellipsoid {
        c: i.c - apex,
        l: i.l,
    };
    let (xn, xxn, s) =
        crate::spherical_reference::patch_terms(&shifted, &|x| margin_j(&(x + apex)), n)?;
    let volume = xn / 3.0;
    Some(Moments {
        volume,
        centroid: Point3::from(xxn / 4.0 / volume + apex),
        area_vector_i: s,
    })
}

/// [`moments_in_cone`] on 512 rays, with its error measured against 256 rays.
pub fn converged_in_cone(
    i: &spherical_reference::Ellipsoid,
    margin_j: &dyn Fn(&Vector3) -> f64,
    apex: &Vector3,
) -> Option<(Moments, f64)> {
    let coarse = moments_in_cone(i, margin_j, apex, 256)?;
    let fine = moments_in_cone(i, margin_j, apex, 512)?;
    let error = (fine.volume - coarse.volume)
        .abs()
        .max((fine.centroid - coarse.centroid).norm())
        .max((fine.area_vector_i - coarse.area_vector_i).norm());
    Some((fine, error))
}

fn ellipsoid(a: f64, b: f64, c: f64) -> GeometryInstance {
    instance(Geometry::Ellipsoid(Ellipsoid::new(a, b, c).unwrap()))
}

fn frustum(r0: f64, r1: f64, len: f64) -> GeometryInstance {
    instance(Geometry::Frustum(Frustum::new(r0, r1, len).unwrap()))
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
            .all(|v| v.is_finite()),
        "{c:?}"
    );
}

#[test]
fn the_coaxial_oracle_reproduces_a_ball_in_a_cylinder_and_a_cap() {
    // A unit ball centred on the top cap of a wide cylinder: half the ball.
    let m = coaxial_frustum(1.0, 1.0, 2.0, 3.0, 3.0, 2.0).unwrap();
    assert!((m.volume - 2.0 * PI / 3.0).abs() < 1e-14);
    assert!((m.centroid.z - (2.0 - 3.0 / 8.0)).abs() < 1e-14);
    assert!((m.area_vector_i.z + PI).abs() < 1e-14);
    // A unit ball in a cone of half-angle 45° with its apex at the centre: a spherical
    // sector of half-angle π/4, volume (2π/3)(1 − cos π/4).
    let m = coaxial_frustum(1.0, 1.0, 0.0, 0.0, 2.0, 2.0).unwrap();
    let expected = 2.0 * PI / 3.0 * (1.0 - 0.5f64.sqrt());
    assert!(
        (m.volume - expected).abs() < 1e-14,
        "{} vs {expected}",
        m.volume
    );
}

#[test]
fn touching_is_no_contact_and_grazing_matches_the_oracles() {
    use crate::common::errors;
    use crate::ellipsoid_oracles::{contact_from, ellipsoid_cap, ellipsoid_exit};
    let semi = Vector3::new(0.5, 0.4, 0.3);
    let e = ellipsoid(semi.x, semi.y, semi.z);
    let (r0, r1, len) = (1.0, 0.6, 2.0);
    let f = frustum(r0, r1, len);
    let q = UnitQuaternion::from_euler_angles(0.2, -0.4, 0.7);
    let l = q.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
    let reach = (l.transpose() * Vector3::z()).norm();
    // On the top cap: the affine spherical cap.
    let centre = |z: f64| Vector3::new(0.1, -0.1, z);
    let at = |z: f64| Isometry3::from_parts(Translation3::from(centre(z)), q);
    assert!(query(&e, &f, &at(len + reach), &Isometry3::identity()).is_empty());
    assert!(
        query(
            &e,
            &f,
            &at(len + reach * (1.0 + 1e-9)),
            &Isometry3::identity()
        )
        .is_empty()
    );
    for depth in [1e-3, 1e-6, 1e-9] {
        let c = centre(len + reach - depth);
        let got = one(&e, &f, &at(len + reach - depth), &Isometry3::identity());
        well_formed(&got);
        let expected = contact_from(
            &ellipsoid_cap(&c, &l, &Vector3::z(), len),
            |g, d| ellipsoid_exit(&c, &l, g, d),
            |g, d| frustum_exit(r0, r1, len, g, d),
        );
        let err = errors(&got, &expected, len);
        assert!(
            err.iter().all(|&x| x < 1e-9),
            "cap {depth:e}: {err:?} {got:?}"
        );
    }
    // On the slanted side, along the side's outward normal from its middle: the divergence
    // theorem about the apex.
    let k = (r1 - r0) / len;
    let apex = Vector3::new(0.0, 0.0, -r0 / k);
    let outward = Vector3::new(1.0, 0.0, -k).normalize();
    let foot = Vector3::new(r0 + k, 0.0, 1.0);
    let turned = UnitQuaternion::rotation_between(&Vector3::z(), &outward).unwrap() * q;
    let l = turned.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
    // The centre that puts the ellipsoid's support point along −n on the foot.
    let support = l * (l.transpose() * outward) / (l.transpose() * outward).norm();
    let pose = |c: &Vector3| Isometry3::from_parts(Translation3::from(*c), turned);
    for gap in [0.0, 1e-9] {
        let c = foot + support + outward * gap;
        assert!(
            query(&e, &f, &pose(&c), &Isometry3::identity()).is_empty(),
            "{gap}"
        );
    }
    for depth in [1e-3, 1e-6, 1e-9] {
        let c = foot + support - outward * depth;
        let found = query(&e, &f, &pose(&c), &Isometry3::identity());
        // A lens 1e-9 thin between two curved surfaces has sections whose overlaps are at
        // round-off: touching within round-off, no contact (`volume_contact::unresolved_lens`),
        // or a shallow one.
        if depth < 1e-8 && found.is_empty() {
            continue;
        }
        assert_eq!(found.len(), 1, "side {depth:e}");
        let got = found[0];
        well_formed(&got);
        // The oracle's rays are sampled 192 times over a half circle: it resolves a patch of
        // 1e-3 of the size, not the thinner ones, which are held to their shape only.
        if depth < 1e-3 {
            assert!(
                got.penetration <= depth * (1.0 + 1e-6) && got.penetration >= 0.5 * depth,
                "side {depth:e}: {got:?}"
            );
            assert!(
                (got.normal_w - outward).norm() < 1e-3,
                "side {depth:e}: {got:?}"
            );
            continue;
        }
        let margin = move |x: &Vector3| (r0 + k * x.z) - x.xy().norm();
        let i = spherical_reference::Ellipsoid { c, l };
        let (moments, error) = converged_in_cone(&i, &margin, &apex).unwrap();
        assert!(error < 1e-11, "{error:e}");
        let expected = contact_from(
            &moments,
            |g, d| ellipsoid_exit(&c, &l, g, d),
            |g, d| frustum_exit(r0, r1, len, g, d),
        );
        let err = errors(&got, &expected, len);
        assert!(
            err.iter().all(|&x| x < 1e-9),
            "side {depth:e}: {err:?} {got:?}"
        );
    }
}

#[test]
fn containment_either_way_has_a_finite_contact_with_the_documented_normal() {
    // The ellipsoid inside the frustum, nearest the top cap: the frustum's outward normal
    // there (from J into I).
    let small = ellipsoid(0.2, 0.15, 0.1);
    let f = frustum(1.5, 1.0, 2.0);
    let inner = Isometry3::from_parts(
        Translation3::new(0.1, 0.05, 1.7),
        UnitQuaternion::from_euler_angles(0.3, 0.2, 0.1),
    );
    let c = one(&small, &f, &inner, &Isometry3::identity());
    well_formed(&c);
    assert!((c.normal_w - Vector3::z()).norm() < 1e-12, "{c:?}");
    // The swapped order gives the swapped contact.
    let back = one(&f, &small, &Isometry3::identity(), &inner);
    assert!((back.normal_w + c.normal_w).norm() < 1e-12);
    // A frustum (and a cone) inside a large ellipsoid: against the level surface's normal.
    // The centroid is the solid's (height z̄ = L(r₀² + 2r₀r₁ + 3r₁²)/(4(r₀² + r₀r₁ + r₁²))).
    let semi = Vector3::new(5.0, 4.0, 6.0);
    let huge = ellipsoid(semi.x, semi.y, semi.z);
    for (r0, r1) in [(1.0, 0.5), (0.0, 1.0), (1.0, 0.0)] {
        let pose = Isometry3::translation(0.3, 0.2, 0.1);
        let c = one(&huge, &frustum(r0, r1, 1.0), &pose, &Isometry3::identity());
        well_formed(&c);
        let z = (r0 * r0 + 2.0 * r0 * r1 + 3.0 * r1 * r1) / (4.0 * (r0 * r0 + r0 * r1 + r1 * r1));
        let p = Vector3::new(-0.3, -0.2, z - 0.1);
        let expected = -p.component_div(&semi.component_mul(&semi)).normalize();
        assert!((c.normal_w - expected).norm() < 1e-9, "{c:?}");
    }
}

#[test]
fn coincident_axes_and_centres_parallel_and_perpendicular_axes_are_finite() {
    let f = frustum(1.0, 0.4, 2.0);
    let cone = frustum(0.0, 1.0, 1.5);
    // Coaxial, centred at the frustum's middle: the area vector is along the axis (or
    // vanishes for a symmetric overlap).
    for e in [
        ellipsoid(0.6, 0.6, 1.5),
        ellipsoid(1.5, 1.5, 0.4),
        ellipsoid(0.7, 0.5, 0.9),
    ] {
        for j in [&f, &cone] {
            for pose in [
                Isometry3::translation(0.0, 0.0, 1.0),
                Isometry3::translation(0.0, 0.0, 0.0),
                Isometry3::from_parts(
                    Translation3::new(0.0, 0.0, 0.75),
                    UnitQuaternion::from_euler_angles(std::f64::consts::FRAC_PI_2, 0.0, 0.0),
                ),
                Isometry3::from_parts(
                    Translation3::new(0.3, 0.0, 0.75),
                    UnitQuaternion::from_euler_angles(0.0, std::f64::consts::FRAC_PI_2, 0.0),
                ),
            ] {
                for c in query(&e, j, &pose, &Isometry3::identity()) {
                    well_formed(&c);
                }
            }
        }
    }
    // A cone's apex inside a small ellipsoid, on and off the axis.
    let e = ellipsoid(0.3, 0.2, 0.25);
    for x in [0.0, 0.1] {
        let c = one(
            &e,
            &cone,
            &Isometry3::translation(x, 0.0, 0.05),
            &Isometry3::identity(),
        );
        well_formed(&c);
        // The ellipsoid's upper surface is inside the cone: it is pushed down, off the apex.
        assert!(c.normal_w.z < 0.0, "{c:?}");
    }
}

#[test]
fn a_frustum_of_equal_radii_is_the_cylinder() {
    // The same solid two ways: the frustum slicing (convex gap bisected for the extent) and
    // the cylinder's (the pencil's extent).
    let e = ellipsoid(0.9, 0.5, 0.35);
    let (r, len) = (0.8, 1.5);
    let mut rng = crate::common::Rng::new(0xF0_5E);
    let mut seen = 0;
    for _ in 0..40 {
        let pose = Isometry3::from_parts(
            Translation3::from(
                Vector3::new(0.0, 0.0, 0.75) + rng.unit_vector() * rng.uniform(0.0, 1.8),
            ),
            rng.rotation(),
        );
        let a = query(&e, &frustum(r, r, len), &pose, &Isometry3::identity());
        let b = query(
            &e,
            &instance(Geometry::Cylinder(Cylinder::new(r, len).unwrap())),
            &pose,
            &Isometry3::identity(),
        );
        assert_eq!(a.len(), b.len(), "{pose:?}");
        for (x, y) in a.iter().zip(&b) {
            crate::common::assert_close(x, y, 2.0, 4.0, 1e-10, "frustum(r, r) vs cylinder");
            seen += 1;
        }
    }
    assert!(seen > 20, "{seen}");
}

fn ellipsoid_frustum(rng: &mut Rng, s: f64) -> Scene {
    let a = random_axes(rng);
    // A cone one time in four (either end).
    let (mut r0, mut r1) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 1.5));
    match rng.next_u64() % 8 {
        0 => r0 = 0.0,
        1 => r1 = 0.0,
        _ => {}
    }
    let len = rng.uniform(0.3, 2.0);
    let pose_j = rng.pose(3.0);
    let frame = pose_j * Isometry3::translation(0.0, 0.0, 0.5 * len);
    let pose_i = ellipsoid_near(rng, &frame, 0.8 * (a.max() + r0.max(r1) + 0.5 * len));
    Scene {
        i: general_ellipsoid(&a, s),
        j: instance(Geometry::Frustum(
            Frustum::new(r0 * s, r1 * s, len * s).unwrap(),
        )),
        pose_i: scaled_pose(&pose_i, s),
        pose_j: scaled_pose(&pose_j, s),
        length: (a.max() + r0.max(r1) + len) * s,
    }
}

const MAKERS: [(&str, Maker); 1] = [("ellipsoid–frustum", ellipsoid_frustum)];

#[test]
fn exchanging_i_and_j_gives_the_swapped_contact() {
    check_swap(&MAKERS, 41);
}

#[test]
fn a_rigid_motion_of_both_bodies_moves_the_contact() {
    check_motion(&MAKERS, 42);
}

#[test]
fn scaling_the_scene_scales_depth_and_points() {
    check_scale(&MAKERS, 43);
}
