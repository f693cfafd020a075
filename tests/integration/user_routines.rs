//! NORMAL_ROUTINE and FRICTION_ROUTINE: user laws loaded from a shared library built from
//! `examples/user_routines/impact_routine.rs`, and laws registered in code, each run against
//! an independent oracle (the 1-DOF reference, the incline's analytic distance, a linear
//! spring's closed-form contact time) and the built-in laws they restate.

use crate::ball_drop::{RADIUS, reference_apexes};
use contact::dataset::{self, read_str};
use contact::model::Model;
use contact::run::lower::{LoweredModel, lower, lower_with_routines};
use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::Analysis;
use contact::solver::simulate::{DynamicsSettings, simulate};
use contact::user_routines::UserRoutines;
use contact_core::laws::UserContact;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("examples")
}

/// A directory holding the example datasets and `libimpact_routine` built from its source by
/// `rustc` (once per test run), as a user would lay them out.
fn routine_dir() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir =
            std::env::temp_dir().join(format!("contact-user-routines-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let source = examples().join("user_routines");
        for file in ["ball_user.adm", "incline_user.adm"] {
            std::fs::copy(source.join(file), dir.join(file)).unwrap();
        }
        let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
        let status = std::process::Command::new(rustc)
            .args([
                "--edition",
                "2021",
                "--crate-type",
                "cdylib",
                "-C",
                "opt-level=2",
            ])
            .arg(source.join("impact_routine.rs"))
            .arg("--out-dir")
            .arg(&dir)
            .status()
            .expect("rustc runs");
        assert!(
            status.success(),
            "building the example routine library failed"
        );
        dir
    })
}

fn lowered(model: &Model, routines: &UserRoutines) -> Result<LoweredModel, String> {
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
    lower_with_routines(
        model,
        &engine_exact::ExactEngine,
        Analysis::Dynamics,
        &no_meshes,
        routines,
    )
    .map_err(|e| e.to_string())
}

/// `(t, z, vz, x, touching)` of the first moving part at one output frame.
type Sample = (f64, f64, f64, f64, bool);

fn read(path: &Path) -> Model {
    let loaded = dataset::read(path, None).unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    loaded.model
}

/// Runs dynamics to `end` and returns `(t, z, vz, x, touching)` of the first moving part per
/// frame.
fn run(
    lowered: &mut LoweredModel,
    end: f64,
    output_step: f64,
    error: f64,
) -> Result<Vec<Sample>, String> {
    let settings = DynamicsSettings {
        start: 0.0,
        end,
        output_step,
        integrator: IntegratorSettings {
            error,
            ..IntegratorSettings::default()
        },
    };
    let part = lowered.parts[0].0;
    let mut out = Vec::new();
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let s = frame.parts[part.0];
            let p = s.pose_w.translation.vector;
            out.push((
                frame.t,
                p.z,
                s.velocity_w.z,
                p.x,
                !frame.contacts[0].is_empty(),
            ));
            Ok(())
        },
    )
    .map_err(|e| e.to_string())?;
    Ok(out)
}

/// The apex heights after each bounce, from the frames.
fn apexes(frames: &[Sample]) -> Vec<f64> {
    let mut out = Vec::new();
    let mut was_rising = false;
    for &(_, z, v, _, touching) in frames {
        if was_rising && v <= 0.0 && !touching {
            out.push(z + v * v / (2.0 * 9.81));
        }
        was_rising = v > 0.0 && !touching;
    }
    out
}

#[test]
fn a_shared_library_impact_law_bounces_the_ball_as_the_reference_and_the_built_in_law() {
    let model = read(&routine_dir().join("ball_user.adm"));
    let error = model.integrator.error;
    let mut user = lowered(&model, &UserRoutines::default()).unwrap();
    let got = apexes(&run(&mut user, 1.6, 1e-3, error).unwrap());
    let reference = reference_apexes(2);
    assert!(got.len() >= 2, "{got:?}");
    for (g, want) in got.iter().zip(&reference) {
        let relative = (g - want).abs() / (want - RADIUS);
        assert!(relative < 1e-4, "rebound {g} vs the 1-DOF reference {want}");
    }
    let built_in = read(&examples().join("ball/ball.adm"));
    let mut built_in = lowered(&built_in, &UserRoutines::default()).unwrap();
    // A user law has no analytic partials, so its contact is differenced; the built-in law
    // differenced too takes the same Newton iterates.
    built_in
        .system
        .set_force_partials(contact::solver::mbs::ForcePartials::Difference);
    let want = apexes(&run(&mut built_in, 0.9, 1e-3, error).unwrap());
    // The first flight is the same law to round-off; later ones differ by step choices only.
    assert!(
        (got[0] - want[0]).abs() < 1e-9 * (want[0] - RADIUS),
        "first apex {} vs built-in IMPACT {}",
        got[0],
        want[0]
    );
}

#[test]
fn shared_library_normal_and_friction_laws_slide_the_block_the_analytic_distance() {
    let model = read(&routine_dir().join("incline_user.adm"));
    let mut user = lowered(&model, &UserRoutines::default()).unwrap();
    let frames = run(&mut user, 1.0, 0.01, model.integrator.error).unwrap();
    let (t, _, _, x, _) = *frames.last().unwrap();
    let theta = 30f64.to_radians();
    let analytic = 0.5 * 9.81 * (theta.sin() - 0.25 * theta.cos()) * t * t;
    let slid = x - frames[0].3;
    assert!(
        (slid - analytic).abs() < 0.01 * analytic,
        "slid {slid} m, analytic {analytic} m"
    );
    let built_in = read(&examples().join("incline/incline.adm"));
    let mut built_in = lowered(&built_in, &UserRoutines::default()).unwrap();
    let want = run(&mut built_in, 1.0, 0.01, model.integrator.error).unwrap();
    let want_slid = want.last().unwrap().3 - want[0].3;
    assert!(
        (slid - want_slid).abs() < 1e-6 * want_slid,
        "slid {slid} m with the user laws, {want_slid} m with the built-in ones"
    );
}

