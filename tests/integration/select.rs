//! `contact select` on datasets: the recommendation follows from the measured rows (the
//! exact engine or the faceted engine at its smallest sufficient tolerance, whichever measured
//! faster; which one that is, is a timing, so it is not asserted here: the choice between two
//! given timings is unit-tested in `tradeoff::select`), the rows a sweep measures, and a clear
//! refusal naming the contact when nothing can be checked against the target.

use contact::engine_choice::build_engine;
use contact::tradeoff::{self, Sweep, Timing, TradeRecord};
use contact_core::FacetingTolerance;
use contact_core::geometry::Ellipsoid;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

fn sweep(tolerances: &[f64]) -> Sweep {
    Sweep {
        tolerances: tolerances
            .iter()
            .map(|&t| FacetingTolerance::new(t).unwrap())
            .collect(),
        timing: Timing {
            rounds: 1,
            min_sample_ns: 0,
        },
    }
}

/// A fresh directory for one test's files.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("contact-select-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A UV sphere of radius `r` with `n` segments around, as an ascii STL file.
fn write_sphere_stl(path: &Path, r: f64, n: u32) {
    let sphere = Ellipsoid::sphere(r).unwrap();
    let deviation = 2.0 * r * (1.0 - (std::f64::consts::PI / f64::from(n)).cos()) * (1.0 + 1e-9);
    let t = engine_facet::tessellate::ellipsoid(&sphere, deviation);
    let mut text = String::from("solid sphere\n");
    for tri in &t.triangles {
        let [a, b, c] = tri.map(|k| t.vertices[k as usize]);
        let normal = (b - a).cross(&(c - a)).normalize();
        let _ = writeln!(text, "facet normal {} {} {}", normal.x, normal.y, normal.z);
        text.push_str("outer loop\n");
        for v in [a, b, c] {
            let _ = writeln!(text, "vertex {:?} {:?} {:?}", v.x, v.y, v.z);
        }
        text.push_str("endloop\nendfacet\n");
    }
    text.push_str("endsolid sphere\n");
    std::fs::write(path, text).unwrap();
}

/// A ball of radius 1 on a moving part above the ground's geometry `ground_graphics`, under
/// gravity along −z.
fn ball_over(ground_graphics: &str, height: f64) -> String {
    format!(
        "ball over the ground\n\
         ACCGRAV/ KGRAV = -9.81\n\
         PART/1, GROUND\n\
         MARKER/10, PART = 1\n\
         PART/2, MASS = 1, CM = 20, IP = 1, 1, 1\n\
         MARKER/20, PART = 2, QP = 0, 0, {height}\n\
         GRAPHICS/1, ELLIPSOID, CM = 20, XSCALE = 2, YSCALE = 2, ZSCALE = 2\n\
         {ground_graphics}\n\
         CONTACT/1, IGEOM = 1, JGEOM = 2, IMPACT, STIFFNESS = 1E5, EXPONENT = 2, DAMPING = 10\
         , DMAX = 0.01\n\
         END\n"
    )
}

fn load(dir: &Path, adm: &str) -> contact::model::Model {
    let path = dir.join("model.adm");
    std::fs::write(&path, adm).unwrap();
    contact::dataset::load(&path, None).unwrap().0
}

/// The model's reference run over `tolerances`, `end` seconds long.
fn reference(
    dir: &Path,
    model: &contact::model::Model,
    tolerances: &[f64],
    end: f64,
) -> tradeoff::RunRecord {
    let exact = build_engine(
        contact_core::GeometryLibrary::Exact,
        FacetingTolerance::DEFAULT,
    );
    tradeoff::record_reference(
        model,
        &dir.join("model.adm"),
        exact.as_ref(),
        &sweep(tolerances).tolerances,
        Some(end),
    )
    .unwrap()
}

/// The smallest tolerance among the faceted rows of `contact` meeting the target, read
/// straight from the records.
fn smallest_sufficient(records: &[TradeRecord], contact: &str, target: f64) -> Option<f64> {
    records
        .iter()
        .filter(|r| r.scene == contact && r.engine == "faceted")
        .filter(|r| r.depth_error.is_some_and(|e| e <= target))
        .filter_map(|r| r.faceting_tolerance)
        .min_by(f64::total_cmp)
}

