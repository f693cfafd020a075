//! The example datasets in `examples/`, read, lowered and run, each asserting its physics.

use crate::ball_drop::{RADIUS, reference_apexes};
use contact::dataset;
use contact::run::lower::lower;
use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::Analysis;
use contact::solver::simulate::{DynamicsSettings, simulate};
use std::path::Path;

fn example(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name)
}

#[test]
fn the_ball_example_bounces_as_the_one_dof_reference() {
    let loaded = dataset::read(&example("ball/ball.adm"), Some(&example("ball/ball.acf"))).unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let engine = engine_exact::ExactEngine;
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
    let mut lowered = lower(&loaded.model, &engine, Analysis::Dynamics, &no_meshes).unwrap();
    let settings = DynamicsSettings {
        start: 0.0,
        end: 1.6,
        output_step: 1e-3,
        integrator: IntegratorSettings {
            error: loaded.model.integrator.error,
            ..IntegratorSettings::default()
        },
    };
    let ball = lowered.parts[0].0;
    let mut apexes = Vec::new();
    let mut was_rising = false;
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let s = frame.parts[ball.0];
            let (z, v) = (s.pose_w.translation.z, s.velocity_w.z);
            if was_rising && v <= 0.0 && frame.contacts[0].is_empty() {
                apexes.push(z + v * v / (2.0 * 9.81));
            }
            was_rising = v > 0.0 && frame.contacts[0].is_empty();
            Ok(())
        },
    )
    .unwrap();
    let reference = reference_apexes(2);
    assert!(apexes.len() >= 2, "{apexes:?}");
    for (got, want) in apexes.iter().zip(&reference) {
        let relative = ((got - RADIUS) - (want - RADIUS)).abs() / (want - RADIUS);
        assert!(relative < 1e-3, "rebound {got} vs {want}");
    }
}
