//! Applied forces: the [`ForceElement`] trait, the state it sees, and its partial derivatives.
//!
//! A force element (spring, SFORCE, contact) acts on a few parts. At each evaluation it gets a
//! [`StateView`] of every part (ground included, as [`PartId::GROUND`]) and writes one [`Load`]
//! per part it acts on. For the Newton matrix it may supply analytic partials
//! ([`ForceElement::partials`]); otherwise the system differences the element alone
//! ([`difference_partials`]): 12 evaluations per moving part it acts on, never the whole model.
//!
//! **Partials layout.** Rows: per part in [`ForceElement::parts`] order, `[force_w (3),
//! torque_w (3)]`. Columns: per part, `[δr (3), θ (3), u (3), ω (3)]`: a displacement of the CM,
//! a small rotation about the CM (world frame, `δa = θ × a`), the CM velocity and the angular
//! velocity, all world frame, each varied with the others held fixed.

use super::part::PartId;
use super::quaternion::skew;
use crate::dae::EvaluationError;
use nalgebra::{DMatrix, Isometry3, Matrix3, UnitQuaternion, Vector3};

/// The kinematic state of one part, world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartState {
    /// Pose of the part (CM) frame in the world.
    pub pose_w: Isometry3<f64>,
    /// Velocity of the CM.
    pub velocity_w: Vector3<f64>,
    /// Angular velocity.
    pub angular_velocity_w: Vector3<f64>,
}

impl PartState {
    /// The ground: at the world frame, at rest.
    pub const GROUND: PartState = PartState {
        pose_w: Isometry3::from_parts(
            nalgebra::Translation3::new(0.0, 0.0, 0.0),
            UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(1.0, 0.0, 0.0, 0.0)),
        ),
        velocity_w: Vector3::new(0.0, 0.0, 0.0),
        angular_velocity_w: Vector3::new(0.0, 0.0, 0.0),
    };

    /// The part's pose and velocities as contact-core's [`BodyMotion`](contact_core::BodyMotion),
    /// for [`ContactKinematics`](contact_core::ContactKinematics).
    pub fn motion(&self) -> contact_core::BodyMotion {
        contact_core::BodyMotion {
            pose_w: self.pose_w,
            velocity_w: self.velocity_w,
            angular_velocity_w: self.angular_velocity_w,
        }
    }

    /// The velocity of a material point of the part at world position `point_w`:
    /// `u + ω × (p − r)`.
    pub fn point_velocity_w(&self, point_w: &Vector3<f64>) -> Vector3<f64> {
        self.velocity_w
            + self
                .angular_velocity_w
                .cross(&(point_w - self.pose_w.translation.vector))
    }
}

/// Read access to the state of every part at one evaluation.
#[derive(Debug, Clone, Copy)]
pub struct StateView<'a> {
    parts: &'a [PartState],
}

impl<'a> StateView<'a> {
    /// A view of `parts`, indexed by [`PartId`] (`parts[0]` is the ground).
    pub fn new(parts: &'a [PartState]) -> Self {
        Self { parts }
    }

    /// The state of part `id`. Ids come from the builder, which checked them.
    pub fn part(&self, id: PartId) -> &PartState {
        &self.parts[id.0]
    }
}

/// A generalized force on one part: a force through its CM and a torque, world frame.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Load {
    /// Force at the CM.
    pub force_w: Vector3<f64>,
    /// Torque about the CM.
    pub torque_w: Vector3<f64>,
}

impl Load {
    /// The load of a force `force_w` applied at world point `point_w` of a part whose CM is at
    /// `cm_w`: the force and its moment `(p − r) × f`.
    pub fn at_point(force_w: Vector3<f64>, point_w: &Vector3<f64>, cm_w: &Vector3<f64>) -> Self {
        Self {
            force_w,
            torque_w: (point_w - cm_w).cross(&force_w),
        }
    }
}

/// An applied force acting on a fixed set of parts.
pub trait ForceElement: Send + Sync {
    /// The name used in messages (e.g. `SFORCE/4`, `CONTACT/2`).
    fn name(&self) -> &str;

    /// The parts it acts on (ground allowed; loads on ground are ignored).
    fn parts(&self) -> &[PartId];

    /// Writes the load on each part of [`Self::parts`] into `loads` (same length, same order).
    fn evaluate(
        &self,
        t: f64,
        state: &StateView<'_>,
        loads: &mut [Load],
    ) -> Result<(), EvaluationError>;

    /// Bounds fixed in the two parts (in [`Self::parts`] order, an element of two parts)
    /// that hold all the element acts through: its loads are zero whenever they are
    /// [`apart`](crate::broad_phase::Bounds::apart). `None` (the default) for an
    /// element that can act at any distance; the broad phase evaluates it always.
    fn bounds(&self) -> Option<[crate::broad_phase::Bounds; 2]> {
        None
    }

