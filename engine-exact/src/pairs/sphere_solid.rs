//! A sphere against a box, cylinder, frustum or torus: closed form through the solid's
//! signed distance.
//!
//! With `c` the sphere's centre, `q` the point of the solid's surface closest to `c`, `n` the
//! solid's outward normal there and `s` the signed distance (`c − q = s·n`; `s < 0` inside):
//! - contact iff `s < r`; δ = `r − s`; normal `n` (from the solid into the sphere); points
//!   `c − r·n` on the sphere and `q` on the solid; area: the cap's base disc
//!   `π(r² − s²)` while the centre is outside, `π r²` inside.
//! - This is SPEC §4's centroid definition wherever the sphere meets one face, one curved
//!   side, or the torus' tube: the intersection's centroid then lies on the line through `c`
//!   along `n`. Where it meets an edge or a corner, the normal is the direction from the
//!   closest point to the centre, the continuous limit of the face answers on either side,
//!   which is the usual answer for a ball on an edge; the region's centroid lies slightly off
//!   that line.
//! - Centre inside the solid: `q` is the projection on the nearest face (ties: the first of
//!   +x, −x, +y, −y, +z, −z for a box; bottom, side, top for a cylinder or frustum).
//! - Centre on a cylinder's, frustum's or torus' axis (no radial direction): the radial
//!   direction is the solid's +x axis.
//! - A torus can be met in two places (a large ball across the ring, or a ball in the hole
//!   touching it all around): one contact, at the closest point, is returned.

pub(crate) use super::solid_distance::Solid;
use super::solid_distance::signed_distance;
use crate::kernel::PairContact;
use contact_core::{Isometry3, Point3};
use std::f64::consts::PI;

/// Contact of the sphere of `radius` at `pose_sphere` with `solid` at `pose_solid`.
pub(crate) fn contact(
    radius: f64,
    pose_sphere: &Isometry3,
    solid: &Solid,
    pose_solid: &Isometry3,
) -> Option<PairContact> {
    let centre = pose_solid.inverse_transform_point(&Point3::from(pose_sphere.translation.vector));
    let (s, q, n) = signed_distance(solid, &centre.coords);
    if s >= radius || !s.is_finite() {
        return None;
    }
    let normal = pose_solid.rotation * n;
    let c_w = pose_sphere.translation.vector;
    let area = if s >= 0.0 {
        PI * (radius - s) * (radius + s)
    } else {
        PI * radius * radius
    };
    Some(PairContact {
        point_a: Point3::from(c_w - radius * normal),
        point_b: pose_solid * Point3::from(q),
        normal,
        depth: radius - s,
        area,
    })
}
