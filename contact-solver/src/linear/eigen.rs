//! The state matrix of the reduced linear system and its eigenvalues.

use super::LinearError;
use nalgebra::{Complex, DMatrix, Schur};

/// One eigenvalue `s = σ + iω_d` of the linearized system, with what it means for the motion.
///
/// A mode behaves as `e^{st}`: σ < 0 decays, σ > 0 grows (an unstable equilibrium), ω_d ≠ 0
/// oscillates. For a mode of `m ẍ + c ẋ + k x = 0` with `k > 0`,
/// `s = −ζω_n ± iω_n√(1 − ζ²)`: `|s| = ω_n` whatever the damping, and `ζ = −σ/|s|`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Eigenvalue {
    /// The real part σ, 1/time.
    pub real: f64,
    /// The imaginary part ω_d, radians per time (positive first within a conjugate pair).
    pub imaginary: f64,
    /// The undamped natural frequency `|s|/(2π)`, cycles per model time unit (Hz when the
    /// model's time is seconds).
    pub frequency: f64,
    /// The damping ratio `ζ = −σ/|s|` (1 for a real decaying mode, −1 for a real growing one,
    /// negative for any growing mode); `None` for `s = 0`, a free or neutral motion, where it is
    /// not defined.
    pub damping_ratio: Option<f64>,
}

impl Eigenvalue {
    /// The eigenvalue `real + i·imaginary` with its frequency and damping ratio.
    pub fn new(real: f64, imaginary: f64) -> Self {
        let magnitude = real.hypot(imaginary);
        // `+ 0.0` turns a −0 into 0, so a zero eigenvalue prints as one.
        Self {
            real: real + 0.0,
            imaginary: imaginary + 0.0,
            frequency: magnitude / (2.0 * std::f64::consts::PI),
            damping_ratio: (magnitude > 0.0).then(|| -real / magnitude),
        }
    }

    /// `|s|`, the undamped natural frequency in radians per time.
    pub fn magnitude(&self) -> f64 {
        self.real.hypot(self.imaginary)
    }
}

/// The eigenvalues of a real matrix (`values` closed under conjugation, as a real Schur form
/// gives them: each complex pair from one 2 × 2 block, exact conjugates) as [`Eigenvalue`]s,
/// sorted by natural frequency `|s|`, then by real part, each conjugate pair kept together
/// with its positive imaginary part first.
///
/// Only the members with a positive imaginary part are read for the complex values (each
/// stands for its pair), so pairing never depends on a tie in the sort.
pub fn sorted_eigenvalues(values: &[Complex<f64>]) -> Vec<Eigenvalue> {
    let mut modes: Vec<Eigenvalue> = values
        .iter()
        .filter(|s| s.im >= 0.0)
        .map(|s| Eigenvalue::new(s.re, s.im))
        .collect();
    modes.sort_by(|a, b| {
        a.magnitude()
            .total_cmp(&b.magnitude())
            .then(a.real.total_cmp(&b.real))
            .then(a.imaginary.total_cmp(&b.imaginary))
    });
    let mut out = Vec::with_capacity(values.len());
    for mode in modes {
        out.push(mode);
        if mode.imaginary > 0.0 {
            out.push(Eigenvalue::new(mode.real, -mode.imaginary));
        }
    }
    debug_assert_eq!(
        out.len(),
        values.len(),
        "values not closed under conjugation"
    );
    out
}

/// `A = [[0, I], [−L⁻¹K L⁻ᵀ, −L⁻¹C L⁻ᵀ]]` with `M = LLᵀ` (Cholesky): the first-order form of
/// `M z̈ + C ż + K z = 0` in `w = Lᵀz`, similar to `[[0, I], [−M⁻¹K, −M⁻¹C]]` and better
/// balanced (every entry of the lower blocks has units of 1/time² or 1/time).
pub(super) fn state_matrix(
    mass: &DMatrix<f64>,
    damping: &DMatrix<f64>,
    stiffness: &DMatrix<f64>,
) -> Result<DMatrix<f64>, LinearError> {
    let d = mass.nrows();
    let singular = LinearError::SingularMass { dimension: d };
    let l = mass.clone().cholesky().ok_or(singular.clone())?.unpack();
    // L⁻¹ X L⁻ᵀ = (L⁻¹ (L⁻¹ X)ᵀ)ᵀ.
    let congruent = |x: &DMatrix<f64>| -> Option<DMatrix<f64>> {
        let left = l.solve_lower_triangular(x)?;
        Some(l.solve_lower_triangular(&left.transpose())?.transpose())
    };
    let k = congruent(stiffness).ok_or(singular.clone())?;
    let c = congruent(damping).ok_or(singular)?;
    let mut a = DMatrix::zeros(2 * d, 2 * d);
    a.view_mut((0, d), (d, d)).fill_with_identity();
    a.view_mut((d, 0), (d, d)).copy_from(&(-k));
    a.view_mut((d, d), (d, d)).copy_from(&(-c));
    Ok(a)
}

/// The eigenvalues of `a` by the real Schur decomposition (Francis double-shift QR, at most
/// `30` iterations per eigenvalue, LAPACK's budget, plus 100), sorted by
/// [`sorted_eigenvalues`]. An empty matrix has none.
pub(super) fn eigenvalues_of(a: DMatrix<f64>) -> Result<Vec<Eigenvalue>, LinearError> {
    let dimension = a.nrows();
    if dimension == 0 {
        return Ok(Vec::new());
    }
    let iterations = 30 * dimension + 100;
    let values = Schur::try_new(a, f64::EPSILON, iterations)
        .map(|schur| schur.complex_eigenvalues())
        .filter(|values| values.iter().all(|s| s.re.is_finite() && s.im.is_finite()))
        .ok_or(LinearError::EigenvaluesNotConverged {
            dimension,
            iterations,
        })?;
    Ok(sorted_eigenvalues(values.as_slice()))
}
