//! Mesh files as geometry: STL and OBJ files read as they are, Parasolid bodies read from
//! their transmit file and tessellated at their faceting tolerance.
//!
//! For the exact engine, a body that is exactly one of its primitives (a sphere, ring torus,
//! cylinder, frustum or box: [`parasolid::primitive::recognise`]) is that primitive
//! ([`exact_instance`]).
//!
//! A transmit file holds every body of a model, and several GRAPHICS (and `check` before
//! `run`) name bodies of the same file: each file is read once per process, each body
//! tessellated once per tolerance and recognised as a primitive or not once, all kept for the
//! process's life.

use crate::model::{MeshFile, ParasolidBody};
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Frustum, Torus, TriangleMesh};
use contact_core::{FacetingTolerance, Geometry, GeometryInstance};
use parasolid::{Body, Part, Primitive, Shape, body_mesh};
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex, OnceLock};

type PartCache = Mutex<HashMap<PathBuf, Arc<Part>>>;
type MeshKey = (PathBuf, u32, String, u64, u64);
type MeshCache = Mutex<HashMap<MeshKey, Arc<TriangleMesh>>>;
type BodyKey = (PathBuf, u32, String);
type PrimitiveCache = Mutex<HashMap<BodyKey, Option<Primitive>>>;

fn parts() -> &'static PartCache {
    static CACHE: OnceLock<PartCache> = OnceLock::new();
    CACHE.get_or_init(Default::default)
}

fn meshes() -> &'static MeshCache {
    static CACHE: OnceLock<MeshCache> = OnceLock::new();
    CACHE.get_or_init(Default::default)
}

fn primitives() -> &'static PrimitiveCache {
    static CACHE: OnceLock<PrimitiveCache> = OnceLock::new();
    CACHE.get_or_init(Default::default)
}

/// The transmit file at `path`, read once.
pub fn read_part(path: &std::path::Path) -> Result<Arc<Part>, parasolid::Error> {
    if let Some(p) = parts().lock().ok().and_then(|c| c.get(path).cloned()) {
        return Ok(p);
    }
    let p = Arc::new(Part::read(path)?);
    if let Ok(mut c) = parts().lock() {
        c.insert(path.to_path_buf(), p.clone());
    }
    Ok(p)
}

/// The mesh of a Parasolid body in model length units (GRAPHICS frame = RM marker frame),
/// tessellated at the GRAPHICS' FACETING_TOLERANCE, else at `model_tolerance` (the run's
/// model-wide faceting tolerance: PREFERENCES/CONTACT_FACETING_TOLERANCE, its overrides, or
/// Adams' default 300.0028).
pub fn body_geometry(
    file: &MeshFile,
    body: &ParasolidBody,
    model_tolerance: FacetingTolerance,
) -> Result<Arc<TriangleMesh>, String> {
    let tolerance = file.faceting_tolerance.unwrap_or(model_tolerance);
    let key = (
        file.path.clone(),
        body.part,
        body.element.to_ascii_uppercase(),
        tolerance.value().to_bits(),
        body.units_per_metre.to_bits(),
    );
    if let Some(m) = meshes().lock().ok().and_then(|c| c.get(&key).cloned()) {
        return Ok(m);
    }
    let part = read_part(&file.path).map_err(|e| e.to_string())?;
    let index = part
        .find_body_on_part(body.part, body.part_name.as_deref(), &body.element)
        .map_err(|e| e.to_string())?;
    let name = format!("PART/{} {}", body.part, body.element);
    let b = Body::read(&part, index).map_err(|e| e.to_string())?;
    let mesh = body_mesh(&part, &b, tolerance, &name).map_err(|e| e.to_string())?;
    let s = body.units_per_metre;
    let vertices = mesh.vertices().iter().map(|p| p * s).collect();
    let mesh = TriangleMesh::new(vertices, mesh.triangles().to_vec())
        .map(Arc::new)
        .map_err(|e| format!("{}: body {name}: {e}", file.path.display()))?;
    if let Ok(mut c) = meshes().lock() {
        c.insert(key, mesh.clone());
    }
    Ok(mesh)
}

/// A mesh file's geometry: an STL or OBJ file as read, a Parasolid body tessellated (see
/// [`body_geometry`] for `model_tolerance`).
pub fn mesh_geometry(
    file: &MeshFile,
    model_tolerance: FacetingTolerance,
) -> Result<Geometry, String> {
    match &file.parasolid {
        Some(body) => Ok(Geometry::Mesh(body_geometry(file, body, model_tolerance)?)),
        None => contact_core::mesh_file::read_mesh_geometry(&file.path).map_err(|e| e.to_string()),
    }
}

/// A recognised primitive in model length units (`s` per metre), or `None` when the geometry
/// refuses its dimensions (out of range or of aspect ratio).
fn primitive_geometry(shape: Shape, s: f64) -> Option<Geometry> {
    let g = match shape {
        Shape::Sphere { radius } => {
            Geometry::Ellipsoid(Ellipsoid::new(radius * s, radius * s, radius * s).ok()?)
        }
        Shape::Torus { major, minor } => Geometry::Torus(Torus::new(major * s, minor * s).ok()?),
        Shape::Frustum {
            bottom,
            top,
            length,
        } if bottom == top => Geometry::Cylinder(Cylinder::new(bottom * s, length * s).ok()?),
        Shape::Frustum {
            bottom,
            top,
            length,
        } => Geometry::Frustum(Frustum::new(bottom * s, top * s, length * s).ok()?),
        Shape::Box { half } => {
            Geometry::Cuboid(Cuboid::centered(half[0] * s, half[1] * s, half[2] * s).ok()?)
        }
    };
    Some(g)
}

/// The Parasolid body `file` names as the exact engine's primitive, placed on its part: the
/// primitive in model length units at the GRAPHICS frame (RM marker) composed with the
/// primitive's frame in the body. `None` for STL and OBJ files, for a body that is not exactly
/// a primitive, and for a file or body that cannot be read (the mesh path reports why).
pub fn exact_instance(file: &MeshFile) -> Option<GeometryInstance> {
    let body = file.parasolid.as_ref()?;
    let primitive = body_primitive(file, body)?;
    let s = body.units_per_metre;
    let geometry = primitive_geometry(primitive.shape, s)?;
    let mut frame = primitive.frame;
    frame.translation.vector *= s;
    let mut instance = GeometryInstance::new(geometry)
        .at(file.pose_part_geometry * frame)
        .labeled(file.label.clone());
    instance.flip_normal = file.flip_normal;
    Some(instance)
}

/// The primitive the body is exactly, if any, recognised once per process (`None` also for a
/// file or body that cannot be read).
fn body_primitive(file: &MeshFile, body: &ParasolidBody) -> Option<Primitive> {
    let key = (
        file.path.clone(),
        body.part,
        body.element.to_ascii_uppercase(),
    );
    if let Some(p) = primitives().lock().ok().and_then(|c| c.get(&key).copied()) {
        return p;
    }
    let recognised = || {
        let part = read_part(&file.path).ok()?;
        let index = part
            .find_body_on_part(body.part, body.part_name.as_deref(), &body.element)
            .ok()?;
        parasolid::primitive::recognise(&Body::read(&part, index).ok()?)
    };
    let primitive = recognised();
    if let Ok(mut c) = primitives().lock() {
        c.insert(key, primitive);
    }
    primitive
}
