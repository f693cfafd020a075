//! A sphere against a box, cylinder, frustum or torus: SPEC §4's definition, by a closed form
//! where the intersection is symmetric about the line through the sphere's centre along the
//! solid's normal, and otherwise by the general ellipsoid slicings with equal semi-axes.
//!
//! ## The fast path (`fast_path`)
//! With `c` the sphere's centre (radius `r`) in the solid's frame, one flat face or a
//! cylinder's side with outward normal `n` and `d` the centre's signed height above it
//! (`|d| < r`), the fast path answers when the intersection is exactly the ball cut by that
//! one surface, i.e. the part of the ball behind it lies inside every other face:
//! - **box face**: `c` projects inside the face with a margin: `|c_j| + a ≤ h_j` on the two
//!   other axes, `a = √(r² − d²)` (the cap's base radius) when `d ≥ 0` and `a = r` when the
//!   centre is inside, and the ball does not reach the opposite face;
//! - **cylinder side**: `ρ = |c_xy| > 0`, the region's height `c_z ± a` (`a` as above, with
//!   `d = ρ − R`) within `[0, L]`, and `r² ≤ ρ² + R²` (the ball wraps at most a quarter turn
//!   on each side of `c`'s azimuth, where the area's periodic quadrature below is at
//!   round-off with 24 nodes);
//! - **cylinder or frustum cap**: `ρ + a ≤` the solid's radius over the heights the region
//!   spans (for a frustum the smaller of the cap's radius and the radius at the region's far
//!   end, the radius being linear), and the ball does not reach the other cap.
//!
//! The region is then the ball cut by one plane (or by the infinite cylinder, with the
//! region's height inside the caps), which is symmetric under every reflection that keeps
//! `c` and the surface: about the line through `c` along `n` for a plane, about the plane
//! `z = c_z` and the meridian plane through `c` for the cylinder's side. So the area vector
//! `S` of the sphere's surface inside lies along `−n`, the intersection's centroid lies on
//! the line through `c` along `n`, and the line through the centroid along `n` is that line:
//! it leaves the sphere at `c − r n` and the solid at the foot `q = c − d n`. Hence, exactly
//! as SPEC §4 defines them: normal `n`, points `c − r n` and `q`, δ = `r − d`. The area
//! estimate is `|S|` as on the general path ([`crate::methods::volume_contact`]): `π(r² − d²)` for a
//! plane (the cap's base, or with the centre inside the projection of the rest of the sphere,
//! the same disc), and for the side `|S| = 2R ∫ cos φ · 2√(r² − |R u(φ) − c_xy|²) dφ`, the
//! side's own area vector inside the ball (the sphere's and the side's close the region), a
//! periodic integral after `sin(φ/2) = k sin θ` taken by the trapezoid rule to round-off
//! (`fast_path::side_area`). (With the centre inside, `|S|` is smaller than the `π r²` the
//! sphere–plane and sphere–mesh pairs report there: the estimates differ by convention.)
//!
//! Measured against the general path at 120 random poses where the fast path fires (unit
//! test `fast_path_equals_the_general_path`): depth 3.8e-16, normal 3.2e-14, points 1.1e-14
//! of the size, area 6.8e-16 of its square.
//!
//! Not fast paths, because the region is not symmetric about that line: an edge, rim or
//! corner within the ball's reach; the centre inside the solid with the ball reaching two
//! faces (or none: containment); a frustum's slanted side (the ball cut by a cone is not
//! symmetric about the cone's normal through `c`: the cone's sections widen on one side);
//! every torus pose (the tube curves differently across and along it); the centre on a
//! cylinder's axis (no radial direction). These take the general path.
//!
//! ## The general path
//! The sphere is the ellipsoid of semi-axes `(r, r, r)`, and the pair is answered by the
//! general ellipsoid kernels, converged to 1e-9 of the pair's size:
//! [`super::ellipsoid_box`], [`super::ellipsoid_cylinder`], `super::ellipsoid_frustum`, and
//! `super::ellipsoid_torus` (one contact per region: a ball through the hole of a small
//! torus meets the ring in two). Their degenerate branches apply: a ball inside the solid
//! takes the outward normal of the face nearest its centre (area a quarter of the sphere),
//! touching is no contact. Apart solids (signed distance `≥ r`) are rejected first, by
//! [`crate::methods::solid_distance`].

pub(crate) mod fast_path;
#[cfg(test)]
mod tests;

use crate::kernel::PairContact;
pub(crate) use crate::methods::solid_distance::Solid;
use crate::methods::solid_distance::signed_distance;
use contact_core::{Isometry3, Point3, Vector3, WorkCounters};

/// The contacts of the sphere of `radius` at `pose_sphere` with `solid` at `pose_solid`, one
/// per intersection region (at most one but for a torus), normals from the solid into the
/// sphere.
pub(crate) fn contacts(
    radius: f64,
    pose_sphere: &Isometry3,
    solid: &Solid,
    pose_solid: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let centre = pose_solid.inverse_transform_point(&Point3::from(pose_sphere.translation.vector));
    work.bounding_volume_tests += 1;
    let (s, _, _) = signed_distance(solid, &centre.coords);
    if s >= radius || !s.is_finite() {
        return;
    }
    if let Some(local) = fast_path::fast_path(radius, &centre.coords, solid) {
        emit(local.to_world(radius, pose_sphere, pose_solid));
        return;
    }
    general(radius, pose_sphere, solid, pose_solid, work, emit);
}

/// The general path: the sphere as the ellipsoid of equal semi-axes.
pub(crate) fn general(
    radius: f64,
    pose_sphere: &Isometry3,
    solid: &Solid,
    pose_solid: &Isometry3,
    work: &mut WorkCounters,
    emit: &mut dyn FnMut(PairContact),
) {
    let semi_axes = Vector3::repeat(radius);
    let found = match solid {
        Solid::Box(cuboid) => {
            super::ellipsoid_box::contact(&semi_axes, pose_sphere, cuboid, pose_solid, work)
        }
        Solid::Cylinder(cylinder) => {
            super::ellipsoid_cylinder::contact(&semi_axes, pose_sphere, cylinder, pose_solid, work)
        }
        Solid::Frustum(frustum) => {
            super::ellipsoid_frustum::contact(&semi_axes, pose_sphere, frustum, pose_solid, work)
        }
        Solid::Torus(torus) => {
            super::ellipsoid_torus::contacts(
                &semi_axes,
                pose_sphere,
                torus,
                pose_solid,
                work,
                emit,
            );
            None
        }
    };
    if let Some(contact) = found {
        emit(contact);
    }
}

/// The one contact of the sphere with a convex `solid` (box, cylinder or frustum), or the
/// first region's for a torus.
pub(crate) fn contact(
    radius: f64,
    pose_sphere: &Isometry3,
    solid: &Solid,
    pose_solid: &Isometry3,
    work: &mut WorkCounters,
) -> Option<PairContact> {
    let mut found = None;
    contacts(radius, pose_sphere, solid, pose_solid, work, &mut |c| {
        found.get_or_insert(c);
    });
    found
}
