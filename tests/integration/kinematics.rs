//! Kinematic analysis (SIMULATE/KINEMATICS) against the closed-form slider-crank.

use contact::dataset;
use contact::run::lower::{LoweredModel, lower};
use contact::solver::contact_force::Analysis;
use contact::solver::kinematics::{KinematicsError, KinematicsSettings, run_kinematics};
use std::f64::consts::TAU;
use std::path::Path;

fn example(path: &str) -> LoweredModel {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let loaded = dataset::read(&dir.join(path), None).unwrap();
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

/// The slider of a crank of radius `r` turning at `w` with a rod of length `l`, at time `t`:
/// position, velocity and acceleration along the line of stroke, differentiated by hand.
fn slider_closed_form(r: f64, l: f64, w: f64, t: f64) -> (f64, f64, f64) {
    let (s, c) = (w * t).sin_cos();
    let root = (l * l - r * r * s * s).sqrt();
    let x = r * c + root;
    // d(root)/dθ = −r² s c / root; d²(root)/dθ² = −r² (c² − s²)/root − r⁴ s² c² / root³.
    let d_root = -r * r * s * c / root;
    let dd_root = -r * r * (c * c - s * s) / root - r.powi(4) * s * s * c * c / root.powi(3);
    (x, w * (-r * s + d_root), w * w * (-r * c + dd_root))
}

#[test]
fn a_slider_crank_follows_the_closed_form_and_its_motion_torque_does_the_virtual_work() {
    let model = example("slider_crank/slider_crank.adm");
    let crank = model.parts.iter().find(|p| p.1 == 2).unwrap().0;
    let slider = model.parts.iter().find(|p| p.1 == 4).unwrap().0;
    let vo = model.system.layout().velocity_offset(slider);
    let settings = KinematicsSettings {
        start: 0.0,
        end: 1.0,
        output_step: 0.05,
    };
    let mut checked = 0;
    let summary = run_kinematics(
        &model.system,
        &model.contacts,
        &settings,
        &mut |frame, state| {
            let (x, v, a) = slider_closed_form(0.1, 0.3, TAU, frame.t);
            let s = frame.parts[slider.0];
            assert!(
                (s.pose_w.translation.x - x).abs() < 1e-9,
                "t = {}: x = {} vs {x}",
                frame.t,
                s.pose_w.translation.x
            );
            assert!(s.pose_w.translation.y.abs() < 1e-9);
            assert!(
                (s.velocity_w.x - v).abs() < 1e-9,
                "t = {}: v {} vs {v}",
                frame.t,
                s.velocity_w.x
            );
            let acceleration = state.yp[vo];
            // Accelerations to 1e-9 relative to the largest, r·w²(1 + r/l).
            let scale = 0.1 * TAU * TAU * (1.0 + 0.1 / 0.3);
            assert!(
                (acceleration - a).abs() < 1e-9 * scale,
                "t = {}: a {acceleration} vs {a}",
                frame.t
            );
            // Virtual work with massless links: T·w + F·v = 0, F = −100 along x.
            let reaction = model
                .system
                .element_reaction(&state.y, "MOTION/1")
                .unwrap()
                .unwrap();
            assert_eq!(reaction[0].0, crank);
            let torque = reaction[0].1.torque_w.z;
            let expected = 100.0 * v / TAU;
            assert!(
                (torque - expected).abs() < 1e-6 * 100.0 * 0.1,
                "t = {}: T = {torque} vs {expected}",
                frame.t
            );
            checked += 1;
            Ok(())
        },
    )
    .unwrap();
    assert_eq!((checked, summary.frames), (21, 21));
}

#[test]
fn kinematics_refuses_a_model_with_a_degree_of_freedom_left() {
    let model = example("pendulum/pendulum.adm");
    let settings = KinematicsSettings {
        start: 0.0,
        end: 1.0,
        output_step: 0.1,
    };
    let mut frames = 0;
    let error = run_kinematics(&model.system, &model.contacts, &settings, &mut |_, _| {
        frames += 1;
        Ok(())
    })
    .unwrap_err();
    assert!(
        matches!(
            error,
            KinematicsError::DegreesOfFreedom {
                dof: 1,
                parts: 1,
                independent: 5
            }
        ),
        "{error}"
    );
    assert!(error.to_string().contains("this one has 1"), "{error}");
    assert_eq!(frames, 0);
}
