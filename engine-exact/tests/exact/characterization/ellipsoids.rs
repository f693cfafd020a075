//! Characterization rows of the general ellipsoid pairs (sliced quadrature in the engine),
//! against the oracles of [`crate::ellipsoid_oracles`] (affine lens, affine caps, the sphere
//! cross-check) and, for two ellipsoids in general poses, the spherical-polar reference of
//! [`crate::spherical_reference`] (converged to 1e-12, `S_I + S_J = 0` checked): all held
//! to the iterative bound 1e-9. The divergence-theorem oracle's general-pose rows are slow
//! unoptimized and run only on request (see [`general_rows`]).

use super::{Case, ITERATIVE_BOUND, Row, run};
use crate::common::{Expected, Rng, instance, one};
use crate::ellipsoid_oracles::{
    CapPatch, EllipsoidPatch, Moments, Patch, SidePatch, box_exit, box_faces, contact_from,
    cylinder_exit, ellipsoid_cap, ellipsoid_exit, ellipsoid_margin, lens_moments, mapped,
    surface_moments,
};
use crate::spherical_reference;
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid};
use contact_core::{Geometry, Isometry3, Point3, UnitQuaternion, Vector3};
use nalgebra::{Matrix3, Translation3};

/// Samples of the closed-form rows.
const CLOSED_SAMPLES: usize = 60;
/// Samples of the general-pose rows against the spherical-polar reference.
const SPHERICAL_SAMPLES: usize = 12;
/// Samples of the rows against the divergence-theorem oracle.
const SURFACE_SAMPLES: usize = 3;
/// The bound of the rows against the divergence-theorem oracle: the iterative bound.
const ORACLE_LIMITED_BOUND: f64 = ITERATIVE_BOUND;
/// The divergence-theorem oracle's absolute tolerance per surface (sizes about 1).
const SURFACE_TOL: f64 = 1e-11;

fn axes(rng: &mut Rng, lo: f64, hi: f64) -> Vector3 {
    Vector3::new(
        rng.uniform(lo, hi),
        rng.uniform(lo, hi),
        rng.uniform(lo, hi),
    )
}

fn matrix_of(semi: &Vector3, rotation: &UnitQuaternion) -> Matrix3<f64> {
    rotation.to_rotation_matrix().matrix() * Matrix3::from_diagonal(semi)
}

fn ellipsoid(semi: &Vector3) -> contact_core::GeometryInstance {
    instance(Geometry::Ellipsoid(
        Ellipsoid::new(semi.x, semi.y, semi.z).unwrap(),
    ))
}

fn pose(c: &Vector3, rotation: UnitQuaternion) -> Isometry3 {
    Isometry3::from_parts(Translation3::from(*c), rotation)
}

fn iterative(row: Row) -> Row {
    Row {
        bound: ITERATIVE_BOUND,
        ..row
    }
}

fn oracle_limited(row: Row) -> Row {
    Row {
        bound: ORACLE_LIMITED_BOUND,
        ..row
    }
}

/// An ellipsoid I `(c, L)` against J in J's frame: the expected contact from `moments`.
fn expected_ellipsoid_i(
    moments: &Moments,
    c: &Vector3,
    l: &Matrix3<f64>,
    exit_j: impl Fn(&Point3, &Vector3) -> Point3,
) -> Expected {
    contact_from(moments, |g, d| ellipsoid_exit(c, l, g, d), exit_j)
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let mut rows = ellipsoid_box_rows(rng);
    rows.extend(cylinder_and_sphere_rows(rng));
    rows
}