    /// The smallest relative speed over which the element's loads change character (a
    /// CONTACT's STICTION_TRANSITION_VELOCITY), if it has one: [`difference_partials`] keeps
    /// its velocity steps well inside it. `None` (the default) for an element without one.
    fn velocity_scale(&self) -> Option<f64> {
        None
    }

    /// Analytic partial derivatives of the loads in the layout of the module docs
    /// (`6·parts` rows, `12·parts` columns), or `None` to let the system difference the
    /// element ([`difference_partials`]).
    fn partials(
        &self,
        _t: f64,
        _state: &StateView<'_>,
    ) -> Option<Result<DMatrix<f64>, EvaluationError>> {
        None
    }

    /// Whether [`Self::partials`] are the loads' true derivatives (to round-off), rather than
    /// an approximation good enough for Newton (a contact's, which hold its geometry frozen).
    /// [`ForcePartials::Exact`] differences the elements that answer `false`. The default
    /// answers `true`.
    fn partials_are_exact(&self) -> bool {
        true
    }

    /// Whether [`Self::step_accepted`], [`Self::attempt_started`] or
    /// [`Self::corrector_converged`] do anything for this element. The system calls those
    /// only on the elements that answer `true` (the default), so a model of many elements
    /// without step state does not visit them all at every step and Newton pass.
    fn tracks_steps(&self) -> bool {
        true
    }

    /// Called once after each step the integrator accepts, with the state at its end: where an
    /// element keeps history (contact onset, augmented-Lagrangian multipliers, output
    /// samples). Evaluations between accepted steps must not change the element. The default
    /// does nothing.
    fn step_accepted(&mut self, _t: f64, _state: &StateView<'_>) {}

    /// Called at the start of every step attempt, accepted or not, before any evaluation of
    /// it: an element whose inner iteration changes it within a step (augmented-Lagrangian
    /// multipliers) returns to its state at the last accepted step. The default does nothing.
    fn attempt_started(&mut self) {}

    /// Called when the corrector has converged on a step attempt, with the state it converged
    /// to: an element with an inner iteration updates itself and returns `true` to have the
    /// corrector run again on the updated forces (the integrator bounds the passes by MAXIT).
    /// The default returns `false`.
    fn corrector_converged(&mut self, _t: f64, _state: &StateView<'_>) -> bool {
        false
    }

    /// Called when a static equilibrium has been found, with its state: an element with an
    /// inner iteration updates itself and returns `true` to have the equilibrium solved again
    /// on the updated forces (the static solver bounds the passes). The default returns
    /// `false`.
    fn equilibrium_converged(&mut self, _t: f64, _state: &StateView<'_>) -> bool {
        false
    }
}

/// Where the Newton matrix takes the force elements' partials from
/// ([`super::MultibodySystem::set_force_partials`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ForcePartials {
    /// Each element's analytic [`ForceElement::partials`] where it supplies them (contacts: one
    /// engine query per Jacobian), the element-local difference otherwise.
    #[default]
    Analytic,
    /// Analytic partials only where they are exact ([`ForceElement::partials_are_exact`]),
    /// the element-local difference elsewhere: where the Jacobian is the answer
    /// (linearization), not a Newton matrix.
    Exact,
    /// The element-local difference ([`difference_partials`]) for every element: 12
    /// evaluations (for a contact, 12 engine queries) per moving part per Jacobian. A check
    /// of the analytic partials, and a way around one that misleads Newton.
    Difference,
}

/// The partials of a force `f(d, ḋ)` acting on part a at marker point `p_I` and `−f` on part b at
/// `p_J`, with `d = p_I − p_J`, in the layout of the module docs (12 × 24).
///
/// `s_i`, `s_j` are the points relative to their CMs, `omega_a`, `omega_b` the angular
/// velocities, `force` the current `f`, `k = ∂f/∂d` and `c = ∂f/∂ḋ`. It applies
/// `∂d/∂θ_a = −s̃_I`, `∂ḋ/∂θ_a = −ω̃_a s̃_I`, `∂ḋ/∂ω_a = −s̃_I` (and the mirror terms for b) and
/// the lever-arm terms `∂(s × f)/∂θ = f̃ s̃`.
#[expect(clippy::too_many_arguments, reason = "the terms of one chain rule")]
pub fn point_pair_partials(
    s_i: &Vector3<f64>,
    s_j: &Vector3<f64>,
    omega_a: &Vector3<f64>,
    omega_b: &Vector3<f64>,
    force: &Vector3<f64>,
    k: &Matrix3<f64>,
    c: &Matrix3<f64>,
    out: &mut DMatrix<f64>,
) {
    let (skew_i, skew_j, skew_f) = (skew(s_i), skew(s_j), skew(force));
    let identity = Matrix3::identity();
    // ∂d/∂x and ∂ḋ/∂x for the 8 column blocks [r_a, θ_a, u_a, ω_a, r_b, θ_b, u_b, ω_b].
    let zero = Matrix3::zeros();
    let dd = [identity, -skew_i, zero, zero, -identity, skew_j, zero, zero];
    let dv = [
        zero,
        -skew(omega_a) * skew_i,
        identity,
        -skew_i,
        zero,
        skew(omega_b) * skew_j,
        -identity,
        skew_j,
    ];
    out.fill(0.0);
    for (block, (d, v)) in dd.iter().zip(dv.iter()).enumerate() {
        let df = k * d + c * v;
        let col = 3 * block;
        let mut torque_a = skew_i * df;
        let mut torque_b = -skew_j * df;
        if block == 1 {
            torque_a += skew_f * skew_i;
        }
        if block == 5 {
            torque_b -= skew_f * skew_j;
        }
        out.fixed_view_mut::<3, 3>(0, col).copy_from(&df);
        out.fixed_view_mut::<3, 3>(3, col).copy_from(&torque_a);
        out.fixed_view_mut::<3, 3>(6, col).copy_from(&(-df));
        out.fixed_view_mut::<3, 3>(9, col).copy_from(&torque_b);
    }
}

