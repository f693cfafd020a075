//! Every contact example run with the exact and with the faceted engine: the quantities each
//! example's own physics test checks agree within a bound derived from the faceting tolerance.
//!
//! The faceting bound (SPEC §7): every facet or chord of a tessellated primitive lies within
//! `d = L/FT` of the true surface, `L` the geometry's bounding-box diagonal. Flat faces (a
//! box's, a cylinder's ends) are tessellated exactly, and the ground PLANE stays exact in both
//! engines. Each test states how a surface displaced by at most `d` moves its quantity.

use contact::dataset;
use contact::model::{Model, Shape};
use contact::run::lower::{LoweredModel, lower};
use contact::session::{ResultFiles, RunOptions, run_files};
use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::{Analysis, ContactReport};
use contact::solver::frame::compute_frame;
use contact::solver::simulate::Frame;
use contact::solver::simulate::{DynamicsSettings, simulate};
use contact_core::{FacetingTolerance, GeometryEngine, GeometryLibrary};
use engine_facet::FacetEngine;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

type Vector3 = nalgebra::Vector3<f64>;
/// A lowered model's `(solver part, Adams PART id)`.
type PartIds = (contact::solver::mbs::PartId, u32);

/// Adams' default faceting tolerance.
const DEFAULT_FT: f64 = 300.0028;
const G: f64 = 9.81;

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(name)
}

/// `examples/<dir>/<file>` (and its command file when given), read without errors.
fn load(dir: &str, file: &str, commands: Option<&str>) -> Model {
    let dir = example(dir);
    let acf = commands.map(|c| dir.join(c));
    let loaded = dataset::read(&dir.join(file), acf.as_deref()).unwrap();
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    loaded.model
}

fn faceted(ft: f64) -> FacetEngine {
    FacetEngine::new(FacetingTolerance::new(ft).unwrap())
}

/// The chord deviation `L/FT` of GRAPHICS/`id` in `model`.
fn chord_deviation(model: &Model, id: u32, ft: f64) -> f64 {
    let Shape::Geometry(instance) = &model.graphics[&id].shape else {
        panic!("GRAPHICS/{id} is not a native geometry")
    };
    let length = instance.geometry.characteristic_length().unwrap();
    FacetingTolerance::new(ft).unwrap().chord_deviation(length)
}

/// The model lowered for dynamics onto `engine` (the examples have no meshes).
fn lowered(model: &Model, engine: &dyn GeometryEngine) -> LoweredModel {
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
    lower(model, engine, Analysis::Dynamics, &no_meshes)
        .unwrap_or_else(|e| panic!("{}: {e}", engine.name()))
}

/// Runs `model` with `engine` from 0 to `end`, a frame every `output_step`, at the model's
/// integrator ERROR, handing each frame and the lowered model's part ids to `each`.
fn run(
    model: &Model,
    engine: &dyn GeometryEngine,
    end: f64,
    output_step: f64,
    each: &mut dyn FnMut(&Frame, &[PartIds]),
) {
    let mut lowered = lowered(model, engine);
    let settings = DynamicsSettings {
        start: 0.0,
        end,
        output_step,
        integrator: IntegratorSettings {
            error: model.integrator.error,
            ..IntegratorSettings::default()
        },
    };
    let parts = lowered.parts.clone();
    simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            each(frame, &parts);
            Ok(())
        },
    )
    .unwrap_or_else(|e| panic!("{} stalled: {e}", engine.name()));
}

/// The ball's centre apex after each bounce: ballistic, `z + v²/2g` at the first frame free of
/// contact and rising after one falling (a bounce may fall between frames).
fn ball_apexes(model: &Model, engine: &dyn GeometryEngine, end: f64) -> Vec<f64> {
    let (mut apexes, mut was_falling) = (Vec::new(), false);
    run(model, engine, end, 1e-3, &mut |frame, parts| {
        let s = frame.parts[parts[0].0.0];
        let (z, v) = (s.pose_w.translation.z, s.velocity_w.z);
        if was_falling && v > 0.0 && frame.contacts[0].is_empty() {
            apexes.push(z + v * v / (2.0 * G));
            was_falling = false;
        }
        was_falling |= v < 0.0;
    });
    apexes
}

