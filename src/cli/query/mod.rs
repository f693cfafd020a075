//! `contact query`: contacts between two geometries at a list of relative poses, with timing
//! and work counters, optionally beside parry's trimesh contact on the same meshes.
//!
//! Geometry specs (sizes in model units): `sphere:r=1`, `ellipsoid:a=1,b=2,c=3` (semi-axes),
//! `box:x=1,y=2,z=3` (full extents, centred on the origin), `cylinder:r=1,l=2` (bottom face at
//! the origin, axis +z), `frustum:r0=1,r1=0.5,l=2`, `torus:R=2,r=0.5`, `plane` (the half-space
//! z ≤ 0); anything else is read as an STL file (ascii or binary).
//!
//! Poses file: one pose of I relative to J a line, `x y z qw qx qy qz` separated by spaces or
//! commas (the quaternion must be unit within 1e-6, then is normalised; else an error with its
//! line); blank lines and lines
//! starting with `#` are skipped.

use crate::peer::{ParryError, ParryPeer};
use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Frustum, Plane, Torus};
use contact_core::mesh_file::stl::read_stl;
use contact_core::mesh_file::{MeshFileError, read_mesh_file};
use contact_core::{
    Contact, FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, GeometryLibrary,
    InvalidArgument, Isometry3, PrepareError, QueryError, UnitQuaternion, Vector3, WorkCounters,
};
use engine_facet::{FacetEngine, Shape};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;
use thiserror::Error;

/// Which geometry engine answers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum EngineName {
    /// The analytic engine.
    Exact,
    /// Tessellated meshes with OBB trees (the default, as in Adams).
    Faceted,
}

/// A library to time beside ours.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Peer {
    /// parry3d-f64's trimesh–trimesh contact manifolds.
    Parry,
}

/// Arguments of `contact query`.
#[derive(Debug, Clone, clap::Args)]
pub struct QueryArgs {
    /// The I geometry: an STL or OBJ file or a primitive spec (`sphere:r=1`, `box:x=1,y=2,z=3`,
    /// `cylinder:r=1,l=2`, `frustum:r0=1,r1=0.5,l=2`, `ellipsoid:a=1,b=2,c=3`,
    /// `torus:R=2,r=0.5`, `plane`).
    pub geometry_i: String,
    /// The J geometry, as the I geometry.
    pub geometry_j: String,
    /// CSV of poses of I relative to J: `x y z qw qx qy qz` per line.
    #[arg(long)]
    pub poses: PathBuf,
    /// The geometry engine.
    #[arg(long, value_enum, default_value = "faceted")]
    pub engine: EngineName,
    /// The faceting tolerance FT (finite, > 0; higher is finer): chord deviation L/FT.
    #[arg(long, default_value_t = FacetingTolerance::DEFAULT.value())]
    pub faceting_tolerance: f64,
    /// Query every pose this many times (≥ 1) for the timing medians.
    #[arg(long, default_value_t = 1)]
    pub repeat: usize,
    /// Print JSON instead of CSV.
    #[arg(long)]
    pub json: bool,
    /// Also time a peer library on the same meshes and poses.
    #[arg(long, value_enum)]
    pub peer: Option<Peer>,
    /// Accept STL meshes that are not closed (with a warning).
    #[arg(long)]
    pub accept_open: bool,
}

