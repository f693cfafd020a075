//! Weighted RMS norms: the local error test over differential variables, and the Newton
//! convergence test over the variables the CORRECTOR setting names.

use super::error::Dominant;
use super::settings::Corrector;
use crate::VariableKind;
use nalgebra::DVector;

/// Tolerance weights and the variable classes they apply to.
#[derive(Debug, Clone)]
pub(super) struct Norms {
    kinds: Vec<VariableKind>,
    /// `w_i = ERROR·(|y_i| + s_i)`: relative tolerance ERROR, absolute ERROR·s_i.
    weights: DVector<f64>,
    /// The absolute scales `s_i` ([`DaeSystem::absolute_scales`](crate::DaeSystem::absolute_scales)).
    scales: DVector<f64>,
    error: f64,
    differential_count: usize,
    /// Whether any variable has index 3 (an index-3 mechanism, whose index-2 variables are
    /// the velocities).
    has_index_three: bool,
    /// See [`Norms::test_index_two`].
    index_two: bool,
}

impl Norms {
    /// Norms for the given variable kinds and tolerance.
    pub fn new(kinds: Vec<VariableKind>, scales: DVector<f64>, error: f64) -> Self {
        let n = kinds.len();
        let differential_count = kinds
            .iter()
            .filter(|k| matches!(k, VariableKind::Differential))
            .count();
        let has_index_three = kinds
            .iter()
            .any(|k| matches!(k, VariableKind::Algebraic { index: 3 }));
        Self {
            kinds,
            weights: DVector::from_element(n, error),
            scales,
            error,
            differential_count,
            has_index_three,
            index_two: false,
        }
    }

    /// Recomputes the weights from the solution at the start of a step.
    pub fn set_weights(&mut self, y: &DVector<f64>) {
        for ((w, yi), s) in self
            .weights
            .iter_mut()
            .zip(y.iter())
            .zip(self.scales.iter())
        {
            *w = self.error * (yi.abs() + s);
        }
    }

    /// The factor a variable's weighted value is multiplied by in the convergence test, or
    /// `None` when the variable does not take part.
    fn convergence_factor(&self, i: usize, h: f64, corrector: Corrector) -> Option<f64> {
        match (self.kinds[i], corrector) {
            (VariableKind::Differential, _) => Some(1.0),
            (VariableKind::Algebraic { index: 2 }, Corrector::Modified)
                if self.differential_count > 0 && self.has_index_three && self.index_two =>
            {
                Some(1.0)
            }
            (VariableKind::Algebraic { .. }, Corrector::Modified)
                if self.differential_count > 0 =>
            {
                None
            }
            (VariableKind::Algebraic { index }, _) => Some(h.powi(i32::from(index) - 1)),
        }
    }

    /// Whether [`Corrector::Modified`] tests the index-2 variables of a system with index-3
    /// ones (the velocities of a mechanism under I3) as well, unscaled: the integrator asks
    /// for it in steps HMAX holds below the error-controlled size, where corrector errors of
    /// the velocities would otherwise accumulate over many steps into the positions.
    pub fn test_index_two(&mut self, on: bool) {
        self.index_two = on;
    }

    /// Weighted RMS of `v` over the differential variables (0 when there are none): the local
    /// error test's norm. Algebraic variables never enter it (Adams I3).
    pub fn error_norm(&self, v: &DVector<f64>) -> f64 {
        if self.differential_count == 0 {
            return 0.0;
        }
        let mut sum = 0.0;
        for (i, kind) in self.kinds.iter().enumerate() {
            if matches!(kind, VariableKind::Differential) {
                let r = v[i] / self.weights[i];
                sum += r * r;
            }
        }
        (sum / self.differential_count as f64).sqrt()
    }

    /// Weighted RMS of a Newton correction over the variables the corrector tests: all of
    /// them with algebraic ones scaled by `h^(index−1)` ([`Corrector::Full`]), or the
    /// differential ones only, with the index-2 ones when [`Norms::test_index_two`] asks
    /// ([`Corrector::Modified`]; all if nothing is differential).
    pub fn convergence_norm(&self, v: &DVector<f64>, h: f64, corrector: Corrector) -> f64 {
        let mut sum = 0.0;
        let mut count = 0usize;
        for i in 0..v.len() {
            if let Some(f) = self.convergence_factor(i, h, corrector) {
                let r = f * v[i] / self.weights[i];
                sum += r * r;
                count += 1;
            }
        }
        if count == 0 {
            0.0
        } else {
            (sum / count as f64).sqrt()
        }
    }

    /// The three largest weighted entries of `v` over the error-test variables
    /// (`convergence = false`) or the convergence-test variables.
    pub fn dominant(
        &self,
        v: &DVector<f64>,
        h: f64,
        corrector: Corrector,
        convergence: bool,
    ) -> Vec<Dominant> {
        let mut all: Vec<Dominant> = (0..v.len())
            .filter_map(|i| {
                let factor = if convergence {
                    self.convergence_factor(i, h, corrector)?
                } else if matches!(self.kinds[i], VariableKind::Differential) {
                    1.0
                } else {
                    return None;
                };
                Some(Dominant {
                    index: i,
                    weighted: (factor * v[i] / self.weights[i]).abs(),
                })
            })
            .collect();
        all.sort_by(|a, b| b.weighted.total_cmp(&a.weighted));
        all.truncate(3);
        all
    }

    /// The kinds of the variables.
    pub fn kinds(&self) -> &[VariableKind] {
        &self.kinds
    }
}