/// The rows of ellipsoid–ellipsoid, ellipsoid–box.
fn ellipsoid_box_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        iterative(run(
            rng,
            CLOSED_SAMPLES,
            "ellipsoid–ellipsoid",
            "M·(two spheres), M = R·diag(0.4..2)·Rᵀ, radii ∈ [0.3, 1.5], lens (no containment)",
            "sliced quadrature",
            |rng| {
                let (r1, r2) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 1.5));
                let d = rng.uniform((r1 - r2).abs() + 0.02, r1 + r2 - 0.02);
                let c1 = Vector3::zeros();
                let c2 = rng.unit_vector() * d;
                let stretch = axes(rng, 0.4, 2.0);
                let rotation = rng.rotation();
                let r = *rotation.to_rotation_matrix().matrix();
                let m = r * Matrix3::from_diagonal(&stretch) * r.transpose();
                let moments = mapped(&lens_moments(r1, &c1, r2, &c2)?, &m, &Vector3::zeros());
                let (semi1, semi2) = (stretch * r1, stretch * r2);
                let (l1, l2) = (matrix_of(&semi1, &rotation), matrix_of(&semi2, &rotation));
                let (m1, m2) = (m * c1, m * c2);
                let expected =
                    expected_ellipsoid_i(&moments, &m1, &l1, |g, d| ellipsoid_exit(&m2, &l2, g, d));
                Some(Case {
                    i: ellipsoid(&semi1),
                    j: ellipsoid(&semi2),
                    pose_i: pose(&m1, rotation),
                    pose_j: pose(&m2, rotation),
                    expected,
                    length: semi1.max().max(semi2.max()),
                })
            },
        )),
        iterative(run(
            rng,
            CLOSED_SAMPLES,
            "ellipsoid–box",
            "one face cutting (affine spherical cap), semi-axes ∈ [0.2, 0.8]",
            "sliced quadrature",
            |rng| {
                let half = Vector3::new(2.0, 1.5, 1.0);
                let semi = axes(rng, 0.2, 0.8);
                let rotation = rng.rotation();
                let l = matrix_of(&semi, &rotation);
                let reach = (l.transpose() * Vector3::z()).norm();
                let c = Vector3::new(
                    rng.uniform(-1.0, 1.0),
                    rng.uniform(-0.6, 0.6),
                    half.z + reach * rng.uniform(-0.9, 0.9),
                );
                let moments = ellipsoid_cap(&c, &l, &Vector3::z(), half.z);
                let expected = expected_ellipsoid_i(&moments, &c, &l, |g, d| box_exit(&half, g, d));
                Some(Case {
                    i: ellipsoid(&semi),
                    j: instance(Geometry::Cuboid(
                        Cuboid::centered(half.x, half.y, half.z).unwrap(),
                    )),
                    pose_i: pose(&c, rotation),
                    pose_j: Isometry3::identity(),
                    expected,
                    length: half.x,
                })
            },
        )),
    ]
}

/// The rows of ellipsoid–cylinder, the sphere cross-check, and sphere–ellipsoid and
/// ellipsoid–ellipsoid against the spherical-polar reference.
fn cylinder_and_sphere_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        iterative(run(
            rng,
            CLOSED_SAMPLES,
            "ellipsoid–cylinder",
            "cap only (affine spherical cap), semi-axes ∈ [0.2, 0.7], r = 2, L = 2",
            "sliced quadrature",
            |rng| {
                let (radius, length) = (2.0, 2.0);
                let semi = axes(rng, 0.2, 0.7);
                let rotation = rng.rotation();
                let l = matrix_of(&semi, &rotation);
                let reach = (l.transpose() * Vector3::z()).norm();
                let angle = rng.uniform(0.0, std::f64::consts::TAU);
                let rho = rng.uniform(0.0, 1.2);
                let c = Vector3::new(
                    rho * angle.cos(),
                    rho * angle.sin(),
                    length + reach * rng.uniform(-0.9, 0.9),
                );
                let moments = ellipsoid_cap(&c, &l, &Vector3::z(), length);
                let expected = expected_ellipsoid_i(&moments, &c, &l, |g, d| {
                    cylinder_exit(radius, length, g, d)
                });
                Some(Case {
                    i: ellipsoid(&semi),
                    j: instance(Geometry::Cylinder(Cylinder::new(radius, length).unwrap())),
                    pose_i: pose(&c, rotation),
                    pose_j: Isometry3::identity(),
                    expected,
                    length: radius,
                })
            },
        )),
        iterative(sphere_cross_check(rng)),
        iterative(run(
            rng,
            SPHERICAL_SAMPLES,
            "sphere–ellipsoid",
            "sphere r ∈ [0.3, 1.2] against semi-axes ∈ [0.3, 1.5], random poses",
            "sliced quadrature",
            |rng| {
                let r = rng.uniform(0.3, 1.2);
                let semi_j = axes(rng, 0.3, 1.5);
                spherical_pair(rng, Vector3::repeat(r), semi_j)
            },
        )),
        iterative(run(
            rng,
            SPHERICAL_SAMPLES,
            "ellipsoid–ellipsoid",
            "semi-axes ∈ [0.3, 1.5], random poses",
            "sliced quadrature",
            |rng| {
                let a = axes(rng, 0.3, 1.5);
                let b = axes(rng, 0.3, 1.5);
                spherical_pair(rng, a, b)
            },
        )),
    ]
}

