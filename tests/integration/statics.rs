//! Static equilibrium (SIMULATE/STATICS) against closed-form force balances.

use crate::inline;
use contact::run::lower::{LoweredModel, lower};
use contact::solver::contact_force::Analysis;
use contact::solver::frame::compute_frame;
use contact::solver::statics::{
    Equilibrium, StaticsError, StaticsMethod, StaticsSettings, solve_statics,
};

/// The model of `text` lowered for statics with the exact engine.
pub fn lowered(name: &str, text: &str) -> LoweredModel {
    let loaded = inline(name, text);
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
    lower(
        &loaded.model,
        &engine_exact::ExactEngine,
        Analysis::Quasistatic,
        &no_meshes,
    )
    .unwrap()
}

/// Tight EQUILIBRIUM settings, so the answer is limited by round-off, not by the tolerances.
fn tight() -> StaticsSettings {
    StaticsSettings {
        error: 1e-10,
        imbalance: 1e-9,
        ..StaticsSettings::default()
    }
}

fn equilibrium(model: &mut LoweredModel, settings: &StaticsSettings) -> Equilibrium {
    let y = model.system.given_state().clone();
    solve_statics(&mut model.system, 0.0, &y, settings).unwrap()
}

/// A sphere of radius 0.1 and mass 1 (kg, m) with its CM at height `z` over a ground plane,
/// IMPACT stiffness 1e6, exponent 1.5, gravity 9.81.
fn sphere_on_plane(z: f64) -> String {
    format!(
        "sphere on a plane\n\
         UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
         PART/1, GROUND\nMARKER/10, PART = 1\n\
         PART/2, MASS = 1, CM = 20, IP = 0.004, 0.004, 0.004\nMARKER/20, PART = 2, QP = 0.01, -0.02, {z}\n\
         GRAPHICS/1, ELLIPSOID, CM = 20, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2\n\
         GRAPHICS/2, PLANE, RM = 10\n\
         CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT, STIFFNESS = 1E6, EXPONENT = 1.5, DAMPING = 50, DMAX = 1E-4\n\
         ACCGRAV/ KGRAV = -9.81\nEND\n"
    )
}

/// The resting penetration of the sphere: k·δ^e = m·g.
fn resting_penetration() -> f64 {
    (1.0 * 9.81 / 1e6_f64).powf(1.0 / 1.5)
}

fn check_resting_sphere(model: &LoweredModel, found: &Equilibrium) {
    let frame = compute_frame(&model.system, &model.contacts, 0.0, &found.y).unwrap();
    let expected = resting_penetration();
    let contact = frame.contacts[0][0];
    let relative = (contact.contact.penetration - expected).abs() / expected;
    assert!(
        relative < 1e-6,
        "δ = {} vs {expected} ({relative:e})",
        contact.contact.penetration
    );
    let z = frame.parts[1].pose_w.translation.z;
    assert!(((0.1 - z) - expected).abs() / expected < 1e-6, "z = {z}");
    // Sideways the sphere stays where it was put, and nothing turns.
    assert!((frame.parts[1].pose_w.translation.x - 0.01).abs() < 1e-12);
    assert!(frame.parts[1].pose_w.rotation.angle() < 1e-9);
    assert!((contact.normal_force - 9.81).abs() < 1e-6 * 9.81);
    assert!(found.imbalance <= 1e-9);
}

#[test]
fn a_sphere_pressed_into_a_plane_rises_to_the_closed_form_penetration_by_newton() {
    let mut model = lowered("statics_sphere_below.adm", &sphere_on_plane(0.099));
    let found = equilibrium(&mut model, &tight());
    assert_eq!(found.method, StaticsMethod::Newton);
    check_resting_sphere(&model, &found);
}

#[test]
fn a_sphere_above_a_plane_settles_by_the_quasi_dynamic_fallback() {
    let mut model = lowered("statics_sphere_above.adm", &sphere_on_plane(0.3));
    let found = equilibrium(&mut model, &tight());
    assert!(
        matches!(
            found.method,
            StaticsMethod::QuasiDynamic {
                newton_failure: Some(_),
                ..
            }
        ),
        "{}",
        found.method
    );
    check_resting_sphere(&model, &found);
}

#[test]
fn equilibrium_dynamic_runs_the_quasi_dynamic_method_from_the_start() {
    let mut model = lowered("statics_sphere_dynamic.adm", &sphere_on_plane(0.099));
    let settings = StaticsSettings {
        dynamic: true,
        ..tight()
    };
    let found = equilibrium(&mut model, &settings);
    assert!(
        matches!(
            found.method,
            StaticsMethod::QuasiDynamic {
                newton_failure: None,
                ..
            }
        ),
        "{}",
        found.method
    );
    check_resting_sphere(&model, &found);
}

/// A 1 kg bob 1 m from a revolute joint about world y, its arm horizontal, held up by a
/// rotational spring of stiffness 10 N·m/rad that is free when the arm is horizontal.
const SPRUNG_PENDULUM: &str = "sprung pendulum\n\
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
PART/1, GROUND\nMARKER/10, PART = 1, REULER = 0, 90D, 0\n\
PART/2, MASS = 1, CM = 20, IP = 1E-3, 1E-3, 1E-3\n\
MARKER/20, PART = 2, QP = 1, 0, 0\nMARKER/21, PART = 2, QP = 0, 0, 0, REULER = 0, 90D, 0\n\
JOINT/1, REVOLUTE, I = 21, J = 10\n\
SFORCE/1, ROTATIONAL, I = 21, J = 10, FUNCTION = -10 * AZ(21, 10)\n\
ACCGRAV/ KGRAV = -9.81\nEND\n";

