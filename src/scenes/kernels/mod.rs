//! The kernel scenes: one characteristic configuration per path of the exact engine's
//! dispatch that the suite does not reach (a pin in a slot, a sphere on a face or an edge, a
//! body across a torus' tube, two regions, bounded planes at an edge and well inside, solids
//! on meshes), each moved along an approach direction through its configuration
//! ([`Scene::through`]). `benches/exact_pairs` times every scene of the suite and of this list;
//! `contact tradeoff --scene NAME` takes them too.
//!
//! A pose's nominal depth is how far I has travelled along the approach past first touch: for
//! a configuration with a closed form (the approach being its contact normal) its depth; for
//! the others the travel found by bisection on whether the exact engine answers a contact,
//! rounded up to four digits. A label for the pose, never an answer: the separated poses are
//! clear and the graded ones touch (`scenes::tests`), and the approach is the exact engine's
//! normal at the configuration where one region answers, else J's z axis.

mod on_planes_and_meshes;

use super::*;
use on_planes_and_meshes::{bounded_plane_scene, feet_scene};

/// The kernel scenes, in order.
pub const KERNEL_NAMES: [&str; 37] = [
    "cylinder_box",
    "cylinder_box_tilted",
    "ellipsoid_box",
    "ellipsoid_cylinder",
    "frustum_frustum",
    "cylinder_frustum",
    "ellipsoid_frustum",
    "ellipsoid_torus",
    "cylinder_torus",
    "frustum_torus",
    "ellipsoid_torus_two_regions",
    "sphere_box_face",
    "sphere_box_edge",
    "sphere_cylinder_side",
    "sphere_frustum_side",
    "sphere_torus_inside_ring",
    "cylinder_plane_resting",
    "box_frustum",
    "box_frustum_tilted",
    "box_torus",
    "box_torus_two_regions",
    "frustum_bounded_plane",
    "cylinder_bounded_plane",
    "torus_bounded_plane",
    "ellipsoid_bounded_plane",
    "cylinder_bounded_plane_inside",
    "torus_bounded_plane_inside",
    "ellipsoid_bounded_plane_inside",
    "mesh_plane_two_feet",
    "mesh_bounded_plane_two_feet",
    "box_mesh_two_feet",
    "cylinder_mesh_two_feet",
    "cylinder_mesh_dented_feet",
    "frustum_mesh_two_feet",
    "torus_mesh_two_feet",
    "ellipsoid_mesh_two_feet",
    "sphere_mesh_foot",
];

/// Every kernel scene.
pub fn kernel_scenes() -> Vec<Scene> {
    KERNEL_NAMES
        .iter()
        .filter_map(|n| kernel_scene(n))
        .collect()
}

/// The kernel scene called `name`, or `None`.
pub(super) fn kernel_scene(name: &str) -> Option<Scene> {
    let name: &'static str = KERNEL_NAMES.iter().find(|n| **n == name)?;
    curved_scene(name)
        .or_else(|| sphere_scene(name))
        .or_else(|| box_scene(name))
        .or_else(|| bounded_plane_scene(name))
        .or_else(|| feet_scene(name))
}

/// One configuration: I and J at world poses `pose_i`, `pose_j`, I at nominal depth `depth`,
/// the approach `approach` (in the world, from J towards I; normalised here), and the scene's
/// length scale `scale` (a radius where the configuration has a closed form, else about four
/// times the exact engine's depth there, so the graded depths to 0.3 of it reach about the
/// configuration).
pub(super) struct Configuration {
    pub(super) i: Geometry,
    pub(super) j: Geometry,
    pub(super) pose_i: Isometry3,
    pub(super) pose_j: Isometry3,
    pub(super) depth: f64,
    pub(super) approach: Vector3,
    pub(super) scale: f64,
}

impl Configuration {
    pub(super) fn scene(
        self,
        name: &'static str,
        description: impl Into<Cow<'static, str>>,
    ) -> Scene {
        Scene::through(
            name,
            description,
            single(self.i),
            single(self.j),
            self.scale,
            self.pose_j.inverse() * self.pose_i,
            self.depth,
            self.pose_j.rotation.inverse() * self.approach.normalize(),
        )
    }
}

