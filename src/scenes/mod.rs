//! The reference scenes: one definition of every pair family users compare the engines on,
//! each with a seeded family of poses from separated through grazing to deep. Tests, benches
//! and `contact tradeoff` all read them from here: the suite ([`suite`], what the trade runs
//! by default) and the kernel scenes ([`kernel_scenes`]: one configuration per path of the
//! exact engine's dispatch that the suite does not reach, moved along an approach).
//!
//! A scene's *reference answer* at a pose is its closed form ([`Scene::closed_form`]) where one
//! exists, else the exact engine's answer. Poses are placed at a *nominal* depth along an
//! approach direction with support functions ([`support`]); the nominal depth labels the pose
//! (separated, grazing, shallow, deep) and is never used as an answer.

mod catalog;
mod closed_form;
mod from_model;
mod from_run;
mod kernels;
mod rng;
mod support;

pub use catalog::scene;
pub use closed_form::{circle_circle, cylinder_plane_side, sphere_plane, sphere_sphere};
pub use from_model::{ModelSceneError, from_model};
pub use from_run::{RUN_POSES_PER_CONTACT, RunScenes, SPREAD_TILT_DEG, from_run};
pub use kernels::{KERNEL_NAMES, kernel_scenes};
pub use rng::SplitMix64;
pub use support::{support, support_point};

use contact_core::geometry::{
    Circle, Cuboid, Curve, CurvePoints, Cylinder, Ellipsoid, Frustum, Plane, Torus,
};
use contact_core::{
    Contact, Geometry, GeometryInstance, Isometry3, Point2, UnitQuaternion, Vector3,
};
use std::borrow::Cow;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_6, TAU};
use std::sync::Arc;

/// A closed-form answer: the contacts at a pose.
pub type ClosedForm = fn(&Scene, &ScenePose) -> Vec<Contact>;

/// One pair family with its poses.
#[derive(Debug, Clone)]
pub struct Scene {
    /// The name `--scene` takes (`sphere_plane`, …; `CONTACT/7` for a dataset's contact).
    pub name: Cow<'static, str>,
    /// One line on what the scene exercises.
    pub description: Cow<'static, str>,
    /// The I list (one part).
    pub i: Vec<GeometryInstance>,
    /// The J list (one part).
    pub j: Vec<GeometryInstance>,
    /// The scene's length scale: point errors are reported relative to it, nominal depths are
    /// fractions of it.
    pub scale: f64,
    /// The poses, in a fixed order.
    pub poses: Vec<ScenePose>,
    /// The closed-form answer, where one exists.
    pub closed_form: Option<ClosedForm>,
}

/// One pose of a scene: both part poses in the world.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScenePose {
    /// The depth the pose was placed at (negative: separated by that much), in model length.
    pub nominal_depth: f64,
    /// `X_WI`.
    pub pose_world_i: Isometry3,
    /// `X_WJ`.
    pub pose_world_j: Isometry3,
}

/// Poses in every scene of the suite: 9 special, 105 graded.
pub const POSES: usize = 114;

/// The graded depths run from 1e-4 to 0.3 of the scale: log10(0.3 / 1e-4) decades.
const DEPTH_DECADES: f64 = 3.477_121_254_719_662_6;

/// Poses at each of the special depths (separated, near, grazing) of [`relative_depths`].
pub const POSES_PER_SPECIAL_DEPTH: usize = 3;

