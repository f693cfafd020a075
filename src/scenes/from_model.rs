//! Scenes from a dataset: each CONTACT of a [`Model`] becomes a scene of its own I and J
//! geometry lists, placed at a family of poses around the initial configuration. `contact
//! tradeoff MODEL.adm` and `contact select` take the geometry and the contact's size from
//! here and the poses from a run of the model ([`super::from_run`]): the family below only
//! reaches the poses the approach direction passes through.
//!
//! # The pose family of a contact
//! - Pose 0 is the model's initial configuration (both parts at their initial world poses).
//! - The *approach direction* `u` (world, pointing from J towards I) is the outward normal of
//!   J's plane when J's list holds a 3-D plane, the reverse of I's plane normal when I's does,
//!   and otherwise the direction from the centre of J's bounding box to the centre of I's (for a
//!   2-D contact projected onto J's plane of motion); when the centres coincide, `u` is against
//!   gravity (or +z without gravity).
//! - Then one pose per nominal depth of [`relative_depths`] (fractions of the contact's size:
//!   separated, near, grazing, shallow to deep): J stays at its initial pose; I keeps its
//!   initial orientation relative to J for every third pose and is tilted by a seeded rotation
//!   of up to 5° about a random axis (about J's plane normal only, for 2-D contacts) for the
//!   others; then I is slid along `u` until its support-function overlap
//!   with J along `u` equals the nominal depth. The nominal depth only labels the pose; the
//!   reference answer is the exact engine's.
//!
//! # The contact's size
//! The scene's `scale` is the smallest half-extent of the bounding boxes (each in its own
//! geometry frame) of the contact's bounded geometries: a sphere's radius, a box's smallest
//! half-edge, a cylinder's radius (or half-length if shorter), a torus's minor radius, a mesh's
//! smallest half-extent. Depth and point errors of the trade are relative to it.

use super::{POSES_PER_SPECIAL_DEPTH, Scene, ScenePose, SplitMix64, relative_depths, support};
use crate::model::{ContactDimension, ContactElement, ContactGeometry, MeshFile, Model};
use contact_core::{Geometry, GeometryInstance, Isometry3, UnitQuaternion, Vector3};

/// Largest tilt of I in the perturbed poses, radians.
const MAX_TILT: f64 = 5.0 * std::f64::consts::PI / 180.0;

/// Why a contact of a model cannot become a scene.
#[derive(Debug, thiserror::Error)]
pub enum ModelSceneError {
    /// A mesh file could not be read.
    #[error("CONTACT/{contact}: {message}")]
    Mesh {
        /// The contact's id.
        contact: u32,
        /// What went wrong, naming the file.
        message: String,
    },
    /// A contact names a part the model does not have.
    #[error("CONTACT/{contact}: PART/{part} is not a part of the model")]
    MissingPart {
        /// The contact's id.
        contact: u32,
        /// The part id.
        part: u32,
    },
    /// No geometry of the contact has a finite, positive size to measure errors against.
    #[error("CONTACT/{contact}: no bounded geometry to take the contact's size from")]
    NoSize {
        /// The contact's id.
        contact: u32,
    },
    /// The model has no contacts.
    #[error("the model has no CONTACT statements")]
    NoContacts,
}

/// One scene per CONTACT of `model`, named `CONTACT/id`, in model order (see the module docs
/// for the poses and the size). Mesh files are read with the faceted engine's STL reader.
pub fn from_model(model: &Model) -> Result<Vec<Scene>, ModelSceneError> {
    if model.contacts.is_empty() {
        return Err(ModelSceneError::NoContacts);
    }
    model
        .contacts
        .iter()
        .map(|c| contact_scene(model, c))
        .collect()
}

