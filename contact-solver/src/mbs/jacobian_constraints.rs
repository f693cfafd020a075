//! The constraint blocks of the Newton matrix, for I3 and SI2.
//!
//! Analytic: `Φ_q = [Φ_r, Φ_π′·P(e)]` (P = 2G(e)/|e|²) in the position-constraint rows, `Φ_vᵀ`
//! in the λ columns of the dynamic rows, and under SI2 `Φ_v` in the velocity-constraint rows
//! and `Φ_qᵀ` in the η columns of the kinematic rows. By central difference of one element
//! over the 7 coordinates of each of its parts (step `ε^(1/3)·max(|r|, L)` for positions,
//! `ε^(1/3)·|e|` for Euler parameters; error O(ε^(2/3))): `∂(Φ_vᵀλ)/∂q`, and under SI2
//! `∂(Φ_qᵀη)/∂q` and `∂(Φ_v v)/∂q`.

use super::constraints::ConstraintElement;
use super::force::PartState;
use super::jacobian::Assembly;
use super::layout::Formulation;
use super::part::PartId;
use super::quaternion::rotation_per_parameter;
use super::residual::multipliers;
use super::system::MultibodySystem;
use crate::dae::EvaluationError;
use nalgebra::{DVector, Isometry3, Vector3, Vector4};

/// The coordinates `(r, e)` of an element's two parts (zeros for the ground).
type ElementCoordinates = [[f64; 7]; 2];

impl MultibodySystem {
    /// Adds every constraint block of the Newton matrix.
    pub(crate) fn add_constraint_blocks(
        &self,
        y: &DVector<f64>,
        states: &[PartState],
        out: &mut impl Assembly,
    ) -> Result<(), EvaluationError> {
        let layout = self.layout;
        let si2 = layout.formulation() == Formulation::Si2;
        for element in &self.constraints {
            let (pose_a, pose_b) = (
                &states[element.part_i.0].pose_w,
                &states[element.part_j.0].pose_w,
            );
            let frames = element.frames(pose_a, pose_b);
            for (k, primitive) in element.primitives.iter().enumerate() {
                let position_row = layout.position_constraint_offset() + element.row + k;
                let lambda_column = layout.lambda_offset() + element.row + k;
                let gradient = ConstraintElement::body_gradient(primitive, &frames, pose_a, pose_b);
                for (part, linear, angular) in [
                    (element.part_i, gradient[0], gradient[1]),
                    (element.part_j, gradient[2], gradient[3]),
                ] {
                    if part.is_ground() {
                        continue;
                    }
                    let (qo, vo) = (layout.position_offset(part), layout.velocity_offset(part));
                    let per_parameter =
                        angular.transpose() * rotation_per_parameter(&self.parameters(y, part));
                    for i in 0..3 {
                        out.add(position_row, qo + i, linear[i]);
                        out.add(vo + i, lambda_column, linear[i]);
                        out.add(vo + 3 + i, lambda_column, angular[i]);
                    }
                    for i in 0..4 {
                        out.add(position_row, qo + 3 + i, per_parameter[i]);
                    }
                    if si2 {
                        // Velocity-constraint row (at λ) in v; kinematic rows in η (at Φ).
                        for i in 0..3 {
                            out.add(lambda_column, vo + i, linear[i]);
                            out.add(lambda_column, vo + 3 + i, angular[i]);
                            out.add(qo + i, position_row, linear[i]);
                        }
                        for i in 0..4 {
                            out.add(qo + 3 + i, position_row, per_parameter[i]);
                        }
                    }
                }
            }
            self.add_constraint_differences(element, y, out)?;
        }
        Ok(())
    }

