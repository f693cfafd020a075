//! The exact_pairs bench's configurations: fixed poses of each pair, with the closed-form
//! depth where one exists.

use contact_core::geometry::{
    Circle, Cuboid, Curve, CurvePoints, Cylinder, Ellipsoid, Frustum, Plane, Torus,
};
use contact_core::{Geometry, Isometry3, Point2, UnitQuaternion};
use std::f64::consts::FRAC_PI_2;

/// One benchmarked configuration with its closed-form depth (`None` where no short closed
/// form exists; the characterization test checks those pairs against independent oracles).
pub struct Case {
    pub name: &'static str,
    pub i: Geometry,
    pub j: Geometry,
    pub pose_i: Isometry3,
    pub pose_j: Isometry3,
    pub depth: Option<f64>,
}

/// A generic tilt for the configurations that need one.
pub(crate) fn tilt() -> UnitQuaternion {
    UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5)
}

/// A cube of half-size `h`, centred.
pub(crate) fn cube(h: f64) -> Geometry {
    Geometry::Cuboid(Cuboid::centered(h, h, h).unwrap())
}

/// The unbounded ground plane.
pub(crate) fn ground() -> Geometry {
    Geometry::Plane(Plane::unbounded())
}

/// A cylinder of radius `r` and length `l`.
pub(crate) fn cylinder(r: f64, l: f64) -> Geometry {
    Geometry::Cylinder(Cylinder::new(r, l).unwrap())
}

/// Every benchmarked configuration, family by family.
pub fn cases() -> Vec<Case> {
    [
        curved_solid_cases(),
        frustum_and_torus_cases(),
        box_and_plane_cases(),
        solid_on_ground_cases(),
        crate::mesh_cases::mesh_cases(),
        bounded_plane_cases(),
        planar_cases(),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// Cylinders, spheres and ellipsoids against each other and the ground.
fn curved_solid_cases() -> Vec<Case> {
    vec![
        // Crossed at right angles, axes 0.8 apart: δ = r_a + r_b − 0.8 by symmetry.
        Case {
            name: "cylinder_cylinder",
            i: cylinder(0.5, 4.0),
            j: cylinder(0.5, 4.0),
            pose_i: Isometry3::translation(0.0, 0.0, -2.0),
            pose_j: Isometry3::from_parts(
                nalgebra::Translation3::new(-2.0, 0.8, 0.0),
                UnitQuaternion::from_axis_angle(&nalgebra::Vector3::y_axis(), FRAC_PI_2),
            ),
            depth: Some(0.2),
        },
        // Parallel, b longer than a at both ends: δ = r_a + r_b − d.
        Case {
            name: "cylinder_cylinder_parallel",
            i: cylinder(1.0, 2.0),
            j: cylinder(0.5, 3.0),
            pose_i: Isometry3::identity(),
            pose_j: Isometry3::translation(1.3, 0.0, -0.5),
            depth: Some(0.2),
        },
        // A pin in a slot: the box's face x = 0.3 cuts the side along the whole length.
        Case {
            name: "cylinder_box",
            i: cylinder(0.5, 2.0),
            j: Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 2.0).unwrap()),
            pose_i: Isometry3::identity(),
            pose_j: Isometry3::translation(1.3, 0.0, 1.0),
            depth: Some(0.2),
        },
        // The same pin and slot with the box tilted off the axis: no face parallel to it, so
        // the pair is sliced (an aligned box takes the closed form above).
        Case {
            name: "cylinder_box_tilted",
            i: cylinder(0.5, 2.0),
            j: Geometry::Cuboid(Cuboid::centered(1.0, 1.0, 2.0).unwrap()),
            pose_i: Isometry3::identity(),
            pose_j: Isometry3::from_parts(nalgebra::Translation3::new(1.3, 0.0, 1.0), tilt()),
            depth: None,
        },
        Case {
            name: "sphere_plane",
            i: Geometry::sphere(1.0).unwrap(),
            j: ground(),
            pose_i: Isometry3::translation(0.3, -0.2, 0.9),
            pose_j: Isometry3::identity(),
            depth: Some(0.1),
        },
        Case {
            name: "sphere_sphere",
            i: Geometry::sphere(1.0).unwrap(),
            j: Geometry::sphere(0.5).unwrap(),
            pose_i: Isometry3::translation(0.8, 0.6, 0.7),
            pose_j: Isometry3::identity(),
            depth: Some(1.5 - (0.64f64 + 0.36 + 0.49).sqrt()),
        },
        Case {
            name: "ellipsoid_plane",
            i: Geometry::Ellipsoid(Ellipsoid::new(1.0, 0.6, 0.4).unwrap()),
            j: ground(),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 0.3), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "ellipsoid_ellipsoid",
            i: Geometry::Ellipsoid(Ellipsoid::new(1.0, 0.6, 0.4).unwrap()),
            j: Geometry::Ellipsoid(Ellipsoid::new(0.8, 0.5, 0.7).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.9, 0.3, 0.4), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "ellipsoid_box",
            i: Geometry::Ellipsoid(Ellipsoid::new(1.0, 0.6, 0.4).unwrap()),
            j: Geometry::Cuboid(Cuboid::centered(1.0, 0.7, 0.4).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.5, 0.3, 0.7), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "ellipsoid_cylinder",
            i: Geometry::Ellipsoid(Ellipsoid::new(1.0, 0.6, 0.4).unwrap()),
            j: Geometry::Cylinder(Cylinder::new(0.8, 1.5).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.9, 0.4, 1.6), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
    ]
}

