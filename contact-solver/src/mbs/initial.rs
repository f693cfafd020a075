//! Consistent initial conditions: assembly, velocity projection, accelerations and multipliers.
//!
//! 1. **Assembly**: Gauss–Newton on `Φ(q, t₀) = 0` with the minimum-norm step
//!    `Δx = −Φ_v⁺ Φ` in virtual displacements (SVD pseudo-inverse), so the user's positions move
//!    as little as possible, halved until the scaled merit `Σ (Φ_k/s_k)²` decreases
//!    (`s_k = L` for lengths, 1 for angles); converged when every length row is within
//!    `1e-10·L` and every angle row within `1e-10`. No decrease means the joints cannot close.
//! 2. **Velocities**: the minimum-norm correction `v = v₀ − Φ_v⁺(Φ_v v₀ + Φ_t)`.
//! 3. **Accelerations and multipliers**: `[M Φ_vᵀ; Φ_v 0] [v̇; λ] = [Q − ω′×Jω′; γ]` with
//!    `γ = −Φ_tt − (dΦ_v/dt) v`; the last term is a central difference of `Φ_v v` along the
//!    motion. Redundant equations were removed when the system was built
//!    ([`MultibodySystem::redundant_equations`]); a singular matrix here is an error.

use super::error::MbsError;
use super::part::PartId;
use super::quaternion::{g_matrix, parameters_of};
use super::system::MultibodySystem;
use nalgebra::{DMatrix, DVector, Matrix3, UnitQuaternion};

/// Consistent `(y, y′)` at the initial time, ready for the integrator.
#[derive(Debug, Clone, PartialEq)]
pub struct InitialState {
    /// The state: assembled positions, projected velocities, multipliers, `μ = 0`.
    pub y: DVector<f64>,
    /// Its derivative: `ṙ = u`, `ė = ½Gᵀω′`, `v̇` from the dynamics, `λ̇ = μ̇ = 0`.
    pub yp: DVector<f64>,
    /// Gauss–Newton iterations the assembly took (0 when the positions already fit).
    pub assembly_iterations: usize,
}

/// The largest number of assembly iterations.
const MAX_ASSEMBLY_ITERATIONS: usize = 50;
/// Relative tolerance of the assembled constraints.
const ASSEMBLY_TOLERANCE: f64 = 1e-10;

/// The minimum-norm least-squares solution of `A x = b` by SVD, singular values below
/// `1e-12·σ_max` treated as zero (redundant rows then cost nothing); `None` if `A` has no
/// nonzero singular value or the result is not finite.
fn minimum_norm_solution(matrix: DMatrix<f64>, rhs: &DVector<f64>) -> Option<DVector<f64>> {
    let svd = matrix.svd(true, true);
    let largest = svd.singular_values.max();
    if !(largest.is_finite() && largest > 0.0) {
        return None;
    }
    svd.solve(rhs, 1e-12 * largest)
        .ok()
        .filter(|x| x.iter().all(|v| v.is_finite()))
}

impl MultibodySystem {
    /// Consistent initial conditions at `t0` from the builder's positions and velocities.
    pub fn compute_initial_state(&self, t0: f64) -> Result<InitialState, MbsError> {
        let mut y = self.initial_y.clone();
        let assembly_iterations = self.assemble(t0, &mut y)?;
        self.project_velocities(t0, &mut y)?;
        let (acceleration, lambda) = self.compute_accelerations_and_multipliers(t0, &y)?;
        let layout = self.layout;
        y.rows_mut(layout.lambda_offset(), layout.constraint_rows())
            .copy_from(&lambda);
        let mut yp = DVector::zeros(layout.size());
        for (k, part) in self.moving_parts().enumerate() {
            let (qo, vo) = (layout.position_offset(part), layout.velocity_offset(part));
            let omega = Self::vector_at(&y, vo + 3);
            let e = self.parameters(&y, part);
            yp.fixed_rows_mut::<3>(qo)
                .copy_from(&Self::vector_at(&y, vo));
            yp.fixed_rows_mut::<4>(qo + 3)
                .copy_from(&(g_matrix(&e).transpose() * omega * 0.5));
            yp.fixed_rows_mut::<6>(vo)
                .copy_from(&acceleration.fixed_rows::<6>(6 * k));
        }
        Ok(InitialState {
            y,
            yp,
            assembly_iterations,
        })
    }

