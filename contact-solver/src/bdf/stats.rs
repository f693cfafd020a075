//! Work counters of one integration, field by field.

/// What the integrator has done since it was created. Every counter only grows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct IntegratorStats {
    /// Accepted steps.
    pub steps: u64,
    /// Step attempts rejected because the local error estimate exceeded ERROR.
    pub rejected_error_test: u64,
    /// Step attempts rejected because Newton did not converge within MAXIT iterations (or
    /// diverged) with an up-to-date Newton matrix.
    pub rejected_convergence: u64,
    /// Step attempts rejected because the system could not evaluate its equations
    /// ([`EvaluationError`](crate::EvaluationError)) or produced non-finite numbers.
    pub rejected_evaluation: u64,
    /// Accepted steps the caller rolled back with
    /// [`Bdf::reject_last_step_and_retry_to`](super::Bdf::reject_last_step_and_retry_to)
    /// (contact onset).
    pub rejected_by_caller: u64,
    /// Newton iterations (linear solves) over all attempts.
    pub newton_iterations: u64,
    /// Extra corrector passes the system's inner iteration asked for
    /// ([`DaeSystem::corrector_converged`](crate::DaeSystem::corrector_converged)
    /// returning true: augmented-Lagrangian updates).
    pub inner_iterations: u64,
    /// Calls of [`DaeSystem::residual`](crate::DaeSystem::residual).
    pub residual_evaluations: u64,
    /// Calls of [`DaeSystem::newton_matrix`](crate::DaeSystem::newton_matrix)
    /// (Jacobian evaluations).
    pub jacobian_evaluations: u64,
    /// LU factorisations of the scaled Newton matrix (one per Jacobian evaluation: the matrix
    /// is reused, factorised, across iterations and steps until it is refreshed).
    pub lu_factorizations: u64,
    /// Accepted steps per BDF order: `steps_by_order[k]` counts steps taken at order `k`
    /// (index 0 unused).
    pub steps_by_order: [u64; 7],
}

impl IntegratorStats {
    /// All rejected step attempts, whatever the cause.
    pub fn rejected(&self) -> u64 {
        self.rejected_error_test
            + self.rejected_convergence
            + self.rejected_evaluation
            + self.rejected_by_caller
    }
}
