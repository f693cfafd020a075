//! The residual `F(t, y, y′)` and the [`DaeSystem`] implementation.

use super::constraints::ConstraintElement;
use super::force::{PartState, StateView};
use super::layout::Formulation;
use super::quaternion::{g_matrix, rotation_per_parameter};
use super::system::MultibodySystem;
use crate::dae::{DaeSystem, EvaluationError, VariableKind};
use nalgebra::{DMatrix, DVector, Vector3};

impl MultibodySystem {
    /// Writes `F(t, y, y′)` (see [`MultibodySystem`] for the equations) into `out`.
    pub fn compute_residual(
        &self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        let layout = self.layout;
        debug_assert!(y.len() == layout.size() && yp.len() == y.len() && out.len() == y.len());
        let states = self.part_states(y)?;
        // Kinematic rows, inertia and the normalization rows; the applied and gyroscopic part
        // comes from `applied_minus_gyroscopic`.
        let applied = self.applied_minus_gyroscopic(t, y, &states)?;
        for (k, (part, data)) in self.moving_parts().zip(&self.parts).enumerate() {
            let (qo, vo) = (layout.position_offset(part), layout.velocity_offset(part));
            let mu = y[layout.mu_offset(part)];
            let e = self.parameters(y, part);
            let u = Self::vector_at(y, vo);
            let omega = Self::vector_at(y, vo + 3);
            let position_rate = Self::vector_at(yp, qo) - u;
            let parameter_rate =
                yp.fixed_rows::<4>(qo + 3) - g_matrix(&e).transpose() * omega * 0.5 - e * mu;
            let linear = Self::vector_at(yp, vo) * data.mass - applied.fixed_rows::<3>(6 * k);
            let angular =
                data.inertia * Self::vector_at(yp, vo + 3) - applied.fixed_rows::<3>(6 * k + 3);
            out.fixed_rows_mut::<3>(qo).copy_from(&position_rate);
            out.fixed_rows_mut::<4>(qo + 3).copy_from(&parameter_rate);
            out.fixed_rows_mut::<3>(vo).copy_from(&linear);
            out.fixed_rows_mut::<3>(vo + 3).copy_from(&angular);
            out[layout.mu_offset(part)] = e.norm_squared() - 1.0;
        }
        // Φ in its rows and the constraint forces Φ_vᵀλ in the dynamic rows, from one set of
        // marker frames per element.
        for element in &self.constraints {
            let (pose_a, pose_b) = (
                &states[element.part_i.0].pose_w,
                &states[element.part_j.0].pose_w,
            );
            let frames = element.frames(pose_a, pose_b);
            let lambda = multipliers(y, layout.lambda_offset(), element);
            let mut reaction = [Vector3::zeros(); 4];
            for (k, (primitive, &l)) in element.primitives.iter().zip(lambda).enumerate() {
                let value = primitive.value(&frames, t);
                if !value.is_finite() {
                    return Err(EvaluationError {
                        element: element.name.clone(),
                        message: format!(
                            "constraint equation {k} ({primitive:?}) is {value} at t = {t}"
                        ),
                        fatal: false,
                    });
                }
                out[layout.position_constraint_offset() + element.row + k] = value;
                let gradient = ConstraintElement::body_gradient(primitive, &frames, pose_a, pose_b);
                for (sum, g) in reaction.iter_mut().zip(gradient) {
                    *sum += g * l;
                }
            }
            for (part, force, torque) in [
                (element.part_i, reaction[0], reaction[1]),
                (element.part_j, reaction[2], reaction[3]),
            ] {
                if part.is_ground() {
                    continue;
                }
                let vo = layout.velocity_offset(part);
                let mut linear = out.fixed_rows_mut::<3>(vo);
                linear += force;
                let mut angular = out.fixed_rows_mut::<3>(vo + 3);
                angular += torque;
            }
        }
        if layout.formulation() == Formulation::Si2 {
            self.add_stabilization(t, y, &states, out);
        }
        Ok(())
    }
}

impl MultibodySystem {
    /// SI2: the velocity constraints `Φ_v v + Φ_t` in the λ rows and `Φ_qᵀη` in the kinematic
    /// rows (`Φ_q = [Φ_r, Φ_π′·2G(e)/|e|²]`).
    fn add_stabilization(
        &self,
        t: f64,
        y: &DVector<f64>,
        states: &[PartState],
        out: &mut DVector<f64>,
    ) {
        let layout = self.layout;
        let (phi_t, _) = self.constraint_time_derivatives(t);
        for element in &self.constraints {
            let (pose_a, pose_b) = (
                &states[element.part_i.0].pose_w,
                &states[element.part_j.0].pose_w,
            );
            let velocities = [element.part_i, element.part_j].map(|p| self.part_velocity(y, p));
            let rates = element.velocity_rates(pose_a, pose_b, &velocities);
            for (k, rate) in rates.into_iter().enumerate() {
                out[layout.lambda_offset() + element.row + k] = rate + phi_t[element.row + k];
            }
            let eta = multipliers(y, layout.position_constraint_offset(), element);
            let correction = element.generalized_reaction(pose_a, pose_b, eta);
            for (part, linear, angular) in [
                (element.part_i, correction[0], correction[1]),
                (element.part_j, correction[2], correction[3]),
            ] {
                if part.is_ground() {
                    continue;
                }
                let qo = layout.position_offset(part);
                let per_parameter =
                    rotation_per_parameter(&self.parameters(y, part)).transpose() * angular;
                let mut position = out.fixed_rows_mut::<3>(qo);
                position += linear;
                let mut parameters = out.fixed_rows_mut::<4>(qo + 3);
                parameters += per_parameter;
            }
        }
    }
}

