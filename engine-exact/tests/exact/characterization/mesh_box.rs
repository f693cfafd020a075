//! Characterization rows of the box against a closed mesh and of a mesh against a bounded
//! plane, against the closed form of grid-cell meshes and boxes aligned with their grid
//! ([`crate::voxel_oracle`]): an L-shaped bar, and a thick-walled square tube whose caps on
//! the box's faces are rings (a hole in each cap).

use super::{Case, Row, SAMPLES, at, run};
use crate::common::{Expected, Rng, instance};
use crate::voxel_oracle::{Aabb, Voxels};
use contact_core::geometry::{Cuboid, Plane};
use contact_core::{Geometry, Point3, Vector3};
use std::sync::Arc;

/// An L-shaped bar: five cells along x and two more along y from the first, two cells high
/// (unequal arms, so no centroid of the whole footprint lies on a wall or equally near two).
pub(crate) fn l_bar(size: f64) -> Voxels {
    let mut cells = Vec::new();
    for k in 0..2 {
        for i in 0..5 {
            cells.push([i, 0, k]);
        }
        for j in 1..3 {
            cells.push([0, j, k]);
        }
    }
    Voxels { cells, size }
}

/// A square tube along z: the ring of eight cells about (1, 1), four cells long.
pub(crate) fn tube(size: f64) -> Voxels {
    let mut cells = Vec::new();
    for k in 0..4 {
        for i in 0..3 {
            for j in 0..3 {
                if (i, j) != (1, 1) {
                    cells.push([i, j, k]);
                }
            }
        }
    }
    Voxels { cells, size }
}

/// The box `b` against the cells (the cells' frame is J's), when the answer is one regular
/// region.
fn box_case(voxels: &Voxels, b: Aabb, length: f64) -> Option<Case> {
    let found = voxels.contacts(&b);
    let [Some(expected)] = found.as_slice() else {
        return None;
    };
    let h = b.half();
    Some(Case {
        i: instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap())),
        j: instance(Geometry::Mesh(Arc::new(voxels.mesh()))),
        pose_i: at(b.centre().x, b.centre().y, b.centre().z),
        pose_j: at(0.0, 0.0, 0.0),
        expected: *expected,
        length,
    })
}

fn random_box(rng: &mut Rng, lo: [f64; 3], hi: [f64; 3], half: [f64; 2]) -> Aabb {
    let c = Point3::new(
        rng.uniform(lo[0], hi[0]),
        rng.uniform(lo[1], hi[1]),
        rng.uniform(lo[2], hi[2]),
    );
    let h = Vector3::new(
        rng.uniform(half[0], half[1]),
        rng.uniform(half[0], half[1]),
        rng.uniform(half[0], half[1]),
    );
    Aabb {
        lo: c - h,
        hi: c + h,
    }
}

pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    vec![
        run(
            rng,
            SAMPLES,
            "box–mesh",
            "an L-shaped bar of 14 cells, the box aligned with its grid at random, one region",
            "exact polyhedral intersection; oracle: cell–box overlaps (interval products)",
            |rng| {
                let b = random_box(rng, [-0.5, -0.5, -0.5], [5.5, 3.5, 2.5], [0.2, 1.5]);
                box_case(&l_bar(1.0), b, 5.0)
            },
        ),
        run(
            rng,
            SAMPLES,
            "box–mesh",
            "a thick-walled square tube cut across by a box wider than it on three sides (caps with holes)",
            "exact polyhedral intersection; oracle: cell–box overlaps (interval products)",
            |rng| {
                let mut b = random_box(rng, [1.2, 1.2, 0.8], [1.8, 1.8, 3.2], [0.3, 1.0]);
                b.lo.x = -rng.uniform(0.1, 0.5);
                // The bottom edge in the wall, so the centroid (in the hole, where the line
                // along the normal misses the tube) has one nearest wall.
                b.lo.y = rng.uniform(0.2, 0.8);
                b.hi.x = 3.0 + rng.uniform(0.1, 0.5);
                b.hi.y = 3.0 + rng.uniform(0.1, 0.5);
                box_case(&tube(1.0), b, 4.0)
            },
        ),
        run(
            rng,
            SAMPLES,
            "mesh–bounded plane",
            "the L-shaped bar sunk into a bounded plane whose rectangle cuts it",
            "exact polyhedral intersection on the plane's prism; oracle: cell–prism overlaps",
            |rng| {
                let voxels = l_bar(1.0);
                let sunk = rng.uniform(0.05, 1.9);
                let (x0, x1) = (rng.uniform(-1.0, 1.5), rng.uniform(1.5, 6.0));
                let (y0, y1) = (rng.uniform(-1.0, 0.8), rng.uniform(1.2, 4.0));
                // The plane's frame: the bar's cells from z = −sunk up.
                let prism = Aabb {
                    lo: Point3::new(x0, y0, sunk - 100.0),
                    hi: Point3::new(x1, y1, sunk),
                };
                let found = voxels.contacts(&prism);
                let [Some(e)] = found.as_slice() else {
                    return None;
                };
                // I is the mesh, J the plane: the box case swapped, moved to the plane's frame.
                let down = Vector3::new(0.0, 0.0, sunk);
                Some(Case {
                    i: instance(Geometry::Mesh(Arc::new(voxels.mesh()))),
                    j: instance(Geometry::Plane(Plane::bounded(x0, x1, y0, y1).unwrap())),
                    pose_i: at(0.0, 0.0, -sunk),
                    pose_j: at(0.0, 0.0, 0.0),
                    expected: Expected {
                        point_i: e.point_j - down,
                        point_j: e.point_i - down,
                        normal: -e.normal,
                        depth: e.depth,
                    },
                    length: 5.0,
                })
            },
        ),
    ]
}
