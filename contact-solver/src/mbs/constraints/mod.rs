//! Joints, JPRIMs and MOTIONs as algebraic constraints `Φ(q, t) = 0` with analytic Jacobians.
//!
//! Every constraint is a list of the scalar equations of [`primitives`] between a marker I
//! on one part and a marker J on another; one file per joint type gives that list. Jacobians
//! are analytic in world virtual displacements `(δr, θ)` of the two parts; the system maps them
//! to the body-frame rotations of the velocity Jacobian `Φ_v = [Φ_r, Φ_π′]` and to the
//! Euler-parameter Jacobian `Φ_e = Φ_π′ · 2G(e)/|e|²`.

mod atpoint;
mod cylindrical;
mod fixed;
mod hooke;
mod inline;
mod inplane;
mod orientation;
mod parallel_axes;
mod perpendicular;
mod planar;
pub(crate) mod primitives;
mod revolute;
mod spherical;
mod translational;
mod universal;

use super::part::PartId;
use nalgebra::{Isometry3, Vector3};
use primitives::{ElementFrames, Primitive, WorldGradient};

/// The joint and JPRIM types (SPEC §8). Each keeps marker I (on one part) in a relation to
/// marker J (on another part); the number of equations is [`ConstraintKind::equations`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ConstraintKind {
    /// JOINT FIXED: origins coincide, axes aligned (6).
    Fixed,
    /// JOINT REVOLUTE: origins coincide, z_I ∥ z_J; rotation about z free (5).
    Revolute,
    /// JOINT TRANSLATIONAL: axes aligned, I origin on the J z axis; translation along z free (5).
    Translational,
    /// JOINT CYLINDRICAL: z_I ∥ z_J, I origin on the J z axis (4).
    Cylindrical,
    /// JOINT SPHERICAL: origins coincide (3).
    Spherical,
    /// JOINT PLANAR: I origin in the J x-y plane, z_I ∥ z_J (3).
    Planar,
    /// JOINT UNIVERSAL: origins coincide, z_I ⊥ z_J (4).
    Universal,
    /// JOINT HOOKE: origins coincide, x_I ⊥ y_J (4).
    Hooke,
    /// JPRIM INPLANE: I origin in the J x-y plane (1).
    InPlane,
    /// JPRIM INLINE: I origin on the J z axis (2).
    InLine,
    /// JPRIM ORIENTATION: axes aligned (3).
    Orientation,
    /// JPRIM PARALLEL_AXES: z_I ∥ z_J (2).
    ParallelAxes,
    /// JPRIM PERPENDICULAR: z_I ⊥ z_J (1).
    Perpendicular,
    /// JPRIM ATPOINT: origins coincide (3).
    AtPoint,
}

impl ConstraintKind {
    /// Every kind, for tests and documentation tables.
    pub const ALL: [ConstraintKind; 14] = [
        Self::Fixed,
        Self::Revolute,
        Self::Translational,
        Self::Cylindrical,
        Self::Spherical,
        Self::Planar,
        Self::Universal,
        Self::Hooke,
        Self::InPlane,
        Self::InLine,
        Self::Orientation,
        Self::ParallelAxes,
        Self::Perpendicular,
        Self::AtPoint,
    ];

    /// The Adams keyword.
    pub fn keyword(self) -> &'static str {
        match self {
            Self::Fixed => "FIXED",
            Self::Revolute => "REVOLUTE",
            Self::Translational => "TRANSLATIONAL",
            Self::Cylindrical => "CYLINDRICAL",
            Self::Spherical => "SPHERICAL",
            Self::Planar => "PLANAR",
            Self::Universal => "UNIVERSAL",
            Self::Hooke => "HOOKE",
            Self::InPlane => "INPLANE",
            Self::InLine => "INLINE",
            Self::Orientation => "ORIENTATION",
            Self::ParallelAxes => "PARALLEL_AXES",
            Self::Perpendicular => "PERPENDICULAR",
            Self::AtPoint => "ATPOINT",
        }
    }

    /// The number of scalar equations (degrees of freedom removed).
    pub fn equations(self) -> usize {
        self.primitives().len()
    }

    pub(crate) fn primitives(self) -> Vec<Primitive> {
        match self {
            Self::Fixed => fixed::primitives(),
            Self::Revolute => revolute::primitives(),
            Self::Translational => translational::primitives(),
            Self::Cylindrical => cylindrical::primitives(),
            Self::Spherical => spherical::primitives(),
            Self::Planar => planar::primitives(),
            Self::Universal => universal::primitives(),
            Self::Hooke => hooke::primitives(),
            Self::InPlane => inplane::primitives(),
            Self::InLine => inline::primitives(),
            Self::Orientation => orientation::primitives(),
            Self::ParallelAxes => parallel_axes::primitives(),
            Self::Perpendicular => perpendicular::primitives(),
            Self::AtPoint => atpoint::primitives(),
        }
    }
}

