//! The interface between the integrator and the equations it integrates.
//!
//! The integrator (`solver::bdf`) solves an implicit DAE `F(t, y, y′) = 0` and knows nothing of
//! parts or joints; the multibody equations (`solver::mbs`) implement [`DaeSystem`] and know
//! nothing of step sizes or orders. The BDF replaces `y′` by `c·(y − ψ)` (ψ the predictor
//! history, `c = α₀/h`) and runs Newton on `F`, whose matrix is `∂F/∂y + c·∂F/∂y′`.

use nalgebra::{DMatrix, DVector};

/// How the integrator treats one component of `y`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VariableKind {
    /// A differential variable (positions, quaternions, velocities): in the local error test.
    Differential,
    /// A variable of DAE index `index` ≥ 2 in the sense of Hairer & Wanner (RADAU5's
    /// NIND2/NIND3), or a plain algebraic variable (`index` 1): excluded from the local error
    /// test, as Adams' index-3 formulation does. In Adams' I3 formulation the Lagrange
    /// multipliers have index 3 and the velocities index 2 (so only displacements are
    /// error-tested); quaternion-norm multipliers have index 3. The integrator multiplies the
    /// variable's Newton column by `h^(1 − index)` and then equilibrates the rows, which keeps
    /// the matrix O(1) as `h → 0` (Bottasso, Bauchau & Cardona 2007); with
    /// `CORRECTOR=ORIGINAL` its Newton corrections are weighted by `h^(index − 1)`.
    /// Allowed range of `index`: 1..=3.
    Algebraic {
        /// The DAE index of the variable (1, 2 or 3).
        index: u8,
    },
}

/// How the integrator stores and factorises the Newton matrix of a system
/// ([`DaeSystem::newton_storage`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NewtonStorage {
    /// A dense `n × n` matrix and nalgebra's LU with partial pivoting: fastest for small
    /// systems, `n²` storage and `⅔n³` operations per factorisation.
    Dense,
    /// Triplets from [`DaeSystem::newton_entries`], compressed columns and a sparse LU (rsparse,
    /// a port of CSparse): storage and work grow with the nonzeros, for systems of many parts.
    Sparse,
}

/// Why the system could not evaluate its equations at the given point. Carries a message the
/// run's diagnosis prints (which element, which value), and whether a smaller step could help.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{element}: {message}")]
pub struct EvaluationError {
    /// The element that failed (e.g. `CONTACT/3`, `JOINT/12`, `SFORCE/4`).
    pub element: String,
    /// What went wrong.
    pub message: String,
    /// The state is one the model cannot represent whatever the step size (a part of a 2-D
    /// contact out of its plane): the integrator stops at once with
    /// `IntegratorError::Stopped` instead of retrying smaller steps. `false` for failures a
    /// smaller step may avoid (a Newton iterate that went too far).
    pub fatal: bool,
}

/// An implicit DAE `F(t, y, y′) = 0` of fixed size.
pub trait DaeSystem {
    /// The number of unknowns (= number of equations).
    fn size(&self) -> usize;

    /// The kind of each component of `y` (length [`Self::size`]).
    fn variable_kinds(&self) -> Vec<VariableKind>;

    /// The absolute part of each variable's error weight: the integrator tests
    /// `|e_i| / (ERROR·(|y_i| + s_i))`. The default, `s_i = 1` for every variable, is Adams'
    /// convention (ERROR absolute in model units). A model passes its characteristic length for
    /// displacements (and the matching scales for velocities and angles) so that the same model
    /// in millimetres or in metres is integrated to the same relative accuracy. Each `s_i` must
    /// be finite and > 0 (length [`Self::size`]).
    fn absolute_scales(&self) -> Vec<f64> {
        vec![1.0; self.size()]
    }

    /// Writes `F(t, y, y′)` into `out` (length [`Self::size`]).
    fn residual(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError>;

    /// Writes the Newton matrix `∂F/∂y + c·∂F/∂y′` at `(t, y, y′)` into `out`
    /// ([`Self::size`] square).
    fn newton_matrix(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError>;

    /// How the integrator should store this system's Newton matrix. The default,
    /// [`NewtonStorage::Dense`], suits small systems; a system that writes its entries
    /// sparse ([`Self::newton_entries`]) answers [`NewtonStorage::Sparse`] when it is large.
    fn newton_storage(&self) -> NewtonStorage {
        NewtonStorage::Dense
    }

    /// The threads the sparse Newton matrix may factorise independent blocks on (each block
    /// alone, so the factors are the same bits at every count). The default is serial.
    fn parallelism(&self) -> crate::parallel::Parallelism {
        crate::parallel::Parallelism::serial()
    }

    /// Pushes the entries of the Newton matrix `∂F/∂y + c·∂F/∂y′` at `(t, y, y′)` onto `out`
    /// as `(row, column, value)`; entries at the same place are summed, in the order pushed.
    /// Every entry that can be nonzero at this point is pushed (zeros included), so the
    /// pattern depends on the model's structure, not on values. The default assembles the
    /// dense matrix ([`Self::newton_matrix`]) and pushes every entry (all `n²`): correct, not
    /// fast; a system meant to run sparse writes its blocks directly.
    fn newton_entries(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        c: f64,
        out: &mut Vec<(usize, usize, f64)>,
    ) -> Result<(), EvaluationError> {
        let n = self.size();
        let mut dense = DMatrix::zeros(n, n);
        self.newton_matrix(t, y, yp, c, &mut dense)?;
        for j in 0..n {
            for i in 0..n {
                out.push((i, j, dense[(i, j)]));
            }
        }
        Ok(())
    }

    /// Called at the start of every step attempt (ending at `t_new`, size `h`), accepted or not,
    /// before any residual of that attempt: a system with state of its own that the corrector
    /// updates (augmented-Lagrangian multipliers) resets it here to its value at the last
    /// accepted step. The default does nothing.
    fn attempt_started(&mut self, _t_new: f64, _h: f64) {}

    /// Called when Newton has converged on a step attempt at `(t, y, y′)`, before the error
    /// test. A system with an inner iteration — SPEC §5's augmented Lagrangian,
    /// `λ ← max(0, λ + p·δ)` until the penetration is below its tolerance — updates its state
    /// here and returns `true` to have Newton run again on the updated equations from the
    /// current iterate; `false` accepts the corrector's result. The integrator allows MAXIT
    /// passes, then fails the attempt with `FailureCause::InnerIterations` (the step is retried
    /// smaller). The default returns `false`.
    fn corrector_converged(&mut self, _t: f64, _y: &DVector<f64>, _yp: &DVector<f64>) -> bool {
        false
    }

    /// Called by the integrator after each accepted step, so the system can update state that
    /// is not part of `y` (contact onset bookkeeping, augmented-Lagrangian multipliers, output).
    /// The default does nothing.
    fn step_accepted(&mut self, _t: f64, _y: &DVector<f64>, _yp: &DVector<f64>) {}
}
