//! ACTIVATE and DEACTIVATE between analyses, against closed forms:
//! - a pendulum on a REVOLUTE whose JOINT is deactivated at 0.5 s flies ballistically from the
//!   state it reached: `r = r₀ + v₀τ + ½gτ²`, `v = v₀ + gτ`, `ω = ω₀`;
//! - a mass on an SFORCE spring: harmonic, then (spring off) uniform motion, then (spring on
//!   again) harmonic from the state at re-activation, `x − L₀ = A cos ωτ + (v/ω) sin ωτ`;
//! - an id the model does not have, a class the solver cannot switch, and a MOTION left on a
//!   deactivated JOINT are errors at the command, in the dataset check and in the run.

use contact_adams::dataset::{self, Diagnostic};
use contact_adams::run::plan::{PlanOverrides, plan_run};
use contact_adams::session::{ResultFiles, RunError, RunOptions, RunSink, run_files};
use contact_solver::simulate::Frame;
use nalgebra::Vector3;
use std::path::{Path, PathBuf};

const G: f64 = 9.81;

/// A 1 kg bob on a massless-looking rod of length 1 about the ground's z axis, released
/// from rest along +x.
const PENDULUM: &str = "\
Pendulum on a revolute
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND
ACCGRAV/ JGRAV = -9.81
PART/1, GROUND
MARKER/10, PART = 1
PART/2, MASS = 1, CM = 20, IP = 0.01, 0.02, 0.03
MARKER/20, PART = 2, QP = 1, 0, 0
MARKER/21, PART = 2
JOINT/1, REVOLUTE, I = 21, J = 10
END
";

const PENDULUM_ACF: &str = "\
pendulum.adm
out
integrator/ error = 1e-7
simulate/dynamics, end = 0.5, dtout = 0.01
deactivate/joint, id = 1
simulate/dynamics, end = 1.0, dtout = 0.01
stop
";

/// `M = 2 kg` on a TRANSLATIONAL joint along x, pulled by an SFORCE spring of `K = 200 N/m`
/// and free length 6 m to x = −5 (at rest at x = 1, never near the anchor); no gravity;
/// released from rest at x = 1.2.
const SPRING: &str = "\
Mass on a spring
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND
ACCGRAV/ JGRAV = 0
PART/1, GROUND
MARKER/10, PART = 1, QP = -5, 0, 0
MARKER/11, PART = 1, REULER = 90D, 90D, 0D
PART/2, MASS = 2, CM = 20, IP = 0.01, 0.01, 0.01, QG = 1.2, 0, 0
MARKER/20, PART = 2
MARKER/21, PART = 2, REULER = 90D, 90D, 0D
JOINT/1, TRANSLATIONAL, I = 21, J = 11
SFORCE/1, TRANSLATIONAL, I = 20, J = 10, FUNCTION = -200 * (DM(20, 10) - 6)
END
";

const SPRING_ACF: &str = "\
spring.adm
out
integrator/ error = 1e-8
simulate/dynamics, end = 0.5, dtout = 0.01
deactivate/sforce, id = 1
simulate/dynamics, end = 1.0, dtout = 0.01
activate/sforce, id = 1
simulate/dynamics, end = 2.0, dtout = 0.01
stop
";

/// A sphere of radius 0.1 and 1 kg resting on a ground plane through an IMPACT CONTACT.
const SPHERE: &str = "\
Sphere on a plane
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND
ACCGRAV/ KGRAV = -9.81
PART/1, GROUND
MARKER/10, PART = 1
PART/2, MASS = 1, CM = 20, IP = 0.004, 0.004, 0.004
MARKER/20, PART = 2, QP = 0, 0, 0.1
GRAPHICS/1, ELLIPSOID, CM = 20, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2
GRAPHICS/2, PLANE, RM = 10
CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT, STIFFNESS = 1E6, EXPONENT = 1.5, DAMPING = 50, DMAX = 1E-4
END
";

const SPHERE_ACF: &str = "\
sphere.adm
out
integrator/ error = 1e-6
simulate/dynamics, end = 0.2, dtout = 0.01
deactivate/contact, id = 1
simulate/dynamics, end = 0.5, dtout = 0.01
stop
";

