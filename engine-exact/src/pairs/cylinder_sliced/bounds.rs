//! The slicing's bounds for each solid `b` the cylinder is sliced against: `b`'s faces (and a
//! cylinder's sides) as [`Bound`]s in the working frame F, its extent along the slicing
//! direction, and the slice positions where the section changes form (its events). Each
//! first rejects a `b` apart from the cylinder's bounding box.

use super::{Obb, Placed, separated};
use crate::methods::sliced::{Bound, SlicedPair};
use contact_core::geometry::{Cuboid, Cylinder, Plane};
use contact_core::{Matrix3, Point3, Vector3, WorkCounters};

/// A second cylinder `c`: its two sides and two caps, its range `t0 ± r` and its rim and
/// side events; `None` when its bounding box is apart from `box_a` (the first cylinder's).
/// `frame` holds F's axes in `a`'s frame.
pub(super) fn cylinder(
    pair: &mut SlicedPair,
    c: &Cylinder,
    frame: &Matrix3,
    box_a: &Obb,
    placed: &Placed,
    work: &mut WorkCounters,
) -> Option<()> {
    let Placed {
        unit,
        pose_ab,
        rot_ab,
        centre_a,
        ..
    } = *placed;
    let to_f = |p: &Vector3| frame.tr_mul(&(p - centre_a)) / unit;
    let dir_f = |v: &Vector3| frame.tr_mul(v);
    let (r, hl) = (c.radius() / unit, 0.5 * c.length() / unit);
    let centre = to_f(&(pose_ab * Point3::new(0.0, 0.0, 0.5 * c.length())).coords);
    let axis = dir_f(&rot_ab.column(2).into_owned());
    // On the slicing planes (a change at round-off; see the module docs).
    let (alpha, beta) = (axis.y, axis.z);
    let norm = alpha.hypot(beta);
    let (alpha, beta) = (alpha / norm, beta / norm);
    let across = contact_core::Vector2::new(-beta, alpha);
    let along = contact_core::Vector2::new(alpha, beta);
    let box_b = (
        centre,
        Matrix3::from_columns(&[
            Vector3::x(),
            Vector3::new(0.0, across.x, across.y),
            Vector3::new(0.0, alpha, beta),
        ]),
        Vector3::new(r, r, hl),
    );
    work.bounding_volume_tests += 1;
    if separated(box_a, &box_b) {
        return None;
    }
    let centre_across = across.dot(&centre.yz());
    let centre_along = along.dot(&centre.yz());
    for (k, sign) in [1.0, -1.0].into_iter().enumerate() {
        pair.bounds[k] = Bound::Side {
            across,
            centre: centre_across,
            sign,
            t0: centre.x,
            radius: r,
        };
        pair.bounds[2 + k] = Bound::Plane {
            normal: Vector3::new(0.0, sign * alpha, sign * beta),
            offset: sign * centre_along + hl,
        };
    }
    pair.bound_count = 4;
    pair.range_b = (centre.x - r, centre.x + r);
    pair.push_cut(centre.x - r);
    pair.push_cut(centre.x + r);
    pair.add_rim_plane_events();
    pair.add_cylinder_events(&centre, &Vector3::new(0.0, alpha, beta), r, hl);
    Some(())
}