/// The faceted row `select` weighs against the exact engine on `contact`: the one at the
/// smallest tolerance meeting `target` (the exact engine's row must meet it), and the row a
/// recommendation must name: the faster of the two by the measured medians, the exact engine
/// on a tie.
fn expected_choice<'r>(
    records: &'r [TradeRecord],
    contact: &str,
    target: f64,
) -> (&'r TradeRecord, &'r TradeRecord) {
    let exact = records
        .iter()
        .find(|r| r.scene == contact && r.engine == "exact")
        .unwrap();
    assert!(tradeoff::meets(exact, target), "{exact:?}");
    let tolerance = smallest_sufficient(records, contact, target)
        .unwrap_or_else(|| panic!("no tolerance met {target}: {records:?}"));
    let faceted = records
        .iter()
        .find(|r| {
            r.scene == contact && r.engine == "faceted" && r.faceting_tolerance == Some(tolerance)
        })
        .unwrap();
    let faster = if faceted.query_ns_median < exact.query_ns_median {
        faceted
    } else {
        exact
    };
    (faceted, faster)
}

/// `(engine, tolerance)` of a row or a choice.
fn setting(engine: &str, tolerance: Option<f64>) -> (String, Option<f64>) {
    (engine.to_string(), tolerance)
}

#[test]
fn select_recommends_from_the_measured_rows_for_a_sphere_on_a_plane() {
    // The ball starts 5 mm into the plane and settles on it (k·δ² = m·g at δ ≈ 0.0099).
    let dir = scratch("plane");
    let model = load(&dir, &ball_over("GRAPHICS/2, PLANE, RM = 10", 0.995));
    let run = reference(&dir, &model, &[100.0, 300.0028], 0.2);
    assert_eq!(run.setting, tradeoff::Setting::EXACT);
    assert!(run.touching[0].len() > 10, "{:?}", run.times);
    let selection = tradeoff::select_for_model(
        &model,
        &run,
        &sweep(&[100.0, 300.0028]),
        &build_engine,
        &[],
        0.01,
        &mut |_| {},
    )
    .unwrap();
    assert_eq!(selection.contacts, ["CONTACT/1"]);
    assert!(selection.untouched.is_empty());
    // The contact's poses: the run's touching frames, each at the run's depth, which for a
    // ball on a plane is exactly r − d (the closed form, independent of the engine), then the
    // spread around them.
    let scene = &contact::scenes::from_run(&model, &run, 50).unwrap().scenes[0];
    assert_eq!(scene.scale, 1.0);
    let sampled = run.touching[0].len().min(50);
    assert_eq!(scene.poses.len(), 2 * sampled);
    for pose in &scene.poses[..sampled] {
        let ball = (pose.pose_world_i * scene.i[0].pose_part_geometry)
            .translation
            .vector;
        assert!(
            (1.0 - ball.z - pose.nominal_depth).abs() < 1e-12,
            "{pose:?}"
        );
    }
    let records = &selection.report.records;
    assert!(
        records.iter().all(|r| r.poses == 2 * sampled),
        "{records:?}"
    );
    // Every pose touches: the exact engine resolves a contact at each.
    let exact = records.iter().find(|r| r.engine == "exact").unwrap();
    assert_eq!(exact.resolved_contacts, 2 * sampled, "{exact:?}");
    let exact = records.iter().find(|r| r.engine == "exact").unwrap();
    assert_eq!(exact.reference, tradeoff::ReferenceSource::ExactEngine);
    assert!(records.iter().all(|r| r.depth_error.is_some()));
    let (_, faster) = expected_choice(records, "CONTACT/1", 0.01);
    let expected = setting(&faster.engine, faster.faceting_tolerance);
    let r = selection.recommendation.unwrap();
    assert_eq!(
        setting(&r.contacts[0].engine, r.contacts[0].faceting_tolerance),
        expected
    );
    // One contact: the model-wide choice is the contact's.
    assert_eq!(
        setting(&r.model.engine, r.model.faceting_tolerance),
        expected
    );
    // The same through the command, with its JSON.
    let json = dir.join("select.json");
    let args = contact::cli::select::SelectArgs {
        model: dir.join("model.adm"),
        commands: None,
        end: Some(0.2),
        max_depth_error: Some(0.01),
        max_run_error: None,
        tolerances: vec![100.0],
        rounds: Some(1),
        json: Some(json.clone()),
        csv: None,
        plot: None,
    };
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code =
        contact::cli::select::run(&args, &build_engine, &mut out, &mut err, &mut |_| {}).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert_eq!(code, 0, "{text}{}", String::from_utf8_lossy(&err));
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(json).unwrap()).unwrap();
    let rows = doc["per_query"]["records"].as_array().unwrap();
    assert_eq!(rows.len(), 2);
    // The faster of the exact row and the faceted one (if it meets the target), as printed.
    let row = |engine: &str| rows.iter().find(|r| r["engine"] == engine).unwrap();
    let median = |r: &serde_json::Value| r["query_ns_median"].as_f64().unwrap();
    let (exact, faceted) = (row("exact"), row("faceted"));
    let faceted_meets = faceted["depth_error"].as_f64().is_some_and(|e| e <= 0.01);
    let expected = if faceted_meets && median(faceted) < median(exact) {
        "faceted engine, faceting tolerance 100"
    } else {
        "exact engine"
    };
    assert!(text.contains(&format!("model: {expected} (")), "{text}");
    assert_eq!(
        doc["per_query"]["recommendation"]["model"]["engine"],
        expected.split(' ').next().unwrap()
    );
}

