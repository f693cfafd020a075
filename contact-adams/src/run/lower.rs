//! Lowering a validated [`Model`] onto the solver: parts at their centres of mass, markers,
//! joints and JPRIMs as constraints, MOTIONs on joints and marker pairs (given as a
//! displacement, or as a velocity or acceleration integrated by [`super::motion_level`]),
//! SFORCEs and CONTACTs as force elements.
//!
//! What the solver does not model yet is an error naming the statement and its `file:line:col`
//! (never dropped silently): massless parts, CONVEL/RACKPIN/SCREW joints, and expressions
//! reading element forces.

mod contacts;

use super::frames::{MarkerTable, PlacedMarker};
use super::motion_level::integrated_motion;
use super::sforce::SForceElement;
use crate::dataset::Origin;
use crate::expr::{Expr, TimeOnly};
use crate::model::{Freedom, JointKind, MeshFile, Model, MotionTarget, PrimitiveKind};
use crate::user_routines::{UserLaws, UserRoutineError, UserRoutines};
use contact_core::{GeometryEngine, GeometryInstance, Isometry3, Matrix3, PrepareError};
use contact_solver::contact_force::{Analysis, ContactForce};
use contact_solver::mbs::{
    ConstraintId, ConstraintKind, MarkerId, MarkerMotionAxis, MbsError, MotionDof,
    MultibodyBuilder, MultibodySystem, PartId, PartSpec, TimeFunction,
};
use contacts::ContactLowering;
use std::collections::BTreeMap;
use std::sync::Arc;

/// The model on the solver.
#[derive(Debug)]
pub struct LoweredModel {
    /// The multibody equations.
    pub system: MultibodySystem,
    /// The CONTACTs, in model order, shared with the system.
    pub contacts: Vec<Arc<ContactForce>>,
    /// `(solver part, Adams PART id)` for every moving part, in solver order.
    pub parts: Vec<(PartId, u32)>,
    /// Every marker on its solver part.
    pub markers: Arc<MarkerTable>,
}

/// Why a model cannot be run.
#[derive(Debug, thiserror::Error)]
pub enum LowerError {
    /// A statement the solver does not support (yet).
    #[error("{origin}: error: {message}")]
    Unsupported {
        /// Where the statement is.
        origin: Origin,
        /// What is not supported.
        message: String,
    },
    /// The multibody builder rejected an element.
    #[error("{origin}: error: {source}")]
    Element {
        /// Where the statement is.
        origin: Origin,
        /// The builder's error.
        source: Box<MbsError>,
    },
    /// The engine could not prepare a CONTACT.
    #[error("{origin}: error: CONTACT/{id}: {source}")]
    Prepare {
        /// Where the contact is.
        origin: Origin,
        /// Its id.
        id: u32,
        /// The engine's error.
        source: Box<PrepareError>,
    },
    /// A CONTACT's NORMAL_ROUTINE or FRICTION_ROUTINE could not be found.
    #[error("{origin}: error: CONTACT/{id}: {source}")]
    UserRoutine {
        /// Where the contact is.
        origin: Origin,
        /// Its id.
        id: u32,
        /// What was tried.
        source: Box<UserRoutineError>,
    },
    /// A mesh file could not be read.
    #[error("{origin}: error: {message}")]
    Mesh {
        /// Where the GRAPHICS is.
        origin: Origin,
        /// What went wrong, naming the file.
        message: String,
    },
    /// Assembling the system failed.
    #[error("the model's equations: {0}")]
    Build(Box<MbsError>),
}

/// Reads a mesh file into a geometry placed on its part (the faceted engine's STL reader).
pub type MeshLoader<'a> = &'a dyn Fn(&MeshFile) -> Result<GeometryInstance, String>;

fn element(origin: &Origin) -> impl Fn(MbsError) -> LowerError + '_ {
    move |source| LowerError::Element {
        origin: origin.clone(),
        source: Box::new(source),
    }
}

fn unsupported(origin: &Origin, message: impl Into<String>) -> LowerError {
    LowerError::Unsupported {
        origin: origin.clone(),
        message: message.into(),
    }
}