/// The POISSON ball example with restitution `eps`.
fn poisson_ball(eps: f64) -> Model {
    let mut model = load("ball_poisson", "ball_poisson.adm", None);
    let args = contact_core::ContactArgs {
        poisson: true,
        penalty: Some(1e6),
        restitution_coefficient: Some(eps),
        ..Default::default()
    };
    model.contacts[0].params = args.validate(&model.units).unwrap().0;
    model
}

/// The ball bound. The ball does not turn (its contact force passes within a facet of its
/// centre), so the faceted penetration is the true one less a constant `c`, `|c| ≤ d` (how far
/// the tessellation's lowest point lies inside or outside the sphere): the faceted run is the
/// exact run of a ball of radius `r − c` under the same force law of the same penetration. It
/// falls `H + c` (`H` the true lowest point's drop) and rises `ε^(2n)·(H + c)` after bounce
/// `n`, so its centre apex differs from the exact one by `c·(1 − ε^(2n))`: at most `d`, the
/// sphere's (GRAPHICS/1) chord deviation.
fn assert_ball_apexes_agree(model: &Model, end: f64, bounces: usize, fts: &[f64]) {
    let exact = ball_apexes(model, &engine_exact::ExactEngine, end);
    assert!(exact.len() >= bounces, "exact apexes {exact:?}");
    for &ft in fts {
        let facet = ball_apexes(model, &faceted(ft), end);
        let d = chord_deviation(model, 1, ft);
        assert!(facet.len() >= bounces, "FT {ft}: faceted apexes {facet:?}");
        for (n, (f, e)) in facet.iter().zip(&exact).take(bounces).enumerate() {
            assert!(
                (f - e).abs() <= d,
                "FT {ft}, bounce {}: faceted apex {f}, exact {e}, differ by {:e} > d = {d:e}",
                n + 1,
                (f - e).abs()
            );
        }
    }
    // Real rebounds: the first rises well clear of the plane (the lowest point 0.1 below).
    assert!(exact[0] > 0.1 + 0.3, "{exact:?}");
}

#[test]
fn the_poisson_ball_rebounds_as_the_exact_one_within_the_chord_deviation() {
    // Two bounces: on the plane at 0.45 s and 0.99 s, clear of it again by 1.05 s.
    assert_ball_apexes_agree(&poisson_ball(0.6), 1.05, 2, &[DEFAULT_FT, 1000.0]);
}

#[test]
fn the_elastic_poisson_ball_rebounds_as_the_exact_one_within_the_chord_deviation() {
    // Three bounces: on the plane at 0.45, 1.35 and 2.26 s.
    assert_ball_apexes_agree(&poisson_ball(1.0), 2.3, 3, &[DEFAULT_FT, 1000.0]);
}

#[test]
fn the_augmented_poisson_ball_rebounds_as_the_exact_one_within_the_chord_deviation() {
    // The example's ball started 1 mm above the plane at the speed of its 1 m drop (the
    // augmented contact is the costly part of the run; the flight is ballistic). The bound's
    // argument holds for any drop height H. The default FT only: in the debug profile the
    // faceted augmented bounce takes about 30 s at FT 300 and 50 s at FT 1000.
    let mut model = load("ball_poisson_al", "ball_poisson_al.adm", None);
    let part = model.parts.get_mut(&2).unwrap();
    // The part frame is at the ground origin, its CM marker 1.1 above it.
    part.pose_world_part.translation.vector.z += 0.1 + 1e-3 - 1.1;
    part.velocity_w.z = -(2.0 * G * (1.0 - 1e-3)).sqrt();
    assert_ball_apexes_agree(&model, 0.02, 1, &[DEFAULT_FT]);
}

