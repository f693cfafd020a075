//! The assembled multibody system and the quantities its residual, Jacobian and initial
//! conditions share: part states from `y`, constraint values and Jacobians, applied loads.

use super::constraints::ConstraintElement;
use super::force::{ForceElement, Load, PartState, StateView};
use super::layout::StateLayout;
use super::part::PartId;
use super::quaternion::rotation_of;
use crate::dae::EvaluationError;
use nalgebra::{DMatrix, DVector, Isometry3, Matrix3, Translation3, Vector3, Vector4};

/// Mass properties of a moving part.
#[derive(Debug, Clone)]
pub(crate) struct PartData {
    pub name: String,
    pub mass: f64,
    pub inertia: Matrix3<f64>,
}

/// A rigid multibody system as an index-3 DAE `F(t, y, y′) = 0` (solver-notes §2.3).
///
/// Built by [`super::MultibodyBuilder`]; the state layout is [`StateLayout`]. The equations,
/// per moving part (body-frame angular velocity ω′, body inertia J, world gravity g):
/// ```text
/// ṙ − u                                        = 0   (3)
/// ė − ½ G(e)ᵀ ω′ − e μ                         = 0   (4)
/// m u̇ − m g − f + Φ_rᵀ λ                       = 0   (3)
/// J ω̇′ + ω′ × J ω′ − Aᵀ n + Φ_π′ᵀ λ            = 0   (3)
/// eᵀe − 1                                      = 0   (1)
/// ```
/// and `Φ(q, t) = 0` for every constraint row, with `f`, `n` the world force and torque of the
/// force elements and `A` the part's rotation (from `e/|e|`). The reaction of the constraints
/// on the parts is `−Φ_vᵀ λ`. Under [`super::Formulation::Si2`] the velocity constraints
/// `Φ_v v + Φ_t = 0` are added (in the λ rows) and the kinematic rows get `+Φ_qᵀη`, with Φ in
/// the η rows.
pub struct MultibodySystem {
    pub(crate) parts: Vec<PartData>,
    pub(crate) constraints: Vec<ConstraintElement>,
    pub(crate) forces: Vec<Box<dyn ForceElement>>,
    /// Which force elements can act at a state.
    pub(crate) broad_phase: crate::broad_phase::BroadPhase,
    /// The force elements given at build time that [track steps](super::ForceElement::tracks_steps).
    pub(crate) step_trackers: Vec<usize>,
    pub(crate) gravity_w: Vector3<f64>,
    pub(crate) layout: StateLayout,
    pub(crate) length_scale: f64,
    /// Initial `y` from the builder (positions and velocities as given, multipliers zero).
    pub(crate) initial_y: DVector<f64>,
    /// Threads for force-element evaluation.
    pub(crate) parallelism: crate::parallel::Parallelism,
    /// Where the Newton matrix takes the force elements' partials from.
    pub(crate) force_partials: super::force::ForcePartials,
    /// Whether output frames carry accelerations and reactions ([`crate::frame::FrameDynamics`]).
    pub(crate) output_dynamics: bool,
    /// The Newton matrix's storage, or `None` to choose by size ([`SPARSE_FROM_SIZE`]).
    pub(crate) newton_storage: Option<crate::NewtonStorage>,
    /// The equations removed as redundant, each with its element reduced to that equation
    /// (for the consistency check after assembly).
    pub(crate) redundant: Vec<(super::RedundantEquation, ConstraintElement)>,
}

/// The size `n` of `y` from which the integrator stores the Newton matrix sparse when the
/// storage is chosen automatically ([`MultibodySystem::set_newton_storage`]). Every model of
/// up to three parts stays below it and keeps the dense LU. Measured on pendulum chains
/// (`benches/newton.rs`, group `newton_matrix/chain`, one evaluation and factorisation with
/// the sparse ordering rebuilt each time, as at a pattern change): the dense LU is faster up to
/// n = 76 (47 against 131 µs at n = 38, 156 against 313 µs at 76), the sparse from n = 152
/// (612 against 724 µs; 1.28 against 4.86 ms at 304, 5.9 against 423 ms at 1216); a run
/// reuses the ordering, so the sparse side is cheaper still there.
pub const SPARSE_FROM_SIZE: usize = 128;

