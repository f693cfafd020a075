//! AUGMENTED_LAGRANGIAN_FORMULATION in statics: the outer multiplier update around the
//! static Newton solve.
//!
//! In dynamics the multipliers of a contact are updated inside the corrector while the bodies
//! approach (`crate::contact_multipliers`). At rest nothing approaches, so statics
//! runs the update itself: once an equilibrium is found (by either method), every contact
//! whose penetration exceeds its tolerance adds `p·δ` to its multiplier, and Newton solves
//! the equilibrium again from where it was, on the augmented forces. The passes stop when no
//! contact updates (every penetration within its tolerance) or fail after
//! [`MAX_AUGMENTATIONS`]. A model without such contacts does no pass at all.
//!
//! The multiplier carries the load the penalty spring would otherwise carry with a deep
//! penetration: the equilibrium force is the same (the load), the penetration falls to the
//! tolerance.

use super::newton::{self, zero_velocities};
use super::{Equilibrium, StaticsDiagnosis, StaticsError, StaticsSettings};
use crate::mbs::{MultibodySystem, StateView};
use nalgebra::DVector;

/// The most multiplier updates (each followed by a Newton solve) of one static analysis.
/// A pass shrinks the penetration of a resting POISSON contact by `ε²/(1 + ε²) ≤ ½` (before
/// any compression work is recorded), so this is far more than a reachable tolerance needs.
pub const MAX_AUGMENTATIONS: usize = 60;

/// Runs the multiplier updates from `found` (an equilibrium of the current multipliers) at
/// time `t`; returns the equilibrium with every augmented-Lagrangian penetration within its
/// tolerance, its iterations including those of the passes.
pub(super) fn augment(
    system: &mut MultibodySystem,
    t: f64,
    mut found: Equilibrium,
    settings: &StaticsSettings,
) -> Result<Equilibrium, StaticsError> {
    for pass in 0..=MAX_AUGMENTATIONS {
        if !system.equilibrium_converged(t, &found.y) {
            return Ok(found);
        }
        let failure = if pass == MAX_AUGMENTATIONS {
            format!(
                "augmented-Lagrangian penetrations still above their tolerance after {MAX_AUGMENTATIONS} multiplier updates"
            )
        } else {
            zero_velocities(system, &mut found.y);
            match newton::solve(system, t, &mut found.y, settings, false) {
                Ok(report) => {
                    found.iterations += report.iterations;
                    found.imbalance = report.imbalance;
                    continue;
                }
                Err(failure) => {
                    found.iterations += failure.iterations;
                    format!(
                        "static Newton failed after augmented-Lagrangian multipliers were updated: {failure}"
                    )
                }
            }
        };
        let cause = format!("after {}: {failure}", found.method);
        return Err(StaticsError::NotConverged(Box::new(StaticsDiagnosis::at(
            system,
            t,
            &found.y,
            cause,
            found.iterations,
        ))));
    }
    Ok(found)
}

impl MultibodySystem {
    /// Forwards a static equilibrium `y` at time `t` to every force element's
    /// [`ForceElement::equilibrium_converged`] (all of them, so each updates at the same
    /// state); `true` if any asks for the equilibrium to be solved again.
    ///
    /// [`ForceElement::equilibrium_converged`]: crate::mbs::ForceElement::equilibrium_converged
    pub fn equilibrium_converged(&mut self, t: f64, y: &DVector<f64>) -> bool {
        let Ok(states) = self.part_states(y) else {
            return false;
        };
        let view = StateView::new(&states);
        let mut again = false;
        for element in &mut self.forces {
            again |= element.equilibrium_converged(t, &view);
        }
        again
    }
}
