//! Errors of building a multibody system and of finding its initial conditions.

use crate::dae::EvaluationError;
use thiserror::Error;

/// Why a multibody system could not be built or started.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MbsError {
    /// A numeric argument is out of its allowed range.
    #[error("{element}: {argument} = {value} is out of range: must be {allowed}")]
    InvalidArgument {
        /// The element the argument belongs to (e.g. `PART/2`).
        element: String,
        /// The argument's name.
        argument: &'static str,
        /// The value given, at round-trip precision.
        value: String,
        /// The allowed range.
        allowed: &'static str,
    },
    /// A part id that the builder never returned.
    #[error("{element}: part id {id} does not exist (the model has parts 0..={last}, 0 = ground)")]
    UnknownPart {
        /// The element that refers to the part.
        element: String,
        /// The id given.
        id: usize,
        /// The largest valid id.
        last: usize,
    },
    /// A marker id that the builder never returned.
    #[error("{element}: marker id {id} does not exist (the model has {count} markers)")]
    UnknownMarker {
        /// The element that refers to the marker.
        element: String,
        /// The id given.
        id: usize,
        /// How many markers exist.
        count: usize,
    },
    /// A constraint or force whose two markers sit on the same part (it would constrain nothing).
    #[error("{element}: markers I and J are both on part {part}; they must be on different parts")]
    SamePart {
        /// The element.
        element: String,
        /// The part both markers are on.
        part: usize,
    },
    /// A MOTION on a joint type or degree of freedom that cannot carry it.
    #[error("{motion}: a {dof} motion needs a {allowed} joint, but {joint} is {kind}")]
    MotionOnWrongJoint {
        /// The motion.
        motion: String,
        /// The joint it refers to.
        joint: String,
        /// The joint's kind.
        kind: &'static str,
        /// `translational` or `rotational`.
        dof: &'static str,
        /// The joint kinds allowed for that degree of freedom.
        allowed: &'static str,
    },
    /// A constraint id that the builder never returned.
    #[error("{element}: constraint id {id} does not exist (the model has {count} constraints)")]
    UnknownConstraint {
        /// The element that refers to the constraint.
        element: String,
        /// The id given.
        id: usize,
        /// How many constraints exist.
        count: usize,
    },
    /// Newton iteration on Φ(q, t) = 0 did not converge from the user's positions.
    #[error(
        "assembly failed after {iterations} iterations: |Φ|/L = {residual:e} on {worst} \
         (tolerance {tolerance:e}); check that the joints can be closed from the given positions"
    )]
    AssemblyFailed {
        /// Iterations made.
        iterations: usize,
        /// The largest constraint residual left, relative: lengths over the model's length
        /// scale L, angles (cosines) as they are.
        residual: f64,
        /// The tolerance asked for.
        tolerance: f64,
        /// The element with the largest residual.
        worst: String,
    },
    /// The acceleration-level system [M Φ_vᵀ; Φ_v 0] is singular at the assembled
    /// configuration although the equations were independent at the given one (equations
    /// redundant there were removed when the system was built): the assembly moved the
    /// mechanism into a singular (toggle) position, or a part has no mass in a free direction.
    #[error(
        "the constraints are redundant or singular at t = {time}: [M Φ_vᵀ; Φ_v 0] cannot be \
         factored; the assembled positions are a singular configuration of the joints (start \
         the mechanism away from it) or a part lacks mass or inertia in a free direction"
    )]
    SingularConstraints {
        /// The time of the initial conditions.
        time: f64,
    },
    /// Equations removed as redundant at the initial configuration do not hold once the
    /// other equations are assembled: the constraints contradict each other (two REVOLUTEs on
    /// one part with different axes).
    #[error(
        "inconsistent redundant constraints between {}: {}; the joints cannot all hold, \
         remove or realign one of them",
        elements.join(", "),
        equations.join("; ")
    )]
    InconsistentRedundancy {
        /// The elements involved, sorted.
        elements: Vec<String>,
        /// Each violated equation: element, equation, what it constrains, what implies it and
        /// its relative value.
        equations: Vec<String>,
    },
    /// The system has no moving part (only ground): no analysis has anything to solve.
    #[error("the model has no moving part: nothing to simulate")]
    NoMovingPart,
    /// With no constraint, the equations of motion `M v̇ = Q − ω′×Jω′` gave accelerations that
    /// are not finite: a MASS or inertia so large or small (1E308, 1E-308) that the
    /// products overflow, or forces that do.
    #[error(
        "the accelerations at t = {time} are not finite (the model has no joint or JPRIM, so \
         the mass matrix alone was solved): check the parts' MASS and IP and the forces for \
         values near the floating-point limits (such as 1E308)"
    )]
    AccelerationsNotFinite {
        /// The time of the initial conditions.
        time: f64,
    },
    /// An element could not be evaluated at the initial state.
    #[error(transparent)]
    Evaluation(#[from] EvaluationError),
}

impl MbsError {
    /// Builds an [`MbsError::InvalidArgument`] for a numeric value.
    pub(crate) fn invalid(
        element: &str,
        argument: &'static str,
        value: f64,
        allowed: &'static str,
    ) -> Self {
        Self::InvalidArgument {
            element: element.to_owned(),
            argument,
            value: format!("{value:?}"),
            allowed,
        }
    }
}
