//! The ball example with the faceted engine against the same run with the exact engine: a
//! tessellated sphere bounces on a plane and on a tessellated box, with rebound heights that
//! agree with the exact engine's within the faceting tolerance's chord deviation.
//!
//! The bound. Every facet of a tessellated primitive lies within `e = L/FT` of the true surface
//! (SPEC §7, `L` the geometry's bounding-box diagonal), so the faceted depth differs from the
//! true one by at most `e` at every pose, and the faceted impact is the true impact with the
//! surface displaced by at most `e`. The ball does not turn (the force's line of action passes
//! within a facet of its centre), so the elastic force is a function of its height alone and
//! returns what it stores; the apex then moves by at most the surface's displacement, `e` per
//! surface in contact (the box is faceted too, but flat faces are exact: its `e` is 0).

use contact::dataset;
use contact::run::lower::lower;
use contact::solver::bdf::IntegratorSettings;
use contact::solver::contact_force::Analysis;
use contact::solver::simulate::{DynamicsSettings, simulate};
use contact_core::{FacetingTolerance, GeometryEngine};
use engine_facet::FacetEngine;
use std::path::Path;

/// Centre apexes after each bounce, and the run's steps, for the ball dataset `adm_text` with
/// `engine`.
fn apexes(adm_text: &str, engine: &dyn GeometryEngine, bounces: usize) -> (Vec<f64>, u64) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/ball");
    let loaded = dataset::read_str(adm_text, dir.join("ball.adm"), None);
    assert!(!loaded.has_errors(), "{:?}", loaded.diagnostics);
    let no_meshes = |_: &contact::model::MeshFile| Err("no meshes in this model".to_string());
    let mut lowered = lower(&loaded.model, engine, Analysis::Dynamics, &no_meshes).unwrap();
    let settings = DynamicsSettings {
        start: 0.0,
        end: 0.5 + 0.9 * bounces as f64,
        output_step: 1e-3,
        integrator: IntegratorSettings {
            error: loaded.model.integrator.error,
            ..IntegratorSettings::default()
        },
    };
    let ball = lowered.parts[0].0;
    let mut found = Vec::new();
    let mut was_rising = false;
    let summary = simulate(
        &mut lowered.system,
        &lowered.contacts,
        &settings,
        &mut |frame| {
            let s = frame.parts[ball.0];
            let (z, v) = (s.pose_w.translation.z, s.velocity_w.z);
            if was_rising && v <= 0.0 && frame.contacts[0].is_empty() {
                found.push(z + v * v / (2.0 * 9.81));
            }
            was_rising = v > 0.0 && frame.contacts[0].is_empty();
            Ok(())
        },
    )
    .unwrap_or_else(|e| panic!("{} stalled: {e}", engine.name()));
    assert!(
        found.len() >= bounces,
        "{} apexes: {found:?}",
        engine.name()
    );
    found.truncate(bounces);
    (found, summary.integrator.steps)
}

fn ball_on_plane() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/ball/ball.adm"))
        .unwrap()
}

/// The ball example with the ground plane replaced by a 2 × 2 × 5 box whose top face is the
/// plane's z = 0 (deep, so that the integrator's first step into it cannot pass through it).
fn ball_on_box() -> String {
    let text = ball_on_plane();
    assert!(text.contains("GRAPHICS/2, PLANE, RM = 10"));
    text.replace(
        "GRAPHICS/2, PLANE, RM = 10",
        "MARKER/11, PART = 1, QP = -1, -1, -5\n\
         GRAPHICS/2, BOX, CORNER = 11, X = 2, Y = 2, Z = 5",
    )
}

fn faceted(ft: f64) -> FacetEngine {
    FacetEngine::new(FacetingTolerance::new(ft).unwrap())
}

/// The sphere's chord deviation `L/FT`: `L` is its bounding-box diagonal, `2r·√3`.
fn sphere_chord_deviation(ft: f64) -> f64 {
    2.0 * 0.1 * 3f64.sqrt() / ft
}

fn assert_within_chord_deviation(adm_text: &str, ft: f64, bounces: usize) {
    let (exact, _) = apexes(adm_text, &engine_exact::ExactEngine, bounces);
    let (facet, steps) = apexes(adm_text, &faceted(ft), bounces);
    let bound = sphere_chord_deviation(ft);
    for (k, (f, e)) in facet.iter().zip(&exact).enumerate() {
        assert!(
            (f - e).abs() <= bound,
            "FT {ft}, bounce {k}: faceted apex {f}, exact {e}, differ by {} > L/FT = {bound} \
             ({steps} steps)",
            (f - e).abs()
        );
    }
    // The rebound is a real one, not a ball resting on the surface.
    assert!(facet[bounces - 1] > 0.1 + 0.3, "{facet:?}");
}

#[test]
fn a_faceted_ball_rebounds_off_a_plane_as_the_exact_one_within_the_chord_deviation() {
    let text = ball_on_plane();
    for ft in [300.0028, 1000.0] {
        assert_within_chord_deviation(&text, ft, 2);
    }
}

#[test]
fn a_faceted_ball_rebounds_off_a_faceted_box_as_the_exact_one_within_the_chord_deviation() {
    // One bounce: two meshes make this the costliest run of the suite.
    let text = ball_on_box();
    for ft in [300.0028, 1000.0] {
        assert_within_chord_deviation(&text, ft, 1);
    }
}
