//! The one place that sees both engines: PREFERENCES (or an override) becomes a
//! `Box<dyn GeometryEngine>` once, and nothing downstream knows which engine it has.
//!
//! # Order of precedence
//! For the geometry library and for the model-wide faceting tolerance, the first of these that
//! is set wins:
//! 1. an explicit override: the CLI's `--engine` / `--faceting-tolerance`, or
//!    [`Overrides`] passed by a library caller;
//! 2. the environment: `CONTACT_GEOMETRY_LIBRARY` (exact, faceted, or an Adams name:
//!    PARASOLID, DEFAULT_LIBRARY, RAPID) and `MDI_FACETING_TOLERANCE` (Adams' variable);
//! 3. the dataset: `PREFERENCES/CONTACT_GEOMETRY_LIBRARY`, `CONTACT_FACETING_TOLERANCE`;
//! 4. the default: the faceted engine at 300.0028, as in Adams.
//!
//! A geometry's own `GRAPHICS/…, FACETING_TOLERANCE` still applies to that geometry whatever
//! the model-wide value is. Every run reports the [`EngineSelection`] it used, with where each
//! value came from.

use contact_core::{
    FacetingTolerance, GeometryEngine, GeometryLibrary, InvalidArgument, Preferences,
};
use std::fmt;

/// The environment variable naming the geometry library.
pub const LIBRARY_VARIABLE: &str = "CONTACT_GEOMETRY_LIBRARY";
/// The environment variable holding the faceting tolerance (Adams' name).
pub const TOLERANCE_VARIABLE: &str = "MDI_FACETING_TOLERANCE";

/// Values a caller imposes over the dataset and the environment.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Overrides {
    /// The geometry library, if imposed.
    pub library: Option<GeometryLibrary>,
    /// The model-wide faceting tolerance, if imposed.
    pub faceting_tolerance: Option<FacetingTolerance>,
}

/// Where a setting came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// `--engine` / `--faceting-tolerance` or the library API.
    Override,
    /// An environment variable.
    Environment,
    /// The dataset's PREFERENCES.
    Dataset,
    /// The built-in default.
    Default,
}

impl fmt::Display for Source {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Override => "override",
            Self::Environment => "environment",
            Self::Dataset => "dataset PREFERENCES",
            Self::Default => "default",
        })
    }
}

/// The engine and tolerance a run uses, and where each came from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EngineSelection {
    /// The geometry library.
    pub library: GeometryLibrary,
    /// Where it came from.
    pub library_source: Source,
    /// The model-wide faceting tolerance (used by the faceted engine).
    pub faceting_tolerance: FacetingTolerance,
    /// Where it came from.
    pub tolerance_source: Source,
}

impl fmt::Display for EngineSelection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "engine: {} ({})",
            self.library.name(),
            self.library_source
        )?;
        if self.library == GeometryLibrary::Faceted {
            write!(
                f,
                ", faceting tolerance {} ({})",
                self.faceting_tolerance.value(),
                self.tolerance_source
            )?;
        }
        Ok(())
    }
}

/// An environment variable with a value out of range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("environment variable {variable}: {source}")]
pub struct EnvironmentError {
    /// The variable.
    pub variable: &'static str,
    /// What is wrong with its value.
    pub source: InvalidArgument,
}

/// The engine settings a dataset's PREFERENCES set: `None` where no PREFERENCES statement
/// names that setting (the default then applies, and is reported as the default).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct DatasetEngine {
    /// `CONTACT_GEOMETRY_LIBRARY`, if given.
    pub library: Option<GeometryLibrary>,
    /// `CONTACT_FACETING_TOLERANCE`, if given.
    pub faceting_tolerance: Option<FacetingTolerance>,
}

impl From<&Preferences> for DatasetEngine {
    /// Both settings of `preferences`, as if both were given.
    fn from(preferences: &Preferences) -> Self {
        Self {
            library: Some(preferences.geometry_library),
            faceting_tolerance: Some(preferences.faceting_tolerance),
        }
    }
}

/// Resolves the selection from the four sources (see the module docs). `environment` looks a
/// variable up (pass `|k| std::env::var(k).ok()` for the process environment).
pub fn resolve(
    overrides: &Overrides,
    environment: &dyn Fn(&str) -> Option<String>,
    dataset: DatasetEngine,
) -> Result<EngineSelection, EnvironmentError> {
    let env_library = environment(LIBRARY_VARIABLE)
        .map(|v| GeometryLibrary::parse(&v))
        .transpose()
        .map_err(|source| EnvironmentError {
            variable: LIBRARY_VARIABLE,
            source,
        })?;
    let env_tolerance = environment(TOLERANCE_VARIABLE)
        .map(|v| {
            let number: f64 = v.trim().parse().map_err(|_| {
                InvalidArgument::with_text("FACETING_TOLERANCE", v.clone(), "a number > 0")
            })?;
            FacetingTolerance::new(number)
        })
        .transpose()
        .map_err(|source| EnvironmentError {
            variable: TOLERANCE_VARIABLE,
            source,
        })?;
    let (library, library_source) = first(
        overrides.library,
        env_library,
        dataset.library,
        GeometryLibrary::default(),
    );
    let (faceting_tolerance, tolerance_source) = first(
        overrides.faceting_tolerance,
        env_tolerance,
        dataset.faceting_tolerance,
        FacetingTolerance::DEFAULT,
    );
    Ok(EngineSelection {
        library,
        library_source,
        faceting_tolerance,
        tolerance_source,
    })
}

