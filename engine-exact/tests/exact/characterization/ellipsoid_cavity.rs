//! Characterization rows of ellipsoids and balls in cylinder- and frustum-shaped cavities
//! (flipped cylinders and frustums), held to the iterative bound 1e-9:
//! - an ellipsoid through one end of the cavity, its sections elsewhere inside: the region
//!   is the cap beyond the end's plane, the affine image of a unit sphere's cap
//!   ([`crate::ellipsoid_cavity::ellipsoid_cap`]), the normal the end's, the points on the
//!   line through the cap's centroid;
//! - a ball pressed into a long bore's wall: by symmetry the normal is radial, the points
//!   lie on the radial line through the centre, and δ = d + r − R;
//! - a prolate spheroid in a spherical cavity, its far end in the wall, and a ball in a
//!   general ellipsoid cavity on one of its axes: symmetric about that axis (or about two
//!   planes through it), so the normal is the axis and the points its ends;
//! - a ball in a torus' tube (a toroidal groove) on the tube's equator, pressed outward or
//!   inward: symmetric about its meridian plane and the equator's, so the normal is radial
//!   and δ = e + r − ρ.

use super::{Case, ITERATIVE_BOUND, Row, run};
use crate::common::{Expected, Rng, instance};
use crate::ellipsoid_cavity::{ellipsoid_cap, ellipsoid_exit_of};
use contact_core::geometry::{Cylinder, Ellipsoid, Frustum, Torus};
use contact_core::{Geometry, Isometry3, Point3, Vector3};
use nalgebra::{Matrix3, Translation3, UnitQuaternion};
use std::f64::consts::{PI, TAU};

/// Samples of each row.
const SAMPLES: usize = 40;

fn iterative(row: Row) -> Row {
    Row {
        bound: ITERATIVE_BOUND,
        ..row
    }
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let bore = Geometry::Cylinder(Cylinder::new(1.0, 3.0).unwrap());
    let cone = Geometry::Frustum(Frustum::new(1.2, 0.7, 3.0).unwrap());
    vec![
        iterative(run(
            rng,
            SAMPLES,
            "ellipsoid in a cylinder cavity",
            "semi-axes 0.3–0.6, 0.3–0.6, 0.8–1.2 tilted up to 0.3 rad, through the top end of a bore R = 1, L = 3, its sides clear of the wall",
            "slicing along the cavity's axis, lunes per region",
            |rng| through_end(rng, &bore, |_| 1.0),
        )),
        iterative(run(
            rng,
            SAMPLES,
            "ellipsoid in a frustum cavity",
            "the same through the narrow end of a conical cavity r₀ = 1.2, r₁ = 0.7, L = 3",
            "slicing along the cavity's axis, lunes per region",
            |rng| through_end(rng, &cone, |z| 1.2 - 0.5 * z / 3.0),
        )),
        iterative(run(
            rng,
            SAMPLES,
            "sphere in a cylinder cavity",
            "r ∈ [0.3, 0.8] pressed 1e-3 r to 0.2 r into the wall of a bore R = 1, L = 6, mid-length",
            "slicing along the cavity's axis, lunes per region",
            pressed_ball,
        )),
        iterative(run(
            rng,
            SAMPLES,
            "ellipsoid in a spherical cavity",
            "spheroid a ∈ [1.1, 1.5], b ∈ [0.2, 0.6] in a socket R = 1, off-centre along its axis so only its far end reaches the wall",
            "slicing along the cavity's axis, lunes per region",
            spheroid_in_socket,
        )),
        iterative(run(
            rng,
            SAMPLES,
            "sphere in an ellipsoid cavity",
            "r ∈ [0.2, 0.4] on an axis of a cavity with semi-axes 1, 0.7, 0.5, pressed 1e-3 r to 0.3 r into its wall",
            "slicing along the cavity's axis, lunes per region",
            ball_in_ellipsoid,
        )),
        iterative(run(
            rng,
            SAMPLES,
            "sphere in a torus cavity",
            "r ∈ [0.1, 0.25] in a groove R = 1, ρ = 0.3 on its equator, pressed 1e-3 r to 0.2 r into the outer or the inner wall",
            "slicing along the cavity's axis, lunes and the hole's part per region",
            ball_in_groove,
        )),
    ]
}

