//! Characterization rows of the box against a frustum or torus, of frustums, tori and general
//! ellipsoids against a bounded plane: each configuration is one whose answer an existing
//! independent oracle gives, since the box's (or the bounded plane's) other faces are out of
//! reach and the intersection is the solid below one plane: the polynomial moments of a
//! truncated cone, Pappus for a torus lying flat, Simpson over slices for tilted solids
//! ([`crate::revolved_oracles`]), the affine cap for an ellipsoid ([`crate::oracles`]); and a
//! bounded plane's edge through a frustum's or a flat torus' axis, the half solid below it,
//! with the moments of half discs and of disc segments written here.

use super::revolved::{extent_z, geometry, random_frustum, random_torus, size};
use super::solids::ellipsoid_over_plane;
use super::{Case, ITERATIVE_BOUND, Row, at, run};
use crate::common::Expected;
use crate::common::{Rng, instance};
use crate::oracles;
use crate::revolved_oracles::{self as revolved_oracles, Revolved};
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Frustum, Plane, Torus};
use contact_core::{Geometry, GeometryInstance, Isometry3, Point3, UnitQuaternion, Vector3};
use nalgebra::Translation3;
use std::f64::consts::PI;

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
    /// The box as a closed mesh (12 triangles).
    Mesh,
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
        Ground::Mesh => {
            let h = 8.0 * size;
            let mesh = crate::common::boxes_mesh(&[(Point3::origin(), Vector3::repeat(h))]);
            (
                instance(Geometry::Mesh(std::sync::Arc::new(mesh))),
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

/// The bounded plane `x ≤ 0` (other bounds far), as I's partner.
fn half_plane() -> GeometryInstance {
    let plane = Plane::bounded(f64::NEG_INFINITY, 0.0, -50.0, 50.0).unwrap();
    instance(Geometry::Plane(plane))
}

/// The contact for the region's centroid `g` and normal `n` (from the plane into the solid,
/// world frame) against the prism `x ≤ 0, z ≤ 0`: the prism's point where the line from `g`
/// along `n` leaves it (the nearer of its two planes), the solid's where the line along `−n`
/// leaves it (bisection on `inside`), or its closest point `closest` when `g` is outside.
fn half_expected(
    g: &Vector3,
    n: &Vector3,
    inside: impl Fn(&Vector3) -> bool,
    closest: impl Fn(&Vector3) -> Vector3,
    reach: f64,
    step: f64,
) -> Expected {
    let t = [(g.x, n.x), (g.z, n.z)]
        .iter()
        .filter(|(_, d)| *d > 0.0)
        .map(|(x, d)| -x / d)
        .fold(f64::INFINITY, f64::min);
    let point_j = Point3::from(g + t * n);
    let point_i = Point3::from(if inside(g) {
        crate::oracles::exit_by_bisection(&inside, g, &-n, reach, step)
    } else {
        closest(g)
    });
    Expected {
        point_i,
        point_j,
        normal: *n,
        depth: (point_i - point_j).norm(),
    }
}

/// An upright frustum, base centre at `(0, y0, −s)`, against the bounded plane `x ≤ 0`: the
/// half of the truncated cone of height `s` with `x ≤ 0`. The plane's surface inside is the
/// half disc `π r(s)²/2` (outward `+z`) and the side's trapezoid `2∫r` (outward `+x`);
/// the centroid has the whole cone's height and `x̄ = −(4/3π)∫r³/∫r²` (half discs).
fn half_frustum(r0: f64, r1: f64, len: f64, s: f64, y0: f64) -> Expected {
    let k = (r1 - r0) / len;
    let top = r0 + k * s;
    let n = Vector3::new(2.0 * (r0 * s + 0.5 * k * s * s), 0.5 * PI * top * top, 0.0);
    let n = Vector3::new(n.x, 0.0, n.y).normalize();
    let m0 = r0 * r0 * s + r0 * k * s * s + k * k * s.powi(3) / 3.0;
    let m1 = r0 * r0 * s * s / 2.0 + 2.0 * r0 * k * s.powi(3) / 3.0 + k * k * s.powi(4) / 4.0;
    let cubes = r0.powi(3) * s
        + 1.5 * r0 * r0 * k * s * s
        + r0 * k * k * s.powi(3)
        + k.powi(3) * s.powi(4) / 4.0;
    let g = Vector3::new(-4.0 / (3.0 * PI) * cubes / m0, y0, m1 / m0 - s);
    let inside = |w: &Vector3| {
        let z = w.z + s;
        z >= 0.0 && z <= len && w.x.hypot(w.y - y0) <= r0 + k * z
    };
    half_expected(&g, &n, inside, |p| *p, 4.0 * (r0 + r1 + len), 0.0)
}

/// A flat torus, centre at `(0, y0, −c)`, against the bounded plane `x ≤ 0`: half the annular
/// slab. Inside the plane: the half annulus `2πR√(r² − c²)` (outward `+z`) and the side's two
/// disc segments `2A` (outward `+x`); the centroid has the whole slab's height (Pappus) and
/// `x̄ = −2∫ρ² dA / (π∫ρ dA)` over the segment, `∫ρ dA = RA`, `∫ρ² dA = R²A + ∫u² dA`.
fn half_torus(big: f64, small: f64, c: f64, y0: f64) -> Expected {
    let r = small;
    let root = (r * r - c * c).sqrt();
    let area = r * r * (-c / r).acos() + c * root;
    let n = Vector3::new(2.0 * area, 0.0, 2.0 * PI * big * root).normalize();
    let f = |z: f64| {
        z / 8.0 * (5.0 * r * r - 2.0 * z * z) * (r * r - z * z).max(0.0).sqrt()
            + 3.0 * r.powi(4) / 8.0 * (z / r).clamp(-1.0, 1.0).asin()
    };
    let uu = 2.0 / 3.0 * (f(c) - f(-r));
    let x_bar = -2.0 * (big * big * area + uu) / (PI * big * area);
    let z_bar = -2.0 / 3.0 * root.powi(3) / area;
    let g = Vector3::new(x_bar, y0, z_bar - c);
    let local = move |w: &Vector3| Vector3::new(w.x, w.y - y0, w.z + c);
    let inside = |w: &Vector3| {
        let p = local(w);
        (p.xy().norm() - big).hypot(p.z) <= r
    };
    let closest = |w: &Vector3| {
        let p = local(w);
        let rho = p.xy().norm();
        let (rf, zf) = revolved_oracles::torus_foot(big, r, rho, p.z);
        let radial = p.xy() / rho;
        Vector3::new(radial.x * rf, radial.y * rf + y0, zf - c)
    };
    half_expected(&g, &n, inside, closest, 4.0 * (big + r), r / 64.0)
}

/// A rotation whose `z` axis is at least 12° from world z.
fn tilt(rng: &mut Rng) -> Option<UnitQuaternion> {
    let q = rng.rotation();
    ((q * Vector3::z()).z.abs() <= 0.2f64.cos()).then_some(q)
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
    let mut rows = box_rows(rng);
    rows.extend(frustum_plane_rows(rng));
    rows.extend(torus_ellipsoid_plane_rows(rng));
    rows.extend(mesh_rows(rng));
    rows
}

/// The rows of box–frustum, box–torus.
fn box_rows(rng: &mut Rng) -> Vec<Row> {
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
    ]
}

/// The rows of frustum–bounded plane.
fn frustum_plane_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        iterative(run(
            rng,
            SAMPLES,
            "frustum–bounded plane",
            "standing on its bottom inside the rectangle",
            "slicing across the axis; oracle: truncated cone (polynomial moments)",
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
            "frustum–bounded plane",
            "standing on its bottom, the rectangle's edge through its axis",
            "slicing across the axis; oracle: half truncated cone (polynomial moments)",
            |rng| {
                let (r0, r1, len) = (
                    rng.uniform(0.3, 1.5),
                    rng.uniform(0.0, 1.5),
                    rng.uniform(0.3, 2.0),
                );
                let sunk = rng.uniform(0.01, 0.99) * len;
                let y0 = rng.uniform(-1.0, 1.0);
                Some(Case {
                    i: instance(Geometry::Frustum(Frustum::new(r0, r1, len).unwrap())),
                    j: half_plane(),
                    pose_i: at(0.0, y0, -sunk),
                    pose_j: Isometry3::identity(),
                    expected: half_frustum(r0, r1, len, sunk, y0),
                    length: r0.max(r1).max(len),
                })
            },
        )),
    ]
}