/// The multipliers of one constraint element (its rows of the block at `offset`).
pub(crate) fn multipliers<'y>(
    y: &'y DVector<f64>,
    offset: usize,
    element: &ConstraintElement,
) -> &'y [f64] {
    let start = offset + element.row;
    &y.as_slice()[start..start + element.primitives.len()]
}

impl DaeSystem for MultibodySystem {
    fn size(&self) -> usize {
        self.layout.size()
    }

    /// q and v are differential; λ has index 3 under I3 and 2 under SI2; η (SI2) index 2; μ
    /// index 2 (the normalization constraint differentiated once gives `2eᵀė = 2μ|e|²`, and μ
    /// follows).
    fn variable_kinds(&self) -> Vec<VariableKind> {
        let layout = self.layout;
        let mut kinds = vec![VariableKind::Algebraic { index: 2 }; layout.size()];
        // Positions are always error-tested. Velocities too, except under I3 with constraints:
        // there they are index-2 variables (Adams tests displacements only), and testing them
        // makes the error test fail down to round-off right after a start.
        let velocities_tested =
            layout.formulation() == Formulation::Si2 || layout.constraint_rows() == 0;
        let tested = if velocities_tested { 13 } else { 7 };
        kinds[..tested * layout.parts()].fill(VariableKind::Differential);
        let lambda_index = match layout.formulation() {
            Formulation::I3 => 3,
            Formulation::Si2 => 2,
        };
        for kind in
            &mut kinds[layout.lambda_offset()..layout.lambda_offset() + layout.constraint_rows()]
        {
            *kind = VariableKind::Algebraic {
                index: lambda_index,
            };
        }
        kinds
    }

    fn residual(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        self.compute_residual(t, y, yp, out)
    }

    fn newton_matrix(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        self.compute_newton_matrix(t, y, yp, c, out)
    }

    fn newton_storage(&self) -> crate::NewtonStorage {
        MultibodySystem::newton_storage(self)
    }

    fn parallelism(&self) -> crate::parallel::Parallelism {
        self.parallelism.clone()
    }

    fn newton_entries(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        c: f64,
        out: &mut Vec<(usize, usize, f64)>,
    ) -> Result<(), EvaluationError> {
        self.compute_newton_entries(t, y, yp, c, out)
    }

    /// Forwards to every force element's [`ForceElement::attempt_started`] (those that
    /// [track steps](super::ForceElement::tracks_steps)).
    ///
    /// [`ForceElement::attempt_started`]: super::ForceElement::attempt_started
    fn attempt_started(&mut self, _t_new: f64, _h: f64) {
        let trackers: Vec<usize> = self.step_trackers().collect();
        for k in trackers {
            self.forces[k].attempt_started();
        }
    }

    /// Forwards to every force element's [`ForceElement::corrector_converged`] (all of those
    /// that track steps, so each updates at the same state) and asks for another pass if any
    /// asked for one.
    ///
    /// [`ForceElement::corrector_converged`]: super::ForceElement::corrector_converged
    fn corrector_converged(&mut self, t: f64, y: &DVector<f64>, _yp: &DVector<f64>) -> bool {
        let trackers: Vec<usize> = self.step_trackers().collect();
        if trackers.is_empty() {
            return false;
        }
        let Ok(states) = self.part_states(y) else {
            return false;
        };
        let view = StateView::new(&states);
        let mut again = false;
        for k in trackers {
            again |= self.forces[k].corrector_converged(t, &view);
        }
        again
    }

    /// Forwards to every force element's [`ForceElement::step_accepted`] (those that track
    /// steps; skipped if `y` has no usable part state, which an accepted step cannot have).
    ///
    /// [`ForceElement::step_accepted`]: super::ForceElement::step_accepted
    fn step_accepted(&mut self, t: f64, y: &DVector<f64>, _yp: &DVector<f64>) {
        let trackers: Vec<usize> = self.step_trackers().collect();
        if trackers.is_empty() {
            return;
        }
        if let Ok(states) = self.part_states(y) {
            let view = StateView::new(&states);
            for k in trackers {
                self.forces[k].step_accepted(t, &view);
            }
        }
    }
}
