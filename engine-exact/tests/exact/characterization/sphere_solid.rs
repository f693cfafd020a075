//! Characterization rows of a sphere against a frustum and a torus off the fast path (a
//! frustum's slanted side and rims, a torus' tube anywhere): the general slicing with equal
//! semi-axes, held to the iterative bound 1e-9 against the divergence-theorem oracles written
//! for the general ellipsoid ([`crate::frustum_oracles::frustum_moments`] about the cone's
//! apex, [`crate::torus_oracles::divergence_moments`]), which share no step with the engine's
//! planar sections. Before, these pairs answered by the closest point: normals up to 33° off
//! on a frustum and 2.5° on a torus.

use super::{Case, ITERATIVE_BOUND, Row, run};
use crate::common::{Rng, instance, query};
use crate::ellipsoid_oracles::{contact_from, ellipsoid_exit};
use crate::ellipsoid_revolved::frustum_exit;
use crate::torus_oracles::{divergence_moments, torus_exit};
use contact_core::geometry::{Frustum, Torus};
use contact_core::{Geometry, Isometry3, Vector3};
use nalgebra::{Matrix3, Translation3};
use std::f64::consts::TAU;

/// Samples of each row (the oracles are slow unoptimized).
const SAMPLES: usize = 12;

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
            SAMPLES,
            "sphere–frustum",
            "centre within 0.8 r of a rim or of the slanted side, r ∈ [0.2, 0.5], r₀ = 1.2, r₁ = 0.5, L = 1.5",
            "general ellipsoid slicing, equal semi-axes",
            frustum_case,
        )),
        iterative(run(
            rng,
            SAMPLES,
            "sphere–torus",
            "centre within 0.7 r of the tube at random (ψ, φ), r ∈ [0.15, 0.45], R = 2, ρ = 0.5",
            "general ellipsoid slicing, equal semi-axes",
            torus_case,
        )),
    ]
}

fn frustum_case(rng: &mut Rng) -> Option<Case> {
    let (r0, r1, len) = (1.2, 0.5, 1.5);
    let r = rng.uniform(0.2, 0.5);
    let l = Matrix3::identity() * r;
    let angle = rng.uniform(0.0, TAU);
    let radial = Vector3::new(angle.cos(), angle.sin(), 0.0);
    let foot = match rng.next_u64() % 3 {
        0 => radial * r0,
        1 => radial * r1 + Vector3::new(0.0, 0.0, len),
        _ => {
            let t = rng.uniform(0.2, 0.8);
            radial * (r0 + (r1 - r0) * t) + Vector3::new(0.0, 0.0, t * len)
        }
    };
    let c = foot + rng.unit_vector() * rng.uniform(0.0, 0.8) * r;
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
        i: instance(Geometry::sphere(r).unwrap()),
        j: instance(Geometry::Frustum(Frustum::new(r0, r1, len).unwrap())),
        pose_i: Isometry3::from_parts(Translation3::from(c), rng.rotation()),
        pose_j: Isometry3::identity(),
        expected,
        length: r0.max(len),
    })
}

fn torus_case(rng: &mut Rng) -> Option<Case> {
    let (big, small) = (2.0, 0.5);
    let r = rng.uniform(0.15, 0.45);
    let l = Matrix3::identity() * r;
    let (psi, phi) = (rng.uniform(0.0, TAU), rng.uniform(0.0, TAU));
    let radial = Vector3::new(phi.cos(), phi.sin(), 0.0);
    let normal = radial * psi.cos() + Vector3::z() * psi.sin();
    let c = radial * big + normal * (small + rng.uniform(-0.7, 0.7) * r);
    let sphere = instance(Geometry::sphere(r).unwrap());
    let torus = instance(Geometry::Torus(Torus::new(big, small).unwrap()));
    let pose_i = Isometry3::from_parts(Translation3::from(c), rng.rotation());
    // One region only (the oracle sums all the patches).
    if query(&sphere, &torus, &pose_i, &Isometry3::identity()).len() != 1 {
        return None;
    }
    let (moments, error, closure) = divergence_moments(&c, &l, big, small, None)?;
    if error > 1e-11 || closure > 1e-11 || moments.area_vector_i.norm() < 1e-3 {
        return None;
    }
    let expected = contact_from(
        &moments,
        |g, d| ellipsoid_exit(&c, &l, g, d),
        |g, d| torus_exit(big, small, g, d),
    );
    Some(Case {
        i: sphere,
        j: torus,
        pose_i,
        pose_j: Isometry3::identity(),
        expected,
        length: big + small,
    })
}
