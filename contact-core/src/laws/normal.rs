//! Normal force laws: IMPACT, POISSON (ours) and the augmented-Lagrangian update.

use super::step::Step;
use crate::error::{InvalidArgument, positive};

/// A normal force magnitude with its partial derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NormalForce {
    /// Fn ≥ 0.
    pub force: f64,
    /// ∂Fn/∂δ.
    pub d_penetration: f64,
    /// ∂Fn/∂δ̇.
    pub d_rate: f64,
}

impl NormalForce {
    /// No force.
    pub const ZERO: Self = Self {
        force: 0.0,
        d_penetration: 0.0,
        d_rate: 0.0,
    };
}

/// The IMPACT parameters by name, for [`ImpactLaw::from_params`]: four numbers of different
/// dimensions that a positional call could swap without a compiler error.
///
/// ```
/// use contact_core::laws::{ImpactLaw, ImpactParams};
///
/// let law = ImpactLaw::from_params(ImpactParams {
///     stiffness: 1e5,
///     exponent: 2.2,
///     damping: 10.0,
///     max_penetration: 0.1,
/// })?;
/// assert_eq!(law.dmax(), 0.1);
/// # Ok::<(), contact_core::InvalidArgument>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactParams {
    /// STIFFNESS k > 0 (force / length^e).
    pub stiffness: f64,
    /// EXPONENT e > 0 (Adams advises e ≥ 1.5).
    pub exponent: f64,
    /// DAMPING c > 0 (force / velocity), reached at `max_penetration`.
    pub damping: f64,
    /// DMAX > 0: the penetration at which the damping reaches `c` (length).
    pub max_penetration: f64,
}

/// The IMPACT law (Adams CONTACT/IMPACT):
///
/// `Fn = max(0, k·δ^e + STEP(δ, 0, 0, dmax, c)·δ̇)` for δ > 0, else 0.
///
/// The damping coefficient ramps smoothly from 0 at first touch to `c` at δ = dmax, so the force
/// starts at zero; the clamp stops it pulling the bodies together while they separate quickly.
/// Where the clamp is active both partials are 0. With `e < 1`, ∂Fn/∂δ grows without bound as
/// δ → 0⁺ (documented by Adams: use e ≥ 1.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactLaw {
    stiffness: f64,
    exponent: f64,
    damping: f64,
    dmax: f64,
    ramp: Step,
}

impl ImpactLaw {
    /// IMPACT from named parameters, validated as [`Self::new`] validates them: each must be
    /// finite and > 0, and the error names the first that is not, with its value.
    pub fn from_params(params: ImpactParams) -> Result<Self, InvalidArgument> {
        Self::new(
            params.stiffness,
            params.exponent,
            params.damping,
            params.max_penetration,
        )
    }

    /// The law's parameters by name.
    pub fn params(&self) -> ImpactParams {
        ImpactParams {
            stiffness: self.stiffness,
            exponent: self.exponent,
            damping: self.damping,
            max_penetration: self.dmax,
        }
    }

    /// IMPACT with STIFFNESS `k` > 0, EXPONENT `e` > 0, DAMPING `c` > 0 and DMAX > 0, in that
    /// order (positional, as the CONTACT statement lists them; [`Self::from_params`] names
    /// them).
    pub fn new(
        stiffness: f64,
        exponent: f64,
        damping: f64,
        dmax: f64,
    ) -> Result<Self, InvalidArgument> {
        let stiffness = positive("STIFFNESS", stiffness)?;
        let exponent = positive("EXPONENT", exponent)?;
        let damping = positive("DAMPING", damping)?;
        let dmax = positive("DMAX", dmax)?;
        let ramp = Step::new(0.0, 0.0, dmax, damping)?;
        Ok(Self {
            stiffness,
            exponent,
            damping,
            dmax,
            ramp,
        })
    }

    /// STIFFNESS k.
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }
    /// EXPONENT e.
    pub fn exponent(&self) -> f64 {
        self.exponent
    }
    /// DAMPING c (full damping, reached at DMAX).
    pub fn damping(&self) -> f64 {
        self.damping
    }
    /// DMAX.
    pub fn dmax(&self) -> f64 {
        self.dmax
    }

    /// The force at penetration `delta` and rate `rate` (positive approaching).
    pub fn force(&self, delta: f64, rate: f64) -> NormalForce {
        if delta.is_nan() || delta <= 0.0 {
            return NormalForce::ZERO;
        }
        let spring = self.stiffness * delta.powf(self.exponent);
        let d_spring = self.exponent * spring / delta;
        let c = self.ramp.cubic(delta);
        let total = spring + c.value * rate;
        if total <= 0.0 {
            return NormalForce::ZERO;
        }
        NormalForce {
            force: total,
            d_penetration: d_spring + c.slope * rate,
            d_rate: c.value,
        }
    }
}

/// The POISSON parameters by name, for [`PoissonLaw::from_params`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoissonParams {
    /// PENALTY p > 0 (force / length).
    pub penalty: f64,
    /// RESTITUTION_COEFFICIENT ε in [0, 1].
    pub restitution: f64,
    /// The transition velocity `v_t` > 0 of the compression/restitution blend (velocity).
    pub transition_velocity: f64,
}

