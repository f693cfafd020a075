//! The 2-D shapes of SPEC §2. Each lies in the x-y plane of its geometry frame `G`; its
//! binormal is +z of `G`. A 2-D contact acts in that plane.

use crate::error::{InvalidArgument, positive};
use std::f64::consts::TAU;

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
            radius: positive("RADIUS", radius)?,
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
        let radius = positive("RADIUS", radius)?;
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