/// The nominal depth of each pose, as fractions of a scene's scale: separated (−0.05), near
/// (−1e-3) and grazing (1e-12 of the scale), three poses each, then 105 shallow to deep depths
/// evenly spaced in log from 1e-4 to 0.3 (a ratio of about 1.08 between neighbours), one pose
/// each, each pose with its own seeded orientation and so its own facet phase.
///
/// Why every pose has its own depth: a faceted engine misses a contact shallower than its
/// faceting band and then errs by that contact's whole depth, so the worst error over the
/// family is the deepest missed depth. With neighbouring depths 1.08× apart, each step of the
/// tolerance sweep (100, 300, 1000, …: about 3.3×) moves the band past about fifteen depths,
/// and the worst error falls at every step instead of standing on a staircase.
///
/// Why so many: the normal and point errors are worst cases over the resolved contacts
/// (deeper than three faceting bands, [`crate::tradeoff::RESOLVED_BANDS`]), and a worst case
/// over a facet phase is only found by sampling many phases. With one pose per depth 1.41×
/// apart (21 graded poses), a tolerance resolving few contacts had the luck of few phases,
/// and the worst normal or point error rose at some steps of the sweep. Depths up to 0.3 give
/// the coarsest tolerances (band up to 0.09 of the scale) contacts to resolve.
pub fn relative_depths() -> [f64; POSES] {
    let mut depths = [0.0; POSES];
    let special = [-0.05, -1e-3, 1e-12];
    let graded = POSES - special.len() * POSES_PER_SPECIAL_DEPTH;
    for (k, d) in depths.iter_mut().enumerate() {
        *d = match k / POSES_PER_SPECIAL_DEPTH {
            s if s < special.len() => special[s],
            _ => {
                let step = k - special.len() * POSES_PER_SPECIAL_DEPTH;
                10f64.powf(-4.0 + DEPTH_DECADES * step as f64 / (graded - 1) as f64)
            }
        };
    }
    depths
}

/// The names of every scene in the suite, in order.
pub const NAMES: [&str; 20] = [
    "sphere_plane",
    "sphere_sphere",
    "ellipsoid_plane",
    "ellipsoid_ellipsoid",
    "cylinder_plane_side",
    "cylinder_plane_edge",
    "cylinder_cylinder_parallel",
    "cylinder_cylinder_crossed",
    "box_plane",
    "box_box",
    "frustum_plane",
    "torus_plane",
    "torus_sphere",
    "circle_circle",
    "point_curve",
    "circle_curve",
    "curve_curve",
    "mesh_sphere_10k",
    "mesh_sphere_100k",
    "mesh_torus",
];

/// Every scene of the suite.
pub fn suite() -> Vec<Scene> {
    NAMES.iter().filter_map(|n| scene(n)).collect()
}

/// The radii of the mesh-sphere scenes' true spheres, I's first.
const MESH_SPHERE_RADII: [f64; 2] = [1.0, 0.7];

/// The true spheres' closed form for the mesh-sphere scenes (the meshes are inscribed in them,
/// so their error is the faceting's).
fn mesh_spheres(scene: &Scene, pose: &ScenePose) -> Vec<Contact> {
    let [ri, rj] = MESH_SPHERE_RADII;
    let spheres = Scene {
        i: vec![GeometryInstance::new(Geometry::Ellipsoid(
            Ellipsoid::sphere(ri).unwrap_or_else(|_| unreachable!()),
        ))],
        j: vec![GeometryInstance::new(Geometry::Ellipsoid(
            Ellipsoid::sphere(rj).unwrap_or_else(|_| unreachable!()),
        ))],
        ..scene.clone()
    };
    sphere_sphere(&spheres, pose)
}

/// A UV-sphere mesh of radius `r` with `n` segments around (`2n(⌈n/2⌉ − 1)` triangles), from
/// the faceted engine's tessellation.
#[expect(
    clippy::expect_used,
    reason = "literal radii and segment counts, always a valid mesh"
)]
fn sphere_mesh(r: f64, n: u32) -> Geometry {
    let sphere = Ellipsoid::sphere(r).expect("valid literal");
    // The ellipsoid tessellation uses n(r, δ/2) segments: this δ gives exactly n.
    let deviation = 2.0 * r * (1.0 - (std::f64::consts::PI / f64::from(n)).cos()) * (1.0 + 1e-9);
    let t = engine_facet::tessellate::ellipsoid(&sphere, deviation);
    let mesh = contact_core::geometry::TriangleMesh::new(t.vertices, t.triangles)
        .expect("a closed tessellation");
    Geometry::Mesh(Arc::new(mesh))
}