/// Writes the dataset and its command file in a fresh folder.
fn files(name: &str, adm: &str, acf: &str) -> (PathBuf, PathBuf) {
    let dir = std::env::temp_dir().join(format!("activate_{}_{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (adm_path, acf_path) = (
        dir.join(format!("{name}.adm")),
        dir.join(format!("{name}.acf")),
    );
    std::fs::write(&adm_path, adm).unwrap();
    std::fs::write(&acf_path, acf).unwrap();
    (adm_path, acf_path)
}

/// Frames, diagnostics and notes of a run.
#[derive(Default)]
struct Collect {
    frames: Vec<Frame>,
    diagnostics: Vec<Diagnostic>,
    notes: Vec<String>,
}

impl RunSink for Collect {
    fn diagnostics(&mut self, diagnostics: &[Diagnostic]) -> std::io::Result<()> {
        self.diagnostics.extend_from_slice(diagnostics);
        Ok(())
    }

    fn note(&mut self, note: &str) -> std::io::Result<()> {
        self.notes.push(note.to_string());
        Ok(())
    }

    fn frame(&mut self, frame: &Frame) -> std::io::Result<()> {
        self.frames.push(frame.clone());
        Ok(())
    }
}

fn run(name: &str, adm: &str, acf: &str) -> (Collect, Result<(), RunError>) {
    let (adm, acf) = files(name, adm, acf);
    let mut sink = Collect::default();
    let result = run_files(&adm, Some(&acf), &RunOptions::default(), &mut sink).map(|_| ());
    (sink, result)
}

/// The frame at time `t`.
fn at(frames: &[Frame], t: f64) -> &Frame {
    frames
        .iter()
        .find(|f| (f.t - t).abs() < 1e-9)
        .unwrap_or_else(|| panic!("no frame at t = {t}"))
}

#[test]
fn a_deactivated_revolute_lets_the_bob_fly_ballistically_from_its_state() {
    let (sink, result) = run("pendulum", PENDULUM, PENDULUM_ACF);
    result.unwrap();
    assert!(
        sink.notes.iter().any(|n| n.ends_with(
            "DEACTIVATE/JOINT, ID = 1: JOINT/1 removed from the model from t = 0.5 (the next analysis) until ACTIVATE"
        )),
        "{:#?}",
        sink.notes
    );
    // On the joint until 0.5 s: the bob stays on its circle of radius 1.
    for f in sink.frames.iter().filter(|f| f.t <= 0.5 + 1e-9) {
        let r = f.parts[1].pose_w.translation.vector;
        assert!(
            (r.norm() - 1.0).abs() < 1e-6,
            "t = {}: |r| = {}",
            f.t,
            r.norm()
        );
    }
    let release = at(&sink.frames, 0.5).parts[1];
    let (r0, v0, w0) = (
        release.pose_w.translation.vector,
        release.velocity_w,
        release.angular_velocity_w,
    );
    // Released while swinging: the ballistic path leaves the circle.
    assert!(v0.norm() > 1.0, "{v0:?}");
    let g = Vector3::new(0.0, -G, 0.0);
    let mut worst: (f64, f64, f64) = (0.0, 0.0, 0.0);
    let after: Vec<&Frame> = sink.frames.iter().filter(|f| f.t > 0.5 + 1e-9).collect();
    assert_eq!(after.len(), 50);
    for f in after {
        let tau = f.t - 0.5;
        let s = f.parts[1];
        let r = r0 + v0 * tau + 0.5 * g * tau * tau;
        let v = v0 + g * tau;
        worst.0 = worst.0.max((s.pose_w.translation.vector - r).norm());
        worst.1 = worst.1.max((s.velocity_w - v).norm());
        worst.2 = worst.2.max((s.angular_velocity_w - w0).norm());
    }
    // The free flight is a quadratic in time, which the BDF integrates to round-off.
    assert!(worst.0 < 1e-9, "position {worst:?}");
    assert!(worst.1 < 1e-9, "velocity {worst:?}");
    assert!(worst.2 < 1e-12, "angular velocity {worst:?}");
    // And the bob has left the circle the joint held it on.
    let last = sink.frames.last().unwrap().parts[1]
        .pose_w
        .translation
        .vector;
    assert!((last.norm() - 1.0).abs() > 0.1, "{last:?}");
}

#[test]
fn a_spring_switched_off_and_on_again_follows_the_closed_forms() {
    let (sink, result) = run("spring", SPRING, SPRING_ACF);
    result.unwrap();
    let (k, m, free) = (200.0, 2.0, 1.0);
    let omega = f64::sqrt(k / m);
    let x = |f: &Frame| f.parts[1].pose_w.translation.vector.x;
    let v = |f: &Frame| f.parts[1].velocity_w.x;
    let mut worst: [f64; 3] = [0.0; 3];
    // Harmonic from rest at x = 1.2.
    for f in sink.frames.iter().filter(|f| f.t <= 0.5 + 1e-9) {
        let expected = free + 0.2 * (omega * f.t).cos();
        worst[0] = worst[0].max((x(f) - expected).abs());
    }
    // Spring off: uniform motion from the state at 0.5 s.
    let off = at(&sink.frames, 0.5);
    let (x0, v0) = (x(off), v(off));
    assert!(v0.abs() > 0.5, "{v0}");
    for f in sink
        .frames
        .iter()
        .filter(|f| f.t > 0.5 + 1e-9 && f.t <= 1.0 + 1e-9)
    {
        let tau = f.t - 0.5;
        worst[1] = worst[1].max((x(f) - (x0 + v0 * tau)).abs() + (v(f) - v0).abs());
    }
    // Spring on again: harmonic from the state at 1.0 s.
    let on = at(&sink.frames, 1.0);
    let (x1, v1) = (x(on), v(on));
    let after: Vec<&Frame> = sink.frames.iter().filter(|f| f.t > 1.0 + 1e-9).collect();
    assert_eq!(after.len(), 100);
    for f in after {
        let tau = f.t - 1.0;
        let expected = free + (x1 - free) * (omega * tau).cos() + v1 / omega * (omega * tau).sin();
        worst[2] = worst[2].max((x(f) - expected).abs());
    }
    // Amplitudes of 0.2 m and then about 1 m, at ERROR = 1e-8 (the harmonic phases carry
    // the integrator's error, which falls with ERROR; the free flight is exact).
    assert!(worst.iter().all(|w| *w < 1e-5), "{worst:?}");
    // The energy is back: ½kA² of the new oscillation equals ½mv₁² + ½k(x₁ − L₀)².
    let energy = |f: &Frame| 0.5 * m * v(f).powi(2) + 0.5 * k * (x(f) - free).powi(2);
    let e1 = energy(on);
    let last = sink.frames.last().unwrap();
    assert!(
        (energy(last) - e1).abs() < 1e-4 * e1,
        "{} vs {e1}",
        energy(last)
    );
}

#[test]
fn a_deactivated_contact_lets_the_sphere_fall_through_the_plane() {
    let (sink, result) = run("sphere", SPHERE, SPHERE_ACF);
    result.unwrap();
    // Every frame keeps the model's one CONTACT; it reports contact only while active.
    assert!(sink.frames.iter().all(|f| f.contacts.len() == 1));
    let before = at(&sink.frames, 0.2);
    assert!(!before.contacts[0].is_empty(), "resting on the plane");
    let state = before.parts[1];
    let (z0, vz0) = (state.pose_w.translation.vector.z, state.velocity_w.z);
    assert!((z0 - 0.1).abs() < 1e-3, "{z0}");
    let after: Vec<&Frame> = sink.frames.iter().filter(|f| f.t > 0.2 + 1e-9).collect();
    assert_eq!(after.len(), 30);
    let mut worst: f64 = 0.0;
    for f in after {
        assert!(f.contacts[0].is_empty(), "t = {}", f.t);
        let tau = f.t - 0.2;
        let z = z0 + vz0 * tau - 0.5 * G * tau * tau;
        worst = worst.max((f.parts[1].pose_w.translation.vector.z - z).abs());
    }
    // Free fall through the plane: a quadratic in time, integrated to round-off.
    assert!(worst < 1e-9, "{worst}");
    assert!(
        sink.frames.last().unwrap().parts[1]
            .pose_w
            .translation
            .vector
            .z
            < -0.2
    );
}

/// The rows of `requests.csv` for request `id`: time and the six columns.
fn request_rows(csv: &str, id: &str) -> Vec<(f64, [f64; 6])> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|row| row[1] == id)
        .map(|row| {
            let value = |k: usize| row[k].parse::<f64>().unwrap();
            (value(0), std::array::from_fn(|c| value(3 + c)))
        })
        .collect()
}

