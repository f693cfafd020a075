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

/// The scenes whose answers do not depend on the faceting tolerance: boxes keep their faces
/// and meshes their facets, so every row of these must be the same.
const TOLERANCE_FREE: [&str; 5] = [
    "box_plane",
    "box_box",
    "mesh_sphere_10k",
    "mesh_sphere_100k",
    "mesh_torus",
];

#[test]
fn exact_matches_its_references_and_every_faceted_error_falls_at_every_step_of_the_default_sweep() {
    // The whole suite but the two large mesh spheres (their rows cannot change with the
    // tolerance, which the small mesh and the boxes check), over the default sweep.
    let chosen: Vec<_> = scenes::NAMES
        .iter()
        .filter(|n| !n.starts_with("mesh_sphere_100k"))
        .map(|n| scenes::scene(n).unwrap())
        .collect();
    let parry = contact::peer::ParryEngine;
    let report = tradeoff::run(
        &chosen,
        &sweep(&tradeoff::DEFAULT_TOLERANCES),
        &build_engine,
        &[&parry],
        &mut |_| {},
    )
    .unwrap();
    for scene in &chosen {
        let name = scene.name.as_ref();
        let rows: Vec<_> = report.records.iter().filter(|r| r.scene == name).collect();
        let faceted: Vec<_> = rows.iter().filter(|r| r.engine == "faceted").collect();
        let exact = rows.iter().find(|r| r.engine == "exact");
        if let (Some(exact), true) = (exact, name.starts_with("mesh_")) {
            // Meshes standing for true spheres: both engines answer the meshes as given (their
            // polyhedral intersection), so the exact row is the faceted one, error and all.
            let f = faceted[0];
            assert_eq!(exact.depth_error, f.depth_error, "{name}");
            assert_eq!(exact.normal_error_deg, f.normal_error_deg, "{name}");
            assert_eq!(exact.point_error, f.point_error, "{name}");
            assert_eq!(exact.missed_contacts, f.missed_contacts, "{name}");
        } else if let Some(exact) = exact {
            assert!(exact.depth_error.unwrap() <= 1e-9, "{name}: {exact:?}");
            assert!(exact.normal_error_deg.unwrap() <= 1e-7, "{name}: {exact:?}");
            assert!(exact.point_error.unwrap() <= 1e-9, "{name}: {exact:?}");
            assert_eq!(exact.missed_contacts + exact.extra_contacts, 0, "{name}");
            assert_eq!(exact.resolved_depth, 0.0, "{name}: no facets, no band");
        }
        assert_eq!(faceted.len(), tradeoff::DEFAULT_TOLERANCES.len(), "{name}");
        if TOLERANCE_FREE.contains(&name) {
            for r in &faceted[1..] {
                assert_eq!(r.depth_error, faceted[0].depth_error, "{name}");
                assert_eq!(r.normal_error_deg, faceted[0].normal_error_deg, "{name}");
                assert_eq!(r.point_error, faceted[0].point_error, "{name}");
                assert_eq!(r.triangles, faceted[0].triangles, "{name}");
            }
            continue;
        }
        // Depth: the worst over the poses is the deepest nominal depth missed (a contact
        // shallower than the band counts its whole depth); the scenes' depths, 1.08× apart,
        // resolve every step. Normal and point: worst over the resolved contacts (deeper than
        // three bands), absent at a tolerance that resolves none. A normal exact by
        // construction (a plane's) stays at round-off, where "falls" means nothing.
        type Field = fn(&tradeoff::TradeRecord) -> Option<f64>;
        let fields: [(&str, Field); 3] = [
            ("depth", |r| r.depth_error),
            ("normal", |r| r.normal_error_deg),
            ("point", |r| r.point_error),
        ];
        let depth: Vec<f64> = faceted.iter().filter_map(|r| r.depth_error).collect();
        assert!(
            depth[4] < 0.05 * depth[0],
            "{name}: a hundredfold finer tolerance, {depth:?}"
        );
        for (what, field) in fields {
            let series: Vec<f64> = faceted.iter().filter_map(|r| field(r)).collect();
            assert!(
                series.len() >= 3,
                "{name}: {what} resolved at too few tolerances"
            );
            assert!(
                series
                    .windows(2)
                    .all(|w| w[1] < w[0] || w[1].max(w[0]) <= 1e-9),
                "{name}: faceted {what} errors over the sweep {series:?}"
            );
        }
        for pair in faceted.windows(2) {
            assert!(
                pair[1].resolved_contacts >= pair[0].resolved_contacts,
                "{name}: a finer tolerance resolves at least as much"
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
    // Where the exact engine answers a primitive pair, the faster of it and the faceted
    // engine's smallest sufficient tolerance is chosen (which one is a timing, not asserted);
    // on the mesh spheres both answer the meshes as given (meshes keep their facets: every
    // tolerance has the same error, and the smallest is the faceted candidate).
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
    let row = |engine: &str, tolerance: Option<f64>| {
        report
            .records
            .iter()
            .find(|r| {
                r.scene == "sphere_plane" && r.engine == engine && r.faceting_tolerance == tolerance
            })
            .unwrap()
    };
    let exact = row("exact", None);
    let smallest = [300.0028, 1000.0]
        .into_iter()
        .find(|&t| tradeoff::meets(row("faceted", Some(t)), 0.01));
    let expected = match smallest.map(|t| row("faceted", Some(t))) {
        Some(f) if f.query_ns_median < exact.query_ns_median => ("faceted", smallest),
        _ => ("exact", None),
    };
    assert_eq!(
        (sphere.engine.as_str(), sphere.faceting_tolerance),
        expected
    );
    let mesh = tradeoff::select(&report.records, "mesh_sphere_10k", 0.01);
    match mesh {
        Some(choice) => {
            // Both engines answer the meshes as given, with the same error: the faster of
            // the exact engine and the faceted one at its smallest tolerance.
            let of = |engine: &str, tolerance: Option<f64>| {
                report
                    .records
                    .iter()
                    .find(|r| {
                        r.scene == "mesh_sphere_10k"
                            && r.engine == engine
                            && r.faceting_tolerance == tolerance
                    })
                    .unwrap()
            };
            let (exact, faceted) = (of("exact", None), of("faceted", Some(300.0028)));
            assert_eq!(exact.depth_error, faceted.depth_error);
            let expected = if faceted.query_ns_median < exact.query_ns_median {
                ("faceted", Some(300.0028))
            } else {
                ("exact", None)
            };
            assert_eq!(
                (choice.engine.as_str(), choice.faceting_tolerance),
                expected,
                "the faster of the sufficient settings"
            );
        }
        None => panic!(
            "no setting met 1% on the mesh spheres: {:?}",
            report.records
        ),
    }
}
