//! A bounded PLANE seen by one body as a box: the plane's solid is the prism `z ≤ 0` (or
//! `z ≥ 0` flipped) over the rectangle `[xmin, xmax] × [ymin, ymax]` of its frame, and a body
//! that fits in a ball of radius `reach` about `c` meets only the part of that prism within
//! `reach` of `c`. So the prism is cut, per query, to a finite box about `c` whose added faces
//! lie at least `R = 4·reach + 2|c_z|` from `c`:
//! - the body never reaches an added face (`R > reach`), so the intersection — volume,
//!   centroid, the body's surface inside — is the prism's, bit for bit the same geometry;
//! - a point at `c` inside the prism is nearer its top face (`|c_z|` away) than any added face
//!   (`≥ R`), so a signed-distance answer never picks an added face either;
//! - the box stays within a few `reach` of the body, so its size, not the plane's (which may be
//!   infinite), sets the working precision.
//!
//! When the rectangle lies farther than `R` from `c` in x or y the body cannot touch it: `None`.

use contact_core::geometry::{Cuboid, Plane};
use contact_core::{Isometry3, Point3};
use nalgebra::Translation3;

/// The finite box (and its pose `X_WB`) that stands for `plane` (its solid on the `side`: +1
/// below `z = 0`, −1 above) at `pose_plane`, for a body within `reach` of the world point
/// `centre`; `None` when the body cannot touch the plane's rectangle.
pub(crate) fn local_box(
    plane: &Plane,
    side: f64,
    pose_plane: &Isometry3,
    centre: &Point3,
    reach: f64,
) -> Option<(Cuboid, Isometry3)> {
    let c = pose_plane.inverse_transform_point(centre);
    let margin = 4.0 * reach + 2.0 * c.z.abs();
    let clamp = |[lo, hi]: [f64; 2], at: f64| -> Option<(f64, f64)> {
        let (lo, hi) = (lo.max(at - margin), hi.min(at + margin));
        (lo < hi).then_some((lo, hi))
    };
    let (x0, x1) = clamp(plane.x_range(), c.x)?;
    let (y0, y1) = clamp(plane.y_range(), c.y)?;
    let (z0, z1) = if side > 0.0 {
        (c.z.min(0.0) - margin, 0.0)
    } else {
        (0.0, c.z.max(0.0) + margin)
    };
    let half = |lo: f64, hi: f64| 0.5 * (hi - lo);
    let cuboid = Cuboid::centered(half(x0, x1), half(y0, y1), half(z0, z1)).ok()?;
    let middle = Translation3::new(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1));
    Some((cuboid, pose_plane * middle))
}