/// The first moving part's CM position at every frame.
fn cm_track(model: &Model, engine: &dyn GeometryEngine, end: f64, step: f64) -> Vec<Vector3> {
    let mut out = Vec::new();
    run(model, engine, end, step, &mut |frame, parts| {
        out.push(frame.parts[parts[0].0.0].pose_w.translation.vector);
    });
    out
}

/// The contact reports of CONTACT/1 at the model's initial state with `engine`.
fn initial_contacts(model: &Model, engine: &dyn GeometryEngine) -> Vec<ContactReport> {
    let lowered = lowered(model, engine);
    let y = lowered.system.given_state().clone();
    compute_frame(&lowered.system, &lowered.contacts, 0.0, &y)
        .unwrap()
        .contacts[0]
        .clone()
}

#[test]
fn the_incline_block_slides_as_the_exact_one() {
    // The bound. A box's faces are flat, so its tessellation is the box itself at every FT,
    // and the plane is exact in both engines: the contact answers agree to round-off (checked
    // at the start). Round-off can still steer the step-size control differently, so the runs
    // are two solutions of the same equations each held to the integrator's ERROR per step;
    // the positions may differ by ERROR (in the model's length unit), no more.
    let model = load("incline", "incline.adm", None);
    let (exact, facet) = (
        initial_contacts(&model, &engine_exact::ExactEngine),
        initial_contacts(&model, &faceted(DEFAULT_FT)),
    );
    assert_eq!((exact.len(), facet.len()), (1, 1));
    let (e, f) = (exact[0], facet[0]);
    let length = 0.2 * 3f64.sqrt();
    assert!((e.contact.point_i_w - f.contact.point_i_w).norm() < 1e-12 * length);
    assert!((e.contact.normal_w - f.contact.normal_w).norm() < 1e-12);
    assert!((e.contact.penetration - f.contact.penetration).abs() < 1e-12 * length);
    assert!((e.contact.area - f.contact.area).abs() < 1e-12 * e.contact.area);
    assert!((e.normal_force - f.normal_force).abs() < 1e-9 * e.normal_force);

    let error = model.integrator.error;
    let exact = cm_track(&model, &engine_exact::ExactEngine, 1.0, 0.01);
    let facet = cm_track(&model, &faceted(DEFAULT_FT), 1.0, 0.01);
    assert_eq!(exact.len(), facet.len());
    for (k, (e, f)) in exact.iter().zip(&facet).enumerate() {
        assert!(
            (e - f).norm() <= error,
            "t = {}: exact CM {e:?}, faceted {f:?}, {:e} apart > ERROR {error:e}",
            k as f64 * 0.01,
            (e - f).norm()
        );
    }
    // The quantity the example checks: the distance slid in 1 s, about 1.39 m.
    let slid = |track: &[Vector3]| track[track.len() - 1].x - track[0].x;
    assert!(slid(&exact) > 1.3, "{}", slid(&exact));
    assert!((slid(&exact) - slid(&facet)).abs() <= error);
}

/// The spinning disk's stop time (ω below `stopped_below`, interpolated between frames: ω
/// falls linearly while the rim slips at μd) and the contact area it saw.
fn disk_stop(model: &Model, engine: &dyn GeometryEngine, stopped_below: f64) -> (f64, f64) {
    let (mut stop, mut area, mut last) = (None, 0.0, (0.0, f64::INFINITY));
    run(model, engine, 0.6, 1e-3, &mut |frame, parts| {
        let w = frame.parts[parts[0].0.0].angular_velocity_w.z;
        if let Some(c) = frame.contacts[0].first() {
            area = c.contact.area;
        }
        if stop.is_none() && w < stopped_below {
            let (t0, w0) = last;
            stop = Some(t0 + (frame.t - t0) * (w0 - stopped_below) / (w0 - w));
        }
        last = (frame.t, w);
    });
    (stop.expect("the disk stops within the run"), area)
}

