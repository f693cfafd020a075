//! Support functions `h(d) = max over the shape of d·x`, used to place two shapes at a nominal
//! depth along an approach direction. Nominal only: the reference answer of a pose always comes
//! from a closed form or the exact engine, never from this placement.

use contact_core::geometry::Curve;
use contact_core::{Geometry, Isometry3, Point3, Vector3};

/// Where a B-spline curve reaches farthest along `d` (in its plane): the best of a dense
/// sampling, refined by Newton on `d·c'(u) = 0` within the neighbouring samples.
fn curve_support_point(c: &Curve, d: &nalgebra::Vector2<f64>) -> nalgebra::Point2<f64> {
    const SAMPLES: usize = 4096;
    let [u0, u1] = c.domain();
    let step = (u1 - u0) / SAMPLES as f64;
    let height = |u: f64| d.dot(&c.point(u).coords);
    let mut best = u0;
    for k in 0..=SAMPLES {
        let u = u0 + step * k as f64;
        if height(u) > height(best) {
            best = u;
        }
    }
    let (lo, hi) = ((best - step).max(u0), (best + step).min(u1));
    let mut u = best;
    for _ in 0..20 {
        let slope = d.dot(&c.derivative(u));
        let curvature = d.dot(&c.second_derivative(u));
        if curvature >= 0.0 {
            break;
        }
        let next = (u - slope / curvature).clamp(lo, hi);
        if height(next) < height(u) || next == u {
            break;
        }
        u = next;
    }
    c.point(u)
}

/// The support value of `geometry` placed at `pose` (geometry frame in world) in world direction
/// `d`; `None` for unbounded shapes (planes, lines) whose support is infinite in most directions.
pub fn support(geometry: &Geometry, pose: &Isometry3, d: &Vector3) -> Option<f64> {
    let local = pose.rotation.inverse() * d;
    let offset = d.dot(&pose.translation.vector);
    let planar = (local.x * local.x + local.y * local.y).sqrt();
    let h = match geometry {
        Geometry::Ellipsoid(e) => e.semi_axes().component_mul(&local).norm(),
        Geometry::Cylinder(c) => c.radius() * planar + (c.length() * local.z).max(0.0),
        Geometry::Frustum(f) => {
            (f.bottom_radius() * planar).max(f.top_radius() * planar + f.length() * local.z)
        }
        Geometry::Cuboid(b) => b.center().coords.dot(&local) + b.half_extents().dot(&local.abs()),
        Geometry::Torus(t) => t.major_radius() * planar + t.minor_radius() * local.norm(),
        Geometry::Mesh(m) => m
            .vertices()
            .iter()
            .map(|v| v.coords.dot(&local))
            .fold(f64::NEG_INFINITY, f64::max),
        Geometry::Point => 0.0,
        Geometry::Circle(c) => c.radius() * planar,
        Geometry::Arc(a) => a.radius() * planar,
        Geometry::Curve(c) => c
            .control_points()
            .iter()
            .map(|q| q.x * local.x + q.y * local.y)
            .fold(f64::NEG_INFINITY, f64::max),
        Geometry::Plane(_) | Geometry::Line(_) => return None,
    };
    Some(h + offset)
}

/// A point of `geometry` placed at `pose` where its support in world direction `d` is
/// attained: for an ellipsoid the unique one, for a box its supporting vertex (the centre of
/// the supporting edge or face when `d` is perpendicular to an edge or a face), for a curve
/// its farthest point in its plane (found numerically); `None` for every other shape. Two shapes whose support points in `u` and `−u` coincide touch there,
/// with `u` a normal of both.
pub fn support_point(geometry: &Geometry, pose: &Isometry3, d: &Vector3) -> Option<Point3> {
    let local = pose.rotation.inverse() * d;
    let point = match geometry {
        Geometry::Ellipsoid(e) => {
            let scaled = e.semi_axes().component_mul(&local);
            let norm = scaled.norm();
            if norm == 0.0 {
                return None;
            }
            e.semi_axes().component_mul(&scaled) / norm
        }
        Geometry::Cuboid(b) => {
            let sign = local.map(|c| if c == 0.0 { 0.0 } else { c.signum() });
            b.center().coords + b.half_extents().component_mul(&sign)
        }
        Geometry::Curve(c) => {
            let q = curve_support_point(c, &nalgebra::Vector2::new(local.x, local.y));
            Vector3::new(q.x, q.y, 0.0)
        }
        _ => return None,
    };
    Some(pose * Point3::from(point))
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::geometry::{Cuboid, Cylinder};

    #[test]
    fn supports_of_simple_shapes() {
        let id = Isometry3::identity();
        let sphere = Geometry::sphere(2.0).unwrap();
        assert_eq!(support(&sphere, &id, &Vector3::x()), Some(2.0));
        let cyl = Geometry::Cylinder(Cylinder::new(1.0, 3.0).unwrap());
        assert_eq!(support(&cyl, &id, &Vector3::z()), Some(3.0));
        assert_eq!(support(&cyl, &id, &-Vector3::z()), Some(0.0));
        let b = Geometry::Cuboid(Cuboid::from_corner(2.0, 2.0, 2.0).unwrap());
        let d = Vector3::new(1.0, 1.0, 0.0).normalize();
        assert!((support(&b, &id, &d).unwrap() - 2.0 * 2f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn an_ellipsoids_support_point_attains_its_support_and_has_the_direction_as_normal() {
        let e = contact_core::geometry::Ellipsoid::new(1.0, 0.6, 0.4).unwrap();
        let g = Geometry::Ellipsoid(e);
        let pose = Isometry3::new(Vector3::new(0.3, -2.0, 1.0), Vector3::new(0.4, -0.2, 0.9));
        let d = Vector3::new(0.2, -0.7, 0.5).normalize();
        let p = support_point(&g, &pose, &d).unwrap();
        assert!((d.dot(&p.coords) - support(&g, &pose, &d).unwrap()).abs() < 1e-14);
        // On the surface, with the gradient of x²/a² + … along d.
        let local = pose.inverse() * p;
        let axes = e.semi_axes();
        let level = local.coords.component_div(&axes).norm_squared();
        assert!((level - 1.0).abs() < 1e-14);
        let gradient = pose.rotation * local.coords.component_div(&axes.component_mul(&axes));
        assert!(gradient.normalize().cross(&d).norm() < 1e-14);
        let cyl = Geometry::Cylinder(Cylinder::new(1.0, 3.0).unwrap());
        assert!(support_point(&cyl, &pose, &d).is_none());
        // A box's supporting vertex attains the support too.
        let b = Geometry::Cuboid(Cuboid::centered(1.0, 0.7, 0.5).unwrap());
        let v = support_point(&b, &pose, &d).unwrap();
        assert!((d.dot(&v.coords) - support(&b, &pose, &d).unwrap()).abs() < 1e-14);
    }
}
