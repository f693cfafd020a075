//! Characterization rows of the general ellipsoid against a ring torus (sliced quadrature in
//! the engine, one contact per region), all held to the iterative bound 1e-9, against oracles
//! that share no step with the engine's planar sections or its azimuth search:
//!
//! - a sphere given as an ellipsoid against the closed-form sphere–torus pair in the torus'
//!   equatorial plane, where that pair is SPEC §4's answer (the region is symmetric about
//!   the plane and about the meridian through the centre);
//! - coaxial ellipsoids of revolution, through the hole or around the ring: 1-D integrals of
//!   concentric sections ([`crate::torus_oracles::coaxial_torus`]); the centroid lies on
//!   the axis, in the hole, so the torus' point is its closest one (`+x` radial), as the
//!   engine documents;
//! - random poses across the tube: the divergence theorem over both patches
//!   ([`crate::torus_oracles::divergence_moments`], converged to 1e-11 and closed,
//!   `|S_I + S_J| ≤ 1e-11`);
//! - two regions (a rod through the hole): the same oracle restricted to each half of the
//!   turn, one contact each.

use super::{Case, ITERATIVE_BOUND, Row, run};
use crate::common::{Expected, Rng, errors, instance, one, query};
use crate::ellipsoid_oracles::{contact_from, ellipsoid_exit};
use crate::torus_oracles::{coaxial_torus, divergence_moments, torus_exit};
use contact_core::geometry::{Ellipsoid, Torus};
use contact_core::{Geometry, GeometryInstance, Isometry3, UnitQuaternion, Vector3};
use nalgebra::{Matrix3, Translation3};
use std::f64::consts::TAU;

/// Samples of the closed-form rows.
const CLOSED_SAMPLES: usize = 60;
/// Samples of the rows against the divergence oracle.
const DIVERGENCE_SAMPLES: usize = 12;
/// The torus of the rows.
const BIG: f64 = 2.0;
const SMALL: f64 = 0.5;

fn ellipsoid(semi: &Vector3) -> GeometryInstance {
    instance(Geometry::Ellipsoid(
        Ellipsoid::new(semi.x, semi.y, semi.z).unwrap(),
    ))
}

fn torus() -> GeometryInstance {
    instance(Geometry::Torus(Torus::new(BIG, SMALL).unwrap()))
}

fn iterative(row: Row) -> Row {
    Row {
        bound: ITERATIVE_BOUND,
        ..row
    }
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        iterative(run(
            rng,
            CLOSED_SAMPLES,
            "sphere as ellipsoid ↔ closed form",
            "r(1, 1, 1 + 2⁻⁴⁰) ∈ [0.1, 0.45] vs the sphere pair on a torus' outer or inner equator (the closest point there, by symmetry), R = 2, ρ = 0.5",
            "sliced quadrature",
            |rng| {
                let r = rng.uniform(0.1, 0.45);
                let near_sphere = Vector3::new(r, r, r * (1.0 + 2f64.powi(-40)));
                let (side, foot) = if rng.uniform(0.0, 1.0) < 0.5 {
                    (1.0, BIG + SMALL)
                } else {
                    (-1.0, BIG - SMALL)
                };
                let d = foot + side * r * rng.uniform(-0.9, 0.9);
                let phi = rng.uniform(0.0, TAU);
                let pose_i = Isometry3::from_parts(
                    Translation3::new(d * phi.cos(), d * phi.sin(), 0.0),
                    rng.rotation(),
                );
                let closed = one(
                    &instance(Geometry::sphere(r).unwrap()),
                    &torus(),
                    &pose_i,
                    &Isometry3::identity(),
                );
                Some(Case {
                    i: ellipsoid(&near_sphere),
                    j: torus(),
                    pose_i,
                    pose_j: Isometry3::identity(),
                    expected: Expected {
                        point_i: closed.point_i_w,
                        point_j: closed.point_j_w,
                        normal: closed.normal_w,
                        depth: closed.penetration,
                    },
                    length: BIG + SMALL,
                })
            },
        )),
        iterative(run(
            rng,
            CLOSED_SAMPLES,
            "ellipsoid–torus",
            "coaxial ellipsoid of revolution (a ∈ [1.2, 3], c ∈ [0.3, 1.5]) through the hole or around the ring, off the equator, R = 2, ρ = 0.5",
            "sliced quadrature",
            coaxial,
        )),
        iterative(run(
            rng,
            DIVERGENCE_SAMPLES,
            "ellipsoid–torus",
            "across the tube at random (ψ, φ), random poses, semi-axes ∈ [0.15, 0.45], R = 2, ρ = 0.5",
            "sliced quadrature",
            across_the_tube,
        )),
        two_regions(rng),
    ]
}

/// Scenes of the two-region row (two contacts each).
const TWO_REGION_SCENES: usize = 6;

