//! Mesh files: `.stl` ([`stl`], ascii or binary) or `.obj` ([`obj`]), picked by extension,
//! welded and checked to bound a solid, for either engine.
//!
//! The one input contact-core reads: a mesh geometry is part of the vocabulary every engine
//! answers, and an embedder of the exact engine alone needs it as much as one of the faceted
//! engine. [`read_mesh_geometry`] is the short path (a closed solid as a [`Geometry`]);
//! [`read_mesh_file`] keeps the warnings and can accept an open mesh.
//!
//! ```
//! use contact_core::{Geometry, mesh_file};
//!
//! // A unit tetrahedron, its faces counter-clockwise seen from outside.
//! let path = std::env::temp_dir().join("contact_core_doc_tetra.obj");
//! std::fs::write(&path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")?;
//! let Geometry::Mesh(mesh) = mesh_file::read_mesh_geometry(&path)? else { unreachable!() };
//! assert_eq!((mesh.vertices().len(), mesh.triangles().len()), (4, 4));
//! // Anything else is an error naming the file.
//! let e = mesh_file::read_mesh_geometry(std::path::Path::new("part.step")).unwrap_err();
//! assert!(e.to_string().contains("part.step"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod obj;
pub mod stl;

use crate::Geometry;
use obj::{ObjError, read_obj};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use stl::{StlError, StlMesh, read_stl};
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

/// Reads an STL or OBJ file (by extension, any case) as a mesh [`Geometry`] in the file's own
/// frame and units: the triangles must bound a solid (closed, 2-manifold, outward oriented, no
/// zero-area facets), every defect is an error naming the file.
pub fn read_mesh_geometry(path: &Path) -> Result<Geometry, MeshFileError> {
    let read = read_mesh_file(path, false)?;
    Ok(Geometry::Mesh(Arc::new(read.mesh)))
}
