//! Characterization rows of the general ellipsoid against a frustum (sliced quadrature in
//! the engine), all held to the iterative bound 1e-9, against oracles that share no step with
//! the engine's planar sections:
//!
//! - cap only: the affine image of a spherical cap ([`crate::ellipsoid_oracles::ellipsoid_cap`]);
//! - side only, general poses: the divergence theorem about the cone's apex, where the cone's
//!   surface carries no flux of `x` (`x·n = 0`), so the ellipsoid's own patch inside the cone
//!   gives volume, centroid and area vector — in geodesic polar coordinates on its unit
//!   sphere ([`crate::ellipsoid_revolved::converged_in_cone`], converged to 1e-12);
//! - coaxial ellipsoids of revolution (spheres and cones included): 1-D integrals of
//!   concentric discs, exact by Gauss–Legendre between the radii's crossings
//!   ([`crate::ellipsoid_revolved::coaxial_frustum`]);
//! - rims, general poses: the same divergence about the apex with the caps' parts inside the
//!   ellipsoid, its patch cut where the binding constraint changes
//!   ([`crate::frustum_oracles::frustum_moments`], converged to 1e-11);
//! - a sphere given as an ellipsoid against the closed-form sphere–frustum pair where that
//!   pair is SPEC §4's answer (one cap);
//! - a cross-check, not an oracle: a frustum of equal radii against the ellipsoid–cylinder
//!   pair in general poses (rims included), whose extent comes from the pencil of the two
//!   quadrics instead of the frustum's convex gap.

use super::{Case, ITERATIVE_BOUND, Row, run};
use crate::common::{Expected, Rng, instance, one, query};
use crate::ellipsoid_oracles::{contact_from, ellipsoid_cap, ellipsoid_exit};
use crate::ellipsoid_revolved::{coaxial_frustum, converged_in_cone, frustum_exit};
use crate::spherical_reference;
use contact_core::geometry::{Ellipsoid, Frustum};
use contact_core::{Geometry, GeometryInstance, Isometry3, UnitQuaternion, Vector3};
use nalgebra::{Matrix3, Translation3};

/// Samples of the closed-form rows.
const CLOSED_SAMPLES: usize = 60;
/// Samples of the rows against the spherical-polar reference.
const SPHERICAL_SAMPLES: usize = 12;

fn axes(rng: &mut Rng, lo: f64, hi: f64) -> Vector3 {
    Vector3::new(
        rng.uniform(lo, hi),
        rng.uniform(lo, hi),
        rng.uniform(lo, hi),
    )
}

fn ellipsoid(semi: &Vector3) -> GeometryInstance {
    instance(Geometry::Ellipsoid(
        Ellipsoid::new(semi.x, semi.y, semi.z).unwrap(),
    ))
}

fn frustum(r0: f64, r1: f64, len: f64) -> GeometryInstance {
    instance(Geometry::Frustum(Frustum::new(r0, r1, len).unwrap()))
}

fn iterative(row: Row) -> Row {
    Row {
        bound: ITERATIVE_BOUND,
        ..row
    }
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let mut rows = frustum_rows(rng);
    rows.extend(cross_check_rows(rng));
    rows
}

/// The rows of ellipsoid–frustum.
fn frustum_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        iterative(run(
            rng,
            CLOSED_SAMPLES,
            "ellipsoid–frustum",
            "top cap only (affine spherical cap), semi-axes ∈ [0.2, 0.6], r₀ = 2.5, r₁ = 2, L = 2",
            "sliced quadrature",
            |rng| {
                let (r0, r1, len) = (2.5, 2.0, 2.0);
                let semi = axes(rng, 0.2, 0.6);
                let rotation = rng.rotation();
                let l = rotation.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
                let reach = (l.transpose() * Vector3::z()).norm();
                let angle = rng.uniform(0.0, std::f64::consts::TAU);
                let rho = rng.uniform(0.0, 1.2);
                let c = Vector3::new(
                    rho * angle.cos(),
                    rho * angle.sin(),
                    len + reach * rng.uniform(-0.9, 0.9),
                );
                let moments = ellipsoid_cap(&c, &l, &Vector3::z(), len);
                let expected = contact_from(
                    &moments,
                    |g, d| ellipsoid_exit(&c, &l, g, d),
                    |g, d| frustum_exit(r0, r1, len, g, d),
                );
                Some(Case {
                    i: ellipsoid(&semi),
                    j: frustum(r0, r1, len),
                    pose_i: Isometry3::from_parts(Translation3::from(c), rotation),
                    pose_j: Isometry3::identity(),
                    expected,
                    length: r0,
                })
            },
        )),
        iterative(run(
            rng,
            SPHERICAL_SAMPLES,
            "ellipsoid–frustum",
            "side only, random poses, semi-axes ∈ [0.2, 0.5], r₀ = 1.5, r₁ = 0.5, L = 4",
            "sliced quadrature",
            side_only,
        )),
        iterative(run(
            rng,
            CLOSED_SAMPLES,
            "ellipsoid–frustum",
            "coaxial ellipsoid of revolution (a, a, c ∈ [0.3, 1.2]), r₀ ∈ {0, [0.2, 1.5]}, r₁ ∈ [0.2, 1.5], L ∈ [0.5, 2]",
            "sliced quadrature",
            coaxial,
        )),
    ]
}

