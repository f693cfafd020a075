//! Bad input and faults: nothing panics, hangs, fills the disk or loses a result. A model with
//! no moving part, options out of range, output without bound, and settings that would never
//! finish are refused before any result file is opened, with the value, its source and the
//! bound; `contact check` refuses what `contact run` refuses.

use crate::{data_dir, errors, inline};
use contact::cli::check::{CheckArgs, check_mesh_files, check_run_settings};
use contact::cli::run::RunArgs;
use contact::dataset::read_str;
use std::path::{Path, PathBuf};

fn example(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(path)
}

/// A scratch directory for one test, empty.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("contact-faults-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn ball_args(out: &Path) -> RunArgs {
    RunArgs {
        model: example("ball/ball.adm"),
        commands: None,
        engine: None,
        faceting_tolerance: None,
        end: Some(0.01),
        dtout: None,
        steps: None,
        out: Some(out.to_path_buf()),
        threads: None,
        quiet: true,
    }
}

/// Runs `contact run`; the exit code, stdout and stderr.
fn run(args: &RunArgs) -> (u8, String, String) {
    let (mut stdout, mut stderr) = (Vec::new(), Vec::new());
    let code = contact::cli::run::run(args, &mut stdout, &mut stderr).unwrap();
    (
        code,
        String::from_utf8(stdout).unwrap(),
        String::from_utf8(stderr).unwrap(),
    )
}

/// Runs `contact check`; the exit code and the report.
fn check(model: PathBuf, commands: Option<PathBuf>) -> (i32, String) {
    let args = CheckArgs {
        model,
        commands,
        engine: None,
    };
    let mut out = Vec::new();
    let code = contact::cli::check::run(&args, &mut out).unwrap();
    (code, String::from_utf8(out).unwrap())
}

#[test]
fn a_model_without_a_moving_part_is_an_error_at_check_and_run() {
    let dir = scratch("ground");
    let cases = [
        (
            "ground.adm",
            "t\nUNITS/ SYSTEM = MKS\nPART/1, GROUND\nMARKER/1, PART = 1\nEND\n",
            "ground.adm:3:1: error: the model has no moving part: nothing to simulate (add a PART with MASS, CM and IP)",
        ),
        // A dataset cut short after its title.
        (
            "short.adm",
            "t\nUNITS/ SYSTEM = MKS\n",
            "short.adm:1:1: error: the model has no moving part: nothing to simulate (add a PART with MASS, CM and IP)",
        ),
        // Lines ending in CR only: one title line, and the message says why.
        (
            "cr.adm",
            "t\rUNITS/ SYSTEM = MKS\rPART/1, GROUND\rPART/2, MASS = 1, CM = 2, IP = 1, 1, 1\rMARKER/2, PART = 2\rEND\r",
            "cr.adm:1:1: error: the model has no moving part: nothing to simulate (add a PART with MASS, CM and IP); the file's lines end in CR only (classic Mac OS), so it was read as one title line: save it with LF or CRLF line endings",
        ),
    ];
    for (name, text, want) in cases {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        let (code, report) = check(path.clone(), None);
        assert_eq!(code, 1, "{report}");
        assert!(report.contains(want), "{report}");
        let mut args = ball_args(&dir.join("out"));
        args.model = path;
        let (code, _, stderr) = run(&args);
        assert_eq!(code, 1, "{stderr}");
        let message = want.split_once("error: ").unwrap().1;
        assert!(stderr.contains(message), "{stderr}");
        assert!(!dir.join("out").exists());
    }

    // The library entry point refuses such a model too, before anything is written.
    let loaded = read_str(cases[0].1, data_dir().join("ground.adm"), None);
    let mut files = contact::session::ResultFiles::new(dir.join("lib"));
    let options = contact::session::RunOptions {
        end: Some(1.0),
        ..Default::default()
    };
    let error = contact::session::run_model(&loaded.model, Path::new("g"), &options, &mut files)
        .unwrap_err();
    assert!(
        matches!(
            error,
            contact::session::RunError::NoMovingPart { cr_only: false }
        ),
        "{error}"
    );
    assert!(!files.started());
}

