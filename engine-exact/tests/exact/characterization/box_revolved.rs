//! Characterization rows of the box against a frustum or torus, of frustums, tori and general
//! ellipsoids against a bounded plane: each configuration is one whose answer an existing
//! independent oracle gives, since the box's (or the bounded plane's) other faces are out of
//! reach and the intersection is the solid below one plane: the polynomial moments of a
//! truncated cone, Pappus for a torus lying flat, Simpson over slices for tilted solids
//! ([`crate::revolved_oracles`]), the affine cap for an ellipsoid ([`crate::oracles`]).

use super::revolved::{extent_z, geometry, random_frustum, random_torus, size};
use super::{Case, ITERATIVE_BOUND, Row, at, run};
use crate::common::{Rng, instance};
use crate::oracles;
use crate::revolved_oracles::{self as revolved_oracles, Revolved};
use contact_core::geometry::{Cuboid, Ellipsoid, Frustum, Plane, Torus};
use contact_core::{Geometry, GeometryInstance, Isometry3, UnitQuaternion, Vector3};
use nalgebra::Translation3;

const SAMPLES: usize = 60;
/// The slicing oracle costs 6,000 slices per sample: fewer samples.
const SLICED_SAMPLES: usize = 30;

/// What stands for the plane `z ≤ 0` near a solid of size `size`: a box whose top face is
/// `z = 0` and whose other faces lie 8·size away, or a bounded plane whose rectangle holds the
/// solid's footprint (its edges 3·size to 5·size from the origin).
#[derive(Clone, Copy)]
enum Ground {
    Box,
    Bounded,
}

fn ground(rng: &mut Rng, kind: Ground, size: f64) -> (GeometryInstance, Isometry3) {
    match kind {
        Ground::Box => {
            let h = 8.0 * size;
            (
                instance(Geometry::Cuboid(Cuboid::centered(h, h, h).unwrap())),
                Isometry3::translation(rng.uniform(-1.0, 1.0) * size, 0.0, -h),
            )
        }
        Ground::Bounded => {
            let mut edge = || rng.uniform(3.0, 5.0) * size;
            let plane = Plane::bounded(-edge(), edge(), -edge(), edge()).unwrap();
            (instance(Geometry::Plane(plane)), Isometry3::identity())
        }
    }
}

fn upright_frustum(rng: &mut Rng, kind: Ground) -> Option<Case> {
    let (r0, r1, len) = (
        rng.uniform(0.3, 1.5),
        rng.uniform(0.0, 1.5),
        rng.uniform(0.3, 2.0),
    );
    let length = r0.max(r1).max(len);
    let sunk = rng.uniform(0.01, 0.99) * len;
    let (x, y) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
    let (j, pose_j) = ground(rng, kind, length);
    Some(Case {
        i: instance(Geometry::Frustum(Frustum::new(r0, r1, len).unwrap())),
        j,
        pose_i: at(x, y, -sunk),
        pose_j,
        expected: revolved_oracles::frustum_upright(r0, r1, len, sunk, x, y),
        length,
    })
}

fn flat_torus(rng: &mut Rng, kind: Ground) -> Option<Case> {
    let Revolved::Torus { big, small } = random_torus(rng) else {
        return None;
    };
    let c = rng.uniform(-0.99, 0.99) * small;
    let (x, y) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
    let (j, pose_j) = ground(rng, kind, big + small);
    Some(Case {
        i: instance(Geometry::Torus(Torus::new(big, small).unwrap())),
        j,
        pose_i: at(x, y, -c),
        pose_j,
        expected: revolved_oracles::torus_flat(big, small, c, x, y),
        length: big + small,
    })
}

/// A solid turned by `q` and sunk to a fraction of its extent along z.
fn tilted(rng: &mut Rng, solid: Revolved, q: UnitQuaternion, kind: Ground) -> Option<Case> {
    let (low, high) = extent_z(&solid, &q);
    // Keep the plane clear of the sampled extremes (their sampling error is ~1e-4).
    let h = low + rng.uniform(0.02, 0.98) * (high - low);
    let (j, pose_j) = ground(rng, kind, size(&solid));
    Some(Case {
        i: instance(geometry(&solid)),
        j,
        pose_i: Isometry3::from_parts(Translation3::new(0.0, 0.0, -h), q),
        pose_j,
        expected: revolved_oracles::revolved_slices(&solid, &q, -h),
        length: size(&solid),
    })
}

