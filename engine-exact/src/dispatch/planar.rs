//! The 2-D pairs' kernels, one helper per row of the dispatch table: points and circles
//! against circles, lines, arcs and curves, and the boundary overlaps (arcs, curves and
//! lines). Each takes the pair in canonical order and says which flips it takes.

use super::{NOT_BUILT, Pair, Selected, canonical, side};
use crate::kernel::{Kernel, PlanarKernel};
use crate::planar::boundary::Chain;
use crate::planar::curve_eval::PlanarCurve;
use contact_core::geometry::{Arc, Circle, Curve, Line};
use contact_core::{Geometry, Unsupported};

// ---- Point and circle pairs (only `b` may be flipped, except a circle pair's hole).
impl Pair<'_> {
    /// A point against a circle (or a circular hole when `b` is flipped).
    pub(super) fn point_circle(&self, c: &Circle) -> Result<Selected, Unsupported> {
        self.no_flip(
            self.flip_a,
            Kernel::Planar(PlanarKernel::PointCircle {
                radius: c.radius(),
                hole: self.flip_b,
            }),
        )
    }

    /// A point against a line.
    pub(super) fn point_line(&self, line: &Line) -> Result<Selected, Unsupported> {
        self.no_flip(
            self.flip_a,
            Kernel::Planar(PlanarKernel::PointLine {
                line: *line,
                side: side(self.flip_b),
            }),
        )
    }

    /// Two circles, or one circle in the other's hole (either may be the hole).
    pub(super) fn circle_circle(&self, ca: &Circle, cb: &Circle) -> Result<Selected, Unsupported> {
        let (radius_a, radius_b) = (ca.radius(), cb.radius());
        match (self.flip_a, self.flip_b) {
            (false, false) => Ok(canonical(Kernel::Planar(PlanarKernel::CircleCircle {
                radius_a,
                radius_b,
            }))),
            (false, true) => Ok(canonical(Kernel::Planar(PlanarKernel::CircleInHole {
                radius_a,
                radius_b,
            }))),
            (true, false) => Ok(Selected {
                kernel: Kernel::Planar(PlanarKernel::CircleInHole {
                    radius_a: radius_b,
                    radius_b: radius_a,
                }),
                swap: true,
            }),
            (true, true) => Err(self.no(super::NOT_A_CONTACT)),
        }
    }

    /// A circle against a line, bounded (a finite end) or not.
    pub(super) fn circle_line(&self, c: &Circle, line: &Line) -> Result<Selected, Unsupported> {
        let x_range = line.x_range();
        let kernel = if x_range.iter().any(|x| x.is_finite()) {
            Kernel::Planar(PlanarKernel::CircleBoundedLine {
                radius: c.radius(),
                x_range,
                side: side(self.flip_b),
            })
        } else {
            Kernel::Planar(PlanarKernel::CircleLine {
                radius: c.radius(),
                side: side(self.flip_b),
            })
        };
        // A flipped circle (a hole) against a line's material is an unbounded region.
        self.no_flip(self.flip_a, kernel)
    }

    /// A point against a curve.
    pub(super) fn point_curve(&self, curve: &Curve) -> Result<Selected, Unsupported> {
        let curve = planar_curve(curve);
        self.no_flip(
            self.flip_a,
            Kernel::Planar(PlanarKernel::PointCurve {
                curve,
                side: side(self.flip_b),
            }),
        )
    }

    /// A circle against a curve.
    pub(super) fn circle_curve(
        &self,
        circle: &Circle,
        curve: &Curve,
    ) -> Result<Selected, Unsupported> {
        let curve = planar_curve(curve);
        self.no_flip(
            self.flip_a,
            Kernel::Planar(PlanarKernel::CircleCurve {
                radius: circle.radius(),
                curve,
                side: side(self.flip_b),
            }),
        )
    }

    /// A point against an arc.
    pub(super) fn point_arc(&self, arc: &Arc) -> Result<Selected, Unsupported> {
        self.no_flip(
            self.flip_a,
            Kernel::Planar(PlanarKernel::PointArc {
                radius: arc.radius(),
                range: arc.range_angle(),
                side: side(self.flip_b),
            }),
        )
    }

    /// A circle against an arc.
    pub(super) fn circle_arc(&self, circle: &Circle, arc: &Arc) -> Result<Selected, Unsupported> {
        self.no_flip(
            self.flip_a,
            Kernel::Planar(PlanarKernel::CircleArc {
                radius_a: circle.radius(),
                radius: arc.radius(),
                range: arc.range_angle(),
                side: side(self.flip_b),
            }),
        )
    }
}

fn planar_curve(curve: &Curve) -> std::sync::Arc<PlanarCurve> {
    std::sync::Arc::new(PlanarCurve::new(curve))
}

// ---- Boundary overlaps (arcs, curves and lines; every side may be flipped).
impl Pair<'_> {
    /// An arc or curve `a` against an arc, a curve or a line `b`: the crossings and one
    /// contact per overlap region.
    pub(super) fn overlap(&self) -> Result<Selected, Unsupported> {
        use Geometry as G;
        let a_chain = std::sync::Arc::new(self.chain(self.a, self.flip_a)?);
        Ok(canonical(match self.b {
            G::Line(line) => Kernel::Planar(PlanarKernel::OverlapLine {
                a: a_chain,
                x_range: line.x_range(),
                side: side(self.flip_b),
            }),
            G::Ellipsoid(_)
            | G::Cylinder(_)
            | G::Cuboid(_)
            | G::Frustum(_)
            | G::Torus(_)
            | G::Mesh(_)
            | G::Plane(_)
            | G::Point
            | G::Circle(_)
            | G::Arc(_)
            | G::Curve(_) => Kernel::Planar(PlanarKernel::Overlap {
                a: a_chain,
                b: std::sync::Arc::new(self.chain(self.b, self.flip_b)?),
            }),
        }))
    }

    /// The boundary chain of the arc or curve `g` (inside out when `flip`).
    fn chain(&self, g: &Geometry, flip: bool) -> Result<Chain, Unsupported> {
        use Geometry as G;
        match g {
            G::Arc(arc) => Ok(Chain::from_arc(arc.radius(), arc.range_angle(), side(flip))),
            G::Curve(curve) => {
                let curve = PlanarCurve::new(curve);
                Ok(Chain::from_curve(&curve, side(flip)))
            }
            // Only arcs and curves reach here (the dispatch arm's patterns).
            G::Ellipsoid(_)
            | G::Cylinder(_)
            | G::Cuboid(_)
            | G::Frustum(_)
            | G::Torus(_)
            | G::Mesh(_)
            | G::Plane(_)
            | G::Point
            | G::Circle(_)
            | G::Line(_) => Err(self.no(NOT_BUILT)),
        }
    }
}
