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
    // Both methods: static Newton, and the damped dynamics of the constrained model.
    for dynamic in [false, true] {
        let mut model = lowered("statics_pendulum.adm", SPRUNG_PENDULUM);
        let settings = StaticsSettings { dynamic, ..tight() };
        let found = equilibrium(&mut model, &settings);
        assert_eq!(
            found.method == StaticsMethod::Newton,
            !dynamic,
            "{}",
            found.method
        );
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

/// `contact run` with `args` into a fresh directory named `name`: (exit code, stdout, stderr,
/// the output directory).
fn run_cli(
    name: &str,
    model: std::path::PathBuf,
    commands: std::path::PathBuf,
) -> (u8, String, String, std::path::PathBuf) {
    let out = std::env::temp_dir().join(format!("contact-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&out).ok();
    let args = contact::cli::run::RunArgs {
        model,
        commands: Some(commands),
        engine: None,
        faceting_tolerance: None,
        end: None,
        dtout: None,
        steps: None,
        out: Some(out.clone()),
        threads: None,
        quiet: true,
    };
    let (mut stdout, mut stderr) = (Vec::new(), Vec::new());
    let code = contact::cli::run::run(&args, &mut stdout, &mut stderr).unwrap();
    let text = |b: Vec<u8>| String::from_utf8(b).unwrap();
    (code, text(stdout), text(stderr), out)
}

/// The rows of a CSV result file, the first `skip` columns dropped (numbers only after them).
fn csv_rows(path: &std::path::Path, skip: usize) -> Vec<Vec<f64>> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| {
            l.split(',')
                .skip(skip)
                .map(|v| v.parse().unwrap())
                .collect()
        })
        .collect()
}

fn example(path: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(path)
}

#[test]
fn the_box_rest_example_finds_its_equilibrium_and_the_dynamics_stay_there() {
    let (code, stdout, stderr, out) = run_cli(
        "box-rest",
        example("box_rest/box_rest.adm"),
        example("box_rest/box_rest.acf"),
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("static equilibrium at t = 0 by quasi-dynamic fallback"),
        "{stdout}"
    );
    assert!(stdout.contains("final imbalance"), "{stdout}");
    assert!(stdout.contains("ran 0.5 s of dynamics"), "{stdout}");
    let expected = resting_penetration();
    // parts.csv: time, part, x, y, z, … ; the box's CM is 0.05 above its bottom face.
    let parts = csv_rows(&out.join("parts.csv"), 0);
    assert_eq!(
        parts.len(),
        51,
        "the statics frame at t = 0, then 50 dynamics frames"
    );
    let resting_z = 0.05 - expected;
    assert!(
        (parts[0][4] - resting_z).abs() < 1e-6 * expected,
        "{:?}",
        parts[0]
    );
    for row in &parts {
        assert!((row[4] - parts[0][4]).abs() < 1e-9 * expected, "{row:?}");
    }
    // contacts.csv: time, contact, index, geometry_i, geometry_j, points (6), normal (3),
    // penetration, …
    let contacts = csv_rows(&out.join("contacts.csv"), 5);
    let penetration = contacts[0][9];
    assert!(
        (penetration - expected).abs() < 1e-6 * expected,
        "δ = {penetration} vs {expected}"
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["analyses"][0]["analysis"], "STATICS");
    assert_eq!(summary["analyses"][1]["analysis"], "DYNAMICS");
    assert!(summary["analyses"][0]["imbalance"].as_f64().unwrap() <= 1e-9);
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn a_failing_statics_after_dynamics_keeps_the_dynamics_output() {
    let dir = std::env::temp_dir().join(format!("contact-falling-model-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (adm, acf) = (dir.join("falling.adm"), dir.join("falling.acf"));
    std::fs::write(&adm, FALLING).unwrap();
    std::fs::write(
        &acf,
        "falling.adm\nfalling\nSIMULATE/DYNAMICS, END = 0.1, DTOUT = 0.01\nSIMULATE/STATICS\nSTOP\n",
    )
    .unwrap();
    let (code, _, stderr, out) = run_cli("statics-fail", adm, acf);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("SIMULATE/STATICS: statics did not converge"),
        "{stderr}"
    );
    assert!(stderr.contains("largest on PART/2 (force)"), "{stderr}");
    assert!(stderr.contains("results up to the failure"), "{stderr}");
    let parts = csv_rows(&out.join("parts.csv"), 0);
    assert_eq!(parts.len(), 11, "the 11 dynamics frames stay");
    // Free fall: z = −g t²/2 at the last frame.
    assert!(
        (parts[10][4] + 0.5 * 9.81 * 0.01).abs() < 1e-6,
        "{:?}",
        parts[10]
    );
    std::fs::remove_dir_all(&out).ok();
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn initial_conditions_and_kinematics_run_from_the_command_file() {
    let dir = std::env::temp_dir().join(format!("contact-ic-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let acf = dir.join("slider.acf");
    std::fs::write(
        &acf,
        "slider\nSIMULATE/INITIAL_CONDITIONS\nSIMULATE/KINEMATICS, END = 0.5, STEPS = 5\nSTOP\n",
    )
    .unwrap();
    let (code, stdout, stderr, out) = run_cli(
        "ic-kinematics",
        example("slider_crank/slider_crank.adm"),
        acf,
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("initial conditions at t = 0 written"),
        "{stdout}"
    );
    assert!(
        stdout.contains("ran kinematics from t = 0 to 0.5"),
        "{stdout}"
    );
    // One frame at t = 0 (the kinematics' first frame is not written twice), then 5; three
    // moving parts each.
    let parts = csv_rows(&out.join("parts.csv"), 0);
    assert_eq!(parts.len(), 6 * 3);
    let slider: Vec<&Vec<f64>> = parts.iter().filter(|r| r[1] == 4.0).collect();
    for row in slider {
        let (s, c) = (std::f64::consts::TAU * row[0]).sin_cos();
        let x = 0.1 * c + (0.09 - 0.01 * s * s).sqrt();
        assert!((row[2] - x).abs() < 1e-9, "{row:?} vs {x}");
    }
    std::fs::remove_dir_all(&out).ok();
    std::fs::remove_dir_all(&dir).ok();
}

/// The static Jacobian against central differences of the static residual over virtual
/// displacements `[δr, δθ′]` per part and the multipliers, at a state with λ ≠ 0.
fn check_static_jacobian(name: &str, text: &str) {
    use contact::solver::statics::newton::{static_jacobian, static_residual, zero_velocities};
    use nalgebra::{UnitQuaternion, Vector3};
    let mut model = lowered(name, text);
    let system = &mut model.system;
    let mut y = system.compute_initial_state(0.0).unwrap().y;
    zero_velocities(system, &mut y);
    let layout = *system.layout();
    let (n, m) = (layout.parts(), layout.constraint_rows());
    let analytic = static_jacobian(system, 0.0, &y, 0.0).unwrap();
    let displaced = |column: usize, h: f64| {
        let mut z = y.clone();
        if column >= 6 * n {
            z[layout.lambda_offset() + column - 6 * n] += h;
            return z;
        }
        let (k, c) = (column / 6, column % 6);
        let qo = 7 * k;
        if c < 3 {
            z[qo + c] += h;
        } else {
            let e = z.fixed_rows::<4>(qo + 3).into_owned();
            let rotation =
                UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(e[0], e[1], e[2], e[3]))
                    * UnitQuaternion::from_scaled_axis(Vector3::ith(c - 3, h));
            z.fixed_rows_mut::<4>(qo + 3)
                .copy_from(&nalgebra::Vector4::new(
                    rotation.w, rotation.i, rotation.j, rotation.k,
                ));
        }
        z
    };
    let scale = analytic.amax();
    for column in 0..6 * n + m {
        let h = 1e-6;
        let plus = static_residual(system, 0.0, &displaced(column, h)).unwrap();
        let minus = static_residual(system, 0.0, &displaced(column, -h)).unwrap();
        let numeric = (plus - minus) / (2.0 * h);
        let error = (numeric - analytic.column(column)).amax();
        assert!(
            error < 1e-5 * scale,
            "{name}: column {column}: error {error:e} of {scale:e}"
        );
    }
}

#[test]
fn the_static_jacobian_is_the_derivative_of_the_static_residual() {
    check_static_jacobian("jacobian_pendulum.adm", SPRUNG_PENDULUM);
    check_static_jacobian("jacobian_spring.adm", HANGING_BLOCK);
    check_static_jacobian("jacobian_sphere.adm", &sphere_on_plane(0.0995));
}

#[test]
fn the_box_pressed_into_the_plane_rises_to_the_closed_form_penetration_by_newton() {
    let text = std::fs::read_to_string(example("box_rest/box_rest.adm")).unwrap();
    // The whole box 1 mm lower than in the example: its bottom face 1 mm into the plane, more
    // than the resting 0.46 mm.
    let below = text
        .replace(
            "MARKER/20, PART = 2, QP = 0, 0, 0.1",
            "MARKER/20, PART = 2, QP = 0, 0, 0.049",
        )
        .replace(
            "MARKER/21, PART = 2, QP = -0.1, -0.1, 0.05",
            "MARKER/21, PART = 2, QP = -0.1, -0.1, -0.001",
        );
    assert_eq!(
        below.matches("0.049").count() + below.matches("-0.001").count(),
        2
    );
    let mut model = lowered("statics_box_below.adm", &below);
    let found = equilibrium(&mut model, &tight());
    assert_eq!(found.method, StaticsMethod::Newton);
    let frame = compute_frame(&model.system, &model.contacts, 0.0, &found.y).unwrap();
    let expected = resting_penetration();
    let penetration = frame.contacts[0][0].contact.penetration;
    assert!(
        (penetration - expected).abs() < 1e-6 * expected,
        "δ = {penetration} vs {expected}"
    );
    let z = frame.parts[1].pose_w.translation.z;
    assert!(((0.05 - z) - expected).abs() < 1e-6 * expected, "z = {z}");
    assert!(frame.parts[1].pose_w.rotation.angle() < 1e-9);
}