/// An ellipsoid I with `semi_i` against an ellipsoid J with `semi_j` at the origin, poses
/// random, by the spherical-polar reference; `None` where it does not apply (apart,
/// containment, a region not star-shaped) or has not converged to 1e-12.
fn spherical_pair(rng: &mut Rng, semi_i: Vector3, semi_j: Vector3) -> Option<Case> {
    let (ri, rj) = (rng.rotation(), rng.rotation());
    let (li, lj) = (matrix_of(&semi_i, &ri), matrix_of(&semi_j, &rj));
    let c = rng.unit_vector() * rng.uniform(0.0, 1.0) * (semi_i.max() + semi_j.max());
    let zero = Vector3::zeros();
    let (moments, error, closure) = spherical_reference::converged(
        &spherical_reference::Ellipsoid { c, l: li },
        &spherical_reference::Ellipsoid { c: zero, l: lj },
    )?;
    if error > 1e-12 || closure > 1e-12 || moments.area_vector_i.norm() < 1e-3 {
        return None;
    }
    let expected = expected_ellipsoid_i(&moments, &c, &li, |g, d| ellipsoid_exit(&zero, &lj, g, d));
    Some(Case {
        i: ellipsoid(&semi_i),
        j: ellipsoid(&semi_j),
        pose_i: pose(&c, ri),
        pose_j: pose(&zero, rj),
        expected,
        length: semi_i.max().max(semi_j.max()),
    })
}

/// The general-pose rows, against the divergence-theorem oracle. Not in the table run by
/// default: the oracle is slow unoptimized (minutes for three samples a row). With this
/// seed one sphere–ellipsoid sample (a sphere of radius 0.665 through both faces of an
/// ellipsoid 0.64 thin) differs by 4e-7 of the volume and 8.2e-7 in the normal; there the
/// spherical-polar reference agrees with the engine to 1e-15 (see
/// `spherical_reference::a_sphere_through_both_faces_of_a_flat_ellipsoid`): the oracle's
/// outer integral, split only where a sampled crossing count changes, is the wrong side.
/// Run with `--ignored --nocapture` to see the rows.
fn general_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        oracle_limited(run(
            rng,
            SURFACE_SAMPLES,
            "sphere–ellipsoid",
            "sphere r ∈ [0.3, 1.2] against semi-axes ∈ [0.3, 1.5], random poses",
            "sliced quadrature",
            |rng| {
                let r = rng.uniform(0.3, 1.2);
                let semi_j = axes(rng, 0.3, 1.5);
                general_pair(rng, Vector3::repeat(r), semi_j)
            },
        )),
        oracle_limited(run(
            rng,
            SURFACE_SAMPLES,
            "ellipsoid–ellipsoid",
            "semi-axes ∈ [0.3, 1.5], random poses",
            "sliced quadrature",
            |rng| {
                let a = axes(rng, 0.3, 1.5);
                let b = axes(rng, 0.3, 1.5);
                general_pair(rng, a, b)
            },
        )),
        oracle_limited(run(
            rng,
            SURFACE_SAMPLES,
            "ellipsoid–box",
            "semi-axes ∈ [0.3, 1.2], half extents ∈ [0.2, 1], random poses (edges, corners)",
            "sliced quadrature",
            |rng| {
                let semi = axes(rng, 0.3, 1.2);
                let half = axes(rng, 0.2, 1.0);
                let rotation = rng.rotation();
                let l = matrix_of(&semi, &rotation);
                let c = rng.unit_vector() * rng.uniform(0.0, 1.0) * (semi.max() + half.norm());
                let faces = box_faces(&half);
                let others: Vec<&dyn Patch> = faces.iter().map(|f| f as &dyn Patch).collect();
                let in_box = move |x: &Vector3| {
                    (0..3)
                        .map(|k| half[k] - x[k].abs())
                        .fold(f64::INFINITY, f64::min)
                };
                let moments = surface_moments(
                    &[&EllipsoidPatch::new(c, l)],
                    &in_box,
                    &others,
                    &ellipsoid_margin(c, l),
                    SURFACE_TOL,
                )?;
                if moments.area_vector_i.norm() < 1e-3 {
                    return None;
                }
                let expected = expected_ellipsoid_i(&moments, &c, &l, |g, d| box_exit(&half, g, d));
                Some(Case {
                    i: ellipsoid(&semi),
                    j: instance(Geometry::Cuboid(
                        Cuboid::centered(half.x, half.y, half.z).unwrap(),
                    )),
                    pose_i: pose(&c, rotation),
                    pose_j: Isometry3::identity(),
                    expected,
                    length: semi.max().max(half.max()),
                })
            },
        )),
        oracle_limited(run(
            rng,
            SURFACE_SAMPLES,
            "ellipsoid–cylinder",
            "side only, semi-axes ∈ [0.2, 0.6], r = 1, L = 4",
            "sliced quadrature",
            |rng| {
                let semi = axes(rng, 0.2, 0.6);
                let c = rng.unit_vector().xy().normalize() * (1.0 + rng.uniform(-0.5, 0.5));
                cylinder_case(rng, semi, Vector3::new(c.x, c.y, 2.0), 1.0, 4.0)
            },
        )),
        oracle_limited(run(
            rng,
            SURFACE_SAMPLES,
            "ellipsoid–cylinder",
            "semi-axes ∈ [0.3, 1.2], r ∈ [0.3, 1], L ∈ [0.4, 2], random poses (rims)",
            "sliced quadrature",
            |rng| {
                let semi = axes(rng, 0.3, 1.2);
                let (radius, length) = (rng.uniform(0.3, 1.0), rng.uniform(0.4, 2.0));
                let c = Vector3::new(0.0, 0.0, 0.5 * length)
                    + rng.unit_vector()
                        * rng.uniform(0.0, 1.0)
                        * (semi.max() + radius + 0.5 * length);
                cylinder_case(rng, semi, c, radius, length)
            },
        )),
    ]
}

