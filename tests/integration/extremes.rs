//! Numerical stability at the extremes, over the scene suite and both engines: scenes scaled to
//! 1e-6 and 1e6, grazing contact (δ = 1e-12 of the size, in every scene's poses), near-parallel
//! faces and axes, very small and very large faceting tolerances, and meshes of very thin
//! triangles. Each answer is finite and well formed, or a typed error — never NaN, never a panic.

use contact::engine_choice::build_engine;
use contact::scenes::{self, Scene};
use contact_core::geometry::{Cuboid, Cylinder, Plane, TriangleMesh};
use contact_core::{
    FacetingTolerance, Geometry, GeometryInstance, GeometryLibrary, Isometry3, PrepareError,
    Vector3, WorkCounters,
};
use std::sync::Arc;

/// Queries every pose of `scene` with `library` at `tolerance`; every contact must be well
/// formed. Returns the number of contacts, or `None` when the engine does not answer the pair.
fn all_answers_finite(scene: &Scene, library: GeometryLibrary, tolerance: f64) -> Option<usize> {
    let engine = build_engine(library, FacetingTolerance::new(tolerance).unwrap());
    let pair = match engine.prepare(&scene.i, &scene.j) {
        Ok(pair) => pair,
        Err(PrepareError::Unsupported(_)) => return None,
        Err(e) => panic!("{} / {}: {e}", scene.name, engine.name()),
    };
    let (mut out, mut work, mut count) = (Vec::new(), WorkCounters::default(), 0);
    for pose in &scene.poses {
        pair.query(&pose.pose_world_i, &pose.pose_world_j, &mut out, &mut work)
            .unwrap();
        for c in &out {
            assert!(
                c.is_well_formed(),
                "{} / {} at scale {}: {c:?}",
                scene.name,
                engine.name(),
                scene.scale
            );
        }
        count += out.len();
    }
    Some(count)
}

/// The scenes cheap enough for a debug-build test (the 10k- and 100k-triangle spheres are left to
/// the release-mode `contact tradeoff`; the mesh torus stands for meshes here).
fn light_scenes() -> Vec<Scene> {
    scenes::NAMES
        .iter()
        .filter(|n| !n.starts_with("mesh_sphere"))
        .filter_map(|n| scenes::scene(n))
        .collect()
}

#[test]
fn every_scene_at_every_scale_gives_finite_answers_with_both_engines() {
    for scene in light_scenes() {
        for library in [GeometryLibrary::Exact, GeometryLibrary::Faceted] {
            let base = all_answers_finite(&scene, library, 300.0028);
            for factor in [1e-6, 1e6] {
                // Scaling changes nothing but the unit: the same contacts at every scale.
                let scaled = all_answers_finite(&scene.scaled(factor).unwrap(), library, 300.0028);
                assert_eq!(scaled, base, "{} {library:?} at scale {factor}", scene.name);
            }
        }
    }
}

#[test]
fn very_small_and_very_large_faceting_tolerances_give_finite_answers_or_a_typed_refusal() {
    for name in [
        "sphere_plane",
        "sphere_sphere",
        "cylinder_plane_edge",
        "torus_plane",
        "box_box",
    ] {
        let scene = scenes::scene(name).unwrap();
        // FT = 0.5: the deviation exceeds the size, every circle becomes a triangle.
        assert!(
            all_answers_finite(&scene, GeometryLibrary::Faceted, 0.5).is_some(),
            "{name}"
        );
        assert!(
            all_answers_finite(&scene, GeometryLibrary::Faceted, 2e4).is_some(),
            "{name}"
        );
    }
    // A tolerance that would need more triangles than the limit is refused, with the numbers.
    let sphere = GeometryInstance::new(Geometry::sphere(1.0).unwrap());
    let plane = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
    let engine = build_engine(
        GeometryLibrary::Faceted,
        FacetingTolerance::new(1e9).unwrap(),
    );
    match engine.prepare(&[sphere], &[plane]) {
        Err(PrepareError::TooManyTriangles {
            requested, limit, ..
        }) => assert!(requested > limit),
        other => panic!("expected TooManyTriangles, got {other:?}"),
    }
}

