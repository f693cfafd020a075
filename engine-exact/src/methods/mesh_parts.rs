//! A closed mesh's connected components, found once when the mesh is prepared, so the pairs
//! with a closed form against a polyhedron (the cylinder's) can take each as one solid.
//!
//! A component is convex when every edge is convex: the vertex across it of the neighbouring
//! triangle lies on or behind the triangle's plane (within 1e-12 of the component's size). A
//! closed, connected, embedded surface that is locally convex at every edge bounds a convex
//! solid, and its solid meets another convex solid in one convex region: one contact. A
//! component that is not convex may meet it in several regions, which the closed form tells
//! apart or hands to the slicing. The parts are only used when their bounding boxes are
//! pairwise apart (two parts touching would make one region of the mesh's solid, two contacts
//! of the parts), and when each has at most [`MAX_PART_TRIANGLES`] triangles (the closed
//! forms' fixed capacity).

use contact_core::Point3;

/// Most triangles a part may have.
pub(crate) const MAX_PART_TRIANGLES: usize = 48;

/// One component of a mesh.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct MeshPart {
    /// Its triangles' indices.
    pub triangles: Vec<u32>,
    /// `neighbours[k][e]`: the position in [`Self::triangles`] of the triangle across edge
    /// `e` (vertices `e`, `e + 1`) of the part's `k`-th triangle.
    pub neighbours: Vec<[u8; 3]>,
    /// A ball holding it: centre and radius (mesh frame).
    pub centre: Point3,
    /// The ball's radius.
    pub radius: f64,
    /// Whether it bounds a convex solid.
    pub convex: bool,
}

/// The mesh's components, or none when one is too large or two components' bounding boxes
/// meet.
pub(crate) fn mesh_parts(
    vertices: &[Point3],
    triangles: &[[u32; 3]],
    neighbours: &[[u32; 3]],
) -> Vec<MeshPart> {
    let mut component = vec![u32::MAX; triangles.len()];
    let mut parts: Vec<(Vec<u32>, Point3, Point3)> = Vec::new();
    for seed in 0..triangles.len() {
        if component[seed] != u32::MAX {
            continue;
        }
        let label = parts.len() as u32;
        let mut members = vec![seed as u32];
        component[seed] = label;
        let mut next = 0;
        while next < members.len() {
            let t = members[next] as usize;
            next += 1;
            for &n in &neighbours[t] {
                if component[n as usize] == u32::MAX {
                    component[n as usize] = label;
                    members.push(n);
                }
            }
            if members.len() > MAX_PART_TRIANGLES {
                return Vec::new();
            }
        }
        let (mut lo, mut hi) = (
            vertices[triangles[seed][0] as usize],
            vertices[triangles[seed][0] as usize],
        );
        for &t in &members {
            for &v in &triangles[t as usize] {
                lo = lo.inf(&vertices[v as usize]);
                hi = hi.sup(&vertices[v as usize]);
            }
        }
        parts.push((members, lo, hi));
    }
    for i in 0..parts.len() {
        for j in 0..i {
            let ((_, lo_i, hi_i), (_, lo_j, hi_j)) = (&parts[i], &parts[j]);
            let apart = (0..3).any(|k| hi_i[k] < lo_j[k] || hi_j[k] < lo_i[k]);
            if !apart {
                return Vec::new();
            }
        }
    }
    parts
        .into_iter()
        .map(|(members, lo, hi)| {
            let convex = is_convex(vertices, triangles, neighbours, &members, (hi - lo).norm());
            // Positions within the part (it has at most MAX_PART_TRIANGLES < 256 triangles).
            let position = |t: u32| members.iter().position(|&m| m == t).unwrap_or(0) as u8;
            let neighbours = members
                .iter()
                .map(|&t| neighbours[t as usize].map(position))
                .collect();
            MeshPart {
                triangles: members,
                neighbours,
                centre: nalgebra::center(&lo, &hi),
                radius: 0.5 * (hi - lo).norm(),
                convex,
            }
        })
        .collect()
}

/// Whether the component `members` (of size `size`) is convex at every edge: the vertex across
/// each edge on or behind the triangle's plane. A triangle without a normal is not.
fn is_convex(
    vertices: &[Point3],
    triangles: &[[u32; 3]],
    neighbours: &[[u32; 3]],
    members: &[u32],
    size: f64,
) -> bool {
    members.iter().all(|&t| {
        let tri = triangles[t as usize];
        let [a, b, c] = tri.map(|v| vertices[v as usize]);
        let Some(normal) = (b - a).cross(&(c - a)).try_normalize(0.0) else {
            return false;
        };
        neighbours[t as usize].iter().all(|&n| {
            let across = triangles[n as usize]
                .iter()
                .find(|v| !tri.contains(v))
                .map(|&v| vertices[v as usize]);
            matches!(across, Some(p) if normal.dot(&(p - a)) <= 1e-12 * size)
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::Vector3;
    use contact_core::geometry::TriangleMesh;

    fn boxes(boxes: &[(Point3, Vector3)]) -> TriangleMesh {
        crate::pairs::box_mesh::boxes_surface(boxes)
    }

    fn parts_of(mesh: &TriangleMesh) -> Vec<MeshPart> {
        let prepared = crate::pairs::mesh_plane::PreparedMesh::new(mesh).unwrap();
        mesh_parts(
            &prepared.vertices,
            &prepared.triangles,
            &prepared.neighbours,
        )
    }

    /// Two boxes apart are two parts; overlapping bounding boxes, none.
    #[test]
    fn boxes_apart_are_parts_and_touching_ones_are_not() {
        let h = Vector3::repeat(0.5);
        let two = parts_of(&boxes(&[
            (Point3::origin(), h),
            (Point3::new(2.0, 0.0, 0.0), h),
        ]));
        assert_eq!(two.len(), 2);
        assert_eq!(two[0].triangles.len(), 12);
        assert!((two[1].centre - Point3::new(2.0, 0.0, 0.0)).norm() < 1e-15);
        let touching = parts_of(&boxes(&[
            (Point3::origin(), h),
            (Point3::new(1.0, 0.0, 0.0), h),
        ]));
        assert!(touching.is_empty());
    }

    /// A mesh with a dent (a vertex pushed inwards) is not convex.
    #[test]
    fn a_dented_box_is_not_convex() {
        let mesh = boxes(&[(Point3::origin(), Vector3::repeat(0.5))]);
        let mut vertices = mesh.vertices().to_vec();
        vertices[7] = Point3::new(0.3, 0.3, 0.3);
        let dented = TriangleMesh::new(vertices, mesh.triangles().to_vec()).unwrap();
        let parts = parts_of(&dented);
        assert_eq!(parts.len(), 1);
        assert!(!parts[0].convex);
        let whole = parts_of(&mesh);
        assert_eq!(whole.len(), 1);
        assert!(whole[0].convex);
    }

    /// The part's neighbours are the mesh's, by position in the part.
    #[test]
    fn part_neighbours_are_the_meshs() {
        let h = Vector3::repeat(0.5);
        let mesh = boxes(&[(Point3::origin(), h), (Point3::new(2.0, 0.0, 0.0), h)]);
        let prepared = crate::pairs::mesh_plane::PreparedMesh::new(&mesh).unwrap();
        for part in parts_of(&mesh) {
            for (k, &t) in part.triangles.iter().enumerate() {
                for e in 0..3 {
                    let across = part.triangles[part.neighbours[k][e] as usize];
                    assert_eq!(across, prepared.neighbours[t as usize][e]);
                }
            }
        }
    }
}