/// Lowers `model` with `engine` for its contacts, in `analysis` (which decides whether
/// DYNAMICS_ONLY friction acts). User force routines come from shared libraries
/// ([`lower_with_routines`] adds laws registered in code).
pub fn lower(
    model: &Model,
    engine: &dyn GeometryEngine,
    analysis: Analysis,
    meshes: MeshLoader<'_>,
) -> Result<LoweredModel, LowerError> {
    lower_with_routines(model, engine, analysis, meshes, &UserRoutines::default())
}

/// The user laws a CONTACT names, found in `routines` (or their libraries, relative to the
/// directory of the dataset the contact is in).
pub fn contact_user_laws(
    params: &contact_core::ContactParams,
    origin: &Origin,
    routines: &UserRoutines,
) -> Result<UserLaws, UserRoutineError> {
    let dir = origin
        .file
        .parent()
        .map_or_else(|| std::path::PathBuf::from("."), |d| d.to_path_buf());
    let normal = match &params.normal {
        contact_core::NormalModel::User(r) => Some(routines.normal(r, &dir)?),
        _ => None,
    };
    let friction = match &params.friction {
        contact_core::FrictionModel::User(r) => Some(routines.friction(r, &dir)?),
        _ => None,
    };
    Ok(UserLaws { normal, friction })
}

/// As [`lower`], with NORMAL_ROUTINE / FRICTION_ROUTINE laws looked up in `routines` first.
pub fn lower_with_routines(
    model: &Model,
    engine: &dyn GeometryEngine,
    analysis: Analysis,
    meshes: MeshLoader<'_>,
    routines: &UserRoutines,
) -> Result<LoweredModel, LowerError> {
    let mut builder = MultibodyBuilder::new(model.gravity);
    let (cm_of, parts) = add_parts(model, &mut builder)?;
    let (table, builder_markers) = add_markers(model, &mut builder, &cm_of)?;
    let joints = add_joints(model, &mut builder, &builder_markers)?;
    add_primitives(model, &mut builder, &builder_markers)?;
    add_gcons(model, &mut builder, &builder_markers)?;
    add_motions(model, &mut builder, &builder_markers, &joints)?;

    let table = Arc::new(table);
    add_sforces(model, &mut builder, &table, parts.len() + 1)?;

    let lowering = ContactLowering {
        engine,
        analysis,
        meshes,
        routines,
        cm_of: &cm_of,
    };
    let contacts = lowering.add_contacts(model, &mut builder)?;
    let system = builder
        .build()
        .map_err(|e| LowerError::Build(Box::new(e)))?;
    Ok(LoweredModel {
        system,
        contacts,
        parts,
        markers: table,
    })
}

/// Part frame → CM frame per Adams part id: the solver part and `X_P,CM` (for ground,
/// [`PartId::GROUND`] and the part's world pose).
type CmFrames = BTreeMap<u32, (PartId, Isometry3)>;

/// The solver's marker ids, per Adams MARKER id.
type BuilderMarkers = BTreeMap<u32, MarkerId>;

/// Adds every moving part at its centre of mass; returns the CM frame of every part (ground
/// included) and `(solver part, Adams PART id)` for the moving ones, in solver order. A part
/// with `MASS <= 0` (or NaN) is an error.
fn add_parts(
    model: &Model,
    builder: &mut MultibodyBuilder,
) -> Result<(CmFrames, Vec<(PartId, u32)>), LowerError> {
    // Part frame → CM frame, per Adams part id.
    let mut cm_of: BTreeMap<u32, (PartId, Isometry3)> = BTreeMap::new();
    let mut parts = Vec::new();
    for part in model.parts.values() {
        if part.ground {
            cm_of.insert(part.id, (PartId::GROUND, part.pose_world_part));
            continue;
        }
        if part.mass.is_nan() || part.mass <= 0.0 {
            return Err(unsupported(
                &part.origin,
                format!(
                    "PART/{}: massless parts (MASS = 0) are not supported by the solver",
                    part.id
                ),
            ));
        }
        let marker_pose = |id: Option<u32>| -> Isometry3 {
            id.and_then(|m| model.markers.get(&m))
                .map_or_else(Isometry3::identity, |m| m.pose_part_marker)
        };
        let pose_part_cm = marker_pose(part.cm);
        let pose_part_im = if part.im.is_some() {
            marker_pose(part.im)
        } else {
            pose_part_cm
        };
        let inertia_cm = inertia_at_cm(&part.inertia, part.mass, &pose_part_cm, &pose_part_im);
        let spec = PartSpec {
            name: format!("PART/{}", part.id),
            mass: part.mass,
            inertia_cm,
            pose_w: part.pose_world_part * pose_part_cm,
            velocity_w: part.velocity_w,
            angular_velocity_w: part.angular_velocity_w,
        };
        let id = builder.add_part(spec).map_err(element(&part.origin))?;
        cm_of.insert(part.id, (id, pose_part_cm));
        parts.push((id, part.id));
    }
    Ok((cm_of, parts))
}

