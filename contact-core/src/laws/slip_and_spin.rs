//! Friction of a contact patch that slips and spins at once: one Coulomb budget shared by the
//! friction force and the friction torque (Contensou's coupling).
//!
//! A patch of radius `R` slipping at `v_t` and spinning at `ω_n` slides at `v_t + ω_n·n × r`
//! under each of its points, and Coulomb friction opposes that local slip with `μ·p` per unit
//! area. Taken apart, as [`CoulombFriction::force`] and [`CoulombFriction::torque`] are, the
//! two laws each spend the whole budget `μ·Fn`; and a patch that spins while its centroid
//! barely slips gets the stiction-band gain `μs·Fn/vs` against that slip, where the sliding
//! patch really resists it with about `μ·Fn/(|ω_n|·R)`. Under a spinning flat disk that
//! too-large gain, acting at the contact point below the centre of mass, couples the disk's
//! tilt in one direction to a torque that tilts it in the other, and the tilt grows from
//! round-off into a wobble the step control must then follow.
//!
//! The law here gives both from one slip speed that counts the spin:
//! ```text
//! R = sqrt(A/π),  w = ω_n·R,  s = sqrt(|v_t|² + w²),  m(s) = μ(s)/s
//! F = m(s)·Fn·v_t                    (force on I, opposes the slip)
//! T = (2/3)·R·m(s)·Fn·w              (torque on I about n, opposes the spin)
//! ```
//! with μ Adams' continuous coefficient ([`CoulombFriction::mu`]). It is the force law of SPEC
//! §6 where the patch does not spin (`w = 0`), its torque law where the patch does not slip
//! (`v_t = 0`), and for `|v_t| ≪ |ω_n|·R` the force is `μ·Fn·v_t/(|ω_n|·R)`, the small-slip
//! limit of uniform-pressure Coulomb friction integrated over the disk. In between it is a
//! smooth interpolation, within a factor of 8/3 of the integrated torque at `|v_t| ≫ |ω_n|·R`
//! (the test `laws::tests::slip_and_spin_*` integrates the patch for the oracle).

use super::friction::{CoulombFriction, FrictionForce, FrictionTorque};
use crate::{Matrix3, Vector3};

/// The friction force and torque of one patch with every partial derivative, from
/// [`CoulombFriction::slip_and_spin`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipAndSpin {
    /// The force on I with ∂/∂v_t and ∂/∂Fn.
    pub force: FrictionForce,
    /// ∂F/∂ω_n: how the spin takes from the force's budget.
    pub force_d_spin: Vector3,
    /// ∂F/∂A: a larger patch turns the same spin into more rim speed (0 at A = 0).
    pub force_d_area: Vector3,
    /// The torque on I about the normal with ∂/∂ω_n, ∂/∂Fn and ∂/∂A.
    pub torque: FrictionTorque,
    /// ∂T/∂v_t (a row, written as a vector): how the slip takes from the torque's budget.
    pub torque_d_slip: Vector3,
}

impl CoulombFriction {
    /// The friction force and torque of a patch of area `area` ≥ 0 that slips at `slip`
    /// (tangential, I relative to J) and spins at `spin` (I relative to J about the normal)
    /// under the normal force `normal_force` ≥ 0, with every partial: the module's law.
    ///
    /// With `A = 0` (or NaN) the patch is a point: the force is [`Self::force`]'s, the torque
    /// 0. With `v_t = 0` the torque is [`Self::torque`]'s and the force 0; with `ω_n = 0` the
    /// force is [`Self::force`]'s and the torque 0.
    pub fn slip_and_spin(
        &self,
        slip: &Vector3,
        spin: f64,
        normal_force: f64,
        area: f64,
    ) -> SlipAndSpin {
        let radius = if area > 0.0 {
            (area / std::f64::consts::PI).sqrt()
        } else {
            0.0
        };
        let w = spin * radius;
        let s = (slip.norm_squared() + w * w).sqrt();
        let (m, dm) = self.mu_over_speed_with_slope(s);
        // ∂s/∂v = v/s, ∂s/∂w = w/s; both 0 in the limit s → 0, where dm/ds → 0 too.
        let (ds_dv, ds_dw) = if s > 0.0 {
            (slip / s, w / s)
        } else {
            (Vector3::zeros(), 0.0)
        };
        let k = 2.0 / 3.0;
        let force = FrictionForce {
            force: slip * (m * normal_force),
            d_slip: (Matrix3::identity() * m + slip * ds_dv.transpose() * dm) * normal_force,
            d_normal_force: slip * m,
        };
        let force_d_spin = slip * (normal_force * dm * ds_dw * radius);
        // T = k·Fn·R·m·w; with w = ω·R: ∂T/∂R = k·Fn·(m·w + R·dm·(w/s)·ω·w + R·m·ω).
        let d_radius =
            k * normal_force * (m * w + radius * dm * ds_dw * spin * w + radius * m * spin);
        let torque = FrictionTorque {
            torque: k * radius * m * w * normal_force,
            d_spin: k * normal_force * radius * radius * (m + dm * ds_dw * w),
            d_normal_force: k * radius * m * w,
            d_area: if area > 0.0 {
                d_radius * radius / (2.0 * area)
            } else {
                0.0
            },
        };
        let torque_d_slip = ds_dv * (k * normal_force * radius * w * dm);
        // ∂F/∂R = Fn·v·dm·(w/s)·ω, and dR/dA = R/(2A).
        let force_d_area = if area > 0.0 {
            slip * (normal_force * dm * ds_dw * spin * radius / (2.0 * area))
        } else {
            Vector3::zeros()
        };
        SlipAndSpin {
            force,
            force_d_spin,
            force_d_area,
            torque,
            torque_d_slip,
        }
    }
}

#[cfg(test)]
mod tests;