/// The rows of torus–bounded plane, ellipsoid–bounded plane.
fn torus_ellipsoid_plane_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        iterative(run(
            rng,
            SAMPLES,
            "torus–bounded plane",
            "lying flat, the rectangle's edge through its axis",
            "slicing across the axis; oracle: half annular slab (segment moments)",
            |rng| {
                let Revolved::Torus { big, small } = random_torus(rng) else {
                    return None;
                };
                let c = rng.uniform(-0.95, 0.95) * small;
                let y0 = rng.uniform(-1.0, 1.0);
                Some(Case {
                    i: instance(Geometry::Torus(Torus::new(big, small).unwrap())),
                    j: half_plane(),
                    pose_i: at(0.0, y0, -c),
                    pose_j: Isometry3::identity(),
                    expected: half_torus(big, small, c, y0),
                    length: big + small,
                })
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
                let (s, q, z0) = ellipsoid_over_plane(rng);
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

/// The rows of frustum–mesh, cylinder–mesh, torus–mesh, ellipsoid–mesh.
fn mesh_rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        iterative(run(
            rng,
            SAMPLES,
            "frustum–mesh",
            "standing on its bottom in a box-shaped mesh (12 triangles), the top face cutting it",
            "slicing across the axis: mesh section chords and arcs; oracle: truncated cone (polynomial moments)",
            |rng| upright_frustum(rng, Ground::Mesh),
        )),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "frustum–mesh",
            "axis tilted ≥ 12° from the mesh's top face normal, other faces out of reach",
            "slicing across the axis: mesh section chords and arcs; oracle: Simpson over slices across the axis",
            |rng| {
                let solid = random_frustum(rng);
                let q = tilt(rng)?;
                tilted(rng, solid, q, Ground::Mesh)
            },
        )),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "cylinder–mesh",
            "axis tilted ≥ 12° from the mesh's top face normal, other faces out of reach",
            "closed form per convex part (the box-shaped mesh is one; sliced within 1e-3 of a face along the axis); oracle: Simpson over slices across the axis",
            |rng| {
                let (r, len) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 2.0));
                let q = tilt(rng)?;
                let mut case = tilted(
                    rng,
                    Revolved::Frustum { r0: r, r1: r, len },
                    q,
                    Ground::Mesh,
                )?;
                case.i = instance(Geometry::Cylinder(Cylinder::new(r, len).unwrap()));
                Some(case)
            },
        )),
        iterative(run(
            rng,
            SAMPLES,
            "torus–mesh",
            "lying flat in a box-shaped mesh (12 triangles), its top face cutting it",
            "slicing across the axis: mesh section chords and annulus arcs; oracle: Pappus (annular slab)",
            |rng| flat_torus(rng, Ground::Mesh),
        )),
        iterative(run(
            rng,
            SLICED_SAMPLES,
            "torus–mesh",
            "any tilt ≥ 12° from the mesh's top face normal, other faces out of reach",
            "slicing across the axis: mesh section chords and annulus arcs; oracle: Simpson over annulus slices",
            |rng| {
                let solid = random_torus(rng);
                let q = tilt(rng)?;
                tilted(rng, solid, q, Ground::Mesh)
            },
        )),
        iterative(run(
            rng,
            SAMPLES,
            "ellipsoid–mesh",
            "semi-axes ∈ [0.3, 2], any orientation, over a box-shaped mesh (12 triangles), cap to beyond the centre",
            "the mesh mapped onto the unit sphere and sliced; oracle: affine cap by slicing",
            |rng| {
                let (s, q, z0) = ellipsoid_over_plane(rng);
                let (j, pose_j) = ground(rng, Ground::Mesh, s.max());
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