    /// The difference terms of one element (see the module docs).
    fn add_constraint_differences(
        &self,
        element: &ConstraintElement,
        y: &DVector<f64>,
        out: &mut impl Assembly,
    ) -> Result<(), EvaluationError> {
        let layout = self.layout;
        let parts = [element.part_i, element.part_j];
        let lambda = multipliers(y, layout.lambda_offset(), element);
        // ∂(Φ_vᵀλ)/∂q into the dynamic rows.
        if lambda.iter().any(|&l| l != 0.0) {
            let value = |poses: &[Isometry3<f64>; 2], _: &ElementCoordinates| {
                let g = element.generalized_reaction(&poses[0], &poses[1], lambda);
                g.iter()
                    .flat_map(|v| v.iter().copied())
                    .collect::<Vec<f64>>()
            };
            let target_rows = parts.map(|p| (!p.is_ground()).then(|| layout.velocity_offset(p)));
            let rows: Vec<Option<usize>> = (0..12)
                .map(|i| target_rows[i / 6].map(|o| o + i % 6))
                .collect();
            self.scatter_difference(element, y, &rows, value, out)?;
        }
        if layout.formulation() != Formulation::Si2 {
            return Ok(());
        }
        // ∂(Φ_qᵀη)/∂q into the kinematic rows.
        let eta = multipliers(y, layout.position_constraint_offset(), element);
        if eta.iter().any(|&l| l != 0.0) {
            let value = |poses: &[Isometry3<f64>; 2], q: &ElementCoordinates| {
                let g = element.generalized_reaction(&poses[0], &poses[1], eta);
                let mut values = Vec::with_capacity(14);
                for slot in 0..2 {
                    let e = Vector4::new(q[slot][3], q[slot][4], q[slot][5], q[slot][6]);
                    let per_parameter = rotation_per_parameter(&e).transpose() * g[2 * slot + 1];
                    values.extend(g[2 * slot].iter().chain(per_parameter.iter()).copied());
                }
                values
            };
            let target_rows = parts.map(|p| (!p.is_ground()).then(|| layout.position_offset(p)));
            let rows: Vec<Option<usize>> = (0..14)
                .map(|i| target_rows[i / 7].map(|o| o + i % 7))
                .collect();
            self.scatter_difference(element, y, &rows, value, out)?;
        }
        // ∂(Φ_v v)/∂q into the velocity-constraint rows (at λ), velocities held.
        let velocities = parts.map(|p| self.part_velocity(y, p));
        let value = |poses: &[Isometry3<f64>; 2], _: &ElementCoordinates| {
            element.velocity_rates(&poses[0], &poses[1], &velocities)
        };
        let rows: Vec<Option<usize>> = (0..element.primitives.len())
            .map(|k| Some(layout.lambda_offset() + element.row + k))
            .collect();
        self.scatter_difference(element, y, &rows, value, out)
    }

    /// `[u, ω′]` of a part in `y` (zeros for the ground).
    pub(crate) fn part_velocity(&self, y: &DVector<f64>, part: PartId) -> [Vector3<f64>; 2] {
        if part.is_ground() {
            return [Vector3::zeros(); 2];
        }
        let vo = self.layout.velocity_offset(part);
        [Self::vector_at(y, vo), Self::vector_at(y, vo + 3)]
    }

    /// Central difference of `value(poses, coordinates)` over the coordinates of the element's
    /// moving parts; entry `i` of the value goes to row `rows[i]` (skipped when `None`).
    fn scatter_difference(
        &self,
        element: &ConstraintElement,
        y: &DVector<f64>,
        rows: &[Option<usize>],
        value: impl Fn(&[Isometry3<f64>; 2], &ElementCoordinates) -> Vec<f64>,
        out: &mut impl Assembly,
    ) -> Result<(), EvaluationError> {
        let layout = self.layout;
        let parts = [element.part_i, element.part_j];
        let base: ElementCoordinates = parts.map(|p| {
            if p.is_ground() {
                [0.0; 7]
            } else {
                let qo = layout.position_offset(p);
                std::array::from_fn(|i| y[qo + i])
            }
        });
        let poses_of = |q: &ElementCoordinates| -> Result<[Isometry3<f64>; 2], EvaluationError> {
            let pose = |slot: usize| {
                let part = parts[slot];
                if part.is_ground() {
                    return Ok(PartState::GROUND.pose_w);
                }
                let c = &q[slot];
                self.pose_from(
                    part,
                    Vector3::new(c[0], c[1], c[2]),
                    &Vector4::new(c[3], c[4], c[5], c[6]),
                )
            };
            Ok([pose(0)?, pose(1)?])
        };
        let cube_root_eps = f64::EPSILON.cbrt();
        for (slot, &part) in parts.iter().enumerate() {
            if part.is_ground() {
                continue;
            }
            let qo = layout.position_offset(part);
            let c = &base[slot];
            let position_scale = Vector3::new(c[0], c[1], c[2]).norm().max(self.length_scale);
            let parameter_scale = Vector4::new(c[3], c[4], c[5], c[6]).norm();
            for coordinate in 0..7 {
                let scale = if coordinate < 3 {
                    position_scale
                } else {
                    parameter_scale
                };
                let h = cube_root_eps * scale;
                let (mut plus, mut minus) = (base, base);
                plus[slot][coordinate] += h;
                minus[slot][coordinate] -= h;
                let forward = value(&poses_of(&plus)?, &plus);
                let backward = value(&poses_of(&minus)?, &minus);
                for ((row, f), b) in rows.iter().zip(&forward).zip(&backward) {
                    if let Some(row) = row {
                        out.add(*row, qo + coordinate, (f - b) / (2.0 * h));
                    }
                }
            }
        }
        Ok(())
    }
}