/// A ball in the tube of the torus R = 1, ρ = 0.3 on its equator at a random azimuth, `e`
/// from the core circle outward or inward.
fn ball_in_groove(rng: &mut Rng) -> Option<Case> {
    let (big, small) = (1.0, 0.3);
    let r = rng.uniform(0.1, 0.25);
    let e = small - r + r * 10f64.powf(rng.uniform(-3.0, -0.7));
    let sign = if rng.uniform(0.0, 1.0) < 0.5 {
        -1.0
    } else {
        1.0
    };
    let azimuth = rng.uniform(0.0, TAU);
    let radial = Vector3::new(azimuth.cos(), azimuth.sin(), 0.0);
    Some(Case {
        i: instance(Geometry::sphere(r).unwrap()),
        j: instance(Geometry::Torus(Torus::new(big, small).unwrap())).flipped(),
        pose_i: Isometry3::from_parts(
            Translation3::from((big + sign * e) * radial),
            rng.rotation(),
        ),
        pose_j: Isometry3::identity(),
        expected: Expected {
            point_i: Point3::from((big + sign * (e + r)) * radial),
            point_j: Point3::from((big + sign * small) * radial),
            normal: -sign * radial,
            depth: e + r - small,
        },
        length: big + small,
    })
}

/// A prolate spheroid in a unit socket along a random axis, moved along it so that its far
/// end is `e` into the wall and its near end clear.
fn spheroid_in_socket(rng: &mut Rng) -> Option<Case> {
    let (a, b) = (rng.uniform(1.1, 1.5), rng.uniform(0.2, 0.6));
    let e = rng.uniform(0.01, 0.3);
    let c = 1.0 + e - a;
    if c - a <= -1.0 + 0.05 || a <= 1.0 || b >= 1.0 {
        return None;
    }
    let turn = rng.rotation();
    let axis = turn * Vector3::x();
    Some(Case {
        i: instance(Geometry::Ellipsoid(Ellipsoid::new(a, b, b).unwrap())),
        j: instance(Geometry::sphere(1.0).unwrap()).flipped(),
        pose_i: Isometry3::from_parts(Translation3::from(c * axis), turn),
        pose_j: Isometry3::identity(),
        expected: Expected {
            point_i: Point3::from((c + a) * axis),
            point_j: Point3::from(axis),
            normal: -axis,
            depth: e,
        },
        length: 1.0,
    })
}

/// A ball on one axis of the cavity with semi-axes (1, 0.7, 0.5), pressed into the wall
/// there (its other points clear: the ball's radius under the wall's curvature radius).
fn ball_in_ellipsoid(rng: &mut Rng) -> Option<Case> {
    let semi = Vector3::new(1.0, 0.7, 0.5);
    let k = (rng.uniform(0.0, 3.0) as usize).min(2);
    let r = rng.uniform(0.2, 0.4);
    let e = r * 10f64.powf(rng.uniform(-3.0, -0.5));
    let sign = if rng.uniform(0.0, 1.0) < 0.5 {
        -1.0
    } else {
        1.0
    };
    let axis = Vector3::ith(k, sign);
    // Clear elsewhere: the ball's radius below the wall's smallest curvature radius there.
    let radius_of_curvature = (0..3)
        .filter(|&j| j != k)
        .map(|j| semi[j] * semi[j] / semi[k])
        .fold(f64::INFINITY, f64::min);
    if r >= radius_of_curvature {
        return None;
    }
    let d = semi[k] - r + e;
    Some(Case {
        i: instance(Geometry::sphere(r).unwrap()),
        j: instance(Geometry::Ellipsoid(
            Ellipsoid::new(semi.x, semi.y, semi.z).unwrap(),
        ))
        .flipped(),
        pose_i: Isometry3::from_parts(Translation3::from(d * axis), rng.rotation()),
        pose_j: Isometry3::identity(),
        expected: Expected {
            point_i: Point3::from((d + r) * axis),
            point_j: Point3::from(semi[k] * axis),
            normal: -axis,
            depth: e,
        },
        length: 1.0,
    })
}

