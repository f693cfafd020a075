//! Output frames from a state, and a state handed from one analysis to the next.

use super::EvaluationError;
use super::contact_force::ContactForce;
use super::mbs::quaternion::parameters_of;
use super::mbs::{MultibodySystem, PartState, StateView};
use super::simulate::Frame;
use nalgebra::DVector;
use std::sync::Arc;

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
    Ok(Frame { t, parts, contacts })
}

impl MultibodySystem {
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