impl std::fmt::Debug for MultibodySystem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MultibodySystem")
            .field("parts", &self.parts)
            .field("constraints", &self.constraints)
            .field(
                "forces",
                &self.forces.iter().map(|e| e.name()).collect::<Vec<_>>(),
            )
            .field("gravity_w", &self.gravity_w)
            .field("layout", &self.layout)
            .field("length_scale", &self.length_scale)
            .field("redundant", &self.redundant)
            .finish()
    }
}

impl MultibodySystem {
    /// Where each unknown sits in `y`.
    pub fn layout(&self) -> &StateLayout {
        &self.layout
    }

    /// The model's length scale `L` (tolerances of assembly and difference steps use it).
    pub fn length_scale(&self) -> f64 {
        self.length_scale
    }

    /// The name of a moving part (`None` for the ground or an unknown id).
    pub fn part_name(&self, part: PartId) -> Option<&str> {
        part.0
            .checked_sub(1)
            .and_then(|k| self.parts.get(k))
            .map(|p| p.name.as_str())
    }

    /// The constraints' names and their first row in Φ (and λ), in row order.
    pub fn constraint_rows(&self) -> impl Iterator<Item = (&str, usize)> {
        self.constraints.iter().map(|c| (c.name.as_str(), c.row))
    }

    /// The part ids of the moving parts, in state order.
    pub fn moving_parts(&self) -> impl Iterator<Item = PartId> + use<> {
        (1..=self.parts.len()).map(PartId)
    }

    /// The raw Euler parameters of `part` in `y`.
    pub(crate) fn parameters(&self, y: &DVector<f64>, part: PartId) -> Vector4<f64> {
        let o = self.layout.position_offset(part) + 3;
        Vector4::new(y[o], y[o + 1], y[o + 2], y[o + 3])
    }

    /// `v3(y, o)`: the 3-vector at offset `o`.
    pub(crate) fn vector_at(y: &DVector<f64>, o: usize) -> Vector3<f64> {
        Vector3::new(y[o], y[o + 1], y[o + 2])
    }

    /// The pose of a moving part from raw coordinates, or an error naming the part when the
    /// Euler parameters are zero or not finite or the position is not finite.
    pub(crate) fn pose_from(
        &self,
        part: PartId,
        r: Vector3<f64>,
        e: &Vector4<f64>,
    ) -> Result<Isometry3<f64>, EvaluationError> {
        let rotation = rotation_of(e).filter(|_| r.iter().all(|x| x.is_finite()));
        rotation
            .map(|rotation| Isometry3::from_parts(Translation3::from(r), rotation))
            .ok_or_else(|| EvaluationError {
                element: self.parts[part.0 - 1].name.clone(),
                message: format!("position {r:?} or Euler parameters {e:?} not usable"),
                fatal: false,
            })
    }

    /// The world state of every part at `y`, indexed by [`PartId`] (`[0]` is the ground); an
    /// error names a part whose coordinates are not finite or whose Euler parameters are zero.
    pub fn part_states(&self, y: &DVector<f64>) -> Result<Vec<PartState>, EvaluationError> {
        let mut states = Vec::with_capacity(self.parts.len() + 1);
        states.push(PartState::GROUND);
        for part in self.moving_parts() {
            let qo = self.layout.position_offset(part);
            let vo = self.layout.velocity_offset(part);
            let pose_w = self.pose_from(part, Self::vector_at(y, qo), &self.parameters(y, part))?;
            let velocity_w = Self::vector_at(y, vo);
            let omega_body = Self::vector_at(y, vo + 3);
            if !(velocity_w
                .iter()
                .chain(omega_body.iter())
                .all(|x| x.is_finite()))
            {
                return Err(EvaluationError {
                    element: self.parts[part.0 - 1].name.clone(),
                    message: format!(
                        "velocity {velocity_w:?} or angular velocity {omega_body:?} not finite"
                    ),
                    fatal: false,
                });
            }
            states.push(PartState {
                pose_w,
                velocity_w,
                angular_velocity_w: pose_w.rotation * omega_body,
            });
        }
        Ok(states)
    }

