//! Characterization rows of the sliced pairs: cylinder–cylinder, cylinder–box and a cylinder
//! on a bounded plane, against [`crate::sliced_oracles`].

use super::{CLOSED_FORM_BOUND, Case, ITERATIVE_BOUND, Row, run};
use crate::common::{Expected, Rng, instance};
use crate::sliced_oracles::{self as oracles, VolumeCentroid};
use contact_core::geometry::{Cuboid, Cylinder, Plane};
use contact_core::{Geometry, Isometry3, Matrix3, Point3, UnitQuaternion, Vector3};
use nalgebra::Translation3;

/// Quadrature-oracle rows are fewer: each sample integrates the volume seven times (the
/// gradient) in an unoptimized test build.
const ORACLE_SAMPLES: usize = 25;
const SAMPLES: usize = 100;
/// The rows whose oracle normal is a finite-difference gradient of a quadrature volume are
/// held to that oracle's own accuracy: a central difference over ±1e-3 of the pair's size,
/// extrapolated twice, still feels the kinks of `V(δ)` where a translation moves an edge
/// across a face (measured 1e-7 to 5e-7 on the normal). The engine itself is held closer by
/// the closed-form rows above, by the I/J exchange in `properties`, and (crossed cylinders)
/// by its unit tests against the polygon slicing perpendicular to both axes (1e-9; measured
/// 4.6e-13 on the normal over 300 poses).
pub(super) const GRADIENT_ORACLE_BOUND: f64 = 1e-6;

fn cylinder(r: f64, l: f64) -> Geometry {
    Geometry::Cylinder(Cylinder::new(r, l).unwrap())
}

/// The pose of a cylinder (geometry frame at its bottom centre) with centre `c` and axis
/// `axis`.
pub(crate) fn centred_pose(c: &Vector3, axis: &Vector3, half_length: f64) -> Isometry3 {
    let q = UnitQuaternion::rotation_between(&Vector3::z(), axis).unwrap_or_else(|| {
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
    });
    Isometry3::from_parts(Translation3::from(c - axis * half_length), q)
}

/// The expected contact from an oracle's volume (as a function of `b`'s translation),
/// with the exits of `a` and `b` along the normal.
fn from_volume(
    volume: impl Fn(&Vector3) -> Option<VolumeCentroid>,
    scale: f64,
    exit_a: impl Fn(&Point3, &Vector3) -> Point3,
    exit_b: impl Fn(&Point3, &Vector3) -> Point3,
) -> Option<Expected> {
    let at_rest = volume(&Vector3::zeros())?;
    // Slivers make the normal ill-conditioned for the finite differences.
    if at_rest.volume < 1e-3 * scale.powi(3) {
        return None;
    }
    let s = oracles::minus_gradient(|d| volume(d).map_or(0.0, |v| v.volume), 1e-3 * scale);
    let n = -s / s.norm();
    let g = at_rest.centroid;
    let (point_i, point_j) = (exit_a(&g, &-n), exit_b(&g, &n));
    Some(Expected {
        point_i,
        point_j,
        normal: n,
        depth: (point_j - point_i).norm(),
    })
}

