//! SFORCE as a force element: a FUNCTION of time and state applied between two markers.
//!
//! Adams conventions: a TRANSLATIONAL SFORCE acts along the line from J's origin to I's, a
//! positive value pushing them apart; with ACTIONONLY it acts on I only, along J's z axis. A
//! ROTATIONAL SFORCE is a torque about J's z axis, on I (and the opposite on J unless
//! ACTIONONLY).
//!
//! The Newton matrix differences the element over its own two parts only: a FUNCTION that
//! measures a third part contributes no partials for it (modified Newton still converges, more
//! slowly).

use super::frames::MarkerTable;
use super::measures::StateContext;
use crate::expr::Expr;
use crate::model::Freedom;
use contact_core::Vector3;
use contact_solver::EvaluationError;
use contact_solver::mbs::{ForceElement, Load, PartId, StateView};
use std::collections::BTreeMap;
use std::sync::Arc;

/// An SFORCE between markers `i` and `j`.
#[derive(Debug)]
pub struct SForceElement {
    /// `SFORCE/id`.
    pub name: String,
    /// The parts of I and J.
    pub parts: [PartId; 2],
    /// Marker ids.
    pub markers: [u32; 2],
    /// Force or torque.
    pub freedom: Freedom,
    /// ACTIONONLY.
    pub action_only: bool,
    /// FUNCTION.
    pub function: Expr,
    /// Where the markers are.
    pub table: Arc<MarkerTable>,
    /// VARIABLE functions by id.
    pub variables: Arc<BTreeMap<u32, Expr>>,
    /// Solver parts in the model (ground included): the FUNCTION may measure any of them.
    pub part_count: usize,
}

impl SForceElement {
    /// The FUNCTION's value at time `t` and `state`.
    pub fn value(
        &self,
        t: f64,
        parts: &[contact_solver::mbs::PartState],
    ) -> Result<f64, EvaluationError> {
        let ctx = StateContext {
            t,
            parts,
            markers: &self.table,
            variables: &self.variables,
            depth: 0,
        };
        self.function.eval(&ctx).map_err(|e| EvaluationError {
            element: self.name.clone(),
            message: e.to_string(),
            fatal: false,
        })
    }
}

impl ForceElement for SForceElement {
    fn name(&self) -> &str {
        &self.name
    }

    fn parts(&self) -> &[PartId] {
        &self.parts
    }

    fn evaluate(
        &self,
        t: f64,
        state: &StateView<'_>,
        loads: &mut [Load],
    ) -> Result<(), EvaluationError> {
        let parts: Vec<_> = (0..self.part_count)
            .map(|k| *state.part(PartId(k)))
            .collect();
        let value = self.value(t, &parts)?;
        let missing = || EvaluationError {
            element: self.name.clone(),
            message: "a marker is not on a part".into(),
            fatal: false,
        };
        let pose_i = self
            .table
            .pose_w(self.markers[0], &parts)
            .ok_or_else(missing)?;
        let pose_j = self
            .table
            .pose_w(self.markers[1], &parts)
            .ok_or_else(missing)?;
        let (cm_i, cm_j) = (
            parts[self.parts[0].0].pose_w.translation.vector,
            parts[self.parts[1].0].pose_w.translation.vector,
        );
        let z_j = pose_j.rotation * Vector3::z();
        let (pi, pj) = (pose_i.translation.vector, pose_j.translation.vector);
        let reaction = if self.action_only { 0.0 } else { 1.0 };
        match self.freedom {
            Freedom::Translational => {
                let direction = if self.action_only {
                    z_j
                } else {
                    let d = pi - pj;
                    let length = d.norm();
                    if length == 0.0 {
                        return Err(EvaluationError {
                            element: self.name.clone(),
                            message:
                                "the I and J markers coincide: the line of action is undefined"
                                    .into(),
                            fatal: false,
                        });
                    }
                    d / length
                };
                let force = direction * value;
                loads[0] = Load::at_point(force, &pi, &cm_i);
                loads[1] = Load::at_point(-force * reaction, &pi, &cm_j);
            }
            Freedom::Rotational => {
                loads[0] = Load {
                    force_w: Vector3::zeros(),
                    torque_w: z_j * value,
                };
                loads[1] = Load {
                    force_w: Vector3::zeros(),
                    torque_w: -z_j * value * reaction,
                };
            }
        }
        Ok(())
    }
}
