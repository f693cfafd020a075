//! The engine trait: prepare a CONTACT's geometry once, then query it at poses.
//!
//! ```text
//!   model check      engine.supports(i, j)?            → Unsupported is reported here
//!                    engine.supports_instances(i, j)?  → and what the instance adds (a flip)
//!   before the run   engine.prepare(&i_list, &j_list)? → Box<dyn PreparedPair>
//!   every step       pair.query(&X_WI, &X_WJ, &mut contacts, &mut work)?
//! ```
//! Queries take `&self` and no locks, so one prepared pair can be queried from many threads;
//! work counters and the contact buffer are the caller's, which keeps results deterministic.

use crate::{Contact, Geometry, GeometryInstance, GeometryKind, InvalidArgument, Isometry3};
use std::fmt::Debug;
use std::ops::AddAssign;
use thiserror::Error;

/// A geometry engine (exact or faceted). Object-safe: the application holds a
/// `Box<dyn GeometryEngine>` chosen once from PREFERENCES.
pub trait GeometryEngine: Send + Sync + Debug {
    /// The engine's name as reports print it (`"exact"`, `"faceted"`).
    fn name(&self) -> &'static str;

    /// Whether this engine can answer contact between `i` and `j` (in either order). Called
    /// when a model is checked, so an unsupported pair is an error before any run starts.
    fn supports(&self, i: &Geometry, j: &Geometry) -> Result<(), Unsupported>;

    /// Whether this engine can answer `i` against `j` as placed instances: [`Self::supports`]
    /// on their geometries, and what the instance adds (a flipped solid, the space outside
    /// it). Called when a model is checked, without preparing anything, so a refusal that
    /// [`Self::prepare`] would give is reported by the check too. The default sees the
    /// geometries only.
    fn supports_instances(
        &self,
        i: &GeometryInstance,
        j: &GeometryInstance,
    ) -> Result<(), PrepareError> {
        Ok(self.supports(&i.geometry, &j.geometry)?)
    }

    /// Prepares one CONTACT: its I list and J list (each list's geometries belong to one part).
    /// Only the geometry given here is processed (faceted, indexed): nothing else is built.
    fn prepare(
        &self,
        i: &[GeometryInstance],
        j: &[GeometryInstance],
    ) -> Result<Box<dyn PreparedPair>, PrepareError>;
}

/// A CONTACT's geometry, prepared for repeated queries.
pub trait PreparedPair: Send + Sync + Debug {
    /// Computes every contact between the I list at part pose `pose_world_i` (`X_WI`) and the J
    /// list at `pose_world_j` (`X_WJ`). Clears `contacts`, then pushes one [`Contact`] per
    /// intersection region of each (I geometry, J geometry) pair, in a deterministic order.
    /// Adds the work done to `work`.
    fn query(
        &self,
        pose_world_i: &Isometry3,
        pose_world_j: &Isometry3,
        contacts: &mut Vec<Contact>,
        work: &mut WorkCounters,
    ) -> Result<(), QueryError>;

    /// What preparation built: geometries, triangles, bytes.
    fn stats(&self) -> PreparedStats;
}

/// Which list of a CONTACT.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// The IGEOM list.
    I,
    /// The JGEOM list.
    J,
}

/// "This engine cannot answer this pair": a typed error, never "no contact".
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("the {engine} engine cannot compute contact between {i} and {j}: {reason}")]
pub struct Unsupported {
    /// The engine's name.
    pub engine: &'static str,
    /// Kind of the I geometry.
    pub i: GeometryKind,
    /// Kind of the J geometry.
    pub j: GeometryKind,
    /// Why, and what to do instead.
    pub reason: &'static str,
}

