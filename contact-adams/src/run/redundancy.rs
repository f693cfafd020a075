//! Redundant constraint equations as diagnostics at the statements they belong to: the
//! equations the lowered system removed at the initial configuration, listed as Adams lists
//! them (warnings), and an inconsistent redundancy (an error naming the joints).

use crate::dataset::{Diagnostic, Origin};
use crate::model::Model;
use contact_solver::mbs::{MbsError, MultibodySystem};

/// The statement of a lowered constraint element (`JOINT/3`, `JPRIM/2`, `MOTION/1`).
fn origin_of<'m>(model: &'m Model, element: &str) -> Option<&'m Origin> {
    let (kind, id) = element.split_once('/')?;
    let id: u32 = id.parse().ok()?;
    match kind {
        "JOINT" => model.joints.iter().find(|j| j.id == id).map(|j| &j.origin),
        "JPRIM" => model
            .primitives
            .iter()
            .find(|p| p.id == id)
            .map(|p| &p.origin),
        "MOTION" => model.motions.iter().find(|m| m.id == id).map(|m| &m.origin),
        _ => None,
    }
}

/// One warning per equation `system` removed as redundant, at its element's statement:
/// `JOINT/2: redundant equation 4 (rotation between Zi & Xj) removed: implied by JOINT/1`.
/// Equations are numbered from 1 in the element's order (REVOLUTE: translations along X, Y,
/// Z, then rotations between Zi & Xj and Zi & Yj).
pub fn redundancy_warnings(model: &Model, system: &MultibodySystem) -> Vec<Diagnostic> {
    system
        .redundant_equations()
        .filter_map(|e| {
            let origin = origin_of(model, &e.element)?;
            Some(Diagnostic::warning(
                origin.clone(),
                format!(
                    "{}: redundant equation {} ({}) removed: implied by {}",
                    e.element,
                    e.equation + 1,
                    e.description,
                    e.depends_on.join(", ")
                ),
            ))
        })
        .collect()
}

/// The warnings of [`redundancy_warnings`], and an error at the first joint named when the
/// removed equations do not hold once the model is assembled at time `t`
/// ([`MbsError::InconsistentRedundancy`]). Other assembly failures are left to the run, which
/// reports them with the analysis.
pub fn redundancy_diagnostics(model: &Model, system: &MultibodySystem, t: f64) -> Vec<Diagnostic> {
    let mut out = redundancy_warnings(model, system);
    let mut y = system.given_state().clone();
    if let Err(error) = system.assemble(t, &mut y)
        && let MbsError::InconsistentRedundancy { elements, .. } = &error
        && let Some(origin) = elements.iter().find_map(|e| origin_of(model, e))
    {
        out.push(Diagnostic::error(origin.clone(), error.to_string()));
    }
    out
}