/// A rotation whose `z` axis is at least 12° from world z.
fn tilt(rng: &mut Rng) -> Option<UnitQuaternion> {
    let q = rng.rotation();
    ((q * Vector3::z()).z.abs() <= 0.2f64.cos()).then_some(q)
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let iterative = |row: Row| Row {
        bound: ITERATIVE_BOUND,
        ..row
    };
    let sliced = "slicing across the solid's axis, disc/annulus–polygon sections in closed form";
    vec![
        iterative(run(
            rng,
            SAMPLES,
            "box–frustum",
            "standing on its bottom, the box's top face cutting it, other faces out of reach",
            "slicing across the axis; oracle: truncated cone (polynomial moments)",
            |rng| upright_frustum(rng, Ground::Box),
        )),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "box–frustum",
            "axis tilted ≥ 12° from the box's top face normal, other faces out of reach",
            "slicing across the axis; oracle: Simpson over slices across the axis",
            |rng| {
                let solid = random_frustum(rng);
                let q = tilt(rng)?;
                tilted(rng, solid, q, Ground::Box)
            },
        )),
        iterative(run(
            rng,
            SAMPLES,
            "box–torus",
            "lying flat, the box's top face cutting it, other faces out of reach",
            "slicing across the axis; oracle: Pappus (annular slab)",
            |rng| flat_torus(rng, Ground::Box),
        )),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "box–torus",
            "any tilt ≥ 12° from the box's top face normal, other faces out of reach",
            "slicing across the axis; oracle: Simpson over annulus slices",
            |rng| {
                let solid = random_torus(rng);
                let q = tilt(rng)?;
                tilted(rng, solid, q, Ground::Box)
            },
        )),
        iterative(run(
            rng,
            SAMPLES,
            "frustum–bounded plane",
            "standing on its bottom inside the rectangle",
            sliced,
            |rng| upright_frustum(rng, Ground::Bounded),
        )),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "frustum–bounded plane",
            "axis tilted ≥ 12° from the normal, inside the rectangle",
            "slicing across the axis; oracle: Simpson over slices across the axis",
            |rng| {
                let solid = random_frustum(rng);
                let q = tilt(rng)?;
                tilted(rng, solid, q, Ground::Bounded)
            },
        )),
        iterative(run(
            rng,
            SAMPLES,
            "torus–bounded plane",
            "lying flat inside the rectangle",
            "slicing across the axis; oracle: Pappus (annular slab)",
            |rng| flat_torus(rng, Ground::Bounded),
        )),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "torus–bounded plane",
            "any tilt ≥ 12° from the normal, inside the rectangle",
            "slicing across the axis; oracle: Simpson over annulus slices",
            |rng| {
                let solid = random_torus(rng);
                let q = tilt(rng)?;
                tilted(rng, solid, q, Ground::Bounded)
            },
        )),
        iterative(run(
            rng,
            SAMPLES,
            "ellipsoid–bounded plane",
            "semi-axes ∈ [0.3, 2], any orientation, inside the rectangle, cap to beyond the centre",
            "the ellipsoid–box slicing on the plane's prism; oracle: affine cap by slicing",
            |rng| {
                let s = Vector3::new(
                    rng.uniform(0.3, 2.0),
                    rng.uniform(0.3, 2.0),
                    rng.uniform(0.3, 2.0),
                );
                let q = rng.rotation();
                let n = q.inverse_transform_vector(&Vector3::z());
                let k = (s.component_mul(&n)).norm();
                let z0 = k * rng.uniform(-0.9, 0.999);
                let (j, pose_j) = ground(rng, Ground::Bounded, s.max());
                Some(Case {
                    i: instance(Geometry::Ellipsoid(Ellipsoid::new(s.x, s.y, s.z).unwrap())),
                    j,
                    pose_i: Isometry3::from_parts(Translation3::new(0.0, 0.0, z0), q),
                    pose_j,
                    expected: oracles::ellipsoid_plane(&s, &q, z0),
                    length: s.max(),
                })
            },
        )),
    ]
}
