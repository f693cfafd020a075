//! AUGMENTED_LAGRANGIAN_FORMULATION (SPEC §5, POISSON only): the multipliers of one CONTACT
//! and the normal force they give. **Ours**: Adams does not publish its formulation.
//!
//! **Compression** (the bodies approach, δ̇ > 0). Each contact of the CONTACT (in the engine's
//! order) carries a multiplier λ ≥ 0 added to the penalty spring: `F_c = max(0, λ + p·δ)`.
//! Inside the corrector, when Newton has converged on a step attempt, every approaching contact
//! whose penetration δ exceeds the tolerance updates `λ ← max(0, λ + p·δ)` (contact-core's
//! `AugmentedLagrangian::update`) and the corrector runs again on the new forces, at most
//! [`PASSES_PER_ATTEMPT`] times per attempt; the multipliers then carry over to the next step,
//! which goes on from them. So λ builds the force that stops the approach while δ stays near
//! the tolerance instead of growing to what the penalty alone needs.
//!
//! **Restitution** (δ̇ < 0). A multiplier is a force without a displacement: held while the
//! bodies separate it would return more energy than the compression stored (energy is created),
//! and the POISSON law's ε²-unloading would not give the exit speed ε. So restitution unloads
//! along a line through the origin that returns exactly ε² of the work `W` the contact force did
//! during compression (summed over accepted steps, trapezoidal rule): `F_r = 2·ε²·W·δ/δ_m²`,
//! `δ_m` the deepest penetration. The exit speed of a two-body impact is then ε times the entry
//! speed whatever the compression path, as POISSON requires.
//!
//! The two are blended by POISSON's STEP in δ̇ over ±v_t:
//! `Fn = s·F_c + (1 − s)·F_r`, `s = STEP(δ̇, −v_t, 0, v_t, 1)`; continuous in δ and δ̇.
//!
//! **Tolerance** (ours): [`PENETRATION_TOLERANCE`] times the pair's length scale `L` (the larger
//! characteristic length of the two geometries), so a model in millimetres and one in metres
//! iterate alike.
//!
//! **Statics** (ours). At rest δ̇ = 0, so the force is the blend's midpoint
//! `½·F_c + ½·F_r`. The static solver finds the equilibrium with the multipliers it has, then
//! every contact whose penetration exceeds the tolerance updates `λ ← max(0, λ + p·δ)` whatever
//! its rate ([`Multipliers::equilibrium_converged`]) and the equilibrium is solved again, until
//! every penetration is within the tolerance. For one contact carrying a fixed load, a pass
//! multiplies the penetration by `k_r/(p + k_r)`, `k_r` the restitution stiffness: `ε²·p`
//! before any compression work is recorded, so `ε²/(1 + ε²) ≤ ½`.
//!
//! **Memory.** Each attempt starts from the state of the last accepted step (an attempt that
//! fails leaves no trace); an accepted step keeps it; a step the driver rolls back (contact
//! prediction) restores the one before. A contact that disappears forgets its state.

use contact_core::InvalidArgument;
use contact_core::laws::{AugmentedLagrangian, NormalForce, PoissonLaw, Step};
use std::sync::Mutex;

/// The penetration the inner iteration allows, relative to the pair's length scale.
pub const PENETRATION_TOLERANCE: f64 = 1e-4;

/// The most multiplier updates (extra corrector passes) per step attempt; then the attempt
/// goes on with the multipliers it has and the next step continues the iteration. Below the
/// integrator's default MAXIT (10), so the inner iteration never fails a step by itself.
pub const PASSES_PER_ATTEMPT: u32 = 4;

/// What one contact remembers.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ContactMemory {
    /// The multiplier λ.
    pub lambda: f64,
    /// Work done by the normal force while approaching (compression), `W`.
    pub compression_work: f64,
    /// The deepest penetration so far, `δ_m`.
    pub deepest: f64,
    /// Penetration at the last accepted step.
    last_penetration: f64,
    /// Normal force at the last accepted step.
    last_force: f64,
}

#[derive(Debug, Clone, Default)]
struct Levels {
    current: Vec<ContactMemory>,
    accepted: Vec<ContactMemory>,
    before: Vec<ContactMemory>,
    passes: u32,
}

/// The multipliers of one CONTACT, their update and the force law they make.
#[derive(Debug)]
pub struct Multipliers {
    law: PoissonLaw,
    update: AugmentedLagrangian,
    blend: Step,
    tolerance: f64,
    levels: Mutex<Levels>,
}

