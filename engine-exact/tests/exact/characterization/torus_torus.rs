//! The characterization row of torus–torus (the engine integrates over `a`'s meridian
//! discs), against the divergence theorem over both surfaces inside the other
//! ([`crate::torus_torus::oracle`]: each torus parametrized by its own angles, converged
//! between 24 and 48 nodes, the patches closed to 1e-10), held to the iterative bound 1e-9.
//! Poses: `b`'s core circle through a random point 0.35 to 0.5 from `a`'s (the radii sum to
//! 0.55), `b` turned at random; a pose whose tubes meet twice, or whose oracle does not
//! converge (deeper crossings, where one tube's meridian circles lie wholly inside the
//! other, defeat its arc sampling), is drawn again.

use super::{Case, ITERATIVE_BOUND, Row, run};
use crate::common::{Rng, instance, query};
use crate::torus_torus::oracle;
use contact_core::geometry::Torus;
use contact_core::{Geometry, Isometry3, Vector3};
use nalgebra::Translation3;

/// Samples of the row (each oracle integrates both surfaces twice).
const SAMPLES: usize = 4;

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let (a, b) = ((1.0, 0.3), (1.2, 0.25));
    let torus =
        |(big, small): (f64, f64)| instance(Geometry::Torus(Torus::new(big, small).unwrap()));
    let row = run(
        rng,
        SAMPLES,
        "torus ↔ torus",
        "R = 1, ρ = 0.3 against R = 1.2, ρ = 0.25 turned at random, its core circle through a point 0.35 to 0.5 from the other's (the tubes' radii sum to 0.55)",
        "meridians in polar coordinates, per region",
        |rng| {
            let theta = rng.uniform(0.0, std::f64::consts::TAU);
            let through = Vector3::new(theta.cos(), theta.sin(), 0.0) * a.0
                + rng.unit_vector() * rng.uniform(0.35, 0.5);
            let turn = rng.rotation();
            let centre = through - turn * Vector3::new(b.0, 0.0, 0.0);
            let pose_j = Isometry3::from_parts(Translation3::from(centre), turn);
            let (i, j) = (torus(a), torus(b));
            if query(&i, &j, &Isometry3::identity(), &pose_j).len() != 1 {
                return None;
            }
            let (expected, error, closure) = oracle(a, &Isometry3::identity(), b, &pose_j);
            if !(error < 1e-8 && closure < 1e-10) {
                eprintln!("oracle {error:e} {closure:e} at {pose_j:?}");
                return None;
            }
            Some(Case {
                i,
                j,
                pose_i: Isometry3::identity(),
                pose_j,
                expected,
                length: a.0 + a.1,
            })
        },
    );
    vec![Row {
        bound: ITERATIVE_BOUND,
        ..row
    }]
}