/// One constraint element (a joint, JPRIM or MOTION) as the system evaluates it.
#[derive(Debug, Clone)]
pub(crate) struct ConstraintElement {
    /// The name in messages (`JOINT/3`, `MOTION/1`).
    pub name: String,
    /// The joint kind, `None` for a MOTION.
    pub kind: Option<ConstraintKind>,
    /// Part a (of marker I) and part b (of marker J).
    pub part_i: PartId,
    pub part_j: PartId,
    /// Marker poses in their parts' CM frames.
    pub marker_i: Isometry3<f64>,
    pub marker_j: Isometry3<f64>,
    /// The equations, in row order.
    pub primitives: Vec<Primitive>,
    /// The first row of this element in Φ (and λ).
    pub row: usize,
}

impl ConstraintElement {
    /// The marker geometry at part poses `pose_a` (of part I) and `pose_b` (of part J).
    pub fn frames(&self, pose_a: &Isometry3<f64>, pose_b: &Isometry3<f64>) -> ElementFrames {
        let s_i = pose_a.rotation * self.marker_i.translation.vector;
        let s_j = pose_b.rotation * self.marker_j.translation.vector;
        let d = pose_a.translation.vector + s_i - pose_b.translation.vector - s_j;
        let rot_i = pose_a.rotation * self.marker_i.rotation;
        let rot_j = pose_b.rotation * self.marker_j.rotation;
        let axes = |r: &nalgebra::UnitQuaternion<f64>| -> [Vector3<f64>; 3] {
            [r * Vector3::x(), r * Vector3::y(), r * Vector3::z()]
        };
        ElementFrames {
            s_i,
            s_j,
            d,
            axes_i: axes(&rot_i),
            axes_j: axes(&rot_j),
        }
    }

    /// The velocity-Jacobian row of one equation: `[∂/∂r_a, ∂/∂π′_a, ∂/∂r_b, ∂/∂π′_b]`, the
    /// rotations in each part's body frame (`∂/∂π′ = Aᵀ ∂/∂θ`).
    pub fn body_gradient(
        primitive: &Primitive,
        frames: &ElementFrames,
        pose_a: &Isometry3<f64>,
        pose_b: &Isometry3<f64>,
    ) -> WorldGradient {
        let [r_a, theta_a, r_b, theta_b] = primitive.gradient(frames);
        [
            r_a,
            pose_a.rotation.inverse_transform_vector(&theta_a),
            r_b,
            pose_b.rotation.inverse_transform_vector(&theta_b),
        ]
    }

    /// `Φ_vᵀ λ` of this element: the generalized constraint forces
    /// `[on r_a, on π′_a, on r_b, on π′_b]` for this element's multipliers `lambda`.
    pub fn generalized_reaction(
        &self,
        pose_a: &Isometry3<f64>,
        pose_b: &Isometry3<f64>,
        lambda: &[f64],
    ) -> WorldGradient {
        let frames = self.frames(pose_a, pose_b);
        let mut sum = [Vector3::zeros(); 4];
        for (primitive, &l) in self.primitives.iter().zip(lambda) {
            let gradient = Self::body_gradient(primitive, &frames, pose_a, pose_b);
            for (s, g) in sum.iter_mut().zip(gradient) {
                *s += g * l;
            }
        }
        sum
    }

    /// [`Self::generalized_reaction`] at the parts' `states`, this element's multipliers read
    /// from the whole multiplier vector `lambda_all` (its rows from `self.row`).
    pub fn generalized_reaction_in(
        &self,
        states: &[crate::mbs::PartState],
        lambda_all: nalgebra::DVectorView<'_, f64>,
    ) -> WorldGradient {
        let slice: Vec<f64> = lambda_all
            .rows(self.row, self.primitives.len())
            .iter()
            .copied()
            .collect();
        let (pose_a, pose_b) = (&states[self.part_i.0].pose_w, &states[self.part_j.0].pose_w);
        self.generalized_reaction(pose_a, pose_b, &slice)
    }

    /// `Φ_v v` of each equation (without `Φ_t`) at the poses, for part velocities
    /// `[[u_a, ω′_a], [u_b, ω′_b]]` (body-frame angular velocities).
    pub fn velocity_rates(
        &self,
        pose_a: &Isometry3<f64>,
        pose_b: &Isometry3<f64>,
        velocities: &[[Vector3<f64>; 2]; 2],
    ) -> Vec<f64> {
        let frames = self.frames(pose_a, pose_b);
        self.primitives
            .iter()
            .map(|primitive| {
                let g = Self::body_gradient(primitive, &frames, pose_a, pose_b);
                g[0].dot(&velocities[0][0])
                    + g[1].dot(&velocities[0][1])
                    + g[2].dot(&velocities[1][0])
                    + g[3].dot(&velocities[1][1])
            })
            .collect()
    }
}
