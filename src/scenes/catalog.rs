//! The scenes by name: one function per family (a solid on the plane, two solids, 2-D, two
//! meshes).

use super::*;

/// The scene called `name` (of the suite, [`super::NAMES`], or of the kernel scenes,
/// [`super::KERNEL_NAMES`]), or `None`.
pub fn scene(name: &str) -> Option<Scene> {
    let Some(name) = NAMES.iter().find(|n| **n == name) else {
        return super::kernels::kernel_scene(name);
    };
    plane_scene(name)
        .or_else(|| pair_scene(name))
        .or_else(|| planar_scene(name))
        .or_else(|| mesh_scene(name))
}

/// The scenes of one solid on the plane.
#[expect(
    clippy::expect_used,
    reason = "literal sizes, all inside their valid ranges"
)]
fn plane_scene(name: &'static str) -> Option<Scene> {
    let free = Orientation::Random;
    Some(match name {
        "sphere_plane" => Scene::on_plane(
            name,
            "sphere resting on a plane: δ = r − d",
            single(sphere(1.0)),
            1.0,
            free,
        )
        .with_closed_form(sphere_plane),
        "ellipsoid_plane" => Scene::on_plane(
            name,
            "tilted ellipsoid on a plane: the cap's centroid is off the deepest point's normal",
            single(Geometry::Ellipsoid(
                Ellipsoid::new(1.0, 0.6, 0.4).expect("valid literal"),
            )),
            0.4,
            free,
        ),
        "cylinder_plane_side" => Scene::on_plane(
            name,
            "cylinder lying on its side on a plane: a line contact",
            vec![centred(cylinder(0.5, 2.0), 2.0)],
            0.5,
            Orientation::AxisParallelToPlane,
        )
        .with_closed_form(cylinder_plane_side),
        "cylinder_plane_edge" => Scene::on_plane(
            name,
            "cylinder tilted 30° onto its rim",
            vec![centred(cylinder(0.5, 2.0), 2.0)],
            0.5,
            Orientation::Tilted(FRAC_PI_6),
        ),
        "box_plane" => Scene::on_plane(
            name,
            "tilted box on a plane: a vertex or edge digs in",
            single(Geometry::Cuboid(
                Cuboid::centered(1.0, 0.7, 0.5).expect("valid literal"),
            )),
            0.5,
            free,
        ),
        "frustum_plane" => Scene::on_plane(
            name,
            "frustum tilted 30° onto its rim",
            vec![centred(
                Geometry::Frustum(Frustum::new(0.8, 0.3, 1.5).expect("valid literal")),
                1.5,
            )],
            0.3,
            Orientation::Tilted(FRAC_PI_6),
        ),
        "torus_plane" => Scene::on_plane(
            name,
            "tilted torus on a plane",
            single(Geometry::Torus(
                Torus::new(1.0, 0.3).expect("valid literal"),
            )),
            0.3,
            free,
        ),
        _ => return None,
    })
}

/// The scenes of two solids.
#[expect(
    clippy::expect_used,
    reason = "literal sizes, all inside their valid ranges"
)]
fn pair_scene(name: &'static str) -> Option<Scene> {
    let free = Orientation::Random;
    Some(match name {
        "sphere_sphere" => Scene::pair(
            name,
            "two spheres: the lens",
            single(sphere(1.0)),
            single(sphere(0.7)),
            0.7,
            free,
        )
        .with_closed_form(sphere_sphere),
        "ellipsoid_ellipsoid" => Scene::pair(
            name,
            "two ellipsoids at random orientations",
            single(Geometry::Ellipsoid(
                Ellipsoid::new(1.0, 0.6, 0.4).expect("valid literal"),
            )),
            single(Geometry::Ellipsoid(
                Ellipsoid::new(0.8, 0.8, 0.5).expect("valid literal"),
            )),
            0.4,
            free,
        ),
        "cylinder_cylinder_parallel" => Scene::pair(
            name,
            "two cylinders with parallel axes: a line contact",
            vec![centred(cylinder(0.5, 2.0), 2.0)],
            vec![centred(cylinder(0.8, 3.0), 3.0)],
            0.5,
            Orientation::ParallelAxes,
        ),
        "cylinder_cylinder_crossed" => Scene::pair(
            name,
            "two cylinders with crossed axes: a point contact",
            vec![centred(cylinder(0.5, 2.0), 2.0)],
            vec![centred(cylinder(0.8, 3.0), 3.0)],
            0.5,
            Orientation::CrossedAxes,
        ),
        "box_box" => Scene::pair(
            name,
            "a turned box's corner into the middle of a face of another box",
            single(Geometry::Cuboid(
                Cuboid::centered(1.0, 0.7, 0.5).expect("valid literal"),
            )),
            single(Geometry::Cuboid(
                Cuboid::centered(0.6, 0.6, 0.9).expect("valid literal"),
            )),
            0.5,
            Orientation::RandomOntoFace,
        ),
        "torus_sphere" => Scene::pair(
            name,
            "a sphere against a torus's outer rim",
            single(sphere(0.4)),
            single(Geometry::Torus(
                Torus::new(1.0, 0.3).expect("valid literal"),
            )),
            0.3,
            Orientation::RandomInPlane,
        ),
        _ => return None,
    })
}

