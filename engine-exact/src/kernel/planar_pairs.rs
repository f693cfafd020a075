//! The kernels of two 2-D geometries in their common plane: points, circles, arcs,
//! curves, lines and boundaries.

use super::PairContact;
use crate::planar;
use crate::planar::curve_eval::PlanarCurve;
use contact_core::geometry::Line;
use contact_core::{Isometry3, WorkCounters};
use std::sync::Arc;

/// The 2-D kernels of [`super::Kernel`], each with the shape data it holds.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum PlanarKernel {
    /// 2-D point `a` against line `b`.
    PointLine { line: Line, side: f64 },
    /// 2-D point `a` against solid circle `b` (or a circular hole when `hole`).
    PointCircle { radius: f64, hole: bool },
    /// Two solid 2-D circles.
    CircleCircle { radius_a: f64, radius_b: f64 },
    /// Solid circle `a` inside the circular hole `b` (a flipped circle).
    CircleInHole { radius_a: f64, radius_b: f64 },
    /// 2-D point `a` against arc `b`.
    PointArc { radius: f64, range: f64, side: f64 },
    /// Solid circle `a` against arc `b`.
    CircleArc {
        radius_a: f64,
        radius: f64,
        range: f64,
        side: f64,
    },
    /// 2-D point `a` against curve `b`.
    PointCurve { curve: Arc<PlanarCurve>, side: f64 },
    /// Solid circle `a` against curve `b`.
    CircleCurve {
        radius: f64,
        curve: Arc<PlanarCurve>,
        side: f64,
    },
    /// Solid circle `a` against an unbounded line `b`.
    CircleLine { radius: f64, side: f64 },
    /// Solid circle `a` against line `b` over `x_range` (an end finite): the disc cut by the
    /// line's half-strip.
    CircleBoundedLine {
        radius: f64,
        x_range: [f64; 2],
        side: f64,
    },
    /// Boundary `a` against boundary `b` (arcs and curves, oriented by their flips): one
    /// contact per overlap region (it allocates per query, see
    /// `planar::overlap`).
    Overlap {
        a: Arc<planar::boundary::Chain>,
        b: Arc<planar::boundary::Chain>,
    },
    /// Boundary `a` (arc or curve) against line `b`: one contact per overlap region.
    OverlapLine {
        a: Arc<planar::boundary::Chain>,
        x_range: [f64; 2],
        side: f64,
    },
}

impl PlanarKernel {
    /// The kernels of two 2-D geometries in the in-plane `frame` (points, circles, arcs,
    /// curves, lines, boundaries): as [`super::SolidKernel::contact`].
    pub(crate) fn contact<E: FnMut(PairContact)>(
        &self,
        frame: &planar::InPlane,
        pose_a: &Isometry3,
        work: &mut WorkCounters,
        emit: &mut E,
    ) -> Option<PairContact> {
        match *self {
            Self::PointLine { ref line, side } => planar::point_line::contact(frame, line, side),
            Self::PointCircle { radius, hole } => {
                planar::circles::point_circle(frame, radius, hole)
            }
            Self::CircleCircle { radius_a, radius_b } => {
                planar::circles::circle_circle(frame, radius_a, radius_b)
            }
            Self::CircleInHole { radius_a, radius_b } => {
                planar::circles::circle_in_hole(frame, radius_a, radius_b)
            }
            Self::PointArc {
                radius,
                range,
                side,
            } => planar::arc::point_arc(frame, radius, range, side),
            Self::CircleArc {
                radius_a,
                radius,
                range,
                side,
            } => planar::arc::circle_arc(frame, radius_a, radius, range, side),
            Self::PointCurve { ref curve, side } => {
                planar::point_curve::point_curve(frame, curve, side, work)
            }
            Self::CircleCurve {
                radius,
                ref curve,
                side,
            } => planar::point_curve::circle_curve(frame, radius, curve, side, work),
            Self::CircleLine { radius, side } => {
                planar::point_line::circle_line(frame, radius, side)
            }
            Self::CircleBoundedLine {
                radius,
                x_range,
                side,
            } => planar::circle_bounded_line::contact(frame, radius, x_range, side),
            Self::Overlap { ref a, ref b } => {
                planar::overlap::chain_chain(frame, pose_a, a, b, work, emit);
                None
            }
            Self::OverlapLine {
                ref a,
                x_range,
                side,
            } => {
                planar::overlap::chain_line(frame, pose_a, a, x_range, side, work, emit);
                None
            }
        }
    }
}
