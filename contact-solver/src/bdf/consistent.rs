//! A consistent start for index-0/1 systems: given `y(t0)` of the differential variables,
//! compute `y′(t0)` of the differential variables and `y(t0)` of the index-1 algebraic ones so
//! that `F(t0, y, y′) = 0` (as DASSL's INFO(11) does).
//!
//! Unknowns `z`: `y′_j` for a differential `j`, `y_j` for an algebraic `j`. Newton on
//! `F(z) = 0` with the matrix whose column `j` is `∂F/∂y′_j = N(1) − N(0)` (differential) or
//! `∂F/∂y_j = N(0)` (algebraic), where `N(c) = ∂F/∂y + c·∂F/∂y′` is the system's Newton matrix
//! (linear in `c`, so two evaluations give both parts exactly). Variables of index 2 or 3 make
//! this matrix singular (a position constraint does not involve `y′` nor the multiplier), so
//! such systems must start consistent: the multibody equations' initial-conditions analysis
//! (Adams: positions, velocities, then accelerations and forces) provides it.

use super::error::{FailureCause, IntegratorError};
use super::{Bdf, Phase};
use crate::{DaeSystem, VariableKind};
use nalgebra::{DMatrix, DVector};

impl Bdf {
    /// Makes the initial point consistent (see the module docs); only before the first step.
    /// Converges when the weighted Newton correction is below `1e-3` (in units of ERROR); fails
    /// with [`IntegratorError::InconsistentStart`] if the system has variables of index 2 or 3,
    /// has stepped already, or Newton does not converge within MAXIT iterations.
    pub fn make_consistent(&mut self, system: &mut dyn DaeSystem) -> Result<(), IntegratorError> {
        let fail = |t: f64, reason: String| IntegratorError::InconsistentStart { t, reason };
        if self.history.is_some() || self.stats.steps > 0 {
            return Err(fail(
                self.t,
                "the integration has already started".to_string(),
            ));
        }
        let kinds = self.norms.kinds().to_vec();
        if let Some(j) = kinds
            .iter()
            .position(|k| matches!(k, VariableKind::Algebraic { index } if *index > 1))
        {
            return Err(fail(
                self.t,
                format!("y[{j}] has DAE index > 1: index-2/3 systems must start consistent"),
            ));
        }
        let n = self.y.len();
        let (mut n0, mut n1) = (DMatrix::zeros(n, n), DMatrix::zeros(n, n));
        let mut residual = DVector::zeros(n);
        self.norms.set_weights(&self.y);
        for _ in 0..self.settings.maxit {
            let evaluate = |e| fail(self.t, FailureCause::Evaluation(e).to_string());
            system
                .residual(self.t, &self.y, &self.yp, &mut residual)
                .map_err(evaluate)?;
            self.stats.residual_evaluations += 1;
            n0.fill(0.0);
            n1.fill(0.0);
            system
                .newton_matrix(self.t, &self.y, &self.yp, 0.0, &mut n0)
                .map_err(evaluate)?;
            system
                .newton_matrix(self.t, &self.y, &self.yp, 1.0, &mut n1)
                .map_err(evaluate)?;
            self.stats.jacobian_evaluations += 2;
            let mut jacobian = n0.clone();
            for (j, kind) in kinds.iter().enumerate() {
                if matches!(kind, VariableKind::Differential) {
                    jacobian.set_column(j, &(n1.column(j) - n0.column(j)));
                }
            }
            self.stats.lu_factorizations += 1;
            let lu = jacobian.lu();
            if !lu.solve_mut(&mut residual) || residual.iter().any(|v| !v.is_finite()) {
                return Err(fail(self.t, FailureCause::SingularMatrix.to_string()));
            }
            for (j, kind) in kinds.iter().enumerate() {
                match kind {
                    VariableKind::Differential => self.yp[j] -= residual[j],
                    VariableKind::Algebraic { .. } => self.y[j] -= residual[j],
                }
            }
            // Weighted by the variable's own scale: y′ corrections relative to ERROR·(|y′|+1).
            let size = residual
                .iter()
                .enumerate()
                .map(|(j, d)| {
                    let scale = match kinds[j] {
                        VariableKind::Differential => self.yp[j].abs() + 1.0,
                        VariableKind::Algebraic { .. } => self.y[j].abs() + 1.0,
                    };
                    d / (self.settings.error * scale)
                })
                .fold(0.0_f64, |m, v| m.max(v.abs()));
            if size <= 1e-3 {
                self.phase = Phase::StartUp;
                return Ok(());
            }
        }
        Err(fail(
            self.t,
            format!(
                "Newton did not converge in MAXIT = {} iterations",
                self.settings.maxit
            ),
        ))
    }
}