fn contact_scene(model: &Model, c: &ContactElement) -> Result<Scene, ModelSceneError> {
    let list = |members: &[(u32, ContactGeometry)]| -> Result<Vec<GeometryInstance>, _> {
        members
            .iter()
            .map(|(_, g)| {
                let mut instance = match g {
                    ContactGeometry::Geometry(instance) => instance.clone(),
                    ContactGeometry::MeshFile(file) => {
                        read_mesh(file, model.preferences.faceting_tolerance).map_err(
                            |message| ModelSceneError::Mesh {
                                contact: c.id,
                                message,
                            },
                        )?
                    }
                };
                // The sweep sets every geometry's tolerance.
                instance.faceting_tolerance = None;
                Ok(instance)
            })
            .collect()
    };
    let (i, j) = (list(&c.i_geometries)?, list(&c.j_geometries)?);
    let part_pose = |part: u32| {
        model
            .parts
            .get(&part)
            .map(|p| p.pose_world_part)
            .ok_or(ModelSceneError::MissingPart {
                contact: c.id,
                part,
            })
    };
    let (pose_i, pose_j) = (part_pose(c.i_part)?, part_pose(c.j_part)?);
    let scale = i
        .iter()
        .chain(&j)
        .filter_map(|g| smallest_half_extent(&g.geometry))
        .fold(f64::INFINITY, f64::min);
    if !(scale.is_finite() && scale > 0.0) {
        return Err(ModelSceneError::NoSize { contact: c.id });
    }
    let planar = c.dimension == ContactDimension::TwoD;
    // 2-D contacts move in the plane of J's first geometry.
    let plane_normal = j.first().map_or_else(Vector3::z, |g| {
        (pose_j * g.pose_part_geometry) * Vector3::z()
    });
    let u = approach(
        &i,
        &pose_i,
        &j,
        &pose_j,
        model.gravity,
        planar.then_some(plane_normal),
    );
    let mut scene = Scene {
        name: format!("CONTACT/{}", c.id).into(),
        description: format!("{}: the dataset's contact at {}", c.origin, model.title).into(),
        i,
        j,
        scale,
        poses: Vec::new(),
        closed_form: None,
    };
    scene.poses.push(ScenePose {
        nominal_depth: overlap(&scene, &pose_i, &pose_j, &u).unwrap_or(f64::NAN),
        pose_world_i: pose_i,
        pose_world_j: pose_j,
    });
    let mut rng = SplitMix64::new(u64::from(c.id).wrapping_mul(0x9e37_79b9_7f4a_7c15));
    for (k, depth) in relative_depths().map(|d| d * scale).into_iter().enumerate() {
        let mut tilted = pose_i;
        if k % POSES_PER_SPECIAL_DEPTH > 0 {
            let axis = if planar {
                plane_normal
            } else {
                rng.unit_vector()
            };
            let angle = rng.range(-MAX_TILT, MAX_TILT);
            let turn = UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(axis), angle);
            tilted.rotation = turn * tilted.rotation;
        }
        let Some(now) = overlap(&scene, &tilted, &pose_j, &u) else {
            continue;
        };
        tilted.translation.vector += u * (now - depth);
        scene.poses.push(ScenePose {
            nominal_depth: depth,
            pose_world_i: tilted,
            pose_world_j: pose_j,
        });
    }
    Ok(scene)
}

/// Reads an STL or OBJ file, or tessellates a Parasolid body (at the GRAPHICS' faceting
/// tolerance, else the dataset's `tolerance`), into a geometry placed on its part.
fn read_mesh(
    file: &MeshFile,
    tolerance: contact_core::FacetingTolerance,
) -> Result<GeometryInstance, String> {
    let geometry = contact_adams::parasolid_bodies::mesh_geometry(file, tolerance)?;
    let mut instance = GeometryInstance::new(geometry)
        .at(file.pose_part_geometry)
        .labeled(file.label.clone());
    instance.flip_normal = file.flip_normal;
    Ok(instance)
}

/// Half the smallest extent of the geometry's bounding box in its own frame; `None` for
/// unbounded or size-less geometries (planes, lines, points).
fn smallest_half_extent(g: &Geometry) -> Option<f64> {
    let id = Isometry3::identity();
    let axes = if g.is_planar() { 2 } else { 3 };
    let mut smallest = f64::INFINITY;
    for k in 0..axes {
        let e = Vector3::ith(k, 1.0);
        let extent = support(g, &id, &e)? + support(g, &id, &-e)?;
        smallest = smallest.min(0.5 * extent);
    }
    (smallest.is_finite() && smallest > 0.0).then_some(smallest)
}