/// The POISSON law. **Ours**: Adams does not publish its formula (SPEC §5).
///
/// A penalty spring stiff `p` while the bodies approach and `ε²·p` while they separate,
/// blended by a STEP in the rate over `±v_t`:
///
/// `Fn = p·δ·(ε² + (1 − ε²)·STEP(δ̇, −v_t, 0, v_t, 1))` for δ > 0, else 0.
///
/// Why it restitutes ε: in compression the spring stores `½·p·δm²` of the entry kinetic energy;
/// unloading along `ε²·p` returns `½·ε²·p·δm²`, so the exit speed is `ε` times the entry speed
/// (exactly so as `v_t → 0`; the blend costs an error of order `v_t / v_entry`). ε = 1 is a
/// conservative spring; ε = 0 is perfectly plastic. The force is continuous everywhere and ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoissonLaw {
    penalty: f64,
    restitution: f64,
    transition_velocity: f64,
    blend: Step,
}

impl PoissonLaw {
    /// POISSON from named parameters, validated as [`Self::new`] validates them.
    pub fn from_params(params: PoissonParams) -> Result<Self, InvalidArgument> {
        Self::new(
            params.penalty,
            params.restitution,
            params.transition_velocity,
        )
    }

    /// The law's parameters by name.
    pub fn params(&self) -> PoissonParams {
        PoissonParams {
            penalty: self.penalty,
            restitution: self.restitution,
            transition_velocity: self.transition_velocity,
        }
    }

    /// POISSON with PENALTY `p` > 0, RESTITUTION_COEFFICIENT ε in [0, 1] and the transition
    /// velocity `v_t` > 0 of the compression/restitution blend.
    pub fn new(
        penalty: f64,
        restitution: f64,
        transition_velocity: f64,
    ) -> Result<Self, InvalidArgument> {
        let penalty = positive("PENALTY", penalty)?;
        if !(0.0..=1.0).contains(&restitution) {
            return Err(InvalidArgument::new(
                "RESTITUTION_COEFFICIENT",
                restitution,
                "in [0, 1]",
            ));
        }
        let transition_velocity = positive("POISSON transition velocity", transition_velocity)?;
        let blend = Step::new(-transition_velocity, 0.0, transition_velocity, 1.0)?;
        Ok(Self {
            penalty,
            restitution,
            transition_velocity,
            blend,
        })
    }

    /// PENALTY p.
    pub fn penalty(&self) -> f64 {
        self.penalty
    }
    /// RESTITUTION_COEFFICIENT ε.
    pub fn restitution(&self) -> f64 {
        self.restitution
    }
    /// The blend's transition velocity `v_t`.
    pub fn transition_velocity(&self) -> f64 {
        self.transition_velocity
    }

    /// The force at penetration `delta` and rate `rate` (positive approaching).
    pub fn force(&self, delta: f64, rate: f64) -> NormalForce {
        if delta.is_nan() || delta <= 0.0 {
            return NormalForce::ZERO;
        }
        let e2 = self.restitution * self.restitution;
        let s = self.blend.cubic(rate);
        let factor = e2 + (1.0 - e2) * s.value;
        NormalForce {
            force: self.penalty * delta * factor,
            d_penetration: self.penalty * factor,
            d_rate: self.penalty * delta * (1.0 - e2) * s.slope,
        }
    }
}

/// The augmented-Lagrangian refinement of POISSON (SPEC §5), iterated by the solver inside its
/// corrector: with multiplier λ_k the force is `Fn = max(0, λ_k + F_P(δ, δ̇))` (F_P the POISSON
/// law), and after each corrector pass `λ_{k+1} = max(0, λ_k + p·δ_k)` until `δ_k` is below
/// the tolerance. The multiplier carries the constraint force, so penetration becomes small and
/// the force insensitive to `p`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AugmentedLagrangian {
    penalty: f64,
}

impl AugmentedLagrangian {
    /// The update with penalty `p` > 0 (the POISSON PENALTY).
    pub fn new(penalty: f64) -> Result<Self, InvalidArgument> {
        Ok(Self {
            penalty: positive("PENALTY", penalty)?,
        })
    }

    /// `λ_{k+1} = max(0, λ_k + p·δ_k)`, with `∂λ_{k+1}/∂δ_k` (p where active, else 0).
    pub fn update(&self, lambda: f64, delta: f64) -> (f64, f64) {
        let next = lambda + self.penalty * delta;
        if next > 0.0 {
            (next, self.penalty)
        } else {
            (0.0, 0.0)
        }
    }

    /// `Fn = max(0, λ + F_P)` given the POISSON law's force `law`; partials pass through where
    /// the force is positive.
    pub fn force(&self, lambda: f64, law: NormalForce) -> NormalForce {
        let total = lambda + law.force;
        if total > 0.0 {
            NormalForce {
                force: total,
                ..law
            }
        } else {
            NormalForce::ZERO
        }
    }
}
