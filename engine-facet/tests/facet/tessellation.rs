//! Tessellations are closed solids whose counts follow the documented formula, rise with FT,
//! stay within the chord deviation L/FT, and whose volumes converge to the analytic ones.

use contact_core::geometry::{Cuboid, Cylinder, Ellipsoid, Frustum, Torus, TriangleMesh};
use contact_core::{FacetingTolerance, Geometry};
use engine_facet::tessellate::{counts, segments_for_circle, tessellate};
use std::f64::consts::PI;

fn shapes() -> Vec<(Geometry, f64)> {
    // (geometry, analytic volume)
    vec![
        (
            Geometry::sphere(1.5).unwrap(),
            4.0 / 3.0 * PI * 1.5f64.powi(3),
        ),
        (
            Geometry::Ellipsoid(Ellipsoid::new(1.0, 2.0, 0.5).unwrap()),
            4.0 / 3.0 * PI * 1.0 * 2.0 * 0.5,
        ),
        (
            Geometry::Cylinder(Cylinder::new(0.5, 3.0).unwrap()),
            PI * 0.25 * 3.0,
        ),
        (
            Geometry::Frustum(Frustum::new(1.0, 0.4, 2.0).unwrap()),
            PI * 2.0 / 3.0 * (1.0 + 0.4 + 0.16),
        ),
        (
            Geometry::Frustum(Frustum::new(0.0, 1.0, 2.0).unwrap()),
            PI * 2.0 / 3.0,
        ),
        (
            Geometry::Cuboid(Cuboid::from_corner(1.0, -2.0, 3.0).unwrap()),
            6.0,
        ),
        (
            Geometry::Torus(Torus::new(2.0, 0.5).unwrap()),
            2.0 * PI * PI * 2.0 * 0.25,
        ),
    ]
}

fn ft(v: f64) -> FacetingTolerance {
    FacetingTolerance::new(v).unwrap()
}

#[test]
fn every_primitive_becomes_a_closed_outward_mesh_with_the_documented_counts() {
    for (g, _) in shapes() {
        for tolerance in [3.0, 100.0, 300.0028, 1000.0] {
            let t = tessellate(&g, ft(tolerance)).unwrap();
            let c = counts(&g, ft(tolerance)).unwrap();
            assert_eq!(
                t.triangles.len() as u64,
                c.triangles,
                "{g:?} at {tolerance}"
            );
            assert_eq!(t.vertices.len() as u64, c.vertices, "{g:?} at {tolerance}");
            assert_eq!(t.corner_normals.len(), t.triangles.len());
            // TriangleMesh::new checks closed, manifold, consistently and outward oriented.
            TriangleMesh::new(t.vertices.clone(), t.triangles.clone())
                .unwrap_or_else(|e| panic!("{g:?} at FT {tolerance}: {e}"));
        }
    }
}

#[test]
fn counts_never_fall_as_the_tolerance_rises() {
    for (g, _) in shapes() {
        let mut last = 0;
        for k in 0..200 {
            let tolerance = 1.0 * 1.05f64.powi(k);
            let n = counts(&g, ft(tolerance)).unwrap().triangles;
            assert!(n >= last, "{g:?}: {n} < {last} at FT {tolerance}");
            last = n;
        }
    }
    assert_eq!(segments_for_circle(1.0, 2.0), 3);
    // n = ⌈π / acos(1 − δ/r)⌉, checked against a hand value: δ/r = 0.01 → acos(0.99) = 0.14154.
    assert_eq!(
        segments_for_circle(2.0, 0.02),
        (PI / 0.99f64.acos()).ceil() as u64
    );
    assert_eq!(segments_for_circle(2.0, 0.02), 23);
}

#[test]
fn facets_stay_within_the_chord_deviation_of_the_true_surface() {
    // Sphere: a facet's farthest point from the sphere is the foot of the perpendicular from
    // the centre, at depth r − dist(centre, facet plane).
    let r = 1.5;
    let g = Geometry::sphere(r).unwrap();
    for tolerance in [30.0, 300.0028, 1000.0] {
        let delta = g.characteristic_length().unwrap() / tolerance;
        let t = tessellate(&g, ft(tolerance)).unwrap();
        let mut worst: f64 = 0.0;
        for tri in &t.triangles {
            let [a, b, c] = tri.map(|v| t.vertices[v as usize].coords);
            let n = (b - a).cross(&(c - a)).normalize();
            worst = worst.max(r - n.dot(&a));
        }
        assert!(
            worst <= delta,
            "FT {tolerance}: deviation {worst} > {delta}"
        );
        // And not absurdly finer than asked (within a factor 4 of the allowance).
        assert!(
            worst > delta / 4.0,
            "FT {tolerance}: deviation {worst} ≪ {delta}"
        );
    }
}

#[test]
fn volumes_converge_to_the_analytic_volumes_within_area_times_deviation() {
    // Every facet lies within δ = L/FT of the surface, so the volumes differ by at most the
    // surface area times δ; inscribed meshes converge at first order in 1/FT.
    for (g, exact) in shapes() {
        let errors: Vec<f64> = [30.0, 300.0, 3000.0]
            .iter()
            .map(|&tolerance| {
                let t = tessellate(&g, ft(tolerance)).unwrap();
                let m = TriangleMesh::new(t.vertices.clone(), t.triangles.clone()).unwrap();
                let area: f64 = (0..t.triangles.len()).map(|k| m.triangle_area(k)).sum();
                let delta = g.characteristic_length().unwrap() / tolerance;
                let error = (m.signed_volume() - exact).abs();
                assert!(
                    error <= area * delta,
                    "{g:?} at FT {tolerance}: {error} > {}",
                    area * delta
                );
                error / exact
            })
            .collect();
        if matches!(g, Geometry::Cuboid(_)) {
            assert!(errors.iter().all(|e| *e < 1e-14), "{errors:?}");
        } else {
            assert!(
                errors[0] / errors[1] > 5.0 && errors[1] / errors[2] > 5.0,
                "{g:?}: {errors:?}"
            );
        }
    }
}

#[test]
fn circles_arcs_and_curves_become_polylines_within_the_deviation() {
    use contact_core::geometry::{Arc, Circle};
    use engine_facet::tessellate::{arc_polyline, circle_polyline};
    let c = Circle::new(2.0).unwrap();
    let p = circle_polyline(&c, 0.01);
    assert!(p.closed);
    let n = p.points.len();
    assert_eq!(n as u64, segments_for_circle(2.0, 0.01));
    // The chord's midpoint is the farthest from the circle.
    let mid = nalgebra::center(&p.points[0], &p.points[1]);
    assert!(2.0 - mid.coords.norm() <= 0.01);
    let a = Arc::new(2.0, PI / 2.0).unwrap();
    let q = arc_polyline(&a, 0.01);
    assert!(!q.closed);
    assert!((q.points.last().unwrap().coords - nalgebra::Vector2::new(0.0, 2.0)).norm() < 1e-12);
    assert!(q.points.len() >= n / 4);
}