/// The outward normal (world) of the first 3-D plane of a list at part pose `pose`.
fn plane_normal(list: &[GeometryInstance], pose: &Isometry3) -> Option<Vector3> {
    list.iter().find_map(|g| match g.geometry.as_ref() {
        Geometry::Plane(_) => Some(outward(g, &(pose * g.pose_part_geometry))),
        _ => None,
    })
}

/// A plane's outward normal (world) with its geometry frame at `at`.
fn outward(g: &GeometryInstance, at: &Isometry3) -> Vector3 {
    let up = at * Vector3::z();
    if g.flip_normal { -up } else { up }
}

/// The centre of a list's world bounding box (bounded members only).
fn centre(list: &[GeometryInstance], pose: &Isometry3) -> Option<Vector3> {
    let mut lo = Vector3::repeat(f64::INFINITY);
    let mut hi = Vector3::repeat(f64::NEG_INFINITY);
    for g in list {
        let at = pose * g.pose_part_geometry;
        for k in 0..3 {
            let e = Vector3::ith(k, 1.0);
            if let (Some(h), Some(l)) = (
                support(&g.geometry, &at, &e),
                support(&g.geometry, &at, &-e),
            ) {
                hi[k] = hi[k].max(h);
                lo[k] = lo[k].min(-l);
            }
        }
    }
    (lo.iter().chain(hi.iter()).all(|v| v.is_finite())).then(|| 0.5 * (lo + hi))
}

/// The approach direction from J towards I (see the module docs).
fn approach(
    i: &[GeometryInstance],
    pose_i: &Isometry3,
    j: &[GeometryInstance],
    pose_j: &Isometry3,
    gravity: Vector3,
    planar_normal: Option<Vector3>,
) -> Vector3 {
    let fallback = if gravity.norm() > 0.0 {
        -gravity.normalize()
    } else {
        Vector3::z()
    };
    if planar_normal.is_none() {
        if let Some(n) = plane_normal(j, pose_j) {
            return n;
        }
        if let Some(n) = plane_normal(i, pose_i) {
            return -n;
        }
    }
    let mut d = match (centre(i, pose_i), centre(j, pose_j)) {
        (Some(ci), Some(cj)) => ci - cj,
        _ => fallback,
    };
    if let Some(n) = planar_normal {
        d -= n * n.dot(&d);
    }
    if d.norm() > 1e-12 * (1.0 + d.norm()) && d.norm() > 0.0 {
        d.normalize()
    } else if let Some(n) = planar_normal {
        // Any in-plane direction.
        let t = fallback - n * n.dot(&fallback);
        if t.norm() > 1e-9 {
            t.normalize()
        } else {
            n.cross(&Vector3::x())
                .try_normalize(1e-9)
                .unwrap_or(Vector3::y())
        }
    } else {
        fallback
    }
}

/// How far the two lists' supports overlap along `u` (positive: overlapping slabs), with I at
/// `pose_i` and J at `pose_j`. A plane's support along its own normal is its height; any
/// other unbounded support makes the overlap undefined (`None`).
fn overlap(scene: &Scene, pose_i: &Isometry3, pose_j: &Isometry3, u: &Vector3) -> Option<f64> {
    let reach = |list: &[GeometryInstance], pose: &Isometry3, d: &Vector3| -> Option<f64> {
        list.iter()
            .map(|g| {
                let at = pose * g.pose_part_geometry;
                support(&g.geometry, &at, d).or_else(|| match g.geometry.as_ref() {
                    // Along its outward normal a half-space reaches its surface's height.
                    Geometry::Plane(_) if outward(g, &at).dot(d) > 1.0 - 1e-12 => {
                        Some(d.dot(&at.translation.vector))
                    }
                    _ => None,
                })
            })
            .try_fold(f64::NEG_INFINITY, |m, h| h.map(|h| m.max(h)))
    };
    Some(reach(&scene.j, pose_j, u)? + reach(&scene.i, pose_i, &-u)?)
}