/// The rows of a sphere as an ellipsoid against the closed form, the ellipsoid across a
/// frustum's rim, and the frustum of equal radii against the ellipsoid–cylinder pair.
fn cross_check_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        iterative(run(
            rng,
            CLOSED_SAMPLES,
            "sphere as ellipsoid ↔ closed form",
            "r(1, 1, 1 + 2⁻⁴⁰) vs sphere_solid on a frustum's cap (bottom or top)",
            "sliced quadrature",
            |rng| {
                let r = rng.uniform(0.2, 0.6);
                let near_sphere = Vector3::new(r, r, r * (1.0 + 2f64.powi(-40)));
                let (r0, r1, len) = (2.0, 1.5, 2.0);
                let angle = rng.uniform(0.0, std::f64::consts::TAU);
                let rho = rng.uniform(0.0, 0.8);
                let z = if rng.uniform(0.0, 1.0) < 0.5 {
                    0.0
                } else {
                    len
                };
                let c = Vector3::new(
                    rho * angle.cos(),
                    rho * angle.sin(),
                    z + r * rng.uniform(-0.9, 0.9),
                );
                let pose_i = Isometry3::from_parts(Translation3::from(c), rng.rotation());
                let j = frustum(r0, r1, len);
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
                    length: r0,
                })
            },
        )),
        iterative(run(
            rng,
            SPHERICAL_SAMPLES,
            "ellipsoid–frustum",
            "across a rim (top or bottom), random poses, semi-axes ∈ [0.25, 0.6], r₀ = 1.2, r₁ = 0.5, L = 1.5",
            "sliced quadrature",
            across_a_rim,
        )),
        iterative(run(
            rng,
            CLOSED_SAMPLES,
            "ellipsoid–frustum ↔ ellipsoid–cylinder",
            "a frustum of equal radii r ∈ [0.3, 1], L ∈ [0.4, 2] against the cylinder pair (the pencil's extent), semi-axes ∈ [0.3, 1.2], random poses (rims included)",
            "sliced quadrature",
            |rng| {
                let semi = axes(rng, 0.3, 1.2);
                let (radius, len) = (rng.uniform(0.3, 1.0), rng.uniform(0.4, 2.0));
                let c = Vector3::new(0.0, 0.0, 0.5 * len)
                    + rng.unit_vector() * rng.uniform(0.0, 1.0) * (semi.max() + radius + 0.5 * len);
                let pose_i = Isometry3::from_parts(Translation3::from(c), rng.rotation());
                let cylinder = instance(Geometry::Cylinder(
                    contact_core::geometry::Cylinder::new(radius, len).unwrap(),
                ));
                let found = query(
                    &ellipsoid(&semi),
                    &cylinder,
                    &pose_i,
                    &Isometry3::identity(),
                );
                let [reference] = found[..] else {
                    return None;
                };
                Some(Case {
                    i: ellipsoid(&semi),
                    j: frustum(radius, radius, len),
                    pose_i,
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: reference.point_i_w,
                        point_j: reference.point_j_w,
                        normal: reference.normal_w,
                        depth: reference.penetration,
                    },
                    length: semi.max().max(radius).max(len),
                })
            },
        )),
    ]
}

