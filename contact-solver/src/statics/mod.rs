//! Static equilibrium (Adams SIMULATE/STATICS with the EQUILIBRIUM settings).
//!
//! The equilibrium is the state where velocities and accelerations vanish and every force —
//! gravity, SFORCEs, springs, CONTACTs with their stiffness law — balances the constraint
//! reactions: with `v = 0` and `v̇ = 0` the dynamic rows of the multibody residual read
//! `Φ_vᵀλ − Q(q, 0, t) = 0`, and the position constraints `Φ(q, t) = 0` hold. Contact damping
//! and friction act through velocities, so at rest they contribute nothing (μ(0) = 0: SPEC §6).
//!
//! Two methods, both ending in the same Newton iteration ([`newton`]):
//! - **Static** (the default): Newton on `(q, λ)` in virtual displacements `[δr, δθ′]` per part,
//!   with the Jacobian of the integrator's Newton matrix taken at `c = 0` (solver-notes §2.3),
//!   each part's increment clamped to TLIMIT (translation) and ALIMIT (rotation), STABILITY
//!   times the mass and damping matrices added to the stiffness matrix, converged when the
//!   last relative correction is within ERROR and the force imbalance within IMBALANCE, or
//!   the imbalance within the round-off the stiffness leaves
//!   ([`newton::roundoff_imbalance`], where no step can lower it further), at
//!   most MAXIT iterations. A step after which a force element
//!   acts that did not act before (a contact coming into contact: Adams' contact-force
//!   sensing) ends the static method, since the Jacobian had no stiffness for it.
//! - **Quasi-dynamic** (EQUILIBRIUM/DYNAMIC, and the fallback when static Newton fails — a part
//!   dropped onto a plane has no contact stiffness at the start, so the static Jacobian is
//!   singular in that direction): the dynamics with added mass-proportional damping, at frozen
//!   time, integrated by the BDF until the parts have settled, then the same Newton
//!   ([`quasi_dynamic`]).
//!
//! **STABILITY** (Adams EQUILIBRIUM/STABILITY): the fraction of the mass matrix `M` and the
//! damping matrix `C` added to the stiffness matrix `K` of the static Jacobian, so a neutral
//! equilibrium — a direction in which the parts move without changing the potential energy, as
//! a part resting on a contact is free to slide along it — keeps a solvable Newton matrix
//! `K + s·(M + C)`. `C` is the partial of the forces with respect to the velocities (contact
//! damping, damped SFORCEs), taken from the velocity columns of the residual's Jacobian at
//! rest. The term multiplies the Newton step, not the state: the residual Newton drives to
//! zero is the unmodified static residual, so STABILITY changes how the iteration converges,
//! never the equilibrium it converges to. With STABILITY = 0 a neutral equilibrium makes the
//! Jacobian singular and the static method hands over to the quasi-dynamic one.
//!
//! **AUGMENTED_LAGRANGIAN_FORMULATION**: the equilibrium found by either method is refined by
//! outer multiplier updates, each followed by Newton, until every such contact's penetration
//! is within its tolerance ([`augmented`]).
//!
//! A failure returns [`StaticsError::NotConverged`] with a diagnosis: the imbalance, the part
//! and the force element that dominate it, the worst constraint, the iterations.

pub mod augmented;
mod diagnosis;
pub mod newton;
pub mod quasi_dynamic;

pub use diagnosis::StaticsDiagnosis;

use super::bdf::IntegratorSettings;
use super::mbs::{MbsError, MultibodySystem};
use nalgebra::DVector;

/// The EQUILIBRIUM settings, in model units (Adams defaults in [`Default`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticsSettings {
    /// TLIMIT: the largest translation of a part's CM per Newton iteration (> 0).
    pub tlimit: f64,
    /// ALIMIT: the largest rotation of a part per Newton iteration, radians (> 0).
    pub alimit: f64,
    /// MAXIT: the most Newton iterations of one static solve (≥ 1).
    pub maxit: usize,
    /// ERROR: convergence needs the last correction below this, relative: translations over
    /// the model's length scale `L`, rotations in radians (> 0).
    pub error: f64,
    /// IMBALANCE: convergence needs every force row of the residual below this, and every
    /// torque row below `IMBALANCE·L` (force units; > 0).
    pub imbalance: f64,
    /// STABILITY: the fraction of the mass and damping matrices added to the stiffness
    /// matrix of the static Jacobian, so neutral equilibria (no stiffness in some direction)
    /// keep a solvable Newton matrix (≥ 0; it does not move the equilibrium).
    pub stability: f64,
    /// DYNAMIC: find the equilibrium by the quasi-dynamic method from the start.
    pub dynamic: bool,
    /// The integrator settings of the quasi-dynamic method.
    pub integrator: IntegratorSettings,
}

