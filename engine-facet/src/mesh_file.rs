//! A mesh file by its extension: `.stl` ([`crate::stl`]) or `.obj` ([`crate::obj`]).

use crate::obj::{ObjError, read_obj};
use crate::stl::{StlError, StlMesh, read_stl};
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why a mesh file could not be used.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MeshFileError {
    /// An STL file's error.
    #[error(transparent)]
    Stl(#[from] StlError),
    /// An OBJ file's error.
    #[error(transparent)]
    Obj(#[from] ObjError),
    /// Neither `.stl` nor `.obj`.
    #[error("mesh file '{0}': not a mesh format contact reads (give a .stl or .obj file)")]
    Format(PathBuf),
}

/// Whether `path` names a mesh format [`read_mesh_file`] reads (`.stl`, `.obj`, any case).
pub fn is_mesh_file(path: &Path) -> bool {
    matches!(extension(path).as_deref(), Some("stl" | "obj"))
}

fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
}

/// Reads an STL or OBJ file (by extension, any case). With `accept_open`, a mesh that is not
/// closed is accepted with a warning.
pub fn read_mesh_file(path: &Path, accept_open: bool) -> Result<StlMesh, MeshFileError> {
    match extension(path).as_deref() {
        Some("stl") => Ok(read_stl(path, accept_open)?),
        Some("obj") => Ok(read_obj(path, accept_open)?),
        _ => Err(MeshFileError::Format(path.to_path_buf())),
    }
}
