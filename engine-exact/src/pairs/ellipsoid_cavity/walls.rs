//! The cavity's walls in its own frame (world lengths): inside tests, closest points, the
//! line through the cavity, and SPEC §4's points for a region of the ellipsoid outside it.

use super::Cavity;
use crate::methods::ellipsoid_sliced::ellipsoid_exit_w;
use crate::methods::solid_distance::{Solid, signed_distance};
use crate::ray_exit::{ellipsoid_exit, frustum_line_interval, surface_point_along};
use contact_core::geometry::Torus;
use contact_core::{Isometry3, Point3, Vector3};

/// Bisection steps for the closest point of an ellipsoid (the multiplier's bracket halved to
/// round-off).
const BISECTIONS: usize = 200;

impl Cavity {
    /// `(s, q)`: the signed distance of `p` from the cavity's wall (negative inside the
    /// cavity) and the wall's closest point.
    pub(super) fn distance(&self, p: &Vector3) -> (f64, Vector3) {
        match self {
            Self::Cylinder(c) => {
                let (s, q, _) = signed_distance(&Solid::Cylinder(*c), p);
                (s, q)
            }
            Self::Frustum(f) => {
                let (s, q, _) = signed_distance(&Solid::Frustum(*f), p);
                (s, q)
            }
            Self::Ellipsoid(semi) => ellipsoid_distance(semi, p),
            Self::Torus(t) => {
                let (s, q, _) = signed_distance(&Solid::Torus(*t), p);
                (s, q)
            }
        }
    }

    /// The first `s ≥ 0` where the line `o + s d` (unit `d`, from `o` outside the cavity)
    /// enters the cavity, or `None`.
    pub(super) fn entry(&self, o: &Vector3, d: &Vector3) -> Option<f64> {
        let first = |(s0, s1): (f64, f64)| (s1 > 0.0).then_some(s0.max(0.0));
        match self {
            Self::Cylinder(c) => {
                frustum_line_interval(c.radius(), c.radius(), c.length(), o, d).and_then(first)
            }
            Self::Frustum(f) => {
                frustum_line_interval(f.bottom_radius(), f.top_radius(), f.length(), o, d)
                    .and_then(first)
            }
            Self::Ellipsoid(semi) => {
                let (u, v) = (o.component_div(semi), d.component_div(semi));
                let (a, b, c) = (v.dot(&v), 2.0 * u.dot(&v), u.dot(&u) - 1.0);
                let disc = b * b - 4.0 * a * c;
                if a == 0.0 || disc.is_nan() || disc <= 0.0 {
                    return None;
                }
                let q = -0.5 * (b + b.signum() * disc.sqrt());
                let (x, y) = (q / a, c / q);
                first((x.min(y), x.max(y)))
            }
            Self::Torus(t) => torus_entry(t, o, d),
        }
    }

    /// Where the line from `o` (inside the cavity) along the unit `d` meets the wall (the
    /// closest point when `o` is outside).
    pub(super) fn exit(&self, o: &Vector3, d: &Vector3) -> Vector3 {
        match self {
            Self::Cylinder(c) => surface_point_along(&Solid::Cylinder(*c), o, d),
            Self::Frustum(f) => surface_point_along(&Solid::Frustum(*f), o, d),
            Self::Ellipsoid(semi) => match ellipsoid_exit(semi, o, d) {
                Some(t) => o + t * d,
                None => ellipsoid_distance(semi, o).1,
            },
            Self::Torus(t) => surface_point_along(&Solid::Torus(*t), o, d),
        }
    }
}

/// Steps of the march into a torus' tube, per tube radius (a chord of the tube cannot hide
/// between two steps of `ρ/8`).
const TORUS_STEPS_PER_RADIUS: f64 = 8.0;

