//! Kinematic analysis (SIMULATE/KINEMATICS) against the closed-form slider-crank.

use contact::dataset;
use contact::run::lower::{LoweredModel, lower};
use contact::solver::contact_force::Analysis;
use contact::solver::kinematics::{KinematicsError, KinematicsSettings, run_kinematics};
use std::f64::consts::TAU;
use std::path::Path;

fn example(path: &str) -> LoweredModel {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    lowered(dataset::read(&dir.join(path), None).unwrap())
}

/// A read dataset without errors, lowered for kinematics with the exact engine.
fn lowered(loaded: dataset::Loaded) -> LoweredModel {
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

/// A 1 kg sphere (radius 0.1) on a vertical TRANSLATIONAL joint, driven into a ground plane
/// by a MOTION at 1 mm/s from touching; IMPACT k = 1e6, e = 1.5, c = 50, dmax = 1e-4.
const PRESSED_SPHERE: &str = "sphere driven into a plane\n\
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
PART/1, GROUND\nMARKER/10, PART = 1\n\
PART/2, MASS = 1, CM = 20, IP = 0.004, 0.004, 0.004\nMARKER/20, PART = 2, QP = 0, 0, 0.1\n\
GRAPHICS/1, ELLIPSOID, CM = 20, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2\n\
GRAPHICS/2, PLANE, RM = 10\n\
JOINT/1, TRANSLATIONAL, I = 20, J = 10\n\
MOTION/1, JOINT = 1, FUNCTION = 0.1 - 0.001 * TIME\n\
CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT, STIFFNESS = 1E6, EXPONENT = 1.5, DAMPING = 50, DMAX = 1E-4\n\
ACCGRAV/ KGRAV = -9.81\nEND\n";

#[test]
fn contacts_in_kinematics_are_outputs_and_the_motion_carries_them() {
    let model = lowered(crate::inline(
        "kinematics_pressed_sphere.adm",
        PRESSED_SPHERE,
    ));
    let settings = KinematicsSettings {
        start: 0.0,
        end: 1.0,
        output_step: 0.1,
    };
    let mut checked = 0;
    run_kinematics(
        &model.system,
        &model.contacts,
        &settings,
        &mut |frame, state| {
            // The motion is the MOTION's, whatever the contact pushes.
            let z = frame.parts[1].pose_w.translation.z;
            assert!(
                (z - (0.1 - 0.001 * frame.t)).abs() < 1e-12,
                "t = {}: z = {z}",
                frame.t
            );
            if frame.t < 0.15 {
                return Ok(());
            }
            // Past dmax the full damping acts: Fn = k·δ^e + c·δ̇ with δ = 0.001·t, δ̇ = 0.001.
            let delta = 0.001 * frame.t;
            let expected = 1e6 * delta.powf(1.5) + 50.0 * 0.001;
            let report = frame.contacts[0][0];
            assert!((report.contact.penetration - delta).abs() < 1e-12 * delta.max(1.0));
            assert!(
                (report.normal_force - expected).abs() < 1e-9 * expected,
                "t = {}: Fn = {} vs {expected}",
                frame.t,
                report.normal_force
            );
            // At constant speed the MOTION holds the sphere against weight and contact.
            let reaction = model
                .system
                .element_reaction(&state.y, "MOTION/1")
                .unwrap()
                .unwrap();
            let want = 9.81 - expected;
            assert!(
                (reaction[0].1.force_w.z - want).abs() < 1e-9 * expected,
                "t = {}: R = {} vs {want}",
                frame.t,
                reaction[0].1.force_w.z
            );
            checked += 1;
            Ok(())
        },
    )
    .unwrap();
    assert_eq!(checked, 9);
}

/// The slider-crank with its MOTION given as a velocity (a constant 360°/s) and as an
/// acceleration (a constant α from rest, so θ = α·t²/2): the slider follows the closed form
/// at the integrated crank angle.
#[test]
fn velocity_and_acceleration_motions_drive_the_slider_crank_as_the_closed_form() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/slider_crank");
    let text = std::fs::read_to_string(dir.join("slider_crank.adm")).unwrap();
    let line = "MOTION/1, JOINT = 1, FUNCTION = 360D * TIME";
    assert!(text.contains(line));
    let alpha = 3.0;
    for (motion, angle) in [
        (
            "MOTION/1, JOINT = 1, VELOCITY, FUNCTION = 360D".to_string(),
            Box::new(|t: f64| (TAU * t, TAU)) as Box<dyn Fn(f64) -> (f64, f64)>,
        ),
        (
            format!("MOTION/1, JOINT = 1, ACCELERATION, FUNCTION = {alpha}"),
            Box::new(move |t: f64| (0.5 * alpha * t * t, alpha * t)),
        ),
    ] {
        let model = lowered(dataset::read_str(
            &text.replace(line, &motion),
            dir.join("driven.adm"),
            None,
        ));
        let slider = model.parts.iter().find(|p| p.1 == 4).unwrap().0;
        let settings = KinematicsSettings {
            start: 0.0,
            end: 1.5,
            output_step: 0.05,
        };
        let mut checked = 0;
        run_kinematics(
            &model.system,
            &model.contacts,
            &settings,
            &mut |frame, _| {
                let (theta, rate) = angle(frame.t);
                // At unit angular speed the closed form's derivatives are d/dθ.
                let (x, dx, _) = slider_closed_form(0.1, 0.3, 1.0, theta);
                let s = frame.parts[slider.0];
                assert!(
                    (s.pose_w.translation.x - x).abs() < 1e-9,
                    "{motion} t = {}: x = {} vs {x}",
                    frame.t,
                    s.pose_w.translation.x
                );
                assert!(
                    (s.velocity_w.x - dx * rate).abs() < 1e-9 * (1.0 + rate),
                    "{motion} t = {}: v = {} vs {}",
                    frame.t,
                    s.velocity_w.x,
                    dx * rate
                );
                checked += 1;
                Ok(())
            },
        )
        .unwrap();
        assert_eq!(checked, 31, "{motion}");
    }
}

