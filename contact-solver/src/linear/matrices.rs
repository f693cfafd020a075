//! The matrices of the linearization at an operating point: `M`, `C`, `K` in virtual
//! displacements, the velocity-constraint Jacobian `Φ_v`, and the basis `N` of its null space.

use super::LinearError;
use crate::mbs::{MbsError, MultibodySystem};
use crate::statics::newton::static_jacobian;
use nalgebra::{DMatrix, DVector};

/// Singular values of the scaled `Φ_v` at or below this fraction of the largest count as zero
/// (the same threshold as [`crate::kinematics::degrees_of_freedom`]).
const RANK_TOLERANCE: f64 = 1e-10;

/// The unreduced matrices at an operating point, in velocity order (per moving part
/// `[u (world), ω′ (body)]`, and the virtual displacements `[δr (world), δθ′ (body)]` in the
/// same order): `6n` columns.
#[derive(Debug, Clone, PartialEq)]
pub struct OperatingMatrices {
    /// The operating point with its multipliers λ solved for (normalization multipliers zero).
    pub y: DVector<f64>,
    /// `M = diag(m I, J)` per part (6n × 6n).
    pub mass: DMatrix<f64>,
    /// `C = ∂(ω′ × Jω′ − Q)/∂v` (6n × 6n).
    pub damping: DMatrix<f64>,
    /// `K = ∂(Φ_vᵀλ − Q)/∂q` in virtual displacements (6n × 6n).
    pub stiffness: DMatrix<f64>,
    /// `Φ_v` (m × 6n).
    pub constraint_jacobian: DMatrix<f64>,
}

/// `M`, `C`, `K` and `Φ_v` of `system` at the positions and velocities of `y`, time `t`.
///
/// The multipliers are the minimum-norm solution of
/// `[M Φ_vᵀ; Φ_v 0][v̇; λ] = [Q − ω′×Jω′; γ]` (SVD, singular values below `1e-12·σ_max` dropped),
/// so redundant constraints do not stop the linearization. `K` is the position block of
/// [`static_jacobian`] at that state (STABILITY 0); `C` is the block of dynamic rows and
/// velocity columns of the Newton matrix at `c = 0`, where the inertia term `c·M` vanishes and
/// what is left is the gyroscopic partial and `−∂Q/∂v`.
pub fn compute_operating_matrices(
    system: &mut MultibodySystem,
    t: f64,
    y: &DVector<f64>,
) -> Result<OperatingMatrices, LinearError> {
    let layout = *system.layout();
    if y.len() != layout.size() {
        return Err(LinearError::WrongLength {
            given: y.len(),
            expected: layout.size(),
        });
    }
    if !t.is_finite() {
        return Err(LinearError::NonFiniteState {
            t,
            index: usize::MAX,
            value: t,
        });
    }
    // Only positions and velocities are read; multipliers are recomputed below.
    if let Some((index, &value)) = y
        .iter()
        .enumerate()
        .take(layout.lambda_offset())
        .find(|(_, x)| !x.is_finite())
    {
        return Err(LinearError::NonFiniteState { t, index, value });
    }
    let n6 = 6 * layout.parts();
    let m = layout.constraint_rows();
    let states = system.part_states(y)?;
    let constraint_jacobian = system.velocity_jacobian(&states);
    let mass = system.mass_matrix();
    let mut operating = y.clone();
    operating
        .rows_mut(
            layout.lambda_offset(),
            layout.size() - layout.lambda_offset(),
        )
        .fill(0.0);
    if m > 0 {
        let mut kkt = DMatrix::zeros(n6 + m, n6 + m);
        kkt.view_mut((0, 0), (n6, n6)).copy_from(&mass);
        kkt.view_mut((0, n6), (n6, m))
            .copy_from(&constraint_jacobian.transpose());
        kkt.view_mut((n6, 0), (m, n6))
            .copy_from(&constraint_jacobian);
        let mut rhs = DVector::zeros(n6 + m);
        rhs.rows_mut(0, n6)
            .copy_from(&system.applied_minus_gyroscopic(t, y, &states)?);
        let gamma = system.acceleration_right_side(t, y).map_err(|e| match e {
            MbsError::Evaluation(e) => LinearError::Evaluation(e),
            _ => LinearError::Multipliers { t },
        })?;
        rhs.rows_mut(n6, m).copy_from(&gamma);
        let svd = kkt.svd(true, true);
        let largest = svd.singular_values.max();
        let solution = (largest.is_finite() && largest > 0.0)
            .then(|| svd.solve(&rhs, 1e-12 * largest).ok())
            .flatten()
            .filter(|s| s.iter().all(|x| x.is_finite()))
            .ok_or(LinearError::Multipliers { t })?;
        operating
            .rows_mut(layout.lambda_offset(), m)
            .copy_from(&solution.rows(n6, m));
    }
    let jacobian = static_jacobian(system, t, &operating, 0.0)?;
    let stiffness = jacobian.view((0, 0), (n6, n6)).into_owned();
    let size = layout.size();
    let mut newton = DMatrix::zeros(size, size);
    system.compute_newton_matrix(t, &operating, &DVector::zeros(size), 0.0, &mut newton)?;
    // The dynamic rows and the velocity columns are both the contiguous block at 7n.
    let vo = 7 * layout.parts();
    let damping = newton.view((vo, vo), (n6, n6)).into_owned();
    Ok(OperatingMatrices {
        y: operating,
        mass,
        damping,
        stiffness,
        constraint_jacobian,
    })
}

