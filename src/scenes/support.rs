//! Support functions `h(d) = max over the shape of d·x`, used to place two shapes at a nominal
//! depth along an approach direction. Nominal only: the reference answer of a pose always comes
//! from a closed form or the exact engine, never from this placement.

use contact_core::{Geometry, Isometry3, Vector3};

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
}
