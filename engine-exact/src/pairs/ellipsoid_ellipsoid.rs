//! Two ellipsoids (a sphere against a general ellipsoid included), by slicing.
//!
//! Slicing frame: origin at `b`'s centre, `z` along the line of centres (from `b` to `a`;
//! `b`'s `+z` when the centres coincide). Each slice overlaps two ellipse sections in closed
//! form (`crate::methods::ellipsoid_sliced::disc_overlap`: the crossings are a quartic's roots), and
//! the slices are integrated between the intersection's lowest and highest `z`, found by
//! duality over the pencil of the two quadrics
//! (`crate::methods::ellipsoid_sliced::extent`); the pencil also proves the ellipsoids apart.
//! Converged to 1e-13 of the volume (round-off away from kinks); where the sections become
//! tangent inside that range the quadrature halves its pieces down to the kink.
//!
//! The contact follows [`crate::methods::volume_contact`]; when the area vector vanishes (one
//! ellipsoid inside the other, or identical ones) the normal is the line of centres (from
//! `b` to `a`), `b`'s `+z` for coincident centres.

use crate::kernel::PairContact;
use crate::methods::clipped::unit_for;
use crate::methods::ellipsoid_sliced::disc_overlap::{DiscOverlap, disc_ellipse};
use crate::methods::ellipsoid_sliced::extent::{Quadric, z_extent};
use crate::methods::ellipsoid_sliced::{
    COMPONENTS, Section, SlicedEllipsoid, curved_area, ellipsoid_exit_w, ellipsoid_in, integrand,
    integrate, shape_events, to_world,
};
use contact_core::{Isometry3, Vector3, WorkCounters};
use nalgebra::{Matrix3, Rotation3, Translation3, UnitQuaternion};

/// A rotation whose `z` axis is the unit `z`.
pub(crate) fn frame_with_z(z: &Vector3) -> UnitQuaternion<f64> {
    let helper = Vector3::ith(z.iamin(), 1.0);
    let x = helper.cross(z).normalize();
    let y = z.cross(&x);
    UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(Matrix3::from_columns(
        &[x, y, *z],
    )))
}

/// Contact of the ellipsoid with `semi_a` at `pose_a` with the one with `semi_b` at `pose_b`.
pub(crate) fn contact(
    semi_a: &Vector3,
    pose_a: &Isometry3,
    semi_b: &Vector3,
    pose_b: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let unit = unit_for(semi_a.max().max(semi_b.max()));
    let delta = pose_a.translation.vector - pose_b.translation.vector;
    let distance = delta.norm();
    let axis = if distance > 0.0 {
        delta / distance
    } else {
        pose_b.rotation * Vector3::z()
    };
    work.bounding_volume_tests += 1;
    if distance >= semi_a.max() + semi_b.max() {
        return None;
    }
    let moments = moments_along(semi_a, pose_a, semi_b, pose_b, &axis, unit, work)?;
    crate::methods::volume_contact::contact(
        &moments,
        |g, d| ellipsoid_exit_w(semi_a, pose_a, g, d),
        |g, d| ellipsoid_exit_w(semi_b, pose_b, g, d),
        || axis,
    )
}

/// The two sections at `z = t` and their overlap.
fn overlap(
    a: &SlicedEllipsoid,
    b: &SlicedEllipsoid,
    t: f64,
) -> Option<(Section, Section, DiscOverlap)> {
    let (sa, sb) = (a.section(t)?, b.section(t)?);
    let inverse = sa.matrix.try_inverse()?;
    let o = disc_ellipse(&(inverse * (sb.center - sa.center)), &(inverse * sb.matrix));
    Some((sa, sb, o))
}

/// The integrand at the slice `z = t`.
fn slice(a: &SlicedEllipsoid, b: &SlicedEllipsoid, t: f64) -> [f64; COMPONENTS] {
    match overlap(a, b, t) {
        Some((sa, sb, o)) => integrand(t, &sa, &o, curved_area(&sb, o.other_arcs.spans())),
        None => [0.0; COMPONENTS],
    }
}

/// The intersection's moments, sliced across `axis`.
fn moments_along(
    semi_a: &Vector3,
    pose_a: &Isometry3,
    semi_b: &Vector3,
    pose_b: &Isometry3,
    axis: &Vector3,
    unit: f64,
    work: &mut WorkCounters,
) -> Option<crate::methods::volume_contact::VolumeMoments> {
    let frame = Isometry3::from_parts(
        Translation3::from(pose_b.translation.vector),
        frame_with_z(axis),
    );
    let (ca, la) = ellipsoid_in(&frame, pose_a, semi_a, unit);
    let (cb, lb) = ellipsoid_in(&frame, pose_b, semi_b, unit);
    let a = SlicedEllipsoid::new(ca, &la)?;
    let b = SlicedEllipsoid::new(cb, &lb)?;
    let quadric = |e: &SlicedEllipsoid| Quadric {
        center: *e.center(),
        q: e.inverse().transpose() * e.inverse(),
    };
    let (lo, hi) = z_extent(&quadric(&a), &quadric(&b))?;
    let mut cuts = [0.0; 24];
    cuts[..2].copy_from_slice(&[lo, hi]);
    let mut n = 2;
    shape_events(
        lo,
        hi,
        |t| overlap(&a, &b, t).map_or(0, |(_, _, o)| o.shape),
        &mut cuts,
        &mut n,
    );
    let mut f = |t: f64| slice(&a, &b, t);
    let integrals = integrate(&mut cuts[..n], &mut f, work);
    Some(to_world(&integrals, &frame, unit))
}
