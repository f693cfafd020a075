//! The kernel scenes on bounded planes (across an edge and well inside) and on two boxes
//! joined as one mesh (two "feet", convex and dented).

use super::shapes::{ball, bounded, cuboid, ellipsoid, frustum, rod, torus};
use super::{Configuration, Scene, at, tilted_at};
use contact_core::geometry::{Plane, TriangleMesh};
use contact_core::{Geometry, Isometry3, Point3, UnitQuaternion, Vector3};
use std::f64::consts::FRAC_PI_2;
use std::sync::Arc;

/// Solids on a bounded plane: across its edge x = −0.2, and well inside a 100 × 100 one (the
/// `_inside` scenes, which the bounded pairs answer with the unbounded plane's closed forms).
pub(super) fn bounded_plane_scene(name: &'static str) -> Option<Scene> {
    let edge = "across a bounded plane's edge";
    let well = "well inside a bounded plane";
    let (body, height, depth, scale, kind, place) = match name {
        "frustum_bounded_plane" => (frustum(0.6, 0.3, 1.5), -0.1, 0.3108, 0.8, "frustum", edge),
        "cylinder_bounded_plane" => (rod(0.5, 2.0), -0.1, 0.2757, 0.75, "cylinder", edge),
        "torus_bounded_plane" => (torus(1.0, 0.3), 0.5, 0.1513, 0.56, "torus", edge),
        "ellipsoid_bounded_plane" => (
            ellipsoid(1.0, 0.6, 0.4),
            0.3,
            0.1575,
            0.54,
            "ellipsoid",
            edge,
        ),
        "cylinder_bounded_plane_inside" => (rod(0.5, 2.0), -0.1, 0.2757, 0.71, "cylinder", well),
        "torus_bounded_plane_inside" => (torus(1.0, 0.3), 0.5, 0.1513, 0.58, "torus", well),
        "ellipsoid_bounded_plane_inside" => (
            ellipsoid(1.0, 0.6, 0.4),
            0.3,
            0.1582,
            0.62,
            "ellipsoid",
            well,
        ),
        _ => return None,
    };
    let inside = name.ends_with("_inside");
    let configuration = Configuration {
        i: body,
        j: if inside {
            bounded(-50.0, 50.0, -50.0, 50.0)
        } else {
            bounded(-0.2, 2.0, -2.0, 2.0)
        },
        pose_i: tilted_at(0.0, 0.0, height),
        pose_j: Isometry3::identity(),
        depth,
        approach: Vector3::z(),
        scale,
    };
    let description = format!("a tilted {kind} {place}");
    Some(configuration.scene(name, description))
}

/// Solids on two boxes joined as one mesh (two "feet", convex and dented), and the feet on
/// planes.
pub(super) fn feet_scene(name: &'static str) -> Option<Scene> {
    let feet = || Geometry::Mesh(Arc::new(two_feet()));
    let across = Isometry3::from_parts(
        nalgebra::Translation3::new(-1.5, 0.0, 1.1),
        UnitQuaternion::from_euler_angles(0.1, FRAC_PI_2 - 0.2, 0.0),
    );
    let on = |i: Geometry, j: Geometry, pose_i: Isometry3, depth: f64, scale: f64| Configuration {
        i,
        j,
        pose_i,
        pose_j: Isometry3::identity(),
        depth,
        approach: Vector3::z(),
        scale,
    };
    let ground = || Geometry::Plane(Plane::unbounded());
    let (configuration, description) = match name {
        "mesh_plane_two_feet" => (
            on(feet(), ground(), tilted_at(0.0, 0.0, 0.9), 0.4502, 1.15),
            "the feet tilted on a plane: two regions",
        ),
        "mesh_bounded_plane_two_feet" => (
            on(
                feet(),
                bounded(-1.2, 2.0, -2.0, 2.0),
                tilted_at(0.0, 0.0, 0.9),
                0.4502,
                1.2,
            ),
            "the feet tilted on a bounded plane, its edge under one foot",
        ),
        "box_mesh_two_feet" => (
            on(
                cuboid(1.5, 0.3, 0.4),
                feet(),
                tilted_at(0.0, 0.1, 1.2),
                0.4495,
                2.0,
            ),
            "a tilted box pressed across both feet's tops: two regions",
        ),
        "cylinder_mesh_two_feet" => (
            on(rod(0.3, 3.0), feet(), across, 0.1941, 0.56),
            "a tilted cylinder across both feet's tops: two regions",
        ),
        "cylinder_mesh_dented_feet" => (
            on(
                rod(0.3, 3.0),
                Geometry::Mesh(Arc::new(dented_feet())),
                across,
                0.1747,
                0.56,
            ),
            "the cylinder across feet dented at a top corner (not convex: sliced)",
        ),
        "frustum_mesh_two_feet" => (
            on(
                frustum(0.6, 0.3, 1.5),
                feet(),
                tilted_at(-1.0, 0.0, 0.8),
                0.3608,
                0.95,
            ),
            "a tilted frustum on a foot",
        ),
        "torus_mesh_two_feet" => (
            on(
                torus(1.0, 0.3),
                feet(),
                tilted_at(0.0, 0.0, 1.1),
                0.4258,
                1.15,
            ),
            "a tilted torus across both feet",
        ),
        "ellipsoid_mesh_two_feet" => (
            on(
                ellipsoid(1.6, 0.5, 0.4),
                feet(),
                tilted_at(0.0, 0.0, 1.2),
                0.3093,
                1.1,
            ),
            "a long tilted ellipsoid across both feet",
        ),
        "sphere_mesh_foot" => (
            on(ball(0.5), feet(), at(-1.0, 0.0, 1.3), 0.2, 0.5),
            "a sphere on a foot's top face (closed form)",
        ),
        _ => return None,
    };
    Some(configuration.scene(name, description))
}

/// A closed mesh of two boxes (two "feet"): 24 triangles, two contact regions on a plane.
#[expect(clippy::expect_used, reason = "literal boxes, valid")]
fn two_feet() -> TriangleMesh {
    TriangleMesh::boxes(&[
        (Point3::new(-1.0, 0.0, 0.0), Vector3::new(0.5, 0.4, 1.0)),
        (Point3::new(1.0, 0.0, 0.0), Vector3::new(0.3, 0.6, 1.0)),
    ])
    .expect("a valid literal mesh")
}

/// [`two_feet`] with each foot's top corner at `+x, +y` pushed in and down: no longer convex.
#[expect(clippy::expect_used, reason = "literal vertices and triangles, valid")]
fn dented_feet() -> TriangleMesh {
    let feet = two_feet();
    let mut vertices = feet.vertices().to_vec();
    for foot in 0..2 {
        let v = &mut vertices[8 * foot + 7];
        *v = Point3::new(v.x - 0.1, v.y - 0.1, 0.7);
    }
    TriangleMesh::new(vertices, feet.triangles().to_vec()).expect("a valid literal mesh")
}
