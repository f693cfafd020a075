//! The 2-D shapes of SPEC §2. Each lies in the x-y plane of its geometry frame `G`; its
//! binormal is +z of `G`. A 2-D contact acts in that plane.

use crate::Isometry3;
use crate::error::InvalidArgument;
use std::f64::consts::TAU;

/// Largest angle (rad) between the planes of a 2-D pair (either orientation of their normals).
pub const PLANE_ANGLE_TOLERANCE: f64 = 1e-6;
/// Largest offset between the planes of a 2-D pair, relative to the pair's length scale.
pub const PLANE_OFFSET_TOLERANCE: f64 = 1e-6;

/// How far the x-y plane of a frame lies from the x-y plane it is seen from, `relative` being
/// its pose in that frame: the angle between the two planes' normals in either orientation (a
/// marker whose z axis is reversed spans the same plane) and the offset of its origin along z.
/// `None` when both are within [`PLANE_ANGLE_TOLERANCE`] and [`PLANE_OFFSET_TOLERANCE`]·`length`
/// (the two 2-D geometries share a plane).
pub fn plane_departure(relative: &Isometry3, length: f64) -> Option<(f64, f64)> {
    let z = relative.rotation * crate::Vector3::z();
    let angle_rad = z.xy().norm().atan2(z.z.abs());
    let offset = relative.translation.vector.z;
    (angle_rad > PLANE_ANGLE_TOLERANCE || offset.abs() > PLANE_OFFSET_TOLERANCE * length)
        .then_some((angle_rad, offset))
}

/// A 2-D line: the x axis of `G` over `[xmin, xmax]`, outward normal +y (Adams `PLANE` in a
/// 2-D contact). The material lies at y ≤ 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    xmin: f64,
    xmax: f64,
}

impl Line {
    /// The unbounded line.
    pub fn unbounded() -> Self {
        Self {
            xmin: f64::NEG_INFINITY,
            xmax: f64::INFINITY,
        }
    }

    /// The line over `[xmin, xmax]` (xmin < xmax, infinite bounds allowed, NaN rejected).
    pub fn bounded(xmin: f64, xmax: f64) -> Result<Self, InvalidArgument> {
        if xmin.is_nan() {
            return Err(InvalidArgument::new(
                "XMIN",
                xmin,
                "a number (may be infinite)",
            ));
        }
        if xmax.is_nan() || xmax <= xmin {
            return Err(InvalidArgument::new(
                "XMAX",
                xmax,
                format!("> XMIN = {xmin:?}"),
            ));
        }
        Ok(Self { xmin, xmax })
    }

    /// `[xmin, xmax]`.
    pub fn x_range(&self) -> [f64; 2] {
        [self.xmin, self.xmax]
    }
}

/// A solid disc of `radius` centred on the origin of `G`; outward normal radial.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    radius: f64,
}

impl Circle {
    /// A circle of `radius` > 0.
    pub fn new(radius: f64) -> Result<Self, InvalidArgument> {
        Ok(Self {
            radius: crate::error::length("RADIUS", radius)?,
        })
    }

    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

/// A circular arc of `radius` centred on the origin of `G`, from the +x axis through
/// `range_angle` radians counter-clockwise about +z; outward normal radial.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arc {
    radius: f64,
    range_angle: f64,
}

impl Arc {
    /// An arc with `radius` > 0 and `0 < range_angle ≤ 2π` (RANGLE, radians).
    pub fn new(radius: f64, range_angle: f64) -> Result<Self, InvalidArgument> {
        let radius = crate::error::length("RADIUS", radius)?;
        if !(range_angle.is_finite() && range_angle > 0.0 && range_angle <= TAU) {
            return Err(InvalidArgument::new(
                "RANGLE",
                range_angle,
                "in (0, 2π] radians",
            ));
        }
        Ok(Self {
            radius,
            range_angle,
        })
    }

    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The swept angle in radians, in (0, 2π].
    pub fn range_angle(&self) -> f64 {
        self.range_angle
    }
}
