//! Where a ray from a point inside a solid leaves it, in the solid's frame.
//!
//! The contact points of SPEC §4 are taken on the line through the intersection's centroid
//! along the contact normal: I's point where the line leaves I along `−n`, J's where it leaves
//! J along `+n`, the penetration their distance. These hits move continuously with the poses
//! (the plain closest points to the centroid jump between faces where two are equally near,
//! and a force that jumps defeats a Newton corrector); for smooth surfaces near a shallow
//! contact they coincide with the closest points, and for a sphere on a plane both give r − d.
//!
//! Each function takes the ray origin `o` (inside or on the solid) and a unit direction `d`,
//! and returns the distance `t ≥ 0` to the exit, or `None` when `o` is outside the solid (a
//! centroid outside a non-convex solid: the caller then falls back to the closest point).

use crate::methods::solid_distance::{Solid, signed_distance};
use contact_core::geometry::{Cylinder, Frustum, Torus};
use contact_core::{Isometry3, Point3, Vector3};

/// The point of `solid`'s surface on the ray from `g` along the unit `direction` where it
/// leaves the solid; when `g` is outside the solid (a centroid in a torus' hole), the point of
/// the surface closest to `g`.
pub(crate) fn surface_point_along(solid: &Solid, g: &Vector3, direction: &Vector3) -> Vector3 {
    let exit = match solid {
        Solid::Box(b) => box_exit(&b.center().coords, &b.half_extents(), g, direction),
        Solid::Cylinder(c) => cylinder_exit(c, g, direction),
        Solid::Frustum(f) => frustum_exit(f, g, direction),
        Solid::Torus(t) => torus_exit(t, g, direction),
    };
    match exit {
        Some(t) => g + t * direction,
        None => signed_distance(solid, g).1,
    }
}

/// [`surface_point_along`] for a solid at `pose` (`X_WG`), with `g` and `direction` in the
/// world.
pub(crate) fn surface_point_along_w(
    solid: &Solid,
    pose: &Isometry3,
    g: &Point3,
    direction: &Vector3,
) -> Point3 {
    let local = pose.inverse_transform_point(g).coords;
    let d = pose.inverse_transform_vector(direction);
    pose * Point3::from(surface_point_along(solid, &local, &d))
}

/// The larger root of `a t² + b t + c` with `c ≤ 0 < a` (one root ≤ 0 ≤ the other), stably.
fn positive_root(a: f64, b: f64, c: f64) -> f64 {
    let disc = (b * b - 4.0 * a * c).max(0.0);
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    // The roots are q/a and c/q, of opposite signs (c ≤ 0 < a): q's sign picks the
    // non-negative one, a single division.
    if q > 0.0 {
        q / a
    } else if q < 0.0 {
        (c / q).max(0.0)
    } else {
        0.0
    }
}

/// Exit through the planes `z = 0` (going down) and `z = top` (going up).
fn cap_exit(o: &Vector3, d: &Vector3, top: f64) -> f64 {
    if d.z > 0.0 {
        ((top - o.z) / d.z).max(0.0)
    } else if d.z < 0.0 {
        (-o.z / d.z).max(0.0)
    } else {
        f64::INFINITY
    }
}

/// A box with centre `centre` and half extents `half` (axis-aligned in its frame).
pub(crate) fn box_exit(centre: &Vector3, half: &Vector3, o: &Vector3, d: &Vector3) -> Option<f64> {
    let p = o - centre;
    if (0..3).any(|k| p[k].abs() > half[k] * (1.0 + 1e-12)) {
        return None;
    }
    let mut best = f64::INFINITY;
    for k in 0..3 {
        if d[k] > 0.0 {
            best = best.min(((half[k] - p[k]) / d[k]).max(0.0));
        } else if d[k] < 0.0 {
            best = best.min(((-half[k] - p[k]) / d[k]).max(0.0));
        }
    }
    best.is_finite().then_some(best)
}

/// An ellipsoid centred at the origin with semi-axes `semi`.
pub(crate) fn ellipsoid_exit(semi: &Vector3, o: &Vector3, d: &Vector3) -> Option<f64> {
    let (p, v) = (o.component_div(semi), d.component_div(semi));
    let c = p.norm_squared() - 1.0;
    if c > 1e-12 {
        return None;
    }
    Some(positive_root(v.norm_squared(), 2.0 * p.dot(&v), c.min(0.0)))
}

/// A cylinder on the `z` axis from `z = 0` to its length.
pub(crate) fn cylinder_exit(cylinder: &Cylinder, o: &Vector3, d: &Vector3) -> Option<f64> {
    // The frustum's exit with the slope 0 taken out: the same arithmetic, without the slope's
    // division or the radial distance's square root.
    let (r, length) = (cylinder.radius(), cylinder.length());
    let tolerance = 1e-12 * r.max(length);
    let rho2 = o.x * o.x + o.y * o.y;
    let reach = r + tolerance;
    if o.z < -tolerance || o.z > length + tolerance || rho2 > reach * reach {
        return None;
    }
    let caps = cap_exit(o, d, length);
    let a = d.x * d.x + d.y * d.y;
    let side = if a > 0.0 {
        let b = 2.0 * (o.x * d.x + o.y * d.y);
        positive_root(a, b, (rho2 - r * r).min(0.0))
    } else {
        f64::INFINITY
    };
    Some(caps.min(side))
}

