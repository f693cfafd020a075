//! The 3-D solid primitives of SPEC §2, each in its own geometry frame `G`.
//!
//! Every constructor validates its arguments; a value out of range gives an
//! [`InvalidArgument`] naming the Adams argument, the value and the allowed range.

use crate::error::{InvalidArgument, length, proportions};
use crate::{Point3, Vector3};

/// An ellipsoid centred on the origin of `G` with semi-axes along x, y and z.
///
/// Adams' `GRAPHICS/…, ELLIPSOID, XSCALE, YSCALE, ZSCALE` gives full diameters; use
/// [`Ellipsoid::from_diameters`] for those. Equal semi-axes make a sphere.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipsoid {
    semi_axes: Vector3,
}

impl Ellipsoid {
    /// An ellipsoid with the given semi-axes (each in [`LENGTH_RANGE`](crate::LENGTH_RANGE),
    /// within [`MAX_ASPECT_RATIO`](crate::MAX_ASPECT_RATIO) of each other).
    pub fn new(a: f64, b: f64, c: f64) -> Result<Self, InvalidArgument> {
        let axes = [("XSCALE/2", a), ("YSCALE/2", b), ("ZSCALE/2", c)];
        for (argument, value) in axes {
            length(argument, value)?;
        }
        proportions(&axes)?;
        Ok(Self {
            semi_axes: Vector3::new(a, b, c),
        })
    }

    /// An ellipsoid from Adams' full diameters XSCALE, YSCALE, ZSCALE (each in
    /// [`LENGTH_RANGE`](crate::LENGTH_RANGE), within
    /// [`MAX_ASPECT_RATIO`](crate::MAX_ASPECT_RATIO) of each other).
    pub fn from_diameters(x: f64, y: f64, z: f64) -> Result<Self, InvalidArgument> {
        let diameters = [("XSCALE", x), ("YSCALE", y), ("ZSCALE", z)];
        for (argument, value) in diameters {
            length(argument, value)?;
        }
        proportions(&diameters)?;
        Ok(Self {
            semi_axes: Vector3::new(0.5 * x, 0.5 * y, 0.5 * z),
        })
    }

    /// A sphere of the given radius (in [`LENGTH_RANGE`](crate::LENGTH_RANGE)).
    pub fn sphere(radius: f64) -> Result<Self, InvalidArgument> {
        let r = length("RADIUS", radius)?;
        Ok(Self {
            semi_axes: Vector3::new(r, r, r),
        })
    }

    /// The semi-axes along x, y, z of `G`.
    pub fn semi_axes(&self) -> Vector3 {
        self.semi_axes
    }

    /// The radius if all three semi-axes are equal (bit for bit), else `None`.
    pub fn sphere_radius(&self) -> Option<f64> {
        let s = self.semi_axes;
        (s.x == s.y && s.y == s.z).then_some(s.x)
    }
}

/// A solid circular cylinder: bottom face centred on the origin of `G`, axis +z, top face at
/// z = `length` (Adams `CYLINDER`: CM at the centre of the bottom face).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylinder {
    radius: f64,
    length: f64,
}

impl Cylinder {
    /// A cylinder of `radius` and `length` in [`LENGTH_RANGE`](crate::LENGTH_RANGE), within
    /// [`MAX_ASPECT_RATIO`](crate::MAX_ASPECT_RATIO) of each other.
    ///
    /// Adams allows a negative LENGTH (the cylinder then extends along −z); the dataset reader
    /// turns that into a positive length and a reference frame flipped about x.
    pub fn new(radius: f64, length_z: f64) -> Result<Self, InvalidArgument> {
        let dimensions = [("RADIUS", radius), ("LENGTH", length_z)];
        for (argument, value) in dimensions {
            length(argument, value)?;
        }
        proportions(&dimensions)?;
        Ok(Self {
            radius,
            length: length_z,
        })
    }

    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The length along +z.
    pub fn length(&self) -> f64 {
        self.length
    }
}

