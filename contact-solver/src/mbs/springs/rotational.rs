//! A rotational spring-damper acting about the z axis of marker J.

use super::SpringParams;
use crate::dae::EvaluationError;
use crate::mbs::error::MbsError;
use crate::mbs::force::{ForceElement, Load, StateView};
use crate::mbs::part::PartId;
use nalgebra::{Isometry3, Vector3};

/// A torsion spring-damper between marker I on one part and marker J on another.
///
/// `θ = atan2(x_I·y_J, x_I·x_J)` is the rotation of x_I about z_J measured from x_J, in
/// (−π, π] (the principal value: this element does not count turns), `θ̇ = (ω_I − ω_J)·z_J`,
/// and the torque on I is `T·z_J` with `T = −k(θ − θ₀) − c·θ̇ + T₀`; J gets `−T·z_J`. It is meant
/// for markers whose z axes stay parallel (a revolute or cylindrical joint between them); when
/// x_I is parallel to z_J the angle is undefined and evaluation fails with an error naming the
/// element. Partials come from the system's element-local difference.
#[derive(Debug, Clone)]
pub struct RotationalSpringDamper {
    name: String,
    parts: [PartId; 2],
    marker_i: Isometry3<f64>,
    marker_j: Isometry3<f64>,
    params: SpringParams,
}

impl RotationalSpringDamper {
    /// A torsion spring between marker `marker_i` (pose in part `part_i`'s CM frame) and
    /// `marker_j` (in `part_j`'s); `params.free_length` is the free angle θ₀ in radians.
    pub fn new(
        name: impl Into<String>,
        part_i: PartId,
        marker_i: Isometry3<f64>,
        part_j: PartId,
        marker_j: Isometry3<f64>,
        params: SpringParams,
    ) -> Result<Self, MbsError> {
        let name = name.into();
        params.validate(&name, false)?;
        if part_i == part_j {
            return Err(MbsError::SamePart {
                element: name,
                part: part_i.0,
            });
        }
        Ok(Self {
            name,
            parts: [part_i, part_j],
            marker_i,
            marker_j,
            params,
        })
    }
}

impl ForceElement for RotationalSpringDamper {
    fn name(&self) -> &str {
        &self.name
    }

    fn parts(&self) -> &[PartId] {
        &self.parts
    }

    fn evaluate(
        &self,
        _t: f64,
        state: &StateView<'_>,
        loads: &mut [Load],
    ) -> Result<(), EvaluationError> {
        let (a, b) = (state.part(self.parts[0]), state.part(self.parts[1]));
        let rot_i = a.pose_w.rotation * self.marker_i.rotation;
        let rot_j = b.pose_w.rotation * self.marker_j.rotation;
        let x_i = rot_i * Vector3::x();
        let (x_j, y_j, z_j) = (
            rot_j * Vector3::x(),
            rot_j * Vector3::y(),
            rot_j * Vector3::z(),
        );
        let (sine, cosine) = (x_i.dot(&y_j), x_i.dot(&x_j));
        if sine.hypot(cosine) < 1e-9 {
            return Err(EvaluationError {
                element: self.name.clone(),
                message: "x_I is parallel to z_J: the rotation angle is undefined".to_owned(),
                fatal: false,
            });
        }
        let angle = sine.atan2(cosine);
        let rate = (a.angular_velocity_w - b.angular_velocity_w).dot(&z_j);
        let p = &self.params;
        let torque = -p.stiffness * (angle - p.free_length) - p.damping * rate + p.preload;
        loads[0] = Load {
            force_w: Vector3::zeros(),
            torque_w: z_j * torque,
        };
        loads[1] = Load {
            force_w: Vector3::zeros(),
            torque_w: -z_j * torque,
        };
        Ok(())
    }
}
