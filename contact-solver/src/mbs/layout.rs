//! Where each unknown sits in the state vector `y`.

use super::part::PartId;

/// How the constraints enter the DAE (Adams INTEGRATOR/…, I3 | SI2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Formulation {
    /// Index 3 (Adams' default): position constraints `Φ(q, t) = 0` with multipliers λ.
    #[default]
    I3,
    /// Stabilized index 2 (Gear–Gupta–Leimkuhler): the velocity constraints
    /// `Φ_v v + Φ_t = 0` with multipliers λ in the dynamic rows, and the position constraints
    /// `Φ = 0` with extra multipliers η in the kinematic rows (`q̇ − T v + Φ_qᵀη = 0`; η = 0 on
    /// the exact solution). Better conditioned at small steps, and velocities can be
    /// error-tested; the reference document's remedy for hard contact.
    Si2,
}

/// The layout of `y = [q, v, λ, μ]` for `n` moving parts and `m` constraint equations:
///
/// | block | offset | length | content per part `k = 1..n` (ids in builder order) |
/// | --- | --- | --- | --- |
/// | q | 0 | 7n | `r_k` (CM position, world, 3) then `e_k` (Euler parameters, `e₀` scalar first, 4) |
/// | v | 7n | 6n | `u_k` (CM velocity, world, 3) then `ω′_k` (angular velocity, **body** frame, 3) |
/// | λ | 13n | m | constraint multipliers, in constraint order, each constraint's rows contiguous |
/// | μ | 13n + m | n | quaternion-normalization multipliers |
/// | η (SI2 only) | 14n + m | m | position-constraint multipliers of the kinematic rows |
///
/// The residual rows follow the same order: kinematic rows (3 + 4 per part) pair with q,
/// dynamic rows (3 + 3) with v, normalization rows with μ; under I3 the constraint rows Φ
/// pair with λ, under SI2 the velocity constraints `Φ_v v + Φ_t` pair with λ and Φ with η.
/// The ground is not in `y`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StateLayout {
    parts: usize,
    constraint_rows: usize,
    formulation: Formulation,
}

impl StateLayout {
    /// A layout for `parts` moving parts and `constraint_rows` constraint equations.
    pub(crate) fn new(parts: usize, constraint_rows: usize, formulation: Formulation) -> Self {
        Self {
            parts,
            constraint_rows,
            formulation,
        }
    }

    /// The formulation the layout is for.
    pub fn formulation(&self) -> Formulation {
        self.formulation
    }

    /// The number of moving parts `n`.
    pub fn parts(&self) -> usize {
        self.parts
    }

    /// The number of constraint equations `m`.
    pub fn constraint_rows(&self) -> usize {
        self.constraint_rows
    }

    /// The length of `y`: `14n + m` (I3) or `14n + 2m` (SI2).
    pub fn size(&self) -> usize {
        match self.formulation {
            Formulation::I3 => 14 * self.parts + self.constraint_rows,
            Formulation::Si2 => 14 * self.parts + 2 * self.constraint_rows,
        }
    }

    /// Offset of the first η (SI2), where the position-constraint rows Φ sit; under I3 the
    /// position constraints sit at [`Self::lambda_offset`].
    pub fn position_constraint_offset(&self) -> usize {
        match self.formulation {
            Formulation::I3 => self.lambda_offset(),
            Formulation::Si2 => 14 * self.parts + self.constraint_rows,
        }
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