/// A box with one corner at the origin of `G` (Adams' CORNER marker) and extents X, Y, Z along
/// the axes of `G`; each extent may be negative (the box then lies on the negative side).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cuboid {
    center: Point3,
    half_extents: Vector3,
}

impl Cuboid {
    /// A box from the corner at the origin with extents `x`, `y`, `z` (each ≠ 0, its magnitude
    /// in [`LENGTH_RANGE`](crate::LENGTH_RANGE), within
    /// [`MAX_ASPECT_RATIO`](crate::MAX_ASPECT_RATIO) of each other).
    pub fn from_corner(x: f64, y: f64, z: f64) -> Result<Self, InvalidArgument> {
        let check = |argument, v: f64| {
            if v.is_finite() && v != 0.0 {
                length(argument, v.abs()).map(|_| v)
            } else {
                Err(InvalidArgument::new(argument, v, "finite and != 0"))
            }
        };
        let extents = Vector3::new(check("X", x)?, check("Y", y)?, check("Z", z)?);
        proportions(&[("X", x.abs()), ("Y", y.abs()), ("Z", z.abs())])?;
        Ok(Self {
            center: Point3::from(0.5 * extents),
            half_extents: 0.5 * extents.abs(),
        })
    }

    /// A box centred on the origin of `G` with the given half extents (each in
    /// [`LENGTH_RANGE`](crate::LENGTH_RANGE), within
    /// [`MAX_ASPECT_RATIO`](crate::MAX_ASPECT_RATIO) of each other).
    pub fn centered(hx: f64, hy: f64, hz: f64) -> Result<Self, InvalidArgument> {
        let halves = [("X/2", hx), ("Y/2", hy), ("Z/2", hz)];
        for (argument, value) in halves {
            length(argument, value)?;
        }
        proportions(&halves)?;
        Ok(Self {
            center: Point3::origin(),
            half_extents: Vector3::new(hx, hy, hz),
        })
    }

    /// The centre of the box in `G`.
    pub fn center(&self) -> Point3 {
        self.center
    }

    /// The half extents along the axes of `G` (all > 0).
    pub fn half_extents(&self) -> Vector3 {
        self.half_extents
    }
}

/// A frustum of a cone: bottom radius at z = 0 of `G`, top radius at z = `length`, axis +z.
/// One radius may be zero (a cone).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frustum {
    bottom_radius: f64,
    top_radius: f64,
    length: f64,
}

impl Frustum {
    /// A frustum with radii ≥ 0 (not both zero) and `length` > 0: the length and each
    /// non-zero radius in [`LENGTH_RANGE`](crate::LENGTH_RANGE), within
    /// [`MAX_ASPECT_RATIO`](crate::MAX_ASPECT_RATIO) of each other (a zero radius is a cone's
    /// apex).
    pub fn new(
        bottom_radius: f64,
        top_radius: f64,
        length_z: f64,
    ) -> Result<Self, InvalidArgument> {
        let bottom = crate::error::non_negative("BOTTOM", bottom_radius)?;
        let top = crate::error::non_negative("TOP", top_radius)?;
        if bottom == 0.0 && top == 0.0 {
            return Err(InvalidArgument::new("TOP", top, "> 0 when BOTTOM = 0"));
        }
        let dimensions: Vec<(&'static str, f64)> = [("BOTTOM", bottom), ("TOP", top)]
            .into_iter()
            .filter(|d| d.1 > 0.0)
            .chain([("LENGTH", length_z)])
            .collect();
        for &(argument, value) in &dimensions {
            length(argument, value)?;
        }
        proportions(&dimensions)?;
        Ok(Self {
            bottom_radius: bottom,
            top_radius: top,
            length: length_z,
        })
    }

    /// The radius at z = 0.
    pub fn bottom_radius(&self) -> f64 {
        self.bottom_radius
    }

    /// The radius at z = length.
    pub fn top_radius(&self) -> f64 {
        self.top_radius
    }

    /// The length along +z.
    pub fn length(&self) -> f64 {
        self.length
    }
}

/// A ring torus centred on the origin of `G`, its centre circle of radius `major_radius` in the
/// x-y plane, its tube of radius `minor_radius`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Torus {
    major_radius: f64,
    minor_radius: f64,
}