/// An ellipsoid about a point of a rim, against the divergence theorem about the apex with the
/// caps' parts ([`crate::frustum_oracles::frustum_moments`], converged to 1e-11).
fn across_a_rim(rng: &mut Rng) -> Option<Case> {
    let (r0, r1, len) = (1.2, 0.5, 1.5);
    let semi = axes(rng, 0.25, 0.6);
    let rotation = rng.rotation();
    let l = rotation.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
    let (z, radius) = if rng.uniform(0.0, 1.0) < 0.5 {
        (0.0, r0)
    } else {
        (len, r1)
    };
    let angle = rng.uniform(0.0, std::f64::consts::TAU);
    let rim = Vector3::new(radius * angle.cos(), radius * angle.sin(), z);
    let c = rim + rng.unit_vector() * rng.uniform(0.0, 0.8) * semi.min();
    let (moments, error) = crate::frustum_oracles::frustum_moments(&c, &l, r0, r1, len)?;
    if error > 1e-11 || moments.area_vector_i.norm() < 1e-3 {
        return None;
    }
    let expected = contact_from(
        &moments,
        |g, d| ellipsoid_exit(&c, &l, g, d),
        |g, d| frustum_exit(r0, r1, len, g, d),
    );
    Some(Case {
        i: ellipsoid(&semi),
        j: frustum(r0, r1, len),
        pose_i: Isometry3::from_parts(Translation3::from(c), rotation),
        pose_j: Isometry3::identity(),
        expected,
        length: r0.max(len),
    })
}

/// An ellipsoid across the slanted side of a long frustum, clear of both caps, against the
/// divergence theorem about the cone's apex.
fn side_only(rng: &mut Rng) -> Option<Case> {
    let (r0, r1, len) = (1.5, 0.5, 4.0);
    let k = (r1 - r0) / len;
    let apex = Vector3::new(0.0, 0.0, -r0 / k);
    let semi = axes(rng, 0.2, 0.5);
    let rotation = rng.rotation();
    let l = rotation.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
    let zc = rng.uniform(1.5, 2.5);
    let angle = rng.uniform(0.0, std::f64::consts::TAU);
    let rho = r0 + k * zc + rng.uniform(-0.8, 0.8) * semi.min();
    let c = Vector3::new(rho * angle.cos(), rho * angle.sin(), zc);
    let margin = move |x: &Vector3| (r0 + k * x.z) - x.xy().norm();
    let i = spherical_reference::Ellipsoid { c, l };
    let (moments, error) = converged_in_cone(&i, &margin, &apex)?;
    if error > 1e-12 || moments.area_vector_i.norm() < 1e-3 {
        return None;
    }
    let expected = contact_from(
        &moments,
        |g, d| ellipsoid_exit(&c, &l, g, d),
        |g, d| frustum_exit(r0, r1, len, g, d),
    );
    Some(Case {
        i: ellipsoid(&semi),
        j: frustum(r0, r1, len),
        pose_i: Isometry3::from_parts(Translation3::from(c), rotation),
        pose_j: Isometry3::identity(),
        expected,
        length: len,
    })
}

/// An ellipsoid of revolution on the frustum's axis (turned about it at random), poking out
/// of one cap or holding the frustum's narrow end, against the 1-D closed form.
fn coaxial(rng: &mut Rng) -> Option<Case> {
    let (a, c) = (rng.uniform(0.3, 1.2), rng.uniform(0.3, 1.2));
    let r0 = if rng.uniform(0.0, 1.0) < 0.25 {
        0.0
    } else {
        rng.uniform(0.2, 1.5)
    };
    let (r1, len) = (rng.uniform(0.2, 1.5), rng.uniform(0.5, 2.0));
    let zc = rng.uniform(-c, len + c);
    let moments = coaxial_frustum(a, c, zc, r0, r1, len)?;
    if moments.area_vector_i.norm() < 1e-3 || moments.volume < 1e-6 {
        return None;
    }
    let centre = Vector3::new(0.0, 0.0, zc);
    let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, 6.0));
    let l = Matrix3::from_diagonal(&Vector3::new(a, a, c));
    let expected = contact_from(
        &moments,
        |g, d| ellipsoid_exit(&centre, &l, g, d),
        |g, d| frustum_exit(r0, r1, len, g, d),
    );
    Some(Case {
        i: ellipsoid(&Vector3::new(a, a, c)),
        j: frustum(r0, r1, len),
        pose_i: Isometry3::from_parts(Translation3::from(centre), spin),
        pose_j: Isometry3::identity(),
        expected,
        length: a.max(c).max(r0).max(r1).max(len),
    })
}
