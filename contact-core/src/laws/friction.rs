//! Coulomb friction with Adams' continuous μ(v), the friction force and the friction torque.

use super::step::{Smooth, Step};
use crate::error::{InvalidArgument, positive};
use crate::{Matrix3, Vector3};

/// The Coulomb friction parameters by name, for [`CoulombFriction::from_params`]: two
/// coefficients and two velocities that a positional call could swap without a compiler error.
///
/// ```
/// use contact_core::laws::{CoulombFriction, CoulombParams};
///
/// let friction = CoulombFriction::from_params(CoulombParams {
///     mu_static: 0.3,
///     mu_dynamic: 0.1,
///     stiction_velocity: 0.1,
///     friction_velocity: 1.0,
/// })?;
/// // Sliding fast: the dynamic coefficient, opposing the slip.
/// assert_eq!(friction.mu(2.0).value, -0.1);
/// # Ok::<(), contact_core::InvalidArgument>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoulombParams {
    /// MU_STATIC μs > 0.
    pub mu_static: f64,
    /// MU_DYNAMIC μd in (0, μs].
    pub mu_dynamic: f64,
    /// STICTION_TRANSITION_VELOCITY vs > 0.
    pub stiction_velocity: f64,
    /// FRICTION_TRANSITION_VELOCITY vd > vs.
    pub friction_velocity: f64,
}

/// Adams' Coulomb friction: MU_STATIC μs, MU_DYNAMIC μd, STICTION_TRANSITION_VELOCITY vs,
/// FRICTION_TRANSITION_VELOCITY vd, with `0 < μd ≤ μs` and `0 < vs < vd`.
///
/// The signed coefficient of slip velocity v (Adams CONTACT, friction force):
/// ```text
/// μ(v) =  STEP(v, −vs, μs, vs, −μs)            |v| ≤ vs   (= −(μs/2)·x·(3 − x²), x = v/vs)
/// μ(v) = −sign(v)·STEP(|v|, vs, μs, vd, μd)    vs < |v| < vd
/// μ(v) = −sign(v)·μd                           |v| ≥ vd
/// ```
/// so μ(0) = 0, μ(±vs) = ∓μs, μ(±vd) = ∓μd: it opposes the slip, is odd and continuously
/// differentiable, and there is no true stiction (Adams FORTRAN models none).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoulombFriction {
    mu_static: f64,
    mu_dynamic: f64,
    stiction_velocity: f64,
    friction_velocity: f64,
    falling: Step,
}

/// A friction force vector with its partial derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionForce {
    /// The force on I, opposite the slip velocity of I relative to J.
    pub force: Vector3,
    /// ∂force/∂slip (3×3).
    pub d_slip: Matrix3,
    /// ∂force/∂Fn.
    pub d_normal_force: Vector3,
}

/// A friction torque about the contact normal with its partial derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionTorque {
    /// Signed torque on I about the normal (opposes the spin).
    pub torque: f64,
    /// ∂T/∂ω.
    pub d_spin: f64,
    /// ∂T/∂Fn.
    pub d_normal_force: f64,
    /// ∂T/∂A (0 at A = 0, where it is unbounded).
    pub d_area: f64,
}

impl CoulombFriction {
    /// Coulomb friction from named parameters, validated as [`Self::new`] validates them.
    pub fn from_params(params: CoulombParams) -> Result<Self, InvalidArgument> {
        Self::new(
            params.mu_static,
            params.mu_dynamic,
            params.stiction_velocity,
            params.friction_velocity,
        )
    }

    /// The parameters by name.
    pub fn params(&self) -> CoulombParams {
        CoulombParams {
            mu_static: self.mu_static,
            mu_dynamic: self.mu_dynamic,
            stiction_velocity: self.stiction_velocity,
            friction_velocity: self.friction_velocity,
        }
    }

    /// Validates the four arguments, in the order MU_STATIC, MU_DYNAMIC,
    /// STICTION_TRANSITION_VELOCITY, FRICTION_TRANSITION_VELOCITY (see the type's docs for the
    /// ranges; [`Self::from_params`] names them).
    pub fn new(
        mu_static: f64,
        mu_dynamic: f64,
        stiction_velocity: f64,
        friction_velocity: f64,
    ) -> Result<Self, InvalidArgument> {
        let mu_static = positive("MU_STATIC", mu_static)?;
        let mu_dynamic = positive("MU_DYNAMIC", mu_dynamic)?;
        if mu_dynamic > mu_static {
            return Err(InvalidArgument::new(
                "MU_DYNAMIC",
                mu_dynamic,
                format!("in (0, MU_STATIC = {mu_static:?}]"),
            ));
        }
        let vs = positive("STICTION_TRANSITION_VELOCITY", stiction_velocity)?;
        let vd = positive("FRICTION_TRANSITION_VELOCITY", friction_velocity)?;
        if vd <= vs {
            return Err(InvalidArgument::new(
                "FRICTION_TRANSITION_VELOCITY",
                vd,
                format!("> STICTION_TRANSITION_VELOCITY = {vs:?}"),
            ));
        }
        let falling = Step::new(vs, mu_static, vd, mu_dynamic)?;
        Ok(Self {
            mu_static,
            mu_dynamic,
            stiction_velocity: vs,
            friction_velocity: vd,
            falling,
        })
    }

