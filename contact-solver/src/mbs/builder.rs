//! Building a [`MultibodySystem`] in code (the dataset lowering calls the same methods).

use super::constraints::primitives::{Axis, Primitive};
use super::constraints::{ConstraintElement, ConstraintKind};
use super::error::MbsError;
use super::force::ForceElement;
use super::layout::{Formulation, StateLayout};
use super::motion::{MarkerMotionAxis, MotionDof, TimeFunction};
use super::part::{Marker, MarkerId, PartId, PartSpec};
use super::quaternion::parameters_of;
use super::system::{MultibodySystem, PartData};
use nalgebra::{DVector, Isometry3, Matrix3, Rotation3, UnitQuaternion, Vector3};

/// A constraint's index in the builder (joints, JPRIMs and MOTIONs, in the order added).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ConstraintId(pub usize);

/// Collects parts, markers, constraints and forces, checks each as it comes, and builds the
/// system.
pub struct MultibodyBuilder {
    gravity_w: Vector3<f64>,
    parts: Vec<PartSpec>,
    markers: Vec<Marker>,
    constraints: Vec<ConstraintElement>,
    forces: Vec<Box<dyn ForceElement>>,
    length_scale: Option<f64>,
    formulation: Formulation,
}

impl MultibodyBuilder {
    /// An empty model with gravitational acceleration `gravity_w` (world frame, model units;
    /// `ACCGRAV`). Non-finite gravity is reported by [`Self::build`].
    pub fn new(gravity_w: Vector3<f64>) -> Self {
        Self {
            gravity_w,
            parts: Vec::new(),
            markers: Vec::new(),
            constraints: Vec::new(),
            forces: Vec::new(),
            length_scale: None,
            formulation: Formulation::I3,
        }
    }

    /// Adds a moving part (checked by [`PartSpec`]'s rules); ids count from 1.
    pub fn add_part(&mut self, spec: PartSpec) -> Result<PartId, MbsError> {
        spec.validate()?;
        self.parts.push(spec);
        Ok(PartId(self.parts.len()))
    }

    fn check_part(&self, element: &str, part: PartId) -> Result<(), MbsError> {
        if part.0 > self.parts.len() {
            return Err(MbsError::UnknownPart {
                element: element.to_owned(),
                id: part.0,
                last: self.parts.len(),
            });
        }
        Ok(())
    }

    /// Adds a marker: a frame with pose `pose_pm` in the part's CM frame (ground: world).
    pub fn add_marker(
        &mut self,
        part: PartId,
        pose_pm: Isometry3<f64>,
    ) -> Result<MarkerId, MbsError> {
        let element = format!("MARKER/{}", self.markers.len());
        self.check_part(&element, part)?;
        let finite = pose_pm.translation.vector.iter().all(|x| x.is_finite())
            && pose_pm.rotation.coords.iter().all(|x| x.is_finite());
        if !finite {
            return Err(MbsError::invalid(
                &element,
                "POSITION",
                pose_pm.translation.vector.norm(),
                "finite",
            ));
        }
        self.markers.push(Marker { part, pose_pm });
        Ok(MarkerId(self.markers.len() - 1))
    }

    /// The part and in-part pose of a marker.
    pub fn marker(&self, id: MarkerId) -> Result<(PartId, Isometry3<f64>), MbsError> {
        self.markers
            .get(id.0)
            .map(|m| (m.part, m.pose_pm))
            .ok_or(MbsError::UnknownMarker {
                element: format!("MARKER/{}", id.0),
                id: id.0,
                count: self.markers.len(),
            })
    }

