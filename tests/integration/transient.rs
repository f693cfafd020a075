//! SIMULATE/TRANSIENT: kinematics for a model without degrees of freedom, dynamics otherwise,
//! and the run summary saying which ran and why.

use contact::run::lower::{LoweredModel, lower};
use contact::run::plan::{AnalysisStep, PlanOverrides, plan_analyses};
use contact::solver::contact_force::Analysis;
use contact::solver::kinematics::initial_degrees_of_freedom;
use std::path::{Path, PathBuf};

fn example(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(path)
}

/// `contact run MODEL ACF` with the command file `acf_text`, both into a fresh directory named
/// `name`: (exit code, stdout, stderr, the output directory).
fn run_with_commands(name: &str, model: PathBuf, acf_text: &str) -> (u8, String, String, PathBuf) {
    let dir = std::env::temp_dir().join(format!("contact-transient-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    let acf = dir.join(format!("{name}.acf"));
    std::fs::write(&acf, acf_text).unwrap();
    let out = dir.join("out");
    let args = contact::cli::run::RunArgs {
        model,
        commands: Some(acf),
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

fn summary(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
}

fn read(out: &Path, file: &str) -> String {
    std::fs::read_to_string(out.join(file)).unwrap()
}

#[test]
fn transient_on_the_slider_crank_runs_kinematics_with_the_same_frames() {
    let model = example("slider_crank/slider_crank.adm");
    let (code, stdout, stderr, transient) = run_with_commands(
        "slider-transient",
        model.clone(),
        "slider_crank\nSIMULATE/TRANSIENT, END = 0.5, DTOUT = 0.05\nSTOP\n",
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("SIMULATE/TRANSIENT ran as KINEMATICS: the model has 0 degrees of freedom"),
        "{stdout}"
    );
    assert!(
        stdout.contains("ran kinematics from t = 0 to 0.5"),
        "{stdout}"
    );
    let (code, _, stderr, kinematics) = run_with_commands(
        "slider-kinematics",
        model,
        "slider_crank\nSIMULATE/KINEMATICS, END = 0.5, DTOUT = 0.05\nSTOP\n",
    );
    assert_eq!(code, 0, "{stderr}");
    for file in ["parts.csv", "contacts.csv"] {
        let (a, b) = (read(&transient, file), read(&kinematics, file));
        assert_eq!(a, b, "{file} differs");
    }
    // 11 frames of 3 moving parts, and a slider on the closed form (so the frames are the
    // mechanism's, not empty files that agree).
    let parts = read(&transient, "parts.csv");
    let rows: Vec<Vec<f64>> = parts
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 11 * 3);
    for row in rows.iter().filter(|r| r[1] == 4.0) {
        let (s, c) = (std::f64::consts::TAU * row[0]).sin_cos();
        let x = 0.1 * c + (0.09 - 0.01 * s * s).sqrt();
        assert!((row[2] - x).abs() < 1e-9, "{row:?} vs {x}");
    }
    let report = &summary(&transient)["analyses"][0];
    assert_eq!(report["analysis"], "KINEMATICS");
    assert_eq!(report["requested"], "TRANSIENT");
    assert_eq!(report["degrees_of_freedom"], 0);
    assert_eq!(summary(&kinematics)["analyses"][0].get("requested"), None);
    std::fs::remove_dir_all(transient.parent().unwrap()).ok();
    std::fs::remove_dir_all(kinematics.parent().unwrap()).ok();
}

#[test]
fn transient_on_the_pendulum_runs_dynamics_with_the_same_frames() {
    let model = example("pendulum/pendulum.adm");
    let (code, stdout, stderr, transient) = run_with_commands(
        "pendulum-transient",
        model.clone(),
        "pendulum\nSIMULATE/TRANSIENT, END = 0.5, DTOUT = 0.05\nSTOP\n",
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("SIMULATE/TRANSIENT ran as DYNAMICS: the model has 1 degree of freedom"),
        "{stdout}"
    );
    assert!(stdout.contains("s of dynamics"), "{stdout}");
    let (code, _, stderr, dynamics) = run_with_commands(
        "pendulum-dynamics",
        model,
        "pendulum\nSIMULATE/DYNAMICS, END = 0.5, DTOUT = 0.05\nSTOP\n",
    );
    assert_eq!(code, 0, "{stderr}");
    let parts = read(&transient, "parts.csv");
    assert_eq!(parts, read(&dynamics, "parts.csv"));
    // The bob swings: released at rest from 60°, it has fallen and moves at t = 0.5.
    let last: Vec<f64> = parts
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(last[0], 0.5);
    assert!(last[4] < -0.6, "{last:?}");
    let report = &summary(&transient)["analyses"][0];
    assert_eq!(report["analysis"], "DYNAMICS");
    assert_eq!(report["requested"], "TRANSIENT");
    assert_eq!(report["degrees_of_freedom"], 1);
    std::fs::remove_dir_all(transient.parent().unwrap()).ok();
    std::fs::remove_dir_all(dynamics.parent().unwrap()).ok();
}

/// The slider-crank with a REVOLUTE joint at the slider pin instead of the UNIVERSAL: 19
/// constraint equations on 18 coordinates, one of them redundant.
fn redundant_slider_crank() -> LoweredModel {
    let text = std::fs::read_to_string(example("slider_crank/slider_crank.adm")).unwrap();
    let text = text
        .replace(
            "MARKER/32, PART = 3, QP = 0.4, 0, 0, REULER = 0D, -90D, 0D",
            "MARKER/32, PART = 3, QP = 0.4, 0, 0",
        )
        .replace(
            "JOINT/3, UNIVERSAL, I = 32, J = 41",
            "JOINT/3, REVOLUTE, I = 32, J = 41",
        );
    let loaded = crate::inline("transient_redundant_slider_crank.adm", &text);
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

#[test]
fn transient_counts_degrees_of_freedom_by_rank_so_redundant_constraints_still_give_kinematics() {
    let model = redundant_slider_crank();
    let layout = model.system.layout();
    // 19 equations on 18 coordinates: the one the rank shows redundant is removed when the
    // system is built (and listed), leaving 18.
    assert_eq!((layout.parts(), layout.constraint_rows()), (3, 18));
    assert_eq!(model.system.redundant_equations().count(), 1);
    // A count of the written equations would say 18 − 19 = −1; the rank says 0.
    assert_eq!(initial_degrees_of_freedom(&model.system, 0.0).unwrap(), 0);
    let loaded = contact::dataset::read_str(
        "plan\nPART/1, GROUND\nEND\n",
        "plan.adm",
        Some((
            "plan.adm\nplan\nSIMULATE/TRANSIENT, END = 1, DTOUT = 0.1\nSTOP\n",
            Path::new("plan.acf"),
        )),
    );
    let mut dof = |t: f64| Ok(initial_degrees_of_freedom(&model.system, t)?);
    let (steps, notes) = plan_analyses(&loaded.model, PlanOverrides::default(), &mut dof).unwrap();
    assert!(
        matches!(steps[..], [AnalysisStep::Kinematics { .. }]),
        "{steps:?}"
    );
    assert!(notes.iter().any(|n| n.contains("0 degrees of freedom")));
    // Take the MOTION away: the crank turns freely, one degree of freedom, dynamics.
    let text = std::fs::read_to_string(example("slider_crank/slider_crank.adm"))
        .unwrap()
        .replace("MOTION/1, JOINT = 1, FUNCTION = 360D * TIME", "");
    let loaded = crate::inline("transient_free_slider_crank.adm", &text);
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
    let free = lower(
        &loaded.model,
        &engine_exact::ExactEngine,
        Analysis::Quasistatic,
        &no_meshes,
    )
    .unwrap();
    assert_eq!(initial_degrees_of_freedom(&free.system, 0.0).unwrap(), 1);
}
