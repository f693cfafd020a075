//! Kinematic analysis (Adams SIMULATE/KINEMATICS) of a model with zero degrees of freedom.
//!
//! With the MOTIONs applied, the constraints `Φ(q, t) = 0` have as many independent rows as
//! the parts have coordinates (6 per part, in virtual displacements), so the motion follows
//! from the constraints alone. At each output time:
//! 1. **Positions**: Newton on `Φ(q, t) = 0` ([`MultibodySystem::assemble`]: with a square,
//!    nonsingular `Φ_v` its minimum-norm step is the Newton step), from the previous output
//!    extrapolated with its velocities and accelerations.
//! 2. **Velocities**: `Φ_v v = −Φ_t`.
//! 3. **Accelerations and reactions**: `[M Φ_vᵀ; Φ_v 0] [v̇; λ] = [Q − ω′×Jω′; γ]`, one linear
//!    solve: `Φ_v` square fixes `v̇` from `γ`, and `λ` is what the constraints (MOTIONs
//!    included) must supply against the inertia and applied forces — gravity, SFORCEs and
//!    CONTACT forces; the reaction on the parts is `−Φ_vᵀλ`.
//!
//! Contacts are evaluated as outputs only (SPEC §8): they enter the reactions, never the
//! motion. A model with degrees of freedom left is refused before anything runs.

use super::EvaluationError;
use super::contact_force::ContactForce;
use super::frame::compute_frame;
use super::mbs::quaternion::parameters_of;
use super::mbs::{MbsError, MultibodySystem};
use super::simulate::Frame;
use nalgebra::{DVector, UnitQuaternion, Vector3};
use std::sync::Arc;

/// The span and output of a kinematic analysis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KinematicsSettings {
    /// Start time.
    pub start: f64,
    /// End time (> start).
    pub end: f64,
    /// Time between output frames (> 0).
    pub output_step: f64,
}

/// The full kinematic state at one time.
#[derive(Debug, Clone, PartialEq)]
pub struct KinematicState {
    /// Positions, velocities and the multipliers λ (reactions `−Φ_vᵀλ`).
    pub y: DVector<f64>,
    /// Its derivative: position rates and the accelerations `v̇` (λ̇ is not computed: zero).
    pub yp: DVector<f64>,
    /// Newton iterations the positions took.
    pub iterations: usize,
}

/// What a kinematic analysis did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct KinematicsSummary {
    /// Output frames written.
    pub frames: u64,
    /// Newton iterations on the positions, all frames.
    pub iterations: usize,
}

/// Why a kinematic analysis stopped.
#[derive(Debug, thiserror::Error)]
pub enum KinematicsError {
    /// The settings are out of range.
    #[error("{0}")]
    Settings(String),
    /// The model can move without violating a constraint.
    #[error(
        "KINEMATICS needs a model with zero degrees of freedom once MOTIONs are applied: this one has {dof} ({parts} moving parts × 6 coordinates, {independent} independent constraint equations); add MOTIONs or joints, or run DYNAMICS"
    )]
    DegreesOfFreedom {
        /// The degrees of freedom left.
        dof: usize,
        /// Moving parts.
        parts: usize,
        /// The rank of the constraint Jacobian.
        independent: usize,
    },
    /// The constraints could not be solved at a time.
    #[error("at t = {t:?}: {source}")]
    Solve {
        /// Time.
        t: f64,
        /// The failure.
        source: MbsError,
    },
    /// A force element failed while computing output.
    #[error("at t = {t:?}: {source}")]
    Evaluation {
        /// Time.
        t: f64,
        /// The failure.
        source: EvaluationError,
    },
    /// The output sink failed.
    #[error("writing results at t = {t:?}: {source}")]
    Output {
        /// Time.
        t: f64,
        /// The failure.
        source: std::io::Error,
    },
}

/// The degrees of freedom at the positions of `y`: `6n − rank(Φ_v)` (singular values below
/// `1e-10·σ_max` count as zero).
pub fn degrees_of_freedom(system: &MultibodySystem, y: &DVector<f64>) -> Result<usize, MbsError> {
    let states = system.part_states(y)?;
    let n6 = 6 * system.layout().parts();
    if system.layout().constraint_rows() == 0 {
        return Ok(n6);
    }
    let singular = system
        .velocity_jacobian(&states)
        .svd(false, false)
        .singular_values;
    let largest = singular.max();
    let rank = singular.iter().filter(|&&s| s > 1e-10 * largest).count();
    Ok(n6 - rank.min(n6))
}

/// The degrees of freedom of the model's given configuration assembled onto the constraints
/// at time `t` ([`degrees_of_freedom`] there): what SIMULATE/TRANSIENT chooses its analysis by.
pub fn initial_degrees_of_freedom(system: &MultibodySystem, t: f64) -> Result<usize, MbsError> {
    let mut y = system.given_state().clone();
    system.assemble(t, &mut y)?;
    degrees_of_freedom(system, &y)
}

/// The kinematic state at `t`, the positions found by Newton from those of `guess`.
pub fn solve_kinematic_state(
    system: &MultibodySystem,
    t: f64,
    guess: &DVector<f64>,
) -> Result<KinematicState, MbsError> {
    let mut y = guess.clone();
    let iterations = system.assemble(t, &mut y)?;
    system.project_velocities(t, &mut y)?;
    let (acceleration, lambda) = system.compute_accelerations_and_multipliers(t, &y)?;
    let layout = *system.layout();
    y.rows_mut(layout.lambda_offset(), layout.constraint_rows())
        .copy_from(&lambda);
    let mut yp = DVector::zeros(layout.size());
    for (k, part) in system.moving_parts().enumerate() {
        let (qo, vo) = (layout.position_offset(part), layout.velocity_offset(part));
        let e = system.parameters(&y, part);
        let omega = MultibodySystem::vector_at(&y, vo + 3);
        yp.rows_mut(qo, 3).copy_from(&y.rows(vo, 3));
        yp.fixed_rows_mut::<4>(qo + 3)
            .copy_from(&(super::mbs::quaternion::g_matrix(&e).transpose() * omega * 0.5));
        yp.rows_mut(vo, 6).copy_from(&acceleration.rows(6 * k, 6));
    }
    Ok(KinematicState { y, yp, iterations })
}