/// Why `contact query` failed.
#[derive(Debug, Error)]
pub enum QueryCliError {
    /// A geometry spec could not be understood.
    #[error("geometry spec '{spec}': {reason}")]
    Spec {
        /// The spec as given.
        spec: String,
        /// What is wrong.
        reason: String,
    },
    /// A size or setting is out of range.
    #[error("{0}")]
    Invalid(#[from] InvalidArgument),
    /// A mesh file could not be used.
    #[error(transparent)]
    Mesh(#[from] MeshFileError),
    /// A line of the poses file is wrong.
    #[error("poses file '{path}', line {line}: {reason}")]
    Poses {
        /// The file.
        path: PathBuf,
        /// The 1-based line number.
        line: usize,
        /// What is wrong.
        reason: String,
    },
    /// The engine could not prepare the pair.
    #[error(transparent)]
    Prepare(#[from] PrepareError),
    /// A query failed.
    #[error(transparent)]
    Query(#[from] QueryError),
    /// `--peer parry` needs two meshes.
    #[error("--peer parry compares mesh against mesh; '{0}' is a plane")]
    PeerNeedsMeshes(String),
    /// parry failed.
    #[error(transparent)]
    Peer(#[from] ParryError),
    /// Writing the output failed.
    #[error("cannot write the output: {0}")]
    Io(#[from] std::io::Error),
}

/// Parses a geometry spec or reads an STL file; returns the geometry and any warnings.
pub fn parse_geometry(
    spec: &str,
    accept_open: bool,
) -> Result<(Geometry, Vec<String>), QueryCliError> {
    let (kind, rest) = spec.split_once(':').unwrap_or((spec, ""));
    let bad = |reason: String| QueryCliError::Spec {
        spec: spec.to_string(),
        reason,
    };
    let mut values: Vec<(String, f64)> = Vec::new();
    for item in rest.split(',').filter(|s| !s.trim().is_empty()) {
        let (key, value) = item
            .split_once('=')
            .ok_or_else(|| bad(format!("'{item}' is not key=value")))?;
        let value: f64 = value
            .trim()
            .parse()
            .map_err(|_| bad(format!("'{value}' is not a number")))?;
        let key = key.trim().to_string();
        if values.iter().any(|(k, _)| *k == key) {
            return Err(bad(format!("{key}= is given twice")));
        }
        values.push((key, value));
    }
    // The arguments each shape takes (an unknown shape is refused below, by name).
    let keys: Option<&[&str]> = match kind.trim().to_ascii_lowercase().as_str() {
        "sphere" => Some(&["r"]),
        "ellipsoid" => Some(&["a", "b", "c"]),
        "box" => Some(&["x", "y", "z"]),
        "cylinder" => Some(&["r", "l"]),
        "frustum" => Some(&["r0", "r1", "l"]),
        "torus" => Some(&["R", "r"]),
        "plane" => Some(&[]),
        _ => None,
    };
    if let Some(keys) = keys
        && let Some((key, _)) = values.iter().find(|(k, _)| !keys.contains(&k.as_str()))
    {
        return Err(bad(format!(
            "unknown argument {key}= (this shape takes {})",
            if keys.is_empty() {
                "none".to_string()
            } else {
                keys.join(", ")
            }
        )));
    }
    let get = |key: &str| -> Result<f64, QueryCliError> {
        values
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| *v)
            .ok_or_else(|| bad(format!("missing {key}=…")))
    };
    let geometry = match kind.trim().to_ascii_lowercase().as_str() {
        "sphere" => Geometry::sphere(get("r")?)?,
        "ellipsoid" => Geometry::Ellipsoid(Ellipsoid::new(get("a")?, get("b")?, get("c")?)?),
        "box" => Geometry::Cuboid(Cuboid::centered(
            0.5 * get("x")?,
            0.5 * get("y")?,
            0.5 * get("z")?,
        )?),
        "cylinder" => Geometry::Cylinder(Cylinder::new(get("r")?, get("l")?)?),
        "frustum" => Geometry::Frustum(Frustum::new(get("r0")?, get("r1")?, get("l")?)?),
        "torus" => Geometry::Torus(Torus::new(get("R")?, get("r")?)?),
        "plane" => Geometry::Plane(Plane::unbounded()),
        _ if rest.is_empty() => {
            // `.obj` by its extension; anything else is read as STL, whatever its name.
            let path = Path::new(spec);
            let read = if contact_core::mesh_file::is_mesh_file(path) {
                read_mesh_file(path, accept_open)
            } else {
                read_stl(path, accept_open).map_err(MeshFileError::from)
            };
            let mesh = read?;
            return Ok((Geometry::Mesh(Arc::new(mesh.mesh)), mesh.warnings));
        }
        other => return Err(bad(format!("unknown shape '{other}'"))),
    };
    Ok((geometry, Vec::new()))
}

/// Reads the poses file.
pub fn read_poses(path: &Path) -> Result<Vec<Isometry3>, QueryCliError> {
    let text = std::fs::read_to_string(path).map_err(|e| QueryCliError::Poses {
        path: path.to_path_buf(),
        line: 0,
        reason: e.to_string(),
    })?;
    parse_poses(&text).map_err(|(line, reason)| QueryCliError::Poses {
        path: path.to_path_buf(),
        line,
        reason,
    })
}

/// How far from 1 a pose quaternion's norm may be: a pose written to 7 significant digits
/// passes; a quaternion that is not a rotation (a scale, a typo) is refused rather than
/// normalised into some other rotation.
pub const POSE_QUATERNION_TOLERANCE: f64 = 1e-6;

/// Parses poses text; an error is `(line, reason)`. Each quaternion must be unit within
/// [`POSE_QUATERNION_TOLERANCE`]; it is then normalised.
pub fn parse_poses(text: &str) -> Result<Vec<Isometry3>, (usize, String)> {
    let mut poses = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let numbers: Vec<f64> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
            .map(|s| {
                s.parse::<f64>()
                    .map_err(|_| (k + 1, format!("'{s}' is not a number")))
            })
            .collect::<Result<_, _>>()?;
        let [x, y, z, qw, qx, qy, qz] = numbers[..] else {
            return Err((
                k + 1,
                format!(
                    "expected 7 numbers (x y z qw qx qy qz), got {}",
                    numbers.len()
                ),
            ));
        };
        let q = nalgebra::Quaternion::new(qw, qx, qy, qz);
        if !numbers.iter().all(|v| v.is_finite()) {
            return Err((k + 1, "needs finite numbers".into()));
        }
        // The norm scaled by the largest component, so that 1e200 does not overflow to inf.
        let largest = q.coords.amax();
        let norm = if largest > 0.0 {
            largest * (q.coords / largest).norm()
        } else {
            0.0
        };
        if (norm - 1.0).abs() > POSE_QUATERNION_TOLERANCE {
            return Err((
                k + 1,
                format!(
                    "the quaternion ({qw:?}, {qx:?}, {qy:?}, {qz:?}) has norm {:?}: it must be \
                     a unit quaternion within {POSE_QUATERNION_TOLERANCE:e} (divide it by its norm)",
                    norm
                ),
            ));
        }
        poses.push(Isometry3::from_parts(
            Vector3::new(x, y, z).into(),
            UnitQuaternion::from_quaternion(q),
        ));
    }
    Ok(poses)
}

/// The engine for a name: the one place `contact query` chooses one.
fn make_engine(
    name: EngineName,
    tolerance: FacetingTolerance,
) -> Result<Box<dyn GeometryEngine>, QueryCliError> {
    let library = match name {
        EngineName::Faceted => GeometryLibrary::Faceted,
        EngineName::Exact => GeometryLibrary::Exact,
    };
    Ok(crate::engine_choice::build_engine(library, tolerance))
}

fn median(samples: &mut [f64]) -> f64 {
    if samples.is_empty() {
        return 0.0;
    }
    samples.sort_by(f64::total_cmp);
    let n = samples.len();
    if n % 2 == 1 {
        samples[n / 2]
    } else {
        0.5 * (samples[n / 2 - 1] + samples[n / 2])
    }
}

/// Timing and counts of a run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Summary {
    /// Seconds to prepare (tessellate and build trees).
    pub prepare_seconds: f64,
    /// Median seconds per query.
    pub median_query_seconds: f64,
    /// Work over all queries.
    pub work: WorkCounters,
    /// Triangles prepared.
    pub triangles: usize,
    /// parry's tree build and median query seconds and points at the first pose, when asked.
    pub peer: Option<(f64, f64, usize)>,
}

/// Runs `contact query`, writing contacts and the summary to `out`, warnings to `warn`.
pub fn run(
    args: &QueryArgs,
    out: &mut dyn Write,
    warn: &mut dyn Write,
) -> Result<Summary, QueryCliError> {
    if args.repeat == 0 {
        return Err(InvalidArgument::new("--repeat", 0.0, ">= 1").into());
    }
    let tolerance = FacetingTolerance::new(args.faceting_tolerance)?;
    let (gi, wi) = parse_geometry(&args.geometry_i, args.accept_open)?;
    let (gj, wj) = parse_geometry(&args.geometry_j, args.accept_open)?;
    for w in wi.iter().chain(&wj) {
        writeln!(warn, "warning: {w}")?;
    }
    let poses = read_poses(&args.poses)?;
    let engine = make_engine(args.engine, tolerance)?;
    let (ii, ij) = (
        GeometryInstance::new(gi).labeled(args.geometry_i.clone()),
        GeometryInstance::new(gj).labeled(args.geometry_j.clone()),
    );
    let start = Instant::now();
    let pair = engine.prepare(std::slice::from_ref(&ii), std::slice::from_ref(&ij))?;
    let prepare_seconds = start.elapsed().as_secs_f64();
    let mut summary = Summary {
        prepare_seconds,
        triangles: pair.stats().triangles,
        ..Summary::default()
    };
    let mut per_pose: Vec<Vec<Contact>> = Vec::with_capacity(poses.len());
    let mut samples = Vec::with_capacity(poses.len() * args.repeat);
    let mut contacts = Vec::new();
    for round in 0..args.repeat {
        for pose in &poses {
            let t = Instant::now();
            pair.query(
                pose,
                &Isometry3::identity(),
                &mut contacts,
                &mut summary.work,
            )?;
            samples.push(t.elapsed().as_secs_f64());
            if round == 0 {
                per_pose.push(contacts.clone());
            }
        }
    }
    summary.median_query_seconds = median(&mut samples);
    if args.peer == Some(Peer::Parry) {
        summary.peer = Some(time_parry(&ii, &ij, tolerance, &poses, args.repeat)?);
    }
    if args.json {
        write_json(out, &poses, &per_pose, &summary)?;
    } else {
        write_csv(out, &per_pose, &summary)?;
    }
    Ok(summary)
}

fn time_parry(
    i: &GeometryInstance,
    j: &GeometryInstance,
    tolerance: FacetingTolerance,
    poses: &[Isometry3],
    repeat: usize,
) -> Result<(f64, f64, usize), QueryCliError> {
    // The peer gets our meshes: same triangles, same poses.
    let facet = FacetEngine::new(tolerance);
    let mesh = |g: &GeometryInstance, side| -> Result<_, QueryCliError> {
        match facet.prepare_geometry(g, side)?.shape {
            Shape::Mesh(m) => Ok(m),
            Shape::HalfSpace(_) | Shape::Planar(_) => {
                Err(QueryCliError::PeerNeedsMeshes(g.label.clone()))
            }
        }
    };
    let (a, b) = (
        mesh(i, contact_core::Side::I)?,
        mesh(j, contact_core::Side::J)?,
    );
    let start = Instant::now();
    let mut peer = ParryPeer::new(&a, &b)?;
    let build = start.elapsed().as_secs_f64();
    let mut samples = Vec::new();
    let mut first_points = 0;
    for round in 0..repeat {
        for (k, pose) in poses.iter().enumerate() {
            let pose_ab = pose.inverse();
            let t = Instant::now();
            let points = peer.contact_points(&pose_ab)?;
            samples.push(t.elapsed().as_secs_f64());
            if round == 0 && k == 0 {
                first_points = points;
            }
        }
    }
    Ok((build, median(&mut samples), first_points))
}

fn write_csv(
    out: &mut dyn Write,
    per_pose: &[Vec<Contact>],
    s: &Summary,
) -> Result<(), QueryCliError> {
    writeln!(
        out,
        "pose,contact,geometry_i,geometry_j,penetration,normal_x,normal_y,normal_z,point_i_x,point_i_y,point_i_z,point_j_x,point_j_y,point_j_z,area"
    )?;
    for (p, contacts) in per_pose.iter().enumerate() {
        for (k, c) in contacts.iter().enumerate() {
            let (n, pi, pj) = (c.normal_w, c.point_i_w, c.point_j_w);
            writeln!(
                out,
                "{p},{k},{},{},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?}",
                c.geometry_i,
                c.geometry_j,
                c.penetration,
                n.x,
                n.y,
                n.z,
                pi.x,
                pi.y,
                pi.z,
                pj.x,
                pj.y,
                pj.z,
                c.area
            )?;
        }
    }
    let w = s.work;
    writeln!(out, "# triangles prepared: {}", s.triangles)?;
    writeln!(
        out,
        "# prepare (tessellation + trees): {:.6} s",
        s.prepare_seconds
    )?;
    writeln!(
        out,
        "# median query: {:.3} us",
        s.median_query_seconds * 1e6
    )?;
    writeln!(
        out,
        "# work: queries {}, geometry pairs {}, box tests {}, triangle tests {}, contacts {}",
        w.queries, w.geometry_pairs, w.bounding_volume_tests, w.primitive_tests, w.contacts
    )?;
    if let Some((build, q, points)) = s.peer {
        writeln!(
            out,
            "# parry: tree build {build:.6} s, median query {:.3} us, {points} contact points at pose 0",
            q * 1e6
        )?;
    }
    Ok(())
}

fn json_vector(v: &[f64]) -> String {
    let items: Vec<String> = v.iter().map(|x| format!("{x:?}")).collect();
    format!("[{}]", items.join(","))
}

fn write_json(
    out: &mut dyn Write,
    poses: &[Isometry3],
    per_pose: &[Vec<Contact>],
    s: &Summary,
) -> Result<(), QueryCliError> {
    writeln!(out, "{{\"poses\":[")?;
    for (p, (pose, contacts)) in poses.iter().zip(per_pose).enumerate() {
        let items: Vec<String> = contacts
            .iter()
            .map(|c| {
                format!(
                    "{{\"geometry_i\":{},\"geometry_j\":{},\"penetration\":{:?},\"normal\":{},\"point_i\":{},\"point_j\":{},\"area\":{:?}}}",
                    c.geometry_i,
                    c.geometry_j,
                    c.penetration,
                    json_vector(c.normal_w.as_slice()),
                    json_vector(c.point_i_w.coords.as_slice()),
                    json_vector(c.point_j_w.coords.as_slice()),
                    c.area
                )
            })
            .collect();
        let comma = if p + 1 < poses.len() { "," } else { "" };
        writeln!(
            out,
            "{{\"pose\":\"{}\",\"contacts\":[{}]}}{comma}",
            contact_core::format_pose(pose),
            items.join(",")
        )?;
    }
    let w = s.work;
    write!(
        out,
        "],\"triangles\":{},\"prepare_seconds\":{:?},\"median_query_seconds\":{:?},\"work\":{{\"queries\":{},\"geometry_pairs\":{},\"bounding_volume_tests\":{},\"primitive_tests\":{},\"contacts\":{}}}",
        s.triangles,
        s.prepare_seconds,
        s.median_query_seconds,
        w.queries,
        w.geometry_pairs,
        w.bounding_volume_tests,
        w.primitive_tests,
        w.contacts
    )?;
    if let Some((build, q, points)) = s.peer {
        write!(
            out,
            ",\"parry\":{{\"build_seconds\":{build:?},\"median_query_seconds\":{q:?},\"points_at_pose_0\":{points}}}"
        )?;
    }
    writeln!(out, "}}")?;
    Ok(())
}

#[cfg(test)]
mod tests;