    /// Adds a joint or JPRIM of `kind` between marker I and marker J (on different parts).
    pub fn add_constraint(
        &mut self,
        name: impl Into<String>,
        kind: ConstraintKind,
        marker_i: MarkerId,
        marker_j: MarkerId,
    ) -> Result<ConstraintId, MbsError> {
        let name = name.into();
        let lookup = |id: MarkerId| {
            self.marker(id).map_err(|error| match error {
                MbsError::UnknownMarker { id, count, .. } => MbsError::UnknownMarker {
                    element: name.clone(),
                    id,
                    count,
                },
                other => other,
            })
        };
        let (part_i, pose_i) = lookup(marker_i)?;
        let (part_j, pose_j) = lookup(marker_j)?;
        if part_i == part_j {
            return Err(MbsError::SamePart {
                element: name,
                part: part_i.0,
            });
        }
        self.constraints.push(ConstraintElement {
            name,
            kind: Some(kind),
            part_i,
            part_j,
            marker_i: pose_i,
            marker_j: pose_j,
            primitives: kind.primitives(),
            row: 0,
        });
        Ok(ConstraintId(self.constraints.len() - 1))
    }

    /// Adds a distance constraint `|p_I − p_J| − length = 0` between the origins of marker I
    /// and marker J (on different parts): Adams' `GCON, FUNCTION = DM(i, j) − L`. One equation;
    /// `length` must be finite and > 0 (at zero distance the direction, and so the Jacobian,
    /// is undefined).
    pub fn add_distance(
        &mut self,
        name: impl Into<String>,
        marker_i: MarkerId,
        marker_j: MarkerId,
        length: f64,
    ) -> Result<ConstraintId, MbsError> {
        let name = name.into();
        if !(length.is_finite() && length > 0.0) {
            return Err(MbsError::InvalidArgument {
                element: name,
                argument: "distance",
                value: format!("{length:?}"),
                allowed: "finite and > 0",
            });
        }
        let id = self.add_constraint(name, ConstraintKind::AtPoint, marker_i, marker_j)?;
        let element = &mut self.constraints[id.0];
        element.kind = None;
        element.primitives = vec![Primitive::Distance { length }];
        Ok(id)
    }

    /// Adds a RACKPIN between marker I (the pinion, z_I its axis) and marker J (the rack, z_J
    /// its direction of travel) with pitch diameter `pitch_diameter` (finite, > 0): one
    /// equation, the rack's travel along z_J equal to PD/2 times the pinion's rotation about
    /// z_I, zero where x_I points along z_J (Adams' convention).
    pub fn add_rackpin(
        &mut self,
        name: impl Into<String>,
        marker_i: MarkerId,
        marker_j: MarkerId,
        pitch_diameter: f64,
    ) -> Result<ConstraintId, MbsError> {
        let name = name.into();
        if !(pitch_diameter.is_finite() && pitch_diameter > 0.0) {
            return Err(MbsError::InvalidArgument {
                element: name,
                argument: "PD",
                value: format!("{pitch_diameter:?}"),
                allowed: "finite and > 0",
            });
        }
        let id = self.add_constraint(name, ConstraintKind::AtPoint, marker_i, marker_j)?;
        let element = &mut self.constraints[id.0];
        element.kind = None;
        element.primitives = vec![Primitive::RackPin {
            radius: 0.5 * pitch_diameter,
        }];
        Ok(id)
    }