/// Why a CONTACT's geometry could not be prepared.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PrepareError {
    /// A pair the engine cannot answer.
    #[error(transparent)]
    Unsupported(#[from] Unsupported),
    /// An I or J list is empty.
    #[error("the {side:?} geometry list is empty")]
    EmptyList {
        /// Which list.
        side: Side,
    },
    /// A 2-D geometry faces a 3-D one (SPEC §3: not supported by CONTACT).
    #[error("cannot mix 2-D and 3-D geometry in one contact: {i} against {j}")]
    MixedDimensions {
        /// Kind of the I geometry.
        i: GeometryKind,
        /// Kind of the J geometry.
        j: GeometryKind,
    },
    /// A faceting tolerance would build more triangles than the engine allows for one geometry.
    #[error(
        "geometry '{label}' at faceting tolerance {tolerance} needs {requested} triangles, more than the limit {limit}; lower the tolerance"
    )]
    TooManyTriangles {
        /// The geometry's label.
        label: String,
        /// The tolerance in force.
        tolerance: f64,
        /// Triangles it would need.
        requested: u64,
        /// The engine's limit.
        limit: u64,
    },
    /// The faceted engine could not tessellate a geometry (its tessellation would not be a
    /// closed mesh in `f64`); the geometry is named, the other side of the pair is not involved.
    #[error(
        "geometry '{label}' ({kind}) cannot be tessellated: its size or proportions are beyond what the faceted engine resolves in f64; use the exact engine or rescale the model"
    )]
    NotTessellated {
        /// The geometry's label.
        label: String,
        /// Its kind.
        kind: GeometryKind,
    },
    /// A placement or setting is out of range.
    #[error("geometry '{label}': {source}")]
    InvalidArgument {
        /// The geometry's label.
        label: String,
        /// What was wrong.
        source: InvalidArgument,
    },
}

/// Why a query could not be answered. Each variant carries its reproducer.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum QueryError {
    /// A pose has NaN or infinite entries.
    #[error("the {side:?} pose is not finite: {pose}")]
    NonFinitePose {
        /// Which part.
        side: Side,
        /// The pose at round-trip precision.
        pose: String,
    },
    /// The two geometries of a 2-D contact are not in one plane (their z axes differ or their
    /// planes are apart by more than the tolerance).
    #[error(
        "2-D geometries {i} ('{label_i}') and {j} ('{label_j}') left their common plane: angle {angle_rad:e} rad, offset {offset:e}; poses X_WI = {pose_i}, X_WJ = {pose_j}"
    )]
    OutOfPlane {
        /// Kind of the I geometry.
        i: GeometryKind,
        /// Kind of the J geometry.
        j: GeometryKind,
        /// Label of the I geometry.
        label_i: String,
        /// Label of the J geometry.
        label_j: String,
        /// Angle between the two planes' normals.
        angle_rad: f64,
        /// Distance of I's plane origin from J's plane.
        offset: f64,
        /// `X_WI` at round-trip precision.
        pose_i: String,
        /// `X_WJ` at round-trip precision.
        pose_j: String,
    },
}

impl QueryError {
    /// Checks both poses are finite; the shared first step of every query. Inlined into each
    /// engine's query (it is a few multiplications on the closed forms' tens of nanoseconds);
    /// the error, which formats the pose, is built out of line.
    #[inline]
    pub fn check_poses(pose_world_i: &Isometry3, pose_world_j: &Isometry3) -> Result<(), Self> {
        if is_finite_pose(pose_world_i) && is_finite_pose(pose_world_j) {
            Ok(())
        } else {
            Err(Self::non_finite_pose(pose_world_i, pose_world_j))
        }
    }

    /// The error for the first of the two poses that is not finite.
    #[cold]
    #[inline(never)]
    fn non_finite_pose(pose_world_i: &Isometry3, pose_world_j: &Isometry3) -> Self {
        let (side, pose) = if is_finite_pose(pose_world_i) {
            (Side::J, pose_world_j)
        } else {
            (Side::I, pose_world_i)
        };
        Self::NonFinitePose {
            side,
            pose: format_pose(pose),
        }
    }
}

/// Whether all seven numbers of a pose are finite, without a branch per number: `x·0` is 0
/// for a finite `x` and NaN for an infinite or NaN one, so the sum of the seven products is
/// 0 exactly when all are finite (it runs on every query of every engine).
#[inline]
fn is_finite_pose(pose: &Isometry3) -> bool {
    let t = &pose.translation.vector;
    let q = &pose.rotation.coords;
    let zero =
        (t.x * 0.0 + t.y * 0.0 + t.z * 0.0) + (q.x * 0.0 + q.y * 0.0 + q.z * 0.0 + q.w * 0.0);
    zero == 0.0
}