#[test]
#[ignore = "slow; the oracle is 4e-7 off on one sphere–ellipsoid sample (see general_rows)"]
fn general_poses_against_the_divergence_oracle() {
    let mut rng = Rng::new(0x05ee_de11);
    for row in general_rows(&mut rng) {
        eprintln!(
            "{} / {}: worst {:?} over {}",
            row.pair, row.family, row.worst, row.samples
        );
        assert!(
            row.worst.iter().all(|&e| e <= row.bound),
            "{}: {:?}",
            row.family,
            row.worst
        );
    }
}

/// An ellipsoid I with `semi_i` against an ellipsoid J with `semi_j` at the origin, poses
/// random, by the divergence-theorem oracle.
fn general_pair(rng: &mut Rng, semi_i: Vector3, semi_j: Vector3) -> Option<Case> {
    let (ri, rj) = (rng.rotation(), rng.rotation());
    let (li, lj) = (matrix_of(&semi_i, &ri), matrix_of(&semi_j, &rj));
    let c = rng.unit_vector() * rng.uniform(0.0, 1.0) * (semi_i.max() + semi_j.max());
    let zero = Vector3::zeros();
    let moments = surface_moments(
        &[&EllipsoidPatch::new(c, li)],
        &ellipsoid_margin(zero, lj),
        &[&EllipsoidPatch::new(zero, lj)],
        &ellipsoid_margin(c, li),
        SURFACE_TOL,
    )?;
    // Containment (a vanishing area vector) has its own tests.
    if moments.area_vector_i.norm() < 1e-3 {
        return None;
    }
    let expected = expected_ellipsoid_i(&moments, &c, &li, |g, d| ellipsoid_exit(&zero, &lj, g, d));
    Some(Case {
        i: ellipsoid(&semi_i),
        j: ellipsoid(&semi_j),
        pose_i: pose(&c, ri),
        pose_j: pose(&zero, rj),
        expected,
        length: semi_i.max().max(semi_j.max()),
    })
}

