//! Reference problems with published solutions or closed forms, shared by the integrator's
//! tests and benches: `y′ = λy`, Robertson, Van der Pol, the index-3 pendulum and Andrews'
//! squeezing mechanism. Each implements [`DaeSystem`] with an analytic Newton matrix unless
//! noted.

mod andrews;

pub use andrews::{ANDREWS_ANGLES_AT_0_03, Andrews};

use crate::{DaeSystem, EvaluationError, VariableKind};
use nalgebra::{DMatrix, DVector};

/// `y′ = λ·y` as `F = y′ − λ·y`; exact solution `y0·e^{λt}`.
pub struct Linear {
    /// The rate λ (any finite value; negative decays).
    pub lambda: f64,
}

impl DaeSystem for Linear {
    fn size(&self) -> usize {
        1
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        out[0] = yp[0] - self.lambda * y[0];
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        _y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        out[(0, 0)] = c - self.lambda;
        Ok(())
    }
}

/// Robertson's chemical kinetics (Hairer & Wanner II, §IV.1), stiff:
/// `y1′ = −0.04·y1 + 1e4·y2·y3`, `y2′ = 0.04·y1 − 1e4·y2·y3 − 3e7·y2²`, `y3′ = 3e7·y2²`,
/// `y(0) = (1, 0, 0)`. With `as_dae` the third equation is the conservation law
/// `y1 + y2 + y3 − 1 = 0` and `y3` is algebraic (index 1), as in the DAE form of the problem.
pub struct Robertson {
    /// Use the conservation law instead of the third rate equation.
    pub as_dae: bool,
}

/// Robertson at `t = 1e11`, from the Bari IVP test set (`rober`, computed with RADAU5 at
/// tolerance 1e-14): Mazzia & Magherini, *Test Set for IVP Solvers*, release 2.4.
pub const ROBERTSON_T_1E11: [f64; 3] = [
    0.2083340149701255e-7,
    0.8333360770334713e-13,
    0.999999979166505,
];

impl DaeSystem for Robertson {
    fn size(&self) -> usize {
        3
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        let third = if self.as_dae {
            VariableKind::Algebraic { index: 1 }
        } else {
            VariableKind::Differential
        };
        vec![
            VariableKind::Differential,
            VariableKind::Differential,
            third,
        ]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        let (y1, y2, y3) = (y[0], y[1], y[2]);
        out[0] = yp[0] + 0.04 * y1 - 1e4 * y2 * y3;
        out[1] = yp[1] - 0.04 * y1 + 1e4 * y2 * y3 + 3e7 * y2 * y2;
        out[2] = if self.as_dae {
            y1 + y2 + y3 - 1.0
        } else {
            yp[2] - 3e7 * y2 * y2
        };
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        let (y2, y3) = (y[1], y[2]);
        out.fill(0.0);
        out[(0, 0)] = c + 0.04;
        out[(0, 1)] = -1e4 * y3;
        out[(0, 2)] = -1e4 * y2;
        out[(1, 0)] = -0.04;
        out[(1, 1)] = c + 1e4 * y3 + 6e7 * y2;
        out[(1, 2)] = 1e4 * y2;
        if self.as_dae {
            out[(2, 0)] = 1.0;
            out[(2, 1)] = 1.0;
            out[(2, 2)] = 1.0;
        } else {
            out[(2, 1)] = -6e7 * y2;
            out[(2, 2)] = c;
        }
        Ok(())
    }
}

/// Van der Pol in the test set's scaled form (`vdpol`, ε = 1e-6, i.e. μ = 1000 in rescaled
/// time): `y1′ = y2`, `ε·y2′ = (1 − y1²)·y2 − y1`, `y(0) = (2, −2/3)`, on `[0, 2]`.
pub struct VanDerPol {
    /// The stiffness parameter ε > 0 (the test set uses 1e-6).
    pub epsilon: f64,
}

/// Van der Pol at `t = 2` (test set `vdpol`, ε = 1e-6, reference computed by the test set's
/// authors at tolerance 1e-14). The R port of the test set prints `y2` with exponent `e-3`;
/// `y2` must lie on the slow manifold `y2 ≈ y1/(1 − y1²) = −0.89281` at this `y1`, so the
/// exponent there is a misprint and the value is taken as `−0.8928…e0`.
pub const VAN_DER_POL_T2: [f64; 2] = [0.1706167732170469e1, -0.8928097010248125];

impl DaeSystem for VanDerPol {
    fn size(&self) -> usize {
        2
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![VariableKind::Differential; 2]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        out[0] = yp[0] - y[1];
        out[1] = self.epsilon * yp[1] - ((1.0 - y[0] * y[0]) * y[1] - y[0]);
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        out[(0, 0)] = c;
        out[(0, 1)] = -1.0;
        out[(1, 0)] = 2.0 * y[0] * y[1] + 1.0;
        out[(1, 1)] = self.epsilon * c - (1.0 - y[0] * y[0]);
        Ok(())
    }
}