impl Torus {
    /// A torus with `0 < minor_radius < major_radius` (a ring torus: a horn or spindle torus
    /// has no hole and is rejected).
    ///
    /// Both radii lie in [`LENGTH_RANGE`](crate::LENGTH_RANGE), within
    /// [`MAX_ASPECT_RATIO`](crate::MAX_ASPECT_RATIO) of each other.
    pub fn new(major_radius: f64, minor_radius: f64) -> Result<Self, InvalidArgument> {
        let major = length("MAJOR_RADIUS", major_radius)?;
        let minor = length("MINOR_RADIUS", minor_radius)?;
        proportions(&[("MAJOR_RADIUS", major), ("MINOR_RADIUS", minor)])?;
        if minor >= major {
            return Err(InvalidArgument::new(
                "MINOR_RADIUS",
                minor,
                format!("< MAJOR_RADIUS = {major:?}"),
            ));
        }
        Ok(Self {
            major_radius: major,
            minor_radius: minor,
        })
    }

    /// The radius of the tube's centre circle.
    pub fn major_radius(&self) -> f64 {
        self.major_radius
    }

    /// The radius of the tube.
    pub fn minor_radius(&self) -> f64 {
        self.minor_radius
    }
}

/// A 3-D plane: the x-y plane of `G` with outward normal +z; the solid is the half-space
/// z ≤ 0 over the rectangle `[xmin, xmax] × [ymin, ymax]` (bounds may be infinite).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    xmin: f64,
    xmax: f64,
    ymin: f64,
    ymax: f64,
}

impl Plane {
    /// The unbounded plane.
    pub fn unbounded() -> Self {
        Self {
            xmin: f64::NEG_INFINITY,
            xmax: f64::INFINITY,
            ymin: f64::NEG_INFINITY,
            ymax: f64::INFINITY,
        }
    }

    /// A plane bounded to `[xmin, xmax] × [ymin, ymax]` (min < max; infinite bounds allowed,
    /// NaN rejected).
    pub fn bounded(xmin: f64, xmax: f64, ymin: f64, ymax: f64) -> Result<Self, InvalidArgument> {
        for (argument, v) in [
            ("XMIN", xmin),
            ("XMAX", xmax),
            ("YMIN", ymin),
            ("YMAX", ymax),
        ] {
            if v.is_nan() {
                return Err(InvalidArgument::new(
                    argument,
                    v,
                    "a number (may be infinite)",
                ));
            }
        }
        if xmin >= xmax {
            return Err(InvalidArgument::new(
                "XMAX",
                xmax,
                format!("> XMIN = {xmin:?}"),
            ));
        }
        if ymin >= ymax {
            return Err(InvalidArgument::new(
                "YMAX",
                ymax,
                format!("> YMIN = {ymin:?}"),
            ));
        }
        Ok(Self {
            xmin,
            xmax,
            ymin,
            ymax,
        })
    }

    /// `[xmin, xmax]`.
    pub fn x_range(&self) -> [f64; 2] {
        [self.xmin, self.xmax]
    }

    /// `[ymin, ymax]`.
    pub fn y_range(&self) -> [f64; 2] {
        [self.ymin, self.ymax]
    }

    /// The same rectangle in its frame turned half a turn about the x axis
    /// (`(x, y, z) → (x, −y, −z)`): `[xmin, xmax] × [−ymax, −ymin]`. With that turn, the
    /// half-space on the plane's other side (a flipped PLANE) is an unflipped one.
    pub fn turned_about_x(&self) -> Self {
        Self {
            xmin: self.xmin,
            xmax: self.xmax,
            ymin: -self.ymax,
            ymax: -self.ymin,
        }
    }

    /// True when all four bounds are infinite.
    pub fn is_unbounded(&self) -> bool {
        self.xmin.is_infinite()
            && self.xmax.is_infinite()
            && self.ymin.is_infinite()
            && self.ymax.is_infinite()
    }
}