/// A torus mesh at the default faceting tolerance.
#[expect(clippy::expect_used, reason = "literal radii, always a valid mesh")]
fn torus_mesh(major: f64, minor: f64) -> Geometry {
    let torus = Geometry::Torus(Torus::new(major, minor).expect("valid literal"));
    let t = engine_facet::tessellate::tessellate(
        &torus,
        contact_core::FacetingTolerance::new(1000.0).expect("valid literal"),
    )
    .expect("a torus tessellates");
    let mesh = contact_core::geometry::TriangleMesh::new(t.vertices, t.triangles)
        .expect("a closed tessellation");
    Geometry::Mesh(Arc::new(mesh))
}

fn single(g: Geometry) -> Vec<GeometryInstance> {
    vec![GeometryInstance::new(g)]
}

#[expect(clippy::expect_used, reason = "callers pass literal radii > 0")]
fn circle(r: f64) -> Geometry {
    Geometry::Circle(Circle::new(r).expect("valid literal"))
}

#[expect(
    clippy::expect_used,
    reason = "literal sizes, all inside their valid ranges"
)]
/// A closed cubic B-spline through `n` points of a wavy circle of radius `r`.
fn blob(r: f64, n: usize, wave: f64) -> Curve {
    let points: Vec<Point2> = (0..3 * n)
        .map(|k| {
            let a = TAU * k as f64 / (3 * n) as f64;
            let rho = r * (1.0 + wave * (n as f64 * a).cos());
            Point2::new(rho * a.cos(), rho * a.sin())
        })
        .collect();
    Curve::new(&points, 4, true, CurvePoints::Interpolated).expect("valid literal")
}

#[expect(clippy::expect_used, reason = "literal points, distinct and finite")]
/// The cam of the 2-D scenes: an egg shape, counter-clockwise so its normal points outward.
fn cam() -> Curve {
    let points: Vec<Point2> = (0..16)
        .map(|k| {
            let a = TAU * k as f64 / 16.0;
            Point2::new(1.2 * a.cos() + 0.2 * (2.0 * a).cos(), 0.9 * a.sin())
        })
        .collect();
    Curve::new(&points, 4, true, CurvePoints::Interpolated).expect("valid literal")
}

/// How I is oriented relative to J in a scene's poses.
#[derive(Debug, Clone, Copy)]
enum Orientation {
    /// Uniform on SO(3).
    Random,
    /// I's z axis parallel to J's x-y plane (rotation about J's z random).
    AxisParallelToPlane,
    /// I's z axis tilted by the angle from J's z (rotation about J's z random).
    Tilted(f64),
    /// I's z axis parallel to J's; approach perpendicular to both.
    ParallelAxes,
    /// I's z axis along J's y; approach along J's x.
    CrossedAxes,
    /// Random rotation; approach direction in J's x-y plane.
    RandomInPlane,
    /// Random rotation; approach along one of J's axes, chosen at random with its sign: a
    /// corner of a turned box dips into the middle of a face of J.
    RandomOntoFace,
    /// 2-D shapes: rotation about J's z only; approach direction in J's x-y plane.
    Planar,
}

impl Scene {
    fn with_closed_form(mut self, f: ClosedForm) -> Self {
        self.closed_form = Some(f);
        self
    }

    fn base(
        name: &'static str,
        description: impl Into<Cow<'static, str>>,
        i: Vec<GeometryInstance>,
        j: Vec<GeometryInstance>,
        scale: f64,
    ) -> Self {
        Self {
            name: name.into(),
            description: description.into(),
            i,
            j,
            scale,
            poses: Vec::new(),
            closed_form: None,
        }
    }