/// The generic tilt of the configurations that need one.
pub(super) fn tilt() -> UnitQuaternion {
    UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5)
}

pub(super) fn at(x: f64, y: f64, z: f64) -> Isometry3 {
    Isometry3::translation(x, y, z)
}

pub(super) fn tilted_at(x: f64, y: f64, z: f64) -> Isometry3 {
    Isometry3::from_parts(nalgebra::Translation3::new(x, y, z), tilt())
}

/// Literal shapes, all inside their valid ranges.
#[expect(
    clippy::expect_used,
    reason = "literal sizes, all inside their valid ranges"
)]
pub(super) mod shapes {
    use super::*;

    pub fn cuboid(x: f64, y: f64, z: f64) -> Geometry {
        Geometry::Cuboid(Cuboid::centered(x, y, z).expect("valid literal"))
    }
    pub fn ellipsoid(a: f64, b: f64, c: f64) -> Geometry {
        Geometry::Ellipsoid(Ellipsoid::new(a, b, c).expect("valid literal"))
    }
    pub fn frustum(bottom: f64, top: f64, length: f64) -> Geometry {
        Geometry::Frustum(Frustum::new(bottom, top, length).expect("valid literal"))
    }
    pub fn torus(major: f64, minor: f64) -> Geometry {
        Geometry::Torus(Torus::new(major, minor).expect("valid literal"))
    }
    pub fn bounded(xmin: f64, xmax: f64, ymin: f64, ymax: f64) -> Geometry {
        Geometry::Plane(Plane::bounded(xmin, xmax, ymin, ymax).expect("valid literal"))
    }
    pub fn ball(r: f64) -> Geometry {
        Geometry::Ellipsoid(Ellipsoid::sphere(r).expect("valid literal"))
    }
    pub fn rod(r: f64, l: f64) -> Geometry {
        Geometry::Cylinder(Cylinder::new(r, l).expect("valid literal"))
    }
}
use shapes::*;

/// A cylinder of radius 0.5 and length 2 in a slot: the face x = −1 of a box at `pose_j`.
fn pin_in_slot(pose_j: Isometry3, depth: f64, approach: Vector3, scale: f64) -> Configuration {
    Configuration {
        i: rod(0.5, 2.0),
        j: cuboid(1.0, 1.0, 2.0),
        pose_i: Isometry3::identity(),
        pose_j,
        depth,
        approach,
        scale,
    }
}

/// Cylinders and ellipsoids against boxes and cylinders.
fn curved_scene(name: &'static str) -> Option<Scene> {
    let (configuration, description) = match name {
        "cylinder_box" => (
            pin_in_slot(at(1.3, 0.0, 1.0), 0.2, -Vector3::x(), 0.5),
            "a pin in a slot: a box face cuts the side along its length (closed form)",
        ),
        "cylinder_box_tilted" => (
            pin_in_slot(
                tilted_at(1.3, 0.0, 1.0),
                0.5861,
                Vector3::new(-0.969, -0.220, -0.108),
                1.6,
            ),
            "the pin in a slot turned off its axis: sliced",
        ),
        "ellipsoid_box" => (
            Configuration {
                i: ellipsoid(1.0, 0.6, 0.4),
                j: cuboid(1.0, 0.7, 0.4),
                pose_i: tilted_at(0.5, 0.3, 0.7),
                pose_j: Isometry3::identity(),
                depth: 0.1582,
                approach: Vector3::z(),
                scale: 0.6,
            },
            "a tilted ellipsoid on a box's face",
        ),
        "ellipsoid_cylinder" => (
            Configuration {
                i: ellipsoid(1.0, 0.6, 0.4),
                j: rod(0.8, 1.5),
                pose_i: tilted_at(0.9, 0.4, 1.6),
                pose_j: Isometry3::identity(),
                depth: 0.3981,
                approach: Vector3::new(0.418, 0.132, 0.899),
                scale: 1.5,
            },
            "a tilted ellipsoid over a cylinder's rim",
        ),
        _ => return frustum_and_torus_scene(name),
    };
    Some(configuration.scene(name, description))
}