    /// Moves the positions in `y` onto `Φ(q, t) = 0` by the smallest correction; returns the
    /// iterations used. Then checks that the equations removed as redundant hold too
    /// ([`MbsError::InconsistentRedundancy`] otherwise).
    pub fn assemble(&self, t: f64, y: &mut DVector<f64>) -> Result<usize, MbsError> {
        // Every analysis starts here; with only ground there is nothing to assemble or solve.
        if self.parts.is_empty() {
            return Err(MbsError::NoMovingPart);
        }
        let mut iterations = 0;
        while iterations < MAX_ASSEMBLY_ITERATIONS {
            let states = self.part_states(y)?;
            let phi = self.constraint_values(t, &states)?;
            if self.worst_constraint(&phi).0 <= ASSEMBLY_TOLERANCE {
                self.check_redundant_equations(t, y)?;
                return Ok(iterations);
            }
            iterations += 1;
            let jacobian = self.velocity_jacobian(&states);
            let Some(step) = minimum_norm_solution(jacobian, &(-&phi)) else {
                break;
            };
            // Backtrack on the scaled least-squares merit so a far-off start cannot diverge; no
            // decrease at all means a least-squares minimum with Φ ≠ 0: the joints cannot close.
            let merit = self.scaled_merit(&phi);
            let mut fraction = 1.0;
            let accepted = loop {
                let mut trial = y.clone();
                self.displace(&mut trial, &(&step * fraction));
                let trial_merit = self
                    .part_states(&trial)
                    .and_then(|states| self.constraint_values(t, &states))
                    .map(|phi| self.scaled_merit(&phi));
                if trial_merit.is_ok_and(|m| m < merit) {
                    break Some(trial);
                }
                fraction *= 0.5;
                if fraction < 1e-6 {
                    break None;
                }
            };
            match accepted {
                Some(trial) => *y = trial,
                None => break,
            }
        }
        let states = self.part_states(y)?;
        let phi = self.constraint_values(t, &states)?;
        let worst = self.worst_constraint(&phi);
        if worst.0 <= ASSEMBLY_TOLERANCE {
            self.check_redundant_equations(t, y)?;
            return Ok(iterations);
        }
        Err(MbsError::AssemblyFailed {
            iterations,
            residual: worst.0,
            tolerance: ASSEMBLY_TOLERANCE,
            worst: worst.1,
        })
    }

    /// `Σ (Φ_k / s_k)²` with `s_k = L` for length rows and 1 for angle rows.
    fn scaled_merit(&self, phi: &DVector<f64>) -> f64 {
        self.constraints
            .iter()
            .flat_map(|element| {
                element
                    .primitives
                    .iter()
                    .enumerate()
                    .map(move |(k, primitive)| {
                        let scale = if primitive.is_length() {
                            self.length_scale
                        } else {
                            1.0
                        };
                        (phi[element.row + k] / scale).powi(2)
                    })
            })
            .sum()
    }

    /// The largest constraint residual, relative (lengths over `L`), and its element.
    fn worst_constraint(&self, phi: &DVector<f64>) -> (f64, String) {
        let mut worst = (0.0, String::new());
        for element in &self.constraints {
            for (k, primitive) in element.primitives.iter().enumerate() {
                let scale = if primitive.is_length() {
                    self.length_scale
                } else {
                    1.0
                };
                let relative = phi[element.row + k].abs() / scale;
                if relative > worst.0 {
                    worst = (relative, element.name.clone());
                }
            }
        }
        worst
    }

    /// Applies a virtual displacement `[δr, δπ′]` per part (velocity order) to the positions.
    fn displace(&self, y: &mut DVector<f64>, step: &DVector<f64>) {
        for (k, part) in self.moving_parts().enumerate() {
            let qo = self.layout.position_offset(part);
            for i in 0..3 {
                y[qo + i] += step[6 * k + i];
            }
            let rotation = self.rotation(y, part)
                * UnitQuaternion::from_scaled_axis(step.fixed_rows::<3>(6 * k + 3).into_owned());
            y.fixed_rows_mut::<4>(qo + 3)
                .copy_from(&parameters_of(&rotation));
        }
    }

    /// The normalized rotation of a part in `y` (identity if unusable; only called on states
    /// that `part_states` accepted).
    fn rotation(&self, y: &DVector<f64>, part: PartId) -> UnitQuaternion<f64> {
        super::quaternion::rotation_of(&self.parameters(y, part))
            .unwrap_or_else(UnitQuaternion::identity)
    }

    /// Replaces the velocities in `y` by the nearest ones satisfying `Φ_v v + Φ_t = 0`.
    pub fn project_velocities(&self, t: f64, y: &mut DVector<f64>) -> Result<(), MbsError> {
        if self.layout.constraint_rows() == 0 {
            return Ok(());
        }
        let states = self.part_states(y)?;
        let jacobian = self.velocity_jacobian(&states);
        let (phi_t, _) = self.constraint_time_derivatives(t);
        let vo = self.layout.velocity_offset(PartId(1));
        let n6 = 6 * self.parts.len();
        let v = y.rows(vo, n6).into_owned();
        let violation = &jacobian * &v + phi_t;
        let correction = minimum_norm_solution(jacobian, &violation)
            .ok_or(MbsError::SingularConstraints { time: t })?;
        y.rows_mut(vo, n6).copy_from(&(v - correction));
        Ok(())
    }