    /// I above J's plane (J's +z), at each nominal depth.
    fn on_plane(
        name: &'static str,
        description: &'static str,
        i: Vec<GeometryInstance>,
        scale: f64,
        orientation: Orientation,
    ) -> Self {
        let mut scene = Self::base(
            name,
            description,
            i,
            single(Geometry::Plane(Plane::unbounded())),
            scale,
        );
        let mut rng = SplitMix64::new(seed(name));
        for depth in relative_depths().map(|d| d * scale) {
            let rotation = orient(orientation, &mut rng);
            let up = Vector3::z();
            let lowest = -support_of(
                &scene.i,
                &Isometry3::from_parts(Default::default(), rotation),
                &-up,
            );
            let offset = Vector3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), -lowest - depth);
            scene.push(
                depth,
                Isometry3::from_parts(offset.into(), rotation),
                &mut rng,
            );
        }
        scene
    }

    /// I approaching J along a direction at each nominal depth.
    fn pair(
        name: &'static str,
        description: &'static str,
        i: Vec<GeometryInstance>,
        j: Vec<GeometryInstance>,
        scale: f64,
        orientation: Orientation,
    ) -> Self {
        let mut scene = Self::base(name, description, i, j, scale);
        let mut rng = SplitMix64::new(seed(name));
        for depth in relative_depths().map(|d| d * scale) {
            let rotation = orient(orientation, &mut rng);
            let u = match orientation {
                Orientation::ParallelAxes | Orientation::RandomInPlane | Orientation::Planar => {
                    let a = rng.range(0.0, TAU);
                    Vector3::new(a.cos(), a.sin(), 0.0)
                }
                Orientation::CrossedAxes => Vector3::x(),
                Orientation::RandomOntoFace => {
                    let k = (rng.range(0.0, 6.0) as usize).min(5);
                    let sign = if k.is_multiple_of(2) { 1.0 } else { -1.0 };
                    Vector3::ith(k / 2, sign)
                }
                _ => rng.unit_vector(),
            };
            let placed = Isometry3::from_parts(Default::default(), rotation);
            // Ellipsoids and boxes touch where their support points along u and −u meet (their
            // extents along u alone can overlap beside each other); the other shapes are
            // placed by their support extents along u, their extreme points lying on one line
            // along the approach for the orientations used here.
            let offset = match (
                single_support_point(&scene.j, &Isometry3::identity(), &u),
                single_support_point(&scene.i, &placed, &-u),
            ) {
                (Some(on_j), Some(on_i)) => on_j - on_i - u * depth,
                _ => {
                    let reach = support_of(&scene.j, &Isometry3::identity(), &u)
                        + support_of(&scene.i, &placed, &-u);
                    u * (reach - depth)
                }
            };
            scene.push(
                depth,
                Isometry3::from_parts(offset.into(), rotation),
                &mut rng,
            );
        }
        scene
    }

    /// A 2-D shape of radius `radius` placed against the cam along the cam's outward normal.
    fn on_curve(
        name: &'static str,
        description: &'static str,
        i: Vec<GeometryInstance>,
        radius: f64,
    ) -> Self {
        let cam = cam();
        let [u0, u1] = cam.domain();
        let mut scene = Self::base(
            name,
            description,
            i,
            single(Geometry::Curve(Arc::new(cam.clone()))),
            0.2,
        );
        let mut rng = SplitMix64::new(seed(name));
        for depth in relative_depths().map(|d| d * 0.2) {
            let u = rng.range(u0, u1);
            let normal = cam.normal(u).unwrap_or(nalgebra::Vector2::x());
            let at = cam.point(u).coords + normal * (radius - depth);
            let rotation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.range(0.0, TAU));
            scene.push(
                depth,
                Isometry3::from_parts(Vector3::new(at.x, at.y, 0.0).into(), rotation),
                &mut rng,
            );
        }
        scene
    }

    /// A kernel's configuration moved along `approach` (a unit vector in J's frame, from J
    /// towards I): I at `reference` relative to J stands at nominal depth `reference_depth`,
    /// and the pose at nominal depth `d` is `reference` translated by
    /// `approach·(reference_depth − d)`, its rotation kept. Where `approach` is the contact
    /// normal and the reference depth a closed form, every pose's nominal depth is its depth.
    #[expect(
        clippy::too_many_arguments,
        reason = "one scene's whole definition, called from one place"
    )]
    fn through(
        name: &'static str,
        description: impl Into<Cow<'static, str>>,
        i: Vec<GeometryInstance>,
        j: Vec<GeometryInstance>,
        scale: f64,
        reference: Isometry3,
        reference_depth: f64,
        approach: Vector3,
    ) -> Self {
        let mut scene = Self::base(name, description, i, j, scale);
        let mut rng = SplitMix64::new(seed(name));
        for depth in relative_depths().map(|d| d * scale) {
            let moved = reference.translation.vector + approach * (reference_depth - depth);
            scene.push(
                depth,
                Isometry3::from_parts(moved.into(), reference.rotation),
                &mut rng,
            );
        }
        scene
    }

    /// Adds a pose given I relative to J, with J at a seeded random world pose (so every
    /// answer is also a check of rigid-motion invariance).
    fn push(&mut self, nominal_depth: f64, pose_j_i: Isometry3, rng: &mut SplitMix64) {
        let t = Vector3::new(
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
        ) * self.scale;
        let pose_world_j = Isometry3::from_parts(t.into(), rng.rotation());
        self.poses.push(ScenePose {
            nominal_depth,
            pose_world_i: pose_world_j * pose_j_i,
            pose_world_j,
        });
    }

    /// The same scene with every length multiplied by `factor` (geometry, placements, poses):
    /// for scale-covariance checks from 1e-6 to 1e6.
    pub fn scaled(&self, factor: f64) -> Result<Self, contact_core::InvalidArgument> {
        let scale_instance =
            |g: &GeometryInstance| -> Result<GeometryInstance, contact_core::InvalidArgument> {
                let mut out = g.clone();
                out.geometry = Arc::new(scale_geometry(&g.geometry, factor)?);
                out.pose_part_geometry.translation.vector *= factor;
                Ok(out)
            };
        let scale_pose = |p: &Isometry3| {
            let mut q = *p;
            q.translation.vector *= factor;
            q
        };
        Ok(Self {
            i: self
                .i
                .iter()
                .map(scale_instance)
                .collect::<Result<_, _>>()?,
            j: self
                .j
                .iter()
                .map(scale_instance)
                .collect::<Result<_, _>>()?,
            scale: self.scale * factor,
            poses: self
                .poses
                .iter()
                .map(|p| ScenePose {
                    nominal_depth: p.nominal_depth * factor,
                    pose_world_i: scale_pose(&p.pose_world_i),
                    pose_world_j: scale_pose(&p.pose_world_j),
                })
                .collect(),
            ..self.clone()
        })
    }
}