    /// Adds a MOTION driving `dof` of `joint` with `function` (see [`MotionDof`] for the measure
    /// and the joints allowed).
    pub fn add_motion(
        &mut self,
        name: impl Into<String>,
        joint: ConstraintId,
        dof: MotionDof,
        function: TimeFunction,
    ) -> Result<ConstraintId, MbsError> {
        let name = name.into();
        let Some(target) = self.constraints.get(joint.0) else {
            return Err(MbsError::UnknownConstraint {
                element: name,
                id: joint.0,
                count: self.constraints.len(),
            });
        };
        let (allowed, dof_name, primitive) = match dof {
            MotionDof::Translational => (
                [ConstraintKind::Translational, ConstraintKind::Cylindrical],
                "translational",
                Primitive::InPlane {
                    normal_j: Axis::Z,
                    drive: Some(function),
                },
            ),
            MotionDof::Rotational => (
                [ConstraintKind::Revolute, ConstraintKind::Cylindrical],
                "rotational",
                Primitive::Angle { drive: function },
            ),
        };
        let kind = target.kind;
        if !kind.is_some_and(|k| allowed.contains(&k)) {
            return Err(MbsError::MotionOnWrongJoint {
                motion: name,
                joint: target.name.clone(),
                kind: kind.map_or("a MOTION", ConstraintKind::keyword),
                dof: dof_name,
                allowed: if dof == MotionDof::Translational {
                    "TRANSLATIONAL or CYLINDRICAL"
                } else {
                    "REVOLUTE or CYLINDRICAL"
                },
            });
        }
        let motion = ConstraintElement {
            name,
            kind: None,
            primitives: vec![primitive],
            ..target.clone()
        };
        self.constraints.push(motion);
        Ok(ConstraintId(self.constraints.len() - 1))
    }