impl Default for StaticsSettings {
    fn default() -> Self {
        Self {
            tlimit: 20.0,
            alimit: 10f64.to_radians(),
            maxit: 25,
            error: 1e-4,
            imbalance: 1e-4,
            stability: 1e-5,
            dynamic: false,
            integrator: IntegratorSettings::default(),
        }
    }
}

impl StaticsSettings {
    /// Checks every setting's range; the error names the argument, the value and the range.
    pub fn validate(&self) -> Result<(), StaticsError> {
        let checks = [
            ("TLIMIT", self.tlimit, self.tlimit > 0.0, "> 0"),
            ("ALIMIT", self.alimit, self.alimit > 0.0, "> 0"),
            ("ERROR", self.error, self.error > 0.0, "> 0"),
            ("IMBALANCE", self.imbalance, self.imbalance > 0.0, "> 0"),
            ("STABILITY", self.stability, self.stability >= 0.0, ">= 0"),
        ];
        for (argument, value, ok, allowed) in checks {
            if !(value.is_finite() && ok) {
                return Err(StaticsError::Settings(format!(
                    "EQUILIBRIUM/{argument} = {value:?} is out of range: must be finite and {allowed}"
                )));
            }
        }
        if self.maxit == 0 {
            return Err(StaticsError::Settings(
                "EQUILIBRIUM/MAXIT = 0 is out of range: must be >= 1".into(),
            ));
        }
        self.integrator
            .validate()
            .map_err(|e| StaticsError::Settings(format!("INTEGRATOR (quasi-dynamic): {e}")))
    }
}

/// Which method found the equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub enum StaticsMethod {
    /// Static Newton from the start.
    Newton,
    /// The quasi-dynamic method, then Newton. `newton_failure` says why the static Newton was
    /// abandoned (`None` when EQUILIBRIUM/DYNAMIC asked for the quasi-dynamic method).
    QuasiDynamic {
        /// The static Newton's failure that caused the fallback.
        newton_failure: Option<String>,
        /// Integrator steps of the damped dynamics.
        steps: u64,
        /// The (frozen-time) duration integrated.
        duration: f64,
    },
}

impl std::fmt::Display for StaticsMethod {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Newton => write!(f, "static Newton"),
            Self::QuasiDynamic {
                newton_failure: None,
                steps,
                duration,
            } => write!(
                f,
                "quasi-dynamic (EQUILIBRIUM/DYNAMIC: {steps} damped steps over {duration:e}) then Newton"
            ),
            Self::QuasiDynamic {
                newton_failure: Some(why),
                steps,
                duration,
            } => write!(
                f,
                "quasi-dynamic fallback ({steps} damped steps over {duration:e}) then Newton, after static Newton failed: {why}"
            ),
        }
    }
}

/// A static equilibrium.
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    /// The state: equilibrium positions, zero velocities, the constraint multipliers.
    pub y: DVector<f64>,
    /// How it was found.
    pub method: StaticsMethod,
    /// Newton iterations, all attempts included.
    pub iterations: usize,
    /// The final force imbalance (largest force row, torque rows over `L`).
    pub imbalance: f64,
}

/// Why no equilibrium was found.
#[derive(Debug, thiserror::Error)]
pub enum StaticsError {
    /// A setting is out of range.
    #[error("{0}")]
    Settings(String),
    /// The start could not be assembled.
    #[error("statics: the start: {0}")]
    Initial(#[from] MbsError),
    /// Neither method converged.
    #[error("statics did not converge: {0}")]
    NotConverged(Box<StaticsDiagnosis>),
}

/// Finds the static equilibrium at time `t` from the positions in `y` (velocities are ignored;
/// the positions are first assembled onto the constraints). The multipliers in the result are
/// the constraint reactions at equilibrium.
pub fn solve_statics(
    system: &mut MultibodySystem,
    t: f64,
    y: &DVector<f64>,
    settings: &StaticsSettings,
) -> Result<Equilibrium, StaticsError> {
    settings.validate()?;
    let mut start = y.clone();
    system.assemble(t, &mut start)?;
    newton::zero_velocities(system, &mut start);
    let found = if settings.dynamic {
        quasi_dynamic::settle(system, t, &start, settings, None)?
    } else {
        let mut trial = start.clone();
        match newton::solve(system, t, &mut trial, settings, true) {
            Ok(report) => Equilibrium {
                y: trial,
                method: StaticsMethod::Newton,
                iterations: report.iterations,
                imbalance: report.imbalance,
            },
            Err(failure) => quasi_dynamic::settle(system, t, &start, settings, Some(failure))?,
        }
    };
    augmented::augment(system, t, found, settings)
}