/// A frustum (or cone) on the `z` axis, bottom radius at `z = 0`, top at its length.
pub(crate) fn frustum_exit(frustum: &Frustum, o: &Vector3, d: &Vector3) -> Option<f64> {
    frustum_like_exit(
        frustum.bottom_radius(),
        frustum.top_radius(),
        frustum.length(),
        o,
        d,
    )
}

fn frustum_like_exit(r0: f64, r1: f64, length: f64, o: &Vector3, d: &Vector3) -> Option<f64> {
    let slope = (r1 - r0) / length;
    let radius_at = |z: f64| r0 + slope * z;
    let size = r0.max(r1).max(length);
    let rho2 = o.x * o.x + o.y * o.y;
    let r_o = radius_at(o.z);
    if o.z < -1e-12 * size
        || o.z > length + 1e-12 * size
        || rho2.sqrt() > r_o.max(0.0) + 1e-12 * size
    {
        return None;
    }
    let caps = cap_exit(o, d, length);
    // The side: x² + y² − r(z)² along the ray, a t² + b t + c with c ≤ 0 at the origin.
    let a = d.x * d.x + d.y * d.y - slope * slope * d.z * d.z;
    let b = 2.0 * (o.x * d.x + o.y * d.y - slope * d.z * r_o);
    let c = (rho2 - r_o * r_o).min(0.0);
    let side = if slope == 0.0 || a > 0.0 {
        if a > 0.0 {
            positive_root(a, b, c)
        } else {
            f64::INFINITY
        }
    } else {
        // a ≤ 0 (the ray is steeper than the side): the first root at which the quadratic
        // rises through zero, if any, is where the ray leaves through the side.
        leaving_root(a, b, c)
    };
    Some(caps.min(side))
}

/// The interval `(s₀, s₁)` of the line `o + s d` inside a frustum (a cylinder when
/// `r0 = r1`) on the `z` axis, bottom radius `r0` at `z = 0`, top `r1` at `length`; `None`
/// when the line misses it or only touches it. The solid is convex, so the line meets it in
/// one interval: the slab `0 ≤ z ≤ length` cut by the side's quadratic
/// `x² + y² − r(z)² ≤ 0` (the cone's other nappe lies beyond the apex, outside the slab).
pub(crate) fn frustum_line_interval(
    r0: f64,
    r1: f64,
    length: f64,
    o: &Vector3,
    d: &Vector3,
) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = if d.z != 0.0 {
        let (a, b) = (-o.z / d.z, (length - o.z) / d.z);
        (a.min(b), a.max(b))
    } else if (0.0..=length).contains(&o.z) {
        (f64::NEG_INFINITY, f64::INFINITY)
    } else {
        return None;
    };
    let slope = (r1 - r0) / length;
    let r_o = r0 + slope * o.z;
    let a = d.x * d.x + d.y * d.y - slope * slope * d.z * d.z;
    let b = 2.0 * (o.x * d.x + o.y * d.y - slope * d.z * r_o);
    let c = o.x * o.x + o.y * o.y - r_o * r_o;
    let radius_along = |s: f64| r0 + slope * (o.z + s * d.z);
    let disc = b * b - 4.0 * a * c;
    if a == 0.0 {
        // Linear: b s + c ≤ 0.
        if b > 0.0 {
            hi = hi.min(-c / b);
        } else if b < 0.0 {
            lo = lo.max(-c / b);
        } else if c > 0.0 {
            return None;
        }
    } else if disc < 0.0 || disc.is_nan() {
        if a > 0.0 {
            return None;
        }
    } else {
        let q = -0.5 * (b + b.signum() * disc.sqrt());
        let (s1, s2) = if q == 0.0 {
            (0.0, 0.0)
        } else {
            let (x, y) = (q / a, c / q);
            (x.min(y), x.max(y))
        };
        if a > 0.0 {
            (lo, hi) = (lo.max(s1), hi.min(s2));
        } else {
            // Outside (s1, s2): the part on the slab's side of the nappe with r(z) ≥ 0.
            let below = (lo, hi.min(s1));
            let above = (lo.max(s2), hi);
            let good = |(x, y): (f64, f64)| {
                y > x && radius_along(if x.is_finite() { 0.5 * (x + y) } else { y }) >= 0.0
            };
            (lo, hi) = if good(below) { below } else { above };
        }
    }
    (hi > lo).then_some((lo, hi))
}