/// A ball on a registered linear spring `k·δ` (no damping): the contact lasts as long as the
/// closed form of a mass on a spring under gravity says, and the ball returns to the height it
/// fell from.
#[test]
fn a_law_registered_in_code_is_a_linear_spring_with_the_closed_form_contact_time() {
    let text = "\
ball on a linear spring
UNITS/ FORCE = NEWTON, MASS = KILOGRAM, LENGTH = METER, TIME = SECOND
PART/1, GROUND
MARKER/10, PART = 1
PART/2, MASS = 2, CM = 20, IP = 0.008, 0.008, 0.008
MARKER/20, PART = 2, QP = 0, 0, 0.3
GRAPHICS/1, ELLIPSOID, CM = 20, XSCALE = 0.2, YSCALE = 0.2, ZSCALE = 0.2
GRAPHICS/2, PLANE, RM = 10
CONTACT/1, IGEOM = 1, JGEOM = 2, NORMAL_ROUTINE = mine::spring, NORMAL_FUNCTION = USER(5E4)
ACCGRAV/ KGRAV = -9.81
END
";
    let loaded = read_str(text, routine_dir().join("spring.adm"), None);
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let mut routines = UserRoutines::default();
    routines.register_normal("mine::spring", |c: &UserContact<'_>| {
        c.parameters[0] * c.penetration
    });
    let mut model = lowered(&loaded.model, &routines).unwrap();
    let frames = run(&mut model, 0.6, 1e-5, 1e-7).unwrap();
    // Under gravity the ball oscillates about z = r − m·g/k with amplitude
    // A = sqrt((m·g/k)² + (v0/ω)²), v0 = sqrt(2·g·h), and is in contact while above that
    // centre by less than m·g/k: for (π + 2·asin(m·g/(k·A)))/ω.
    let (mass, k, g, h): (f64, f64, f64, f64) = (2.0, 5e4, 9.81, 0.3 - RADIUS);
    let omega = (k / mass).sqrt();
    let sag = mass * g / k;
    let amplitude = (sag * sag + 2.0 * g * h / (omega * omega)).sqrt();
    let contact_time = (std::f64::consts::PI + 2.0 * (sag / amplitude).asin()) / omega;
    // The first contact's start and end, interpolated where z crosses the radius.
    let crossing = |a: &Sample, b: &Sample| a.0 + (RADIUS - a.1) / (b.1 - a.1) * (b.0 - a.0);
    let mut times = Vec::new();
    for w in frames.windows(2) {
        if (w[0].1 - RADIUS) * (w[1].1 - RADIUS) < 0.0 {
            times.push(crossing(&w[0], &w[1]));
        }
    }
    assert!(times.len() >= 2, "{times:?}");
    let duration = times[1] - times[0];
    assert!(
        (duration - contact_time).abs() < 1e-4 * contact_time,
        "contact lasted {duration}, the closed form says {contact_time}"
    );
    let apex = apexes(&frames)[0];
    assert!(
        (apex - 0.3).abs() < 1e-4 * (0.3 - RADIUS),
        "rebounded to {apex} from 0.3"
    );
}

#[test]
fn missing_libraries_functions_and_failing_routines_are_errors_naming_them() {
    let dir = routine_dir();
    let ball = std::fs::read_to_string(dir.join("ball_user.adm")).unwrap();
    let with = |routine: &str| ball.replace("impact_routine::impact_force", routine);

    let loaded = read_str(&with("no_such_library::f"), dir.join("a.adm"), None);
    let err = lowered(&loaded.model, &UserRoutines::default()).unwrap_err();
    assert!(err.contains("a.adm:19:1: error: CONTACT/1"), "{err}");
    assert!(err.contains("libno_such_library"), "{err}");
    // `contact check` reports it at the CONTACT statement too.
    let checked = contact::cli::check::check_contacts(&loaded.model, &engine_exact::ExactEngine);
    assert!(
        checked
            .iter()
            .any(|d| d.to_string().contains("cannot load the library")),
        "{checked:?}"
    );

    let loaded = read_str(
        &with("impact_routine::no_such_function"),
        dir.join("b.adm"),
        None,
    );
    let err = lowered(&loaded.model, &UserRoutines::default()).unwrap_err();
    assert!(
        err.contains("has no function \"no_such_function\""),
        "{err}"
    );

    let loaded = read_str(
        &with("impact_routine::failing_force"),
        dir.join("c.adm"),
        None,
    );
    let mut failing = lowered(&loaded.model, &UserRoutines::default()).unwrap();
    let err = run(&mut failing, 1.0, 1e-3, 1e-6).unwrap_err();
    assert!(
        err.contains("CONTACT/1") && err.contains("impact_routine::failing_force"),
        "{err}"
    );
    assert!(err.contains("error code 7"), "{err}");

    // Plain `lower` resolves shared libraries the same way.
    let loaded = read_str(&ball, dir.join("d.adm"), None);
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes".to_string());
    assert!(
        lower(
            &loaded.model,
            &engine_exact::ExactEngine,
            Analysis::Dynamics,
            &no_meshes
        )
        .is_ok()
    );
}
