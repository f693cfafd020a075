//! Linearization: the eigenvalues of the multibody equations about an operating point (Adams
//! LINEAR/EIGENSOL).
//!
//! The operating point is a state `y` at time `t`: normally a static equilibrium from
//! [`crate::statics`], or the state a run has reached. About it the dynamic rows of the
//! multibody DAE (solver-notes §2.3), `M v̇ + Φ_vᵀλ − Q(q, v, t) + gyro(v) = 0` with the
//! constraints `Φ(q, t) = 0`, are expanded to first order in virtual displacements
//! `δq = [δr, δθ′]` per part (world translation, body-frame rotation, the coordinates the static
//! Newton uses) and velocity perturbations `δv = [δu, δω′]`:
//!
//! ```text
//! M δv̇ + C δv + K δq + Φ_vᵀ δλ = 0,     Φ_v δq = 0,     δq̇ = δv
//! M = diag(m I, J)                       (per part)
//! C = ∂(ω′ × Jω′ − Q)/∂v                 (gyroscopic coupling, damping of forces and contacts)
//! K = ∂(Φ_vᵀλ − Q)/∂q                    (force-element stiffness and the geometric stiffness
//!                                         of the constraint reactions)
//! ```
//!
//! `K` is the static Jacobian of [`crate::statics::newton::static_jacobian`] and `C`
//! the velocity columns of the integrator's Newton matrix at `c = 0`
//! ([`MultibodySystem::compute_newton_matrix`]): the same blocks the integrator and the statics
//! use, with one difference: here a force element whose analytic partials are approximate is
//! differenced element-locally ([`crate::mbs::ForcePartials::Exact`]), since the
//! eigenvalues are the answer: the contacts' analytic partials hold the contact geometry
//! frozen, good enough for Newton, but leave out how the contact point and normal move with the
//! pose. A CONTACT acts through `∂Q/∂q` and `∂Q/∂v`: one in contact at the
//! operating point adds its normal stiffness `dFn/dδ` (the high frequency the Adams CONTACT
//! document describes) and its damping; one out of contact exerts no force whatever the
//! perturbation and adds nothing.
//!
//! **Constraint projection.** With `N` an orthonormal basis of the null space of `Φ_v`
//! (`Φ_v N = 0`, from an SVD, see [`null_space_basis`]), every admissible perturbation is
//! `δq = N z`; premultiplying by `Nᵀ` removes the reactions `Φ_vᵀδλ`:
//!
//! ```text
//! M_r z̈ + C_r ż + K_r z = 0,    M_r = NᵀMN,  C_r = NᵀCN,  K_r = NᵀKN
//! A = [[0, I], [−M_r⁻¹K_r, −M_r⁻¹C_r]]
//! ```
//!
//! The eigenvalues of `A` are those of the linearized motion (ODE-form, so no algebraic
//! constraint is left, unlike eigen-solvers that need an unconstrained system). They are
//! computed on the similar matrix with `M_r = LLᵀ` and `w = Lᵀz` (`L⁻¹K_rL⁻ᵀ` and
//! `L⁻¹C_rL⁻ᵀ` in place of `M_r⁻¹K_r`, `M_r⁻¹C_r`), whose entries all have units of 1/time or
//! 1/time², by nalgebra's real Schur decomposition ([`nalgebra::Schur`]).
//!
//! The multipliers λ of the operating point are computed, not taken from `y`: the minimum-norm
//! solution of `[M Φ_vᵀ; Φ_v 0][v̇; λ] = [Q − ω′×Jω′; γ]` (at an equilibrium `v̇ = 0` and λ is
//! the static one; redundant constraints get the least-norm λ, which has the same reactions
//! `Φ_vᵀλ`).
//!
//! **Moving operating points.** The kinematic relation used, `δq̇ = δv`, is exact for parts at
//! rest; for a part turning at ω′ the exact relation has an extra `−ω̃′ δθ′`, and the velocity
//! constraints an extra `∂(Φ_v v)/∂q δq`. Both vanish at an equilibrium, the operating point
//! LINEAR is meant for; at a moving state the result is the linearization with those terms
//! left out (the gyroscopic coupling `∂(ω′ × Jω′)/∂ω′` is kept in `C`).

mod eigen;
mod matrices;

#[cfg(test)]
mod tests;

pub use eigen::{Eigenvalue, sorted_eigenvalues};
pub use matrices::{OperatingMatrices, compute_operating_matrices, null_space_basis};

use crate::dae::EvaluationError;
use crate::mbs::MultibodySystem;
use nalgebra::{DMatrix, DVector};

/// What a linearization takes besides the operating point (Adams LINEAR/EIGENSOL options).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LinearSettings {
    /// Keep the damping matrix `C` (false: LINEAR/EIGENSOL, NODAMPIN — the undamped eigenvalues
    /// `±i·ω` of `M_r z̈ + K_r z = 0`).
    pub damping: bool,
}

impl Default for LinearSettings {
    /// Damping kept, as Adams does without NODAMPIN.
    fn default() -> Self {
        Self { damping: true }
    }
}

