//! The geometry vocabulary: a closed enum of every kind in SPEC §2.
//!
//! Engines `match` on [`Geometry`] exhaustively, so a new kind is a compile error in every
//! engine's dispatch. Each shape lives in its own geometry frame `G` (the Adams reference marker,
//! CM or CORNER marker); [`GeometryInstance`](crate::GeometryInstance) places it on a part.

mod curve;
mod mesh;
pub mod outline;
mod planar;
mod solids;
mod triangle;

pub use curve::{Curve, CurvePoints};
pub use mesh::{MeshError, TriangleMesh, ZERO_AREA_RELATIVE};
pub use planar::{
    Arc, Circle, Line, PLANE_ANGLE_TOLERANCE, PLANE_OFFSET_TOLERANCE, plane_departure,
};
pub use solids::{Cuboid, Cylinder, Ellipsoid, Frustum, Plane, Torus};
pub use triangle::{closest_point_on_triangle, line_triangle};

use crate::{Point3, Vector3};
use std::sync::Arc as Shared;

/// Every geometry a CONTACT can use (SPEC §2). Not `#[non_exhaustive]`: engines in other crates
/// must match exhaustively.
#[derive(Debug, Clone, PartialEq)]
pub enum Geometry {
    /// Ellipsoid (a sphere when its semi-axes are equal).
    Ellipsoid(Ellipsoid),
    /// Solid circular cylinder.
    Cylinder(Cylinder),
    /// Box.
    Cuboid(Cuboid),
    /// Frustum of a cone (or a cone).
    Frustum(Frustum),
    /// Ring torus.
    Torus(Torus),
    /// Half-space below a (possibly bounded) plane.
    Plane(Plane),
    /// Closed triangle mesh (shared: many instances may use one mesh).
    Mesh(Shared<TriangleMesh>),
    /// 2-D point: the origin of `G`.
    Point,
    /// 2-D line along x of `G`, outward +y.
    Line(Line),
    /// 2-D solid circle.
    Circle(Circle),
    /// 2-D circular arc.
    Arc(Arc),
    /// 2-D B-spline curve (shared: curves can be large).
    Curve(Shared<Curve>),
}

/// The kind of a [`Geometry`] without its data; `Ord` is the canonical pair order engines use
/// (a pair `(a, b)` is computed with `a.kind() <= b.kind()`, the other order by swapping).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum GeometryKind {
    /// See [`Geometry::Ellipsoid`].
    Ellipsoid,
    /// See [`Geometry::Cylinder`].
    Cylinder,
    /// See [`Geometry::Cuboid`].
    Cuboid,
    /// See [`Geometry::Frustum`].
    Frustum,
    /// See [`Geometry::Torus`].
    Torus,
    /// See [`Geometry::Mesh`].
    Mesh,
    /// See [`Geometry::Plane`].
    Plane,
    /// See [`Geometry::Point`].
    Point,
    /// See [`Geometry::Circle`].
    Circle,
    /// See [`Geometry::Arc`].
    Arc,
    /// See [`Geometry::Curve`].
    Curve,
    /// See [`Geometry::Line`].
    Line,
}

impl GeometryKind {
    /// The Adams-style name, upper case (`ELLIPSOID`, `BOX`, `CURVE`, …).
    pub fn name(self) -> &'static str {
        match self {
            Self::Ellipsoid => "ELLIPSOID",
            Self::Cylinder => "CYLINDER",
            Self::Cuboid => "BOX",
            Self::Frustum => "FRUSTUM",
            Self::Torus => "TORUS",
            Self::Mesh => "EXTERNAL",
            Self::Plane => "PLANE",
            Self::Point => "POINT",
            Self::Circle => "CIRCLE",
            Self::Arc => "ARC",
            Self::Curve => "CURVE",
            Self::Line => "PLANE (2-D)",
        }
    }

    /// True for the 2-D kinds (point, line, circle, arc, curve).
    pub fn is_planar(self) -> bool {
        matches!(
            self,
            Self::Point | Self::Line | Self::Circle | Self::Arc | Self::Curve
        )
    }
}

impl std::fmt::Display for GeometryKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl Geometry {
    /// A sphere of `radius` (finite, > 0).
    pub fn sphere(radius: f64) -> Result<Self, crate::InvalidArgument> {
        Ellipsoid::sphere(radius).map(Self::Ellipsoid)
    }