/// A pose at round-trip precision: `x y z qw qx qy qz`, the order `contact query` reads.
pub fn format_pose(pose: &Isometry3) -> String {
    let t = pose.translation.vector;
    let q = pose.rotation.quaternion();
    format!(
        "{:?} {:?} {:?} {:?} {:?} {:?} {:?}",
        t.x, t.y, t.z, q.w, q.i, q.j, q.k
    )
}

/// Work done by queries, counted instead of timed: deterministic, so tests can assert on it and
/// reports can compare engines without a clock.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct WorkCounters {
    /// Queries answered.
    pub queries: u64,
    /// Geometry pairs (one I geometry against one J geometry) examined.
    pub geometry_pairs: u64,
    /// Bounding-volume overlap tests (box–box, sphere–sphere culling).
    pub bounding_volume_tests: u64,
    /// Primitive tests: triangle–triangle tests, or analytic pair evaluations.
    pub primitive_tests: u64,
    /// Iterations of iterative methods (Newton steps, bisections, quadrature nodes).
    pub iterations: u64,
    /// Contacts returned.
    pub contacts: u64,
}

impl AddAssign for WorkCounters {
    fn add_assign(&mut self, o: Self) {
        self.queries += o.queries;
        self.geometry_pairs += o.geometry_pairs;
        self.bounding_volume_tests += o.bounding_volume_tests;
        self.primitive_tests += o.primitive_tests;
        self.iterations += o.iterations;
        self.contacts += o.contacts;
    }
}

/// What [`GeometryEngine::prepare`] built for one CONTACT.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PreparedStats {
    /// Geometries prepared (I list + J list).
    pub geometries: usize,
    /// Triangles held (built by tessellation or read from meshes).
    pub triangles: usize,
    /// Heap bytes held by the prepared data.
    pub bytes: usize,
}

/// Checks the lists of a CONTACT are non-empty and of one dimension, and every pair is
/// supported; engines call this first in `prepare`.
pub fn check_lists(
    engine: &dyn GeometryEngine,
    i: &[GeometryInstance],
    j: &[GeometryInstance],
) -> Result<(), PrepareError> {
    if i.is_empty() {
        return Err(PrepareError::EmptyList { side: Side::I });
    }
    if j.is_empty() {
        return Err(PrepareError::EmptyList { side: Side::J });
    }
    for gi in i {
        for gj in j {
            let (ki, kj) = (gi.geometry.kind(), gj.geometry.kind());
            if ki.is_planar() != kj.is_planar() {
                return Err(PrepareError::MixedDimensions { i: ki, j: kj });
            }
            engine.supports(&gi.geometry, &gj.geometry)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Quaternion, Translation3, UnitQuaternion};

    #[test]
    fn a_pose_is_refused_when_any_of_its_seven_numbers_is_not_finite() {
        let good = [1e300, -2.5, 3.0, 0.5, 0.5, 0.5, 0.5];
        let pose = |v: [f64; 7]| {
            Isometry3::from_parts(
                Translation3::new(v[0], v[1], v[2]),
                UnitQuaternion::new_unchecked(Quaternion::new(v[3], v[4], v[5], v[6])),
            )
        };
        let id = Isometry3::identity();
        assert!(QueryError::check_poses(&pose(good), &pose(good)).is_ok());
        for k in 0..7 {
            for bad in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
                let mut v = good;
                v[k] = bad;
                let on_i = QueryError::check_poses(&pose(v), &id);
                assert!(
                    matches!(on_i, Err(QueryError::NonFinitePose { side: Side::I, .. })),
                    "{k} {bad}"
                );
                let on_j = QueryError::check_poses(&id, &pose(v));
                assert!(
                    matches!(on_j, Err(QueryError::NonFinitePose { side: Side::J, .. })),
                    "{k} {bad}"
                );
            }
        }
    }
}