    /// MU_STATIC.
    pub fn mu_static(&self) -> f64 {
        self.mu_static
    }
    /// MU_DYNAMIC.
    pub fn mu_dynamic(&self) -> f64 {
        self.mu_dynamic
    }
    /// STICTION_TRANSITION_VELOCITY.
    pub fn stiction_velocity(&self) -> f64 {
        self.stiction_velocity
    }
    /// FRICTION_TRANSITION_VELOCITY.
    pub fn friction_velocity(&self) -> f64 {
        self.friction_velocity
    }

    /// The signed coefficient μ(v) and dμ/dv.
    pub fn mu(&self, v: f64) -> Smooth {
        let vs = self.stiction_velocity;
        let speed = v.abs();
        if speed <= vs {
            // STEP(v, −vs, μs, vs, −μs) expanded: exactly odd, no cancellation near v = 0.
            let x = v / vs;
            Smooth {
                value: -0.5 * self.mu_static * x * (3.0 - x * x),
                slope: -1.5 * self.mu_static * (1.0 - x * x) / vs,
            }
        } else {
            let s = self.falling.cubic(speed);
            Smooth {
                value: -v.signum() * s.value,
                slope: -s.slope,
            }
        }
    }

    /// `μ(v)/v` for v ≥ 0, finite at v = 0 (its limit dμ/dv(0) = −1.5·μs/vs).
    fn mu_over_speed(&self, speed: f64) -> f64 {
        self.mu_over_speed_with_slope(speed).0
    }

    /// `m(s) = μ(s)/s` and `dm/ds` for a slip speed s ≥ 0, finite at 0 (`m(0) = μ′(0)`,
    /// `dm/ds(0) = 0`).
    pub(super) fn mu_over_speed_with_slope(&self, speed: f64) -> (f64, f64) {
        let vs = self.stiction_velocity;
        if speed <= vs {
            // μ = −(μs/2)·x·(3 − x²): m = −(μs/2)·(3 − x²)/vs, dm/ds = μs·x/vs².
            let x = speed / vs;
            (
                -0.5 * self.mu_static * (3.0 - x * x) / vs,
                self.mu_static * x / (vs * vs),
            )
        } else {
            let mu = self.mu(speed);
            let m = mu.value / speed;
            (m, (mu.slope - m) / speed)
        }
    }

    /// The friction force on I for slip velocity `slip` (velocity of I's contact point relative
    /// to J's, tangential) and normal force `normal_force` ≥ 0:
    /// `F = μ(|v|)·Fn·v/|v|` (μ signed, so F opposes v), and 0 at v = 0.
    ///
    /// `∂F/∂v = Fn·(μ′(s)·v̂v̂ᵀ + μ(s)/s·(I − v̂v̂ᵀ))`, s = |v|, with the limit `Fn·μ′(0)·I` at 0.
    pub fn force(&self, slip: &Vector3, normal_force: f64) -> FrictionForce {
        let s = slip.norm();
        let ratio = self.mu_over_speed(s);
        if s == 0.0 {
            return FrictionForce {
                force: Vector3::zeros(),
                d_slip: Matrix3::identity() * (normal_force * ratio),
                d_normal_force: Vector3::zeros(),
            };
        }
        let dir = slip / s;
        let mu = self.mu(s);
        let outer = dir * dir.transpose();
        FrictionForce {
            force: slip * (ratio * normal_force),
            d_slip: (outer * mu.slope + (Matrix3::identity() - outer) * ratio) * normal_force,
            d_normal_force: slip * ratio,
        }
    }

    /// The friction torque on I about the contact normal for relative spin `spin` (rad per
    /// time, about the normal), normal force `normal_force` and contact area `area`:
    /// `T = (2/3)·R·μ(ω·R)·Fn`, `R = sqrt(A/π)` (Marks' flat pivot under uniform pressure;
    /// μ signed, so T opposes the spin). Zero when A = 0.
    pub fn torque(&self, spin: f64, normal_force: f64, area: f64) -> FrictionTorque {
        if area.is_nan() || area <= 0.0 {
            return FrictionTorque {
                torque: 0.0,
                d_spin: 0.0,
                d_normal_force: 0.0,
                d_area: 0.0,
            };
        }
        let radius = (area / std::f64::consts::PI).sqrt();
        let mu = self.mu(spin * radius);
        let k = 2.0 / 3.0;
        let d_radius = k * normal_force * (mu.value + radius * mu.slope * spin);
        FrictionTorque {
            torque: k * radius * mu.value * normal_force,
            d_spin: k * radius * radius * mu.slope * normal_force,
            d_normal_force: k * radius * mu.value,
            d_area: d_radius * radius / (2.0 * area),
        }
    }
}