    /// The kind, for dispatch and messages.
    pub fn kind(&self) -> GeometryKind {
        match self {
            Self::Ellipsoid(_) => GeometryKind::Ellipsoid,
            Self::Cylinder(_) => GeometryKind::Cylinder,
            Self::Cuboid(_) => GeometryKind::Cuboid,
            Self::Frustum(_) => GeometryKind::Frustum,
            Self::Torus(_) => GeometryKind::Torus,
            Self::Plane(_) => GeometryKind::Plane,
            Self::Mesh(_) => GeometryKind::Mesh,
            Self::Point => GeometryKind::Point,
            Self::Line(_) => GeometryKind::Line,
            Self::Circle(_) => GeometryKind::Circle,
            Self::Arc(_) => GeometryKind::Arc,
            Self::Curve(_) => GeometryKind::Curve,
        }
    }

    /// True for 2-D geometry.
    pub fn is_planar(&self) -> bool {
        self.kind().is_planar()
    }

    /// The axis-aligned bounding box `(min, max)` in `G`; infinite components for unbounded
    /// planes and lines. A 2-D shape has zero z extent; a point is a degenerate box.
    pub fn local_bounding_box(&self) -> (Point3, Point3) {
        let p = |x: f64, y: f64, z: f64| Point3::new(x, y, z);
        match self {
            Self::Ellipsoid(e) => {
                let s = e.semi_axes();
                (Point3::from(-s), Point3::from(s))
            }
            Self::Cylinder(c) => (
                p(-c.radius(), -c.radius(), 0.0),
                p(c.radius(), c.radius(), c.length()),
            ),
            Self::Cuboid(b) => (b.center() - b.half_extents(), b.center() + b.half_extents()),
            Self::Frustum(f) => {
                let r = f.bottom_radius().max(f.top_radius());
                (p(-r, -r, 0.0), p(r, r, f.length()))
            }
            Self::Torus(t) => {
                let r = t.major_radius() + t.minor_radius();
                (p(-r, -r, -t.minor_radius()), p(r, r, t.minor_radius()))
            }
            Self::Plane(pl) => {
                let [x0, x1] = pl.x_range();
                let [y0, y1] = pl.y_range();
                (p(x0, y0, 0.0), p(x1, y1, 0.0))
            }
            Self::Mesh(m) => m.bounding_box(),
            Self::Point => (Point3::origin(), Point3::origin()),
            Self::Line(l) => {
                let [x0, x1] = l.x_range();
                (p(x0, 0.0, 0.0), p(x1, 0.0, 0.0))
            }
            Self::Circle(c) => (
                p(-c.radius(), -c.radius(), 0.0),
                p(c.radius(), c.radius(), 0.0),
            ),
            Self::Arc(a) => arc_bounding_box(a),
            Self::Curve(c) => {
                let mut lo = Vector3::repeat(f64::INFINITY);
                let mut hi = Vector3::repeat(f64::NEG_INFINITY);
                // The convex hull property: the curve lies inside its control polygon's box.
                for q in c.control_points() {
                    let v = Vector3::new(q.x, q.y, 0.0);
                    lo = lo.inf(&v);
                    hi = hi.sup(&v);
                }
                (Point3::from(lo), Point3::from(hi))
            }
        }
    }

    /// The characteristic length `L`: the diagonal of [`Self::local_bounding_box`]. `None` for
    /// geometry without one (unbounded planes and lines, the point). Tolerances (faceting
    /// deviation `L/FT`, convergence `1e-9·L`) are relative to it.
    pub fn characteristic_length(&self) -> Option<f64> {
        let (lo, hi) = self.local_bounding_box();
        let d = (hi - lo).norm();
        (d.is_finite() && d > 0.0).then_some(d)
    }
}

fn arc_bounding_box(a: &Arc) -> (Point3, Point3) {
    let r = a.radius();
    let mut lo = Vector3::new(r, 0.0, 0.0);
    let mut hi = lo;
    let mut include = |angle: f64| {
        let v = Vector3::new(r * angle.cos(), r * angle.sin(), 0.0);
        lo = lo.inf(&v);
        hi = hi.sup(&v);
    };
    include(a.range_angle());
    for k in 1..4 {
        let angle = k as f64 * std::f64::consts::FRAC_PI_2;
        if angle <= a.range_angle() {
            include(angle);
        }
    }
    (Point3::from(lo), Point3::from(hi))
}

#[cfg(test)]
mod tests;