#[test]
fn the_spinning_disk_stops_as_the_exact_one_within_the_chord_deviation() {
    // The bound. The disk's flat face is exact; its rim is a polygon inscribed in the circle of
    // radius r and, every edge within d of the circle, containing the circle of radius r − d:
    // the contact area A lies in [π(r − d)², πr²] and the friction torque's radius
    // R = √(A/π) in [r − d, r]. The torque (2/3)·R·μd·m·g is constant while the rim slips, so
    // the stop time is ω0·I/((2/3)·R·μd·m·g) ∝ 1/R: the faceted disk stops later, by at most
    // the factor r/(r − d). (The stop threshold is 2e-3/r rad/s, where the rim's speed leaves
    // μd: a change of R moves it by d/r of 0.02 rad/s, under 1e-5 s at 26 rad/s².)
    let model = load("spinning_disk", "spinning_disk.adm", None);
    let r = 0.1;
    let stopped_below = 2e-3 / r;
    let (exact, exact_area) = disk_stop(&model, &engine_exact::ExactEngine, stopped_below);
    assert!((exact_area - PI * r * r).abs() < 1e-12, "{exact_area}");
    for ft in [DEFAULT_FT, 1000.0] {
        let d = chord_deviation(&model, 1, ft);
        let (facet, area) = disk_stop(&model, &faceted(ft), stopped_below);
        assert!(
            (PI * (r - d).powi(2)..=PI * r * r).contains(&area),
            "FT {ft}: faceted area {area}, outside [π(r − d)², πr²] with d = {d:e}"
        );
        let later = facet - exact;
        assert!(
            (0.0..=exact * d / (r - d)).contains(&later),
            "FT {ft}: faceted disk stops at {facet} s, exact at {exact} s: {later:e} s later, \
             bound [0, {:e}]",
            exact * d / (r - d)
        );
    }
}

/// One cam frame: the follower's height, the contact normal, the penetration.
struct CamFrame {
    lift: f64,
    normal: Vector3,
    penetration: f64,
}

fn cam_frames(model: &Model, engine: &dyn GeometryEngine) -> Vec<CamFrame> {
    let mut out = Vec::new();
    run(model, engine, 1.0, 0.005, &mut |frame, parts| {
        let contact = frame.contacts[0]
            .first()
            .unwrap_or_else(|| panic!("{}: the roller left the cam at {}", engine.name(), frame.t));
        out.push(CamFrame {
            lift: frame.parts[parts[1].0.0].pose_w.translation.y,
            normal: contact.contact.normal_w,
            penetration: contact.contact.penetration,
        });
    });
    out
}

#[test]
fn the_cam_follower_lifts_as_the_exact_one_within_the_chord_deviation() {
    // The bound. The faceted engine answers on polylines within d_cam of the profile and
    // d_roller of the roller, so the rigid contact of the faceted shapes sits at most
    // d_cam + d_roller from the true one along the contact normal; the follower, which moves
    // along y, is moved by that over cos φ (φ the pressure angle, the normal's angle from y,
    // taken from the exact run). Each run's roller then sinks its own penetration δ ≥ 0
    // (again over cos φ) below its rigid contact, so the two lifts differ by at most
    // (d_cam + d_roller + max(δ_exact, δ_faceted)) / cos φ.
    let model = load("cam_follower", "cam_follower.adm", Some("cam_follower.acf"));
    let exact = cam_frames(&model, &engine_exact::ExactEngine);
    assert_eq!(exact.len(), 201);
    let lifts = exact.iter().map(|f| f.lift);
    let rise = lifts.clone().fold(f64::MIN, f64::max) - lifts.fold(f64::MAX, f64::min);
    assert!(rise > 0.019, "the follower rises {rise}");
    for ft in [DEFAULT_FT, 1000.0] {
        let chords = chord_deviation(&model, 1, ft) + chord_deviation(&model, 2, ft);
        let facet = cam_frames(&model, &faceted(ft));
        assert_eq!(facet.len(), exact.len());
        for (k, (e, f)) in exact.iter().zip(&facet).enumerate() {
            let cos_phi = e.normal.y.abs();
            let bound = (chords + e.penetration.max(f.penetration)) / cos_phi;
            assert!(
                (e.lift - f.lift).abs() <= bound,
                "FT {ft}, t = {}: faceted follower at {}, exact {}, {:e} apart > {bound:e}",
                k as f64 * 0.005,
                f.lift,
                e.lift,
                (e.lift - f.lift).abs()
            );
        }
    }
}

