//! The integrator against Adams' own output and the closed form, on the Adams test model
//! `Revolute_Case02` (`tests/data/adams-tests/`, copied from the shared datasets): a compound pendulum on a REVOLUTE
//! joint at (1, 2, 3) with axis (0, 1, 1)/√2, CM 2 m from the axis, m = 1 kg, I_zz = 0.1 kg·m²
//! about the axis through the CM, released at rest with the arm horizontal (90° from the
//! bottom of its swing plane), g = 9.80665 m/s² along −Z.
//!
//! Oracles, written apart from the solver:
//! - Adams' `.req` (REQUEST/01, the CM's x y z every 0.01 s, 6 significant digits);
//! - the exact period of a pendulum of amplitude θ₀, `T = 4·sqrt(I_p/(m·g⊥·L))·K(sin(θ₀/2))`
//!   with `K` from the arithmetic-geometric mean, `I_p = I_zz + m·L²` and `g⊥ = g/√2` the part
//!   of gravity in the swing plane;
//! - the energy `½·I_p·(ω·a)² + m·g·z`, which is conserved (no friction, no damping).

use contact_adams::session::{RunOptions, RunSink, run_files};
use contact_solver::simulate::Frame;
use nalgebra::Vector3;
use std::f64::consts::{FRAC_1_SQRT_2, PI};
use std::path::{Path, PathBuf};

const G: f64 = 9.80665;
const MASS: f64 = 1.0;
const ARM: f64 = 2.0;
const I_AXIS: f64 = 0.1;

/// The case's folder: a copy of the shared dataset in tests/data (see its PROVENANCE.md).
fn case_dir() -> PathBuf {
    let dir =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/adams-tests/Revolute_Case02");
    assert!(
        dir.is_dir(),
        "{} is missing: the Adams test models are kept in tests/data/adams-tests",
        dir.display()
    );
    dir
}

/// Adams' REQUEST/01 (CM position) at every output time, from the `.req` file's layout
/// (header, two lines per request, then a time line and one line per request per frame).
fn adams_positions() -> Vec<(f64, Vector3<f64>)> {
    let text = std::fs::read_to_string(case_dir().join("test_Revolute_Case02_ADAMS.req"))
        .expect("the .req file reads");
    let lines: Vec<&str> = text.lines().collect();
    let requests: usize = lines[2].split_whitespace().next().unwrap().parse().unwrap();
    let numbers = |line: &str| -> Vec<f64> {
        line.split_whitespace()
            .map(|w| w.parse::<f64>().unwrap())
            .collect()
    };
    let mut frames = Vec::new();
    let mut at = 3 + 2 * requests;
    while at + requests < lines.len() + 1 && at < lines.len() {
        let t = numbers(lines[at])[0];
        let d = numbers(lines[at + 1]);
        frames.push((t, Vector3::new(d[0], d[1], d[2])));
        at += requests + 1;
    }
    assert_eq!(frames.len(), 501, "the .req holds 501 frames");
    frames
}

/// The complete elliptic integral of the first kind `K(k) = π / (2·AGM(1, sqrt(1 − k²)))`.
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    // Quadratic convergence: 10 rounds reach round-off from any k < 1 - 1e-100.
    for _ in 0..10 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

/// The exact period of the case's pendulum (amplitude 90°).
fn exact_period() -> f64 {
    let i_pivot = I_AXIS + MASS * ARM * ARM;
    let g_plane = G * FRAC_1_SQRT_2;
    4.0 * (i_pivot / (MASS * g_plane * ARM)).sqrt() * elliptic_k((PI / 4.0).sin())
}

/// Collects every output frame.
struct Frames(Vec<Frame>);

impl RunSink for Frames {
    fn frame(&mut self, frame: &Frame) -> std::io::Result<()> {
        self.0.push(frame.clone());
        Ok(())
    }
}

/// What one run of the case gave, measured against the oracles.
#[derive(Debug)]
struct Accuracy {
    /// Largest distance of the CM from Adams' over the 501 frames (m).
    from_adams: f64,
    /// Largest |E − E₀| over the frames, in units of m·g·L.
    energy: f64,
    /// Largest |t_crossing − t_exact| of the arm through the bottom of its swing (s).
    crossings: f64,
    /// Accepted integrator steps.
    steps: u64,
}

