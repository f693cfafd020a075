//! Reading Adams datasets (`.adm`) and command files (`.acf`) into a [`Model`].
//!
//! The pipeline, one module per stage:
//! - [`lexer`]: lines → statements (title, continuation lines, comments, `&`, END);
//! - [`parser`]: statements → keywords, ids and located values (abbreviations resolved by
//!   [`keywords`]);
//! - `lower`: statements → a validated [`Model`], with every problem as a [`Diagnostic`]
//!   (`file:line:col: error|warning: message`).
//!
//! ```
//! use contact_adams::dataset::read_str;
//! let adm = "model\nUNITS/ SYSTEM = MKS\nPART/1, GROUND\nPART/2, MASS = 2, CM = 3, IP = 1, 1, 1\n\
//!            MARKER/3, PART = 2, QP = 0, 0, 1, REULER = 90D, 0, 0\nEND\n";
//! let loaded = read_str(adm, "model.adm", None);
//! assert!(loaded.diagnostics.iter().all(|d| !d.is_error()));
//! assert_eq!(loaded.model.parts[&2].mass, 2.0);
//! ```

mod arguments;
mod error;
pub mod keywords;
pub mod lexer;
mod lower;
pub mod parser;
mod tables;

pub use error::{DatasetError, Diagnostic, Loc, Origin, Severity};
pub use lexer::FileKind;
pub use lower::parse_number;

use crate::model::Model;
use std::path::Path;

/// A model with every problem found while reading it. With errors, the model is incomplete
/// (statements in error are left out).
#[derive(Debug, Clone)]
pub struct Loaded {
    /// The model.
    pub model: Model,
    /// Errors and warnings, dataset first, each in file order of discovery.
    pub diagnostics: Vec<Diagnostic>,
}

impl Loaded {
    /// True when any diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(Diagnostic::is_error)
    }
}

/// Reads a dataset (and optionally its command file) from text. `adm_path` names the file in
/// messages and is the base for relative EXTERNAL file names.
pub fn read_str(adm_text: &str, adm_path: impl AsRef<Path>, acf: Option<(&str, &Path)>) -> Loaded {
    let adm_parsed = parser::parse(adm_text, FileKind::Dataset);
    let acf_parsed = acf.map(|(text, path)| (parser::parse(text, FileKind::Commands), path));
    let (model, diagnostics) = lower::lower(
        (&adm_parsed, adm_path.as_ref()),
        acf_parsed.as_ref().map(|(p, path)| (p, *path)),
    );
    Loaded { model, diagnostics }
}

fn read_file(path: &Path) -> Result<String, DatasetError> {
    let bytes = std::fs::read(path).map_err(|source| DatasetError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    // Datasets are ASCII; bytes that are not UTF-8 (Latin-1 comments) are replaced, not fatal.
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// Reads a dataset file and optionally a command file. Only I/O failures are `Err`; problems in
/// the files are in [`Loaded::diagnostics`].
pub fn read(adm: &Path, acf: Option<&Path>) -> Result<Loaded, DatasetError> {
    let adm_text = read_file(adm)?;
    let acf_text = match acf {
        Some(p) => Some((read_file(p)?, p)),
        None => None,
    };
    Ok(read_str(
        &adm_text,
        adm,
        acf_text.as_ref().map(|(t, p)| (t.as_str(), *p)),
    ))
}

/// Reads and validates: the model and its warnings, or [`DatasetError::Invalid`] with every
/// problem when there is any error.
pub fn load(adm: &Path, acf: Option<&Path>) -> Result<(Model, Vec<Diagnostic>), DatasetError> {
    let loaded = read(adm, acf)?;
    if loaded.has_errors() {
        return Err(DatasetError::Invalid(loaded.diagnostics));
    }
    Ok((loaded.model, loaded.diagnostics))
}

/// Runs only the lexer and parser (no lowering): what the fuzz target exercises. Never panics.
pub fn parse_only(text: &str, kind: FileKind) -> parser::ParsedFile {
    parser::parse(text, kind)
}