/// A box `c`: its six faces, its range over its corners and its corner and edge events;
/// `None` when it is apart from `box_a` (the cylinder's bounding box). `frame` holds F's
/// axes in `a`'s frame.
pub(super) fn cuboid(
    pair: &mut SlicedPair,
    c: &Cuboid,
    frame: &Matrix3,
    box_a: &Obb,
    placed: &Placed,
    work: &mut WorkCounters,
) -> Option<()> {
    let Placed {
        unit,
        pose_ab,
        rot_ab,
        centre_a,
        ..
    } = *placed;
    let to_f = |p: &Vector3| frame.tr_mul(&(p - centre_a)) / unit;
    let centre = to_f(&(pose_ab * c.center()).coords);
    let axes = frame.tr_mul(&rot_ab);
    let half = c.half_extents() / unit;
    work.bounding_volume_tests += 1;
    if separated(box_a, &(centre, axes, half)) {
        return None;
    }
    for k in 0..3 {
        let axis = axes.column(k).into_owned();
        for (s, sign) in [1.0, -1.0].into_iter().enumerate() {
            pair.bounds[2 * k + s] = Bound::Plane {
                normal: sign * axis,
                offset: sign * axis.dot(&centre) + half[k],
            };
        }
    }
    pair.bound_count = 6;
    let mut range = (f64::INFINITY, f64::NEG_INFINITY);
    let mut corners = [Vector3::zeros(); 8];
    for (v, corner) in corners.iter_mut().enumerate() {
        let s = |bit: usize| if v & (1 << bit) != 0 { 1.0 } else { -1.0 };
        *corner = centre + axes * Vector3::new(s(0) * half.x, s(1) * half.y, s(2) * half.z);
        range = (range.0.min(corner.x), range.1.max(corner.x));
    }
    pair.range_b = range;
    // The twelve edges: along each axis, from the corners with that bit clear.
    let mut edges = [(Vector3::zeros(), Vector3::zeros()); 12];
    let mut count = 0;
    for k in 0..3 {
        for (v, corner) in corners.iter().enumerate() {
            if v & (1 << k) == 0 {
                edges[count] = (*corner, axes.column(k).into_owned());
                count += 1;
            }
        }
    }
    pair.add_polyhedron_events(&corners, &edges);
    pair.add_rim_plane_events();
    Some(())
}

/// A bounded plane's prism (`placed`'s prism planes over `plane`'s rectangle): its faces, and the
/// events of its top's edges, corners and vertical edges; `None` when the cylinder lies
/// outside one of its planes (`box_a` the cylinder's bounding box). `frame` holds F's axes in
/// `a`'s frame.
pub(super) fn prism(
    pair: &mut SlicedPair,
    plane: &Plane,
    frame: &Matrix3,
    box_a: &Obb,
    placed: &Placed,
    work: &mut WorkCounters,
) -> Option<()> {
    let Placed {
        unit,
        pose_ab,
        rot_ab,
        centre_a,
        ..
    } = *placed;
    let planes = placed.prism();
    let to_f = |p: &Vector3| frame.tr_mul(&(p - centre_a)) / unit;
    let to_world_f = frame.tr_mul(&rot_ab);
    let origin = to_f(&pose_ab.translation.vector);
    for (k, h) in planes.iter().enumerate() {
        let normal = to_world_f * h.normal;
        pair.bounds[k] = Bound::Plane {
            normal,
            offset: normal.dot(&origin) + h.offset / unit,
        };
    }
    pair.bound_count = planes.len();
    work.bounding_volume_tests += 1;
    // The cylinder's lowest point along each prism plane's normal: outside one, apart.
    let apart = pair.bounds[..planes.len()]
        .iter()
        .any(|bound| match *bound {
            Bound::Plane { normal, offset } => {
                let reach = box_a.2.x * normal.x.hypot(normal.y) + box_a.2.z * normal.z.abs();
                -reach >= offset
            }
            Bound::Side { .. } => false,
        });
    if apart {
        return None;
    }
    let [x0, x1] = plane.x_range();
    let [y0, y1] = plane.y_range();
    let at = |x: f64, y: f64| origin + to_world_f * Vector3::new(x, y, 0.0) / unit;
    let (dx, dy, dz) = (
        to_world_f.column(0).into_owned(),
        to_world_f.column(1).into_owned(),
        to_world_f.column(2).into_owned(),
    );
    let mut corners = [Vector3::zeros(); 4];
    let mut corner_count = 0;
    // The prism's edges: the top's edges (lines along y at a finite x bound, along
    // x at a finite y bound) and the vertical edges down from the top's corners.
    let mut edges = [(Vector3::zeros(), Vector3::zeros()); 8];
    let mut edge_count = 0;
    for x in [x0, x1].into_iter().filter(|x| x.is_finite()) {
        edges[edge_count] = (at(x, 0.0), dy);
        edge_count += 1;
    }
    for y in [y0, y1].into_iter().filter(|y| y.is_finite()) {
        edges[edge_count] = (at(0.0, y), dx);
        edge_count += 1;
    }
    for x in [x0, x1] {
        for y in [y0, y1] {
            if x.is_finite() && y.is_finite() {
                corners[corner_count] = at(x, y);
                edges[edge_count] = (at(x, y), dz);
                corner_count += 1;
                edge_count += 1;
            }
        }
    }
    pair.add_polyhedron_events(&corners[..corner_count], &edges[..edge_count]);
    pair.add_rim_plane_events();
    Some(())
}