/// The rows, in table order.
pub(super) fn rows(rng: &mut Rng) -> Vec<Row> {
    let iterative = |row: Row| Row {
        bound: ITERATIVE_BOUND,
        ..row
    };
    let closed_form = |row: Row| Row {
        bound: CLOSED_FORM_BOUND,
        ..row
    };
    let gradient = |row: Row| Row {
        bound: GRADIENT_ORACLE_BOUND,
        ..row
    };
    vec![
        closed_form(run(
            rng,
            SAMPLES,
            "cylinder–cylinder",
            "parallel axes, lens × axial overlap, caps inside or not",
            "closed form (lens × overlap); oracle: segments by acos",
            |rng| parallel(rng, 0.0),
        )),
        iterative(run(
            rng,
            SAMPLES,
            "cylinder–cylinder",
            "axes 1e-12 rad from parallel",
            "slicing; oracle: the parallel closed form",
            |rng| parallel(rng, 1e-12),
        )),
        gradient(run(
            rng,
            ORACLE_SAMPLES,
            "cylinder–cylinder",
            "crossed and skew axes (≥ 0.05 rad apart), any offset",
            "divergence theorem, lateral fluxes; oracle: strips quadrature, S = −∂V/∂x_b",
            crossed,
        )),
        closed_form(run(
            rng,
            SAMPLES,
            "cylinder–box",
            "a face parallel to the axis cutting the side",
            "closed form (disc ∩ section × overlap); oracle: circular segment × length",
            |rng| segment_case(rng, false, false),
        )),
        closed_form(run(
            rng,
            SAMPLES,
            "cylinder–box",
            "a face across the cap, another cutting the side",
            "closed form (disc ∩ section × overlap); oracle: disc part × overlap",
            |rng| segment_case(rng, true, false),
        )),
        closed_form(run(
            rng,
            SAMPLES,
            "cylinder–box",
            "any orientation and offset",
            "closed form (divergence theorem; slicing within 1e-3 of a face along the axis); \
             oracle: disc ∩ polygon slices along the axis, S by quadrature around the side",
            tilted_box,
        )),
        iterative(run(
            rng,
            SAMPLES,
            "cylinder–bounded plane",
            "the plane's edge across the sunk cylinder",
            "slicing; oracle: circular segment × depth",
            |rng| segment_case(rng, true, true),
        )),
    ]
}

fn parallel(rng: &mut Rng, tilt: f64) -> Option<Case> {
    let (ra, rb) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 1.5));
    let (la, lb) = (rng.uniform(0.5, 3.0), rng.uniform(0.5, 3.0));
    let d = rng.uniform((ra - rb).abs() + 0.02, ra + rb - 0.02);
    let zb = rng.uniform(-lb + 0.05, la - 0.05);
    let expected = oracles::parallel_cylinders(ra, la, rb, zb, lb, d);
    // b's axis tilted by `tilt` about the line of centres' normal, through b's mid-axis.
    let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt);
    let mid = Vector3::new(d, 0.0, zb + 0.5 * lb);
    let pose_j = Isometry3::from_parts(
        Translation3::from(mid - q * Vector3::new(0.0, 0.0, 0.5 * lb)),
        q,
    );
    Some(Case {
        i: instance(cylinder(ra, la)),
        j: instance(cylinder(rb, lb)),
        pose_i: Isometry3::identity(),
        pose_j,
        expected,
        length: ra.max(rb).max(la).max(lb),
    })
}

pub(super) fn crossed(rng: &mut Rng) -> Option<Case> {
    let (ra, rb) = (rng.uniform(0.3, 1.5), rng.uniform(0.3, 1.5));
    let (ha, hb) = (rng.uniform(0.3, 2.0), rng.uniform(0.3, 2.0));
    let axis = rng.unit_vector();
    if axis.z.abs() > 0.05f64.cos() {
        return None;
    }
    let cb = Vector3::new(
        rng.uniform(-ra - rb, ra + rb),
        rng.uniform(-ra - rb, ra + rb),
        rng.uniform(-ha - rb, ha + rb),
    );
    let scale = ra.max(rb).max(ha).max(hb);
    let pose_b = centred_pose(&cb, &axis, hb);
    let expected = from_volume(
        |d| oracles::crossed_cylinders_volume(ra, ha, rb, hb, &(cb + d), &axis),
        scale,
        |g, n| oracles::cylinder_ray(ra, -ha, ha, g, n),
        |g, n| {
            let local = Isometry3::from_parts(Translation3::from(cb), pose_b.rotation);
            local
                * oracles::cylinder_ray(
                    rb,
                    -hb,
                    hb,
                    &local.inverse_transform_point(g),
                    &local.inverse_transform_vector(n),
                )
        },
    )?;
    Some(Case {
        i: instance(cylinder(ra, 2.0 * ha)),
        j: instance(cylinder(rb, 2.0 * hb)),
        pose_i: Isometry3::translation(0.0, 0.0, -ha),
        pose_j: pose_b,
        expected,
        length: scale,
    })
}