/// Sets one flag of `contact run`.
type SetFlag = fn(&mut RunArgs);

#[test]
fn an_option_out_of_range_is_refused_before_any_file_is_touched() {
    let out = scratch("options").join("out");
    let (code, _, stderr) = run(&ball_args(&out));
    assert_eq!(code, 0, "{stderr}");
    let parts = std::fs::read(out.join("parts.csv")).unwrap();
    let cases: [(&str, SetFlag); 10] = [
        ("--dtout 0.0 is out of range: must be finite and > 0", |a| {
            a.dtout = Some(0.0)
        }),
        ("--dtout NaN is out of range", |a| a.dtout = Some(f64::NAN)),
        (
            "--end 0.0 is out of range: the end must be finite and after the start time 0.0",
            |a| a.end = Some(0.0),
        ),
        ("--end -1.0 is out of range", |a| a.end = Some(-1.0)),
        ("--end NaN is out of range: must be finite", |a| {
            a.end = Some(f64::NAN)
        }),
        ("--steps 0 is out of range: must be >= 1", |a| {
            a.steps = Some(0)
        }),
        ("--threads 0 is out of range: must be in [1, 1024]", |a| {
            a.threads = Some(0)
        }),
        (
            "--threads 1000000 is out of range: must be in [1, 1024]",
            |a| a.threads = Some(1_000_000),
        ),
        ("--faceting-tolerance", |a| {
            a.faceting_tolerance = Some(-1.0)
        }),
        ("--engine", |a| a.engine = Some("nonesuch".into())),
    ];
    for (message, set) in cases {
        let mut args = ball_args(&out);
        set(&mut args);
        let (code, _, stderr) = run(&args);
        assert_eq!(code, 1, "{message}");
        assert!(stderr.contains(message), "want {message:?} in {stderr}");
        assert!(!stderr.contains("results up to"), "{stderr}");
        assert_eq!(
            std::fs::read(out.join("parts.csv")).unwrap(),
            parts,
            "{message}"
        );
    }
}

#[test]
fn output_without_bound_is_refused_with_the_bound_and_the_remedy() {
    let out = scratch("frames").join("out");
    let mut args = ball_args(&out);
    args.end = Some(1.0);
    args.dtout = Some(1e-300);
    let (code, _, stderr) = run(&args);
    assert_eq!(code, 1);
    assert!(
        stderr.contains(
            "error: --dtout: a span of 1.0 at an output step of 1e-300 makes 1.000e300 output frames, more than the bound of 1000000 per analysis: raise --dtout to at least 1e-6"
        ),
        "{stderr}"
    );
    assert!(!stderr.contains("results up to"), "{stderr}");
    assert!(!out.exists());
    args.dtout = None;
    args.steps = Some(20_000_000);
    let (code, _, stderr) = run(&args);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("lower --steps to at most 1000000"),
        "{stderr}"
    );
    assert!(!out.exists());

    // The same from a command file, located, and reported by `contact check`.
    let dir = scratch("frames-acf");
    let (adm, acf) = (dir.join("ball.adm"), dir.join("big.acf"));
    std::fs::copy(example("ball/ball.adm"), &adm).unwrap();
    std::fs::write(
        &acf,
        "ball\nbig\nSIMULATE/DYNAMICS, DURATION = 1E308, DTOUT = 0.1\nSTOP\n",
    )
    .unwrap();
    let (code, report) = check(adm, Some(acf));
    assert_eq!(code, 1, "{report}");
    assert!(
        report.contains("big.acf:3:1: error: DTOUT: a span of 1e308 at an output step of 0.1 makes inf output frames, more than the bound of 1000000 per analysis: raise DTOUT to at least 1e302"),
        "{report}"
    );
}

