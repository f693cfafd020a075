//! Closed triangle meshes (Adams `EXTERNAL` geometry), validated at construction.

use crate::{Point3, Vector3};
use std::collections::HashMap;
use thiserror::Error;

/// Why a triangle list is not a closed, consistently oriented solid.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MeshError {
    /// Fewer than four triangles cannot close a volume.
    #[error("a closed mesh needs at least 4 triangles, got {count}")]
    TooFewTriangles {
        /// Triangles given.
        count: usize,
    },
    /// A triangle refers to a vertex that does not exist.
    #[error("triangle {triangle} refers to vertex {vertex}, but there are {vertex_count} vertices")]
    IndexOutOfRange {
        /// Triangle index.
        triangle: usize,
        /// The vertex index it uses.
        vertex: u32,
        /// Vertices given.
        vertex_count: usize,
    },
    /// A vertex coordinate is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate {coordinates:?}")]
    NonFiniteVertex {
        /// Vertex index.
        vertex: usize,
        /// Its coordinates.
        coordinates: [f64; 3],
    },
    /// A vertex coordinate is beyond the largest size a geometry may have.
    #[error(
        "vertex {vertex} has a coordinate beyond ±{:e} (LENGTH_RANGE): {coordinates:?}",
        crate::LENGTH_RANGE[1]
    )]
    VertexOutOfRange {
        /// Vertex index.
        vertex: usize,
        /// Its coordinates.
        coordinates: [f64; 3],
    },
    /// The mesh's bounding-box diagonal is below the smallest size a geometry may have.
    #[error(
        "the mesh is {size:e} across (its bounding-box diagonal), below {:e} (LENGTH_RANGE)",
        crate::LENGTH_RANGE[0]
    )]
    TooSmall {
        /// The bounding-box diagonal.
        size: f64,
    },
    /// A triangle has (relatively) zero area.
    #[error("triangle {triangle} has zero area (area {area:e} against the mesh size {size:e})")]
    ZeroAreaFacet {
        /// Triangle index.
        triangle: usize,
        /// Its area.
        area: f64,
        /// The mesh's bounding-box diagonal.
        size: f64,
    },
    /// An edge is used by only one triangle: the surface has a hole.
    #[error(
        "the mesh is open: {open_edges} edges belong to one triangle only (first: vertices {first:?})"
    )]
    Open {
        /// Number of boundary edges.
        open_edges: usize,
        /// One of them, as vertex indices.
        first: [u32; 2],
    },
    /// An edge is used by more than two triangles.
    #[error("the mesh is non-manifold: edge {edge:?} belongs to {count} triangles")]
    NonManifold {
        /// The edge, as vertex indices.
        edge: [u32; 2],
        /// How many triangles use it.
        count: usize,
    },
    /// Two neighbouring triangles traverse their shared edge in the same direction.
    #[error(
        "the mesh is inconsistently oriented: triangles {first} and {second} traverse edge {edge:?} the same way"
    )]
    InconsistentOrientation {
        /// The edge, as vertex indices.
        edge: [u32; 2],
        /// One triangle.
        first: usize,
        /// The other.
        second: usize,
    },
    /// Consistently oriented but the normals point inward (negative enclosed volume).
    #[error(
        "the mesh is inside out: its enclosed volume is {volume:e} < 0 (reverse the triangle winding)"
    )]
    InsideOut {
        /// The signed volume.
        volume: f64,
    },
}

/// A triangle mesh in its geometry frame `G`: counter-clockwise triangles seen from outside.
///
/// [`TriangleMesh::new`] accepts only closed, 2-manifold, consistently and outward oriented
/// meshes without zero-area facets: every edge is shared by exactly two triangles that traverse
/// it in opposite directions, and the enclosed volume is positive. Such a mesh bounds a solid,
/// so "inside" is defined and a body fully inside another is a contact.
/// [`TriangleMesh::new_open`] skips the closedness checks for callers that accept open meshes
/// knowingly (they then cannot rely on inside tests).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleMesh {
    vertices: Vec<Point3>,
    triangles: Vec<[u32; 3]>,
    closed: bool,
}

/// A facet whose area is below `ZERO_AREA_RELATIVE · L²` (L the bounding-box diagonal) is
/// degenerate: its normal is not defined to better than about 1e-4 rad in f64.
pub const ZERO_AREA_RELATIVE: f64 = 1e-24;

impl TriangleMesh {
    /// A closed, outward-oriented mesh; see the type's docs for the checks.
    pub fn new(vertices: Vec<Point3>, triangles: Vec<[u32; 3]>) -> Result<Self, MeshError> {
        let mesh = Self::checked_facets(vertices, triangles)?;
        mesh.check_closed()?;
        let volume = mesh.signed_volume();
        if volume <= 0.0 {
            return Err(MeshError::InsideOut { volume });
        }
        Ok(Self {
            closed: true,
            ..mesh
        })
    }

