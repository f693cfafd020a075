//! Characterization rows of frustum–frustum and cylinder–frustum: coaxial stacks (a closed
//! form by symmetry) and frusta of equal radii against the crossed cylinders' strips oracle
//! (slices perpendicular to both axes, written apart from the engine). The engine's own
//! checks of general frusta and cones, and of crossed cylinders, are its unit tests of the
//! divergence theorem against the polar slicing and the polygon slicing (1e-9).

use super::sliced::{GRADIENT_ORACLE_BOUND, crossed};
use super::{Case, ITERATIVE_BOUND, Row, at, run};
use crate::common::{Expected, Rng, instance};
use contact_core::geometry::{Cylinder, Frustum};
use contact_core::{Geometry, GeometryInstance, Isometry3, Point3, Vector3};

/// Samples per row: the coaxial stacks are sliced in polar coordinates (milliseconds).
const SAMPLES: usize = 60;
/// The strips oracle integrates the volume seven times per sample (the gradient), as in the
/// crossed cylinders' row.
const ORACLE_SAMPLES: usize = 25;

fn frustum(r0: f64, r1: f64, len: f64) -> Geometry {
    Geometry::Frustum(Frustum::new(r0, r1, len).unwrap())
}

/// `b` stands on `a`'s top cap, coaxial, sunk by δ (`a` narrowing upwards or a cylinder, so
/// its top cap dominates the area vector): by symmetry the normal is `−z` and the line
/// through the centroid is the axis, so the points are `a`'s top centre and `b`'s bottom
/// centre and the depth is δ.
fn coaxial(rng: &mut Rng) -> Option<Case> {
    let (r0a, la) = (rng.uniform(0.4, 1.2), rng.uniform(0.4, 2.0));
    let r1a = rng.uniform(0.2, r0a);
    let (r0b, r1b, lb) = (
        rng.uniform(0.2, 1.2),
        rng.uniform(0.0, 1.2),
        rng.uniform(0.4, 2.0),
    );
    let delta = rng.uniform(0.01, 0.9) * la.min(lb);
    let i = if rng.uniform(0.0, 1.0) < 0.3 {
        Geometry::Cylinder(Cylinder::new(r0a, la).unwrap())
    } else {
        frustum(r0a, r1a, la)
    };
    Some(Case {
        i: instance(i),
        j: instance(frustum(r0b, r1b, lb)),
        pose_i: Isometry3::identity(),
        pose_j: at(0.0, 0.0, la - delta),
        expected: Expected {
            point_i: Point3::new(0.0, 0.0, la),
            point_j: Point3::new(0.0, 0.0, la - delta),
            normal: -Vector3::z(),
            depth: delta,
        },
        length: r0a.max(la).max(r0b).max(r1b).max(lb),
    })
}

/// Frusta of equal radii in the crossed cylinders' family (crossed and skew axes, any
/// offset; `j` always, `i` every other time a frustum): the same solids, so the same strips
/// oracle ([`crossed`]).
fn equal_radii(rng: &mut Rng) -> Option<Case> {
    let as_frustum = rng.uniform(0.0, 1.0) < 0.5;
    let case = crossed(rng)?;
    let frustum_of = |g: &GeometryInstance| match *g.geometry {
        Geometry::Cylinder(c) => instance(frustum(c.radius(), c.radius(), c.length())),
        ref other => panic!("the crossed family is of cylinders: {other:?}"),
    };
    Some(Case {
        i: if as_frustum {
            frustum_of(&case.i)
        } else {
            case.i.clone()
        },
        j: frustum_of(&case.j),
        ..case
    })
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let iterative = |row: Row| Row {
        bound: ITERATIVE_BOUND,
        ..row
    };
    let gradient = |row: Row| Row {
        bound: GRADIENT_ORACLE_BOUND,
        ..row
    };
    vec![
        iterative(run(
            rng,
            SAMPLES,
            "frustum–frustum, cylinder–frustum",
            "coaxial stack, sunk δ",
            "polar-ray slicing; oracle: symmetry",
            coaxial,
        )),
        gradient(run(
            rng,
            ORACLE_SAMPLES,
            "frustum–frustum, cylinder–frustum",
            "equal radii, crossed and skew axes (≥ 0.05 rad apart), any offset",
            "divergence theorem, lateral fluxes; oracle: strips quadrature, S = −∂V/∂x_b",
            equal_radii,
        )),
    ]
}