#[test]
fn an_hmax_too_small_for_its_span_is_refused_at_check_and_run() {
    let dir = scratch("hmax");
    let (adm, acf) = (dir.join("ball.adm"), dir.join("hmax.acf"));
    std::fs::copy(example("ball/ball.adm"), &adm).unwrap();
    std::fs::write(
        &acf,
        "ball\nhmax\nINTEGRATOR/ HMAX = 1E-300\nSIMULATE/DYNAMICS, END = 1, DTOUT = 0.1\nSTOP\n",
    )
    .unwrap();
    let want = "hmax.acf:4:1: error: INTEGRATOR/HMAX = 1e-300 over a span of 1.0 needs more than 1e10 steps: HMAX must be >= 1e-10 (the span × 1e-10)";
    let (code, report) = check(adm.clone(), Some(acf.clone()));
    assert_eq!(code, 1, "{report}");
    assert!(report.contains(want), "{report}");
    let mut args = ball_args(&dir.join("out"));
    args.model = adm;
    args.end = None;
    args.commands = Some(acf);
    let (code, _, stderr) = run(&args);
    assert_eq!(code, 1);
    assert!(stderr.contains("INTEGRATOR/HMAX = 1e-300"), "{stderr}");
    assert!(!dir.join("out").exists());
}

#[test]
fn check_refuses_what_run_refuses() {
    // INTEGRATOR/ERROR outside (0, 1), a physically impossible inertia, a VARVAL cycle and
    // NTHREADS beyond the bound: errors with their locations.
    let text = "t\nUNITS/ SYSTEM = MKS\nPART/1, GROUND\nMARKER/1, PART = 1\nPART/2, MASS = 1, CM = 2, IP = 1, 0.001, 0.001\nMARKER/2, PART = 2\nVARIABLE/1, FUNCTION = VARVAL(2) + 1\nVARIABLE/2, FUNCTION = 2 * VARVAL(1)\nINTEGRATOR/ ERROR = 2\nPREFERENCES/ NTHREADS = 1000000\nEND\n";
    assert_eq!(
        errors(&inline("bad.adm", text)),
        [
            "data/bad.adm:10:25: error: PREFERENCES: NTHREADS = 1000000 is out of range: must be in [1, 1024]",
            "data/bad.adm:5:32: error: PART/2: IP is not the inertia of a rigid body: its principal moments are 1.0, 0.001, 0.001, and each must be >= 0 and at most the sum of the other two",
            "data/bad.adm:6:18: error: MARKER/2: PART/2 is not defined",
            "data/bad.adm:7:1: error: VARIABLE/1: FUNCTION: the variables read each other in a cycle (VARIABLE/1 → VARIABLE/2 → VARIABLE/1): none has a value",
            "data/bad.adm:9:21: error: INTEGRATOR: ERROR = 2.0 is out of range: must be finite and in (0, 1)",
        ]
    );
    // A thin rod (0, I, I) is a rigid body.
    let rod = text
        .replace("IP = 1, 0.001, 0.001", "IP = 0, 1, 1")
        .replace(
            "VARIABLE/2, FUNCTION = 2 * VARVAL(1)\n",
            "VARIABLE/2, FUNCTION = 2\n",
        )
        .replace("ERROR = 2", "ERROR = 0.01")
        .replace("NTHREADS = 1000000", "NTHREADS = 2");
    assert_eq!(errors(&inline("rod.adm", &rod)), Vec::<String>::new());

    // A mesh file that does not parse is an error at the CONTACT that uses it.
    let dir = scratch("mesh");
    std::fs::write(
        dir.join("bad.stl"),
        "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 oops\n",
    )
    .unwrap();
    let adm = "t\nUNITS/ SYSTEM = MKS\nPART/1, GROUND\nMARKER/1, PART = 1\nPART/2, MASS = 1, CM = 2, IP = 1, 1, 1\nMARKER/2, PART = 2\nGRAPHICS/1, PLANE, RM = 1\nGRAPHICS/2, EXTERNAL, RM = 2, FILE = bad.stl\nCONTACT/1, IGEOM = 2, JGEOM = 1, IMPACT, STIFFNESS = 1e5, DAMPING = 10, DMAX = 0.001, EXPONENT = 1.5\nEND\n";
    let loaded = read_str(adm, dir.join("mesh.adm"), None);
    assert_eq!(errors(&loaded), Vec::<String>::new());
    let found = check_mesh_files(&loaded.model);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(
        found[0]
            .to_string()
            .contains("mesh.adm:9:1: error: CONTACT/1: GRAPHICS/2: STL file"),
        "{}",
        found[0]
    );
    // The ASCII file's bad line is named.
    assert!(
        found[0]
            .to_string()
            .contains("(line 4: 'vertex 0 0 oops': expected 3 numbers after 'vertex')"),
        "{}",
        found[0]
    );
    // Without a command file, only the INTEGRATOR settings are planned at check.
    assert!(check_run_settings(&loaded.model, &dir.join("mesh.adm")).is_empty());
}

