//! Characterization rows of cylinder–torus and frustum–torus (polar-ray slicing across the
//! torus' axis, one contact per region), all held to the iterative bound 1e-9, against
//! oracles that share no step with the engine's slices or its azimuth search
//! ([`crate::torus_pair_oracles`]):
//!
//! - coaxial cylinders and frusta through the hole or as sleeves over the ring, their bottom
//!   cap inside the tube's height: the meridian section's 1-D closed form; the centroid lies
//!   on the axis, so the torus' point is its closest one (`+x` radial);
//! - random poses across the tube (a quarter perpendicular to the torus' axis): the
//!   divergence theorem over both surfaces, compared where its own error (tolerance change and
//!   closure `|S_I + S_J|`) is at most 1e-11;
//! - two regions (a rod through the hole, its ends inside the tube): the closed form over the
//!   rod's disc, one contact each.

use super::{Case, ITERATIVE_BOUND, Row, run};
use crate::common::{Rng, errors, query};
use crate::revolved_torus::{coaxial_case, crossing_case, solid};
use crate::torus_pair_oracles::{Cone, coaxial, contact_of, divergence, rod_through_hole};
use contact_core::geometry::Torus;
use contact_core::{Geometry, GeometryInstance, Isometry3, UnitQuaternion, Vector3};
use nalgebra::Translation3;
use std::f64::consts::{FRAC_PI_2, TAU};

/// Samples of the closed-form row.
const CLOSED_SAMPLES: usize = 40;
/// Samples of the row against the divergence oracle (seconds each).
const DIVERGENCE_SAMPLES: usize = 12;
/// Scenes of the two-region row (two contacts each).
const TWO_REGION_SCENES: usize = 8;
const BIG: f64 = 2.0;
const SMALL: f64 = 0.5;

fn torus() -> GeometryInstance {
    crate::common::instance(Geometry::Torus(Torus::new(BIG, SMALL).unwrap()))
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
            "cylinder–torus, frustum–torus",
            "coaxial through the hole or as a sleeve (radii ∈ [R − 0.8ρ, R + 1.5ρ]), bottom cap at |z| ≤ 0.7ρ, R = 2, ρ = 0.5",
            "polar-ray slicing; oracle: meridian closed form",
            |rng| {
                let (cone, z0) = coaxial_case(rng);
                let expected = coaxial(&cone, z0, BIG, SMALL)?;
                Some(Case {
                    i: solid(&cone, rng.uniform(0.0, 1.0) < 0.5),
                    j: torus(),
                    pose_i: Isometry3::translation(0.0, 0.0, z0),
                    pose_j: Isometry3::identity(),
                    expected,
                    length: BIG + SMALL,
                })
            },
        )),
        iterative(run(
            rng,
            DIVERGENCE_SAMPLES,
            "cylinder–torus, frustum–torus",
            "across the tube, random and perpendicular poses, radii ∈ [0.05, 0.4], R = 2, ρ = 0.5",
            "polar-ray slicing; oracle: divergence theorem",
            |rng| {
                let (cone, pose) = crossing_case(rng);
                let (m, error) = divergence(&cone, &pose, BIG, SMALL, None, None, 1e-12)?;
                if error > 1e-11 || m.volume < 1e-6 || m.area_vector_i.norm() < 1e-6 {
                    return None;
                }
                Some(Case {
                    i: solid(&cone, rng.uniform(0.0, 1.0) < 0.5),
                    j: torus(),
                    pose_i: pose,
                    pose_j: Isometry3::identity(),
                    expected: contact_of(&m, &cone, &pose, BIG, SMALL),
                    length: BIG + SMALL,
                })
            },
        )),
        two_regions(rng),
    ]
}

/// A rod of radius 0.1–0.3 along a random azimuth through the hole at a height within
/// ±0.15, its ends inside the tube (half-length within 0.25ρ of R), tilted 0: each of its two
/// contacts against the closed form, matched by the torus point; seen from a random frame.
fn two_regions(rng: &mut Rng) -> Row {
    let mut worst = [0.0f64; 3];
    let mut samples = 0;
    while samples < TWO_REGION_SCENES {
        let c = rng.uniform(0.1, 0.3);
        let half = BIG + rng.uniform(-0.25, 0.25) * SMALL;
        let lift = rng.uniform(-0.15, 0.15);
        let cone = Cone {
            r0: c,
            r1: c,
            len: 2.0 * half,
        };
        let along_x = Isometry3::from_parts(
            Translation3::new(-half, 0.0, lift),
            UnitQuaternion::from_axis_angle(&Vector3::y_axis(), FRAC_PI_2),
        );
        let world = rng.pose(2.0 * (BIG + SMALL))
            * Isometry3::rotation(Vector3::z() * rng.uniform(0.0, TAU));
        let found = query(
            &solid(&cone, rng.uniform(0.0, 1.0) < 0.5),
            &torus(),
            &(world * along_x),
            &world,
        );
        assert_eq!(found.len(), 2, "{found:?}");
        for want in rod_through_hole(c, half, lift, BIG, SMALL) {
            let want = want.moved(&world);
            let got = found
                .iter()
                .min_by(|a, b| {
                    let da = (a.point_j_w - want.point_j).norm();
                    let db = (b.point_j_w - want.point_j).norm();
                    da.total_cmp(&db)
                })
                .copied()
                .unwrap();
            let e = errors(&got, &want, BIG + SMALL);
            for k in 0..3 {
                worst[k] = worst[k].max(if e[k].is_nan() { f64::INFINITY } else { e[k] });
            }
        }
        samples += 1;
    }
    Row {
        bound: ITERATIVE_BOUND,
        pair: "cylinder–torus, frustum–torus",
        family: "two regions: a rod (radius 0.1–0.3) through the hole, ends inside the tube, R = 2, ρ = 0.5; each contact (of 2 per scene)",
        method: "polar-ray slicing; oracle: closed form over the rod's disc",
        worst,
        samples: 2 * samples,
    }
}
