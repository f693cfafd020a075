//! The accuracy contract: one row per pair, measured against an independent closed form
//! (see [`crate::oracles`]) over seeded random configurations, each seen from a random world
//! frame. Run with `--nocapture` to print the table.
//!
//! Bounds: 1e-12 relative to the pair's size for closed forms and exact clipping, 1e-9 for
//! quadrature and iterative pairs (cylinder–plane tilted, curves); depth, normal and points
//! are each checked.

use crate::common::{Expected, Rng, errors, query};
use contact_core::{GeometryInstance, Isometry3};

pub(crate) mod bounded_line;
mod box_revolved;
mod ellipsoid_cavity;
mod ellipsoid_revolved;
mod ellipsoid_torus;
mod ellipsoids;
pub(crate) mod mesh_box;
mod planar;
pub(crate) mod planar_overlap;
mod revolved;
mod revolved_pair;
mod revolved_torus;
mod sliced;
mod solids;
mod sphere_rows;
mod sphere_solid;
mod torus_torus;

pub(super) const SAMPLES: usize = 200;
/// Curve rows are fewer: the oracle's evaluator allocates per call and runs unoptimized.
pub(super) const CURVE_SAMPLES: usize = 60;
pub(super) const CLOSED_FORM_BOUND: f64 = 1e-12;
/// Quadrature pairs (and their Simpson oracles) are held to the iterative bound.
pub(super) const ITERATIVE_BOUND: f64 = 1e-9;

/// One row of the table.
pub(super) struct Row {
    pub(super) bound: f64,
    pub(super) pair: &'static str,
    pub(super) family: &'static str,
    pub(super) method: &'static str,
    pub(super) worst: [f64; 3],
    pub(super) samples: usize,
}

/// One case: the I and J instances, the part poses in the canonical frame, the expected
/// answer there, and the pair's size.
pub(super) struct Case {
    pub(super) i: GeometryInstance,
    pub(super) j: GeometryInstance,
    pub(super) pose_i: Isometry3,
    pub(super) pose_j: Isometry3,
    pub(super) expected: Expected,
    pub(super) length: f64,
}

pub(super) fn run(
    rng: &mut Rng,
    count: usize,
    pair: &'static str,
    family: &'static str,
    method: &'static str,
    mut make: impl FnMut(&mut Rng) -> Option<Case>,
) -> Row {
    let mut worst = [0.0f64; 3];
    let mut samples = 0;
    while samples < count {
        let Some(case) = make(rng) else { continue };
        let world = rng.pose(2.0 * case.length);
        let found = query(
            &case.i,
            &case.j,
            &(world * case.pose_i),
            &(world * case.pose_j),
        );
        assert_eq!(
            found.len(),
            1,
            "{pair} ({family}): {found:?} for {:?}",
            case.expected
        );
        let got = found[0];
        let e = errors(&got, &case.expected.moved(&world), case.length);
        for k in 0..3 {
            // NaN must fail the row, so it counts as infinite.
            worst[k] = worst[k].max(if e[k].is_nan() { f64::INFINITY } else { e[k] });
        }
        samples += 1;
    }
    Row {
        bound: CLOSED_FORM_BOUND,
        pair,
        family,
        method,
        worst,
        samples,
    }
}

pub(super) fn at(x: f64, y: f64, z: f64) -> Isometry3 {
    Isometry3::translation(x, y, z)
}

#[test]
fn characterization_table() {
    let mut rng = Rng::new(0x5EED_0003);
    let mut rows = solids::rows(&mut rng);
    rows.extend(revolved::rows(&mut rng));
    rows.extend(sliced::rows(&mut rng));
    rows.extend(ellipsoids::rows(&mut rng));
    rows.extend(planar::rows(&mut rng));
    rows.extend(planar_overlap::rows(&mut rng));
    // Added last, so the rows above keep their seeded configurations.
    rows.extend(box_revolved::rows(&mut rng));
    rows.extend(mesh_box::rows(&mut rng));
    rows.extend(bounded_line::rows(&mut rng));
    rows.extend(ellipsoid_revolved::rows(&mut rng));
    rows.extend(ellipsoid_torus::rows(&mut rng));
    rows.extend(revolved_pair::rows(&mut rng));
    rows.extend(revolved_torus::rows(&mut rng));
    rows.extend(sphere_solid::rows(&mut rng));
    rows.extend(torus_torus::rows(&mut rng));
    rows.extend(ellipsoid_cavity::rows(&mut rng));
    println!(
        "| pair | configuration family | method | samples | max depth err | max normal err | max point err | bound |"
    );
    println!("| --- | --- | --- | --- | --- | --- | --- | --- |");
    for r in &rows {
        println!(
            "| {} | {} | {} | {} | {:.1e} | {:.1e} | {:.1e} | {:.0e} |",
            r.pair, r.family, r.method, r.samples, r.worst[0], r.worst[1], r.worst[2], r.bound
        );
    }
    for r in &rows {
        assert!(
            r.worst.iter().all(|&e| e <= r.bound),
            "{} ({}): errors {:?} exceed {:e}",
            r.pair,
            r.family,
            r.worst,
            r.bound
        );
    }
}