#[test]
fn a_run_whose_time_stops_advancing_stops_with_a_diagnosis_and_keeps_its_frames() {
    // STICTION_TRANSITION_VELOCITY = 1E-300 makes the friction law's slope μN/v_s overflow:
    // Newton fails every other step and the steps shrink to 1e-10 of the span. The progress
    // guard stops the run instead of spinning for 1e10 steps.
    let dir = scratch("stall");
    let adm = std::fs::read_to_string(example("incline/incline.adm"))
        .unwrap()
        .replace(
            "STICTION_TRANSITION_VELOCITY = 0.01",
            "STICTION_TRANSITION_VELOCITY = 1E-300",
        );
    std::fs::write(dir.join("incline.adm"), adm).unwrap();
    std::fs::copy(example("incline/incline.acf"), dir.join("incline.acf")).unwrap();
    let mut args = ball_args(&dir.join("out"));
    args.model = dir.join("incline.adm");
    args.commands = Some(dir.join("incline.acf"));
    args.end = None;
    let (code, _, stderr) = run(&args);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("the run is not advancing: the last 10000 steps advanced time by"),
        "{stderr}"
    );
    assert!(
        stderr.contains("results up to the failure are in"),
        "{stderr}"
    );
    let parts = std::fs::read_to_string(dir.join("out").join("parts.csv")).unwrap();
    assert!(parts.lines().count() >= 2, "{parts}");
    let summary = std::fs::read_to_string(dir.join("out").join("summary.json")).unwrap();
    assert!(summary.contains("not advancing"), "{summary}");
}

/// The final state (parts.csv's last row) of the incline example run to 5 ms with the stiction
/// and friction transition velocities `vs` and `2·vs` at ERROR = 1e-8, and its step count.
fn incline_with_stiction(vs: f64) -> (Vec<f64>, u64) {
    use contact::session::{ResultFiles, RunOptions, run_files};
    let dir = scratch(&format!("stiction-{vs:e}"));
    let adm = std::fs::read_to_string(example("incline/incline.adm"))
        .unwrap()
        .replace(
            "STICTION_TRANSITION_VELOCITY = 0.01, FRICTION_TRANSITION_VELOCITY = 0.02",
            &format!(
                "STICTION_TRANSITION_VELOCITY = {vs:e}, FRICTION_TRANSITION_VELOCITY = {:e}",
                2.0 * vs
            ),
        )
        .replace("INTEGRATOR/ ERROR = 1E-6", "INTEGRATOR/ ERROR = 1E-8");
    std::fs::write(dir.join("incline.adm"), adm).unwrap();
    let acf = dir.join("incline.acf");
    std::fs::write(
        &acf,
        "incline.adm\nincline\nSIMULATE/DYNAMIC, END = 0.005, DTOUT = 0.001\nSTOP\n",
    )
    .unwrap();
    let mut files = ResultFiles::new(dir.join("out"));
    let report = run_files(
        &dir.join("incline.adm"),
        Some(&acf),
        &RunOptions::default(),
        &mut files,
    )
    .unwrap_or_else(|e| panic!("vs = {vs:e}: {e}"));
    let parts = std::fs::read_to_string(dir.join("out").join("parts.csv")).unwrap();
    let last = parts.lines().last().unwrap();
    let state = last.split(',').map(|v| v.parse().unwrap()).collect();
    (state, report.dynamics.steps)
}