/// An ellipsoid with `semi` centred at `c` (random orientation) against the cylinder
/// (`radius`, `length`) at the origin, by the divergence-theorem oracle.
fn cylinder_case(
    rng: &mut Rng,
    semi: Vector3,
    c: Vector3,
    radius: f64,
    length: f64,
) -> Option<Case> {
    let rotation = rng.rotation();
    let l = matrix_of(&semi, &rotation);
    let in_cylinder = move |x: &Vector3| (radius - x.xy().norm()).min(x.z).min(length - x.z);
    let side = SidePatch {
        r: radius,
        len: length,
    };
    let bottom = CapPatch {
        r: radius,
        z: 0.0,
        up: false,
    };
    let top = CapPatch {
        r: radius,
        z: length,
        up: true,
    };
    let moments = surface_moments(
        &[&EllipsoidPatch::new(c, l)],
        &in_cylinder,
        &[&side, &bottom, &top],
        &ellipsoid_margin(c, l),
        SURFACE_TOL,
    )?;
    if moments.area_vector_i.norm() < 1e-3 {
        return None;
    }
    let expected =
        expected_ellipsoid_i(&moments, &c, &l, |g, d| cylinder_exit(radius, length, g, d));
    Some(Case {
        i: ellipsoid(&semi),
        j: instance(Geometry::Cylinder(Cylinder::new(radius, length).unwrap())),
        pose_i: pose(&c, rotation),
        pose_j: Isometry3::identity(),
        expected,
        length: semi.max().max(radius).max(length),
    })
}

/// A sphere given as an ellipsoid whose third axis differs by 2⁻⁴⁰ (so the general sliced
/// path answers) against the closed-form sphere pairs: sphere–sphere (lens), sphere–box
/// (one face), sphere–cylinder (side or cap).
fn sphere_cross_check(rng: &mut Rng) -> Row {
    run(
        rng,
        CLOSED_SAMPLES,
        "sphere as ellipsoid ↔ closed forms",
        "r(1, 1, 1 + 2⁻⁴⁰) vs sphere_sphere (lens), sphere_solid (box face, cylinder side/cap)",
        "sliced quadrature",
        |rng| {
            let r = rng.uniform(0.3, 1.0);
            let near_sphere = Vector3::new(r, r, r * (1.0 + 2f64.powi(-40)));
            let rotation = rng.rotation();
            let (j, c) = match rng.next_u64() % 4 {
                0 => {
                    let rb = rng.uniform(0.3, 1.0);
                    let d = rng.uniform((r - rb).abs() + 0.02, r + rb - 0.02);
                    (
                        instance(Geometry::sphere(rb).unwrap()),
                        rng.unit_vector() * d,
                    )
                }
                1 => (
                    instance(Geometry::Cuboid(Cuboid::centered(2.0, 2.0, 1.0).unwrap())),
                    Vector3::new(
                        rng.uniform(-1.0, 1.0),
                        rng.uniform(-1.0, 1.0),
                        1.0 + r * rng.uniform(-0.9, 0.9),
                    ),
                ),
                2 => {
                    let angle = rng.uniform(0.0, std::f64::consts::TAU);
                    let rho = 2.0 + r * rng.uniform(-0.9, 0.9);
                    (
                        instance(Geometry::Cylinder(Cylinder::new(2.0, 4.0).unwrap())),
                        Vector3::new(rho * angle.cos(), rho * angle.sin(), 2.0),
                    )
                }
                _ => (
                    instance(Geometry::Cylinder(Cylinder::new(2.0, 4.0).unwrap())),
                    Vector3::new(
                        rng.uniform(-0.8, 0.8),
                        rng.uniform(-0.8, 0.8),
                        4.0 + r * rng.uniform(-0.9, 0.9),
                    ),
                ),
            };
            let pose_i = pose(&c, rotation);
            let closed = one(
                &instance(Geometry::sphere(r).unwrap()),
                &j,
                &pose_i,
                &Isometry3::identity(),
            );
            Some(Case {
                i: ellipsoid(&near_sphere),
                j,
                pose_i,
                pose_j: Isometry3::identity(),
                expected: Expected {
                    point_i: closed.point_i_w,
                    point_j: closed.point_j_w,
                    normal: closed.normal_w,
                    depth: closed.penetration,
                },
                length: 2.0,
            })
        },
    )
}