/// The box_rest example (statics, then 0.5 s of dynamics) run with `engine`, its results
/// written as `contact run` writes them: the rows of parts.csv and contacts.csv (numbers only,
/// the first columns dropped).
fn box_rest_run(engine: GeometryLibrary) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let out = std::env::temp_dir().join(format!(
        "contact-cross-{}-{}",
        engine.name(),
        std::process::id()
    ));
    std::fs::remove_dir_all(&out).ok();
    let options = RunOptions {
        engine: Some(engine),
        faceting_tolerance: Some(FacetingTolerance::new(DEFAULT_FT).unwrap()),
        ..RunOptions::default()
    };
    run_files(
        &example("box_rest/box_rest.adm"),
        Some(&example("box_rest/box_rest.acf")),
        &options,
        &mut ResultFiles::new(&out),
    )
    .unwrap();
    let rows = |file: &str, skip: usize| -> Vec<Vec<f64>> {
        std::fs::read_to_string(out.join(file))
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
    };
    let found = (rows("parts.csv", 0), rows("contacts.csv", 5));
    std::fs::remove_dir_all(&out).ok();
    found
}

#[test]
fn the_box_rest_example_rests_as_the_exact_one() {
    // The bound. The box's faces are flat (its tessellation is the box) and the plane is exact
    // in both engines, so both solve the same equilibrium equations, each to the dataset's
    // EQUILIBRIUM/ ERROR = 1e-10 (positions) and IMBALANCE = 1e-9 (forces): the resting states
    // agree within 2·ERROR and the contact forces within 2·IMBALANCE. The penetration is the
    // box's height deficit, so it agrees within 2·ERROR too. The dynamics then start at rest
    // in equilibrium and stay there in both.
    let (error, imbalance) = (1e-10, 1e-9);
    let (exact_parts, exact_contacts) = box_rest_run(GeometryLibrary::Exact);
    let (facet_parts, facet_contacts) = box_rest_run(GeometryLibrary::Faceted);
    assert_eq!(
        exact_parts.len(),
        51,
        "the statics frame, then 50 dynamics frames"
    );
    assert_eq!(facet_parts.len(), exact_parts.len());
    // contacts.csv after its first 5 columns: points (6), normal (3), penetration,
    // penetration rate, normal force, …
    let (penetration, force) = (9, 11);
    let (e, f) = (&exact_contacts[0], &facet_contacts[0]);
    let resting = (9.81 / 1e6_f64).powf(1.0 / 1.5);
    assert!((e[penetration] - resting).abs() < 1e-6 * resting, "{e:?}");
    assert!(
        (e[penetration] - f[penetration]).abs() <= 2.0 * error,
        "static penetration: exact {}, faceted {}",
        e[penetration],
        f[penetration]
    );
    assert!(
        (e[force] - f[force]).abs() <= 2.0 * imbalance,
        "static force: exact {}, faceted {}",
        e[force],
        f[force]
    );
    // parts.csv: time, part, x, y, z, …: the CM height through the dynamics.
    for (e, f) in exact_parts.iter().zip(&facet_parts) {
        assert!(
            (e[4] - f[4]).abs() <= 2.0 * error,
            "t = {}: CM at z = {} (exact), {} (faceted)",
            e[0],
            e[4],
            f[4]
        );
    }
}