/// The 2-D scenes.
fn planar_scene(name: &'static str) -> Option<Scene> {
    Some(match name {
        "circle_circle" => Scene::pair(
            name,
            "two circles in one plane",
            single(circle(0.6)),
            single(circle(1.0)),
            0.6,
            Orientation::Planar,
        )
        .with_closed_form(circle_circle),
        "point_curve" => Scene::on_curve(
            name,
            "a point against a closed cubic cam",
            single(Geometry::Point),
            0.0,
        ),
        "circle_curve" => Scene::on_curve(
            name,
            "a circle follower on a closed cubic cam",
            single(circle(0.2)),
            0.2,
        ),
        "curve_curve" => Scene::pair(
            name,
            "two closed B-spline curves",
            single(Geometry::Curve(Arc::new(blob(0.5, 5, 0.15)))),
            single(Geometry::Curve(Arc::new(cam()))),
            0.3,
            Orientation::Planar,
        ),
        _ => return None,
    })
}

/// The scenes of two meshes given as triangles.
fn mesh_scene(name: &'static str) -> Option<Scene> {
    let free = Orientation::Random;
    Some(match name {
        "mesh_sphere_10k" => Scene::pair(
            name,
            "two triangle-mesh spheres of 9,800 triangles each (closed form of the true spheres)",
            single(sphere_mesh(1.0, 100)),
            single(sphere_mesh(0.7, 100)),
            0.7,
            free,
        )
        .with_closed_form(mesh_spheres),
        "mesh_sphere_100k" => Scene::pair(
            name,
            "two triangle-mesh spheres of 99,224 triangles each (closed form of the true spheres)",
            single(sphere_mesh(1.0, 316)),
            single(sphere_mesh(0.7, 316)),
            0.7,
            free,
        )
        .with_closed_form(mesh_spheres),
        "mesh_torus" => Scene::pair(
            name,
            "two triangle-mesh tori (no exact reference: timing and work only)",
            single(torus_mesh(1.0, 0.3)),
            single(torus_mesh(0.8, 0.25)),
            0.25,
            free,
        ),
        _ => return None,
    })
}

/// A sphere of radius `r` (a literal in range).
#[expect(
    clippy::expect_used,
    reason = "literal sizes, all inside their valid ranges"
)]
fn sphere(r: f64) -> Geometry {
    Geometry::Ellipsoid(Ellipsoid::sphere(r).expect("valid literal"))
}

/// A cylinder of radius `r` and length `l` (literals in range).
#[expect(
    clippy::expect_used,
    reason = "literal sizes, all inside their valid ranges"
)]
fn cylinder(r: f64, l: f64) -> Geometry {
    Geometry::Cylinder(Cylinder::new(r, l).expect("valid literal"))
}

/// A cylinder or frustum with its part origin at its centre (its frame is at the base).
fn centred(g: Geometry, length: f64) -> GeometryInstance {
    GeometryInstance::new(g).at(Isometry3::translation(0.0, 0.0, -0.5 * length))
}