/// Where a thing fixed on Adams part `p` at X_P,G sits on the solver part: X_CM,G (for
/// ground, the world pose); `None` if `p` is not a part of the model.
fn on_solver_part(
    cm_of: &CmFrames,
    p: u32,
    pose_part_thing: &Isometry3,
) -> Option<(PartId, Isometry3)> {
    let (id, pose) = cm_of.get(&p)?;
    Some(if id.is_ground() {
        (*id, pose * pose_part_thing)
    } else {
        (*id, pose.inverse() * pose_part_thing)
    })
}

/// Places every MARKER on its solver part: the table the measures read and the builder's
/// marker ids. A marker on an unknown part is an error.
fn add_markers(
    model: &Model,
    builder: &mut MultibodyBuilder,
    cm_of: &CmFrames,
) -> Result<(MarkerTable, BuilderMarkers), LowerError> {
    let mut table = MarkerTable::default();
    let mut builder_markers = BTreeMap::new();
    for m in model.markers.values() {
        let Some((part, pose_cm_marker)) = on_solver_part(cm_of, m.part, &m.pose_part_marker)
        else {
            return Err(unsupported(
                &m.origin,
                format!(
                    "MARKER/{}: PART/{} is not a part of the model",
                    m.id, m.part
                ),
            ));
        };
        table.markers.insert(
            m.id,
            PlacedMarker {
                part,
                pose_cm_marker,
            },
        );
        builder_markers.insert(
            m.id,
            builder
                .add_marker(part, pose_cm_marker)
                .map_err(element(&m.origin))?,
        );
    }
    Ok((table, builder_markers))
}

/// The builder's marker for MARKER `id`, or an error at `origin` if it is not defined.
fn marker(
    builder_markers: &BuilderMarkers,
    id: u32,
    origin: &Origin,
) -> Result<MarkerId, LowerError> {
    builder_markers
        .get(&id)
        .copied()
        .ok_or_else(|| unsupported(origin, format!("MARKER/{id} is not defined")))
}

/// Adds every JOINT as a constraint (RACKPIN with its PD); returns the constraint of each,
/// per JOINT id. CONVEL and SCREW joints are errors.
fn add_joints(
    model: &Model,
    builder: &mut MultibodyBuilder,
    markers: &BuilderMarkers,
) -> Result<BTreeMap<u32, ConstraintId>, LowerError> {
    let marker = |id: u32, origin: &Origin| marker(markers, id, origin);
    let mut joints: BTreeMap<u32, ConstraintId> = BTreeMap::new();
    for j in &model.joints {
        let kind = match j.kind {
            JointKind::Fixed => ConstraintKind::Fixed,
            JointKind::Revolute => ConstraintKind::Revolute,
            JointKind::Translational => ConstraintKind::Translational,
            JointKind::Cylindrical => ConstraintKind::Cylindrical,
            JointKind::Spherical => ConstraintKind::Spherical,
            JointKind::Planar => ConstraintKind::Planar,
            JointKind::Universal => ConstraintKind::Universal,
            JointKind::Hooke => ConstraintKind::Hooke,
            JointKind::Rackpin => {
                let (mi, mj) = (marker(j.i, &j.origin)?, marker(j.j, &j.origin)?);
                let pd = j.parameter.ok_or_else(|| {
                    unsupported(&j.origin, format!("JOINT/{}: RACKPIN needs PD", j.id))
                })?;
                let id = builder
                    .add_rackpin(format!("JOINT/{}", j.id), mi, mj, pd)
                    .map_err(element(&j.origin))?;
                joints.insert(j.id, id);
                continue;
            }
            JointKind::Convel | JointKind::Screw => {
                return Err(unsupported(
                    &j.origin,
                    format!(
                        "JOINT/{}: {:?} joints are not supported by the solver",
                        j.id, j.kind
                    ),
                ));
            }
        };
        let (mi, mj) = (marker(j.i, &j.origin)?, marker(j.j, &j.origin)?);
        let id = builder
            .add_constraint(format!("JOINT/{}", j.id), kind, mi, mj)
            .map_err(element(&j.origin))?;
        joints.insert(j.id, id);
    }
    Ok(joints)
}