/// An orthonormal basis `N` (6n × d) of the null space of `Φ_v` (m × 6n): the admissible
/// perturbations `δq = N z`. With no constraint rows it is the identity.
///
/// The rank is decided on a scaled copy of `Φ_v`: each part's rotation columns divided by the
/// length scale `L` (so every column is a length per length) and then each row divided by its
/// norm (a length row and an angle row weigh alike). Singular values at or below
/// `1e-10·σ_max` of that matrix count as zero; the right singular vectors that belong to them
/// span the null space of the scaled matrix, which, mapped back and orthonormalized (QR), is
/// the null space of `Φ_v`. The matrix is padded with zero rows to be at least square, since
/// the thin SVD of a wide matrix has no vectors for the null space.
pub fn null_space_basis(constraint_jacobian: &DMatrix<f64>, length_scale: f64) -> DMatrix<f64> {
    let (m, n6) = constraint_jacobian.shape();
    if m == 0 || n6 == 0 {
        return DMatrix::identity(n6, n6);
    }
    let column_scale =
        DVector::from_fn(n6, |i, _| if i % 6 < 3 { 1.0 } else { 1.0 / length_scale });
    let mut scaled = DMatrix::zeros(m.max(n6), n6);
    for r in 0..m {
        let row = DVector::from_fn(n6, |c, _| constraint_jacobian[(r, c)] * column_scale[c]);
        let norm = row.norm();
        if norm > 0.0 {
            for c in 0..n6 {
                scaled[(r, c)] = row[c] / norm;
            }
        }
    }
    let svd = scaled.svd(false, true);
    let largest = svd.singular_values.max();
    let Some(v_t) = svd.v_t else {
        return DMatrix::identity(n6, n6);
    };
    let null: Vec<usize> = (0..svd.singular_values.len())
        .filter(|&i| svd.singular_values[i] <= RANK_TOLERANCE * largest)
        .collect();
    if null.is_empty() {
        return DMatrix::zeros(n6, 0);
    }
    let mut basis = DMatrix::zeros(n6, null.len());
    for (k, &i) in null.iter().enumerate() {
        for c in 0..n6 {
            basis[(c, k)] = v_t[(i, c)] * column_scale[c];
        }
    }
    basis.qr().q()
}
