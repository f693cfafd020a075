//! Characterization rows of the solids of revolution against a plane.

use super::{Case, ITERATIVE_BOUND, Row, at, run};
use crate::common::{Rng, instance};
use crate::revolved_oracles::{self as oracles, Revolved};
use contact_core::geometry::{Frustum, Plane, Torus};
use contact_core::{Geometry, Isometry3, UnitQuaternion, Vector3};
use nalgebra::Translation3;

/// The slicing oracle costs 6,000 slices per sample: fewer samples.
const SLICED_SAMPLES: usize = 40;
const SAMPLES: usize = 100;

fn plane() -> contact_core::GeometryInstance {
    instance(Geometry::Plane(Plane::unbounded()))
}

/// The lowest point along world z of the solid turned by `q` (solid frame at the origin), by
/// dense sampling of its rims (a frustum) or its tube (a torus), and the highest.
pub(super) fn extent_z(solid: &Revolved, q: &UnitQuaternion) -> (f64, f64) {
    let mut range = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..720 {
        let phi = i as f64 * std::f64::consts::TAU / 720.0;
        let points: Vec<Vector3> = match *solid {
            Revolved::Frustum { r0, r1, len } => vec![
                Vector3::new(r0 * phi.cos(), r0 * phi.sin(), 0.0),
                Vector3::new(r1 * phi.cos(), r1 * phi.sin(), len),
            ],
            Revolved::Torus { big, small } => (0..90)
                .map(|j| {
                    let theta = j as f64 * std::f64::consts::TAU / 90.0;
                    let rho = big + small * theta.cos();
                    Vector3::new(rho * phi.cos(), rho * phi.sin(), small * theta.sin())
                })
                .collect(),
        };
        for p in points {
            let z = (q * p).z;
            range = (range.0.min(z), range.1.max(z));
        }
    }
    range
}

pub(super) fn geometry(solid: &Revolved) -> Geometry {
    match *solid {
        Revolved::Frustum { r0, r1, len } => Geometry::Frustum(Frustum::new(r0, r1, len).unwrap()),
        Revolved::Torus { big, small } => Geometry::Torus(Torus::new(big, small).unwrap()),
    }
}

/// A tilted solid sunk to a fraction of its extent along z: the slicing oracle's case.
fn tilted(rng: &mut Rng, solid: Revolved, q: UnitQuaternion, size: f64) -> Option<Case> {
    let (low, high) = extent_z(&solid, &q);
    // Keep the plane clear of the sampled extremes (their sampling error is ~1e-4).
    let h = low + rng.uniform(0.02, 0.98) * (high - low);
    Some(Case {
        i: instance(geometry(&solid)),
        j: plane(),
        pose_i: Isometry3::from_parts(Translation3::new(0.0, 0.0, -h), q),
        pose_j: Isometry3::identity(),
        expected: oracles::revolved_slices(&solid, &q, -h),
        length: size,
    })
}

pub(super) fn random_frustum(rng: &mut Rng) -> Revolved {
    Revolved::Frustum {
        r0: rng.uniform(0.0, 1.5),
        r1: rng.uniform(0.3, 1.5),
        len: rng.uniform(0.3, 2.0),
    }
}

pub(super) fn random_torus(rng: &mut Rng) -> Revolved {
    let big = rng.uniform(0.8, 2.0);
    Revolved::Torus {
        big,
        small: rng.uniform(0.1, 0.9) * big,
    }
}

pub(super) fn size(solid: &Revolved) -> f64 {
    match *solid {
        Revolved::Frustum { r0, r1, len } => r0.max(r1).max(len),
        Revolved::Torus { big, small } => big + small,
    }
}

/// `row` held to the iterative bound.
fn iterative(row: Row) -> Row {
    Row {
        bound: ITERATIVE_BOUND,
        ..row
    }
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let mut rows = frustum_plane_rows(rng);
    rows.extend(torus_plane_rows(rng));
    rows
}

/// The rows of frustum–plane.
fn frustum_plane_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        run(
            rng,
            SAMPLES,
            "frustum–plane",
            "standing on its bottom, sunk by up to its length",
            "azimuthal quadrature; oracle: truncated cone (polynomial moments)",
            |rng| {
                let (r0, r1, len) = (
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.0, 1.5),
                    rng.uniform(0.3, 2.0),
                );
                let sunk = rng.uniform(0.01, 0.99) * len;
                let (x, y) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
                Some(Case {
                    i: instance(Geometry::Frustum(Frustum::new(r0, r1, len).unwrap())),
                    j: plane(),
                    pose_i: at(x, y, -sunk),
                    pose_j: Isometry3::identity(),
                    expected: oracles::frustum_upright(r0, r1, len, sunk, x, y),
                    length: r0.max(r1).max(len),
                })
            },
        ),
        run(
            rng,
            SAMPLES,
            "frustum–plane",
            "a cone on its tip, sunk by up to its length",
            "azimuthal quadrature; oracle: cone (polynomial moments)",
            |rng| {
                let (r1, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 2.0));
                let sunk = rng.uniform(0.01, 0.99) * len;
                Some(Case {
                    i: instance(Geometry::Frustum(Frustum::new(0.0, r1, len).unwrap())),
                    j: plane(),
                    pose_i: at(0.0, 0.0, -sunk),
                    pose_j: Isometry3::identity(),
                    expected: oracles::frustum_upright(0.0, r1, len, sunk, 0.0, 0.0),
                    length: r1.max(len),
                })
            },
        ),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "frustum–plane",
            "axis tilted 12°–78° from the normal, rim to beyond half immersion",
            "azimuthal quadrature; oracle: Simpson over slices across the axis",
            |rng| {
                let solid = random_frustum(rng);
                let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), rng.uniform(0.2, 1.37))
                    * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, 6.0));
                tilted(rng, solid, q, size(&solid))
            },
        )),
    ]
}

/// The rows of torus–plane.
fn torus_plane_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        run(
            rng,
            SAMPLES,
            "torus–plane",
            "lying flat, cut up to near its mid-plane from either side",
            "azimuthal quadrature; oracle: Pappus (annular slab)",
            |rng| {
                let Revolved::Torus { big, small } = random_torus(rng) else {
                    return None;
                };
                let c = rng.uniform(-0.99, 0.99) * small;
                let (x, y) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
                Some(Case {
                    i: instance(Geometry::Torus(Torus::new(big, small).unwrap())),
                    j: plane(),
                    pose_i: at(x, y, -c),
                    pose_j: Isometry3::identity(),
                    expected: oracles::torus_flat(big, small, c, x, y),
                    length: big + small,
                })
            },
        ),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "torus–plane",
            "standing on its edge (axis in the plane's directions), cut through the hole",
            "azimuthal quadrature; oracle: Simpson over annulus slices",
            |rng| {
                let solid = random_torus(rng);
                let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, 6.0))
                    * UnitQuaternion::from_axis_angle(
                        &Vector3::y_axis(),
                        -std::f64::consts::FRAC_PI_2,
                    );
                tilted(rng, solid, q, size(&solid))
            },
        )),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "torus–plane",
            "any tilt with the axis at least 12° from the normal",
            "azimuthal quadrature; oracle: Simpson over annulus slices",
            |rng| {
                let solid = random_torus(rng);
                let q = rng.rotation();
                if (q * Vector3::z()).z.abs() > 0.2f64.cos() {
                    return None;
                }
                tilted(rng, solid, q, size(&solid))
            },
        )),
    ]
}