/// Runs `adm` with `acf` into result files; `requests.csv`.
fn requests_csv(name: &str, adm: &str, acf: &str) -> String {
    let (adm_path, acf_path) = files(name, adm, acf);
    let out = adm_path.parent().unwrap().join("out");
    let mut sink = ResultFiles::new(&out);
    run_files(
        &adm_path,
        Some(&acf_path),
        &RunOptions::default(),
        &mut sink,
    )
    .unwrap();
    std::fs::read_to_string(out.join("requests.csv")).unwrap()
}

/// REQUESTs read what the elements apply: a switched-off SFORCE's force is zero while off,
/// the spring's `−K·(DM − L₀)` while on.
#[test]
fn requests_read_no_force_from_a_switched_off_sforce() {
    let adm = SPRING.replace(
        "END\n",
        "REQUEST/1, D, I = 20, J = 10\nREQUEST/2, F2=SFORCE(1,0,2,0)\nEND\n",
    );
    let csv = requests_csv("sforce_requests", &adm, SPRING_ACF);
    let (d, f) = (request_rows(&csv, "1"), request_rows(&csv, "2"));
    assert_eq!((d.len(), f.len()), (201, 201));
    let (mut on, mut off) = (0, 0);
    for ((t, d), (_, f)) in d.iter().zip(&f) {
        let expected = if *t > 0.5 + 1e-9 && *t <= 1.0 + 1e-9 {
            off += 1;
            0.0
        } else {
            on += 1;
            -200.0 * (d[0] - 6.0)
        };
        assert!(
            (f[0] - expected).abs() <= 1e-9 * (1.0 + expected.abs()),
            "t = {t}: {} vs {expected}",
            f[0]
        );
    }
    assert_eq!((on, off), (151, 50));
}