/// Adds every JPRIM as a constraint between its markers.
fn add_primitives(
    model: &Model,
    builder: &mut MultibodyBuilder,
    markers: &BuilderMarkers,
) -> Result<(), LowerError> {
    let marker = |id: u32, origin: &Origin| marker(markers, id, origin);
    for p in &model.primitives {
        let kind = match p.kind {
            PrimitiveKind::Atpoint => ConstraintKind::AtPoint,
            PrimitiveKind::Inline => ConstraintKind::InLine,
            PrimitiveKind::Inplane => ConstraintKind::InPlane,
            PrimitiveKind::Orientation => ConstraintKind::Orientation,
            PrimitiveKind::ParallelAxes => ConstraintKind::ParallelAxes,
            PrimitiveKind::Perpendicular => ConstraintKind::Perpendicular,
        };
        let (mi, mj) = (marker(p.i, &p.origin)?, marker(p.j, &p.origin)?);
        builder
            .add_constraint(format!("JPRIM/{}", p.id), kind, mi, mj)
            .map_err(element(&p.origin))?;
    }
    Ok(())
}

/// Adds every GCON as a distance constraint between its markers.
fn add_gcons(
    model: &Model,
    builder: &mut MultibodyBuilder,
    markers: &BuilderMarkers,
) -> Result<(), LowerError> {
    let marker = |id: u32, origin: &Origin| marker(markers, id, origin);
    for g in &model.gcons {
        let (mi, mj) = (marker(g.i, &g.origin)?, marker(g.j, &g.origin)?);
        builder
            .add_distance(format!("GCON/{}", g.id), mi, mj, g.length)
            .map_err(element(&g.origin))?;
    }
    Ok(())
}

/// Adds every MOTION, on a joint's freedom or on an axis between two markers, its FUNCTION
/// (of TIME only, else an error) integrated to a displacement where it is given as a velocity
/// or an acceleration.
fn add_motions(
    model: &Model,
    builder: &mut MultibodyBuilder,
    markers: &BuilderMarkers,
    joints: &BTreeMap<u32, ConstraintId>,
) -> Result<(), LowerError> {
    let marker = |id: u32, origin: &Origin| marker(markers, id, origin);
    for m in &model.motions {
        if !m.function.is_time_only() {
            return Err(unsupported(
                &m.origin,
                format!("MOTION/{}: the FUNCTION must depend on TIME only", m.id),
            ));
        }
        let function = integrated_motion(
            m.function.clone(),
            m.level,
            m.ic_displacement.unwrap_or(0.0),
            m.ic_velocity.unwrap_or(0.0),
        )
        .unwrap_or_else(|| time_function(m.function.clone()));
        let (joint, freedom) = match m.target {
            MotionTarget::Joint { joint, freedom } => (joint, freedom),
            MotionTarget::Markers { i, j, axis } => {
                let axis = MarkerMotionAxis::from_index(axis).ok_or_else(|| {
                    unsupported(&m.origin, format!("MOTION/{}: no such axis {axis}", m.id))
                })?;
                let (mi, mj) = (marker(i, &m.origin)?, marker(j, &m.origin)?);
                builder
                    .add_marker_motion(format!("MOTION/{}", m.id), mi, mj, axis, function)
                    .map_err(element(&m.origin))?;
                continue;
            }
        };
        let target = *joints.get(&joint).ok_or_else(|| {
            unsupported(
                &m.origin,
                format!("MOTION/{}: JOINT/{joint} is not defined", m.id),
            )
        })?;
        let dof = match freedom {
            Freedom::Translational => MotionDof::Translational,
            Freedom::Rotational => MotionDof::Rotational,
        };
        builder
            .add_motion(format!("MOTION/{}", m.id), target, dof, function)
            .map_err(element(&m.origin))?;
    }
    Ok(())
}