/// A stable seed per scene name (FNV-1a), so adding a scene does not move the others' poses.
fn seed(name: &str) -> u64 {
    name.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
    })
}

fn orient(orientation: Orientation, rng: &mut SplitMix64) -> UnitQuaternion {
    let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.range(0.0, TAU));
    match orientation {
        Orientation::Random | Orientation::RandomInPlane | Orientation::RandomOntoFace => {
            rng.rotation()
        }
        // A random roll about I's own axis too, so faceted shapes show every facet phase.
        Orientation::AxisParallelToPlane => {
            spin * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), FRAC_PI_2) * roll(rng)
        }
        Orientation::Tilted(angle) => {
            spin * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), angle) * roll(rng)
        }
        Orientation::ParallelAxes => spin * roll(rng),
        Orientation::Planar => spin,
        Orientation::CrossedAxes => {
            UnitQuaternion::from_axis_angle(&Vector3::x_axis(), FRAC_PI_2) * roll(rng)
        }
    }
}

/// A random rotation about z (a shape's own axis).
fn roll(rng: &mut SplitMix64) -> UnitQuaternion {
    UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.range(0.0, TAU))
}

/// The support point of a one-member list placed at part pose `pose`, where it is unique
/// ([`support_point`]).
fn single_support_point(
    list: &[GeometryInstance],
    pose: &Isometry3,
    d: &Vector3,
) -> Option<contact_core::Point3> {
    match list {
        [g] => support_point(&g.geometry, &(pose * g.pose_part_geometry), d),
        _ => None,
    }
}