#[test]
fn a_pendulum_on_a_rotational_spring_droops_to_the_moment_balance() {
    // Moment balance about the joint: k·φ = m·g·l·cos φ, solved by bisection.
    let balance = |phi: f64| 10.0 * phi - 9.81 * phi.cos();
    let (mut lo, mut hi) = (0.0, std::f64::consts::FRAC_PI_2);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if balance(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let phi = 0.5 * (lo + hi);
    let mut model = lowered("statics_pendulum.adm", SPRUNG_PENDULUM);
    let found = equilibrium(&mut model, &tight());
    assert_eq!(found.method, StaticsMethod::Newton);
    let frame = compute_frame(&model.system, &model.contacts, 0.0, &found.y).unwrap();
    let bob = frame.parts[1].pose_w.translation.vector;
    // The CM marker is 1 m out along the arm: x = cos φ, z = −sin φ.
    assert!((bob.x - phi.cos()).abs() < 1e-9, "{bob:?} vs φ = {phi}");
    assert!((bob.z + phi.sin()).abs() < 1e-9, "{bob:?} vs φ = {phi}");
    assert!(bob.y.abs() < 1e-12);
    // The joint carries the weight: the reaction on the bob is m·g up.
    let reactions = model.system.constraint_reactions(&found.y).unwrap();
    assert!(
        (reactions[0].force_w.z - 9.81).abs() < 1e-8,
        "{reactions:?}"
    );
}

/// A 2 kg block on a vertical TRANSLATIONAL joint hanging from a spring of stiffness 400 N/m
/// and free length 0.5 m, released with the spring at its free length.
const HANGING_BLOCK: &str = "block on a spring\n\
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
PART/1, GROUND\nMARKER/10, PART = 1\nMARKER/11, PART = 1, QP = 0, 0, 1\n\
PART/2, MASS = 2, CM = 20, IP = 1E-2, 1E-2, 1E-2\n\
MARKER/20, PART = 2, QP = 0, 0, 0.5\nMARKER/21, PART = 2, QP = 0, 0, 0.5\n\
JOINT/1, TRANSLATIONAL, I = 21, J = 10\n\
SFORCE/1, TRANSLATIONAL, I = 20, J = 11, FUNCTION = -400 * (DM(20, 11) - 0.5)\n\
ACCGRAV/ KGRAV = -9.81\nEND\n";

#[test]
fn a_block_on_a_spring_hangs_at_m_g_over_k() {
    let mut model = lowered("statics_spring.adm", HANGING_BLOCK);
    let found = equilibrium(&mut model, &tight());
    let frame = compute_frame(&model.system, &model.contacts, 0.0, &found.y).unwrap();
    let extension = 0.5 - frame.parts[1].pose_w.translation.z;
    let expected = 2.0 * 9.81 / 400.0;
    assert!(
        (extension - expected).abs() < 1e-9 * expected.max(1.0),
        "x = {extension} vs m g / k = {expected}"
    );
    assert!(found.iterations <= 5, "{} iterations", found.iterations);
}

/// A free part under gravity has no equilibrium.
const FALLING: &str = "falling part\n\
PART/1, GROUND\nMARKER/10, PART = 1\n\
PART/2, MASS = 1, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2\n\
ACCGRAV/ KGRAV = -9.81\nEND\n";

#[test]
fn a_statics_without_an_equilibrium_stops_with_a_diagnosis() {
    let mut model = lowered("statics_falling.adm", FALLING);
    let y = model.system.given_state().clone();
    let settings = StaticsSettings {
        maxit: 5,
        ..StaticsSettings::default()
    };
    let error = solve_statics(&mut model.system, 0.0, &y, &settings).unwrap_err();
    let StaticsError::NotConverged(diagnosis) = &error else {
        panic!("{error}");
    };
    assert_eq!(
        diagnosis.dominant_part,
        Some(("PART/2".to_string(), "force"))
    );
    assert!(diagnosis.iterations >= 5, "{diagnosis:?}");
    assert!((diagnosis.imbalance - 9.81).abs() < 1e-9, "{diagnosis:?}");
    let message = error.to_string();
    for needle in [
        "static Newton",
        "MAXIT = 5",
        "quasi-dynamic",
        "PART/2",
        "Remedies",
    ] {
        assert!(message.contains(needle), "{needle:?} not in {message}");
    }
}

#[test]
fn out_of_range_equilibrium_settings_are_refused_by_name() {
    let mut model = lowered("statics_settings.adm", HANGING_BLOCK);
    let y = model.system.given_state().clone();
    let settings = StaticsSettings {
        tlimit: -1.0,
        ..StaticsSettings::default()
    };
    let error = solve_statics(&mut model.system, 0.0, &y, &settings).unwrap_err();
    assert_eq!(
        error.to_string(),
        "EQUILIBRIUM/TLIMIT = -1.0 is out of range: must be finite and > 0"
    );
}