/// The smallest `t > 0` where `a t² + b t + c` (≤ 0 at 0) rises through 0, or ∞.
fn leaving_root(a: f64, b: f64, c: f64) -> f64 {
    if a == 0.0 {
        return if b > 0.0 {
            (-c / b).max(0.0)
        } else {
            f64::INFINITY
        };
    }
    let disc = b * b - 4.0 * a * c;
    // No real roots, or a double one within round-off: the line misses or only touches the
    // side (a line along the axis through a cone's tip), it does not leave through it.
    if disc <= 1e-14 * b * b {
        return f64::INFINITY;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let roots = if q == 0.0 { [0.0, 0.0] } else { [q / a, c / q] };
    roots
        .into_iter()
        .filter(|&t| t >= 0.0 && 2.0 * a * t + b > 0.0)
        .fold(f64::INFINITY, f64::min)
}

/// A ring torus about the `z` axis: major radius R, tube radius r. The tube's signed
/// distance `g(p) = √((ρ − R)² + z²) − r` is marched in steps of r/8 (a chord of the tube
/// cannot hide between two steps) and the sign change bisected to round-off.
pub(crate) fn torus_exit(torus: &Torus, o: &Vector3, d: &Vector3) -> Option<f64> {
    let (big, small) = (torus.major_radius(), torus.minor_radius());
    let g = |t: f64| {
        let p = o + t * d;
        let rho = (p.x * p.x + p.y * p.y).sqrt();
        ((rho - big).powi(2) + p.z * p.z).sqrt() - small
    };
    if g(0.0) > 1e-12 * (big + small) {
        return None;
    }
    let step = small / 8.0;
    let limit = 2.0 * (big + small) + o.norm();
    let mut lo = 0.0;
    let mut hi = step;
    while g(hi) <= 0.0 {
        lo = hi;
        hi += step;
        if hi > limit {
            return Some(lo);
        }
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if g(mid) <= 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(x: f64, y: f64, z: f64) -> Vector3 {
        Vector3::new(x, y, z).normalize()
    }

    #[test]
    fn box_and_ellipsoid_exits_lie_on_their_surfaces() {
        let half = Vector3::new(1.0, 2.0, 0.5);
        let o = Vector3::new(0.2, -0.3, 0.1);
        let d = unit(0.3, -1.0, 0.2);
        let t = box_exit(&Vector3::zeros(), &half, &o, &d).unwrap();
        // y is the first face met: (−2 + 0.3)/d.y.
        assert!((t - (-2.0 - o.y) / d.y).abs() < 1e-15);
        let semi = Vector3::new(1.0, 2.0, 3.0);
        let t = ellipsoid_exit(&semi, &o, &d).unwrap();
        let p = (o + t * d).component_div(&semi);
        assert!((p.norm() - 1.0).abs() < 1e-15);
        assert!(ellipsoid_exit(&semi, &Vector3::new(2.0, 0.0, 0.0), &d).is_none());
    }

    #[test]
    fn cylinder_and_cone_exits_by_the_side_or_a_cap() {
        let c = Cylinder::new(1.0, 2.0).unwrap();
        let o = Vector3::new(0.5, 0.0, 1.0);
        // Sideways: out through the side at x = 1.
        assert!((cylinder_exit(&c, &o, &Vector3::x()).unwrap() - 0.5).abs() < 1e-15);
        // Up: out through the top cap.
        assert!((cylinder_exit(&c, &o, &Vector3::z()).unwrap() - 1.0).abs() < 1e-15);
        // A cone (tip up, radius 1 → 0 over height 2): straight up from the axis reaches the tip;
        // from x = 0.5 at z = 0 upwards the side is met at z = 1.
        let cone = Frustum::new(1.0, 0.0, 2.0).unwrap();
        let axis = frustum_exit(&cone, &Vector3::new(0.0, 0.0, 0.5), &Vector3::z()).unwrap();
        assert!((axis - 1.5).abs() < 1e-12);
        let t = frustum_exit(&cone, &Vector3::new(0.5, 0.0, 0.0), &Vector3::z()).unwrap();
        assert!((t - 1.0).abs() < 1e-12);
        // A slanted ray leaves where the side's equation holds.
        let d = unit(1.0, 0.4, 0.7);
        let o = Vector3::new(0.1, 0.1, 0.3);
        let t = frustum_exit(&cone, &o, &d).unwrap();
        let p = o + t * d;
        assert!(((p.x * p.x + p.y * p.y).sqrt() - (1.0 - 0.5 * p.z)).abs() < 1e-12);
    }

    #[test]
    fn torus_exit_is_on_the_tube_and_outside_origins_are_refused() {
        let torus = Torus::new(2.0, 0.5).unwrap();
        let o = Vector3::new(2.0, 0.0, 0.1);
        let t = torus_exit(&torus, &o, &Vector3::z()).unwrap();
        assert!((t - (0.5 - 0.1)).abs() < 1e-13);
        let d = unit(0.2, 1.0, -0.3);
        let t = torus_exit(&torus, &o, &d).unwrap();
        let p = o + t * d;
        let tube = (((p.x * p.x + p.y * p.y).sqrt() - 2.0).powi(2) + p.z * p.z).sqrt();
        assert!((tube - 0.5).abs() < 1e-13);
        assert!(torus_exit(&torus, &Vector3::zeros(), &Vector3::z()).is_none());
    }
}