#[test]
fn a_stiction_velocity_far_below_the_difference_step_runs_in_ordinary_steps() {
    // The block starts by tipping forward on its bottom face with the contact point stuck
    // (friction 0.23 of the normal force against MU_STATIC = 0.3), so the slip stays inside
    // the stiction band |v| < vs. The face contact's partials are differenced; a velocity
    // step of √ε·L = 3e-9 m/s spans a band of 1e-9 and gave Newton a fifth of the slope: it
    // diverged at every step that was not tiny (52,102 steps for the first 0.3 ms).
    let (coarse, coarse_steps) = incline_with_stiction(1e-6);
    let (fine, fine_steps) = incline_with_stiction(1e-9);
    assert!(
        fine_steps < 3 * coarse_steps,
        "{fine_steps} steps at vs = 1e-9 against {coarse_steps} at 1e-6"
    );
    // Columns: time, part, x y z, quaternion, velocity, angular velocity. Within the first 5
    // ms, before the first slip, a band of 1e-6 or 1e-9 leaves the motion the same to 3e-5
    // (at ERROR = 1e-6 the runs differ by 1.5e-3, the integrator's error; at 0.05 s the
    // stick–slip events that follow differ by more between two ERRORs than between two bands).
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let apart =
        |a: &[f64], b: &[f64]| norm(&a.iter().zip(b).map(|(x, y)| x - y).collect::<Vec<_>>());
    for (what, cols) in [("velocity", 9..12), ("angular velocity", 12..15)] {
        let (f, c) = (&fine[cols.clone()], &coarse[cols]);
        assert!(apart(f, c) < 1e-3 * norm(c), "{what}: {f:?} against {c:?}");
    }
}