/// A FORCE REQUEST on a switched-off JOINT reads zero: the pendulum's pivot carries a
/// reaction until the release (at t = 0, from rest, `m·g·I_cm/(I_cm + m·L²)` = 0.2857 N up),
/// nothing after it.
#[test]
fn requests_read_no_reaction_from_a_switched_off_joint() {
    let adm = PENDULUM.replace("END\n", "REQUEST/1, FORCE, I = 21, J = 10\nEND\n");
    let csv = requests_csv("joint_requests", &adm, PENDULUM_ACF);
    let rows = request_rows(&csv, "1");
    assert_eq!(rows.len(), 101);
    let start = G * 0.03 / 1.03;
    assert!((rows[0].1[1] - start).abs() < 1e-6, "{:?}", rows[0]);
    for (t, f) in rows {
        let force = Vector3::new(f[0], f[1], f[2]).norm();
        if t <= 0.5 + 1e-9 {
            assert!(force > 0.9 * start, "t = {t}: {f:?}");
        } else {
            assert_eq!(f, [0.0; 6], "t = {t}");
        }
    }
}

/// The errors a command file's switches can have, as `contact check` reads them.
fn read_errors(acf: &str) -> Vec<String> {
    let acf_path = Path::new("data/p.acf");
    let loaded = dataset::read_str(PENDULUM, "data/p.adm", Some((acf, acf_path)));
    loaded
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(ToString::to_string)
        .collect()
}

#[test]
fn unknown_ids_and_classes_are_errors_at_the_command() {
    let errors = read_errors(
        "p.adm\nout\ndeactivate/joint, id = 1, 9\nsimulate/dyn, end = 1, dtout = 0.1\n",
    );
    assert_eq!(
        errors,
        ["data/p.acf:3:27: error: DEACTIVATE/JOINT: the model has no JOINT/9"]
    );
    let errors = read_errors("p.adm\nout\nactivate/sensor, id = 1\n");
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].starts_with(
            "data/p.acf:3:10: error: ACTIVATE/SENSOR: SENSOR elements cannot be switched by this solver (it switches JOINT, JPRIM, GCON, MOTION, SFORCE, CONTACT)"
        ),
        "{errors:?}"
    );
    // RANGE: two ids, in order, with an element of the class between them.
    let errors = read_errors("p.adm\nout\ndeactivate/joint, range = 2, 1\n");
    assert_eq!(
        errors,
        [
            "data/p.acf:3:30: error: DEACTIVATE/JOINT: RANGE = 2, 1: the last id must be >= the first"
        ]
    );
    let errors = read_errors("p.adm\nout\ndeactivate/joint, range = 5, 9\n");
    assert_eq!(
        errors,
        [
            "data/p.acf:3:27: error: DEACTIVATE/JOINT: RANGE = 5, 9: the model has no JOINT with an id in it"
        ]
    );
    let errors = read_errors("p.adm\nout\ndeactivate/joint, range = 1\n");
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].contains("RANGE takes two ids (first, last), got 1"),
        "{errors:?}"
    );
    // `run` refuses the same, with the same message.
    let (sink, result) = run(
        "unknown",
        PENDULUM,
        "unknown.adm\nout\ndeactivate/joint, id = 9\nsimulate/dyn, end = 1, dtout = 0.1\n",
    );
    assert!(matches!(result, Err(RunError::ModelErrors)), "{result:?}");
    assert!(
        sink.diagnostics.iter().any(|d| d
            .to_string()
            .ends_with("unknown.acf:3:24: error: DEACTIVATE/JOINT: the model has no JOINT/9")),
        "{:#?}",
        sink.diagnostics
    );
}

