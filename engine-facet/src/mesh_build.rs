//! What [`crate::facet_mesh::FacetMesh::build`] derives from a tessellation before its tree:
//! the triangles' edge neighbours, the bounds, the mass properties, the longest edge and
//! whether the mesh is convex.

use crate::facet_mesh::NO_NEIGHBOR;
use contact_core::{Point3, Vector3};
use std::collections::HashMap;

/// Each triangle's neighbour across each of its edges (edge `k` runs from corner `k` to
/// `k + 1`): the triangle holding the same edge the other way, [`NO_NEIGHBOR`] where none does.
pub(crate) fn edge_neighbours(triangles: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let edge = |from: u32, to: u32| (u64::from(from) << 32) | u64::from(to);
    let mut edges: HashMap<u64, u32, BuildEdgeHasher> =
        HashMap::with_capacity_and_hasher(triangles.len() * 3, BuildEdgeHasher);
    for (i, tri) in triangles.iter().enumerate() {
        for k in 0..3 {
            edges.insert(edge(tri[k], tri[(k + 1) % 3]), i as u32);
        }
    }
    triangles
        .iter()
        .map(|tri| {
            [0, 1, 2].map(|k| {
                edges
                    .get(&edge(tri[(k + 1) % 3], tri[k]))
                    .copied()
                    .unwrap_or(NO_NEIGHBOR)
            })
        })
        .collect()
}

/// The vertices' axis-aligned bounds, `(lo, hi)`.
pub(crate) fn bounds(vertices: &[Point3]) -> (Vector3, Vector3) {
    let mut lo = Vector3::repeat(f64::INFINITY);
    let mut hi = Vector3::repeat(f64::NEG_INFINITY);
    for v in vertices {
        lo = lo.inf(&v.coords);
        hi = hi.sup(&v.coords);
    }
    (lo, hi)
}

/// A tessellation's volume, centroid, area and unit face normals (divergence theorem over
/// cones from `origin`, the bounds' centre, which keeps the sums small).
pub(crate) struct MassProperties {
    pub volume: f64,
    pub centroid: Point3,
    pub area: f64,
    pub face_normals: Vec<Vector3>,
}

impl MassProperties {
    /// The centroid of a closed body with positive volume is its volume's; otherwise the
    /// vertices' mean.
    pub fn of(vertices: &[Point3], triangles: &[[u32; 3]], origin: Vector3, closed: bool) -> Self {
        let (mut volume, mut moment, mut area) = (0.0, Vector3::zeros(), 0.0);
        let mut face_normals = Vec::with_capacity(triangles.len());
        for tri in triangles {
            let [a, b, c] = tri.map(|v| vertices[v as usize].coords - origin);
            let n = (b - a).cross(&(c - a));
            area += 0.5 * n.norm();
            face_normals.push(n.try_normalize(0.0).unwrap_or_else(Vector3::z));
            let v = a.dot(&b.cross(&c)) / 6.0;
            volume += v;
            moment += v * (a + b + c) / 4.0;
        }
        let centroid = if closed && volume > 0.0 {
            Point3::from(origin + moment / volume)
        } else {
            let sum: Vector3 = vertices.iter().map(|v| v.coords).sum();
            Point3::from(sum / vertices.len().max(1) as f64)
        };
        Self {
            volume,
            centroid,
            area,
            face_normals,
        }
    }
}

/// The longest edge of any triangle.
pub(crate) fn longest_edge(vertices: &[Point3], triangles: &[[u32; 3]]) -> f64 {
    triangles
        .iter()
        .flat_map(|t| {
            let [a, b, c] = t.map(|v| vertices[v as usize]);
            [
                (b - a).norm_squared(),
                (c - b).norm_squared(),
                (a - c).norm_squared(),
            ]
        })
        .fold(0.0, f64::max)
        .sqrt()
}

