//! STL input (ascii and binary, through `stl_io`): weld, then check the mesh bounds a solid.
//!
//! STL stores every triangle with its own three f32 corners. Corners closer than
//! [`WELD_RELATIVE`] × the bounding-box diagonal are merged into one vertex (grid hashing with a
//! cell of that size, checking the 27 neighbouring cells), then
//! [`TriangleMesh::new`](crate::geometry::TriangleMesh::new) checks the mesh is closed,
//! 2-manifold, consistently and outward oriented and free of zero-area facets (a facet whose
//! corners weld together has zero area). Errors name the file.

use crate::Point3;
use crate::geometry::{MeshError, TriangleMesh};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Corners within this fraction of the mesh's bounding-box diagonal are one vertex.
pub const WELD_RELATIVE: f64 = 1e-7;

/// The most triangles an STL file may hold (about 1.5 GB of corners while it is welded). A
/// binary file's count is read from its header and checked before anything is allocated; an
/// ASCII file is refused when its triangles pass the bound.
pub const MAX_TRIANGLES: u64 = 20_000_000;

/// A binary STL: an 80-byte header, a little-endian `u32` triangle count, 50 bytes a triangle.
const BINARY_HEADER: u64 = 84;
/// Bytes per triangle in a binary STL (normal, three corners, attribute count).
const BINARY_TRIANGLE: u64 = 50;

/// Why an STL file could not be used.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StlError {
    /// The file could not be opened or parsed.
    #[error("STL file '{path}': cannot read: {message}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The reader's message.
        message: String,
    },
    /// Not a regular file (a directory, a device such as `/dev/zero`, a pipe).
    #[error("STL file '{path}': not a regular file")]
    NotAFile {
        /// The file.
        path: PathBuf,
    },
    /// More triangles than [`MAX_TRIANGLES`].
    #[error("STL file '{path}': {triangles} triangles, more than the bound of {MAX_TRIANGLES}")]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its triangle count (a binary file's header, or an ASCII file's triangles so far).
        triangles: u64,
    },
    /// A binary STL whose size does not match the triangle count in its header.
    #[error(
        "STL file '{path}': not a valid STL: it does not start with 'solid' (ASCII), and as binary STL its header gives {triangles} triangles ({} bytes) but the file has {size} bytes (cut short, or not an STL file)",
        BINARY_HEADER + BINARY_TRIANGLE * triangles
    )]
    BinarySize {
        /// The file.
        path: PathBuf,
        /// The count in the header.
        triangles: u64,
        /// The file's size in bytes.
        size: u64,
    },
    /// Too short to be an STL file.
    #[error(
        "STL file '{path}': not a valid STL: {size} bytes, shorter than a binary STL's {BINARY_HEADER}-byte header, and it does not start with 'solid' (ASCII)"
    )]
    TooShort {
        /// The file.
        path: PathBuf,
        /// The file's size in bytes.
        size: u64,
    },
    /// The triangles do not bound a solid (open, non-manifold, inconsistently oriented, inside
    /// out, zero-area facets, too few triangles).
    #[error("STL file '{path}': {source}")]
    Mesh {
        /// The file.
        path: PathBuf,
        /// What is wrong with the mesh.
        source: MeshError,
    },
}

/// A mesh read from STL, with any warnings (an accepted open mesh).
#[derive(Debug, Clone, PartialEq)]
pub struct StlMesh {
    /// The welded mesh.
    pub mesh: TriangleMesh,
    /// Warnings to show the user.
    pub warnings: Vec<String>,
}

/// Reads an ascii or binary STL file. With `accept_open`, a mesh that is not closed is accepted
/// with a warning (it then cannot be "inside" anything); every other defect is an error.
pub fn read_stl(path: &Path, accept_open: bool) -> Result<StlMesh, StlError> {
    let read_error = |message: String| StlError::Read {
        path: path.to_path_buf(),
        message,
    };
    let mut file = std::fs::File::open(path).map_err(|e| read_error(e.to_string()))?;
    check_size(path, &mut file)?;
    // stl_io's messages name no line ("invalid float literal"): an ASCII file's first
    // malformed line is found and named.
    let located = |e: std::io::Error| read_error(with_ascii_line(path, e.to_string()));
    let reader = stl_io::create_stl_reader(&mut file).map_err(located)?;
    let mut corners: Vec<[Point3; 3]> = Vec::new();
    for t in reader {
        let t = t.map_err(located)?;
        if corners.len() as u64 >= MAX_TRIANGLES {
            return Err(StlError::TooLarge {
                path: path.to_path_buf(),
                triangles: corners.len() as u64 + 1,
            });
        }
        corners.push(
            t.vertices
                .map(|v| Point3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]))),
        );
    }
    solid_from_corners(&corners, accept_open, "STL", path).map_err(|source| StlError::Mesh {
        path: path.to_path_buf(),
        source,
    })
}

