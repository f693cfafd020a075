//! Regressions, each named after what went wrong, with its reproducer.

use crate::common::{instance, one};
use contact_core::geometry::{Curve, CurvePoints};
use contact_core::{Geometry, Isometry3, Point2};
use std::sync::Arc;

/// At the end of a knot span the knot lookup switched to the next span, so Newton on a
/// polyline's segment used the following segment's derivative and stopped at the vertex:
/// the point below got the next segment (δ 0.0674) instead of the nearer one (δ 0.0226).
#[test]
fn closest_point_near_a_polyline_vertex_stays_on_its_own_segment() {
    let vertices = [
        Point2::new(0.11798821407379095, 0.2453913394360172),
        Point2::new(1.1447745151079238, -0.4757140072853828),
        Point2::new(1.8858855138364574, 0.20525468898165689),
        Point2::new(2.794934687374525, -0.47464601886924374),
        Point2::new(3.826850426665854, 0.08941970121990506),
        Point2::new(5.152794193831549, -0.015085629599315697),
    ];
    let curve = Curve::new(&vertices, 2, false, CurvePoints::Control).unwrap();
    let p = Point2::new(1.1053695161787735, -0.4204078626044989);
    // Independent answer: projection on the first segment.
    let (a, b) = (vertices[0], vertices[1]);
    let d = b - a;
    let t = (p - a).dot(&d) / d.norm_squared();
    let q = a + t * d;
    let n = nalgebra::Vector2::new(d.y, -d.x).normalize();
    let expected_depth = -(p - q).dot(&n);
    let c = one(
        &instance(Geometry::Point),
        &instance(Geometry::Curve(Arc::new(curve))),
        &Isometry3::translation(p.x, p.y, 0.0),
        &Isometry3::identity(),
    );
    assert!(
        (c.penetration - expected_depth).abs() < 1e-14,
        "{c:?} vs {expected_depth}"
    );
    assert!((c.point_j_w.x - q.x).abs() < 1e-14 && (c.point_j_w.y - q.y).abs() < 1e-14);
}
