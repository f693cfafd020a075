//! The net force and torque at a marker (`FX(i, j, k)` … `TM(i, j)`), `MOTION(id, …)` and FORCE
//! requests against the closed form of a driven slider: a part of mass `m` on a TRANSLATIONAL
//! joint along the world x axis, its CM on the joint's I marker, driven by a MOTION
//! `x = A sin ωt`, pushed by an action-only SFORCE of `P` along x, under gravity `g` along −z.
//! Newton's law with the motion prescribed: the joint carries `m·g` up, the MOTION
//! `m·ẍ − P` along x (`ẍ = −A ω² sin ωt`), no element carries a torque about the CM, and the net
//! force between the joint's markers is `(m·ẍ, 0, m·g)`.

use contact_adams::session::{ResultFiles, RunOptions, run_files};
use std::f64::consts::PI;
use std::path::PathBuf;

const M: f64 = 2.0;
const G: f64 = 9.81;
const A: f64 = 0.1;
const OMEGA: f64 = 2.0 * PI;
const P: f64 = 5.0;

/// Marker 11 (ground) and 21 (the slider's CM) have their z along world x; marker 12 is the
/// ground's axes turned 90° about z (its x is world y, its y world −x).
const SLIDER: &str = "\
Driven slider
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND
ACCGRAV/ KGRAV = -9.81
PART/1, GROUND
MARKER/11, PART = 1, REULER = 90D, 90D, 0D
MARKER/12, PART = 1, REULER = 90D, 0D, 0D
PART/2, MASS = 2, CM = 20, IP = 0.01, 0.02, 0.03
MARKER/20, PART = 2
MARKER/21, PART = 2, REULER = 90D, 90D, 0D
JOINT/1, TRANSLATIONAL, I = 21, J = 11
MOTION/1, JOINT = 1, TRANSLATION, FUNCTION = 0.1 * SIN(2 * PI * TIME)
SFORCE/1, TRANSLATIONAL, ACTIONONLY, I = 21, J = 11, FUNCTION = 5
VARIABLE/1, FUNCTION = FZ(21, 11)
REQUEST/1, F2 = MOTION(1, 0, 2, 0)\\F3 = JOINT(1, 0, 4, 0)\\F4 = FX(21, 11)\\F6 = FZ(21, 11)\\F7 = FM(21)\\F8 = FY(21, 11, 12)
REQUEST/2, FORCE, I = 21, J = 11
REQUEST/3, FORCE, I = 21
REQUEST/4, F2 = VARVAL(1)\\F3 = TM(21, 11)\\F4 = MOTION(1, 1, 2, 0)\\F6 = FX(11, 21)
END
";

const ACF: &str = "\
slider.adm
out
integrator/ error = 1e-8
simulate/dynamics, end = 1.0, dtout = 0.01
stop
";

/// Runs the slider into result files; `requests.csv`.
fn requests_csv() -> String {
    let dir: PathBuf = std::env::temp_dir().join(format!("force_measures_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (adm, acf) = (dir.join("slider.adm"), dir.join("slider.acf"));
    std::fs::write(&adm, SLIDER).unwrap();
    std::fs::write(&acf, ACF).unwrap();
    let out = dir.join("out");
    let mut sink = ResultFiles::new(&out);
    run_files(&adm, Some(&acf), &RunOptions::default(), &mut sink).unwrap();
    std::fs::read_to_string(out.join("requests.csv")).unwrap()
}

/// The rows of `requests.csv` for request `id`: time and the six columns.
fn rows(csv: &str, id: &str) -> Vec<(f64, [f64; 6])> {
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

#[test]
fn marker_force_measures_and_motion_reactions_follow_newtons_law() {
    let csv = requests_csv();
    let tolerance = 1e-8 * M * G;
    let close = |got: f64, want: f64, what: &str, t: f64| {
        assert!(
            (got - want).abs() <= tolerance,
            "t = {t}: {what} = {got}, closed form {want}"
        );
    };
    let [r1, r2, r3, r4] = ["1", "2", "3", "4"].map(|id| rows(&csv, id));
    assert_eq!([r1.len(), r2.len(), r3.len(), r4.len()], [101; 4]);
    for k in 0..101 {
        let t = r1[k].0;
        let accel = -A * OMEGA * OMEGA * (OMEGA * t).sin();
        let (drive, support) = (M * accel, M * G);
        let c = r1[k].1;
        close(c[0], drive - P, "MOTION(1,0,2,0)", t);
        close(c[1], support, "JOINT(1,0,4,0)", t);
        close(c[2], drive, "FX(21,11)", t);
        close(c[3], support, "FZ(21,11)", t);
        close(c[4], drive.hypot(support), "FM(21)", t);
        close(c[5], -drive, "FY(21,11,12)", t);
        let f = r2[k].1;
        for (got, want) in f.iter().zip([drive, 0.0, support, 0.0, 0.0, 0.0]) {
            close(*got, want, "FORCE I=21 J=11", t);
        }
        let f = r3[k].1;
        for (got, want) in f.iter().zip([P, 0.0, 0.0, 0.0, 0.0, 0.0]) {
            close(*got, want, "FORCE I=21 (action-only)", t);
        }
        let c = r4[k].1;
        close(c[0], support, "VARVAL(1) = FZ(21,11)", t);
        close(c[1], 0.0, "TM(21,11)", t);
        close(c[2], -(drive - P), "MOTION(1,1,2,0)", t);
        // At the ground's marker: the joint's and the motion's reactions on J; the action-only
        // SFORCE applies nothing there.
        close(c[3], -(drive - P), "FX(11,21)", t);
    }
}