    /// The surfaces of axis-aligned boxes `(centre, half extents)` as one closed mesh: each box
    /// its 8 corners (corner `k` at `centre + (±h_x, ±h_y, ±h_z)`, bit 0 of `k` the sign of
    /// x, bit 1 of y, bit 2 of z) and 12 outward triangles, two a face. Boxes that overlap or
    /// touch make a mesh that is closed but not the surface of their union. Errors as
    /// [`TriangleMesh::new`] (a zero half extent makes zero-area facets).
    pub fn boxes(boxes: &[(Point3, Vector3)]) -> Result<Self, MeshError> {
        const FACES: [[u32; 4]; 6] = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let mut vertices = Vec::with_capacity(8 * boxes.len());
        let mut triangles = Vec::with_capacity(12 * boxes.len());
        for (c, h) in boxes {
            let base = vertices.len() as u32;
            vertices.extend((0..8u32).map(|k| {
                let s = |bit: u32| if k & (1 << bit) != 0 { 1.0 } else { -1.0 };
                Point3::new(c.x + s(0) * h.x, c.y + s(1) * h.y, c.z + s(2) * h.z)
            }));
            for q in FACES.map(|q| q.map(|k| base + k)) {
                triangles.push([q[0], q[1], q[2]]);
                triangles.push([q[0], q[2], q[3]]);
            }
        }
        Self::new(vertices, triangles)
    }

    /// A mesh that may be open; indices, coordinates and facet areas are still checked.
    pub fn new_open(vertices: Vec<Point3>, triangles: Vec<[u32; 3]>) -> Result<Self, MeshError> {
        let mesh = Self::checked_facets(vertices, triangles)?;
        let closed = mesh.check_closed().is_ok() && mesh.signed_volume() > 0.0;
        Ok(Self { closed, ..mesh })
    }

    fn checked_facets(vertices: Vec<Point3>, triangles: Vec<[u32; 3]>) -> Result<Self, MeshError> {
        if triangles.len() < 4 {
            return Err(MeshError::TooFewTriangles {
                count: triangles.len(),
            });
        }
        for (i, v) in vertices.iter().enumerate() {
            if !v.iter().all(|c| c.is_finite()) {
                return Err(MeshError::NonFiniteVertex {
                    vertex: i,
                    coordinates: [v.x, v.y, v.z],
                });
            }
            if v.iter().any(|c| c.abs() > crate::LENGTH_RANGE[1]) {
                return Err(MeshError::VertexOutOfRange {
                    vertex: i,
                    coordinates: [v.x, v.y, v.z],
                });
            }
        }
        for (t, tri) in triangles.iter().enumerate() {
            for &v in tri {
                if v as usize >= vertices.len() {
                    return Err(MeshError::IndexOutOfRange {
                        triangle: t,
                        vertex: v,
                        vertex_count: vertices.len(),
                    });
                }
            }
        }
        let mesh = Self {
            vertices,
            triangles,
            closed: false,
        };
        let size = mesh.bounding_box_diagonal();
        if size < crate::LENGTH_RANGE[0] {
            return Err(MeshError::TooSmall { size });
        }
        for t in 0..mesh.triangles.len() {
            let area = mesh.triangle_area(t);
            if area.is_nan() || area <= ZERO_AREA_RELATIVE * size * size {
                return Err(MeshError::ZeroAreaFacet {
                    triangle: t,
                    area,
                    size,
                });
            }
        }
        Ok(mesh)
    }

