//! Wavefront OBJ input: the vertices (`v`) and faces (`f`) of a closed mesh.
//!
//! Faces may be polygons (fan-triangulated from their first corner, which keeps a convex or
//! star-shaped face's orientation) and may reference corners as `v`, `v/vt`, `v//vn` or
//! `v/vt/vn`, with 1-based or negative (relative) indices. Texture coordinates, normals,
//! groups, objects, smoothing and materials are not geometry and are skipped; points (`p`),
//! lines (`l`) and free-form curves and surfaces cannot bound a solid and are errors. The
//! corners are then welded as STL corners are ([`super::stl::solid_from_corners`]), so a file that repeats a
//! vertex is read as one solid, and the mesh is checked to bound a solid. Errors name the file, and the line where there is one.

use super::stl::{StlMesh, solid_from_corners};
use crate::Point3;
use crate::geometry::MeshError;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why an OBJ file could not be used.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ObjError {
    /// The file could not be opened.
    #[error("OBJ file '{path}': cannot read: {message}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The system's message.
        message: String,
    },
    /// A line is not valid OBJ geometry.
    #[error("{path}:{line}: {message}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// The line, from 1.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// The faces do not bound a solid.
    #[error("OBJ file '{path}': {source}")]
    Mesh {
        /// The file.
        path: PathBuf,
        /// What is wrong with the mesh.
        source: MeshError,
    },
}

/// Statements that carry no geometry a contact needs.
const SKIPPED: [&str; 9] = ["vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib", "mg"];

/// Reads an OBJ file. With `accept_open`, a mesh that is not closed is accepted with a warning;
/// every other defect is an error.
pub fn read_obj(path: &Path, accept_open: bool) -> Result<StlMesh, ObjError> {
    // A device such as /dev/zero would be read without end.
    if std::fs::metadata(path).is_ok_and(|m| !m.is_file()) {
        return Err(ObjError::Read {
            path: path.to_path_buf(),
            message: "not a regular file".into(),
        });
    }
    let text = std::fs::read_to_string(path).map_err(|e| ObjError::Read {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    let corners = parse(&text).map_err(|(line, message)| ObjError::Parse {
        path: path.to_path_buf(),
        line,
        message,
    })?;
    solid_from_corners(&corners, accept_open, "OBJ", path).map_err(|source| ObjError::Mesh {
        path: path.to_path_buf(),
        source,
    })
}

/// The triangles' corners of an OBJ text, or the line (from 1) and message of the first error.
pub fn parse(text: &str) -> Result<Vec<[Point3; 3]>, (usize, String)> {
    let mut vertices: Vec<Point3> = Vec::new();
    let mut corners = Vec::new();
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let content = raw.split('#').next().unwrap_or("").trim();
        let mut words = content.split_whitespace();
        let Some(keyword) = words.next() else {
            continue;
        };
        match keyword {
            "v" => {
                let mut xyz = [0.0; 3];
                for (k, value) in xyz.iter_mut().enumerate() {
                    let word = words.next().ok_or_else(|| {
                        (
                            line,
                            format!("a vertex needs x, y and z; coordinate {} is missing", k + 1),
                        )
                    })?;
                    *value = word
                        .parse::<f64>()
                        .ok()
                        .filter(|x| x.is_finite())
                        .ok_or_else(|| {
                            (
                                line,
                                format!("vertex coordinate {word:?} is not a finite number"),
                            )
                        })?;
                }
                vertices.push(Point3::new(xyz[0], xyz[1], xyz[2]));
            }
            "f" => {
                let ids = words
                    .map(|word| corner(word, vertices.len()).map_err(|m| (line, m)))
                    .collect::<Result<Vec<usize>, _>>()?;
                if ids.len() < 3 {
                    return Err((
                        line,
                        format!("a face needs 3 corners or more, not {}", ids.len()),
                    ));
                }
                for k in 1..ids.len() - 1 {
                    corners.push([vertices[ids[0]], vertices[ids[k]], vertices[ids[k + 1]]]);
                }
            }
            "p" | "l" => {
                return Err((
                    line,
                    format!(
                        "'{keyword}' elements (points, lines) cannot bound a solid; give faces"
                    ),
                ));
            }
            k if SKIPPED.contains(&k) => {}
            other => {
                return Err((
                    line,
                    format!(
                        "'{other}' is not supported: only polygonal faces (v, f) describe the solid"
                    ),
                ));
            }
        }
    }
    if corners.is_empty() {
        return Err((
            text.lines().count().max(1),
            "no faces in the file".to_string(),
        ));
    }
    Ok(corners)
}

/// The 0-based vertex of a face corner `v`, `v/vt`, `v//vn` or `v/vt/vn` (1-based, or negative
/// counting back from the last vertex read), given `count` vertices so far.
fn corner(word: &str, count: usize) -> Result<usize, String> {
    let first = word.split('/').next().unwrap_or("");
    let index: i64 = first
        .parse()
        .map_err(|_| format!("face corner {word:?} does not start with a vertex index"))?;
    let resolved = match index {
        i if i > 0 => usize::try_from(i - 1).ok(),
        i if i < 0 => usize::try_from(i64::try_from(count).unwrap_or(i64::MAX) + i).ok(),
        _ => None,
    };
    resolved.filter(|&i| i < count).ok_or_else(|| {
        format!(
            "face corner {word:?} names vertex {index}, but {count} vertices are defined so far"
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quads_and_relative_indices_become_outward_triangles() {
        let text = "# a unit square's fan\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\nf -4 -3 -2\n";
        let corners = parse(text).unwrap();
        assert_eq!(corners.len(), 3);
        assert_eq!(corners[1][1], Point3::new(1.0, 1.0, 0.0));
        assert_eq!(corners[1][2], Point3::new(0.0, 1.0, 0.0));
        assert_eq!(corners[2][0], Point3::new(0.0, 0.0, 0.0));
    }

    #[test]
    fn malformed_lines_are_errors_at_their_line() {
        let cases = [
            ("v 0 0\n", 1, "coordinate 3 is missing"),
            ("v 0 0 x\n", 1, "not a finite number"),
            (
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
                4,
                "names vertex 4, but 3",
            ),
            ("v 0 0 0\nv 1 0 0\nf 1 2\n", 3, "3 corners or more"),
            ("v 0 0 0\nf 0 1 1\n", 2, "names vertex 0"),
            ("v 0 0 0\nl 1 1\n", 2, "cannot bound a solid"),
            ("cstype bspline\n", 1, "not supported"),
            ("v 0 0 0\n", 1, "no faces"),
        ];
        for (text, line, message) in cases {
            let (got_line, got) = parse(text).unwrap_err();
            assert_eq!(got_line, line, "{text:?}: {got}");
            assert!(got.contains(message), "{text:?}: {got}");
        }
    }
}
