//! Sphere against an unbounded plane: closed form.
//!
//! With `c` the sphere's centre, `n` the plane's outward normal and `d = n·(c − o)` the
//! centre's height above the plane:
//! - contact iff `d < r`; δ = `r − d` exactly;
//! - the cap's centroid lies on the line `c − s·n`, so the surface points along `n` are the
//!   sphere's lowest point `c − r·n` and the foot `c − d·n` on the plane;
//! - area = the cap's base disc `π(r² − d²)` for `d ≥ 0`; once the centre is below the plane
//!   the projected region is the sphere's full disc `π r²` (continuous at `d = 0`);
//! - full immersion (`d ≤ −r`) continues the same formulas: δ = `r − d`.
//!
//! A flipped plane (`side = −1`) reverses `n`: the material then lies above the plane.

use crate::kernel::PairContact;
use contact_core::{Isometry3, Vector3};
use std::f64::consts::PI;

/// Contact of the sphere of `radius` at `pose_sphere` with the plane at `pose_plane`.
pub(crate) fn contact(
    radius: f64,
    pose_sphere: &Isometry3,
    pose_plane: &Isometry3,
    side: f64,
) -> Option<PairContact> {
    let center = pose_sphere.translation.vector;
    let normal = side * (pose_plane.rotation * Vector3::z());
    let d = normal.dot(&(center - pose_plane.translation.vector));
    if d >= radius {
        return None;
    }
    let area = if d >= 0.0 {
        PI * (radius - d) * (radius + d)
    } else {
        PI * radius * radius
    };
    Some(PairContact {
        point_a: (center - radius * normal).into(),
        point_b: (center - d * normal).into(),
        normal,
        depth: radius - d,
        area,
    })
}
