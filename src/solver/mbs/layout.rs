//! Where each unknown sits in the state vector `y`.

use super::part::PartId;

/// The layout of `y = [q, v, λ, μ]` for `n` moving parts and `m` constraint equations:
///
/// | block | offset | length | content per part `k = 1..n` (ids in builder order) |
/// | --- | --- | --- | --- |
/// | q | 0 | 7n | `r_k` (CM position, world, 3) then `e_k` (Euler parameters, `e₀` scalar first, 4) |
/// | v | 7n | 6n | `u_k` (CM velocity, world, 3) then `ω′_k` (angular velocity, **body** frame, 3) |
/// | λ | 13n | m | constraint multipliers, in constraint order, each constraint's rows contiguous |
/// | μ | 13n + m | n | quaternion-normalization multipliers |
///
/// The residual rows follow the same order: kinematic rows (3 + 4 per part) pair with q,
/// dynamic rows (3 + 3) with v, constraint rows Φ with λ and normalization rows with μ.
/// The ground is not in `y`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StateLayout {
    parts: usize,
    constraint_rows: usize,
}

impl StateLayout {
    /// A layout for `parts` moving parts and `constraint_rows` constraint equations.
    pub(crate) fn new(parts: usize, constraint_rows: usize) -> Self {
        Self {
            parts,
            constraint_rows,
        }
    }

    /// The number of moving parts `n`.
    pub fn parts(&self) -> usize {
        self.parts
    }

    /// The number of constraint equations `m`.
    pub fn constraint_rows(&self) -> usize {
        self.constraint_rows
    }

    /// The length of `y`: `14n + m`.
    pub fn size(&self) -> usize {
        14 * self.parts + self.constraint_rows
    }

    /// Offset of `r_k` (then `e_k` at +3) of moving part `part` (not ground).
    pub fn position_offset(&self, part: PartId) -> usize {
        debug_assert!(!part.is_ground());
        7 * (part.0 - 1)
    }

    /// Offset of `u_k` (then `ω′_k` at +3) of moving part `part` (not ground).
    pub fn velocity_offset(&self, part: PartId) -> usize {
        debug_assert!(!part.is_ground());
        7 * self.parts + 6 * (part.0 - 1)
    }

    /// Offset of the first constraint multiplier.
    pub fn lambda_offset(&self) -> usize {
        13 * self.parts
    }

    /// Offset of the normalization multiplier `μ_k` of moving part `part` (not ground).
    pub fn mu_offset(&self, part: PartId) -> usize {
        debug_assert!(!part.is_ground());
        13 * self.parts + self.constraint_rows + (part.0 - 1)
    }
}