impl Multipliers {
    /// Multipliers of the POISSON `law` updated by `update`, with tolerance
    /// `PENETRATION_TOLERANCE · length` (`length` > 0 and finite; otherwise 1 model unit).
    /// Fails only if the law's transition velocity cannot make a STEP (it is validated > 0).
    pub fn new(
        law: PoissonLaw,
        update: AugmentedLagrangian,
        length: f64,
    ) -> Result<Self, InvalidArgument> {
        let length = if length.is_finite() && length > 0.0 {
            length
        } else {
            1.0
        };
        let vt = law.transition_velocity();
        Ok(Self {
            law,
            update,
            blend: Step::new(-vt, 0.0, vt, 1.0)?,
            tolerance: PENETRATION_TOLERANCE * length,
            levels: Mutex::new(Levels::default()),
        })
    }

    /// The penetration the iteration allows.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// What contact `index` remembers now (zero for a new contact).
    pub fn memory(&self, index: usize) -> ContactMemory {
        self.levels
            .lock()
            .ok()
            .and_then(|l| l.current.get(index).copied())
            .unwrap_or_default()
    }

    /// The normal force of contact `index` at penetration `delta` and rate `rate`.
    pub fn force(&self, index: usize, delta: f64, rate: f64) -> NormalForce {
        if delta.is_nan() || delta <= 0.0 {
            return NormalForce::ZERO;
        }
        let m = self.memory(index);
        let p = self.law.penalty();
        let compression = (m.lambda + p * delta).max(0.0);
        let e2 = self.law.restitution() * self.law.restitution();
        let deepest = m.deepest.max(delta);
        // Before any compression work is recorded, POISSON's own unloading spring ε²·p.
        let restitution_stiffness = if m.compression_work > 0.0 {
            2.0 * e2 * m.compression_work / (deepest * deepest)
        } else {
            e2 * p
        };
        let restitution = restitution_stiffness * delta;
        // Deeper than ever before, the line's slope is 2·ε²·W/δ² itself: `F_r = 2·ε²·W/δ`
        // falls with δ.
        let d_restitution = if m.compression_work > 0.0 && delta > m.deepest {
            -restitution_stiffness
        } else {
            restitution_stiffness
        };
        let s = self.blend.cubic(rate);
        let force = s.value * compression + (1.0 - s.value) * restitution;
        NormalForce {
            force,
            d_penetration: s.value * p + (1.0 - s.value) * d_restitution,
            d_rate: s.slope * (compression - restitution),
        }
    }

    /// A step attempt starts: back to the state of the last accepted step.
    pub fn attempt_started(&self) {
        if let Ok(mut l) = self.levels.lock() {
            l.current = l.accepted.clone();
            l.passes = 0;
        }
    }

    /// The corrector converged with these `(penetration, rate)` per contact (engine order):
    /// updates every approaching contact whose δ exceeds the tolerance and returns whether any
    /// did (the corrector must run again), at most [`PASSES_PER_ATTEMPT`] times per attempt.
    pub fn corrector_converged(&self, contacts: &[(f64, f64)]) -> bool {
        let Ok(mut l) = self.levels.lock() else {
            return false;
        };
        if l.passes >= PASSES_PER_ATTEMPT {
            return false;
        }
        l.current.resize(contacts.len(), ContactMemory::default());
        let mut again = false;
        for (m, &(delta, rate)) in l.current.iter_mut().zip(contacts) {
            if rate > 0.0 && delta > self.tolerance {
                m.lambda = self.update.update(m.lambda, delta).0;
                again = true;
            }
        }
        l.passes += u32::from(again);
        again
    }

    /// A static equilibrium was found with these penetrations per contact (engine order):
    /// every contact whose δ exceeds the tolerance updates `λ ← max(0, λ + p·δ)` (at rest,
    /// whatever the rate) and the call returns whether any did (the equilibrium must be solved
    /// again). The multipliers are kept as the accepted state, since an equilibrium is one; the
    /// caller bounds the passes.
    pub fn equilibrium_converged(&self, penetrations: &[f64]) -> bool {
        let Ok(mut l) = self.levels.lock() else {
            return false;
        };
        l.current
            .resize(penetrations.len(), ContactMemory::default());
        let mut again = false;
        for (m, &delta) in l.current.iter_mut().zip(penetrations) {
            if delta > self.tolerance {
                m.lambda = self.update.update(m.lambda, delta).0;
                again = true;
            }
        }
        l.accepted = l.current.clone();
        again
    }

    /// The step was accepted with these `(penetration, rate, normal force)` per contact: its
    /// state is the new start, with the compression work and deepest penetration updated.
    pub fn step_accepted(&self, contacts: &[(f64, f64, f64)]) {
        let Ok(mut l) = self.levels.lock() else {
            return;
        };
        l.current.resize(contacts.len(), ContactMemory::default());
        for (m, &(delta, rate, force)) in l.current.iter_mut().zip(contacts) {
            if rate > 0.0 {
                m.compression_work +=
                    0.5 * (force + m.last_force) * (delta - m.last_penetration).max(0.0);
            }
            m.deepest = m.deepest.max(delta);
            m.last_penetration = delta;
            m.last_force = force;
        }
        let current = l.current.clone();
        l.before = std::mem::replace(&mut l.accepted, current);
    }

