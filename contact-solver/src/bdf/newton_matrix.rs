//! The scaled, factorised Newton matrix `∂F/∂y + c·∂F/∂y′`, kept across iterations and steps
//! (modified Newton).
//!
//! Scaling (Bottasso, Bauchau & Cardona, SIAM J. Sci. Comput. 29, 2007): the column of an
//! algebraic variable of DAE index `i` is multiplied by `h^(1−i)`, then every row is divided by
//! its largest entry. For an index-3 mechanism (`q` index 1, `v` index 2, `λ` index 3) this
//! turns the matrix `[cI, −I, 0; K, cM, Gᵀ; G, 0, 0]` into the O(1) matrix
//! `[αI, −I, 0; h²K, αM, Gᵀ; G, 0, 0]`, whose conditioning no longer grows like `h⁻³` as the
//! step shrinks. Scaling changes only the pivoting and round-off, never the solution.
//!
//! A system that asks for it ([`DaeSystem::newton_storage`]) has its matrix stored and
//! factorised sparse instead (`super::sparse_newton`, the same scaling); the dense buffer is
//! allocated only when the dense path is used.

use super::error::FailureCause;
use super::sparse_newton::SparseNewton;
use crate::{DaeSystem, NewtonStorage, VariableKind};
use nalgebra::{DMatrix, DVector, Dyn, LU};

/// A factorised, scaled Newton matrix and the `c` it was built with, dense or sparse as the
/// system asks ([`DaeSystem::newton_storage`]). The integrator owns one; it is public so that
/// one factorisation can be timed on its own (`benches/newton.rs`).
pub struct NewtonMatrix {
    buffer: DMatrix<f64>,
    lu: Option<LU<f64, Dyn, Dyn>>,
    row_scale: DVector<f64>,
    col_scale: DVector<f64>,
    /// The sparse path, when the system asks for it.
    sparse: Option<SparseNewton>,
    /// `c` at the last factorisation.
    pub cj: f64,
}

impl NewtonMatrix {
    /// An empty (not yet factorised) matrix of size `n`.
    pub fn new(n: usize) -> Self {
        Self {
            buffer: DMatrix::zeros(0, 0),
            lu: None,
            row_scale: DVector::from_element(n, 1.0),
            col_scale: DVector::from_element(n, 1.0),
            sparse: None,
            cj: 0.0,
        }
    }

    /// Whether a factorisation exists.
    pub fn is_factorised(&self) -> bool {
        match &self.sparse {
            Some(sparse) => sparse.is_factorised(),
            None => self.lu.is_some(),
        }
    }

    /// Drops the factorisation so the next iteration rebuilds it.
    pub fn invalidate(&mut self) {
        self.lu = None;
        if let Some(sparse) = &mut self.sparse {
            sparse.invalidate();
        }
    }

    /// Evaluates, scales and factorises the matrix at `(t, y, y′)` with coefficient `cj` and
    /// step size `h`.
    #[expect(
        clippy::too_many_arguments,
        reason = "the point, c, h and the classes are all needed"
    )]
    pub fn refresh(
        &mut self,
        system: &mut dyn DaeSystem,
        t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        cj: f64,
        h: f64,
        kinds: &[VariableKind],
    ) -> Result<(), FailureCause> {
        self.lu = None;
        if system.newton_storage() == NewtonStorage::Sparse {
            let sparse = self.sparse.get_or_insert_with(SparseNewton::default);
            sparse.refresh(system, t, y, yp, cj, h, kinds)?;
            self.cj = cj;
            return Ok(());
        }
        self.sparse = None;
        let n = y.len();
        if self.buffer.nrows() != n {
            self.buffer = DMatrix::zeros(n, n);
        }
        self.buffer.fill(0.0);
        system
            .newton_matrix(t, y, yp, cj, &mut self.buffer)
            .map_err(FailureCause::Evaluation)?;
        for (j, kind) in kinds.iter().enumerate() {
            let s = column_scale(*kind, h);
            self.col_scale[j] = s;
            if s != 1.0 {
                self.buffer.column_mut(j).scale_mut(s);
            }
        }
        for i in 0..n {
            let row_max = self
                .buffer
                .row(i)
                .iter()
                .fold(0.0_f64, |m, v| m.max(v.abs()));
            if !row_max.is_finite() {
                let index = (0..n)
                    .find(|&j| !self.buffer[(i, j)].is_finite())
                    .unwrap_or(i);
                return Err(FailureCause::NonFinite { index });
            }
            if row_max == 0.0 {
                return Err(FailureCause::SingularMatrix);
            }
            self.row_scale[i] = 1.0 / row_max;
            self.buffer.row_mut(i).scale_mut(1.0 / row_max);
        }
        let lu = self.buffer.clone().lu();
        if !lu.is_invertible() {
            return Err(FailureCause::SingularMatrix);
        }
        self.lu = Some(lu);
        self.cj = cj;
        Ok(())
    }

    /// Solves `J·Δ = r` in place (`r` in, `Δ` out) with the stored factorisation. Returns
    /// false if there is none or the solve failed.
    pub fn solve(&self, r: &mut DVector<f64>) -> bool {
        if let Some(sparse) = &self.sparse {
            return sparse.solve(r);
        }
        let Some(lu) = &self.lu else { return false };
        r.component_mul_assign(&self.row_scale);
        if !lu.solve_mut(r) {
            return false;
        }
        r.component_mul_assign(&self.col_scale);
        true
    }
}

/// The index-3 column scale of a variable for step size `h`: 1 for a differential one,
/// `h^(1 − index)` for an algebraic one of that index (multipliers of position constraints
/// scaled by `h²`), the same for the dense and the sparse matrix.
pub(super) fn column_scale(kind: VariableKind, h: f64) -> f64 {
    match kind {
        VariableKind::Differential => 1.0,
        VariableKind::Algebraic { index } => h.powi(1 - i32::from(index)),
    }
}
