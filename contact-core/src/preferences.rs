//! PREFERENCES as data: which geometry engine, which faceting tolerance, how many threads.

use crate::error::{InvalidArgument, positive};
use std::num::NonZeroUsize;

/// The geometry engine (Adams `PREFERENCES/CONTACT_GEOMETRY_LIBRARY`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum GeometryLibrary {
    /// Analytic answers for primitives (Adams PARASOLID; also EXACT).
    Exact,
    /// Tessellated meshes with OBB trees (Adams DEFAULT_LIBRARY, RAPID; also FACETED). The
    /// default, as in Adams.
    #[default]
    Faceted,
}

impl GeometryLibrary {
    /// Parses an Adams or project value, case-insensitively: PARASOLID or EXACT → exact;
    /// DEFAULT_LIBRARY, RAPID or FACETED → faceted.
    pub fn parse(value: &str) -> Result<Self, InvalidArgument> {
        match value.trim().to_ascii_uppercase().as_str() {
            "PARASOLID" | "EXACT" => Ok(Self::Exact),
            "DEFAULT_LIBRARY" | "RAPID" | "FACETED" => Ok(Self::Faceted),
            _ => Err(InvalidArgument::with_text(
                "CONTACT_GEOMETRY_LIBRARY",
                value,
                "one of PARASOLID, EXACT, DEFAULT_LIBRARY, RAPID, FACETED",
            )),
        }
    }

    /// The name reports print: `exact` or `faceted`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Exact => "exact",
            Self::Faceted => "faceted",
        }
    }
}

impl std::str::FromStr for GeometryLibrary {
    type Err = InvalidArgument;

    /// As [`GeometryLibrary::parse`]: `"parasolid".parse::<GeometryLibrary>()`.
    fn from_str(value: &str) -> Result<Self, Self::Err> {
        Self::parse(value)
    }
}

impl std::fmt::Display for GeometryLibrary {
    /// The name reports print ([`GeometryLibrary::name`]), which [`GeometryLibrary::parse`]
    /// reads back.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The faceting tolerance FT (ours, SPEC §7): dimensionless; a geometry with bounding-box
/// diagonal `L` is faceted so that no chord deviates from the true surface by more than `L/FT`.
/// Higher is finer. Finite and > 0; the default is Adams' 300.0028.
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct FacetingTolerance(f64);

impl FacetingTolerance {
    /// Adams' default, 300.0028.
    pub const DEFAULT: Self = Self(300.0028);

    /// A tolerance (finite, > 0).
    pub fn new(value: f64) -> Result<Self, InvalidArgument> {
        Ok(Self(positive("FACETING_TOLERANCE", value)?))
    }

    /// The number.
    pub fn value(self) -> f64 {
        self.0
    }

    /// The largest chord deviation allowed for a geometry of characteristic length `length`.
    pub fn chord_deviation(self, length: f64) -> f64 {
        length / self.0
    }
}

impl Default for FacetingTolerance {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// PREFERENCES for a model (SPEC §7).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Preferences {
    /// The geometry engine.
    pub geometry_library: GeometryLibrary,
    /// The model-wide faceting tolerance.
    pub faceting_tolerance: FacetingTolerance,
    /// Threads for contact evaluation (`PREFERENCES/NTHREADS`); `None` = all cores.
    pub threads: Option<NonZeroUsize>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adams_library_names_map_to_engines() {
        assert_eq!(
            GeometryLibrary::parse("Parasolid").unwrap(),
            GeometryLibrary::Exact
        );
        assert_eq!(
            GeometryLibrary::parse("default_library").unwrap(),
            GeometryLibrary::Faceted
        );
        assert_eq!(
            GeometryLibrary::parse("RAPID").unwrap(),
            GeometryLibrary::Faceted
        );
        let e = GeometryLibrary::parse("ACIS").unwrap_err();
        assert!(
            e.to_string().contains("CONTACT_GEOMETRY_LIBRARY = ACIS"),
            "{e}"
        );
        assert_eq!(GeometryLibrary::default(), GeometryLibrary::Faceted);
        // FromStr and Display round-trip through the short names.
        for library in [GeometryLibrary::Exact, GeometryLibrary::Faceted] {
            assert_eq!(library.to_string().parse::<GeometryLibrary>(), Ok(library));
        }
        assert_eq!(" exact ".parse(), Ok(GeometryLibrary::Exact));
    }

    #[test]
    fn faceting_tolerance_is_positive_and_maps_to_a_chord() {
        assert_eq!(FacetingTolerance::default().value(), 300.0028);
        assert_eq!(
            FacetingTolerance::new(100.0).unwrap().chord_deviation(2.0),
            0.02
        );
        let e = FacetingTolerance::new(0.0).unwrap_err();
        assert_eq!(
            e.to_string(),
            "FACETING_TOLERANCE = 0.0 is out of range: must be finite and > 0"
        );
        assert!(FacetingTolerance::new(f64::NAN).is_err());
    }
}
