//! A box: 8 vertices, 12 triangles, exact at every tolerance.

use super::Tessellation;
use contact_core::geometry::Cuboid;
use contact_core::{Point3, Vector3};

/// The 12-triangle box in `G` (two per face, counter-clockwise from outside).
pub fn cuboid(b: &Cuboid) -> Tessellation {
    let (c, h) = (b.center(), b.half_extents());
    let vertices: Vec<Point3> = (0..8)
        .map(|k| {
            let s = |bit: u32| if k & (1 << bit) != 0 { 1.0 } else { -1.0 };
            c + Vector3::new(s(0) * h.x, s(1) * h.y, s(2) * h.z)
        })
        .collect();
    // Faces as quads (corner indices, counter-clockwise from outside) with their normals.
    let faces: [([u32; 4], Vector3); 6] = [
        ([0, 2, 3, 1], -Vector3::z()),
        ([4, 5, 7, 6], Vector3::z()),
        ([0, 1, 5, 4], -Vector3::y()),
        ([2, 6, 7, 3], Vector3::y()),
        ([0, 4, 6, 2], -Vector3::x()),
        ([1, 3, 7, 5], Vector3::x()),
    ];
    let mut triangles = Vec::with_capacity(12);
    let mut corner_normals = Vec::with_capacity(12);
    for ([a, b, c, d], n) in faces {
        triangles.push([a, b, c]);
        triangles.push([a, c, d]);
        corner_normals.push([n; 3]);
        corner_normals.push([n; 3]);
    }
    Tessellation {
        vertices,
        triangles,
        corner_normals,
    }
}