/// A rod (semi-axes 1.8–2.4 by 0.15–0.35) through the hole, tilted up to 0.2 rad, meeting
/// the ring twice: each contact against the divergence oracle restricted to its half of the
/// turn (the plane through the axis across the rod misses both regions), matched by the
/// torus point; seen from a random world frame.
fn two_regions(rng: &mut Rng) -> Row {
    let mut worst = [0.0f64; 3];
    let mut samples = 0;
    'scenes: while samples < TWO_REGION_SCENES {
        let semi = Vector3::new(
            rng.uniform(1.8, 2.4),
            rng.uniform(0.15, 0.35),
            rng.uniform(0.15, 0.35),
        );
        let rotation = UnitQuaternion::from_euler_angles(
            rng.uniform(0.0, TAU),
            rng.uniform(-0.2, 0.2),
            rng.uniform(0.0, TAU),
        );
        let l = rotation.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
        let c = Vector3::new(
            rng.uniform(-0.15, 0.15),
            rng.uniform(-0.15, 0.15),
            rng.uniform(-0.15, 0.15),
        );
        let pose_i = Isometry3::from_parts(Translation3::from(c), rotation);
        let world = rng.pose(2.0 * (BIG + SMALL));
        let found = query(&ellipsoid(&semi), &torus(), &(world * pose_i), &world);
        if found.len() != 2 {
            continue;
        }
        let long = rotation * Vector3::x();
        let mid = long.y.atan2(long.x);
        let mut scene = [[0.0f64; 3]; 2];
        for (k, half) in [mid, mid + std::f64::consts::PI].into_iter().enumerate() {
            let Some((moments, error, closure)) =
                divergence_moments(&c, &l, BIG, SMALL, Some(half))
            else {
                continue 'scenes;
            };
            if error > 1e-11 || closure > 1e-11 || moments.area_vector_i.norm() < 1e-3 {
                continue 'scenes;
            }
            let expected = contact_from(
                &moments,
                |g, d| ellipsoid_exit(&c, &l, g, d),
                |g, d| torus_exit(BIG, SMALL, g, d),
            )
            .moved(&world);
            let got = found
                .iter()
                .min_by(|a, b| {
                    let da = (a.point_j_w - expected.point_j).norm();
                    let db = (b.point_j_w - expected.point_j).norm();
                    da.total_cmp(&db)
                })
                .copied();
            let Some(got) = got else {
                continue 'scenes;
            };
            scene[k] = errors(&got, &expected, BIG + SMALL);
        }
        for e in scene {
            for k in 0..3 {
                worst[k] = worst[k].max(if e[k].is_nan() { f64::INFINITY } else { e[k] });
            }
        }
        samples += 1;
    }
    Row {
        bound: ITERATIVE_BOUND,
        pair: "ellipsoid–torus",
        family: "two regions: a rod (1.8–2.4 × 0.15–0.35) through the hole, tilted ≤ 0.2 rad, R = 2, ρ = 0.5; each contact (of 2 per scene)",
        method: "sliced quadrature",
        worst,
        samples: 2 * samples,
    }
}

/// An ellipsoid of revolution on the axis, off the equator, against the 1-D closed form.
fn coaxial(rng: &mut Rng) -> Option<Case> {
    let (a, c) = (rng.uniform(1.2, 3.0), rng.uniform(0.3, 1.5));
    let zc = rng.uniform(0.1, 1.0)
        * (c + SMALL)
        * if rng.uniform(0.0, 1.0) < 0.5 {
            1.0
        } else {
            -1.0
        };
    let (moments, error) = coaxial_torus(a, c, zc, BIG, SMALL)?;
    if error > 1e-12 || moments.area_vector_i.norm() < 1e-3 || moments.volume < 1e-6 {
        return None;
    }
    let centre = Vector3::new(0.0, 0.0, zc);
    let l = Matrix3::from_diagonal(&Vector3::new(a, a, c));
    let expected = contact_from(
        &moments,
        |g, d| ellipsoid_exit(&centre, &l, g, d),
        |g, d| torus_exit(BIG, SMALL, g, d),
    );
    let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, TAU));
    Some(Case {
        i: ellipsoid(&Vector3::new(a, a, c)),
        j: torus(),
        pose_i: Isometry3::from_parts(Translation3::from(centre), spin),
        pose_j: Isometry3::identity(),
        expected,
        length: BIG + SMALL,
    })
}

/// A small ellipsoid across the tube's surface at a random point, one region, against the
/// divergence theorem.
fn across_the_tube(rng: &mut Rng) -> Option<Case> {
    let semi = Vector3::new(
        rng.uniform(0.15, 0.45),
        rng.uniform(0.15, 0.45),
        rng.uniform(0.15, 0.45),
    );
    let rotation = rng.rotation();
    let l = rotation.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
    let (psi, phi) = (rng.uniform(0.0, TAU), rng.uniform(0.0, TAU));
    let radial = Vector3::new(phi.cos(), phi.sin(), 0.0);
    let normal = radial * psi.cos() + Vector3::z() * psi.sin();
    let c = radial * BIG + normal * (SMALL + rng.uniform(-0.7, 0.7) * semi.min());
    let pose_i = Isometry3::from_parts(Translation3::from(c), rotation);
    // One region only (the oracle sums all the patches).
    if query(&ellipsoid(&semi), &torus(), &pose_i, &Isometry3::identity()).len() != 1 {
        return None;
    }
    let (moments, error, closure) = divergence_moments(&c, &l, BIG, SMALL, None)?;
    if error > 1e-11 || closure > 1e-11 || moments.area_vector_i.norm() < 1e-3 {
        return None;
    }
    let expected = contact_from(
        &moments,
        |g, d| ellipsoid_exit(&c, &l, g, d),
        |g, d| torus_exit(BIG, SMALL, g, d),
    );
    Some(Case {
        i: ellipsoid(&semi),
        j: torus(),
        pose_i,
        pose_j: Isometry3::identity(),
        expected,
        length: BIG + SMALL,
    })
}