/// The support of a list placed at part pose `pose` (the largest over its members).
fn support_of(list: &[GeometryInstance], pose: &Isometry3, d: &Vector3) -> f64 {
    list.iter()
        .filter_map(|g| support(&g.geometry, &(pose * g.pose_part_geometry), d))
        .fold(f64::NEG_INFINITY, f64::max)
}

fn scale_geometry(g: &Geometry, f: f64) -> Result<Geometry, contact_core::InvalidArgument> {
    Ok(match g {
        Geometry::Ellipsoid(e) => {
            let s = e.semi_axes() * f;
            Geometry::Ellipsoid(Ellipsoid::new(s.x, s.y, s.z)?)
        }
        Geometry::Cylinder(c) => Geometry::Cylinder(Cylinder::new(c.radius() * f, c.length() * f)?),
        Geometry::Cuboid(b) => {
            let h = b.half_extents() * f;
            let c = b.center().coords * f;
            let centred = Cuboid::centered(h.x, h.y, h.z)?;
            if c == Vector3::zeros() {
                Geometry::Cuboid(centred)
            } else {
                Geometry::Cuboid(Cuboid::from_corner(2.0 * c.x, 2.0 * c.y, 2.0 * c.z)?)
            }
        }
        Geometry::Frustum(fr) => Geometry::Frustum(Frustum::new(
            fr.bottom_radius() * f,
            fr.top_radius() * f,
            fr.length() * f,
        )?),
        Geometry::Torus(t) => {
            Geometry::Torus(Torus::new(t.major_radius() * f, t.minor_radius() * f)?)
        }
        Geometry::Plane(p) => {
            let [x0, x1] = p.x_range();
            let [y0, y1] = p.y_range();
            Geometry::Plane(if p.is_unbounded() {
                Plane::unbounded()
            } else {
                Plane::bounded(x0 * f, x1 * f, y0 * f, y1 * f)?
            })
        }
        Geometry::Mesh(m) => {
            let vertices = m.vertices().iter().map(|v| v * f).collect();
            Geometry::Mesh(Arc::new(
                contact_core::geometry::TriangleMesh::new(vertices, m.triangles().to_vec())
                    .map_err(|e| {
                        contact_core::InvalidArgument::with_text(
                            "scale",
                            format!("{f:?}"),
                            format!("a factor that keeps the mesh valid ({e})"),
                        )
                    })?,
            ))
        }
        Geometry::Point => Geometry::Point,
        Geometry::Line(l) => {
            let [x0, x1] = l.x_range();
            Geometry::Line(contact_core::geometry::Line::bounded(x0 * f, x1 * f)?)
        }
        Geometry::Circle(c) => Geometry::Circle(Circle::new(c.radius() * f)?),
        Geometry::Arc(a) => Geometry::Arc(contact_core::geometry::Arc::new(
            a.radius() * f,
            a.range_angle(),
        )?),
        Geometry::Curve(c) => {
            // Scaling the control points scales the B-spline exactly.
            let points: Vec<Point2> = c.control_points().iter().map(|q| q * f).collect();
            let distinct = if c.is_closed() {
                &points[..points.len() + 1 - c.order()]
            } else {
                &points[..]
            };
            Geometry::Curve(Arc::new(Curve::new(
                distinct,
                c.order(),
                c.is_closed(),
                CurvePoints::Control,
            )?))
        }
    })
}

#[cfg(test)]
mod tests;