/// Adds every SFORCE as a force element between its markers' parts, reading the model's
/// VARIABLEs; `part_count` counts ground. A FUNCTION reading an element's force is an error.
fn add_sforces(
    model: &Model,
    builder: &mut MultibodyBuilder,
    table: &Arc<MarkerTable>,
    part_count: usize,
) -> Result<(), LowerError> {
    let variables: Arc<BTreeMap<u32, Expr>> = Arc::new(
        model
            .variables
            .iter()
            .map(|v| (v.id, v.function.clone()))
            .collect(),
    );
    for s in &model.sforces {
        let mut uses_element_forces = false;
        s.function.walk(&mut |e| {
            uses_element_forces |= matches!(e, Expr::Element(..) | Expr::ForceMeasure(..))
        });
        if uses_element_forces {
            return Err(unsupported(
                &s.origin,
                format!(
                    "SFORCE/{}: FUNCTION reads an element's force (JOINT/MOTION/SFORCE, FX … TM): not supported by the solver",
                    s.id
                ),
            ));
        }
        let part_of = |id: u32| {
            table
                .markers
                .get(&id)
                .map(|m| m.part)
                .ok_or_else(|| unsupported(&s.origin, format!("MARKER/{id} is not defined")))
        };
        let element = SForceElement {
            name: format!("SFORCE/{}", s.id),
            parts: [part_of(s.i)?, part_of(s.j)?],
            markers: [s.i, s.j],
            freedom: s.freedom,
            action_only: s.action_only,
            function: s.function.clone(),
            table: table.clone(),
            variables: variables.clone(),
            part_count,
        };
        builder
            .add_force(Box::new(element))
            .map_err(element_error(&s.origin))?;
    }
    Ok(())
}

fn element_error(origin: &Origin) -> impl Fn(MbsError) -> LowerError + '_ {
    element(origin)
}

/// The inertia at the CM in CM axes, from the inertia given at IM in IM axes (parallel-axis
/// theorem, then a rotation of axes).
pub fn inertia_at_cm(
    inertia_im: &Matrix3,
    mass: f64,
    pose_part_cm: &Isometry3,
    pose_part_im: &Isometry3,
) -> Matrix3 {
    let cm_im = pose_part_cm.inverse() * pose_part_im;
    let r = cm_im.rotation.to_rotation_matrix().into_inner();
    let at_im_in_cm_axes = r * inertia_im * r.transpose();
    let d = cm_im.translation.vector;
    at_im_in_cm_axes - (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * mass
}

/// A MOTION's time function with its first two derivatives: those of its jet
/// ([`Expr::time_jet`], exact to round-off) where every function in it has a rule, else
/// central differences, `h = 1e-3·max(1, |t|)` for the first (error ~h²·f‴/6) and the second
/// (error ~h²·f⁗/12, round-off ~4ε|f|/h²), good to ~1e-6 relative for smooth functions of
/// order-1 time scale.
fn time_function(function: Expr) -> TimeFunction {
    Arc::new(move |t: f64| {
        if let Some(jet) = function.time_jet(t) {
            return (jet.value, jet.first, jet.second);
        }
        let f = |t: f64| function.eval(&TimeOnly(t)).unwrap_or(f64::NAN);
        let h = 1e-3 * t.abs().max(1.0);
        let (minus, here, plus) = (f(t - h), f(t), f(t + h));
        (
            here,
            (plus - minus) / (2.0 * h),
            (plus - 2.0 * here + minus) / (h * h),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inertia_moves_from_an_offset_rotated_marker_to_the_cm() {
        // A point-like 2 kg mass at the CM has zero inertia there; at a marker 0.5 away along
        // x it has m·d² about y and z.
        let at_im = Matrix3::new(0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.5);
        let cm = Isometry3::identity();
        let im = Isometry3::translation(0.5, 0.0, 0.0);
        let at_cm = inertia_at_cm(&at_im, 2.0, &cm, &im);
        assert!(at_cm.norm() < 1e-15, "{at_cm}");
        // A rotated IM: Ixx given about IM's x, which is CM's y.
        let rotated = Isometry3::rotation(contact_core::Vector3::z() * std::f64::consts::FRAC_PI_2);
        let diag = Matrix3::from_diagonal(&contact_core::Vector3::new(1.0, 2.0, 3.0));
        let at_cm = inertia_at_cm(&diag, 1.0, &cm, &rotated);
        assert!((at_cm[(1, 1)] - 1.0).abs() < 1e-12 && (at_cm[(0, 0)] - 2.0).abs() < 1e-12);
    }
}