/// Frusta and tori against the curved solids.
fn frustum_and_torus_cases() -> Vec<Case> {
    vec![
        // Two frusta crossed at a tilt() (the exact engine alone: parry has no frustum).
        Case {
            name: "frustum_frustum",
            i: Geometry::Frustum(Frustum::new(1.0, 0.5, 1.5).unwrap()),
            j: Geometry::Frustum(Frustum::new(0.8, 0.6, 1.2).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.6, 0.2, 0.9), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        // A cylinder across a cone's flank (the frustum of no top radius).
        Case {
            name: "cylinder_frustum",
            i: cylinder(0.3, 2.0),
            j: Geometry::Frustum(Frustum::new(0.9, 0.0, 1.5).unwrap()),
            pose_i: Isometry3::from_parts(
                nalgebra::Translation3::new(-1.0, 0.5, 0.5),
                UnitQuaternion::from_euler_angles(0.2, 1.3, 0.1),
            ),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "ellipsoid_frustum",
            i: Geometry::Ellipsoid(Ellipsoid::new(1.0, 0.6, 0.4).unwrap()),
            j: Geometry::Frustum(Frustum::new(1.0, 0.5, 1.5).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.8, 0.3, 1.4), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "ellipsoid_torus",
            i: Geometry::Ellipsoid(Ellipsoid::new(0.5, 0.3, 0.25).unwrap()),
            j: Geometry::Torus(Torus::new(2.0, 0.5).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(2.3, 0.4, 0.45), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        // A tilted rod across the tube (one region) and a cone on the tube's flank.
        Case {
            name: "cylinder_torus",
            i: cylinder(0.3, 1.5),
            j: Geometry::Torus(Torus::new(2.0, 0.5).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(2.2, 0.3, -0.6), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "frustum_torus",
            i: Geometry::Frustum(Frustum::new(0.5, 0.1, 1.0).unwrap()),
            j: Geometry::Torus(Torus::new(2.0, 0.5).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(2.6, 0.2, -0.3), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "ellipsoid_torus_two_regions",
            i: Geometry::Ellipsoid(Ellipsoid::new(2.3, 0.3, 0.25).unwrap()),
            j: Geometry::Torus(Torus::new(2.0, 0.5).unwrap()),
            pose_i: Isometry3::from_parts(
                nalgebra::Translation3::new(0.0, 0.0, 0.1),
                UnitQuaternion::from_euler_angles(0.0, 0.1, 0.3),
            ),
            pose_j: Isometry3::identity(),
            depth: None,
        },
    ]
}

/// Boxes, and spheres against solids' faces, edges, sides and tubes.
fn box_and_plane_cases() -> Vec<Case> {
    vec![
        Case {
            name: "box_plane",
            i: cube(0.5),
            j: ground(),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 0.6), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "box_box",
            i: cube(0.5),
            j: Geometry::Cuboid(Cuboid::centered(1.0, 0.7, 0.4).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.2, 0.1, 0.95), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        // Over a face, the cap clear of its edges: the closed-form fast path, δ = r − d.
        Case {
            name: "sphere_box_face",
            i: Geometry::sphere(0.5).unwrap(),
            j: cube(1.0),
            pose_i: Isometry3::translation(0.2, 0.1, 1.3),
            pose_j: Isometry3::identity(),
            depth: Some(0.2),
        },
        // At an edge: the general slicing (the ball as an ellipsoid of equal semi-axes).
        Case {
            name: "sphere_box_edge",
            i: Geometry::sphere(0.5).unwrap(),
            j: cube(1.0),
            pose_i: Isometry3::translation(1.2, 1.1, 0.3),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "sphere_cylinder_side",
            i: Geometry::sphere(0.5).unwrap(),
            j: Geometry::Cylinder(Cylinder::new(1.0, 2.0).unwrap()),
            pose_i: Isometry3::translation(1.3, 0.0, 1.0),
            pose_j: Isometry3::identity(),
            depth: Some(0.2),
        },
        // A frustum's slanted side and a torus' tube: the general slicings (the torus pose is
        // the reproduction, δ = 0.201397 by SPEC §4).
        Case {
            name: "sphere_frustum_side",
            i: Geometry::sphere(0.3).unwrap(),
            j: Geometry::Frustum(Frustum::new(1.0, 0.5, 2.0).unwrap()),
            pose_i: Isometry3::translation(0.9, 0.0, 1.0),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "sphere_torus",
            i: Geometry::sphere(0.6).unwrap(),
            j: Geometry::Torus(Torus::new(1.0, 0.3).unwrap()),
            pose_i: Isometry3::translation(
                -0.8905746147450594,
                -0.12550109474163762,
                -0.6910480248729591,
            ),
            pose_j: Isometry3::identity(),
            depth: None,
        },
    ]
}

/// Solids tilted on, lying on and resting on the ground.
fn solid_on_ground_cases() -> Vec<Case> {
    vec![
        Case {
            name: "cylinder_plane_tilted",
            i: Geometry::Cylinder(Cylinder::new(0.5, 2.0).unwrap()),
            j: ground(),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, -0.1), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "frustum_plane_tilted",
            i: Geometry::Frustum(Frustum::new(0.6, 0.3, 1.5).unwrap()),
            j: ground(),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, -0.1), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "torus_plane_tilted",
            i: Geometry::Torus(Torus::new(1.0, 0.3).unwrap()),
            j: ground(),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 0.5), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "cylinder_plane_on_side",
            i: Geometry::Cylinder(Cylinder::new(0.5, 2.0).unwrap()),
            j: ground(),
            pose_i: Isometry3::new(
                nalgebra::Vector3::new(-1.0, 0.0, 0.4),
                nalgebra::Vector3::new(0.0, std::f64::consts::FRAC_PI_2, 0.0),
            ),
            pose_j: Isometry3::identity(),
            depth: Some(0.1),
        },
        Case {
            // A wheel at rest: on its side, tilted 1e-4 rad, 1e-3 of its radius deep (the
            // shallow cut the end-piece series takes).
            name: "cylinder_plane_resting",
            i: Geometry::Cylinder(Cylinder::new(0.5, 2.0).unwrap()),
            j: ground(),
            pose_i: Isometry3::new(
                nalgebra::Vector3::new(-1.0, 0.0, 0.5 - 5e-4),
                nalgebra::Vector3::new(1e-4, std::f64::consts::FRAC_PI_2, 0.0),
            ),
            pose_j: Isometry3::identity(),
            depth: None,
        },
    ]
}

/// Boxes against frusta and tori, and solids on bounded planes (at an edge and well inside).
fn bounded_plane_cases() -> Vec<Case> {
    vec![
        // The box's top face at z = 0.4 across an upright frustum, its other faces out of
        // reach: δ = 0.4 along the axis.
        Case {
            name: "box_frustum",
            i: Geometry::Frustum(Frustum::new(0.6, 0.3, 1.5).unwrap()),
            j: cube(2.0),
            pose_i: Isometry3::identity(),
            pose_j: Isometry3::translation(0.1, 0.0, -1.6),
            depth: Some(0.4),
        },
        Case {
            name: "box_frustum_tilted",
            i: cube(0.5),
            j: Geometry::Frustum(Frustum::new(0.6, 0.3, 1.5).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.9, 0.2, 0.7), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "box_torus",
            i: cube(0.4),
            j: Geometry::Torus(Torus::new(1.0, 0.3).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(1.0, 0.2, 0.5), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        // A slab through the ring: two regions.
        Case {
            name: "box_torus_two_regions",
            i: Geometry::Cuboid(Cuboid::centered(0.3, 2.0, 1.0).unwrap()),
            j: Geometry::Torus(Torus::new(1.0, 0.3).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(-0.1, 0.0, 0.2), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "frustum_bounded_plane",
            i: Geometry::Frustum(Frustum::new(0.6, 0.3, 1.5).unwrap()),
            j: Geometry::Plane(Plane::bounded(-0.2, 2.0, -2.0, 2.0).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, -0.1), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "cylinder_bounded_plane",
            i: Geometry::Cylinder(Cylinder::new(0.5, 2.0).unwrap()),
            j: Geometry::Plane(Plane::bounded(-0.2, 2.0, -2.0, 2.0).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, -0.1), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "torus_bounded_plane",
            i: Geometry::Torus(Torus::new(1.0, 0.3).unwrap()),
            j: Geometry::Plane(Plane::bounded(-0.2, 2.0, -2.0, 2.0).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 0.5), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "ellipsoid_bounded_plane",
            i: Geometry::Ellipsoid(Ellipsoid::new(1.0, 0.6, 0.4).unwrap()),
            j: Geometry::Plane(Plane::bounded(-0.2, 2.0, -2.0, 2.0).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 0.3), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        // The same bodies well inside a large bounded ground (no edge within reach): the
        // bounded pairs answer with the unbounded plane's closed forms.
        Case {
            name: "cylinder_bounded_plane_inside",
            i: Geometry::Cylinder(Cylinder::new(0.5, 2.0).unwrap()),
            j: Geometry::Plane(Plane::bounded(-50.0, 50.0, -50.0, 50.0).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, -0.1), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "torus_bounded_plane_inside",
            i: Geometry::Torus(Torus::new(1.0, 0.3).unwrap()),
            j: Geometry::Plane(Plane::bounded(-50.0, 50.0, -50.0, 50.0).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 0.5), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "ellipsoid_bounded_plane_inside",
            i: Geometry::Ellipsoid(Ellipsoid::new(1.0, 0.6, 0.4).unwrap()),
            j: Geometry::Plane(Plane::bounded(-50.0, 50.0, -50.0, 50.0).unwrap()),
            pose_i: Isometry3::from_parts(nalgebra::Translation3::new(0.0, 0.0, 0.3), tilt()),
            pose_j: Isometry3::identity(),
            depth: None,
        },
    ]
}

/// 2-D: a circle against a curve and against a circle.
fn planar_cases() -> Vec<Case> {
    vec![
        Case {
            name: "circle_curve",
            i: Geometry::Circle(Circle::new(0.3).unwrap()),
            j: Geometry::Curve(std::sync::Arc::new(
                Curve::new(
                    &(0..8)
                        .map(|k| {
                            let a = k as f64 * std::f64::consts::TAU / 8.0;
                            Point2::new(2.0 * a.cos(), 1.5 * a.sin())
                        })
                        .collect::<Vec<_>>(),
                    4,
                    true,
                    CurvePoints::Interpolated,
                )
                .unwrap(),
            )),
            pose_i: Isometry3::translation(1.9, 0.2, 0.0),
            pose_j: Isometry3::identity(),
            depth: None,
        },
        Case {
            name: "circle_circle",
            i: Geometry::Circle(Circle::new(1.0).unwrap()),
            j: Geometry::Circle(Circle::new(0.5).unwrap()),
            pose_i: Isometry3::translation(1.2, 0.3, 0.0),
            pose_j: Isometry3::identity(),
            depth: Some(1.5 - (1.44f64 + 0.09).sqrt()),
        },
    ]
}