/// `RANGE = first, last` switches every element of the class with an id in between: the
/// spring switched off by RANGE runs exactly as switched off by ID.
#[test]
fn a_range_switches_the_elements_between_its_ids() {
    let by_range = SPRING_ACF
        .replace(
            "deactivate/sforce, id = 1",
            "deactivate/sforce, range = 1, 4",
        )
        .replace("activate/sforce, id = 1", "activate/sforce, range = 1, 1");
    assert_ne!(by_range, SPRING_ACF);
    let (by_id, result) = run("spring_by_id", SPRING, SPRING_ACF);
    result.unwrap();
    let (by_range, result) = run("spring_by_range", SPRING, &by_range);
    result.unwrap();
    assert_eq!(by_id.frames.len(), by_range.frames.len());
    for (a, b) in by_id.frames.iter().zip(&by_range.frames) {
        assert_eq!(a.t, b.t);
        assert_eq!(a.parts, b.parts, "t = {}", a.t);
    }
}

#[test]
fn a_motion_left_on_a_deactivated_joint_is_refused_at_the_analysis() {
    let adm = PENDULUM.replace(
        "END\n",
        "MOTION/5, JOINT = 1, ROTATION, FUNCTION = TIME\nEND\n",
    );
    let acf = "p.adm\nout\ndeactivate/joint, id = 1\nsimulate/dyn, end = 1, dtout = 0.1\n";
    let loaded = dataset::read_str(&adm, "data/p.adm", Some((acf, Path::new("data/p.acf"))));
    assert!(!loaded.has_errors(), "{:#?}", loaded.diagnostics);
    let error = plan_run(&loaded.model, PlanOverrides::default(), &mut |_, _| Ok(1)).unwrap_err();
    assert_eq!(
        error.to_string(),
        "data/p.acf:4:1: MOTION/5 drives JOINT/1, which is deactivated: deactivate the MOTION too"
    );
    // Deactivating the MOTION as well plans, and each switch says what it does.
    let acf = "p.adm\nout\ndeactivate/joint, id = 1\ndeactivate/motion, id = 5\nsimulate/dyn, end = 1, dtout = 0.1\n\
activate/joint, id = 1\nactivate/joint, id = 1\nactivate/motion, id = 5\nlinear/eigensol\n";
    let loaded = dataset::read_str(&adm, "data/p.adm", Some((acf, Path::new("data/p.acf"))));
    let plan = plan_run(&loaded.model, PlanOverrides::default(), &mut |_, _| Ok(1)).unwrap();
    assert_eq!(plan.inactive[0].names(), "JOINT/1, MOTION/5");
    assert!(plan.inactive[1].is_empty());
    let switches: Vec<String> = plan
        .switches
        .iter()
        .map(|(o, s)| format!("{o}: {s}"))
        .collect();
    assert_eq!(
        switches,
        [
            "data/p.acf:3:1: DEACTIVATE/JOINT, ID = 1: JOINT/1 removed from the model from t = 0.0 (the next analysis) until ACTIVATE",
            "data/p.acf:4:1: DEACTIVATE/MOTION, ID = 5: MOTION/5 removed from the model from t = 0.0 (the next analysis) until ACTIVATE",
            "data/p.acf:6:1: ACTIVATE/JOINT, ID = 1: JOINT/1 back in the model from t = 1.0 (the next analysis)",
            "data/p.acf:7:1: ACTIVATE/JOINT, ID = 1: JOINT/1 already active: no change",
            "data/p.acf:8:1: ACTIVATE/MOTION, ID = 5: MOTION/5 back in the model from t = 1.0 (the next analysis)",
        ]
    );
}
