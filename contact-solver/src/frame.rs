//! Output frames from a state, and a state handed from one analysis to the next.

use super::EvaluationError;
use super::contact_force::ContactForce;
use super::mbs::quaternion::parameters_of;
use super::mbs::{MultibodySystem, PartState, StateView};
use super::simulate::Frame;
use nalgebra::{DVector, Vector3};
use std::sync::Arc;

/// What an output frame adds when accelerations and reactions are asked for
/// ([`MultibodySystem::set_output_dynamics`]): the solution of
/// `[M Φ_vᵀ; Φ_v 0] [v̇; λ] = [Q − ω′×Jω′; γ]` at the frame's state, so the values are those of
/// the equations of motion at that state (not differences of the integrator's history).
#[derive(Debug, Clone, PartialEq)]
pub struct FrameDynamics {
    /// Per part id (ground first, zero): the CM acceleration and the angular acceleration
    /// `R ω̇′`, both in world axes.
    pub accelerations: Vec<(Vector3<f64>, Vector3<f64>)>,
    /// Per constraint element, in the order of [`MultibodySystem::constraint_rows`]: its
    /// reaction on each of its two parts.
    pub reactions: Vec<ElementReaction>,
}

/// The reaction of one joint, JPRIM, MOTION or distance constraint: `−Φ_vᵀλ` of its own rows,
/// as the force and torque it applies to the part of its I marker and to the part of its J
/// marker (world axes; each torque taken about that marker's origin). The two are equal and
/// opposite when the markers coincide.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ElementReaction {
    /// Force on the I marker's part.
    pub force_i_w: Vector3<f64>,
    /// Torque on the I marker's part about the I marker's origin.
    pub torque_i_w: Vector3<f64>,
    /// Force on the J marker's part.
    pub force_j_w: Vector3<f64>,
    /// Torque on the J marker's part about the J marker's origin.
    pub torque_j_w: Vector3<f64>,
}

/// The output frame at time `t` and state `y`: every part's state and every CONTACT's
/// kinematics and forces.
pub fn compute_frame(
    system: &MultibodySystem,
    contacts: &[Arc<ContactForce>],
    t: f64,
    y: &DVector<f64>,
) -> Result<Frame, EvaluationError> {
    let parts = system.part_states(y)?;
    let view = StateView::new(&parts);
    let contacts = contacts
        .iter()
        .map(|c| c.reports(t, &view))
        .collect::<Result<_, _>>()?;
    let dynamics = if system.output_dynamics {
        Some(system.frame_dynamics(t, y)?)
    } else {
        None
    };
    Ok(Frame {
        t,
        parts,
        contacts,
        dynamics,
    })
}

impl MultibodySystem {
    /// Makes every output frame carry [`FrameDynamics`] (one linear solve per output frame,
    /// none per integrator step). Off by default.
    pub fn set_output_dynamics(&mut self, on: bool) {
        self.output_dynamics = on;
    }

    /// Whether output frames carry [`FrameDynamics`].
    pub fn output_dynamics(&self) -> bool {
        self.output_dynamics
    }

    /// The accelerations and constraint reactions at time `t` and state `y` (positions and
    /// velocities; the multipliers in `y` are not read but solved for). The error names the
    /// constraints when they are singular at this state.
    pub fn frame_dynamics(
        &self,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<FrameDynamics, EvaluationError> {
        let failed = |e: super::mbs::MbsError| EvaluationError {
            element: "accelerations and reactions".into(),
            message: e.to_string(),
            fatal: false,
        };
        let (vdot, lambda) = self
            .compute_accelerations_and_multipliers(t, y)
            .map_err(failed)?;
        let states = self.part_states(y)?;
        let mut accelerations = vec![(Vector3::zeros(), Vector3::zeros())];
        for k in 0..self.parts.len() {
            let rotation = states[k + 1].pose_w.rotation;
            accelerations.push((
                vdot.fixed_rows::<3>(6 * k).into_owned(),
                rotation * vdot.fixed_rows::<3>(6 * k + 3).into_owned(),
            ));
        }
        let reactions = self
            .constraints
            .iter()
            .map(|element| {
                let (pose_a, pose_b) = (
                    &states[element.part_i.0].pose_w,
                    &states[element.part_j.0].pose_w,
                );
                let g = element.generalized_reaction_in(&states, lambda.as_view());
                let frames = element.frames(pose_a, pose_b);
                // −Φ_vᵀλ: the force at the CM and the body torque about it, the torque moved
                // to the marker origin `r + s`: τ_p = τ_cm + (r − p) × f = τ_cm − s × f.
                let (force_i, force_j) = (-g[0], -g[2]);
                ElementReaction {
                    force_i_w: force_i,
                    torque_i_w: -(pose_a.rotation * g[1]) - frames.s_i.cross(&force_i),
                    force_j_w: force_j,
                    torque_j_w: -(pose_b.rotation * g[3]) - frames.s_j.cross(&force_j),
                }
            })
            .collect();
        Ok(FrameDynamics {
            accelerations,
            reactions,
        })
    }

    /// Makes `parts` (indexed by part id, ground first, as in a [`Frame`]) the start of the
    /// next analysis: positions, orientations and velocities; the next analysis assembles and
    /// makes them consistent. `parts` must come from a system with the same parts.
    pub fn start_from(&mut self, parts: &[PartState]) {
        let layout = self.layout;
        for (part, state) in self.moving_parts().zip(parts.iter().skip(1)) {
            let (qo, vo) = (layout.position_offset(part), layout.velocity_offset(part));
            let y = &mut self.initial_y;
            y.fixed_rows_mut::<3>(qo)
                .copy_from(&state.pose_w.translation.vector);
            y.fixed_rows_mut::<4>(qo + 3)
                .copy_from(&parameters_of(&state.pose_w.rotation));
            y.fixed_rows_mut::<3>(vo).copy_from(&state.velocity_w);
            y.fixed_rows_mut::<3>(vo + 3).copy_from(
                &state
                    .pose_w
                    .rotation
                    .inverse_transform_vector(&state.angular_velocity_w),
            );
        }
    }

    /// The builder's (or [`Self::start_from`]'s) state: positions and velocities as given,
    /// not yet assembled.
    pub fn given_state(&self) -> &DVector<f64> {
        &self.initial_y
    }
}
