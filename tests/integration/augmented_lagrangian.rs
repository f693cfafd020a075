//! AUGMENTED_LAGRANGIAN_FORMULATION on the POISSON ball (`examples/ball_poisson_al/`): the
//! penetration falls, the rebound keeps ε, and what the peak force does when p changes.

use contact::dataset;
use contact::run::lower::lower;
use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::Analysis;
use contact::solver::simulate::{DynamicsSettings, simulate};
use std::path::Path;

/// Gravity and the ball's radius in the example.
const G: f64 = 9.81;
const RADIUS: f64 = 0.1;
/// The gap the ball starts above the plane, falling at the speed of the example's 1 m drop.
const GAP: f64 = 1e-3;

/// What one bounce of the ball gives.
#[derive(Debug, Clone, Copy)]
struct Bounce {
    /// Exit over entry speed at the contact level (ballistic: v² + 2·g·(height above it)).
    rebound_ratio: f64,
    /// The deepest penetration.
    peak_penetration: f64,
    /// The largest normal force (output every 10 µs: the contact lasts 0.1 to 4 ms).
    peak_force: f64,
}

/// One bounce of the ball of `file` (in `examples/ball_poisson_al/`) with PENALTY `penalty`,
/// the augmented Lagrangian on or off: the example's ball placed `GAP` above the plane with
/// the speed of its 1 m drop (so the run holds the bounce and little else), for 10 ms.
fn drop_ball(file: &str, penalty: f64, augmented: bool) -> Bounce {
    let adm = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join("ball_poisson_al")
        .join(file);
    let mut loaded = dataset::read(&adm, None).unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let contact = &mut loaded.model.contacts[0];
    let contact_core::NormalModel::Poisson { law, .. } = contact.params.normal else {
        panic!("{file} is not POISSON")
    };
    let args = contact_core::ContactArgs {
        poisson: true,
        penalty: Some(penalty),
        restitution_coefficient: Some(law.restitution()),
        augmented_lagrangian: augmented,
        ..Default::default()
    };
    contact.params = args.validate(&loaded.model.units).unwrap().0;
    let entry_speed = (2.0 * G * 1.0_f64).sqrt();
    let part = loaded.model.parts.get_mut(&2).unwrap();
    part.pose_world_part.translation.vector.z += RADIUS + GAP - 1.1;
    part.velocity_w.z = -entry_speed;
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
    let mut lowered = lower(
        &loaded.model,
        &engine_exact::ExactEngine,
        Analysis::Dynamics,
        &no_meshes,
    )
    .unwrap();
    let settings = DynamicsSettings {
        start: 0.0,
        end: 0.01,
        output_step: 1e-5,
        integrator: IntegratorSettings {
            error: loaded.model.integrator.error,
            ..IntegratorSettings::default()
        },
    };
    let ball = lowered.parts[0].0;
    let mut last = None;
    let (mut peak_penetration, mut peak_force) = (0.0_f64, 0.0_f64);
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let s = frame.parts[ball.0];
            last = Some((
                s.pose_w.translation.z,
                s.velocity_w.z,
                frame.contacts[0].is_empty(),
            ));
            for r in &frame.contacts[0] {
                peak_penetration = peak_penetration.max(r.contact.penetration);
                peak_force = peak_force.max(r.normal_force);
            }
            Ok(())
        },
    )
    .unwrap();
    let (z, v, free) = last.unwrap();
    assert!(
        free && v > 0.0,
        "still in contact or falling at the end: z {z}, v {v}"
    );
    let entry = (entry_speed * entry_speed + 2.0 * G * GAP).sqrt();
    let exit = (v * v + 2.0 * G * (z - RADIUS)).sqrt();
    Bounce {
        rebound_ratio: exit / entry,
        peak_penetration,
        peak_force,
    }
}

#[test]
fn the_augmented_lagrangian_cuts_the_penetration_tenfold_and_keeps_the_rebound() {
    let plain = drop_ball("ball_poisson_al.adm", 1e6, false);
    let augmented = drop_ball("ball_poisson_al.adm", 1e6, true);
    // Penalty alone: δ = v·sqrt(m/p) = 4.43 m/s · 1e-3 s (measured 4.4e-3 m); with the
    // multipliers about 2e-4 m, 21 times less.
    assert!(
        augmented.peak_penetration * 10.0 <= plain.peak_penetration,
        "{augmented:?} against {plain:?}"
    );
    assert!(
        (augmented.rebound_ratio - 0.6).abs() < 0.02 * 0.6,
        "{augmented:?}"
    );
}

#[test]
fn the_elastic_ball_leaves_at_its_entry_speed() {
    let augmented = drop_ball("ball_poisson_al_elastic.adm", 1e6, true);
    assert!(
        (augmented.rebound_ratio - 1.0).abs() < 0.02,
        "{augmented:?}"
    );
}

#[test]
fn the_peak_impact_force_is_not_insensitive_to_the_penalty() {
    // The SPEC asks for under 5% per 100× p. That does not hold at an impact: a rigid impact
    // has no finite peak force, and the multipliers stop the ball within the few steps whose
    // size sets the peak. Measured here at 10 µs output: 3.2e5 N at p = 1e6 and 1.6e6 N at
    // 1e7, a factor 5.0 for 10× p (the penalty alone grows as sqrt(p): 3.2×). This test
    // holds that measurement (under 8×) and that the rebound survives the stiffer penalty;
    // it does not claim the SPEC's insensitivity.
    let low = drop_ball("ball_poisson_al.adm", 1e6, true);
    let high = drop_ball("ball_poisson_al.adm", 1e7, true);
    let factor = high.peak_force / low.peak_force;
    assert!((1.0..8.0).contains(&factor), "{low:?} against {high:?}");
    assert!((high.rebound_ratio - 0.6).abs() < 0.02 * 0.6, "{high:?}");
    assert!(
        high.peak_penetration < low.peak_penetration,
        "{low:?} against {high:?}"
    );
}