/// A planar pendulum in Cartesian coordinates, index 3 (Adams' I3 form): a point mass `m` on a
/// massless rod of length `l` from the origin, gravity `−g` along y.
/// `y = (x, y, vx, vy, λ)`; `F = (x′ − vx, y′ − vy, m·vx′ + 2xλ, m·vy′ + 2yλ + m·g,
/// x² + y² − l²)`. Positions differential, velocities index 2, λ index 3.
pub struct Pendulum {
    /// Point mass m > 0.
    pub mass: f64,
    /// Rod length l > 0.
    pub length: f64,
    /// Gravity g (downward, along −y).
    pub gravity: f64,
}

impl Pendulum {
    /// A consistent state at rest at angle `theta0` from the downward vertical, and its
    /// derivative.
    pub fn at_rest(&self, theta0: f64) -> (DVector<f64>, DVector<f64>) {
        let (m, l, g) = (self.mass, self.length, self.gravity);
        let (x, y) = (l * theta0.sin(), -l * theta0.cos());
        // Rod tension T = m·g·cos θ0 at rest; the force on the mass is −2λ·(x, y), so λ = T/(2l).
        let lambda = m * g * theta0.cos() / (2.0 * l);
        let y0 = DVector::from_vec(vec![x, y, 0.0, 0.0, lambda]);
        let yp0 = DVector::from_vec(vec![
            0.0,
            0.0,
            -2.0 * x * lambda / m,
            -2.0 * y * lambda / m - g,
            0.0,
        ]);
        (y0, yp0)
    }

    /// Kinetic plus potential energy.
    pub fn energy(&self, y: &DVector<f64>) -> f64 {
        0.5 * self.mass * (y[2] * y[2] + y[3] * y[3]) + self.mass * self.gravity * y[1]
    }
}

impl DaeSystem for Pendulum {
    fn size(&self) -> usize {
        5
    }
    fn variable_kinds(&self) -> Vec<VariableKind> {
        vec![
            VariableKind::Differential,
            VariableKind::Differential,
            VariableKind::Algebraic { index: 2 },
            VariableKind::Algebraic { index: 2 },
            VariableKind::Algebraic { index: 3 },
        ]
    }
    fn residual(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        yp: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), EvaluationError> {
        let (m, l, g) = (self.mass, self.length, self.gravity);
        out[0] = yp[0] - y[2];
        out[1] = yp[1] - y[3];
        out[2] = m * yp[2] + 2.0 * y[0] * y[4];
        out[3] = m * yp[3] + 2.0 * y[1] * y[4] + m * g;
        out[4] = y[0] * y[0] + y[1] * y[1] - l * l;
        Ok(())
    }
    fn newton_matrix(
        &mut self,
        _t: f64,
        y: &DVector<f64>,
        _yp: &DVector<f64>,
        c: f64,
        out: &mut DMatrix<f64>,
    ) -> Result<(), EvaluationError> {
        let m = self.mass;
        out.fill(0.0);
        out[(0, 0)] = c;
        out[(0, 2)] = -1.0;
        out[(1, 1)] = c;
        out[(1, 3)] = -1.0;
        out[(2, 0)] = 2.0 * y[4];
        out[(2, 2)] = m * c;
        out[(2, 4)] = 2.0 * y[0];
        out[(3, 1)] = 2.0 * y[4];
        out[(3, 3)] = m * c;
        out[(3, 4)] = 2.0 * y[1];
        out[(4, 0)] = 2.0 * y[0];
        out[(4, 1)] = 2.0 * y[1];
        Ok(())
    }
}

/// The exact period of a pendulum released at rest from `theta0`:
/// `T = 4·sqrt(l/g)·K(sin(θ0/2))`, with the complete elliptic integral of the first kind
/// `K(k) = π / (2·AGM(1, sqrt(1 − k²)))` (arithmetic-geometric mean).
pub fn pendulum_period(length: f64, gravity: f64, theta0: f64) -> f64 {
    let k = (theta0 / 2.0).sin();
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    while (a - b).abs() > 1e-16 * a {
        let next = ((a + b) / 2.0, (a * b).sqrt());
        a = next.0;
        b = next.1;
    }
    let elliptic_k = std::f64::consts::PI / (2.0 * a);
    4.0 * (length / gravity).sqrt() * elliptic_k
}

/// A Newton matrix by forward differences of the residual, column by column (`size + 1`
/// residual evaluations), for checking an analytic matrix or for small test systems:
/// `(F(y + δ_j e_j, y′ + c·δ_j e_j) − F(y, y′))/δ_j`, `δ_j = sqrt(ε)·max(|y_j|, 1)`.
pub fn difference_newton_matrix(
    system: &mut dyn DaeSystem,
    t: f64,
    y: &DVector<f64>,
    yp: &DVector<f64>,
    c: f64,
    out: &mut DMatrix<f64>,
) -> Result<(), EvaluationError> {
    let n = y.len();
    let mut f0 = DVector::zeros(n);
    system.residual(t, y, yp, &mut f0)?;
    let mut f1 = DVector::zeros(n);
    let (mut yj, mut ypj) = (y.clone(), yp.clone());
    for j in 0..n {
        let delta = f64::EPSILON.sqrt() * y[j].abs().max(1.0);
        yj[j] = y[j] + delta;
        ypj[j] = yp[j] + c * delta;
        system.residual(t, &yj, &ypj, &mut f1)?;
        out.column_mut(j).copy_from(&((&f1 - &f0) / delta));
        yj[j] = y[j];
        ypj[j] = yp[j];
    }
    Ok(())
}