/// The linearized system at an operating point and its eigenvalues.
#[derive(Debug, Clone, PartialEq)]
pub struct Linearization {
    /// The time of the operating point.
    pub t: f64,
    /// The degrees of freedom `d = 6n − rank(Φ_v)`: the columns of `N`.
    pub degrees_of_freedom: usize,
    /// The reduced mass matrix `M_r = NᵀMN` (d × d).
    pub mass: DMatrix<f64>,
    /// The reduced damping matrix `C_r = NᵀCN` (zero with NODAMPIN).
    pub damping: DMatrix<f64>,
    /// The reduced stiffness matrix `K_r = NᵀKN`.
    pub stiffness: DMatrix<f64>,
    /// The `2d` eigenvalues of `A`, sorted as [`sorted_eigenvalues`] does.
    pub eigenvalues: Vec<Eigenvalue>,
}

/// Why a linearization failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LinearError {
    /// `y` does not have the system's length.
    #[error("the operating point has {given} values, the system {expected}")]
    WrongLength {
        /// The length of `y`.
        given: usize,
        /// [`crate::mbs::StateLayout::size`].
        expected: usize,
    },
    /// A coordinate, a velocity or the time of the operating point is not finite.
    #[error("the operating point at t = {t} is not finite (entry {index} of y is {value})")]
    NonFiniteState {
        /// The time.
        t: f64,
        /// The first offending index of `y` (`usize::MAX` for the time itself).
        index: usize,
        /// Its value.
        value: f64,
    },
    /// An element could not be evaluated at the operating point.
    #[error(transparent)]
    Evaluation(#[from] EvaluationError),
    /// The multipliers of the operating point could not be solved for.
    #[error(
        "the constraint multipliers at t = {t} cannot be computed: [M Φ_vᵀ; Φ_v 0] has no finite least-squares solution"
    )]
    Multipliers {
        /// The time.
        t: f64,
    },
    /// The reduced mass matrix `NᵀMN` is not positive definite: a direction of motion the
    /// constraints allow carries no mass or inertia.
    #[error(
        "the reduced mass matrix NᵀMN ({dimension} × {dimension}) is not positive definite: a free direction has no mass or inertia"
    )]
    SingularMass {
        /// The degrees of freedom.
        dimension: usize,
    },
    /// A reduced matrix has a non-finite entry (a force element's partials blew up).
    #[error("the reduced {matrix} matrix has a non-finite entry at the operating point")]
    NonFiniteMatrix {
        /// `stiffness` or `damping`.
        matrix: &'static str,
    },
    /// The real Schur decomposition did not converge within its iteration limit.
    #[error(
        "the eigenvalues of the {dimension} × {dimension} state matrix did not converge in {iterations} QR iterations"
    )]
    EigenvaluesNotConverged {
        /// The size of `A`.
        dimension: usize,
        /// The iteration limit.
        iterations: usize,
    },
}

/// Linearizes `system` about the positions and velocities of `y` at time `t` and returns the
/// reduced matrices and the eigenvalues (module docs for the formulas).
///
/// The positions of `y` should satisfy the constraints (an assembled state, an equilibrium, a
/// state of a run); its multipliers are not read (they are solved for). A model without
/// degrees of freedom gives no eigenvalues.
pub fn linearize(
    system: &mut MultibodySystem,
    t: f64,
    y: &DVector<f64>,
    settings: &LinearSettings,
) -> Result<Linearization, LinearError> {
    // The eigenvalues are the answer here, not a Newton matrix: elements whose analytic
    // partials are approximate are differenced, so a contact's stiffness includes how its
    // point and normal move with the pose (the frozen-geometry analytic contact partials leave
    // that out; a faceted ball rocking on its facets is the case that shows it).
    let source = system.force_partials();
    system.set_force_partials(crate::mbs::ForcePartials::Exact);
    let matrices = compute_operating_matrices(system, t, y);
    system.set_force_partials(source);
    let matrices = matrices?;
    let basis = null_space_basis(&matrices.constraint_jacobian, system.length_scale());
    let degrees_of_freedom = basis.ncols();
    let project = |matrix: &DMatrix<f64>| basis.transpose() * matrix * &basis;
    let mass = project(&matrices.mass);
    let stiffness = project(&matrices.stiffness);
    let damping = if settings.damping {
        project(&matrices.damping)
    } else {
        DMatrix::zeros(degrees_of_freedom, degrees_of_freedom)
    };
    for (name, matrix) in [("stiffness", &stiffness), ("damping", &damping)] {
        if !matrix.iter().all(|x| x.is_finite()) {
            return Err(LinearError::NonFiniteMatrix { matrix: name });
        }
    }
    let state = eigen::state_matrix(&mass, &damping, &stiffness)?;
    let eigenvalues = eigen::eigenvalues_of(state)?;
    Ok(Linearization {
        t,
        degrees_of_freedom,
        mass,
        damping,
        stiffness,
        eigenvalues,
    })
}