/// An ellipsoid through the top end (`z = 3`) of the cavity `geometry` of radius `radius(z)`,
/// or `None` when a sampled surface point between the ends reaches within 2% of the wall.
fn through_end(rng: &mut Rng, geometry: &Geometry, radius: impl Fn(f64) -> f64) -> Option<Case> {
    let semi = Vector3::new(
        rng.uniform(0.3, 0.6),
        rng.uniform(0.3, 0.6),
        rng.uniform(0.8, 1.2),
    );
    let tilt = UnitQuaternion::from_scaled_axis(rng.unit_vector() * rng.uniform(0.0, 0.3));
    let c = Vector3::new(
        rng.uniform(-0.1, 0.1),
        rng.uniform(-0.1, 0.1),
        3.0 - rng.uniform(0.1, 0.8) * semi.z,
    );
    let l = tilt.to_rotation_matrix().matrix() * Matrix3::from_diagonal(&semi);
    let clear = (0..400).all(|k| {
        let th = TAU * k as f64 / 400.0;
        (0..24).all(|j| {
            let ph = PI * j as f64 / 23.0;
            let p = c + l * Vector3::new(ph.sin() * th.cos(), ph.sin() * th.sin(), ph.cos());
            p.z >= 3.0 || (p.z > 0.0 && p.xy().norm() < 0.98 * radius(p.z))
        })
    });
    if !clear {
        return None;
    }
    let (g, _) = ellipsoid_cap(&c, &l, 3.0, true);
    let normal = -Vector3::z();
    Some(Case {
        i: instance(Geometry::Ellipsoid(
            Ellipsoid::new(semi.x, semi.y, semi.z).unwrap(),
        )),
        j: instance(geometry.clone()).flipped(),
        pose_i: Isometry3::from_parts(Translation3::from(c), tilt),
        pose_j: Isometry3::identity(),
        expected: Expected {
            point_i: ellipsoid_exit_of(&c, &l, &g, &-normal),
            point_j: Point3::new(g.x, g.y, 3.0),
            normal,
            depth: ellipsoid_exit_of(&c, &l, &g, &-normal).z - 3.0,
        },
        length: 3.0,
    })
}

/// A ball pressed into a long bore's wall at a random azimuth and height.
fn pressed_ball(rng: &mut Rng) -> Option<Case> {
    let r = rng.uniform(0.3, 0.8);
    let d = 1.0 - r + r * 10f64.powf(rng.uniform(-3.0, -0.7));
    let azimuth = rng.uniform(0.0, TAU);
    let radial = Vector3::new(azimuth.cos(), azimuth.sin(), 0.0);
    let z = rng.uniform(2.0, 4.0);
    Some(Case {
        i: instance(Geometry::sphere(r).unwrap()),
        j: instance(Geometry::Cylinder(Cylinder::new(1.0, 6.0).unwrap())).flipped(),
        pose_i: Isometry3::from_parts(
            Translation3::from(d * radial + Vector3::new(0.0, 0.0, z)),
            rng.rotation(),
        ),
        pose_j: Isometry3::identity(),
        expected: Expected {
            point_i: Point3::from((d + r) * radial + Vector3::new(0.0, 0.0, z)),
            point_j: Point3::from(radial + Vector3::new(0.0, 0.0, z)),
            normal: -radial,
            depth: d + r - 1.0,
        },
        length: 6.0,
    })
}