/// `message` with the first line of an ASCII STL file that is not valid ASCII STL, when there
/// is one (`line 5: 'vertex 0 0 oops': expected 3 numbers after 'vertex'`).
fn with_ascii_line(path: &Path, message: String) -> String {
    // Files past 256 MiB are not read a second time just to locate the line.
    if std::fs::metadata(path).is_ok_and(|m| m.len() > 1 << 28) {
        return message;
    }
    let Ok(text) = std::fs::read_to_string(path) else {
        return message;
    };
    if !text.trim_start().starts_with("solid") {
        return message;
    }
    for (index, line) in text.lines().enumerate() {
        let words: Vec<&str> = line.split_whitespace().collect();
        let numbers = |after: usize| {
            words.len() == after + 3 && words[after..].iter().all(|w| w.parse::<f32>().is_ok())
        };
        let problem = match words.as_slice() {
            [] | ["endloop"] | ["endfacet"] | ["outer", "loop"] => None,
            ["solid", ..] | ["endsolid", ..] => None,
            ["vertex", ..] if numbers(1) => None,
            ["vertex", ..] => Some("expected 3 numbers after 'vertex'"),
            ["facet", "normal", ..] if numbers(2) => None,
            ["facet", ..] => Some("expected 'facet normal' and 3 numbers"),
            _ => Some(
                "not an ASCII STL keyword (solid, facet normal, outer loop, vertex, endloop, endfacet, endsolid)",
            ),
        };
        if let Some(problem) = problem {
            return format!(
                "{message} (line {}: '{}': {problem})",
                index + 1,
                line.trim()
            );
        }
    }
    message
}

/// Refuses, before anything is allocated, a file that is not a regular file, and a file that
/// is not ASCII (`solid` first) whose size does not match its binary header's triangle count
/// or whose count passes [`MAX_TRIANGLES`]. Leaves `file` at its start.
fn check_size(path: &Path, file: &mut std::fs::File) -> Result<(), StlError> {
    use std::io::{Read, Seek};
    let read_error = |e: std::io::Error| StlError::Read {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let metadata = file.metadata().map_err(read_error)?;
    if !metadata.is_file() {
        return Err(StlError::NotAFile {
            path: path.to_path_buf(),
        });
    }
    let size = metadata.len();
    let mut head = Vec::with_capacity(BINARY_HEADER as usize);
    file.by_ref()
        .take(BINARY_HEADER)
        .read_to_end(&mut head)
        .map_err(read_error)?;
    file.rewind().map_err(read_error)?;
    let ascii = head.trim_ascii_start().starts_with(b"solid");
    if head.len() < BINARY_HEADER as usize {
        return if ascii {
            Ok(())
        } else {
            Err(StlError::TooShort {
                path: path.to_path_buf(),
                size,
            })
        };
    }
    let triangles = u64::from(u32::from_le_bytes([head[80], head[81], head[82], head[83]]));
    let binary_size = BINARY_HEADER + BINARY_TRIANGLE * triangles;
    if binary_size == size && triangles > MAX_TRIANGLES {
        return Err(StlError::TooLarge {
            path: path.to_path_buf(),
            triangles,
        });
    }
    if binary_size != size && !ascii {
        return Err(StlError::BinarySize {
            path: path.to_path_buf(),
            triangles,
            size,
        });
    }
    Ok(())
}

/// Welds triangle corners read from a mesh file and checks they bound a solid; with
/// `accept_open`, an open mesh is kept with a warning naming the `format` and the file.
pub fn solid_from_corners(
    corners: &[[Point3; 3]],
    accept_open: bool,
    format: &str,
    path: &Path,
) -> Result<StlMesh, MeshError> {
    let (vertices, triangles) = weld(corners);
    match TriangleMesh::new(vertices.clone(), triangles.clone()) {
        Ok(mesh) => Ok(StlMesh {
            mesh,
            warnings: Vec::new(),
        }),
        Err(e @ MeshError::Open { .. }) if accept_open => Ok(StlMesh {
            mesh: TriangleMesh::new_open(vertices, triangles)?,
            warnings: vec![format!(
                "{format} file '{}': accepted although {e}; it cannot contain another body",
                path.display()
            )],
        }),
        Err(e) => Err(e),
    }
}

/// Merges corners closer than [`WELD_RELATIVE`] × the bounding-box diagonal.
pub fn weld(corners: &[[Point3; 3]]) -> (Vec<Point3>, Vec<[u32; 3]>) {
    let mut lo = Point3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY);
    let mut hi = Point3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    for p in corners.iter().flatten() {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    let tol = (WELD_RELATIVE * (hi - lo).norm()).max(f64::MIN_POSITIVE);
    let cell = |p: &Point3| -> [i64; 3] {
        [0, 1, 2].map(|k| ((p[k] - lo[k]) / tol).floor().clamp(-1e18, 1e18) as i64)
    };
    let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
    let mut vertices: Vec<Point3> = Vec::new();
    let mut triangles = Vec::with_capacity(corners.len());
    for tri in corners {
        let ids = tri.map(|p| {
            let c = cell(&p);
            for dx in -1..=1 {
                for dy in -1..=1 {
                    for dz in -1..=1 {
                        if let Some(list) = grid.get(&[c[0] + dx, c[1] + dy, c[2] + dz]) {
                            for &v in list {
                                if (vertices[v as usize] - p).norm() <= tol {
                                    return v;
                                }
                            }
                        }
                    }
                }
            }
            let id = vertices.len() as u32;
            vertices.push(p);
            grid.entry(c).or_default().push(id);
            id
        });
        triangles.push(ids);
    }
    (vertices, triangles)
}