    fn check_closed(&self) -> Result<(), MeshError> {
        // Directed edge → triangle. A closed, consistently oriented 2-manifold has every
        // directed edge exactly once and its reverse exactly once.
        let mut directed: HashMap<(u32, u32), usize> =
            HashMap::with_capacity(self.triangles.len() * 3);
        let mut undirected: HashMap<(u32, u32), usize> =
            HashMap::with_capacity(self.triangles.len() * 3);
        for (t, tri) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                let key = (a.min(b), a.max(b));
                let count = undirected.entry(key).or_insert(0);
                *count += 1;
                if *count > 2 {
                    return Err(MeshError::NonManifold {
                        edge: [key.0, key.1],
                        count: *count,
                    });
                }
                if let Some(&first) = directed.get(&(a, b)) {
                    return Err(MeshError::InconsistentOrientation {
                        edge: [a, b],
                        first,
                        second: t,
                    });
                }
                directed.insert((a, b), t);
            }
        }
        let mut open: Vec<[u32; 2]> = undirected
            .iter()
            .filter(|&(_, &c)| c == 1)
            .map(|(&(a, b), _)| [a, b])
            .collect();
        if !open.is_empty() {
            open.sort_unstable();
            return Err(MeshError::Open {
                open_edges: open.len(),
                first: open[0],
            });
        }
        Ok(())
    }

    /// The vertices in `G`.
    pub fn vertices(&self) -> &[Point3] {
        &self.vertices
    }

    /// The triangles as vertex indices, counter-clockwise seen from outside.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// True when the mesh passed the closed-solid checks.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The three corners of triangle `t`.
    pub fn triangle(&self, t: usize) -> [Point3; 3] {
        let [a, b, c] = self.triangles[t];
        [
            self.vertices[a as usize],
            self.vertices[b as usize],
            self.vertices[c as usize],
        ]
    }

    /// The area of triangle `t`.
    pub fn triangle_area(&self, t: usize) -> f64 {
        let [a, b, c] = self.triangle(t);
        0.5 * (b - a).cross(&(c - a)).norm()
    }

    /// The enclosed volume by the divergence theorem (positive for an outward mesh), computed
    /// about the bounding-box centre to keep round-off relative to the mesh's size.
    pub fn signed_volume(&self) -> f64 {
        let (lo, hi) = self.bounding_box();
        let o = Point3::from(0.5 * (lo.coords + hi.coords));
        (0..self.triangles.len())
            .map(|t| {
                let [a, b, c] = self.triangle(t);
                (a - o).dot(&(b - o).cross(&(c - o))) / 6.0
            })
            .sum()
    }

    /// The axis-aligned bounding box `(min, max)` in `G`.
    pub fn bounding_box(&self) -> (Point3, Point3) {
        let mut lo = Vector3::repeat(f64::INFINITY);
        let mut hi = Vector3::repeat(f64::NEG_INFINITY);
        for v in &self.vertices {
            lo = lo.inf(&v.coords);
            hi = hi.sup(&v.coords);
        }
        (Point3::from(lo), Point3::from(hi))
    }

    /// The diagonal of the bounding box.
    pub fn bounding_box_diagonal(&self) -> f64 {
        let (lo, hi) = self.bounding_box();
        (hi - lo).norm()
    }

    /// Bytes held by the vertex and triangle arrays.
    pub fn heap_bytes(&self) -> usize {
        self.vertices.capacity() * std::mem::size_of::<Point3>()
            + self.triangles.capacity() * std::mem::size_of::<[u32; 3]>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetra() -> (Vec<Point3>, Vec<[u32; 3]>) {
        (
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
                Point3::new(0.0, 0.0, 1.0),
            ],
            vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        )
    }

    #[test]
    fn a_tetrahedron_is_a_closed_solid_of_volume_one_sixth() {
        let (v, t) = tetra();
        let m = TriangleMesh::new(v, t).unwrap();
        assert!((m.signed_volume() - 1.0 / 6.0).abs() < 1e-15);
        assert!(m.is_closed());
    }

    #[test]
    fn each_defect_is_reported() {
        let (v, mut t) = tetra();
        t.swap(0, 0);
        let mut flipped = t.clone();
        flipped[0] = [0, 1, 2];
        assert!(matches!(
            TriangleMesh::new(v.clone(), flipped).unwrap_err(),
            MeshError::InconsistentOrientation { .. }
        ));
        let inside_out: Vec<[u32; 3]> = t.iter().map(|&[a, b, c]| [a, c, b]).collect();
        assert!(matches!(
            TriangleMesh::new(v.clone(), inside_out).unwrap_err(),
            MeshError::InsideOut { .. }
        ));
        let mut open = t.clone();
        open[3] = [1, 2, 0];
        let err = TriangleMesh::new(v.clone(), open).unwrap_err();
        assert!(
            matches!(
                err,
                MeshError::NonManifold { .. } | MeshError::InconsistentOrientation { .. }
            ),
            "{err}"
        );
        let mut bad_index = t.clone();
        bad_index[1] = [0, 1, 9];
        assert!(matches!(
            TriangleMesh::new(v.clone(), bad_index).unwrap_err(),
            MeshError::IndexOutOfRange { vertex: 9, .. }
        ));
        let mut degenerate_v = v.clone();
        degenerate_v[3] = Point3::new(0.5, 0.5, 0.0);
        assert!(matches!(
            TriangleMesh::new(degenerate_v, t.clone()).unwrap_err(),
            MeshError::ZeroAreaFacet { triangle: 3, .. }
        ));
        let mut nan = v.clone();
        nan[2].y = f64::NAN;
        assert!(matches!(
            TriangleMesh::new(nan, t.clone()).unwrap_err(),
            MeshError::NonFiniteVertex { vertex: 2, .. }
        ));
        assert!(matches!(
            TriangleMesh::new(v.clone(), t[..3].to_vec()).unwrap_err(),
            MeshError::TooFewTriangles { count: 3 }
        ));
    }

    #[test]
    fn an_open_mesh_is_reported_as_open_and_accepted_by_new_open() {
        // A square pyramid without its base: 4 side triangles, 4 boundary edges.
        let v = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.5, 0.5, 1.0),
        ];
        let t = vec![[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]];
        let err = TriangleMesh::new(v.clone(), t.clone()).unwrap_err();
        assert!(
            matches!(err, MeshError::Open { open_edges: 4, .. }),
            "{err}"
        );
        let m = TriangleMesh::new_open(v, t).unwrap();
        assert!(!m.is_closed());
    }
}