#[test]
fn an_stl_file_is_checked_against_its_header_before_anything_is_allocated() {
    use contact_core::mesh_file::read_mesh_geometry;
    let dir = scratch("stl");
    // A binary header claiming 4e9 triangles in a file of 84 bytes.
    let mut header = vec![0u8; 80];
    header.extend_from_slice(&u32::MAX.to_le_bytes());
    std::fs::write(dir.join("liar.stl"), &header).unwrap();
    let e = read_mesh_geometry(&dir.join("liar.stl"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("as binary STL its header gives 4294967295 triangles (214748364834 bytes) but the file has 84 bytes"),
        "{e}"
    );
    std::fs::write(dir.join("short.stl"), b"abc").unwrap();
    let e = read_mesh_geometry(&dir.join("short.stl"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("3 bytes, shorter than a binary STL's 84-byte header"),
        "{e}"
    );
    // A device is not read at all (it would never end).
    if Path::new("/dev/zero").exists() {
        std::os::unix::fs::symlink("/dev/zero", dir.join("zero.stl")).unwrap();
        let e = read_mesh_geometry(&dir.join("zero.stl"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("not a regular file"), "{e}");
        std::os::unix::fs::symlink("/dev/zero", dir.join("zero.obj")).unwrap();
        let e = read_mesh_geometry(&dir.join("zero.obj"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("not a regular file"), "{e}");
    }
}

#[test]
fn an_output_directory_that_cannot_be_made_is_named_in_the_error() {
    let dir = scratch("outdir");
    let file = dir.join("a_file");
    std::fs::write(&file, "x").unwrap();
    let args = ball_args(&file.join("out"));
    let (mut stdout, mut stderr) = (Vec::new(), Vec::new());
    let error = contact::cli::run::run(&args, &mut stdout, &mut stderr).unwrap_err();
    assert!(
        error
            .to_string()
            .contains(&file.join("out").display().to_string()),
        "{error}"
    );
}

#[test]
fn an_interrupted_run_ends_at_its_frame_with_whole_records_and_says_so() {
    use std::sync::Arc;
    use std::sync::atomic::AtomicBool;
    // The flag SIGINT/SIGTERM set in `contact run`, set before the run: it ends at its first
    // frame, with that frame written whole and the summary saying "interrupted".
    let dir = scratch("interrupt").join("out");
    let mut files =
        contact::session::ResultFiles::new(&dir).interrupted_by(Arc::new(AtomicBool::new(true)));
    let options = contact::session::RunOptions {
        end: Some(0.1),
        ..Default::default()
    };
    let error = contact::session::run_files(&example("ball/ball.adm"), None, &options, &mut files)
        .unwrap_err();
    let contact::session::RunError::Stopped(report) = error else {
        panic!("{error}")
    };
    assert!(report.interrupted());
    assert_eq!(report.output_frames, 1);
    let parts = std::fs::read_to_string(dir.join("parts.csv")).unwrap();
    assert_eq!(parts.lines().count(), 2, "{parts}");
    assert!(parts.ends_with('\n'));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["status"], "interrupted");
    assert_eq!(summary["analyses"][0]["status"], "interrupted");
    assert!(!dir.join("summary.json.partial").exists());
}

/// `ResultFiles` whose interrupt flag is raised after `after` accepted steps, as a signal
/// arriving mid-run would.
struct SignalAfter {
    files: contact::session::ResultFiles,
    flag: std::sync::Arc<std::sync::atomic::AtomicBool>,
    after: u64,
    last_t: f64,
}

impl contact::session::RunSink for SignalAfter {
    fn start(&mut self, layout: &contact::session::RunLayout<'_>) -> std::io::Result<()> {
        self.files.start(layout)
    }
    fn progress(&mut self, p: &contact::solver::simulate::Progress) {
        if p.steps >= self.after {
            self.flag.store(true, std::sync::atomic::Ordering::Relaxed);
            self.last_t = self.last_t.max(p.t);
        }
    }
    fn stop_requested(&self) -> bool {
        self.files.stop_requested()
    }
    fn frame(&mut self, frame: &contact::solver::simulate::Frame) -> std::io::Result<()> {
        self.files.frame(frame)
    }
    fn finish(&mut self, report: &contact::session::RunReport) -> std::io::Result<()> {
        self.files.finish(report)
    }
}

#[test]
fn an_interrupt_between_output_frames_ends_the_run_at_the_current_step() {
    use std::sync::Arc;
    use std::sync::atomic::AtomicBool;
    // One output step over the whole second: without the per-step check the run would go on
    // to t = 1 after the signal.
    let dir = scratch("interrupt-mid-step").join("out");
    let flag = Arc::new(AtomicBool::new(false));
    let mut sink = SignalAfter {
        files: contact::session::ResultFiles::new(&dir).interrupted_by(flag.clone()),
        flag,
        after: 20,
        last_t: 0.0,
    };
    let options = contact::session::RunOptions {
        end: Some(1.0),
        steps: Some(1),
        ..Default::default()
    };
    let error = contact::session::run_files(&example("ball/ball.adm"), None, &options, &mut sink)
        .unwrap_err();
    let contact::session::RunError::Stopped(report) = error else {
        panic!("{error}")
    };
    assert!(report.interrupted(), "{report:?}");
    assert_eq!(report.output_frames, 2);
    let parts = std::fs::read_to_string(dir.join("parts.csv")).unwrap();
    let times: Vec<f64> = parts
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap().parse().unwrap())
        .collect();
    // The start, then the step the signal arrived at: not the output grid's t = 1.
    assert_eq!(times.len(), 2, "{parts}");
    assert_eq!(times[0], 0.0);
    assert!(times[1] > 0.0 && times[1] < 1.0, "{times:?}");
    assert_eq!(times[1], sink.last_t, "{times:?}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["status"], "interrupted");
}

#[test]
fn a_mass_at_the_floating_point_limit_is_diagnosed_as_such() {
    // No joint: the message must not blame redundant joints, nor claim results it has not.
    let dir = scratch("huge-mass");
    let adm = dir.join("m.adm");
    std::fs::write(
        &adm,
        "t\nUNITS/ SYSTEM = MKS\nPART/1, GROUND\nMARKER/1, PART = 1\nPART/2, MASS = 1E308, CM = 2, IP = 1, 1, 1\nMARKER/2, PART = 2\nACCGRAV/ KGRAV = -9.81\nEND\n",
    )
    .unwrap();
    let mut args = ball_args(&dir.join("out"));
    args.model = adm;
    let (code, _, stderr) = run(&args);
    assert_eq!(code, 1);
    assert!(
        stderr
            .contains("the accelerations at t = 0 are not finite (the model has no joint or JPRIM"),
        "{stderr}"
    );
    assert!(!stderr.contains("duplicated joints"), "{stderr}");
    assert!(stderr.contains("no frame was computed"), "{stderr}");
}

#[test]
fn a_pose_quaternion_that_is_not_unit_is_refused_with_its_line() {
    use contact::cli::query::{POSE_QUATERNION_TOLERANCE, parse_poses};
    // The issue's reproduction: (1e200, 0, 0, 0) was used as is (depth 0.9998 instead of 0.5).
    let (line, reason) = parse_poses("# x y z qw qx qy qz\n0 0 0.5 1e200 0 0 0\n").unwrap_err();
    assert_eq!(line, 2);
    assert!(
        reason.contains("has norm 1e200") && reason.contains("1e-6"),
        "{reason}"
    );
    // Written to 7 significant digits (cos, sin of 0.3 rad about z): within the tolerance.
    let poses = parse_poses("0 0 1 0.9887711 0 0 0.1494381\n").unwrap();
    let q = poses[0].rotation.quaternion();
    assert!((q.norm() - 1.0).abs() < 1e-15);
    assert!((q.k - 0.1494381 / 0.98877110f64.hypot(0.1494381)).abs() < 1e-15);
    // Just past the bound, either way.
    for scale in [
        1.0 + 2.0 * POSE_QUATERNION_TOLERANCE,
        1.0 - 2.0 * POSE_QUATERNION_TOLERANCE,
    ] {
        let text = format!("0 0 0 {scale:?} 0 0 0\n");
        assert_eq!(parse_poses(&text).unwrap_err().0, 1, "{scale}");
    }
}

#[test]
fn a_geometry_spec_with_a_repeated_unknown_or_out_of_range_argument_is_refused() {
    use contact::cli::query::parse_geometry;
    let refused = |spec: &str| parse_geometry(spec, false).unwrap_err().to_string();
    let e = refused("sphere:r=1,r=2");
    assert!(e.contains("r= is given twice"), "{e}");
    let e = refused("sphere:r=1,q=2");
    assert!(
        e.contains("unknown argument q=") && e.contains("takes r"),
        "{e}"
    );
    let e = refused("sphere:r=1e300");
    assert!(e.contains("RADIUS") && e.contains("LENGTH_RANGE"), "{e}");
    let e = refused("box:x=1e-300,y=1,z=1");
    assert!(e.contains("LENGTH_RANGE"), "{e}");
    assert!(parse_geometry("torus:R=1,r=0.3", false).is_ok());
}