/// Frusta, ellipsoids and cylinders against frusta and tori.
fn frustum_and_torus_scene(name: &'static str) -> Option<Scene> {
    let torus_j =
        |i: Geometry, pose_i: Isometry3, depth: f64, approach: Vector3, scale: f64| Configuration {
            i,
            j: torus(2.0, 0.5),
            pose_i,
            pose_j: Isometry3::identity(),
            depth,
            approach,
            scale,
        };
    let (configuration, description) = match name {
        "frustum_frustum" => (
            Configuration {
                i: frustum(1.0, 0.5, 1.5),
                j: frustum(0.8, 0.6, 1.2),
                pose_i: tilted_at(0.6, 0.2, 0.9),
                pose_j: Isometry3::identity(),
                depth: 0.6458,
                approach: Vector3::new(0.438, -0.106, 0.893),
                scale: 1.8,
            },
            "two frusta crossed at a tilt",
        ),
        "cylinder_frustum" => (
            Configuration {
                i: rod(0.3, 2.0),
                j: frustum(0.9, 0.0, 1.5),
                pose_i: Isometry3::from_parts(
                    nalgebra::Translation3::new(-1.0, 0.5, 0.5),
                    UnitQuaternion::from_euler_angles(0.2, 1.3, 0.1),
                ),
                pose_j: Isometry3::identity(),
                depth: 0.3416,
                approach: Vector3::new(-0.087, 0.776, 0.624),
                scale: 1.3,
            },
            "a cylinder across a cone's flank",
        ),
        "ellipsoid_frustum" => (
            Configuration {
                i: ellipsoid(1.0, 0.6, 0.4),
                j: frustum(1.0, 0.5, 1.5),
                pose_i: tilted_at(0.8, 0.3, 1.4),
                pose_j: Isometry3::identity(),
                depth: 0.6494,
                approach: Vector3::new(0.703, 0.167, 0.691),
                scale: 2.4,
            },
            "a tilted ellipsoid over a frustum's top rim",
        ),
        "ellipsoid_torus" => (
            torus_j(
                ellipsoid(0.5, 0.3, 0.25),
                tilted_at(2.3, 0.4, 0.45),
                0.2979,
                Vector3::new(0.470, 0.077, 0.879),
                1.2,
            ),
            "a tilted ellipsoid on a torus' tube",
        ),
        "cylinder_torus" => (
            torus_j(
                rod(0.3, 1.5),
                tilted_at(2.2, 0.3, -0.6),
                0.6148,
                Vector3::new(0.998, 0.038, 0.041),
                2.5,
            ),
            "a tilted rod across a torus' tube",
        ),
        "frustum_torus" => (
            torus_j(
                frustum(0.5, 0.1, 1.0),
                tilted_at(2.6, 0.2, -0.3),
                0.3016,
                Vector3::new(0.996, 0.041, -0.081),
                1.2,
            ),
            "a cone on a torus' flank",
        ),
        "ellipsoid_torus_two_regions" => (
            torus_j(
                ellipsoid(2.3, 0.3, 0.25),
                Isometry3::from_parts(
                    nalgebra::Translation3::new(0.0, 0.0, 0.1),
                    UnitQuaternion::from_euler_angles(0.0, 0.1, 0.3),
                ),
                0.7225,
                Vector3::z(),
                1.5,
            ),
            "a long ellipsoid across a torus' hole: two regions",
        ),
        _ => return None,
    };
    Some(configuration.scene(name, description))
}

