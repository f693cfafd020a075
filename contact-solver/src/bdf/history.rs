//! The solution history as modified divided differences, and the fixed-leading-coefficient
//! BDF coefficients computed from it (the formulation of DASSL, Petzold 1982; Brenan, Campbell
//! & Petzold, *Numerical Solution of IVPs in DAEs*, SIAM 1996, §5.2).
//!
//! `phi[j]` holds the `j`-th modified divided difference of the solution, scaled by the product
//! of the last `j` step sizes, and `psi[i] = t_{n+1} − t_{n−i}` the distances to past points.
//! The predictor is the interpolating polynomial through the last `k+1` points,
//! `y⁽⁰⁾ = Σ_{j≤k} φ*_j`, `y′⁽⁰⁾ = Σ_{j≤k} γ_j φ*_j`; the corrector is
//! `y′ = y′⁽⁰⁾ + c·(y − y⁽⁰⁾)` with the *fixed leading coefficient* `c = −α_s/h`,
//! `α_s = −Σ_{j=1..k} 1/j`, the leading coefficient of the constant-step BDF of order `k`.
//! Because `c` depends on `h` and `k` only, the Newton matrix stays valid across steps of equal
//! size and order whatever the step history was — which is why this form suits runs whose steps
//! are cut short all the time (contact onset, output times).

use nalgebra::DVector;

/// Differences, step-size history and the coefficients of the current step.
#[derive(Debug, Clone)]
pub(super) struct History {
    /// Modified divided differences `φ_0 … φ_{kmax+1}`.
    pub phi: Vec<DVector<f64>>,
    /// `psi[i]`: distance from the new point back to the point `i+1` steps before it.
    pub psi: [f64; 8],
    alpha: [f64; 8],
    beta: [f64; 8],
    gamma: [f64; 8],
    /// `sigma[i]`: the factor that turns the `i+1`-th difference into an error estimate.
    pub sigma: [f64; 8],
    /// Order of the step being taken.
    pub k: usize,
    /// Order of the last accepted step (0 right after a restart).
    pub kold: usize,
    /// Size of the last accepted step (0 right after a restart).
    pub hold: f64,
    /// Number of steps taken at constant size and order, capped at `kold + 2`.
    pub ns: usize,
    /// The step size `φ_1 = h·y′` was built with after a restart.
    h_restart: f64,
}

/// The coefficients of one step attempt.
#[derive(Debug, Clone, Copy)]
pub(super) struct StepCoefficients {
    /// `c = −α_s/h`: `∂y′/∂y` of the corrector.
    pub cj: f64,
    /// `ck = max(|α_{k+1} + α_s − α⁰|, α_{k+1})`: turns the corrector change into the
    /// local error estimate of order `k`.
    pub ck: f64,
}

impl History {
    /// A history at order 1 from the point `(y, y′)` for a first step of size `h`:
    /// `φ_0 = y`, `φ_1 = h·y′`.
    pub fn restart(y: &DVector<f64>, yp: &DVector<f64>, h: f64, kmax: usize) -> Self {
        let n = y.len();
        let mut phi = vec![DVector::zeros(n); kmax + 2];
        phi[0].copy_from(y);
        phi[1] = yp * h;
        let mut psi = [0.0; 8];
        psi[0] = h;
        Self {
            phi,
            psi,
            alpha: [0.0; 8],
            beta: [0.0; 8],
            gamma: [0.0; 8],
            sigma: [0.0; 8],
            k: 1,
            kold: 0,
            hold: 0.0,
            ns: 0,
            h_restart: h,
        }
    }