    /// Evaluates every force element into `loads` (one `Vec` per element).
    pub(crate) fn element_loads(
        &self,
        t: f64,
        states: &[PartState],
    ) -> Result<Vec<Vec<Load>>, EvaluationError> {
        let view = StateView::new(states);
        // Each element into its own slot (in parallel when configured), then the first error
        // in index order: the same answer at every thread count.
        let results = self
            .parallelism
            .map_indexed(self.forces.len(), |k| self.checked_loads(k, t, &view));
        results.into_iter().collect()
    }

    /// The loads of the force elements the broad phase lets through at `states`, as
    /// `(element index, loads)` in index order; every other element's loads are zero.
    pub(crate) fn active_element_loads(
        &self,
        t: f64,
        states: &[PartState],
    ) -> Result<Vec<(usize, Vec<Load>)>, EvaluationError> {
        // Elements added after the system was built (the quasi-dynamic method's damping)
        // are evaluated always.
        let mut active = self.broad_phase.candidates(states);
        active.retain(|&k| k < self.forces.len());
        active.extend(self.broad_phase.len()..self.forces.len());
        let view = StateView::new(states);
        // Each element into its own slot (in parallel when configured), then the first error
        // in index order: the same answer at every thread count.
        let results = self.parallelism.map_indexed(active.len(), |n| {
            let k = active[n];
            self.checked_loads(k, t, &view).map(|loads| (k, loads))
        });
        results.into_iter().collect()
    }

    /// The loads of element `k`, or an error naming it when one is not finite.
    fn checked_loads(
        &self,
        k: usize,
        t: f64,
        view: &StateView<'_>,
    ) -> Result<Vec<Load>, EvaluationError> {
        let element = &self.forces[k];
        let mut loads = vec![Load::default(); element.parts().len()];
        element.evaluate(t, view, &mut loads)?;
        if let Some(bad) = loads.iter().find(|l| {
            !l.force_w
                .iter()
                .chain(l.torque_w.iter())
                .all(|x| x.is_finite())
        }) {
            return Err(EvaluationError {
                element: element.name().to_owned(),
                message: format!("non-finite load {bad:?}"),
                fatal: false,
            });
        }
        Ok(loads)
    }

    /// The force elements that track steps, ascending: those given at build time that say
    /// so, and every element added since (the quasi-dynamic method's damping).
    pub(crate) fn step_trackers(&self) -> impl Iterator<Item = usize> {
        let built = self.broad_phase.len().min(self.forces.len());
        self.step_trackers
            .iter()
            .copied()
            .filter(move |&k| k < built)
            .chain(built..self.forces.len())
    }

    /// `(evaluated, skipped)`: the force-element evaluations the broad phase let through and
    /// those it skipped, since the system was built.
    pub fn broad_phase_counts(&self) -> (u64, u64) {
        self.broad_phase.counts()
    }

    /// Takes the force elements' partials in the Newton matrix from `source` from now on
    /// (default [`super::ForcePartials::Analytic`]).
    pub fn set_force_partials(&mut self, source: super::ForcePartials) {
        self.force_partials = source;
    }

    /// Where the Newton matrix takes the force elements' partials from.
    pub fn force_partials(&self) -> super::ForcePartials {
        self.force_partials
    }

