//! Meshes made of unit cells, their walls split along every cell boundary: vertices and edges
//! lie on many planes a box's faces can take, the degenerate contacts the triangle tests must
//! resolve alike in every pair.

use contact_core::geometry::TriangleMesh;
use contact_core::{Geometry, Point3};
use std::collections::{HashMap, HashSet};

/// The closed mesh bounding the union of the unit cells `cells` (integer corners): each cell
/// face no other cell covers, as two triangles, outward.
pub fn voxel_mesh(cells: &[[i32; 3]]) -> Geometry {
    let filled: HashSet<[i32; 3]> = cells.iter().copied().collect();
    let mut index: HashMap<[i32; 3], u32> = HashMap::new();
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for &c in cells {
        for axis in 0..3 {
            for sign in [-1, 1] {
                let mut next = c;
                next[axis] += sign;
                if filled.contains(&next) {
                    continue;
                }
                let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
                let mut base = c;
                if sign > 0 {
                    base[axis] += 1;
                }
                let corner = |du: i32, dv: i32| {
                    let mut p = base;
                    p[u] += du;
                    p[v] += dv;
                    p
                };
                let mut quad = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
                if sign < 0 {
                    quad.reverse();
                }
                let q = quad.map(|p| {
                    *index.entry(p).or_insert_with(|| {
                        vertices.push(Point3::new(
                            f64::from(p[0]),
                            f64::from(p[1]),
                            f64::from(p[2]),
                        ));
                        (vertices.len() - 1) as u32
                    })
                });
                triangles.push([q[0], q[1], q[2]]);
                triangles.push([q[0], q[2], q[3]]);
            }
        }
    }
    Geometry::Mesh(std::sync::Arc::new(
        TriangleMesh::new(vertices, triangles).unwrap(),
    ))
}

/// A 3 × 3 × 4 block of cells with the middle column removed: a square tube with a hole
/// `[1, 2]²` along z.
pub fn tube() -> Geometry {
    let mut cells = Vec::new();
    for k in 0..4 {
        for i in 0..3 {
            for j in 0..3 {
                if (i, j) != (1, 1) {
                    cells.push([i, j, k]);
                }
            }
        }
    }
    voxel_mesh(&cells)
}
