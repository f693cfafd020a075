//! AUGMENTED_LAGRANGIAN_FORMULATION in statics: the multipliers are augmented until the
//! penetration is within the contact's tolerance, and the contact still carries the load.

use crate::statics::lowered;
use contact::run::lower::LoweredModel;
use contact::solver::frame::compute_frame;
use contact::solver::statics::{Equilibrium, StaticsMethod, StaticsSettings, solve_statics};

const MASS: f64 = 1.0;
const GRAVITY: f64 = 9.81;
const PENALTY: f64 = 1e4;
const RESTITUTION: f64 = 0.5;

/// The box_rest example (a 1 kg box 0.2 × 0.2 × 0.1 on a ground plane, kg, m) with a POISSON
/// contact (PENALTY 1e4, ε = 0.5), augmented or not, its bottom face `depth` into the plane
/// (negative: above it).
fn box_on_plane(depth: f64, augmented: bool) -> String {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/box_rest/box_rest.adm"),
    )
    .unwrap();
    let law = format!(
        "CONTACT/1, IGEOM = 1, JGEOM = 2, POISSON, PENALTY = 1E4, RESTITUTION_COEFFICIENT = 0.5{}",
        if augmented {
            ", AUGMENTED_LAGRANGIAN_FORMULATION"
        } else {
            ""
        }
    );
    let replaced = text
        .replace(
            "MARKER/20, PART = 2, QP = 0, 0, 0.1",
            &format!("MARKER/20, PART = 2, QP = 0, 0, {}", 0.05 - depth),
        )
        .replace(
            "MARKER/21, PART = 2, QP = -0.1, -0.1, 0.05",
            &format!("MARKER/21, PART = 2, QP = -0.1, -0.1, {}", -depth),
        )
        .replace(
            "CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT\n, STIFFNESS = 1E6, EXPONENT = 1.5, DAMPING = 50, DMAX = 1E-4",
            &law,
        );
    assert!(replaced.contains("POISSON") && !replaced.contains("STIFFNESS = 1E6"));
    replaced
}

/// The penalty-only resting penetration, by hand: at rest (δ̇ = 0) the POISSON blend is half
/// way between the compression spring p and the restitution spring ε²·p, so
/// `m·g = p·δ·(1 + ε²)/2`.
fn penalty_penetration() -> f64 {
    2.0 * MASS * GRAVITY / (PENALTY * (1.0 + RESTITUTION * RESTITUTION))
}

fn settings() -> StaticsSettings {
    StaticsSettings {
        error: 1e-10,
        imbalance: 1e-9,
        ..StaticsSettings::default()
    }
}

fn solve(name: &str, text: &str) -> (LoweredModel, Equilibrium) {
    let mut model = lowered(name, text);
    let y = model.system.given_state().clone();
    let found = solve_statics(&mut model.system, 0.0, &y, &settings()).unwrap();
    (model, found)
}

/// The penetration and the total vertical contact force at the equilibrium.
fn resting(model: &LoweredModel, found: &Equilibrium) -> (f64, f64) {
    let frame = compute_frame(&model.system, &model.contacts, 0.0, &found.y).unwrap();
    let reports = &frame.contacts[0];
    assert_eq!(reports.len(), 1, "{reports:?}");
    let force: f64 = reports
        .iter()
        .map(|r| r.normal_force * r.contact.normal_w.z + r.friction_force_w.z)
        .sum();
    (reports[0].contact.penetration, force)
}

#[test]
fn the_penalty_only_box_rests_at_the_hand_computed_penetration() {
    let (model, found) = solve("al_penalty_box.adm", &box_on_plane(2e-3, false));
    assert_eq!(found.method, StaticsMethod::Newton);
    let (penetration, force) = resting(&model, &found);
    let expected = penalty_penetration();
    assert!(
        (penetration - expected).abs() < 1e-9 * expected,
        "δ = {penetration} vs {expected}"
    );
    assert!((force - MASS * GRAVITY).abs() < 1e-9 * MASS * GRAVITY);
}

fn check_augmented(name: &str, depth: f64) -> StaticsMethod {
    let (model, found) = solve(name, &box_on_plane(depth, true));
    let (penetration, force) = resting(&model, &found);
    let multipliers = model.contacts[0].multipliers().unwrap();
    let tolerance = multipliers.tolerance();
    let penalty_only = penalty_penetration();
    // The tolerance is well below the penalty-only penetration, so the test can tell them apart.
    assert!(
        tolerance < penalty_only / 10.0,
        "{tolerance} vs {penalty_only}"
    );
    assert!(
        penetration > 0.0 && penetration <= tolerance,
        "δ = {penetration}, tolerance {tolerance}, penalty only {penalty_only}"
    );
    assert!(
        (force - MASS * GRAVITY).abs() < 1e-9 * MASS * GRAVITY,
        "F = {force}"
    );
    // The multiplier carries the load the penalty spring no longer does: at rest the force is
    // ½·(λ + p·δ) + ½·k_r·δ, with k_r = ε²·p before any compression work is recorded.
    let memory = multipliers.memory(0);
    if memory.compression_work == 0.0 {
        // Each update multiplies the resting penetration by ε²/(1 + ε²) (the load is fixed):
        // the first power of it that is within the tolerance is where the passes stop.
        let ratio = RESTITUTION * RESTITUTION / (1.0 + RESTITUTION * RESTITUTION);
        let mut expected = penalty_only;
        while expected > tolerance {
            expected *= ratio;
        }
        assert!(
            (penetration - expected).abs() < 1e-6 * expected,
            "δ = {penetration} vs {expected}"
        );
        let e2 = RESTITUTION * RESTITUTION;
        let law = 0.5 * (memory.lambda + PENALTY * penetration) + 0.5 * e2 * PENALTY * penetration;
        assert!(
            (law - MASS * GRAVITY).abs() < 1e-9 * MASS * GRAVITY,
            "{law}"
        );
    }
    assert!(
        memory.lambda > 0.9 * MASS * GRAVITY,
        "λ = {}",
        memory.lambda
    );
    found.method
}

#[test]
fn an_augmented_box_pressed_into_the_plane_rests_within_the_tolerance_carrying_its_weight() {
    let method = check_augmented("al_pressed_box.adm", 2e-3);
    assert_eq!(method, StaticsMethod::Newton);
}

#[test]
fn an_augmented_box_dropped_onto_the_plane_settles_within_the_tolerance() {
    let method = check_augmented("al_dropped_box.adm", -0.01);
    assert!(
        matches!(method, StaticsMethod::QuasiDynamic { .. }),
        "{method}"
    );
}