/// The cylinder (z from 0 to l) against the box `x ≥ c` (rotated about the axis by a random
/// angle): the side cut only, the cap too (`cap`), or the same as a bounded plane's prism
/// (`plane`: top at `z1`, edge along `x = c`).
fn segment_case(rng: &mut Rng, cap: bool, plane: bool) -> Option<Case> {
    let r = rng.uniform(0.3, 1.5);
    let l = rng.uniform(0.5, 3.0);
    let c = rng.uniform(-0.95, 0.95) * r;
    let (z0, z1) = if cap || plane {
        (-l, rng.uniform(0.05, 0.95) * l)
    } else {
        let z0 = rng.uniform(-0.5, 0.5) * l;
        (z0, z0 + l * rng.uniform(0.6, 1.5))
    };
    let (z0, z1) = if cap && !plane {
        (l - z1, 2.0 * l)
    } else {
        (z0, z1)
    };
    let (expected, centre, half) = oracles::cylinder_box_segment(r, l, c, z0, z1);
    let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(0.0, 6.3));
    let expected = expected.moved(&Isometry3::from_parts(Translation3::identity(), spin));
    let (j, pose_j) = if plane {
        (
            Geometry::Plane(
                Plane::bounded(c, f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY).unwrap(),
            ),
            Isometry3::from_parts(Translation3::from(spin * Vector3::new(0.0, 0.0, z1)), spin),
        )
    } else {
        (
            Geometry::Cuboid(Cuboid::centered(half.x, half.y, half.z).unwrap()),
            Isometry3::from_parts(Translation3::from(spin * centre), spin),
        )
    };
    Some(Case {
        i: instance(cylinder(r, l)),
        j: instance(j),
        pose_i: Isometry3::identity(),
        pose_j,
        expected,
        length: r.max(l),
    })
}

fn tilted_box(rng: &mut Rng) -> Option<Case> {
    let r = rng.uniform(0.3, 1.5);
    let l = rng.uniform(0.5, 3.0);
    let h = Vector3::new(
        rng.uniform(0.2, 1.5),
        rng.uniform(0.2, 1.5),
        rng.uniform(0.2, 1.5),
    );
    let q = rng.rotation();
    let axes: Matrix3 = q.to_rotation_matrix().into_inner();
    let c = Vector3::new(
        rng.uniform(-r - h.max(), r + h.max()),
        rng.uniform(-r - h.max(), r + h.max()),
        rng.uniform(-h.max(), l + h.max()),
    );
    let scale = r.max(l).max(h.norm());
    let at_rest = oracles::cylinder_box_volume(r, l, &c, &axes, &h, 1e-14 * scale.powi(3))?;
    // A sliver's centroid is the quadrature's tolerance over its volume: here at most
    // 1e-11 of the size (the rule converges far below its tolerance: 2e-14 measured).
    if at_rest.volume < 1e-3 * scale.powi(3) {
        return None;
    }
    let s = oracles::cylinder_box_area_vector(r, l, &c, &axes, &h);
    let n = -s / s.norm();
    let g = at_rest.centroid;
    let frame = Isometry3::from_parts(Translation3::from(c), q);
    let point_i = oracles::cylinder_ray(r, 0.0, l, &g, &-n);
    let point_j = frame
        * oracles::box_ray(
            &Vector3::zeros(),
            &h,
            &frame.inverse_transform_point(&g),
            &frame.inverse_transform_vector(&n),
        );
    let expected = Expected {
        point_i,
        point_j,
        normal: n,
        depth: (point_j - point_i).norm(),
    };
    Some(Case {
        i: instance(cylinder(r, l)),
        j: instance(Geometry::Cuboid(Cuboid::centered(h.x, h.y, h.z).unwrap())),
        pose_i: Isometry3::identity(),
        pose_j: Isometry3::from_parts(Translation3::from(c), q),
        expected,
        length: scale,
    })
}
