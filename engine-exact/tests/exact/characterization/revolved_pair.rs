//! Characterization rows of frustum–frustum and cylinder–frustum: coaxial stacks (a closed
//! form by symmetry) and frusta of equal radii against the cylinder–cylinder pair (a
//! different method: slicing perpendicular to both axes, polygon sections).

use super::{Case, ITERATIVE_BOUND, Row, at, run};
use crate::common::{Expected, Rng, instance, query};
use contact_core::geometry::{Cylinder, Frustum};
use contact_core::{Geometry, Isometry3, Point3, Vector3};
use nalgebra::Translation3;

/// Samples per row: each query integrates slices in polar coordinates (milliseconds).
const SAMPLES: usize = 60;

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

/// Frusta of equal radii in general poses (crossed, skew, a quarter perpendicular) against
/// the cylinder pair's answer.
fn equal_radii(rng: &mut Rng) -> Option<Case> {
    let (ra, la) = (rng.uniform(0.3, 1.0), rng.uniform(0.4, 1.6));
    let (rb, lb) = (rng.uniform(0.3, 1.0), rng.uniform(0.4, 1.6));
    let turn = if rng.uniform(0.0, 1.0) < 0.25 {
        nalgebra::UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_2)
    } else {
        rng.rotation()
    };
    let offset = Vector3::new(0.0, 0.0, 0.5 * la) + rng.unit_vector() * rng.uniform(0.0, 0.8);
    let pose_j = Isometry3::from_parts(Translation3::from(offset), turn);
    let cylinder = |r, l| instance(Geometry::Cylinder(Cylinder::new(r, l).unwrap()));
    let found = query(
        &cylinder(ra, la),
        &cylinder(rb, lb),
        &Isometry3::identity(),
        &pose_j,
    );
    let c = found.first()?;
    let i = if rng.uniform(0.0, 1.0) < 0.5 {
        cylinder(ra, la)
    } else {
        instance(frustum(ra, ra, la))
    };
    Some(Case {
        i,
        j: instance(frustum(rb, rb, lb)),
        pose_i: Isometry3::identity(),
        pose_j,
        expected: Expected {
            point_i: c.point_i_w,
            point_j: c.point_j_w,
            normal: c.normal_w,
            depth: c.penetration,
        },
        length: ra.max(la).max(rb).max(lb),
    })
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let iterative = |row: Row| Row {
        bound: ITERATIVE_BOUND,
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
        iterative(run(
            rng,
            SAMPLES,
            "frustum–frustum, cylinder–frustum",
            "equal radii, general and perpendicular poses",
            "divergence theorem, lateral fluxes; oracle: cylinder–cylinder slicing",
            equal_radii,
        )),
    ]
}