    /// The driver rolled the last accepted step back: the state of the step before.
    pub fn rolled_back(&self) {
        if let Ok(mut l) = self.levels.lock() {
            l.accepted = l.before.clone();
            l.current = l.before.clone();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use contact_core::laws::PoissonParams;

    fn multipliers(restitution: f64) -> Multipliers {
        let law = PoissonLaw::from_params(PoissonParams {
            penalty: 1e6,
            restitution,
            transition_velocity: 1e-3,
        })
        .unwrap();
        Multipliers::new(law, AugmentedLagrangian::new(1e6).unwrap(), 0.1).unwrap()
    }

    #[test]
    fn approaching_penetration_above_the_tolerance_accumulates_p_delta_and_asks_again() {
        let m = multipliers(0.6);
        assert!((m.tolerance() - 1e-5).abs() < 1e-20);
        assert!(m.corrector_converged(&[(2e-5, 1.0)]));
        assert_eq!(m.memory(0).lambda, 1e6 * 2e-5);
        assert!(m.corrector_converged(&[(3e-5, 1.0)]));
        assert_eq!(m.memory(0).lambda, 1e6 * 5e-5);
        // Within the tolerance, or separating: unchanged, done.
        assert!(!m.corrector_converged(&[(1e-5, 1.0)]));
        assert!(!m.corrector_converged(&[(1e-3, -1.0)]));
        assert_eq!(m.memory(0).lambda, 50.0);
        // Compression force: λ + p·δ well inside compression.
        assert!((m.force(0, 1e-5, 1.0).force - 60.0).abs() < 1e-9);
    }

    #[test]
    fn passes_per_attempt_are_bounded_and_attempts_restart_from_the_accepted_step() {
        let m = multipliers(0.6);
        for _ in 0..PASSES_PER_ATTEMPT {
            assert!(m.corrector_converged(&[(1e-4, 1.0)]));
        }
        assert!(!m.corrector_converged(&[(1e-4, 1.0)]));
        let lambda = m.memory(0).lambda;
        m.step_accepted(&[(1e-4, 1.0, lambda + 100.0)]);
        // A new attempt may update again; one that fails leaves no trace.
        m.attempt_started();
        assert!(m.corrector_converged(&[(1e-4, 1.0)]));
        m.attempt_started();
        assert_eq!(m.memory(0).lambda, lambda);
        m.corrector_converged(&[(1e-4, 1.0)]);
        m.step_accepted(&[(2e-4, 1.0, 1000.0)]);
        assert!(m.memory(0).lambda > lambda);
        m.rolled_back();
        assert_eq!(m.memory(0).lambda, lambda);
    }

    #[test]
    fn restitution_returns_eps_squared_of_the_compression_work() {
        // Compression records W = ∫F dδ (trapezoids): here a straight line to (δm, Fm).
        let eps = 0.6;
        let m = multipliers(eps);
        let (dm, fm) = (1e-4, 500.0);
        for k in 1..=10 {
            let d = dm * f64::from(k) / 10.0;
            m.step_accepted(&[(d, 1.0, fm * d / dm)]);
        }
        let w = 0.5 * fm * dm;
        assert!((m.memory(0).compression_work - w).abs() < 1e-12 * w);
        // Unloading (well past the blend) is linear and returns ε²·W.
        let n = 1000;
        let returned: f64 = (0..n)
            .map(|k| {
                let d = dm * (f64::from(k) + 0.5) / f64::from(n);
                m.force(0, d, -1.0).force * dm / f64::from(n)
            })
            .sum();
        assert!((returned - eps * eps * w).abs() < 1e-9 * w, "{returned}");
    }

    #[test]
    fn at_equilibrium_every_contact_above_the_tolerance_updates_whatever_its_rate() {
        let m = multipliers(0.6);
        assert!(m.equilibrium_converged(&[2e-5, 1e-6]));
        assert_eq!(m.memory(0).lambda, 1e6 * 2e-5);
        assert_eq!(m.memory(1).lambda, 0.0);
        // Kept as the accepted state: a new attempt starts from it.
        m.attempt_started();
        assert_eq!(m.memory(0).lambda, 20.0);
        assert!(!m.equilibrium_converged(&[1e-5, 0.0]));
        assert_eq!(m.memory(0).lambda, 20.0);
    }

    #[test]
    fn a_contact_that_appears_later_starts_from_nothing() {
        let m = multipliers(0.6);
        m.corrector_converged(&[(2e-5, 1.0)]);
        assert_eq!(m.memory(1), ContactMemory::default());
        assert_eq!(m.force(0, 0.0, 1.0), NormalForce::ZERO);
    }
}