/// The state `h` later by a second-order Taylor step of every part's motion (the Newton
/// start of the next output time).
fn extrapolate(system: &MultibodySystem, state: &KinematicState, h: f64) -> DVector<f64> {
    let layout = *system.layout();
    let mut y = state.y.clone();
    for part in system.moving_parts() {
        let (qo, vo) = (layout.position_offset(part), layout.velocity_offset(part));
        let at = |v: &DVector<f64>, o| MultibodySystem::vector_at(v, o);
        let dr = at(&state.y, vo) * h + at(&state.yp, vo) * (0.5 * h * h);
        let dtheta: Vector3<f64> = at(&state.y, vo + 3) * h + at(&state.yp, vo + 3) * (0.5 * h * h);
        for i in 0..3 {
            y[qo + i] += dr[i];
        }
        let e = system.parameters(&state.y, part);
        let rotation =
            UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(e[0], e[1], e[2], e[3]))
                * UnitQuaternion::from_scaled_axis(dtheta);
        y.fixed_rows_mut::<4>(qo + 3)
            .copy_from(&parameters_of(&rotation));
        let mut v = y.rows_mut(vo, 6);
        v += state.yp.rows(vo, 6) * h;
    }
    y
}

/// Runs a kinematic analysis from `settings.start` to `settings.end`, calling `sink` with a
/// frame at the start and every `output_step`; frames already given stay given when a later
/// time fails.
pub fn run_kinematics(
    system: &MultibodySystem,
    contacts: &[Arc<ContactForce>],
    settings: &KinematicsSettings,
    sink: &mut dyn FnMut(&Frame, &KinematicState) -> std::io::Result<()>,
) -> Result<KinematicsSummary, KinematicsError> {
    let KinematicsSettings {
        start,
        end,
        output_step,
    } = *settings;
    if !(start.is_finite() && end.is_finite() && end >= start) {
        return Err(KinematicsError::Settings(format!(
            "END = {end:?} must be finite and >= START = {start:?}"
        )));
    }
    if !(output_step.is_finite() && output_step > 0.0) {
        return Err(KinematicsError::Settings(format!(
            "DTOUT = {output_step:?} must be finite and > 0"
        )));
    }
    let mut first = system.given_state().clone();
    system
        .assemble(start, &mut first)
        .map_err(|source| KinematicsError::Solve { t: start, source })?;
    let dof = degrees_of_freedom(system, &first)
        .map_err(|source| KinematicsError::Solve { t: start, source })?;
    if dof > 0 {
        let parts = system.layout().parts();
        return Err(KinematicsError::DegreesOfFreedom {
            dof,
            parts,
            independent: 6 * parts - dof,
        });
    }
    let outputs = ((end - start) / output_step).round().max(0.0) as u64;
    let mut summary = KinematicsSummary::default();
    let mut guess = first;
    for k in 0..=outputs {
        let t = if k == outputs && k > 0 {
            end
        } else {
            start + k as f64 * output_step
        };
        let state = solve_kinematic_state(system, t, &guess)
            .map_err(|source| KinematicsError::Solve { t, source })?;
        let frame = compute_frame(system, contacts, t, &state.y)
            .map_err(|source| KinematicsError::Evaluation { t, source })?;
        sink(&frame, &state).map_err(|source| KinematicsError::Output { t, source })?;
        summary.frames += 1;
        summary.iterations += state.iterations;
        let next = if k + 1 == outputs {
            end
        } else {
            start + (k + 1) as f64 * output_step
        };
        guess = extrapolate(system, &state, next - t);
    }
    Ok(summary)
}

impl MultibodySystem {
    /// The reaction of one constraint element (`JOINT/3`, `MOTION/1`, `JPRIM/2`) on its two
    /// parts at `y`: `−Φ_vᵀλ` over its rows only, as a world force and a world torque about
    /// each part's CM (ground included, first I's part then J's); `None` for an unknown name.
    pub fn element_reaction(
        &self,
        y: &DVector<f64>,
        name: &str,
    ) -> Result<Option<[(super::mbs::PartId, super::mbs::Load); 2]>, EvaluationError> {
        let Some(element) = self.constraints.iter().find(|c| c.name == name) else {
            return Ok(None);
        };
        let states = self.part_states(y)?;
        let (pose_a, pose_b) = (
            &states[element.part_i.0].pose_w,
            &states[element.part_j.0].pose_w,
        );
        let start = self.layout.lambda_offset() + element.row;
        let lambda: Vec<f64> = y
            .rows(start, element.primitives.len())
            .iter()
            .copied()
            .collect();
        let g = element.generalized_reaction(pose_a, pose_b, &lambda);
        let load =
            |force: Vector3<f64>, torque_body: Vector3<f64>, pose: &nalgebra::Isometry3<f64>| {
                super::mbs::Load {
                    force_w: -force,
                    torque_w: -(pose.rotation * torque_body),
                }
            };
        Ok(Some([
            (element.part_i, load(g[0], g[1], pose_a)),
            (element.part_j, load(g[2], g[3], pose_b)),
        ]))
    }
}