    /// Stores the Newton matrix as `storage` from now on, or chooses by size when `None` (the
    /// default): sparse from [`SPARSE_FROM_SIZE`] unknowns on. Both give the same solution to
    /// round-off.
    pub fn set_newton_storage(&mut self, storage: Option<crate::NewtonStorage>) {
        self.newton_storage = storage;
    }

    /// The Newton matrix's storage: as set, or chosen by size.
    pub fn newton_storage(&self) -> crate::NewtonStorage {
        self.newton_storage
            .unwrap_or(if self.layout.size() >= SPARSE_FROM_SIZE {
                crate::NewtonStorage::Sparse
            } else {
                crate::NewtonStorage::Dense
            })
    }

    /// Uses `parallelism` to evaluate force elements from now on (results do not depend on it).
    pub fn set_parallelism(&mut self, parallelism: crate::parallel::Parallelism) {
        self.parallelism = parallelism;
    }

    /// The generalized applied forces minus gyroscopic terms, `[f + m g, Aᵀn − ω′ × Jω′]` per
    /// part (6n, velocity order).
    pub(crate) fn applied_minus_gyroscopic(
        &self,
        t: f64,
        y: &DVector<f64>,
        states: &[PartState],
    ) -> Result<DVector<f64>, EvaluationError> {
        let n = self.parts.len();
        let mut q = DVector::zeros(6 * n);
        for (k, data) in self.parts.iter().enumerate() {
            let omega = Self::vector_at(y, self.layout.velocity_offset(PartId(k + 1)) + 3);
            let gyro = omega.cross(&(data.inertia * omega));
            q.fixed_rows_mut::<3>(6 * k)
                .copy_from(&(self.gravity_w * data.mass));
            q.fixed_rows_mut::<3>(6 * k + 3).copy_from(&(-gyro));
        }
        for (k, loads) in self.active_element_loads(t, states)? {
            for (part, load) in self.forces[k].parts().iter().zip(loads) {
                if part.is_ground() {
                    continue;
                }
                let k = part.0 - 1;
                let body_torque = states[part.0]
                    .pose_w
                    .rotation
                    .inverse_transform_vector(&load.torque_w);
                let mut f = q.fixed_rows_mut::<3>(6 * k);
                f += load.force_w;
                let mut tau = q.fixed_rows_mut::<3>(6 * k + 3);
                tau += body_torque;
            }
        }
        Ok(q)
    }

    /// `Φ(q, t)` (m rows) at the part states, with an error naming a constraint whose value is
    /// not finite (a MOTION function returning NaN).
    pub(crate) fn constraint_values(
        &self,
        t: f64,
        states: &[PartState],
    ) -> Result<DVector<f64>, EvaluationError> {
        let mut phi = DVector::zeros(self.layout.constraint_rows());
        for element in &self.constraints {
            let (pose_a, pose_b) = (
                &states[element.part_i.0].pose_w,
                &states[element.part_j.0].pose_w,
            );
            let frames = element.frames(pose_a, pose_b);
            for (k, primitive) in element.primitives.iter().enumerate() {
                let value = primitive.value(&frames, t);
                if !value.is_finite() {
                    return Err(EvaluationError {
                        element: element.name.clone(),
                        message: format!(
                            "constraint equation {k} ({primitive:?}) is {value} at t = {t}"
                        ),
                        fatal: false,
                    });
                }
                phi[element.row + k] = value;
            }
        }
        Ok(phi)
    }

    /// `Φ_v` (m × 6n, velocity order: per part `[u, ω′]`) at the part states.
    pub(crate) fn velocity_jacobian(&self, states: &[PartState]) -> DMatrix<f64> {
        let mut jacobian = DMatrix::zeros(self.layout.constraint_rows(), 6 * self.parts.len());
        for element in &self.constraints {
            let (pose_a, pose_b) = (
                &states[element.part_i.0].pose_w,
                &states[element.part_j.0].pose_w,
            );
            let frames = element.frames(pose_a, pose_b);
            for (k, primitive) in element.primitives.iter().enumerate() {
                let gradient = ConstraintElement::body_gradient(primitive, &frames, pose_a, pose_b);
                for (part, halves) in [
                    (element.part_i, &gradient[0..2]),
                    (element.part_j, &gradient[2..4]),
                ] {
                    if part.is_ground() {
                        continue;
                    }
                    let col = 6 * (part.0 - 1);
                    for i in 0..3 {
                        jacobian[(element.row + k, col + i)] += halves[0][i];
                        jacobian[(element.row + k, col + 3 + i)] += halves[1][i];
                    }
                }
            }
        }
        jacobian
    }