    /// Adds a MOTION between marker I and marker J (on different parts) driving `axis` (see
    /// [`MarkerMotionAxis`] for the measure) with `function`.
    pub fn add_marker_motion(
        &mut self,
        name: impl Into<String>,
        marker_i: MarkerId,
        marker_j: MarkerId,
        axis: MarkerMotionAxis,
        function: TimeFunction,
    ) -> Result<ConstraintId, MbsError> {
        let name = name.into();
        let (part_i, pose_i) = self.marker(marker_i)?;
        let (part_j, pose_j) = self.marker(marker_j)?;
        if part_i == part_j {
            return Err(MbsError::SamePart {
                element: name,
                part: part_i.0,
            });
        }
        // Rotations about x or y: both frames turned so that axis is their z and the angle
        // primitive (x about z) measures the cyclically next axis about it.
        let cyclic = |columns: [Vector3<f64>; 3]| {
            UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(
                Matrix3::from_columns(&columns),
            ))
        };
        let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
        let (primitive, turn) = match axis {
            MarkerMotionAxis::X | MarkerMotionAxis::Y | MarkerMotionAxis::Z => (
                Primitive::InPlane {
                    normal_j: match axis {
                        MarkerMotionAxis::X => Axis::X,
                        MarkerMotionAxis::Y => Axis::Y,
                        _ => Axis::Z,
                    },
                    drive: Some(function),
                },
                UnitQuaternion::identity(),
            ),
            MarkerMotionAxis::B1 => (Primitive::Angle { drive: function }, cyclic([y, z, x])),
            MarkerMotionAxis::B2 => (Primitive::Angle { drive: function }, cyclic([z, x, y])),
            MarkerMotionAxis::B3 => (
                Primitive::Angle { drive: function },
                UnitQuaternion::identity(),
            ),
        };
        let turned =
            |pose: Isometry3<f64>| Isometry3::from_parts(pose.translation, pose.rotation * turn);
        self.constraints.push(ConstraintElement {
            name,
            kind: None,
            part_i,
            part_j,
            marker_i: turned(pose_i),
            marker_j: turned(pose_j),
            primitives: vec![primitive],
            row: 0,
        });
        Ok(ConstraintId(self.constraints.len() - 1))
    }

    /// Adds a force element after checking the parts it names exist and are distinct.
    pub fn add_force(&mut self, element: Box<dyn ForceElement>) -> Result<(), MbsError> {
        for (k, &part) in element.parts().iter().enumerate() {
            self.check_part(element.name(), part)?;
            if element.parts()[..k].contains(&part) {
                return Err(MbsError::SamePart {
                    element: element.name().to_owned(),
                    part: part.0,
                });
            }
        }
        self.forces.push(element);
        Ok(())
    }

    /// Chooses how constraints enter the DAE (default [`Formulation::I3`]).
    pub fn set_formulation(&mut self, formulation: Formulation) {
        self.formulation = formulation;
    }

    /// Sets the model's length scale `L` (> 0, finite) instead of deriving it (see
    /// [`Self::build`]).
    pub fn set_length_scale(&mut self, length: f64) -> Result<(), MbsError> {
        if !(length.is_finite() && length > 0.0) {
            return Err(MbsError::invalid(
                "MODEL",
                "LENGTH_SCALE",
                length,
                "finite and > 0",
            ));
        }
        self.length_scale = Some(length);
        Ok(())
    }

    /// The derived length scale: the largest of the marker offsets from their CMs and the
    /// distances of the part CMs from their mean; 1 (model unit) when all of those are zero
    /// (every point of the model at one place — nothing has a size to be relative to).
    fn derived_length_scale(&self) -> f64 {
        let offsets = self
            .markers
            .iter()
            .map(|m| m.pose_pm.translation.vector.norm());
        let centres: Vec<Vector3<f64>> = self
            .parts
            .iter()
            .map(|p| p.pose_w.translation.vector)
            .collect();
        let mean = centres.iter().sum::<Vector3<f64>>() / (centres.len().max(1) as f64);
        let spread = centres.iter().map(|c| (c - mean).norm());
        let scale = offsets.chain(spread).fold(0.0, f64::max);
        if scale > 0.0 { scale } else { 1.0 }
    }

    /// Checks gravity, numbers the constraint rows, and builds the system with the initial
    /// positions and velocities as given (see [`MultibodySystem::compute_initial_state`] to
    /// make them consistent).
    pub fn build(self) -> Result<MultibodySystem, MbsError> {
        if !self.gravity_w.iter().all(|g| g.is_finite()) {
            return Err(MbsError::invalid(
                "ACCGRAV",
                "gravity",
                self.gravity_w.norm(),
                "finite",
            ));
        }
        let length_scale = self
            .length_scale
            .unwrap_or_else(|| self.derived_length_scale());
        let mut constraints = self.constraints;
        let mut rows = 0;
        for element in &mut constraints {
            element.row = rows;
            rows += element.primitives.len();
        }
        let layout = StateLayout::new(self.parts.len(), rows, self.formulation);
        let mut initial_y = DVector::zeros(layout.size());
        for (k, spec) in self.parts.iter().enumerate() {
            let part = PartId(k + 1);
            let (qo, vo) = (layout.position_offset(part), layout.velocity_offset(part));
            initial_y
                .fixed_rows_mut::<3>(qo)
                .copy_from(&spec.pose_w.translation.vector);
            // Renormalized: a quaternion built unchecked may be off the unit sphere.
            let rotation = UnitQuaternion::new_normalize(spec.pose_w.rotation.into_inner());
            initial_y
                .fixed_rows_mut::<4>(qo + 3)
                .copy_from(&parameters_of(&rotation));
            initial_y
                .fixed_rows_mut::<3>(vo)
                .copy_from(&spec.velocity_w);
            let omega_body = spec
                .pose_w
                .rotation
                .inverse_transform_vector(&spec.angular_velocity_w);
            initial_y.fixed_rows_mut::<3>(vo + 3).copy_from(&omega_body);
        }
        let parts = self
            .parts
            .into_iter()
            .map(|spec| PartData {
                name: spec.name,
                mass: spec.mass,
                inertia: spec.inertia_cm,
            })
            .collect();
        let mut system = MultibodySystem {
            parts,
            constraints,
            broad_phase: crate::broad_phase::BroadPhase::new(&self.forces),
            step_trackers: (self.forces.iter().enumerate())
                .filter(|(_, e)| e.tracks_steps())
                .map(|(k, _)| k)
                .collect(),
            forces: self.forces,
            parallelism: crate::parallel::Parallelism::serial(),
            force_partials: super::force::ForcePartials::default(),
            output_dynamics: false,
            newton_storage: None,
            gravity_w: self.gravity_w,
            layout,
            length_scale,
            initial_y,
            redundant: Vec::new(),
        };
        system.remove_redundant_equations()?;
        Ok(system)
    }
}
