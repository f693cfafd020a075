//! The Newton matrix `∂F/∂y + c·∂F/∂y′`, assembled by blocks (solver-notes §2.3).
//!
//! - Kinematic, inertia, gyroscopic and normalization blocks: analytic.
//! - Constraint Jacobians `Φ_q = [Φ_r, Φ_π′·2G(e)/|e|²]` and `Φ_vᵀ` in the dynamic rows:
//!   analytic (`constraints::primitives`).
//! - `∂(Φ_vᵀλ)/∂q` (and under SI2 `∂(Φ_qᵀη)/∂q`, `∂(Φ_v v)/∂q`): a central difference of one
//!   element at a time over the 7 coordinates of each of its two parts (see
//!   `jacobian_constraints`).
//! - Force elements: their analytic partials (contacts: the force laws' partials with the
//!   contact geometry frozen, from one engine query, `crate::contact_partials`), or an
//!   element-local forward difference ([`super::force::difference_partials`]) where an element
//!   has none or [`super::ForcePartials::Difference`] asks for it everywhere, mapped from world `(δr, θ, u, ω)` to the state:
//!   `∂/∂e = (D_θ − D_ω ω̃) A · 2G(e)/|e|²`, `∂/∂ω′ = D_ω A`, and for the body torque
//!   `Aᵀn` of a part the extra `∂/∂e_p = ñ′ · 2G(e_p)/|e_p|²`.

use super::force::{ForcePartials, StateView, difference_partials};
use super::quaternion::{g_matrix, g_transpose_omega_partial, rotation_per_parameter, skew};
use super::system::MultibodySystem;
use crate::dae::EvaluationError;
use nalgebra::{DMatrix, DVector, Matrix3, Matrix4};

impl MultibodySystem {
    /// Writes the Newton matrix `∂F/∂y + c·∂F/∂y′` at `(t, y, y′)` into `out` (size² entries).
    /// `F` is linear in `y′` with constant coefficients (I, M, J), so `y′` itself is not used.
    pub fn compute_newton_matrix(
        &self,
        t: f64,
        y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        let layout = self.layout;
        debug_assert_eq!(out.shape(), (layout.size(), layout.size()));
        debug_assert_eq!(y.len(), layout.size());
        let states = self.part_states(y)?;
        out.fill(0.0);
        for (part, data) in self.moving_parts().zip(&self.parts) {
            let (qo, vo, mo) = (
                layout.position_offset(part),
                layout.velocity_offset(part),
                layout.mu_offset(part),
            );
            let e = self.parameters(y, part);
            let omega = Self::vector_at(y, vo + 3);
            let mu = y[mo];
            for i in 0..3 {
                out[(qo + i, qo + i)] = c;
                out[(qo + i, vo + i)] = -1.0;
            }
            let parameter_block =
                Matrix4::identity() * (c - mu) - g_transpose_omega_partial(&omega) * 0.5;
            out.fixed_view_mut::<4, 4>(qo + 3, qo + 3)
                .copy_from(&parameter_block);
            out.fixed_view_mut::<4, 3>(qo + 3, vo + 3)
                .copy_from(&(g_matrix(&e).transpose() * -0.5));
            out.fixed_view_mut::<4, 1>(qo + 3, mo).copy_from(&(-e));
            out.fixed_view_mut::<3, 3>(vo, vo)
                .copy_from(&(Matrix3::identity() * (c * data.mass)));
            let j_omega = data.inertia * omega;
            let gyro = skew(&omega) * data.inertia - skew(&j_omega);
            out.fixed_view_mut::<3, 3>(vo + 3, vo + 3)
                .copy_from(&(data.inertia * c + gyro));
            out.fixed_view_mut::<1, 4>(mo, qo + 3)
                .copy_from(&(e.transpose() * 2.0));
        }
        self.add_constraint_blocks(y, &states, out)?;
        self.add_force_blocks(t, y, &states, out)?;
        Ok(())
    }

    /// `−∂(f, Aᵀn)/∂(q, v)` of every force element.
    fn add_force_blocks(
        &self,
        t: f64,
        y: &DVector<f64>,
        states: &[super::force::PartState],
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        let layout = self.layout;
        let view = StateView::new(states);
        let all_loads = self.element_loads(t, states)?;
        // The partials, each element into its own slot (in parallel when configured), are
        // assembled below in index order: the same matrix at every thread count.
        let all_partials = self.parallelism.map_indexed(self.forces.len(), |k| {
            let element = &self.forces[k];
            let analytic = match self.force_partials {
                ForcePartials::Analytic => element.partials(t, &view),
                ForcePartials::Exact if element.partials_are_exact() => element.partials(t, &view),
                ForcePartials::Exact => None,
                ForcePartials::Difference => None,
            };
            match analytic {
                Some(result) => result,
                None => difference_partials(element.as_ref(), t, states, self.length_scale),
            }
        });
        for ((element, loads), partials) in self.forces.iter().zip(all_loads).zip(all_partials) {
            let partials = partials?;
            let parts = element.parts();
            for (row_slot, &row_part) in parts.iter().enumerate() {
                if row_part.is_ground() {
                    continue;
                }
                let vo = layout.velocity_offset(row_part);
                let rotation_row = states[row_part.0]
                    .pose_w
                    .rotation
                    .to_rotation_matrix()
                    .into_inner();
                // The body torque Aᵀn turns with the part itself.
                let body_torque = rotation_row.transpose() * loads[row_slot].torque_w;
                let own =
                    skew(&body_torque) * rotation_per_parameter(&self.parameters(y, row_part));
                let qo_row = layout.position_offset(row_part);
                let mut block = out.fixed_view_mut::<3, 4>(vo + 3, qo_row + 3);
                block -= own;
                for (col_slot, &col_part) in parts.iter().enumerate() {
                    if col_part.is_ground() {
                        continue;
                    }
                    let state = &states[col_part.0];
                    let rotation = state.pose_w.rotation.to_rotation_matrix().into_inner();
                    let per_parameter =
                        rotation * rotation_per_parameter(&self.parameters(y, col_part));
                    let (qo, vo_col) = (
                        layout.position_offset(col_part),
                        layout.velocity_offset(col_part),
                    );
                    let block = |r: usize, b: usize| -> Matrix3<f64> {
                        partials
                            .fixed_view::<3, 3>(6 * row_slot + r, 12 * col_slot + 3 * b)
                            .into_owned()
                    };
                    for r in [0, 3] {
                        let to_body = if r == 0 {
                            Matrix3::identity()
                        } else {
                            rotation_row.transpose()
                        };
                        let d_theta = block(r, 1) - block(r, 3) * skew(&state.angular_velocity_w);
                        let mut position = out.fixed_view_mut::<3, 3>(vo + r, qo);
                        position -= to_body * block(r, 0);
                        let mut parameters = out.fixed_view_mut::<3, 4>(vo + r, qo + 3);
                        parameters -= to_body * d_theta * per_parameter;
                        let mut velocity = out.fixed_view_mut::<3, 3>(vo + r, vo_col);
                        velocity -= to_body * block(r, 2);
                        let mut angular = out.fixed_view_mut::<3, 3>(vo + r, vo_col + 3);
                        angular -= to_body * block(r, 3) * rotation;
                    }
                }
            }
        }
        Ok(())
    }
}
