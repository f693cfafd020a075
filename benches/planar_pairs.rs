//! Per-query cost of the 2-D pairs: the exact engine (closed forms, Newton on curves) beside
//! the faceted engine on polylines at the default faceting tolerance and at 3000.
//!
//! `cargo bench --bench planar_pairs` (release). Each group `planar/<pair>` has the ids
//! `exact`, `faceted_300` and `faceted_3000` (those an engine does not build are skipped,
//! with its reason printed): a prepared pair's full `query` into a reused buffer. Before
//! timing, each group prints every answer's depth, so speed and accuracy are read together.

#![expect(
    missing_docs,
    reason = "criterion_group! generates an undocumented public function"
)]

use contact_core::geometry::{Circle, Curve, CurvePoints, Line};
use contact_core::{
    Contact, FacetingTolerance, Geometry, GeometryEngine, GeometryInstance, Isometry3, Point2,
    Vector3, WorkCounters,
};
use criterion::{Criterion, criterion_group, criterion_main};
use engine_exact::ExactEngine;
use engine_facet::FacetEngine;
use std::hint::black_box;
use std::sync::Arc;
use std::time::Duration;

fn planar(x: f64, y: f64, angle: f64) -> Isometry3 {
    Isometry3::new(Vector3::new(x, y, 0.0), Vector3::z() * angle)
}

/// A closed cubic B-spline cam-like blob about 2.5 across.
fn blob() -> Geometry {
    let points: Vec<Point2> = (0..12)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 12.0;
            let r = 1.0 + 0.25 * (3.0 * t).cos();
            Point2::new(r * t.cos(), 0.8 * r * t.sin())
        })
        .collect();
    Geometry::Curve(Arc::new(
        Curve::new(&points, 4, true, CurvePoints::Control).unwrap(),
    ))
}

fn bench(c: &mut Criterion) {
    let circle = |r: f64| Geometry::Circle(Circle::new(r).unwrap());
    let cases = [
        (
            "circle_circle",
            circle(0.4),
            circle(1.0),
            planar(1.3, 0.2, 0.3),
        ),
        (
            "circle_line",
            circle(0.4),
            Geometry::Line(Line::unbounded()),
            planar(0.1, 0.35, 0.3),
        ),
        // The line's end 0.1 left of the centre, inside the disc (the faceted engine does
        // not build a circle on a bounded line: exact only).
        (
            "circle_bounded_line",
            circle(0.4),
            Geometry::Line(Line::bounded(0.0, 5.0).unwrap()),
            planar(0.1, 0.35, 0.3),
        ),
        (
            "point_curve",
            Geometry::Point,
            blob(),
            planar(1.0, 0.1, 0.0),
        ),
        ("circle_curve", circle(0.15), blob(), planar(1.2, 0.1, 0.0)),
    ];
    let engines: [(&str, Box<dyn GeometryEngine>); 3] = [
        ("exact", Box::new(ExactEngine)),
        (
            "faceted_300",
            Box::new(FacetEngine::new(FacetingTolerance::new(300.0028).unwrap())),
        ),
        (
            "faceted_3000",
            Box::new(FacetEngine::new(FacetingTolerance::new(3000.0).unwrap())),
        ),
    ];
    for (name, i, j, pose_i) in cases {
        let mut group = c.benchmark_group(format!("planar/{name}"));
        group.measurement_time(Duration::from_secs(2));
        group.warm_up_time(Duration::from_millis(500));
        for (id, engine) in &engines {
            let prepared = engine.prepare(
                &[GeometryInstance::new(i.clone())],
                &[GeometryInstance::new(j.clone())],
            );
            let pair = match prepared {
                Ok(pair) => pair,
                Err(e) => {
                    println!("planar/{name} {id}: not built ({e})");
                    continue;
                }
            };
            let pose_j = Isometry3::identity();
            let mut out: Vec<Contact> = Vec::new();
            let mut work = WorkCounters::default();
            pair.query(&pose_i, &pose_j, &mut out, &mut work).unwrap();
            println!(
                "planar/{name} {id}: depth {:?}",
                out.iter().map(|c| c.penetration).collect::<Vec<_>>()
            );
            group.bench_function(*id, |b| {
                b.iter(|| {
                    pair.query(black_box(&pose_i), &pose_j, &mut out, &mut work)
                        .unwrap();
                    black_box(out.len())
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
