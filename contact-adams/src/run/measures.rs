//! Adams measures (DX … AZ) and VARVAL evaluated on the solver's state: the expression
//! [`crate::expr::Context`] that SFORCE and VARIABLE expressions read.
//!
//! Conventions (Adams): `DX(i, j, k)` is the x component of marker i's origin relative to
//! marker j's, in marker k's axes (j and k default to ground); `VX(i, j, k)` the same for the
//! velocity (the time derivative taken in ground; a fourth argument naming another frame is
//! an error); `VR(i, j)` the rate of `DM(i, j)`, positive separating; `WX(i, j, k)` the angular
//! velocity of i relative to j in k's axes; `AX(i, j)` the rotation of i about j's x axis,
//! `atan2(y_i·z_j, y_i·y_j)` (and cyclically `AY`, `AZ = atan2(x_i·y_j, x_i·x_j)`).

use super::frames::MarkerTable;
use crate::expr::{Context, ElementKind, EvalError, Expr, Measure};
use contact_core::{Isometry3, Vector3};
use contact_solver::mbs::PartState;
use std::collections::BTreeMap;

/// The state an expression reads at one evaluation.
pub struct StateContext<'a> {
    /// Time.
    pub t: f64,
    /// Every part's state, indexed by solver part id.
    pub parts: &'a [PartState],
    /// Where the markers are.
    pub markers: &'a MarkerTable,
    /// VARIABLE functions by id.
    pub variables: &'a BTreeMap<u32, Expr>,
    /// How deep VARVAL calls are nested (a cycle is an error, not a stack overflow).
    pub depth: usize,
}

/// The deepest VARVAL nesting allowed before a cycle is assumed.
pub(crate) const MAX_VARIABLE_DEPTH: usize = 64;

impl StateContext<'_> {
    fn pose(&self, id: u32) -> Result<Isometry3, EvalError> {
        if id == 0 {
            return Ok(Isometry3::identity());
        }
        self.markers
            .pose_w(id, self.parts)
            .ok_or(EvalError::NeedsState("a marker the model does not define"))
    }

    fn velocity(&self, id: u32) -> Result<(Vector3, Vector3), EvalError> {
        if id == 0 {
            return Ok((Vector3::zeros(), Vector3::zeros()));
        }
        self.markers
            .velocity_w(id, self.parts)
            .ok_or(EvalError::NeedsState("a marker the model does not define"))
    }
}

impl Context for StateContext<'_> {
    fn time(&self) -> f64 {
        self.t
    }

    fn measure(&self, measure: Measure, markers: &[u32]) -> Result<f64, EvalError> {
        let arg = |k: usize| markers.get(k).copied().unwrap_or(0);
        let (i, j, k) = (arg(0), arg(1), arg(2));
        let pi = self.pose(i)?;
        let pj = self.pose(j)?;
        let axes_k = self.pose(k)?.rotation;
        let d = pi.translation.vector - pj.translation.vector;
        let component = |v: Vector3, c: usize| (axes_k.inverse() * v)[c];
        let (vi, wi) = self.velocity(i)?;
        let (vj, wj) = self.velocity(j)?;
        let angle = |a: Vector3, b: Vector3, c: Vector3| {
            let (ai, bj, cj) = (pi.rotation * a, pj.rotation * b, pj.rotation * c);
            ai.dot(&cj).atan2(ai.dot(&bj))
        };
        Ok(match measure {
            Measure::Dx => component(d, 0),
            Measure::Dy => component(d, 1),
            Measure::Dz => component(d, 2),
            Measure::Dm => d.norm(),
            Measure::Vx | Measure::Vy | Measure::Vz | Measure::Vm => {
                if arg(3) != 0 {
                    return Err(EvalError::NeedsState(
                        "VX/VY/VZ/VM with a fourth (derivative frame) argument",
                    ));
                }
                let v = vi - vj;
                match measure {
                    Measure::Vx => component(v, 0),
                    Measure::Vy => component(v, 1),
                    Measure::Vz => component(v, 2),
                    _ => v.norm(),
                }
            }
            Measure::Vr => {
                let dist = d.norm();
                if dist == 0.0 {
                    0.0
                } else {
                    (vi - vj).dot(&d) / dist
                }
            }
            Measure::Wx => component(wi - wj, 0),
            Measure::Wy => component(wi - wj, 1),
            Measure::Wz => component(wi - wj, 2),
            Measure::Wm => (wi - wj).norm(),
            Measure::Ax => angle(Vector3::y(), Vector3::y(), Vector3::z()),
            Measure::Ay => angle(Vector3::z(), Vector3::z(), Vector3::x()),
            Measure::Az => angle(Vector3::x(), Vector3::x(), Vector3::y()),
        })
    }

    fn variable(&self, id: u32) -> Result<f64, EvalError> {
        let function = self.variables.get(&id).ok_or(EvalError::NeedsState(
            "VARVAL of a VARIABLE the model does not define",
        ))?;
        if self.depth >= MAX_VARIABLE_DEPTH {
            return Err(EvalError::VariableCycle { id });
        }
        function.eval(&StateContext {
            depth: self.depth + 1,
            ..*self
        })
    }

    fn element_force(&self, kind: ElementKind, _args: [u32; 4]) -> Result<f64, EvalError> {
        Err(EvalError::NeedsState(kind.name()))
    }
}