#[test]
fn select_recommends_from_the_measured_rows_for_a_ball_on_a_large_mesh() {
    // A ball on a 39,600-triangle STL sphere: the exact engine passes over every triangle on
    // every query (skipping the closest-point test of those its ball rules out); the faceted
    // engine descends two trees to the few near the contact. The ball's own faceting sets the
    // error.
    let dir = scratch("mesh");
    write_sphere_stl(&dir.join("big.stl"), 5.0, 200);
    let model = load(
        &dir,
        &ball_over("GRAPHICS/2, EXTERNAL, RM = 10, FILE = big.stl", 5.995),
    );
    let target = 0.01;
    let run = reference(&dir, &model, &[300.0028, 100.0], 0.1);
    let selection = tradeoff::select_for_model(
        &model,
        &run,
        &sweep(&[300.0028, 100.0]),
        &build_engine,
        &[],
        target,
        &mut |_| {},
    )
    .unwrap();
    let records = &selection.report.records;
    let exact = records.iter().find(|r| r.engine == "exact").unwrap();
    assert_eq!(exact.reference, tradeoff::ReferenceSource::ExactEngine);
    let (at_expected, faster) = expected_choice(records, "CONTACT/1", target);
    // The work each engine does per query, counted (not timed): two tree descents against a
    // pass over the whole mesh.
    assert!(
        at_expected.work.primitive_tests * 5.0 < exact.work.primitive_tests,
        "exact {exact:?}\nfaceted {at_expected:?}"
    );
    let expected = setting(&faster.engine, faster.faceting_tolerance);
    let r = selection.recommendation.unwrap();
    assert_eq!(
        setting(&r.contacts[0].engine, r.contacts[0].faceting_tolerance),
        expected
    );
    assert_eq!(
        setting(&r.model.engine, r.model.faceting_tolerance),
        expected
    );
}

