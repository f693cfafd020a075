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
use nalgebra::{DMatrix, DVector, Matrix3, Matrix4, SMatrix};

impl MultibodySystem {
    /// Writes the Newton matrix `∂F/∂y + c·∂F/∂y′` at `(t, y, y′)` into `out` (size² entries).
    /// `F` is linear in `y′` with constant coefficients (I, M, J), so `y′` itself is not used.
    pub fn compute_newton_matrix(
        &self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        debug_assert_eq!(out.shape(), (self.layout.size(), self.layout.size()));
        out.fill(0.0);
        self.assemble_newton_matrix(t, y, yp, c, out)
    }

    /// The entries of the Newton matrix at `(t, y, y′)` pushed onto `out` as
    /// `(row, column, value)`, block by block (duplicates to be summed): the same blocks as
    /// [`Self::compute_newton_matrix`], for the sparse path.
    pub fn compute_newton_entries(
        &self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        c: f64,
        out: &mut Vec<(usize, usize, f64)>,
    ) -> Result<(), EvaluationError> {
        self.assemble_newton_matrix(t, y, yp, c, &mut Triplets(out))
    }

    /// Every block of the Newton matrix into `out` (zero before the call).
    fn assemble_newton_matrix(
        &self,
        t: f64,
        y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut impl Assembly,
    ) -> Result<(), EvaluationError> {
        let layout = self.layout;
        debug_assert_eq!(y.len(), layout.size());
        let states = self.part_states(y)?;
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
                out.set(qo + i, qo + i, c);
                out.set(qo + i, vo + i, -1.0);
            }
            let parameter_block =
                Matrix4::identity() * (c - mu) - g_transpose_omega_partial(&omega) * 0.5;
            out.set_block(qo + 3, qo + 3, &parameter_block);
            out.set_block(qo + 3, vo + 3, &(g_matrix(&e).transpose() * -0.5));
            out.set_block(qo + 3, mo, &(-e));
            out.set_block(vo, vo, &(Matrix3::identity() * (c * data.mass)));
            let j_omega = data.inertia * omega;
            let gyro = skew(&omega) * data.inertia - skew(&j_omega);
            out.set_block(vo + 3, vo + 3, &(data.inertia * c + gyro));
            out.set_block(mo, qo + 3, &(e.transpose() * 2.0));
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
        out: &mut impl Assembly,
    ) -> Result<(), EvaluationError> {
        let layout = self.layout;
        let view = StateView::new(states);
        let all_loads = self.active_element_loads(t, states)?;
        // The partials, each element into its own slot (in parallel when configured), are
        // assembled below in index order: the same matrix at every thread count.
        let all_partials = self.parallelism.map_indexed(all_loads.len(), |n| {
            let element = &self.forces[all_loads[n].0];
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
        for ((k, loads), partials) in all_loads.into_iter().zip(all_partials) {
            let element = &self.forces[k];
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
                out.sub_block(vo + 3, qo_row + 3, &own);
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
                        out.sub_block(vo + r, qo, &(to_body * block(r, 0)));
                        out.sub_block(vo + r, qo + 3, &(to_body * d_theta * per_parameter));
                        out.sub_block(vo + r, vo_col, &(to_body * block(r, 2)));
                        out.sub_block(vo + r, vo_col + 3, &(to_body * block(r, 3) * rotation));
                    }
                }
            }
        }
        Ok(())
    }
}

/// Where the Newton matrix's blocks go: a dense matrix (zeroed first), or triplets for the
/// sparse path. `set` writes an entry no other block writes; `add` and `sub_block` accumulate.
pub(crate) trait Assembly {
    /// Writes `value` at `(row, col)`.
    fn set(&mut self, row: usize, col: usize, value: f64);
    /// Adds `value` at `(row, col)`.
    fn add(&mut self, row: usize, col: usize, value: f64);
    /// Writes `block` with its first entry at `(row, col)`.
    fn set_block<const R: usize, const C: usize>(
        &mut self,
        row: usize,
        col: usize,
        block: &SMatrix<f64, R, C>,
    );
    /// Subtracts `block` with its first entry at `(row, col)`.
    fn sub_block<const R: usize, const C: usize>(
        &mut self,
        row: usize,
        col: usize,
        block: &SMatrix<f64, R, C>,
    );
}

impl Assembly for DMatrix<f64> {
    fn set(&mut self, row: usize, col: usize, value: f64) {
        self[(row, col)] = value;
    }

    fn add(&mut self, row: usize, col: usize, value: f64) {
        self[(row, col)] += value;
    }

    fn set_block<const R: usize, const C: usize>(
        &mut self,
        row: usize,
        col: usize,
        block: &SMatrix<f64, R, C>,
    ) {
        self.fixed_view_mut::<R, C>(row, col).copy_from(block);
    }

    fn sub_block<const R: usize, const C: usize>(
        &mut self,
        row: usize,
        col: usize,
        block: &SMatrix<f64, R, C>,
    ) {
        let mut view = self.fixed_view_mut::<R, C>(row, col);
        view -= block;
    }
}

/// Triplets `(row, column, value)` to be summed.
pub(crate) struct Triplets<'a>(pub &'a mut Vec<(usize, usize, f64)>);

impl Assembly for Triplets<'_> {
    fn set(&mut self, row: usize, col: usize, value: f64) {
        self.0.push((row, col, value));
    }

    fn add(&mut self, row: usize, col: usize, value: f64) {
        self.0.push((row, col, value));
    }

    fn set_block<const R: usize, const C: usize>(
        &mut self,
        row: usize,
        col: usize,
        block: &SMatrix<f64, R, C>,
    ) {
        for j in 0..C {
            for i in 0..R {
                self.0.push((row + i, col + j, block[(i, j)]));
            }
        }
    }

    fn sub_block<const R: usize, const C: usize>(
        &mut self,
        row: usize,
        col: usize,
        block: &SMatrix<f64, R, C>,
    ) {
        for j in 0..C {
            for i in 0..R {
                self.0.push((row + i, col + j, -block[(i, j)]));
            }
        }
    }
}
