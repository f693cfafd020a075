//! Parts and markers: what the builder takes and what the system keeps.

use super::error::MbsError;
use nalgebra::{Isometry3, Matrix3, Vector3};

/// A part's index in the system; [`PartId::GROUND`] is the fixed ground, parts added by the
/// builder are numbered from 1 in the order they were added.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PartId(pub usize);

impl PartId {
    /// The ground part: fixed at the world frame, not in the state vector.
    pub const GROUND: PartId = PartId(0);

    /// Whether this is the ground.
    pub fn is_ground(self) -> bool {
        self.0 == 0
    }
}

/// A marker's index in the system (in the order markers were added, from 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct MarkerId(pub usize);

/// A rigid part as the builder takes it.
///
/// The part frame is its centre-of-mass frame: `pose_w` places the CM and the axes in which
/// `inertia_cm` is given. (The dataset lowering converts Adams' part frame + CM marker to this.)
#[derive(Debug, Clone, PartialEq)]
pub struct PartSpec {
    /// The name used in messages (e.g. `PART/2`).
    pub name: String,
    /// Mass, `> 0`.
    pub mass: f64,
    /// Inertia tensor about the CM in the part frame: symmetric positive definite.
    pub inertia_cm: Matrix3<f64>,
    /// Initial pose of the part (CM) frame in the world.
    pub pose_w: Isometry3<f64>,
    /// Initial velocity of the CM, world frame.
    pub velocity_w: Vector3<f64>,
    /// Initial angular velocity, world frame.
    pub angular_velocity_w: Vector3<f64>,
}

impl PartSpec {
    /// A part at rest at `pose_w`.
    pub fn at_rest(
        name: impl Into<String>,
        mass: f64,
        inertia_cm: Matrix3<f64>,
        pose_w: Isometry3<f64>,
    ) -> Self {
        Self {
            name: name.into(),
            mass,
            inertia_cm,
            pose_w,
            velocity_w: Vector3::zeros(),
            angular_velocity_w: Vector3::zeros(),
        }
    }

    /// Checks mass, inertia and initial state: mass finite and `> 0`; inertia finite, symmetric
    /// to 1e-12 of its largest entry and positive definite (Cholesky succeeds); position and
    /// velocities finite; orientation quaternion finite and nonzero (it is renormalized).
    pub(crate) fn validate(&self) -> Result<(), MbsError> {
        let name = self.name.as_str();
        if !(self.mass.is_finite() && self.mass > 0.0) {
            return Err(MbsError::invalid(name, "MASS", self.mass, "finite and > 0"));
        }
        let inertia = &self.inertia_cm;
        let largest = inertia.amax();
        let asymmetry = (inertia - inertia.transpose()).amax();
        if !largest.is_finite() || asymmetry > 1e-12 * largest {
            return Err(MbsError::invalid(
                name,
                "INERTIA (largest asymmetry)",
                asymmetry,
                "finite and symmetric to 1e-12 of the largest entry",
            ));
        }
        if inertia.cholesky().is_none() {
            return Err(MbsError::invalid(
                name,
                "INERTIA (smallest eigenvalue)",
                inertia.symmetric_eigenvalues().min(),
                "> 0 (positive definite)",
            ));
        }
        let finite = |v: &Vector3<f64>| v.iter().all(|x| x.is_finite());
        let rotation = self.pose_w.rotation.quaternion().coords;
        if !finite(&self.pose_w.translation.vector) {
            let norm = self.pose_w.translation.vector.norm();
            return Err(MbsError::invalid(name, "POSITION (norm)", norm, "finite"));
        }
        let rotation_norm = rotation.norm();
        if !(rotation_norm.is_finite() && rotation_norm > 0.0) {
            return Err(MbsError::invalid(
                name,
                "ORIENTATION (quaternion norm)",
                rotation_norm,
                "finite and > 0",
            ));
        }
        if !finite(&self.velocity_w) {
            return Err(MbsError::invalid(
                name,
                "VELOCITY",
                self.velocity_w.norm(),
                "finite",
            ));
        }
        if !finite(&self.angular_velocity_w) {
            return Err(MbsError::invalid(
                name,
                "ANGULAR_VELOCITY",
                self.angular_velocity_w.norm(),
                "finite",
            ));
        }
        Ok(())
    }
}

/// A marker: a frame fixed on a part.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Marker {
    /// The part it is on.
    pub part: PartId,
    /// Its pose in the part (CM) frame.
    pub pose_pm: Isometry3<f64>,
}