/// A velocity column's difference step for a variable of size `scale`: `√ε·scale`, capped at a
/// thousandth of the element's own scale `fine` if it has one, and never below `64·ε·scale`.
fn velocity_step(scale: f64, fine: Option<f64>) -> f64 {
    let h = f64::EPSILON.sqrt() * scale;
    match fine {
        Some(fine) if fine.is_finite() && fine > 0.0 => {
            h.min(1e-3 * fine).max(64.0 * f64::EPSILON * scale)
        }
        _ => h,
    }
}

/// Forward-difference partials of one element in the layout of the module docs, perturbing
/// only the parts it acts on: `12` evaluations per moving part.
///
/// Steps: `√ε·max(|r|, L)` for positions, `√ε` rad for rotations, `√ε·max(|u|, L)` for velocities
/// (L per unit time) and `√ε·max(|ω|, 1)` for angular velocities, with `L` the model's length
/// scale. For an element with a [`ForceElement::velocity_scale`] `vs`, the velocity steps are
/// at most `vs/1000` (and the angular ones `vs/(1000·L)`, the slip they make at a lever arm
/// `L`), so that a difference across a friction law's stiction band is not taken for its slope,
/// but not below `64·ε·max(|u|, L)` (`64·ε·max(|ω|, 1)`), where round-off would rule.
/// Columns of ground parts are zero.
pub fn difference_partials(
    element: &dyn ForceElement,
    t: f64,
    states: &[PartState],
    length_scale: f64,
) -> Result<DMatrix<f64>, EvaluationError> {
    let parts = element.parts();
    let count = parts.len();
    let mut base = vec![Load::default(); count];
    element.evaluate(t, &StateView::new(states), &mut base)?;
    let mut perturbed_loads = vec![Load::default(); count];
    let mut perturbed = states.to_vec();
    let mut out = DMatrix::zeros(6 * count, 12 * count);
    let root_eps = f64::EPSILON.sqrt();
    for (slot, &part) in parts.iter().enumerate() {
        if part.is_ground() {
            continue;
        }
        let original = states[part.0];
        // The velocity columns first: they keep the poses of the base evaluation, so an
        // element that remembers its last geometry query (a CONTACT) answers them without one.
        for column in (6..12).chain(0..6) {
            let (block, axis) = (column / 3, column % 3);
            let mut state = original;
            let step = match block {
                0 => {
                    let h = root_eps * original.pose_w.translation.vector.norm().max(length_scale);
                    state.pose_w.translation.vector[axis] += h;
                    h
                }
                1 => {
                    let h = root_eps;
                    let rotation = UnitQuaternion::from_scaled_axis(Vector3::ith(axis, h));
                    state.pose_w.rotation = rotation * original.pose_w.rotation;
                    h
                }
                2 => {
                    let scale = original.velocity_w.norm().max(length_scale);
                    let h = velocity_step(scale, element.velocity_scale());
                    state.velocity_w[axis] += h;
                    h
                }
                _ => {
                    let scale = original.angular_velocity_w.norm().max(1.0);
                    let slip = element.velocity_scale().map(|vs| vs / length_scale);
                    let h = velocity_step(scale, slip);
                    state.angular_velocity_w[axis] += h;
                    h
                }
            };
            perturbed[part.0] = state;
            element.evaluate(t, &StateView::new(&perturbed), &mut perturbed_loads)?;
            perturbed[part.0] = original;
            for (row_slot, (now, before)) in perturbed_loads.iter().zip(&base).enumerate() {
                let df = (now.force_w - before.force_w) / step;
                let dt = (now.torque_w - before.torque_w) / step;
                for i in 0..3 {
                    out[(6 * row_slot + i, 12 * slot + column)] = df[i];
                    out[(6 * row_slot + 3 + i, 12 * slot + column)] = dt[i];
                }
            }
        }
    }
    Ok(out)
}
