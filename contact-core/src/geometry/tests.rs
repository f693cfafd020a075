//! Each geometry argument rejects a value out of its range with a message naming it.

use super::*;
use crate::Point2;

fn message<T: std::fmt::Debug>(r: Result<T, crate::InvalidArgument>) -> String {
    r.unwrap_err().to_string()
}

#[test]
fn every_solid_argument_is_range_checked() {
    let cases: Vec<(String, &str)> = vec![
        (
            message(Ellipsoid::from_diameters(0.0, 1.0, 1.0)),
            "XSCALE = 0.0 is out of range: must be finite, from 1e-30 to 1e30 (LENGTH_RANGE)",
        ),
        (
            message(Ellipsoid::from_diameters(1.0, -1.0, 1.0)),
            "YSCALE = -1.0 is out of range: must be finite, from 1e-30 to 1e30 (LENGTH_RANGE)",
        ),
        (
            message(Ellipsoid::from_diameters(1.0, 1.0, f64::NAN)),
            "ZSCALE = NaN is out of range: must be finite, from 1e-30 to 1e30 (LENGTH_RANGE)",
        ),
        (
            message(Ellipsoid::sphere(f64::INFINITY)),
            "RADIUS = inf is out of range: must be finite, from 1e-30 to 1e30 (LENGTH_RANGE)",
        ),
        (
            message(Cylinder::new(0.0, 1.0)),
            "RADIUS = 0.0 is out of range: must be finite, from 1e-30 to 1e30 (LENGTH_RANGE)",
        ),
        (
            message(Cylinder::new(1.0, -2.0)),
            "LENGTH = -2.0 is out of range: must be finite, from 1e-30 to 1e30 (LENGTH_RANGE)",
        ),
        (
            message(Cuboid::from_corner(0.0, 1.0, 1.0)),
            "X = 0.0 is out of range: must be finite and != 0",
        ),
        (
            message(Cuboid::from_corner(1.0, f64::NAN, 1.0)),
            "Y = NaN is out of range: must be finite and != 0",
        ),
        (
            message(Cuboid::from_corner(1.0, 1.0, 0.0)),
            "Z = 0.0 is out of range: must be finite and != 0",
        ),
        (
            message(Frustum::new(-1.0, 1.0, 1.0)),
            "BOTTOM = -1.0 is out of range: must be finite and >= 0",
        ),
        (
            message(Frustum::new(0.0, 0.0, 1.0)),
            "TOP = 0.0 is out of range: must be > 0 when BOTTOM = 0",
        ),
        (
            message(Frustum::new(1.0, 1.0, 0.0)),
            "LENGTH = 0.0 is out of range: must be finite, from 1e-30 to 1e30 (LENGTH_RANGE)",
        ),
        (
            message(Torus::new(0.0, 1.0)),
            "MAJOR_RADIUS = 0.0 is out of range: must be finite, from 1e-30 to 1e30 (LENGTH_RANGE)",
        ),
        (
            message(Torus::new(1.0, 1.0)),
            "MINOR_RADIUS = 1.0 is out of range: must be < MAJOR_RADIUS = 1.0",
        ),
    ];
    for (got, want) in cases {
        assert_eq!(got, want);
    }
}

#[test]
fn every_plane_and_planar_argument_is_range_checked() {
    let cases: Vec<(String, &str)> = vec![
        (
            message(Plane::bounded(1.0, 1.0, 0.0, 1.0)),
            "XMAX = 1.0 is out of range: must be > XMIN = 1.0",
        ),
        (
            message(Plane::bounded(0.0, 1.0, 2.0, -1.0)),
            "YMAX = -1.0 is out of range: must be > YMIN = 2.0",
        ),
        (
            message(Plane::bounded(f64::NAN, 1.0, 0.0, 1.0)),
            "XMIN = NaN is out of range: must be a number (may be infinite)",
        ),
        (
            message(Line::bounded(0.0, -1.0)),
            "XMAX = -1.0 is out of range: must be > XMIN = 0.0",
        ),
        (
            message(Circle::new(-3.0)),
            "RADIUS = -3.0 is out of range: must be finite, from 1e-30 to 1e30 (LENGTH_RANGE)",
        ),
        (
            message(Arc::new(1.0, 7.0)),
            "RANGLE = 7.0 is out of range: must be in (0, 2π] radians",
        ),
        (
            message(Arc::new(1.0, 0.0)),
            "RANGLE = 0.0 is out of range: must be in (0, 2π] radians",
        ),
        (
            message(Curve::new(
                &[Point2::origin(), Point2::new(1.0, 0.0)],
                1,
                false,
                CurvePoints::Control,
            )),
            "ORDER = 1 is out of range: must be 2, 3 or 4",
        ),
        (
            message(Curve::new(
                &[Point2::origin(), Point2::new(f64::NAN, 0.0)],
                2,
                false,
                CurvePoints::Control,
            )),
            "CURVE point coordinate = NaN is out of range: must be finite",
        ),
    ];
    for (got, want) in cases {
        assert_eq!(got, want);
    }
}

#[test]
fn kinds_and_dimensions() {
    let sphere = Geometry::sphere(1.0).unwrap();
    assert_eq!(sphere.kind(), GeometryKind::Ellipsoid);
    assert!(!sphere.is_planar());
    assert!(Geometry::Point.is_planar());
    assert_eq!(
        Geometry::Circle(Circle::new(1.0).unwrap()).kind().name(),
        "CIRCLE"
    );
    assert!((sphere.characteristic_length().unwrap() - 2.0 * 3f64.sqrt()).abs() < 1e-15);
    assert_eq!(
        Geometry::Plane(Plane::unbounded()).characteristic_length(),
        None
    );
    // Canonical order: solids before meshes before planes before 2-D shapes.
    assert!(
        GeometryKind::Ellipsoid < GeometryKind::Mesh && GeometryKind::Mesh < GeometryKind::Plane
    );
    assert!(GeometryKind::Plane < GeometryKind::Point);
}

#[test]
fn boxes_from_negative_corners_lie_on_the_negative_side() {
    let b = Cuboid::from_corner(-2.0, 4.0, -6.0).unwrap();
    assert_eq!(b.center(), crate::Point3::new(-1.0, 2.0, -3.0));
    assert_eq!(b.half_extents(), crate::Vector3::new(1.0, 2.0, 3.0));
}

#[test]
fn arc_bounding_box_covers_the_quadrant_extremes() {
    let g = Geometry::Arc(Arc::new(2.0, 3.0 * std::f64::consts::FRAC_PI_4 * 2.0).unwrap());
    let (lo, hi) = g.local_bounding_box();
    // 270°: reaches +y (90°) and −x (180°), ends at −y (270°).
    assert!((hi.y - 2.0).abs() < 1e-15 && (lo.x + 2.0).abs() < 1e-15 && (lo.y + 2.0).abs() < 1e-12);
    assert_eq!(hi.x, 2.0);
}
