//! The exact_pairs bench's mesh configurations: solids against two boxes joined as one mesh
//! (two 'feet', convex and dented) and a mesh box.

use crate::cases::{Case, cylinder, ground, tilt};
use contact_core::geometry::{Cuboid, Ellipsoid, Frustum, Plane, Torus, TriangleMesh};
use contact_core::{Geometry, Isometry3, Point3, UnitQuaternion};
use std::f64::consts::FRAC_PI_2;

/// Solids against the two-feet meshes (convex and dented) and a mesh box.
pub fn mesh_cases() -> Vec<Case> {
    vec![
        Case {
            name: "mesh_plane_two_feet",
            i: Geometry::Mesh(std::sync::Arc::new(two_feet())),
            j: ground(),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 0.9), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        // A tilted box pressed across both feet's tops: two regions.
        Case {
            name: "box_mesh_two_feet",
            i: Geometry::Cuboid(Cuboid::centered(1.5, 0.3, 0.4).unwrap()),
            j: Geometry::Mesh(std::sync::Arc::new(two_feet())),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.1, 1.2), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        // A tilted cylinder across both feet's tops: two regions.
        Case {
            name: "cylinder_mesh_two_feet",
            i: cylinder(0.3, 3.0),
            j: Geometry::Mesh(std::sync::Arc::new(two_feet())),
            pose_i: Isometry3::from_parts(
                nalgebra::Translation3::new(-1.5, 0.0, 1.1),
                UnitQuaternion::from_euler_angles(0.1, FRAC_PI_2 - 0.2, 0.0),
            ),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        // The same across feet each dented at a top corner (not convex: sliced).
        Case {
            name: "cylinder_mesh_dented_feet",
            i: cylinder(0.3, 3.0),
            j: Geometry::Mesh(std::sync::Arc::new(dented_feet())),
            pose_i: Isometry3::from_parts(
                nalgebra::Translation3::new(-1.5, 0.0, 1.1),
                UnitQuaternion::from_euler_angles(0.1, FRAC_PI_2 - 0.2, 0.0),
            ),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "frustum_mesh_two_feet",
            i: Geometry::Frustum(Frustum::new(0.6, 0.3, 1.5).unwrap()),
            j: Geometry::Mesh(std::sync::Arc::new(two_feet())),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(-1.0, 0.0, 0.8), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "torus_mesh_two_feet",
            i: Geometry::Torus(Torus::new(1.0, 0.3).unwrap()),
            j: Geometry::Mesh(std::sync::Arc::new(two_feet())),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 1.1), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "ellipsoid_mesh_two_feet",
            i: Geometry::Ellipsoid(Ellipsoid::new(1.6, 0.5, 0.4).unwrap()),
            j: Geometry::Mesh(std::sync::Arc::new(two_feet())),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 1.2), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "mesh_bounded_plane_two_feet",
            i: Geometry::Mesh(std::sync::Arc::new(two_feet())),
            j: Geometry::Plane(Plane::bounded(-1.2, 2.0, -2.0, 2.0).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 0.9), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "sphere_mesh_box",
            i: Geometry::sphere(0.5).unwrap(),
            j: Geometry::Mesh(std::sync::Arc::new(two_feet())),
            pose_i: Isometry3::translation(-1.0, 0.0, 1.3),
            pose_j: Isometry3::identity(),
            depth: Some(0.2),
        },
    ]
}

/// A closed mesh of two boxes (two 'feet'): 24 triangles, two contact regions on a plane.
fn two_feet() -> TriangleMesh {
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for (cx, h) in [(-1.0, [0.5, 0.4, 1.0]), (1.0, [0.3, 0.6, 1.0])] {
        let base = vertices.len() as u32;
        for k in 0..8u32 {
            let s = |bit: u32| if k & (1 << bit) != 0 { 1.0 } else { -1.0 };
            vertices.push(Point3::new(cx + s(0) * h[0], s(1) * h[1], s(2) * h[2]));
        }
        for q in [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ] {
            triangles.push([base + q[0], base + q[1], base + q[2]]);
            triangles.push([base + q[0], base + q[2], base + q[3]]);
        }
    }
    TriangleMesh::new(vertices, triangles).unwrap()
}

/// [`two_feet`] with each foot's top corner at `+x, +y` pushed in and down: no longer convex.
fn dented_feet() -> TriangleMesh {
    let feet = two_feet();
    let mut vertices = feet.vertices().to_vec();
    for foot in 0..2 {
        let v = &mut vertices[8 * foot + 7];
        *v = Point3::new(v.x - 0.1, v.y - 0.1, 0.7);
    }
    TriangleMesh::new(vertices, feet.triangles().to_vec()).unwrap()
}