/// Runs the case for 5 s with output every 0.01 s, GSTIFF, the given ERROR and HMAX.
fn run(error: f64, hmax: Option<f64>) -> Accuracy {
    let dir = case_dir();
    let hmax = hmax.map(|h| format!(", hmax = {h:e}")).unwrap_or_default();
    let acf = format!(
        "test_Revolute_Case02.adm\nout\nintegrator/gstiff, error = {error:e}{hmax}\n\
         simulate/transient, end = 5.0, dtout = 1.0E-002\nstop\n"
    );
    let acf_path = std::env::temp_dir().join(format!(
        "integrator_accuracy_{}_{error:e}{hmax}.acf",
        std::process::id()
    ));
    std::fs::write(&acf_path, acf).unwrap();
    let mut frames = Frames(Vec::new());
    let report = run_files(
        &dir.join("test_Revolute_Case02.adm"),
        Some(&acf_path),
        &RunOptions::default(),
        &mut frames,
    )
    .expect("the case runs");
    std::fs::remove_file(&acf_path).ok();
    let frames = frames.0;
    let adams = adams_positions();
    assert_eq!(frames.len(), adams.len());
    let pivot = Vector3::new(1.0, 2.0, 3.0);
    let axis = Vector3::new(0.0, FRAC_1_SQRT_2, FRAC_1_SQRT_2);
    let i_pivot = I_AXIS + MASS * ARM * ARM;
    let energy = |f: &Frame| {
        let part = &f.parts[1];
        let w = part.angular_velocity_w.dot(&axis);
        0.5 * i_pivot * w * w + MASS * G * part.pose_w.translation.vector.z
    };
    let e0 = energy(&frames[0]);
    let mut accuracy = Accuracy {
        from_adams: 0.0,
        energy: 0.0,
        crossings: 0.0,
        steps: report.dynamics.steps,
    };
    for (f, (t, r)) in frames.iter().zip(&adams) {
        assert!((f.t - t).abs() < 1e-9, "frame times {} {t}", f.t);
        let x = f.parts[1].pose_w.translation.vector;
        accuracy.from_adams = accuracy.from_adams.max((x - r).norm());
        accuracy.energy = accuracy
            .energy
            .max((energy(f) - e0).abs() / (MASS * G * ARM));
    }
    // The arm passes the bottom when its x offset from the pivot changes sign, at
    // T/4 + n·T/2; cubic Hermite between frames (x and ẋ) locates each crossing.
    let period = exact_period();
    let mut n = 0;
    for w in frames.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        let (xa, xb) = (
            a.parts[1].pose_w.translation.x - pivot.x,
            b.parts[1].pose_w.translation.x - pivot.x,
        );
        if xa == 0.0 || xa.signum() == xb.signum() {
            continue;
        }
        let dt = b.t - a.t;
        let (va, vb) = (a.parts[1].velocity_w.x * dt, b.parts[1].velocity_w.x * dt);
        let hermite = |s: f64| {
            let (s2, s3) = (s * s, s * s * s);
            (2.0 * s3 - 3.0 * s2 + 1.0) * xa
                + (s3 - 2.0 * s2 + s) * va
                + (-2.0 * s3 + 3.0 * s2) * xb
                + (s3 - s2) * vb
        };
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if hermite(mid).signum() == xa.signum() {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let crossing = a.t + 0.5 * (lo + hi) * dt;
        let exact = period / 4.0 + n as f64 * period / 2.0;
        accuracy.crossings = accuracy.crossings.max((crossing - exact).abs());
        n += 1;
    }
    assert!(n >= 2, "only {n} crossings in 5 s (period {period} s)");
    eprintln!("ERROR = {error:e}{hmax}: {accuracy:?}");
    accuracy
}

/// The `.req` holds 6 significant digits: a coordinate in [1, 10) is rounded by up to 5e-6 m,
/// so two runs closer to the truth than this cannot be ranked by their distance from Adams.
const REQ_ROUNDING: f64 = 5e-6 * 1.732_050_807_568_877_2;

/// Tightening ERROR 1e-3 → 1e-6 makes every measure of the error fall.
#[test]
fn tighter_error_is_more_accurate() {
    let runs: Vec<Accuracy> = [1e-3, 1e-4, 1e-5, 1e-6]
        .into_iter()
        .map(|e| run(e, None))
        .collect();
    for w in runs.windows(2) {
        assert!(
            w[1].from_adams < w[0].from_adams,
            "{:?} then {:?}",
            w[0],
            w[1]
        );
        assert!(w[1].energy < w[0].energy, "{:?} then {:?}", w[0], w[1]);
        assert!(w[1].steps > w[0].steps, "{:?} then {:?}", w[0], w[1]);
    }
}

/// A smaller HMAX never makes the run less accurate (ERROR = 1e-4): the distance from Adams
/// falls or stays within the `.req`'s rounding, the crossing times approach the exact ones.
#[test]
fn smaller_hmax_is_never_less_accurate() {
    let runs: Vec<Accuracy> = [None, Some(1e-2), Some(1e-3), Some(1e-4)]
        .into_iter()
        .map(|h| run(1e-4, h))
        .collect();
    for w in runs.windows(2) {
        assert!(
            w[1].from_adams <= w[0].from_adams.max(REQ_ROUNDING),
            "{:?} then {:?}",
            w[0],
            w[1]
        );
        assert!(
            w[1].crossings < w[0].crossings,
            "{:?} then {:?}",
            w[0],
            w[1]
        );
    }
}

/// The case at its own settings (GSTIFF, ERROR = 1e-4, HMAX = 1e-5, 5 s): energy conserved
/// to 1e-5·mgL, positions within Adams' rounding plus 1e-6 of the arm, the crossings of the
/// bottom within 1e-6 s of the elliptic-integral times.
#[test]
fn pendulum_at_the_dataset_settings() {
    let a = run(1e-4, Some(1e-5));
    assert!(a.energy < 1e-5, "{a:?}");
    assert!(a.from_adams < REQ_ROUNDING + 1e-6 * ARM, "{a:?}");
    assert!(a.crossings < 1e-6, "{a:?}");
}
