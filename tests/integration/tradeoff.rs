//! The trade report on real engines: the exact engine matches the closed forms, the faceted
//! engine's errors shrink as the faceting tolerance rises, and the JSON follows the README's
//! schema.

use contact::engine_choice::build_engine;
use contact::scenes;
use contact::tradeoff::{self, Sweep, Timing};
use contact_core::FacetingTolerance;

fn sweep(tolerances: &[f64]) -> Sweep {
    Sweep {
        tolerances: tolerances
            .iter()
            .map(|&t| FacetingTolerance::new(t).unwrap())
            .collect(),
        // One untimed-quality pass: this test is about errors, not speed.
        timing: Timing {
            rounds: 1,
            min_sample_ns: 0,
        },
    }
}

#[test]
fn exact_matches_closed_forms_and_faceted_errors_shrink_with_the_tolerance() {
    let names = [
        "sphere_plane",
        "sphere_sphere",
        "ellipsoid_plane",
        "cylinder_plane_side",
    ];
    let chosen: Vec<_> = names.iter().map(|n| scenes::scene(n).unwrap()).collect();
    let parry = engine_exact::parry_adapter::ParryEngine;
    let tolerances = [100.0, 300.0028, 1000.0, 3000.0];
    let report = tradeoff::run(
        &chosen,
        &sweep(&tolerances),
        &build_engine,
        &[&parry],
        &mut |_| {},
    )
    .unwrap();
    for name in names {
        let rows: Vec<_> = report.records.iter().filter(|r| r.scene == name).collect();
        if let Some(exact) = rows.iter().find(|r| r.engine == "exact") {
            assert!(
                exact.depth_error.unwrap() <= 1e-9,
                "{name}: exact depth error {:?}",
                exact.depth_error
            );
            assert!(exact.normal_error_deg.unwrap() <= 1e-7, "{name}");
            assert!(exact.point_error.unwrap() <= 1e-9, "{name}: {exact:?}");
            assert_eq!(exact.missed_contacts + exact.extra_contacts, 0, "{name}");
        }
        let faceted: Vec<f64> = rows
            .iter()
            .filter(|r| r.engine == "faceted")
            .map(|r| r.depth_error.unwrap())
            .collect();
        // Strictly better at each finer tolerance, and much better over the sweep. The worst
        // error over a scene's poses is the deepest nominal depth missed (a contact shallower
        // than the faceting band counts its whole depth); the scenes' depths, 1.41× apart,
        // resolve every step of the sweep.
        assert_eq!(faceted.len(), tolerances.len(), "{name}");
        assert!(
            faceted.windows(2).all(|w| w[1] < w[0]),
            "{name}: faceted errors {faceted:?}"
        );
        assert!(
            faceted[3] < 0.2 * faceted[0],
            "{name}: faceted errors {faceted:?}"
        );
        // Normal and point errors are the worst over the contacts found, and the shallowest
        // contacts found at each tolerance are slivers within a facet of the band, whose
        // point and normal depend on the facet phase: they fall over the sweep, not at every
        // step. A normal exact by construction (a plane's) stays at round-off.
        let faceted_rows: Vec<_> = rows.iter().filter(|r| r.engine == "faceted").collect();
        for (what, first, last) in [
            (
                "normal",
                faceted_rows[0].normal_error_deg.unwrap(),
                faceted_rows[3].normal_error_deg.unwrap(),
            ),
            (
                "point",
                faceted_rows[0].point_error.unwrap(),
                faceted_rows[3].point_error.unwrap(),
            ),
        ] {
            assert!(
                last <= 1e-9 || last < 0.5 * first,
                "{name}: faceted {what} error {first:e} at FT 100, {last:e} at FT 3000"
            );
        }
    }
    let json: serde_json::Value =
        serde_json::from_str(&tradeoff::json(&report.records).unwrap()).unwrap();
    crate::trade_schema::validate(&json).unwrap();
    assert!(
        report.records.iter().any(|r| r.engine == "parry"),
        "parry rows present"
    );
}

#[test]
fn select_picks_exact_where_it_wins_and_the_smallest_sufficient_tolerance_otherwise() {
    // Where the exact engine answers a primitive pair, it is both faster and exact; on the
    // mesh spheres it cannot answer, so the faceted engine is chosen (meshes keep their facets:
    // every tolerance has the same error, and the smallest is taken).
    let chosen = [
        scenes::scene("sphere_plane").unwrap(),
        scenes::scene("mesh_sphere_10k").unwrap(),
    ];
    let report = tradeoff::run(
        &chosen,
        &sweep(&[300.0028, 1000.0]),
        &build_engine,
        &[],
        &mut |_| {},
    )
    .unwrap();
    let sphere = tradeoff::select(&report.records, "sphere_plane", 0.01).unwrap();
    assert_eq!(sphere.engine, "exact");
    let mesh = tradeoff::select(&report.records, "mesh_sphere_10k", 0.01);
    match mesh {
        Some(choice) => {
            assert_eq!(choice.engine, "faceted");
            assert_eq!(
                choice.faceting_tolerance,
                Some(300.0028),
                "the smallest sufficient tolerance"
            );
        }
        None => panic!(
            "no setting met 1% on the mesh spheres: {:?}",
            report.records
        ),
    }
}