/// A joint, its markers' REULER, the MOTION's axis, a point of the part and that point's
/// world position in time.
type MarkerMotionCase = (
    &'static str,
    &'static str,
    &'static str,
    [f64; 3],
    Box<dyn Fn(f64) -> [f64; 3]>,
);

/// MOTIONs on marker pairs: a crank on a REVOLUTE joint about world x, y or z turned by a
/// B1, B2 or B3 MOTION between two unrotated markers, and a slider on a TRANSLATIONAL joint
/// along world x moved by an X MOTION: a point of the part follows the rotation or the
/// displacement in closed form.
#[test]
fn marker_pair_motions_turn_and_move_parts_as_the_closed_form() {
    let w = 2.0;
    let cases: [MarkerMotionCase; 4] = [
        (
            "REVOLUTE",
            "90D, 90D, 0D",
            "B1",
            [0.0, 0.1, 0.0],
            Box::new(move |t: f64| [0.0, 0.1 * (w * t).cos(), 0.1 * (w * t).sin()]),
        ),
        (
            "REVOLUTE",
            "0D, -90D, 0D",
            "B2",
            [0.0, 0.0, 0.1],
            Box::new(move |t: f64| [0.1 * (w * t).sin(), 0.0, 0.1 * (w * t).cos()]),
        ),
        (
            "REVOLUTE",
            "0D, 0D, 0D",
            "B3",
            [0.1, 0.0, 0.0],
            Box::new(move |t: f64| [0.1 * (w * t).cos(), 0.1 * (w * t).sin(), 0.0]),
        ),
        (
            "TRANSLATIONAL",
            "90D, 90D, 0D",
            "X",
            [0.0, 0.0, 0.0],
            Box::new(move |t: f64| [w * t, 0.0, 0.0]),
        ),
    ];
    for (joint, euler, axis, point, expected) in cases {
        let text = format!(
            "driven part\n\
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND\n\
PART/1, GROUND\nMARKER/10, PART = 1\nMARKER/11, PART = 1, REULER = {euler}\n\
PART/2, MASS = 1, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2\nMARKER/21, PART = 2, REULER = {euler}\n\
MARKER/22, PART = 2, QP = {}, {}, {}\n\
JOINT/1, {joint}, I = 21, J = 11\n\
MOTION/1, I = 20, J = 10, {axis}, FUNCTION = {w} * TIME\nEND\n",
            point[0], point[1], point[2]
        );
        let model = lowered(dataset::read_str(&text, "driven.adm", None));
        let part = model.parts[0].0;
        let settings = KinematicsSettings {
            start: 0.0,
            end: 2.0,
            output_step: 0.1,
        };
        let mut checked = 0;
        run_kinematics(
            &model.system,
            &model.contacts,
            &settings,
            &mut |frame, _| {
                let pose = frame.parts[part.0].pose_w;
                let got = pose * nalgebra::Point3::from(nalgebra::Vector3::from(point));
                let want = expected(frame.t);
                for k in 0..3 {
                    assert!(
                        (got[k] - want[k]).abs() < 1e-9,
                        "{axis} t = {}: {got} vs {want:?}",
                        frame.t
                    );
                }
                checked += 1;
                Ok(())
            },
        )
        .unwrap();
        assert_eq!(checked, 21, "{axis}");
    }
}