    /// `(Φ_t, Φ_tt)` at time `t` (nonzero only on MOTION rows).
    pub(crate) fn constraint_time_derivatives(&self, t: f64) -> (DVector<f64>, DVector<f64>) {
        let m = self.layout.constraint_rows();
        let (mut first, mut second) = (DVector::zeros(m), DVector::zeros(m));
        for element in &self.constraints {
            for (k, primitive) in element.primitives.iter().enumerate() {
                let (d1, d2) = primitive.time_derivatives(t);
                first[element.row + k] = d1;
                second[element.row + k] = d2;
            }
        }
        (first, second)
    }

    /// The mass matrix in velocity order: `diag(m I, J)` per part.
    pub(crate) fn mass_matrix(&self) -> DMatrix<f64> {
        let n = self.parts.len();
        let mut mass = DMatrix::zeros(6 * n, 6 * n);
        for (k, data) in self.parts.iter().enumerate() {
            mass.fixed_view_mut::<3, 3>(6 * k, 6 * k)
                .copy_from(&(Matrix3::identity() * data.mass));
            mass.fixed_view_mut::<3, 3>(6 * k + 3, 6 * k + 3)
                .copy_from(&data.inertia);
        }
        mass
    }

    /// Kinetic energy `Σ ½ m |u|² + ½ ω′ᵀ J ω′` at `y`.
    pub fn kinetic_energy(&self, y: &DVector<f64>) -> f64 {
        self.moving_parts()
            .zip(&self.parts)
            .map(|(part, data)| {
                let vo = self.layout.velocity_offset(part);
                let (u, w) = (Self::vector_at(y, vo), Self::vector_at(y, vo + 3));
                0.5 * data.mass * u.norm_squared() + 0.5 * w.dot(&(data.inertia * w))
            })
            .sum()
    }

    /// Potential energy of gravity `−Σ m g·r` at `y` (zero at the world origin).
    pub fn gravity_potential_energy(&self, y: &DVector<f64>) -> f64 {
        self.moving_parts()
            .zip(&self.parts)
            .map(|(part, data)| {
                -data.mass
                    * self
                        .gravity_w
                        .dot(&Self::vector_at(y, self.layout.position_offset(part)))
            })
            .sum()
    }

    /// The generalized reactions `−Φ_vᵀ λ` at `y`, as a world force and a world torque about
    /// the CM per moving part (for joint reaction output).
    pub fn constraint_reactions(&self, y: &DVector<f64>) -> Result<Vec<Load>, EvaluationError> {
        let states = self.part_states(y)?;
        let lambda = y.rows(self.layout.lambda_offset(), self.layout.constraint_rows());
        let mut reactions = vec![Load::default(); self.parts.len()];
        for element in &self.constraints {
            let (pose_a, pose_b) = (
                &states[element.part_i.0].pose_w,
                &states[element.part_j.0].pose_w,
            );
            let g = element.generalized_reaction_in(&states, lambda);
            for (part, pose, force, torque_body) in [
                (element.part_i, pose_a, g[0], g[1]),
                (element.part_j, pose_b, g[2], g[3]),
            ] {
                if part.is_ground() {
                    continue;
                }
                let entry = &mut reactions[part.0 - 1];
                entry.force_w -= force;
                entry.torque_w -= pose.rotation * torque_body;
            }
        }
        Ok(reactions)
    }
}