#[test]
fn select_on_two_tori_takes_the_exact_reference_and_refuses_a_bad_target() {
    // Two tori lying side by side, one 0.1 into the other: the exact engine answers torus
    // against torus, so the reference run is the exact one and the exact engine meets the
    // target (its own error is zero by construction). The refusal with no candidate is the
    // library's (`tradeoff::select`'s tests): every pair the dataset reader accepts now has an
    // exact reference.
    let dir = scratch("none");
    let adm = "two tori\n\
         PART/1, GROUND\n\
         MARKER/10, PART = 1\n\
         PART/2, MASS = 1, CM = 20, IP = 1, 1, 1\n\
         MARKER/20, PART = 2, QP = 2.5, 0, 0\n\
         GRAPHICS/1, TORUS, CM = 20, MAJOR_RADIUS = 1, MINOR_RADIUS = 0.3\n\
         GRAPHICS/2, TORUS, CM = 10, MAJOR_RADIUS = 1, MINOR_RADIUS = 0.3\n\
         CONTACT/7, IGEOM = 1, JGEOM = 2, IMPACT, STIFFNESS = 1E5, EXPONENT = 2, DAMPING = 10\
         , DMAX = 0.01\n\
         END\n";
    load(&dir, adm);
    let args = contact::cli::select::SelectArgs {
        model: dir.join("model.adm"),
        commands: None,
        end: Some(0.05),
        max_depth_error: Some(0.01),
        max_run_error: None,
        tolerances: vec![100.0],
        rounds: Some(1),
        json: None,
        csv: None,
        plot: None,
    };
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code =
        contact::cli::select::run(&args, &build_engine, &mut out, &mut err, &mut |_| {}).unwrap();
    let (out, err) = (
        String::from_utf8(out).unwrap(),
        String::from_utf8(err).unwrap(),
    );
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("CONTACT/7"), "{out}");
    let model_line = out
        .lines()
        .find(|l| l.starts_with("model"))
        .unwrap_or_default();
    assert!(model_line.contains("exact"), "{out}");
    // A target that is not a positive number is refused before anything is measured.
    let bad = contact::cli::select::SelectArgs {
        max_depth_error: Some(-1.0),
        ..args
    };
    let mut err = Vec::new();
    let code =
        contact::cli::select::run(&bad, &build_engine, &mut Vec::new(), &mut err, &mut |_| {})
            .unwrap();
    assert_eq!(code, 1);
    assert!(
        String::from_utf8(err)
            .unwrap()
            .contains("--max-depth-error")
    );
}

#[test]
fn a_contact_that_never_touches_in_the_reference_run_is_reported_as_such() {
    // A ball 0.5 above a plane without gravity: it never moves, so the contact never touches
    // and nothing is measured, never an error of 0.
    let dir = scratch("untouched");
    let adm = ball_over("GRAPHICS/2, PLANE, RM = 10", 1.5).replace("ACCGRAV/ KGRAV = -9.81\n", "");
    let model = load(&dir, &adm);
    let run = reference(&dir, &model, &[100.0], 0.05);
    assert!(run.touching[0].is_empty());
    let selection = tradeoff::select_for_model(
        &model,
        &run,
        &sweep(&[100.0]),
        &build_engine,
        &[],
        0.01,
        &mut |_| {},
    )
    .unwrap();
    assert!(selection.contacts.is_empty());
    assert_eq!(selection.untouched, ["CONTACT/1"]);
    assert!(selection.report.records.is_empty());
    assert!(matches!(
        selection.recommendation,
        Err(tradeoff::NoRecommendation::NothingTouched { .. })
    ));
    let args = contact::cli::select::SelectArgs {
        model: dir.join("model.adm"),
        commands: None,
        end: Some(0.05),
        max_depth_error: Some(0.01),
        max_run_error: None,
        tolerances: vec![100.0],
        rounds: Some(1),
        json: None,
        csv: None,
        plot: None,
    };
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code =
        contact::cli::select::run(&args, &build_engine, &mut out, &mut err, &mut |_| {}).unwrap();
    let (out, err) = (
        String::from_utf8(out).unwrap(),
        String::from_utf8(err).unwrap(),
    );
    assert_eq!(code, 1, "{out}{err}");
    assert!(
        out.contains("CONTACT/1: no contact in the reference run (exact): not measured"),
        "{out}"
    );
    assert!(
        err.contains("no contact in the reference run (exact)"),
        "{err}"
    );
    // Whole runs without a contact cannot tell the engines apart: refused as well.
    let runs = contact::cli::select::SelectArgs {
        max_depth_error: None,
        max_run_error: Some(0.01),
        ..args
    };
    let mut err = Vec::new();
    let code =
        contact::cli::select::run(&runs, &build_engine, &mut Vec::new(), &mut err, &mut |_| {})
            .unwrap();
    let err = String::from_utf8(err).unwrap();
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("no contact in the reference run (exact)"),
        "{err}"
    );
}