/// Spheres on faces, edges, sides and tubes.
fn sphere_scene(name: &'static str) -> Option<Scene> {
    let identity = Isometry3::identity();
    let (configuration, description) = match name {
        "sphere_box_face" => (
            Configuration {
                i: ball(0.5),
                j: cuboid(1.0, 1.0, 1.0),
                pose_i: at(0.2, 0.1, 1.3),
                pose_j: identity,
                depth: 0.2,
                approach: Vector3::z(),
                scale: 0.5,
            },
            "a sphere over a box's face, the cap clear of its edges (closed form)",
        ),
        "sphere_box_edge" => (
            Configuration {
                i: ball(0.5),
                j: cuboid(1.0, 1.0, 1.0),
                pose_i: at(1.2, 1.1, 0.3),
                pose_j: identity,
                depth: 0.2789,
                approach: Vector3::new(0.788, 0.616, 0.0),
                scale: 1.0,
            },
            "a sphere on a box's edge",
        ),
        "sphere_cylinder_side" => (
            Configuration {
                i: ball(0.5),
                j: rod(1.0, 2.0),
                pose_i: at(1.3, 0.0, 1.0),
                pose_j: identity,
                depth: 0.2,
                approach: Vector3::x(),
                scale: 0.5,
            },
            "a sphere on a cylinder's side (closed form)",
        ),
        "sphere_frustum_side" => (
            Configuration {
                i: ball(0.3),
                j: frustum(1.0, 0.5, 2.0),
                pose_i: at(0.9, 0.0, 1.0),
                pose_j: identity,
                depth: 0.1545,
                approach: Vector3::new(0.969, 0.0, 0.245),
                scale: 0.6,
            },
            "a sphere on a frustum's slanted side",
        ),
        "sphere_torus_inside_ring" => (
            Configuration {
                i: ball(0.6),
                j: torus(1.0, 0.3),
                pose_i: at(
                    -0.890_574_614_745_059_4,
                    -0.125_501_094_741_637_62,
                    -0.691_048_024_872_959_1,
                ),
                pose_j: identity,
                depth: 0.2019,
                approach: Vector3::new(0.1002, 0.0141, -0.9949),
                scale: 0.8,
            },
            "a sphere under a torus, inside its ring (SPEC §4's δ = 0.201397)",
        ),
        _ => return None,
    };
    Some(configuration.scene(name, description))
}

/// Boxes against frusta and tori; a wheel at rest.
fn box_scene(name: &'static str) -> Option<Scene> {
    let identity = Isometry3::identity();
    let (configuration, description) = match name {
        "cylinder_plane_resting" => (
            Configuration {
                i: rod(0.5, 2.0),
                j: Geometry::Plane(Plane::unbounded()),
                pose_i: Isometry3::new(
                    Vector3::new(-1.0, 0.0, 0.5 - 5e-4),
                    Vector3::new(1e-4, FRAC_PI_2, 0.0),
                ),
                pose_j: identity,
                depth: 5e-4,
                approach: Vector3::z(),
                scale: 2e-3,
            },
            "a wheel at rest: on its side, tilted 1e-4 rad, 1e-3 of its radius deep",
        ),
        "box_frustum" => (
            Configuration {
                i: frustum(0.6, 0.3, 1.5),
                j: cuboid(2.0, 2.0, 2.0),
                pose_i: identity,
                pose_j: at(0.1, 0.0, -1.6),
                depth: 0.4,
                approach: Vector3::z(),
                scale: 1.5,
            },
            "a box's face across an upright frustum (closed form)",
        ),
        "box_frustum_tilted" => (
            Configuration {
                i: cuboid(0.5, 0.5, 0.5),
                j: frustum(0.6, 0.3, 1.5),
                pose_i: tilted_at(0.9, 0.2, 0.7),
                pose_j: identity,
                depth: 0.08431,
                approach: Vector3::new(0.887, 0.412, 0.206),
                scale: 0.33,
            },
            "a tilted cube against a frustum's side",
        ),
        "box_torus" => (
            Configuration {
                i: cuboid(0.4, 0.4, 0.4),
                j: torus(1.0, 0.3),
                pose_i: tilted_at(1.0, 0.2, 0.5),
                pose_j: identity,
                depth: 0.3504,
                approach: Vector3::z(),
                scale: 1.0,
            },
            "a tilted cube on a torus' tube",
        ),
        "box_torus_two_regions" => (
            Configuration {
                i: cuboid(0.3, 2.0, 1.0),
                j: torus(1.0, 0.3),
                pose_i: tilted_at(-0.1, 0.0, 0.2),
                pose_j: identity,
                depth: 1.516,
                approach: Vector3::z(),
                scale: 4.5,
            },
            "a slab through a torus' ring: two regions",
        ),
        _ => return None,
    };
    Some(configuration.scene(name, description))
}