/// Hashes a directed edge `(from << 32) | to` with one multiply-xorshift round: the keys are
/// small integers, not chosen by an adversary, and SipHash made the edge map a third of
/// building a mesh. Lookups only: the neighbours do not depend on the hash.
#[derive(Debug, Clone, Copy, Default)]
struct BuildEdgeHasher;

impl std::hash::BuildHasher for BuildEdgeHasher {
    type Hasher = EdgeHasher;

    fn build_hasher(&self) -> EdgeHasher {
        EdgeHasher(0)
    }
}

/// See [`BuildEdgeHasher`].
#[derive(Debug, Clone, Copy)]
struct EdgeHasher(u64);

impl std::hash::Hasher for EdgeHasher {
    fn finish(&self) -> u64 {
        let mut z = self.0.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        z ^= z >> 29;
        z = z.wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z ^ (z >> 32)
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = self.0.rotate_left(8) ^ u64::from(b);
        }
    }

    fn write_u64(&mut self, n: u64) {
        self.0 ^= n;
    }
}

/// Each vertex's unit normal: its triangles' unit normals weighted by their angles at the
/// vertex (the angle-weighted pseudo-normal, Bærentzen & Aanæs 2005: a direction in the
/// vertex's normal cone, the same whichever way the faces around it are triangulated). A
/// vertex of no triangle, or whose weighted normals cancel, gets the zero vector.
pub(crate) fn vertex_normals(
    vertices: &[Point3],
    triangles: &[[u32; 3]],
    face_normals: &[Vector3],
) -> Vec<Vector3> {
    let mut sums = vec![Vector3::zeros(); vertices.len()];
    for (t, n) in triangles.iter().zip(face_normals) {
        for k in 0..3 {
            let v = vertices[t[k] as usize];
            let (e1, e2) = (
                vertices[t[(k + 1) % 3] as usize] - v,
                vertices[t[(k + 2) % 3] as usize] - v,
            );
            let angle = e1.cross(&e2).norm().atan2(e1.dot(&e2));
            sums[t[k] as usize] += angle * n;
        }
    }
    sums.into_iter()
        .map(|s| s.try_normalize(0.0).unwrap_or_else(Vector3::zeros))
        .collect()
}

/// Whether a closed mesh bounds a convex solid: it is one edge-connected surface, every edge
/// has a neighbour that returns the link, and at every edge the neighbour's far corner lies on
/// or behind the triangle's plane, within `1e-12·size` (coplanar facets, such as a cap's fan,
/// count as convex). A closed embedded surface that is convex at every edge bounds a convex
/// solid, whose surface below any plane is one connected piece.
pub(crate) fn is_convex(
    vertices: &[Point3],
    triangles: &[[u32; 3]],
    neighbors: &[[u32; 3]],
    face_normals: &[Vector3],
    size: f64,
) -> bool {
    let tolerance = 1e-12 * size;
    let convex_edges = triangles.iter().enumerate().all(|(t, tri)| {
        (0..3).all(|k| {
            let nb = neighbors[t][k];
            if nb == NO_NEIGHBOR || !neighbors[nb as usize].contains(&(t as u32)) {
                return false;
            }
            let far = triangles[nb as usize]
                .into_iter()
                .find(|&v| v != tri[k] && v != tri[(k + 1) % 3]);
            far.is_some_and(|v| {
                let offset = vertices[v as usize] - vertices[tri[0] as usize];
                face_normals[t].dot(&offset) <= tolerance
            })
        })
    });
    convex_edges && edge_connected(triangles.len(), neighbors)
}

/// Whether every triangle is reached from the first across shared edges.
fn edge_connected(count: usize, neighbors: &[[u32; 3]]) -> bool {
    if count == 0 {
        return false;
    }
    let mut seen = vec![false; count];
    let mut stack = vec![0u32];
    seen[0] = true;
    let mut reached = 1;
    while let Some(t) = stack.pop() {
        for nb in neighbors[t as usize] {
            if nb != NO_NEIGHBOR && !seen[nb as usize] {
                seen[nb as usize] = true;
                reached += 1;
                stack.push(nb);
            }
        }
    }
    reached == count
}