    /// Computes the coefficients for a step of size `h` at order `self.k` and turns `φ` into
    /// the predicted differences `φ*` (DASSL block 2). Undo with [`History::restore`].
    pub fn begin_step(&mut self, h: f64) -> StepCoefficients {
        if self.kold == 0 && h != self.h_restart {
            // Right after a restart φ_1 = h·y′ was built for another h: rescale it.
            let ratio = h / self.h_restart;
            self.phi[1] *= ratio;
            self.psi[0] = h;
            self.h_restart = h;
        }
        let k = self.k;
        let kp1 = k + 1;
        if h != self.hold || k != self.kold {
            self.ns = 0;
        }
        self.ns = (self.ns + 1).min(self.kold + 2);
        if kp1 >= self.ns {
            self.beta[0] = 1.0;
            self.alpha[0] = 1.0;
            self.gamma[0] = 0.0;
            self.sigma[0] = 1.0;
            let mut temp1 = h;
            for i in 1..kp1 {
                let temp2 = self.psi[i - 1];
                self.psi[i - 1] = temp1;
                self.beta[i] = self.beta[i - 1] * self.psi[i - 1] / temp2;
                temp1 = temp2 + h;
                self.alpha[i] = h / temp1;
                self.sigma[i] = i as f64 * self.sigma[i - 1] * self.alpha[i];
                self.gamma[i] = self.gamma[i - 1] + self.alpha[i - 1] / h;
            }
            self.psi[k] = temp1;
        }
        let alphas: f64 = -(1..=k).map(|i| 1.0 / i as f64).sum::<f64>();
        let alpha0: f64 = -self.alpha[..k].iter().sum::<f64>();
        let cj = -alphas / h;
        let ck = (self.alpha[k] + alphas - alpha0).abs().max(self.alpha[k]);
        for j in self.ns..=k {
            let b = self.beta[j];
            self.phi[j] *= b;
        }
        StepCoefficients { cj, ck }
    }

    /// Undoes [`History::begin_step`] after a failed attempt of size `h` (DASSL block 6).
    pub fn restore(&mut self, h: f64) {
        let k = self.k;
        for j in self.ns..=k {
            let b = self.beta[j];
            self.phi[j] /= b;
        }
        for i in 1..=k {
            self.psi[i - 1] = self.psi[i] - h;
        }
    }

    /// The predictor: `y⁽⁰⁾ = Σ φ*_j`, `y′⁽⁰⁾ = Σ γ_j φ*_j`, `j ≤ k`.
    pub fn predict(&self, y: &mut DVector<f64>, yp: &mut DVector<f64>) {
        y.copy_from(&self.phi[0]);
        yp.fill(0.0);
        for j in 1..=self.k {
            y.axpy(1.0, &self.phi[j], 1.0);
            yp.axpy(self.gamma[j], &self.phi[j], 1.0);
        }
    }

    /// Folds the accepted correction `e = y − y⁽⁰⁾` into the differences, for a step taken at
    /// order `k` (DASSL's update after block 5).
    pub fn accept(&mut self, e: &DVector<f64>, k: usize, kmax: usize) {
        if k < kmax {
            self.phi[k + 1].copy_from(e);
        }
        self.phi[k] += e;
        for j in (0..k).rev() {
            let (lo, hi) = self.phi.split_at_mut(j + 1);
            lo[j] += &hi[0];
        }
    }

    /// Interpolates the solution at `t` from the differences of the last accepted step
    /// (DASSL's DDATRP): the polynomial of degree `kold` through the last `kold + 1` points,
    /// and its derivative. `t_now` is the time of the last accepted point.
    pub fn interpolate(&self, t_now: f64, t: f64, y: &mut DVector<f64>, yp: &mut DVector<f64>) {
        let dt = t - t_now;
        y.copy_from(&self.phi[0]);
        yp.fill(0.0);
        let mut c = 1.0;
        let mut d = 0.0;
        let mut gamma = dt / self.psi[0];
        for j in 1..=self.kold {
            d = d * gamma + c / self.psi[j - 1];
            c *= gamma;
            gamma = (dt + self.psi[j - 1]) / self.psi[j];
            y.axpy(c, &self.phi[j], 1.0);
            yp.axpy(d, &self.phi[j], 1.0);
        }
    }

    /// `sigma` of index `i`, the error-estimate factor of difference `i+1`.
    pub fn sigma(&self, i: usize) -> f64 {
        self.sigma[i]
    }
}