    /// Solves `[M Φ_vᵀ; Φ_v 0] [v̇; λ] = [Q − ω′×Jω′; γ]` at the state `y` (positions and
    /// velocities consistent); returns `(v̇, λ)`.
    pub fn compute_accelerations_and_multipliers(
        &self,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<(DVector<f64>, DVector<f64>), MbsError> {
        let states = self.part_states(y)?;
        let (n6, m) = (6 * self.parts.len(), self.layout.constraint_rows());
        if m == 0 {
            let rhs = self.applied_minus_gyroscopic(t, y, &states)?;
            return Ok((self.solve_mass_blocks(&rhs, t)?, DVector::zeros(0)));
        }
        let jacobian = self.velocity_jacobian(&states);
        if m > 0 {
            let singular = jacobian.clone().svd(false, false).singular_values;
            if singular.min() <= 1e-10 * singular.max().max(f64::MIN_POSITIVE) || m > n6 {
                return Err(MbsError::SingularConstraints { time: t });
            }
        }
        let mut kkt = DMatrix::zeros(n6 + m, n6 + m);
        kkt.view_mut((0, 0), (n6, n6))
            .copy_from(&self.mass_matrix());
        kkt.view_mut((0, n6), (n6, m))
            .copy_from(&jacobian.transpose());
        kkt.view_mut((n6, 0), (m, n6)).copy_from(&jacobian);
        let mut rhs = DVector::zeros(n6 + m);
        rhs.rows_mut(0, n6)
            .copy_from(&self.applied_minus_gyroscopic(t, y, &states)?);
        if m > 0 {
            let gamma = self.acceleration_right_side(t, y)?;
            rhs.rows_mut(n6, m).copy_from(&gamma);
        }
        let solution = kkt
            .lu()
            .solve(&rhs)
            .filter(|s| s.iter().all(|x| x.is_finite()));
        let solution = solution.ok_or(if m == 0 {
            MbsError::AccelerationsNotFinite { time: t }
        } else {
            MbsError::SingularConstraints { time: t }
        })?;
        Ok((
            solution.rows(0, n6).into_owned(),
            solution.rows(n6, m).into_owned(),
        ))
    }

    /// `M⁻¹·rhs` for the block-diagonal mass matrix, part by part: each part's `6 × 6` block
    /// factorised on its own. The LU of the whole matrix would choose the same pivots and do
    /// the same operations (every other entry of a block's columns is zero) in `(6N)³` work
    /// rather than `N·6³`.
    fn solve_mass_blocks(&self, rhs: &DVector<f64>, t: f64) -> Result<DVector<f64>, MbsError> {
        let mut solution = DVector::zeros(rhs.len());
        for (k, data) in self.parts.iter().enumerate() {
            let mut block = DMatrix::<f64>::zeros(6, 6);
            block
                .fixed_view_mut::<3, 3>(0, 0)
                .copy_from(&(Matrix3::identity() * data.mass));
            block.fixed_view_mut::<3, 3>(3, 3).copy_from(&data.inertia);
            let part = block
                .lu()
                .solve(&rhs.rows(6 * k, 6).into_owned())
                .filter(|s| s.iter().all(|x| x.is_finite()))
                .ok_or(MbsError::AccelerationsNotFinite { time: t })?;
            solution.rows_mut(6 * k, 6).copy_from(&part);
        }
        Ok(solution)
    }

    /// `γ = −Φ_tt − (dΦ_v/dt)·v`, the second term by a central difference of `Φ_v v` along the
    /// motion over `±h`, `h = ε^(1/3) / max(|u|/L, |ω′|)` (zero when nothing moves).
    pub(crate) fn acceleration_right_side(
        &self,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<DVector<f64>, MbsError> {
        let (_, phi_tt) = self.constraint_time_derivatives(t);
        let vo = self.layout.velocity_offset(PartId(1));
        let v = y.rows(vo, 6 * self.parts.len()).into_owned();
        let rate = (0..self.parts.len())
            .map(|k| {
                let linear = v.fixed_rows::<3>(6 * k).norm() / self.length_scale;
                linear.max(v.fixed_rows::<3>(6 * k + 3).norm())
            })
            .fold(0.0, f64::max);
        if rate == 0.0 {
            return Ok(-phi_tt);
        }
        let h = f64::EPSILON.cbrt() / rate;
        let mut advanced = [y.clone(), y.clone()];
        for (state, sign) in advanced.iter_mut().zip([1.0, -1.0]) {
            self.displace(state, &(&v * (sign * h)));
        }
        let forward = self.velocity_jacobian(&self.part_states(&advanced[0])?) * &v;
        let backward = self.velocity_jacobian(&self.part_states(&advanced[1])?) * &v;
        Ok(-phi_tt - (forward - backward) / (2.0 * h))
    }
}
