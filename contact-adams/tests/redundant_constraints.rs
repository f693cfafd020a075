//! Redundant constraints through the dataset: a planar slider-crank of two REVOLUTEs, an
//! INLINE JPRIM and a MOTION (13 equations on 12 coordinates, one redundant) runs, its slider
//! on the closed-form position `x = r·cos θ + sqrt(l² − r²·sin² θ)`; the removed equation is
//! listed at its statement; two REVOLUTEs that cannot both hold are refused naming both.

use contact_adams::dataset::{self, Diagnostic, Severity};
use contact_adams::session::{RunOptions, RunSink, check_constraints, run_files};
use contact_solver::simulate::Frame;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

const R: f64 = 0.1;
const L: f64 = 0.3;

/// The slider-crank with the crank along +x at t = 0, driven at one turn per second.
const SLIDER_CRANK: &str = "\
Planar slider-crank: two REVOLUTEs, an INLINE JPRIM, a MOTION
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND
PART/1, GROUND
MARKER/10, PART = 1
MARKER/12, PART = 1, REULER = 90D, 90D, 0D
PART/2, MASS = 1, CM = 20, IP = 1E-3, 1E-3, 1E-3
MARKER/20, PART = 2, QP = 0.05, 0, 0
MARKER/21, PART = 2
MARKER/22, PART = 2, QP = 0.1, 0, 0
PART/3, MASS = 1, CM = 30, IP = 1E-3, 1E-3, 1E-3
MARKER/30, PART = 3, QP = 0.25, 0, 0
MARKER/31, PART = 3, QP = 0.1, 0, 0
MARKER/32, PART = 3, QP = 0.4, 0, 0
JOINT/1, REVOLUTE, I = 21, J = 10
JOINT/2, REVOLUTE, I = 31, J = 22
JPRIM/3, INLINE, I = 32, J = 12
MOTION/1, JOINT = 1, FUNCTION = 360D * TIME
END
";

/// A part held by two parallel REVOLUTEs 0.1 apart on the part and 0.15 apart on the ground.
const MISALIGNED: &str = "\
Two REVOLUTEs that cannot both hold
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND
PART/1, GROUND
MARKER/10, PART = 1
MARKER/11, PART = 1, QP = 0, 0.15, 0
PART/2, MASS = 1, CM = 20, IP = 1E-3, 1E-3, 1E-3
MARKER/20, PART = 2, QP = 0.05, 0, 0
MARKER/21, PART = 2
MARKER/22, PART = 2, QP = 0, 0.1, 0
JOINT/1, REVOLUTE, I = 21, J = 10
JOINT/5, REVOLUTE, I = 22, J = 11
END
";

const COMMANDS: &str = "out\nsimulate/transient, end = 0.5, dtout = 0.01\nstop\n";

/// Writes `text` as `name` in a fresh temporary folder, with its command file.
fn dataset(name: &str, text: &str) -> (PathBuf, PathBuf) {
    let dir = std::env::temp_dir().join(format!("redundant_{}_{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let adm = dir.join(format!("{name}.adm"));
    let acf = dir.join(format!("{name}.acf"));
    std::fs::write(&adm, text).unwrap();
    std::fs::write(&acf, format!("{name}.adm\n{COMMANDS}")).unwrap();
    (adm, acf)
}

/// Collects frames and diagnostics.
#[derive(Default)]
struct Collect {
    frames: Vec<Frame>,
    diagnostics: Vec<Diagnostic>,
}

impl RunSink for Collect {
    fn diagnostics(&mut self, diagnostics: &[Diagnostic]) -> std::io::Result<()> {
        self.diagnostics.extend_from_slice(diagnostics);
        Ok(())
    }

    fn frame(&mut self, frame: &Frame) -> std::io::Result<()> {
        self.frames.push(frame.clone());
        Ok(())
    }
}

/// What `contact check` adds for the model's constraints.
fn check(adm: &Path) -> Vec<Diagnostic> {
    let model = dataset::read(adm, None).unwrap().model;
    let engine = contact_adams::engine_choice::build_engine(
        model.preferences.geometry_library,
        contact_core::FacetingTolerance::DEFAULT,
    );
    check_constraints(&model, engine.as_ref(), 0.0)
}

#[test]
fn a_planar_slider_crank_runs_on_the_closed_form() {
    let (adm, acf) = dataset("slider_crank", SLIDER_CRANK);
    let mut sink = Collect::default();
    run_files(&adm, Some(&acf), &RunOptions::default(), &mut sink).expect("the model runs");
    let warnings: Vec<&Diagnostic> = sink
        .diagnostics
        .iter()
        .filter(|d| d.message.contains("redundant equation"))
        .collect();
    assert_eq!(warnings.len(), 1, "{:#?}", sink.diagnostics);
    assert_eq!(warnings[0].severity, Severity::Warning);
    assert_eq!(sink.frames.len(), 51);
    for frame in &sink.frames {
        let rod = &frame.parts[2].pose_w; // ground, PART/2, PART/3
        let end = rod * nalgebra::Point3::new(0.15, 0.0, 0.0);
        let theta = 2.0 * PI * frame.t;
        let exact = R * theta.cos() + (L * L - (R * theta.sin()).powi(2)).sqrt();
        assert!(
            (end.x - exact).abs() < 1e-9 * L,
            "t = {}: {} vs {exact}",
            frame.t,
            end.x
        );
        assert!(end.y.abs() < 1e-9 * L && end.z.abs() < 1e-9 * L, "{end}");
    }
    // `contact check` lists the same equation, at its statement, as a warning only.
    let checked = check(&adm);
    assert_eq!(checked.len(), 1, "{checked:#?}");
    assert_eq!(checked[0].message, warnings[0].message);
    assert_eq!(checked[0].origin.loc, warnings[0].origin.loc);
    let line = SLIDER_CRANK
        .lines()
        .nth(checked[0].origin.loc.line as usize - 1)
        .unwrap();
    let element = checked[0].message.split(':').next().unwrap();
    assert!(
        line.starts_with(&format!("{element},")),
        "{line} vs {element}"
    );
}

#[test]
fn joints_that_cannot_both_hold_are_an_error_naming_them() {
    let (adm, acf) = dataset("misaligned", MISALIGNED);
    let mut sink = Collect::default();
    let error = run_files(&adm, Some(&acf), &RunOptions::default(), &mut sink)
        .expect_err("the model is refused");
    let report = format!("{error}");
    let failure = match error {
        contact_adams::session::RunError::Stopped(report) => format!("{:?}", report.failure),
        other => format!("{other}"),
    };
    assert!(
        failure.contains("JOINT/1") && failure.contains("JOINT/5"),
        "{report}: {failure}"
    );
    let checked = check(&adm);
    let errors: Vec<&Diagnostic> = checked.iter().filter(|d| d.is_error()).collect();
    assert_eq!(errors.len(), 1, "{checked:#?}");
    assert!(
        errors[0]
            .message
            .contains("inconsistent redundant constraints between JOINT/1, JOINT/5"),
        "{}",
        errors[0].message
    );
    assert_eq!(errors[0].origin.loc.line, 10, "{}", errors[0]);
}