/// The first `s ≥ 0` where the line from `o` along the unit `d` enters the tube of `torus`:
/// the tube's signed distance `√((ρ_xy − R)² + z²) − ρ` marched in steps of `ρ/8` out to the
/// torus' bounding sphere, the sign change bisected to round-off.
fn torus_entry(torus: &Torus, o: &Vector3, d: &Vector3) -> Option<f64> {
    let (big, small) = (torus.major_radius(), torus.minor_radius());
    let inside = |s: f64| {
        let p = o + s * d;
        let rho = (p.x * p.x + p.y * p.y).sqrt() - big;
        rho * rho + p.z * p.z < small * small
    };
    let reach = o.norm() + big + small;
    let step = small / TORUS_STEPS_PER_RADIUS;
    let mut s = 0.0;
    while s < reach {
        let next = s + step;
        if inside(next) {
            let (mut lo, mut hi) = (s, next);
            for _ in 0..BISECTIONS {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if inside(mid) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return Some(0.5 * (lo + hi));
        }
        s = next;
    }
    None
}

/// The signed distance of `p` from the ellipsoid with `semi` axes about the origin (negative
/// inside) and the closest surface point: `x_k = a_k² p_k / (a_k² + λ)` with `λ` the root of
/// `Σ (a_k p_k / (a_k² + λ))² = 1`, bisected (outside `λ > 0`, inside `−min a_k² < λ < 0`;
/// a point on a principal plane where the root is not interior takes the smallest axis'
/// pole side, the branch the bracket ends at).
pub(crate) fn ellipsoid_distance(semi: &Vector3, p: &Vector3) -> (f64, Vector3) {
    let a2 = semi.component_mul(semi);
    let level = p.component_div(semi).norm_squared();
    let f = |lambda: f64| {
        (0..3)
            .map(|k| (semi[k] * p[k] / (a2[k] + lambda)).powi(2))
            .sum::<f64>()
            - 1.0
    };
    let smallest = a2.min();
    let (mut lo, mut hi) = if level >= 1.0 {
        (0.0, p.norm() * semi.max() + a2.max())
    } else {
        (-smallest, 0.0)
    };
    for _ in 0..BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        // f falls as λ rises on (−min a², ∞).
        if f(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let lambda = 0.5 * (lo + hi);
    let mut q = Vector3::from_fn(|k, _| a2[k] * p[k] / (a2[k] + lambda));
    // Back onto the surface (the root's round-off, or a degenerate branch).
    let scale = q.component_div(semi).norm();
    if scale > 0.0 && scale.is_finite() {
        q /= scale;
    } else {
        q = Vector3::new(0.0, 0.0, semi.z.copysign(p.z));
    }
    let distance = (q - p).norm();
    (if level < 1.0 { -distance } else { distance }, q)
}

/// The two contact points of SPEC §4 on the line through `g` along the normal `n` (world
/// frame): the ellipsoid's and the cavity's (see the parent module's doc).
pub(super) fn cavity_points(
    semi_axes: &Vector3,
    pose_a: &Isometry3,
    cavity: &Cavity,
    pose_b: &Isometry3,
    g: &Point3,
    n: &Vector3,
) -> (Point3, Point3) {
    let gb = pose_b.inverse_transform_point(g).coords;
    let nb = pose_b.inverse_transform_vector(n);
    let (distance, closest) = cavity.distance(&gb);
    let closest_w = pose_b * Point3::from(closest);
    let default_a = ellipsoid_exit_w(semi_axes, pose_a, g, &-n);
    if distance >= 0.0 {
        // In the material: the line enters the cavity along +n.
        return match cavity.entry(&gb, &nb) {
            Some(s) => (default_a, g + s * n),
            None => (default_a, closest_w),
        };
    }
    // In the cavity: the nearer chord beside g whose middle lies in both bodies.
    let mut best: Option<(f64, Point3, Point3)> = None;
    for side in [-1.0, 1.0] {
        let dir = n * side;
        let pa = ellipsoid_exit_w(semi_axes, pose_a, g, &dir);
        let pb = pose_b * Point3::from(cavity.exit(&gb, &(nb * side)));
        let middle = Point3::from(0.5 * (pa.coords + pb.coords));
        let middle_b = pose_b.inverse_transform_point(&middle).coords;
        let in_a = {
            let p = pose_a.inverse_transform_point(&middle).coords;
            p.component_div(semi_axes).norm_squared() < 1.0
        };
        if (pb - pa).dot(n) <= 0.0 || !in_a || cavity.distance(&middle_b).0 <= 0.0 {
            continue;
        }
        let near = (pa - g).norm().min((pb - g).norm());
        if best.as_ref().is_none_or(|(d, _, _)| near < *d) {
            best = Some((near, pa, pb));
        }
    }
    match best {
        Some((_, pa, pb)) => (pa, pb),
        None => (default_a, closest_w),
    }
}

/// From the centroid to the cavity's closest wall point (world frame), or the cavity's `−z`
/// when the centroid is on its wall.
pub(super) fn toward_cavity(cavity: &Cavity, pose_b: &Isometry3, g: &Point3) -> Vector3 {
    let gb = pose_b.inverse_transform_point(g).coords;
    let (_, closest) = cavity.distance(&gb);
    let away = pose_b.rotation * (closest - gb);
    away.try_normalize(0.0)
        .unwrap_or_else(|| -(pose_b.rotation * Vector3::z()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closest point is on the surface, and the offset from it is along the surface's
    /// normal there (the gradient `q/a²`), inside and out.
    #[test]
    fn the_ellipsoids_closest_point_is_normal_to_it() {
        let semi = Vector3::new(1.5, 0.7, 0.4);
        let mut rng = crate::test_rng::Rng(7);
        for _ in 0..2000 {
            let p = Vector3::new(
                rng.uniform(-3.0, 3.0),
                rng.uniform(-2.0, 2.0),
                rng.uniform(-1.5, 1.5),
            );
            let (s, q) = ellipsoid_distance(&semi, &p);
            assert!((q.component_div(&semi).norm() - 1.0).abs() < 1e-13);
            let normal = q.component_div(&semi.component_mul(&semi)).normalize();
            let offset = p - q;
            assert!((offset.norm() - s.abs()).abs() < 1e-13);
            assert!(
                offset.cross(&normal).norm() < 1e-9 * (1.0 + offset.norm()),
                "{p:?}"
            );
            assert_eq!(s < 0.0, p.component_div(&semi).norm() < 1.0);
        }
    }
}