#[test]
fn near_parallel_faces_and_axes_give_finite_answers() {
    let block = Geometry::Cuboid(Cuboid::centered(0.5, 0.5, 0.5).unwrap());
    let cylinder = GeometryInstance::new(Geometry::Cylinder(Cylinder::new(0.3, 2.0).unwrap()))
        .at(Isometry3::translation(0.0, 0.0, -1.0));
    for library in [GeometryLibrary::Exact, GeometryLibrary::Faceted] {
        let engine = build_engine(library, FacetingTolerance::DEFAULT);
        for tilt in [0.0, 1e-15, 1e-12, 1e-9, 1e-6] {
            // Box face on box face, tilted by `tilt`, 1e-3 deep.
            let pair = engine
                .prepare(
                    &[GeometryInstance::new(block.clone())],
                    &[GeometryInstance::new(block.clone())],
                )
                .unwrap();
            let pose_i = Isometry3::new(Vector3::new(0.2, 0.1, 1.0 - 1e-3), Vector3::x() * tilt);
            let (mut out, mut work) = (Vec::new(), WorkCounters::default());
            pair.query(&pose_i, &Isometry3::identity(), &mut out, &mut work)
                .unwrap();
            assert!(
                !out.is_empty() && out.iter().all(|c| c.is_well_formed()),
                "{library:?} tilt {tilt}: {out:?}"
            );
            // A cylinder lying on a plane, its axis tilted by `tilt`.
            let plane = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
            if let Ok(pair) = engine.prepare(std::slice::from_ref(&cylinder), &[plane]) {
                let down = Isometry3::new(
                    Vector3::new(0.0, 0.0, 0.3 - 1e-3),
                    Vector3::y() * (std::f64::consts::FRAC_PI_2 + tilt),
                );
                pair.query(&down, &Isometry3::identity(), &mut out, &mut work)
                    .unwrap();
                assert!(
                    !out.is_empty() && out.iter().all(|c| c.is_well_formed()),
                    "{library:?} tilt {tilt}: {out:?}"
                );
            }
        }
    }
}

#[test]
fn meshes_of_very_thin_triangles_give_finite_answers() {
    // A 100 × 0.01 × 0.01 rod as a closed mesh: its side triangles have aspect ratio 1e4.
    let (l, w) = (100.0, 0.01);
    let v = |x: f64, y: f64, z: f64| contact_core::Point3::new(x, y, z);
    let vertices = vec![
        v(0.0, 0.0, 0.0),
        v(l, 0.0, 0.0),
        v(l, w, 0.0),
        v(0.0, w, 0.0),
        v(0.0, 0.0, w),
        v(l, 0.0, w),
        v(l, w, w),
        v(0.0, w, w),
    ];
    let triangles = vec![
        [0, 2, 1],
        [0, 3, 2],
        [4, 5, 6],
        [4, 6, 7],
        [0, 1, 5],
        [0, 5, 4],
        [1, 2, 6],
        [1, 6, 5],
        [2, 3, 7],
        [2, 7, 6],
        [3, 0, 4],
        [3, 4, 7],
    ];
    let rod = Geometry::Mesh(Arc::new(TriangleMesh::new(vertices, triangles).unwrap()));
    let plane = GeometryInstance::new(Geometry::Plane(Plane::unbounded()));
    for library in [GeometryLibrary::Exact, GeometryLibrary::Faceted] {
        let engine = build_engine(library, FacetingTolerance::DEFAULT);
        let pair = engine
            .prepare(
                &[GeometryInstance::new(rod.clone())],
                std::slice::from_ref(&plane),
            )
            .unwrap();
        let (mut out, mut work) = (Vec::new(), WorkCounters::default());
        for (dz, tilt) in [(-1e-3, 0.0), (-1e-12, 0.0), (-1e-3, 1e-7), (1e-3, 0.0)] {
            let pose = Isometry3::new(Vector3::new(-50.0, 0.0, dz), Vector3::y() * tilt);
            pair.query(&pose, &Isometry3::identity(), &mut out, &mut work)
                .unwrap();
            assert!(
                out.iter().all(|c| c.is_well_formed()),
                "{library:?} dz {dz} tilt {tilt}: {out:?}"
            );
            assert_eq!(out.is_empty(), dz > 0.0, "{library:?} dz {dz}: {out:?}");
        }
    }
}