fn first<T>(over: Option<T>, env: Option<T>, dataset: Option<T>, default: T) -> (T, Source) {
    over.map(|v| (v, Source::Override))
        .or(env.map(|v| (v, Source::Environment)))
        .or(dataset.map(|v| (v, Source::Dataset)))
        .unwrap_or((default, Source::Default))
}

/// The engine named `name` at the model-wide faceting `tolerance` (used by the faceted engine
/// only): `exact` or `faceted`, or an Adams `PREFERENCES/CONTACT_GEOMETRY_LIBRARY` value
/// (PARASOLID → exact; DEFAULT_LIBRARY, RAPID → faceted), any case, as
/// [`GeometryLibrary::parse`] reads them; then [`build_engine`]. An unknown name is an error
/// listing the accepted ones.
///
/// ```
/// use contact_adams::engine_choice::engine_by_name;
/// use contact_core::FacetingTolerance;
///
/// let engine = engine_by_name("PARASOLID", FacetingTolerance::DEFAULT)?;
/// assert_eq!(engine.name(), "exact");
/// assert!(engine_by_name("ACIS", FacetingTolerance::DEFAULT).is_err());
/// # Ok::<(), contact_core::InvalidArgument>(())
/// ```
pub fn engine_by_name(
    name: &str,
    tolerance: FacetingTolerance,
) -> Result<Box<dyn GeometryEngine>, InvalidArgument> {
    Ok(build_engine(GeometryLibrary::parse(name)?, tolerance))
}

/// Builds the engine for a library and model-wide tolerance: the one place that names both
/// engines' types.
pub fn build_engine(
    library: GeometryLibrary,
    tolerance: FacetingTolerance,
) -> Box<dyn GeometryEngine> {
    match library {
        GeometryLibrary::Exact => Box::new(engine_exact::ExactEngine),
        GeometryLibrary::Faceted => Box::new(engine_facet::FacetEngine::new(tolerance)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env(pairs: &'static [(&'static str, &'static str)]) -> impl Fn(&str) -> Option<String> {
        move |k| {
            pairs
                .iter()
                .find(|(name, _)| *name == k)
                .map(|(_, v)| v.to_string())
        }
    }

    #[test]
    fn each_source_wins_over_the_ones_below_it() {
        let dataset = Preferences {
            geometry_library: GeometryLibrary::Exact,
            faceting_tolerance: FacetingTolerance::new(2000.0).unwrap(),
            threads: None,
        };
        let none = resolve(&Overrides::default(), &env(&[]), DatasetEngine::default()).unwrap();
        assert_eq!(
            (none.library, none.library_source),
            (GeometryLibrary::Faceted, Source::Default)
        );
        assert_eq!(none.faceting_tolerance, FacetingTolerance::DEFAULT);
        let from_dataset = resolve(&Overrides::default(), &env(&[]), (&dataset).into()).unwrap();
        assert_eq!(
            (from_dataset.library, from_dataset.library_source),
            (GeometryLibrary::Exact, Source::Dataset)
        );
        let e = env(&[
            ("CONTACT_GEOMETRY_LIBRARY", "rapid"),
            ("MDI_FACETING_TOLERANCE", "500"),
        ]);
        let from_env = resolve(&Overrides::default(), &e, (&dataset).into()).unwrap();
        assert_eq!(
            (from_env.library, from_env.library_source),
            (GeometryLibrary::Faceted, Source::Environment)
        );
        assert_eq!(from_env.faceting_tolerance.value(), 500.0);
        let over = Overrides {
            library: Some(GeometryLibrary::Exact),
            faceting_tolerance: None,
        };
        let from_override = resolve(&over, &e, (&dataset).into()).unwrap();
        assert_eq!(
            (from_override.library, from_override.library_source),
            (GeometryLibrary::Exact, Source::Override)
        );
        assert_eq!(from_override.tolerance_source, Source::Environment);
        assert_eq!(
            from_env.to_string(),
            "engine: faceted (environment), faceting tolerance 500 (environment)"
        );
    }

    #[test]
    fn bad_environment_values_are_errors_naming_the_variable() {
        let e = resolve(
            &Overrides::default(),
            &env(&[("MDI_FACETING_TOLERANCE", "fine")]),
            DatasetEngine::default(),
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "environment variable MDI_FACETING_TOLERANCE: FACETING_TOLERANCE = fine is out of range: must be a number > 0"
        );
        let e = resolve(
            &Overrides::default(),
            &env(&[("CONTACT_GEOMETRY_LIBRARY", "acis")]),
            DatasetEngine::default(),
        )
        .unwrap_err();
        assert!(e.to_string().starts_with(
            "environment variable CONTACT_GEOMETRY_LIBRARY: CONTACT_GEOMETRY_LIBRARY = acis"
        ));
    }
}
