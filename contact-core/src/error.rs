//! Errors for bad input: every variant names the argument, the value and the allowed range.

use thiserror::Error;

/// A value given for a named argument is outside its allowed range.
///
/// This is the one error shape for every scalar argument in the crate (geometry sizes, contact
/// parameters, preferences), so messages read the same everywhere:
/// `STIFFNESS = -1 is out of range: must be > 0`.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{argument} = {value} is out of range: must be {allowed}")]
pub struct InvalidArgument {
    /// The argument's name as the user wrote it (Adams keyword where there is one).
    pub argument: &'static str,
    /// The value given, printed at round-trip precision.
    pub value: String,
    /// The allowed range, e.g. `> 0` or `in [0, 1]`.
    pub allowed: String,
}

impl InvalidArgument {
    /// Builds the error for a numeric value.
    pub fn new(argument: &'static str, value: f64, allowed: impl Into<String>) -> Self {
        Self {
            argument,
            value: format!("{value:?}"),
            allowed: allowed.into(),
        }
    }

    /// Builds the error for a non-numeric value (a count, a name, a list).
    pub fn with_text(
        argument: &'static str,
        value: impl Into<String>,
        allowed: impl Into<String>,
    ) -> Self {
        Self {
            argument,
            value: value.into(),
            allowed: allowed.into(),
        }
    }
}

/// The sizes a geometry's dimensions may have, in the model's length unit: from `1e-30` to
/// `1e30`. Both engines answer every pair alike at every scale inside it (checked at 1e±40: the
/// same contacts as at scale 1); beyond it areas overflow (a sphere of radius 1e300 has an
/// infinite area) and the faceted engine's mesh–mesh products lose contacts (at 1e60). A
/// dimension outside is refused with this range.
pub const LENGTH_RANGE: [f64; 2] = [1e-30, 1e30];

/// The largest ratio of a geometry's largest dimension to its smallest (a box 1e12 times as
/// long as it is thick is the limit): beyond it the faceted engine's tessellation and the exact
/// engine's quadratures no longer resolve the thin dimension in `f64`.
pub const MAX_ASPECT_RATIO: f64 = 1e12;

/// Checks a geometry dimension is finite and within [`LENGTH_RANGE`].
pub(crate) fn length(argument: &'static str, value: f64) -> Result<f64, InvalidArgument> {
    let [lo, hi] = LENGTH_RANGE;
    if value.is_finite() && (lo..=hi).contains(&value) {
        Ok(value)
    } else {
        Err(InvalidArgument::new(
            argument,
            value,
            format!("finite, from {lo:e} to {hi:e} (LENGTH_RANGE)"),
        ))
    }
}

/// Checks the dimensions `(argument, value)` (each > 0) are within [`MAX_ASPECT_RATIO`] of the
/// largest; the smallest is named when they are not.
pub(crate) fn proportions(dimensions: &[(&'static str, f64)]) -> Result<(), InvalidArgument> {
    let largest = dimensions.iter().map(|d| d.1).fold(0.0, f64::max);
    match dimensions.iter().min_by(|a, b| a.1.total_cmp(&b.1)) {
        Some(&(argument, smallest)) if smallest * MAX_ASPECT_RATIO < largest => {
            Err(InvalidArgument::new(
                argument,
                smallest,
                format!(
                    "at least {:e}: the largest dimension {largest:e} over {MAX_ASPECT_RATIO:e} (MAX_ASPECT_RATIO)",
                    largest / MAX_ASPECT_RATIO
                ),
            ))
        }
        _ => Ok(()),
    }
}

/// Checks `value` is finite and `> 0`.
pub(crate) fn positive(argument: &'static str, value: f64) -> Result<f64, InvalidArgument> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(InvalidArgument::new(argument, value, "finite and > 0"))
    }
}

/// Checks `value` is finite and `>= 0`.
pub(crate) fn non_negative(argument: &'static str, value: f64) -> Result<f64, InvalidArgument> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(InvalidArgument::new(argument, value, "finite and >= 0"))
    }
}

/// Checks `value` is finite.
pub(crate) fn finite(argument: &'static str, value: f64) -> Result<f64, InvalidArgument> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(InvalidArgument::new(argument, value, "finite"))
    }
}

#[cfg(test)]
mod tests {
    use crate::geometry::{Cuboid, Cylinder, Ellipsoid, Frustum, Torus, TriangleMesh};
    use crate::{LENGTH_RANGE, MAX_ASPECT_RATIO, Point3};

    #[test]
    fn sizes_beyond_the_range_are_refused_naming_the_argument_and_the_range() {
        let [lo, hi] = LENGTH_RANGE;
        for bad in [1e300, 1e-300, hi * 1.5, lo / 1.5] {
            let e = Ellipsoid::sphere(bad).unwrap_err().to_string();
            assert!(e.contains("RADIUS") && e.contains("LENGTH_RANGE"), "{e}");
            assert!(Cuboid::from_corner(bad, bad, bad).is_err());
            assert!(Cuboid::centered(bad, bad, bad).is_err());
            assert!(Cylinder::new(bad, bad).is_err());
            assert!(Frustum::new(bad, 0.0, bad).is_err());
            assert!(Torus::new(2.0 * bad, bad).is_err());
        }
        for good in [lo, hi, 1.0] {
            assert!(Ellipsoid::sphere(good).is_ok());
            assert!(Cuboid::from_corner(-good, good, good).is_ok());
            assert!(Frustum::new(good, 0.0, good).is_ok());
        }
    }

    #[test]
    fn proportions_beyond_the_aspect_ratio_are_refused_naming_the_smallest() {
        let thin = 1.0 / MAX_ASPECT_RATIO;
        assert!(Cuboid::centered(1.0, 1.0, thin).is_ok());
        let e = Cuboid::centered(1.0, 1.0, thin / 2.0)
            .unwrap_err()
            .to_string();
        assert!(e.contains("Z/2") && e.contains("MAX_ASPECT_RATIO"), "{e}");
        let e = Cylinder::new(1.0, 3.0 / thin).unwrap_err().to_string();
        assert!(e.contains("RADIUS"), "{e}");
        assert!(Ellipsoid::new(1.0, thin / 3.0, 1.0).is_err());
        assert!(Torus::new(1.0, thin / 3.0).is_err());
        // A cone's zero radius is its apex, not a proportion.
        assert!(Frustum::new(1.0, 0.0, 2.0).is_ok());
    }

    #[test]
    fn a_mesh_beyond_the_range_is_refused() {
        let tetrahedron = |s: f64| {
            TriangleMesh::new(
                vec![
                    Point3::origin(),
                    Point3::new(s, 0.0, 0.0),
                    Point3::new(0.0, s, 0.0),
                    Point3::new(0.0, 0.0, s),
                ],
                vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
            )
        };
        assert!(tetrahedron(1.0).is_ok());
        let e = tetrahedron(1e300).unwrap_err().to_string();
        assert!(e.contains("LENGTH_RANGE"), "{e}");
        let e = tetrahedron(1e-300).unwrap_err().to_string();
        assert!(e.contains("LENGTH_RANGE"), "{e}");
    }
}
